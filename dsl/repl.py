"""The interactive read-eval-print loop: reads lines until a statement is complete, runs it,
prints, and survives errors and Ctrl-C; Ctrl-D (or ``quit;``) leaves."""
from __future__ import annotations

import importlib
import sys
from typing import Callable, Optional

from .errors import MechError
from .interpreter import Interpreter, QuitSignal, convert_exception
from .parser import split_complete

BANNER = "mech {version}: Singular-compatible algebra for mechanisms.  help; lists commands, quit; leaves."


def run_repl(warnings: bool = True, read: Optional[Callable[[str], str]] = None) -> int:
    """Run the plain REPL on the terminal (``read`` replaces ``input`` in tests)."""
    from .. import __version__
    if read is None:
        try:
            importlib.import_module("readline")  # line editing and history for input()
        except ImportError:
            pass
        read = input
    interp = Interpreter(out=sys.stdout, flush=True, warnings=warnings)
    print(BANNER.format(version=__version__))
    buf = ""
    while True:
        try:
            line = read("> " if not buf else ". ")
        except EOFError:
            print()
            return 0
        except KeyboardInterrupt:
            print()
            buf = ""
            continue
        buf += line + "\n"
        _, unfinished = split_complete(buf)
        if unfinished:
            continue
        text, buf = buf, ""
        if not text.strip():
            continue
        try:
            interp.execute(text, "<stdin>")
        except QuitSignal:
            return 0
        except MechError as e:
            sys.stdout.flush()
            sys.stderr.write(e.format())
        except KeyboardInterrupt:
            sys.stdout.flush()
            sys.stderr.write("interrupted\n")
        except Exception as e:
            sys.stdout.flush()
            sys.stderr.write(convert_exception(e).format())
