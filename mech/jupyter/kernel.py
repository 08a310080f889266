"""The Jupyter kernel of mech, on ipykernel's wrapper-kernel base class.

A cell is mech code in the notebook's dialect (the kernel spec: ``mech`` for Singular's, ``mech-m2``
for Macaulay2's), or in the other one when its first line is ``%%m2`` or ``%%singular`` (each
dialect has its own variables).  Text is printed as the statements run; expression values,
analysis reports and pictures are sent as rich output (LaTeX, HTML tables, inline SVG) with the
text beside them.  Errors show as ``cell[N]:LINE:COL: error: ...`` with the source line and a
caret, never a Python traceback; an interrupt stops the cell and keeps the session.  Lines of the
kernel's own at the top of a cell: ``%timeout S`` and ``%max-memory MB`` (limits of each later
cell, 0: none), ``%reset`` (a fresh session); a cell ``?NAME`` shows a command's help.
Tab completes names, commands and libraries; Shift-Tab (inspect) shows a command's help.
"""
from __future__ import annotations

import re
import sys
from typing import Any, Optional

from ipykernel.kernelbase import Kernel

from .. import __version__
from ..dsl.errors import MechError
from ..dsl.interpreter import Interpreter, QuitSignal
from ..dsl.limits import Limits
from ..kernel import offload

DIALECTS = ("singular", "m2")
_WORD = re.compile(r"[A-Za-z_@][A-Za-z0-9_@]*")
_LIMIT = re.compile(r"%(timeout|max-memory)(?:\s+(\S+))?\s*$")
LANGUAGES = {
    "singular": {"name": "mech", "mimetype": "text/x-mech", "file_extension": ".mech", "pygments_lexer": "mech",
                 "codemirror_mode": "clike"},
    "m2": {"name": "mech-m2", "mimetype": "text/x-macaulay2", "file_extension": ".m2", "pygments_lexer": "text"},
}


class _Stream:
    """The interpreter's output: each write goes to the notebook at once (a ``stream`` message)."""

    def __init__(self, kernel: "MechKernel", name: str = "stdout") -> None:
        self.kernel, self.name = kernel, name

    def write(self, text: str) -> int:
        if text and not self.kernel.silent:
            self.kernel.send_response(self.kernel.iopub_socket, "stream", {"name": self.name, "text": text})
        return len(text)

    def flush(self) -> None:
        pass


