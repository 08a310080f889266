"""The interactive shell: a prompt_toolkit REPL over one :class:`Interpreter`.

Input is highlighted (:mod:`mech.dsl.highlight`), Tab completes (:mod:`mech.dsl.completion`),
history persists in the user's data directory (``$MECH_HISTORY`` overrides it) and Ctrl-R searches
it.  Enter runs the input once its last statement is complete (the closing ``;`` or brace
balance), otherwise it starts a continuation line.  The prompt names the basering.

Commands run in the main thread, so Ctrl-C raises KeyboardInterrupt inside the pure-Python kernel
loops at once, and long python-flint calls run in a child process that it kills
(:mod:`mech.kernel.offload`); the interpreter's ``finally`` blocks restore its scopes and basering, values are
immutable, and :meth:`Interpreter.unwind` drops whatever an interrupted cleanup left: the session,
its rings and variables survive.  (Python cannot stop a worker thread: every kernel loop would have
to poll a cancellation flag.)  After a second a status line on stderr shows the elapsed time; it is
erased before any output and when the command ends.
"""
from __future__ import annotations

import builtins
import importlib
import os
import re
import sys
import threading
import time
from pathlib import Path
from typing import Any, Callable, Optional, TextIO

from ..kernel import offload
from .errors import MechError
from .boundary import convert_exception
from .interpreter import Interpreter
from .split import split_complete
from .printing import ordstr
from .signals import QuitSignal

BANNER = "mech {version}: Singular-compatible algebra.  ?NAME explains a command, :help the shell, Ctrl-D quits."

SHELL_HELP = """\
// Enter runs the input once its statement is complete (';' or closing brace); Esc Enter runs it anyway.
// Tab completes names, commands and libraries; Ctrl-R searches the history; Ctrl-C interrupts a
// running command (the session is kept) or clears the input; Ctrl-D (or quit;) leaves.
// ?NAME          what a command or procedure does (help NAME;); ? or help; lists the commands
// :time on|off   print the time of each command (also %time on|off, or timer = 1; / timer = 0;)
// :reset         a fresh session: no rings, no variables, no libraries
"""

_INDENT = "  "


def history_path() -> Path:
    """``$MECH_HISTORY``, else ``$XDG_DATA_HOME/mech/history`` (``~/.local/share/mech/history``)."""
    env = os.environ.get("MECH_HISTORY")
    if env:
        return Path(env)
    base = os.environ.get("XDG_DATA_HOME") or os.path.join(os.path.expanduser("~"), ".local", "share")
    return Path(base) / "mech" / "history"


def is_complete(text: str) -> bool:
    """Whether the input is ready to run: blank, a shell command (``:``, ``%``, ``?``), or its last
    statement closed (comments and strings are skipped)."""
    stripped = text.strip()
    if not stripped or stripped[0] in ":%?":
        return True
    # closed strings count as one token: split_complete takes a string for an opening bracket
    masked = _CLOSED_STRINGS.sub(lambda m: m.group(0) if m.group(0)[0] == "/" else "0", text)
    return not split_complete(masked)[1]


_CLOSED_STRINGS = re.compile(r'//[^\n]*|/\*.*?(?:\*/|$)|"(?:[^"\\]|\\.)*"', re.S)


class StatusLine:
    """While a command runs: after ``delay`` seconds its elapsed time on ``stream`` (a terminal;
    None shows nothing), redrawn every ``interval`` and erased by :meth:`clear`."""

    def __init__(self, stream: Optional[TextIO], delay: float = 1.0, interval: float = 0.1) -> None:
        self.stream = stream
        self.delay, self.interval = delay, interval
        self.lock = threading.Lock()
        self.at_line_start = True    # the output's cursor: the status line is drawn only there
        self._shown = False
        self._stop = threading.Event()
        self._thread: Optional[threading.Thread] = None
        self._t0 = 0.0

    def start(self) -> None:
        if self.stream is None:
            return
        self._t0 = time.perf_counter()
        self.at_line_start = True
        self._stop.clear()
        self._thread = threading.Thread(target=self._tick, name="mech-status", daemon=True)
        self._thread.start()

    def stop(self) -> None:
        self._stop.set()
        thread, self._thread = self._thread, None
        if thread is not None:
            thread.join()
        self.clear()

    def clear(self) -> None:
        with self.lock:
            if self._shown and self.stream is not None:
                self.stream.write("\r\x1b[2K")
                self.stream.flush()
                self._shown = False

    def _tick(self) -> None:
        assert self.stream is not None
        while not self._stop.wait(self.interval):
            elapsed = time.perf_counter() - self._t0
            if elapsed < self.delay:
                continue
            with self.lock:
                if self.at_line_start and not self._stop.is_set():
                    self.stream.write(f"\r\x1b[2K\x1b[2m[{elapsed:.1f} s - Ctrl-C interrupts]\x1b[0m")
                    self.stream.flush()
                    self._shown = True


