"""Control flow as exceptions: ``break``, ``continue``, ``return`` and ``quit`` unwind the
interpreter's Python stack to the loop, procedure call or program that handles them."""
from __future__ import annotations

from typing import Any


class BreakSignal(Exception):
    """``break``: leave the innermost loop."""


class ContinueSignal(Exception):
    """``continue``: go on with the innermost loop's condition."""


class ReturnSignal(Exception):
    """``return(...)``: leave the procedure with ``value``."""

    def __init__(self, value: Any) -> None:
        self.value = value


class QuitSignal(Exception):
    """``quit;`` or ``exit;``: stop the program (not an error)."""


#: The signals evaluation passes on untouched.
SIGNALS = (BreakSignal, ContinueSignal, ReturnSignal, QuitSignal)