class MechKernel(Kernel):
    """mech's kernel: one interpreter per dialect, kept across cells."""

    implementation = "mech"
    implementation_version = __version__
    language = "mech"
    language_version = __version__
    banner = f"mech {__version__}: Singular-compatible algebra for the configuration spaces of mechanisms"
    dialect = "singular"   # the notebook's (the kernel spec's --dialect)

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.language_info = LANGUAGES[self.dialect]
        self.silent = False
        self.timeout: Optional[float] = None
        self.max_memory: Optional[float] = None
        self._interps: dict[str, Interpreter] = {}
        offload.INTERRUPTIBLE = True  # long python-flint calls in a child that an interrupt or a limit stops

    # ------------------------------------------------------------ sessions
    def interpreter(self, dialect: Optional[str] = None) -> Interpreter:
        """The interpreter of ``dialect`` (the notebook's by default), created on first use."""
        dialect = dialect or self.dialect
        it = self._interps.get(dialect)
        if it is None:
            cls = Interpreter
            if dialect == "m2":
                from ..dsl.m2 import M2Interpreter as cls
            it = cls(out=_Stream(self), flush=True, settings={"display": self._display, "report_format": "text"})
            self._interps[dialect] = it
        return it

    def _display(self, bundle: dict[str, str]) -> None:
        if not self.silent:
            self.send_response(self.iopub_socket, "display_data", {"data": bundle, "metadata": {}})

    # ------------------------------------------------------------ execution
    def do_execute(self, code: str, silent: bool, store_history: bool = True, user_expressions: Any = None,
                   allow_stdin: bool = False, **kwargs: Any) -> dict[str, Any]:
        self.silent = silent
        try:
            return self._execute(code)
        finally:
            self.silent = False

    def _execute(self, code: str) -> dict[str, Any]:
        dialect, code = self._cell_dialect(code)
        code, note = self._kernel_lines(code)
        if note is not None:
            if note.startswith("error"):
                return self._error("MechError", note.rstrip("\n"), [note.rstrip("\n")])
            _Stream(self).write(note)
        stripped = code.strip()
        if stripped.startswith("?") and "\n" not in stripped:
            topic = stripped[1:].strip().rstrip(";").strip()
            code = f"help {topic};" if topic else "help;"
        if not stripped:
            return self._ok()
        it = self.interpreter(dialect)
        limits = Limits(self.timeout or 0, self.max_memory or 0)
        name = f"cell[{self.execution_count}]"
        try:
            limits.run(it, it.execute, code, name)  # one watch for the whole cell
        except QuitSignal:
            pass
        except MechError as e:
            it.unwind()
            return self._error(type(e).__name__, e.message, e._render_traceback_())
        except KeyboardInterrupt:
            it.unwind()
            msg = "interrupted (rings and variables are kept)"
            return self._error("KeyboardInterrupt", msg, [msg])
        except Exception as e:  # a bug: still the error format, never a traceback
            from ..dsl.boundary import convert_exception
            it.unwind()
            err = convert_exception(e)
            return self._error(type(err).__name__, err.message, err.format().rstrip("\n").split("\n"))
        return self._ok()

    def _cell_dialect(self, code: str) -> tuple[str, str]:
        """The cell's dialect (``%%m2``/``%%singular`` on its first line) and its code, that line blank."""
        lines = code.split("\n")
        first = next((k for k, line in enumerate(lines) if line.strip()), None)
        if first is not None and lines[first].strip() in ("%%m2", "%%singular"):
            dialect = lines[first].strip()[2:]
            lines[first] = ""
            return dialect, "\n".join(lines)
        return self.dialect, code

    def _kernel_lines(self, code: str) -> tuple[str, Optional[str]]:
        """Run the kernel's own lines at the top of the cell; the rest of the cell and what to say."""
        lines = code.split("\n")
        notes = []
        while lines and lines[0].strip().startswith("%"):
            line = lines.pop(0).strip()
            m = _LIMIT.match(line)
            if line in ("%reset", ":reset"):
                self._interps.clear()
                notes.append("// a fresh session: no rings, no variables, no libraries\n")
            elif m:
                value = m.group(2)
                attr = "timeout" if m.group(1) == "timeout" else "max_memory"
                if value is None:
                    current = getattr(self, attr) or 0
                    notes.append(f"// {m.group(1)} {current:g} (per cell; 0: none)\n")
                    continue
                try:
                    number = float(value)
                    Limits(**{attr: number})   # the same checks as mech --timeout/--max-memory
                except ValueError as e:
                    return "", f"error: %{m.group(1)} {value}: {e}\n"
                setattr(self, attr, number or None)
                notes.append(f"// {m.group(1)} {number:g} per cell{' (none)' if not number else ''}\n")
            else:
                return "", (f"error: unknown kernel command '{line}' (%timeout S, %max-memory MB, %reset; "
                            f"%%m2 or %%singular on a cell's first line)\n")
        return "\n" * (len(code.split("\n")) - len(lines)) + "\n".join(lines), "".join(notes) or None

    def _ok(self) -> dict[str, Any]:
        return {"status": "ok", "execution_count": self.execution_count, "payload": [], "user_expressions": {}}

    def _error(self, ename: str, evalue: str, traceback: list[str]) -> dict[str, Any]:
        """The reply of a failed cell; the notebook shows ``traceback``: the error as mech prints it."""
        content = {"ename": ename, "evalue": evalue, "traceback": traceback}
        if not self.silent:
            self.send_response(self.iopub_socket, "error", content)
        return {"status": "error", "execution_count": self.execution_count, **content}

    # ------------------------------------------------------------ completion, help, input
    def do_complete(self, code: str, cursor_pos: int) -> dict[str, Any]:
        from ..dsl.completion import candidates
        prefix, items = candidates(self.interpreter(self._cell_dialect(code)[0]), code[:cursor_pos])
        return {"status": "ok", "matches": [text for text, _ in items], "cursor_start": cursor_pos - len(prefix),
                "cursor_end": cursor_pos, "metadata": {"_jupyter_types_experimental": [
                    {"text": text, "type": what, "start": cursor_pos - len(prefix), "end": cursor_pos}
                    for text, what in items]}}

    def do_inspect(self, code: str, cursor_pos: int, detail_level: int = 0, omit_sections: Any = ()) -> dict:
        word = _word_at(code, cursor_pos)
        text = help_text(self.interpreter(self._cell_dialect(code)[0]), word) if word else None
        if text is None:
            return {"status": "ok", "found": False, "data": {}, "metadata": {}}
        return {"status": "ok", "found": True, "data": {"text/plain": text}, "metadata": {}}

    def do_is_complete(self, code: str) -> dict[str, Any]:
        from ..dsl.repl import is_complete
        if self._cell_dialect(code)[0] == "m2":
            from ..dsl.m2_parser import is_complete as m2_complete
            done = m2_complete(code)
        else:
            done = is_complete(code)
        return {"status": "complete"} if done else {"status": "incomplete", "indent": ""}


def _word_at(code: str, pos: int) -> str:
    for m in _WORD.finditer(code):
        if m.start() <= pos <= m.end():
            return m.group(0)
    return ""


def help_text(interp: Interpreter, name: str) -> Optional[str]:
    """What ``help NAME;`` prints for a command or procedure (None when there is no such name)."""
    from ..dsl.values import Proc
    var = interp.lookup(name)
    if var is not None and isinstance(var.value, Proc):
        return (var.value.doc or f"procedure {name} has no help text").strip("\n") + "\n"
    text = interp.registry.help_text(name)
    return None if text is None else text.rstrip("\n") + "\n"


def launch(argv: list[str]) -> None:
    """Start the kernel: ``argv`` as Jupyter gives it (``-f CONNECTION_FILE``), with ``--dialect D``."""
    from ipykernel.kernelapp import IPKernelApp
    args = list(argv)
    dialect = "singular"
    if "--dialect" in args:
        k = args.index("--dialect")
        dialect = args[k + 1] if k + 1 < len(args) else ""
        del args[k:k + 2]
    if dialect not in DIALECTS:
        sys.exit(f"mech kernel: error: unknown dialect '{dialect}' (singular or m2)")
    kernel = type("MechKernel", (MechKernel,), {"dialect": dialect})
    IPKernelApp.launch_instance(argv=args, kernel_class=kernel)
