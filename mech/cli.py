"""The ``mech`` command: run a script (``mech FILE``), code (``mech -c CODE``), standard input
(``mech -``) or, without arguments, the interactive REPL; ``mech sweep FILE ...`` sweeps a
mechanism over designs (mech.sweep)."""
from __future__ import annotations

import argparse
import gc
import os
import sys
from typing import Any, Optional

from . import __version__


class _Formats:
    """The report formats (:data:`mech.stdlib.reports.FORMATS`), read only when argparse checks a
    ``--format`` or prints the help: the analysis modules stay unimported at start-up."""

    def __contains__(self, name: object) -> bool:
        return name in self._names()

    def __iter__(self) -> Any:
        return iter(self._names())

    @staticmethod
    def _names() -> list[str]:
        from .stdlib.reports import FORMATS
        return list(FORMATS)


def _parser() -> argparse.ArgumentParser:
    from .kernel.engines import list_engines
    p = argparse.ArgumentParser(prog="mech", description="mech: a Singular-compatible computer-algebra language "
                                "for the configuration spaces of rigid mechanisms.")
    p.add_argument("file", nargs="?", help="script to run (.mech or .sing); '-' reads standard input")
    p.add_argument("-c", dest="code", metavar="CODE", help="run CODE")
    p.add_argument("-q", "--quiet", action="store_true", help="no banner in the interactive shell (as Singular -q)")
    p.add_argument("--no-warn", action="store_true", help="do not print '// **' warnings")
    p.add_argument("--dialect", choices=("singular", "m2"), help="the language: Singular's (default) or "
                   "Macaulay2's (default for .m2 files)")
    p.add_argument("--timeout", type=_limit, metavar="SECONDS", help="time limit of each statement (0: none)")
    p.add_argument("--max-memory", type=_memory, metavar="MB", help="memory each statement may add to the process, "
                   "in MB (0: none)")
    p.add_argument("--format", choices=_Formats(), default="text", metavar="FORMAT",
                   help="the format of mechanism reports: %(choices)s (analyze's default; default %(default)s)")
    p.add_argument("--json", dest="format", action="store_const", const="json", help="the same as --format json")
    p.add_argument("--engine", choices=[name for name, _ in list_engines()], default="auto",
                   help="the Groebner engine of every standard basis (default auto; see 'help engine;')")
    p.add_argument("--install-kernel", action="store_true", help="install the Jupyter kernels mech and mech-m2 in "
                   "this Python environment (needs the jupyter extra)")
    p.add_argument("--version", action="version", version=f"mech {__version__}")
    return p


def _limit(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = -1.0
    if not 0 <= value < float("inf"):
        raise argparse.ArgumentTypeError(f"expected a nonnegative number, got '{text}'")
    return value


def _memory(text: str) -> float:
    from .dsl.limits import MIN_MEMORY
    value = _limit(text)
    if 0 < value < MIN_MEMORY:
        raise argparse.ArgumentTypeError(f"expected 0 (no limit) or at least {MIN_MEMORY} MB, got '{text}'")
    return value


_FROZEN = []


def _freeze_startup() -> None:
    """The start-up's objects (modules, parser tables, commands) kept for good, once per process:
    full collections skip them (one during numpy's import walked them all: 5 % of the four-bar
    example's time)."""
    if not _FROZEN:
        gc.freeze()
        _FROZEN.append(True)


def run_text(text: str, name: str, warnings: bool = True, dialect: str = "singular",
             settings: Optional[dict[str, Any]] = None) -> int:
    """Run a program, printing its output as it is produced; errors go to stderr.  The exit status.
    ``settings``: the interpreter's (``{"report_format": "json"}``...)."""
    from .dsl.errors import MechError, MechInternalError
    from .dsl.interpreter import Interpreter, QuitSignal
    cls = Interpreter
    if dialect == "m2":
        from .dsl.m2 import M2Interpreter as cls
    interp = cls(out=sys.stdout, flush=True, warnings=warnings, settings=settings)
    if dialect == "m2":  # as Macaulay2: a script (M2 --script) prints no values, standard input (M2 < f) does
        interp.echo = name == "<stdin>"
    _freeze_startup()
    try:
        interp.execute(text, name)
    except QuitSignal:
        return 0
    except MechError as e:
        sys.stdout.flush()
        sys.stderr.write(e.format())
        return 1
    except KeyboardInterrupt:
        sys.stdout.flush()
        sys.stderr.write(f"{name}: error: interrupted\n")
        return 130
    except BrokenPipeError:  # `mech f | head`: stop quietly, as Unix tools do
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 141
    except Exception as e:  # a bug: still the error format, never a traceback
        sys.stdout.flush()
        sys.stderr.write(MechInternalError(f"internal error: {type(e).__name__}: {e}").format())
        return 1
    return 0


def main(argv: Optional[list[str]] = None) -> int:
    """The ``mech`` command; the exit status (0 ok, 1 an error in the program, 2 a usage error)."""
    if sys.stderr is None:  # nowhere to report anything: run with errors dropped
        sys.stderr = open(os.devnull, "w")
    if sys.stdout is None:
        sys.stderr.write("mech: error: standard output is closed\n")
        return _exit(2)
    for stream in (sys.stdout, sys.stderr):  # a locale that cannot encode the output (LANG=C): escape
        if (getattr(stream, "encoding", "") or "").lower().replace("-", "") != "utf8" and hasattr(stream, "reconfigure"):
            stream.reconfigure(errors="backslashreplace")
    argv = sys.argv[1:] if argv is None else argv
    if "sweep" in argv and not os.path.isfile("sweep"):  # the subcommand (a script named sweep still runs)
        status = _sweep(argv)
        if status is not None:
            return _exit(status)
    try:
        args = _parser().parse_args(argv)
    except SystemExit as e:  # --help, --version, a usage error
        return _exit(e.code if isinstance(e.code, int) else 2)
    if args.code is not None:  # under LANG=C Python decodes arguments as ASCII: the bytes were UTF-8
        args.code = os.fsencode(args.code).decode("utf-8", "replace")
    from .dsl.limits import default_limits
    from .dsl.progress import terminal_progress
    with default_limits(args.timeout, args.max_memory), terminal_progress():  # for this run, the REPL's too
        return _exit(_main(args))


def _sweep(argv: list[str]) -> Optional[int]:
    """``mech [--timeout T] [--max-memory MB] sweep ...``: the subcommand's exit status, the limits
    applying to the whole sweep as to one statement; None when ``sweep`` is not the subcommand
    (a script or code after options)."""
    k = argv.index("sweep")
    from .sweep import main as sweep_main
    if k == 0:
        return sweep_main(argv[1:])
    try:
        args = _parser().parse_args(argv[:k])
    except SystemExit as e:
        return e.code if isinstance(e.code, int) else 2
    if args.file is not None or args.code is not None:
        return None
    other = [o for o, given in (("--format", args.format != "text"), ("--engine", args.engine != "auto"),
                                ("--dialect", args.dialect), ("--install-kernel", args.install_kernel)) if given]
    if other:
        sys.stderr.write(f"mech: error: {other[0]} does not apply to 'mech sweep' (only --timeout and --max-memory, "
                         "which limit the whole sweep)\n")
        return 2
    return sweep_main(argv[k + 1:], total_timeout=args.timeout, max_memory=args.max_memory)


def _exit(status: int) -> int:
    """``status`` for ``sys.exit``; with Python's inspect mode on (``PYTHONINSPECT``), which would
    print ``sys.exit``'s SystemExit as a traceback, the process ends here instead."""
    if sys.flags.inspect or os.environ.get("PYTHONINSPECT"):
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError, AttributeError):
                pass
        os._exit(status)
    return status