class _Output:
    """The interpreter's output stream: erases the status line before writing."""

    def __init__(self, out: TextIO, status: StatusLine) -> None:
        self.out, self.status = out, status

    def write(self, text: str) -> int:
        if not text:
            return 0
        self.status.clear()
        with self.status.lock:
            self.out.write(text)
            self.out.flush()
            self.status.at_line_start = text.endswith("\n")
        return len(text)

    def flush(self) -> None:
        self.out.flush()


class Shell:
    """One interactive session: the interpreter plus what the shell adds (shell commands, timing,
    interrupts).  :meth:`run` takes one complete input; the input loops are :func:`run_repl`'s."""

    def __init__(self, warnings: bool = True, out: Optional[TextIO] = None, err: Optional[TextIO] = None,
                 status: Optional[StatusLine] = None, settings: Optional[dict[str, Any]] = None) -> None:
        self.out = out if out is not None else sys.stdout
        self.err = err if err is not None else sys.stderr
        self.warnings = warnings
        offload.INTERRUPTIBLE = True  # long python-flint calls run in a child that Ctrl-C stops
        self.settings = settings  # the interpreter's, also after :reset
        self.status = status if status is not None else StatusLine(self.err if _isatty(self.err) else None)
        self._output = _Output(self.out, self.status)
        self.interp = self._fresh_interpreter()
        self.last_time: Optional[float] = None

    def _fresh_interpreter(self) -> Interpreter:
        return Interpreter(out=self._output, flush=True, warnings=self.warnings, settings=self.settings)

    @property
    def timing(self) -> bool:
        """Whether each command's time is printed (``:time on`` or ``timer = 1;``)."""
        return bool(self.interp.sysvars.get("timer"))

    def prompt(self) -> str:
        ring = self.interp.ring
        return f"{ring.name or 'basering'}> " if ring is not None else "mech> "

    def continuation(self, width: int) -> str:
        """The prompt of continuation lines, as wide as the first prompt."""
        return " " * max(width - 3, 0) + ".. "

    def toolbar(self) -> str:
        ring = self.interp.ring
        if ring is None:
            where = "no ring: ring r = 0,(x,y,z),dp;"
        else:
            field = "QQ" if ring.characteristic == 0 else f"ZZ/{ring.characteristic}"
            if ring.params:
                field += f"({','.join(ring.params)})"
            names = ",".join(ring.names)
            if len(names) > 48:
                names = names[:45] + "..."
            where = f"ring {ring.name or 'basering'}: {field}[{names}], {ordstr(ring)}"
        last = f"  |  last {self.last_time:.2f} s" if self.last_time is not None else ""
        timing = "  |  :time on" if self.timing else ""
        return f" {where}{last}{timing}  |  Tab completes, ?NAME helps, Ctrl-R searches, Ctrl-D quits"

    def run(self, text: str) -> bool:
        """Run one complete input (statements or a shell command); False when the session ends."""
        line = text.strip()
        if not line:
            return True
        if line[0] in ":%":
            self._shell_command(line)
            return True
        if line[0] == "?":
            topic = line[1:].strip().rstrip(";").strip()
            text = f"help {topic};" if topic else "help;"
        return self._execute(text)

    def _execute(self, text: str) -> bool:
        wall, cpu = time.perf_counter(), time.process_time()
        self.status.start()
        try:
            self.interp.execute(text, "<stdin>")
        except QuitSignal:
            return False
        except MechError as e:
            self.error(e.format())
        except KeyboardInterrupt:
            self.interrupted()
        except Exception as e:  # a bug: still the error format, never a traceback
            self.error(convert_exception(e).format())
        finally:
            self.status.stop()
        self.last_time = time.perf_counter() - wall
        if self.timing:
            self.note(f"time: {self.last_time:.2f} s (cpu {time.process_time() - cpu:.2f} s)", self.err)
        return True

    def interrupted(self) -> None:
        """After Ctrl-C during a command: back to the top level, keeping the session."""
        self.status.stop()
        self.interp.unwind()
        self.error("interrupted (rings and variables are kept)\n")

    def error(self, text: str) -> None:
        self.out.flush()
        if _isatty(self.err):
            first, _, rest = text.partition("\n")
            text = f"\x1b[1;31m{first}\x1b[0m\n{rest}"
        self.err.write(text)
        self.err.flush()

    def note(self, text: str, stream: Optional[TextIO] = None) -> None:
        stream = stream if stream is not None else self.out
        stream.write(f"// {text}\n")
        stream.flush()
        self.status.at_line_start = True

    def _shell_command(self, line: str) -> None:
        word, _, arg = line[1:].partition(" ")
        arg = arg.strip().rstrip(";").strip()
        if word == "reset" and not arg:
            self.interp = self._fresh_interpreter()
            self.last_time = None
            self.note("a fresh session: no rings, no variables, no libraries")
        elif word == "time" and arg in ("on", "off", ""):
            on = not self.timing if not arg else arg == "on"
            self.interp.sysvars["timer"] = int(on)
            self.note(f"timing {'on' if on else 'off'}")
        elif word == "help" and not arg:
            self.out.write(SHELL_HELP)
        else:
            self.error(f"error: unknown shell command '{line}' (:help lists them)\n")


