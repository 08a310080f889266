"""mech in IPython and Jupyter's Python kernel: ``%load_ext mech`` (or ``%load_ext mech.ipython``).

``%%mech`` runs a cell of mech code and ``%mech CODE`` one line, all in one :class:`mech.Session`
(the variable ``mech_session`` of the notebook, so Python reads and sets its variables:
``mech_session["I"]``).  A line without a final ``;`` is an expression: ``%mech std(I)`` returns
its value (``G = %mech std(I)``).  Values of expression statements show as LaTeX, analysis reports
as HTML tables, pictures inline; errors as mech prints them, never a Python traceback.
``%%mech --m2`` reads Macaulay2's syntax (in a session of its own), ``--timeout S`` and
``--max-memory MB`` limit each statement of the cell.
"""
from __future__ import annotations

import shlex
import sys
from typing import Any, Optional

from IPython.core.magic import Magics, line_cell_magic, magics_class
from IPython.core.error import UsageError

from .session import Session


@magics_class
class MechMagics(Magics):
    """The ``%mech`` line magic and ``%%mech`` cell magic."""

    def __init__(self, shell: Any) -> None:
        super().__init__(shell)
        self.sessions: dict[str, Session] = {}

    def session(self, dialect: str = "singular") -> Session:
        s = self.sessions.get(dialect)
        if s is None:
            s = self.sessions[dialect] = Session(dialect=dialect, display=_publish, echo=True)
            self.shell.user_ns["mech_session" if dialect == "singular" else "mech_session_m2"] = s
        return s

    @line_cell_magic
    def mech(self, line: str, cell: Optional[str] = None) -> Any:
        """%mech CODE: run a line (its value when it has no final ';'); %%mech [--m2] [--timeout S]
        [--max-memory MB]: run the cell."""
        if cell is None:
            return self._line(line)
        opts = _options(line)
        s = self.session("m2" if opts.pop("m2", False) else "singular")
        limits = s.interpreter.limits
        saved = limits.timeout, limits.max_memory
        try:
            if "timeout" in opts:
                limits.timeout = opts["timeout"] or None
            if "max_memory" in opts:
                limits.max_memory = opts["max_memory"] or None
            s.execute(cell, "<cell>")
        finally:
            limits.timeout, limits.max_memory = saved
        return None

    def _line(self, line: str) -> Any:
        code = line.strip()
        if not code:
            raise UsageError("%mech CODE runs mech code (%%mech runs a cell)")
        s = self.session()
        if code.endswith(";") or code.endswith("}"):
            s.execute(code, "<line>")
            return None
        return s.eval(code)


def _publish(bundle: dict[str, str]) -> None:
    from IPython.display import publish_display_data
    sys.stdout.flush()
    publish_display_data(bundle)


def _options(line: str) -> dict[str, Any]:
    words = shlex.split(line)
    out: dict[str, Any] = {}
    k = 0
    while k < len(words):
        w = words[k]
        if w == "--m2":
            out["m2"] = True
        elif w in ("--timeout", "--max-memory") and k + 1 < len(words):
            try:
                value = float(words[k + 1])
                if not 0 <= value < float("inf"):
                    raise ValueError
            except ValueError:
                raise UsageError(f"%%mech {w}: expected a nonnegative number, got '{words[k + 1]}'") from None
            out[w[2:].replace("-", "_")] = value
            k += 1
        else:
            raise UsageError(f"%%mech: unknown option '{w}' (--m2, --timeout S, --max-memory MB)")
        k += 1
    return out


def load_ipython_extension(ipython: Any) -> None:
    """``%load_ext mech``: register the magics."""
    ipython.register_magics(MechMagics(ipython))
