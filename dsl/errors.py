"""mech's errors: every failure the user sees is a :class:`MechError` formatted as

    FILE:LINE:COL: error: message
    <the source line>
        ^~~~

followed by ``note:`` entries for the chain of procedure calls it happened in.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

from .ast import Pos

MAX_NOTES = 12  # procedure-call notes shown under an error (deep recursion elides the middle)
MAX_SHOWN = 200  # characters of a long source line shown under an error (around its column)


@dataclass
class Source:
    """A named program text (a file name, ``<string>`` for ``-c`` code, ``<stdin>``)."""

    name: str
    text: str

    def line(self, n: int) -> str:
        """Line ``n`` (1-based; lines end at ``\n`` as the parser counts them, a ``\r`` before it
        dropped), found from the last line asked for: long scripts warn often, mostly further on,
        and a list of all their lines would cost memory in proportion to the script."""
        text = self.text
        k, start = getattr(self, "_at", (1, 0))
        if getattr(self, "_of", None) is not text or n < k:
            k, start = 1, 0
            self._of = text
        if n < 1:
            return ""
        while k < n:
            j = text.find("\n", start)
            if j < 0:
                return ""
            k, start = k + 1, j + 1
        self._at = (k, start)
        end = text.find("\n", start)
        line = text[start:] if end < 0 else text[start:end]
        if not line and start == len(text):
            return ""
        return line[:-1] if line.endswith("\r") else line


@dataclass
class Note:
    message: str
    source: Optional[Source]
    pos: Optional[Pos]
    underline: bool = True


class MechError(Exception):
    """Base class of mech's errors; ``line`` and ``column`` locate it (0 when unknown)."""

    kind = "error"

    def __init__(self, message: str, pos: Optional[Pos] = None, source: Optional[Source] = None,
                 underline: bool = False) -> None:
        super().__init__(message)
        self.message = message
        self.pos = pos
        self.source = source
        self.underline = underline
        self.notes: list[Note] = []

    @property
    def line(self) -> int:
        return self.pos.line if self.pos else 0

    @property
    def column(self) -> int:
        return self.pos.col if self.pos else 0

    @property
    def filename(self) -> str:
        return self.source.name if self.source else "<input>"

    def locate(self, pos: Pos, source: Optional[Source], underline: bool = False) -> "MechError":
        """Attach a position unless the error already has one."""
        if self.pos is None:
            self.pos, self.source, self.underline = pos, source, underline
        elif self.source is None:
            self.source = source
        return self

    def format(self) -> str:
        """The error as the user sees it (ends with a newline)."""
        out = [_entry(self.source, self.pos, "error", self.message, self.underline)]
        notes = self.notes
        if len(notes) > MAX_NOTES:
            skipped = len(notes) - MAX_NOTES + 1
            head, tail = notes[:MAX_NOTES - 2], notes[-1:]
            skip = Note(f"... {skipped} more procedure calls ...", None, None)
            notes = head + [skip] + tail
        for n in notes:
            if n.pos is None:
                out.append(f"note: {n.message}\n")
            else:
                out.append(_entry(n.source, n.pos, "note", n.message, n.underline))
        return "".join(out)

    def _render_traceback_(self) -> list[str]:
        """What IPython and Jupyter show instead of a Python traceback: the error as mech prints it."""
        return self.format().rstrip("\n").split("\n")

    def __str__(self) -> str:
        if self.pos is None:
            return self.message
        return f"{self.filename}:{self.pos.line}:{self.pos.col}: {self.message}"


class MechSyntaxError(MechError):
    """The program text does not parse."""


class MechRuntimeError(MechError):
    """Evaluation failed (wrong value, division by zero, no ring, ...)."""


class MechNameError(MechRuntimeError):
    """An unknown identifier, command or library."""


class MechTypeError(MechRuntimeError):
    """Arguments or operands of the wrong type or number."""


class MechInternalError(MechError):
    """A bug in mech itself, reported in the same format."""


def _entry(source: Optional[Source], pos: Optional[Pos], kind: str, message: str, underline: bool) -> str:
    name = source.name if source else "<input>"
    message = message.replace("\r", "\\r").replace("\n", "\\n")  # one line, whatever strings it quotes
    if len(message) > 2 * MAX_SHOWN:
        message = message[:2 * MAX_SHOWN] + "..."
    if pos is None or pos.line == 0:
        return f"{name}: {kind}: {message}\n"
    head = f"{name}:{pos.line}:{pos.col}: {kind}: {message}\n"
    text = source.line(pos.line) if source else ""
    if not text:
        return head
    col = min(pos.col, len(text) + 1)
    end = pos.end_col if underline and pos.end_line == pos.line else len(text) + 1 if underline else col + 1
    if len(text) > MAX_SHOWN:  # a long line: the part around the error
        lo = max(0, min(col - 1 - MAX_SHOWN // 2, len(text) - MAX_SHOWN))
        cut = ("..." if lo else "") + text[lo:lo + MAX_SHOWN] + ("..." if lo + MAX_SHOWN < len(text) else "")
        shift = lo - (3 if lo else 0)
        text, col, end = cut, col - shift, min(end - shift, len(cut) + 1)
    lead = "".join(c if c == "\t" else " " for c in text[:col - 1])
    width = max(1, end - col)
    return f"{head}{text}\n{lead}^{'~' * (width - 1)}\n"