def _isatty(stream: Any) -> bool:
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):
        return False


# ------------------------------------------------------------------ the input loops
def run_repl(warnings: bool = True, read: Optional[Callable[[str], str]] = None, quiet: bool = False,
             input: Any = None, output: Any = None, version: str = "(development)",
             settings: Optional[dict[str, Any]] = None) -> int:
    """Run the shell.  ``read`` (a replacement for :func:`input`) gives the plain line-by-line loop;
    otherwise prompt_toolkit on the terminal, or on ``input``/``output`` (tests pass a pipe input
    and a ``DummyOutput``); ``version`` is the one the banner shows; ``settings``: the interpreter's
    (mech --format).  Returns the exit status."""
    shell = Shell(warnings, settings=settings)
    if not quiet:
        shell.out.write(BANNER.format(version=version) + "\n")
    if read is None and input is None and (not _isatty(sys.stdout) or os.environ.get("TERM") == "dumb"):
        try:
            importlib.import_module("readline")  # line editing for input()
        except ImportError:
            pass
        read = builtins.input
    if read is not None:
        return _plain_loop(shell, read)
    return prompt_loop(shell, prompt_session(shell, input=input, output=output))


def prompt_loop(shell: Shell, session: Any) -> int:
    """Read inputs with the prompt_toolkit ``session`` and run them until Ctrl-D or ``quit;``."""
    while True:
        try:
            text = session.prompt(shell.prompt())
        except KeyboardInterrupt:
            continue
        except EOFError:
            return 0
        try:
            if not shell.run(text):
                return 0
        except KeyboardInterrupt:  # arrived just after the command ended
            shell.interrupted()


def _plain_loop(shell: Shell, read: Callable[[str], str]) -> int:
    buf = ""
    while True:
        try:
            line = read(shell.prompt() if not buf else shell.continuation(len(shell.prompt())))
        except EOFError:
            shell.out.write("\n")
            return 0
        except KeyboardInterrupt:
            shell.out.write("\n")
            buf = ""
            continue
        buf += line + "\n"
        if not is_complete(buf):
            continue
        text, buf = buf, ""
        try:
            if not shell.run(text):
                return 0
        except KeyboardInterrupt:
            shell.interrupted()


def prompt_session(shell: Shell, input: Any = None, output: Any = None) -> Any:
    """The prompt_toolkit session of ``shell``: highlighting, completion, history, key bindings."""
    from prompt_toolkit import PromptSession
    from prompt_toolkit.auto_suggest import AutoSuggestFromHistory
    from prompt_toolkit.history import FileHistory, History, InMemoryHistory
    from prompt_toolkit.lexers import PygmentsLexer

    from .completion import MechCompleter
    from .highlight import MechLexer

    history: History
    path = history_path()
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.touch()
        history = FileHistory(str(path))
    except OSError as e:
        shell.note(f"history is not saved: cannot write {path} ({e.strerror})", shell.err)
        history = InMemoryHistory()
    return PromptSession(
        multiline=True, prompt_continuation=lambda width, line, soft: shell.continuation(width),
        lexer=PygmentsLexer(MechLexer), completer=MechCompleter(lambda: shell.interp),
        complete_while_typing=False, auto_suggest=AutoSuggestFromHistory(), history=history,
        key_bindings=_key_bindings(), bottom_toolbar=shell.toolbar, input=input, output=output)


def _key_bindings() -> Any:
    from prompt_toolkit.filters import Condition, is_searching
    from prompt_toolkit.key_binding import KeyBindings

    kb = KeyBindings()
    blank_before = Condition(lambda: _current_buffer().document.current_line_before_cursor.strip() == "")

    @kb.add("enter", filter=~is_searching)
    def _enter(event: Any) -> None:
        buf = event.current_buffer
        if buf.complete_state is not None and buf.complete_state.current_completion is not None:
            buf.complete_state = None          # Enter takes the highlighted completion
            return
        doc = buf.document
        if is_complete(doc.text) and ("\n" not in doc.text or doc.text_after_cursor.strip() == ""):
            buf.validate_and_handle()
            return
        line = doc.current_line_before_cursor
        indent = re.match(r"[ \t]*", line).group(0)  # type: ignore[union-attr]
        if line.rstrip().endswith(("{", "(")):
            indent += _INDENT
        buf.insert_text("\n" + indent)

    @kb.add("escape", "enter", filter=~is_searching)
    def _run_anyway(event: Any) -> None:
        event.current_buffer.validate_and_handle()

    @kb.add("tab", filter=blank_before)
    def _indent(event: Any) -> None:
        event.current_buffer.insert_text(_INDENT)

    @kb.add("}", filter=blank_before)
    def _dedent(event: Any) -> None:
        buf = event.current_buffer
        line = buf.document.current_line_before_cursor
        buf.delete_before_cursor(min(len(line), len(_INDENT)))
        buf.insert_text("}")

    return kb


def _current_buffer() -> Any:
    from prompt_toolkit.application.current import get_app
    return get_app().current_buffer
