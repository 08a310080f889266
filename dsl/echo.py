"""Singular's ``echo``: with ``echo = 1`` (or more), each line of a script is printed as it is read,
``FILE  LINE> text``, before its statement runs (statements at the top level of the script)."""
from __future__ import annotations

from typing import Any

from . import ast as A


def mark_echo(interp: Any) -> None:
    """Note that the lines up to the running statement have been read (``echo`` was just set)."""
    stmt = interp.stmt
    interp.echo_mark = (interp.source, stmt.pos.end_line if stmt is not None else 0)


def echo_lines(interp: Any, stmt: A.Stmt) -> None:
    """Print the lines of the script from the last one echoed up to the end of ``stmt`` (not those of
    a library being loaded)."""
    if interp._loading_lib:
        return
    source, last = getattr(interp, "echo_mark", (None, 0))
    if source is not interp.source:
        source, last = interp.source, stmt.pos.line - 1
    end = stmt.pos.end_line
    for n in range(last + 1, end + 1):
        interp.write(f"{source.name} {n:3d}> {source.line(n).rstrip()}\n")
    interp.echo_mark = (source, max(last, end))