def _read_stdin() -> Optional[str]:
    """Standard input as text (UTF-8, a byte-order mark dropped); None when it is closed."""
    if sys.stdin is None:
        return None
    try:
        data = sys.stdin.buffer.read() if hasattr(sys.stdin, "buffer") else sys.stdin.read().encode()
    except (OSError, ValueError):
        return None
    return data.decode("utf-8-sig")


def _stdin_is_terminal() -> bool:
    try:
        return sys.stdin is not None and sys.stdin.isatty()
    except (OSError, ValueError):
        return False


def _main(args: argparse.Namespace) -> int:
    warnings = not args.no_warn
    settings = {"report_format": args.format, "engine": args.engine}
    dialect = args.dialect or ("m2" if args.file and args.file.endswith(".m2") else "singular")

    def run_script(text: str, name: str) -> int:  # under limits, a watcher process stands by (mech/watcher.py)
        from .watcher import run_watched
        return run_watched(lambda: run_text(text, name, warnings, dialect, settings), name, text,
                           args.timeout, args.max_memory)

    if args.code is not None:
        if args.file:
            sys.stderr.write("mech: error: give either -c CODE or a FILE, not both\n")
            return 2
        return run_script(args.code, "<string>")
    if args.install_kernel:
        from .kernelspec import install
        for folder in install():
            print(f"installed the Jupyter kernel spec {os.path.basename(folder)} in {folder}")
        return 0
    if args.file == "-" or (args.file is None and not _stdin_is_terminal()):
        try:
            text = _read_stdin()
        except UnicodeDecodeError:
            sys.stderr.write("mech: error: standard input is not UTF-8 text\n")
            return 2
        if text is None:
            sys.stderr.write("mech: error: standard input is closed (give a FILE, -c CODE, or run in a terminal)\n")
            return 2
        return run_script(text, "<stdin>")
    if args.file:
        try:
            with open(args.file, encoding="utf-8-sig") as fh:  # a byte-order mark is dropped
                text = fh.read()
        except OSError as e:
            sys.stderr.write(f"mech: error: cannot read {args.file}: {e.strerror}\n")
            return 2
        except UnicodeDecodeError:
            sys.stderr.write(f"mech: error: {args.file} is not a UTF-8 text file\n")
            return 2
        return run_script(text, args.file)
    from .kernel import offload
    offload.INTERRUPTIBLE = True  # the shells: long python-flint calls in a child, so Ctrl-C stops them
    if dialect == "m2":
        from .dsl.m2 import run_m2_repl
        return run_m2_repl(warnings=warnings)
    from .dsl.repl import run_repl
    return run_repl(warnings=warnings, quiet=args.quiet, version=__version__, settings=settings)


if __name__ == "__main__":
    sys.exit(main())
