"""Time and memory limits per statement: ``mech --timeout S --max-memory MB``,
``Session(timeout=S, max_memory=MB)`` and, in the language, ``limits("timeout", S)``.

Each top-level statement (with the procedures and commands it calls) runs under the limits: its
time, and the memory it adds to the process (resident memory beyond what the process held when
the statement started, so that values kept from earlier statements never block later ones).  A
watchdog thread checks the clock and the resident memory while a statement runs and, when a limit
is exceeded, raises :class:`LimitExceeded` in the thread running the statement
(``PyThreadState_SetAsyncExc``: no signals, so any thread works, and the process is never
killed).  The interpreter turns it into ``error: time limit of 5 s exceeded in std`` at the call;
:meth:`Limits.run` then puts the interpreter back as it was before the statement (procedure
frames, basering), so rings and variables stay usable.  A memory limit also lowers the address
space limit (``RLIMIT_AS``) during the statement to the limit (plus ``SLACK``) beyond the current
size: a backstop against single huge allocations in C, which then fail with ``MemoryError`` instead of
exhausting the machine (GMP, inside python-flint, aborts the process when its allocation fails).

Budgets (:func:`within`) run inside a statement on the same watchdog.  A thread holds one pending
asynchronous exception at a time, and one C call (python-flint) may outlast a budget and the
statement's deadline together; so the watchdog never lets the statement's time limit (nor an inner
budget) replace a budget's exception that has not arrived yet: the statement waits, at most
:func:`overrun` seconds past its deadline, and a budget given a ``reserve`` leaves the statement
that many seconds after its exception arrives (to print what was finished), within the same bound.
"""
from __future__ import annotations

import contextlib
import os
import sys
import threading
import time
from typing import Any, Callable, Iterator, Optional

from ..kernel import lazy_modules, offload
from .errors import MechRuntimeError
from .registry import command

POLL = 0.02     # seconds between the watchdog's checks
REFIRE = 1.0    # raise again if the statement is still running this long after the first time
SLACK = 64 << 20  # address space beyond the memory limit: at least this (bytes), or a quarter of the limit

#: The watcher outside the process (``mech/watcher.py``, set in the child it runs a script in): told
#: when each top-level statement under limits begins (``begin(pos, rss)``) and ends (``end()``).
OUTSIDE: Optional[Any] = None

#: Limits for interpreters created without explicit ones (``mech --timeout`` sets them for the REPL).
DEFAULTS: dict[str, Optional[float]] = {"timeout": None, "max_memory": None}


class LimitExceeded(BaseException):
    """Raised asynchronously in the running statement; a BaseException so that no ``except
    Exception`` on the way swallows it (it becomes a :class:`MechLimitError` at the call)."""


class TimeLimitExceeded(LimitExceeded):
    pass


class MemoryLimitExceeded(LimitExceeded):
    pass


class BudgetExceeded(BaseException):
    """Raised asynchronously when a :func:`within` budget runs out (each budget raises its own
    subclass, so nested budgets tell theirs apart; not a :class:`LimitExceeded`: the statement
    goes on)."""


class MechLimitError(MechRuntimeError):
    """A statement ran out of its time or memory (the session stays usable)."""


@contextlib.contextmanager
def default_limits(timeout: Optional[float], max_memory: Optional[float]) -> Iterator[None]:
    """Use these limits for the interpreters created inside the ``with`` block."""
    saved = dict(DEFAULTS)
    DEFAULTS.update(timeout=timeout, max_memory=max_memory)
    try:
        yield
    finally:
        DEFAULTS.update(saved)


#: The smallest memory limit (MB): below it the process's own bookkeeping (a library loaded, the
#: interpreter's caches) would exceed the limit of statements that compute nothing.
MIN_MEMORY = 16


def _positive(value: Optional[float], what: str) -> Optional[float]:
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not 0 <= value < float("inf"):
        raise ValueError(f"{what} must be a nonnegative number (0: no limit)")
    if "memory" in what and 0 < value < MIN_MEMORY:
        raise ValueError(f"{what} must be 0 (no limit) or at least {MIN_MEMORY} MB")
    return value or None


def overrun(timeout: float) -> float:
    """The longest a statement's time limit waits past its deadline for a budget's pending
    exception and the reserve after it (the watcher outside, ``mech.watcher.grace``, waits longer)."""
    return 1.0 + min(timeout, 16.0) / 4


def _seconds(t: float) -> str:
    return f"{t:g}"


class Limits:
    """The limits of one interpreter: ``timeout`` in seconds, ``max_memory`` in MB a statement may
    add to the process (None: none)."""

    def __init__(self, timeout: Optional[float] = None, max_memory: Optional[float] = None) -> None:
        self.timeout = _positive(timeout if timeout is not None else DEFAULTS["timeout"], "timeout")
        self.max_memory = _positive(max_memory if max_memory is not None else DEFAULTS["max_memory"],
                                    "max_memory")

    def run(self, interp: Any, fn: Callable[..., Any], *args: Any) -> Any:
        """``fn(*args)`` under the limits (nested calls run under the outermost one's)."""
        if getattr(_current, "watch", None) is not None or not (self.timeout or self.max_memory):
            return fn(*args)
        saved = (interp.frames, len(interp.frames), interp.ring, interp.source, interp.stmt, interp.argnames)
        watch = _current.watch = _Watch(self.timeout, self.max_memory)
        outside = OUTSIDE if threading.current_thread() is threading.main_thread() else None
        try:
            try:
                _WATCHDOG.arm(watch)
                if outside is not None:
                    node = args[0] if args and hasattr(args[0], "pos") else interp.stmt
                    outside.begin(getattr(node, "pos", None), watch.max_rss - watch.grow if watch.max_rss else 0)
                return fn(*args)
            finally:
                if outside is not None:
                    outside.end()
                late = _WATCHDOG.disarm(watch)
                if late is not None:
                    raise late
        except (LimitExceeded, MemoryError) as e:
            _restore(interp, saved)
            raise limit_error(e) from None
        except MechLimitError:
            _restore(interp, saved)
            raise
        finally:
            _current.watch = None

    def describe(self) -> str:
        t = f"{_seconds(self.timeout)} s" if self.timeout else "none"
        m = f"{_seconds(self.max_memory)} MB" if self.max_memory else "none"
        return f"timeout {t}, max-memory {m} (per statement)"


def remaining() -> Optional[float]:
    """Seconds left before the running statement's time limit (None: no time limit)."""
    watch = getattr(_current, "watch", None)
    if watch is None or watch.deadline is None:
        return None
    return max(0.0, watch.deadline - time.monotonic())


def within(seconds: Optional[float], fn: Callable[..., Any], *args: Any, cpu: bool = False,
           reserve: Optional[float] = None) -> tuple[bool, Any]:
    """``(True, fn(*args))``, or ``(False, None)`` when ``fn`` runs longer than ``seconds``
    (wall time, or with ``cpu`` the CPU time of this thread, which a busy machine does not
    shorten; None: no budget): a watchdog interrupts it with a :class:`BudgetExceeded` of its
    own.  Limits of the statement and outer budgets still apply inside and propagate, except that
    the statement's time limit waits for this budget's exception once raised; ``reserve``: seconds
    the statement keeps after it arrives (for a report of what was done; at most until
    :func:`overrun` past the statement's deadline)."""
    if seconds is None:
        return True, fn(*args)
    own = type("BudgetExceeded", (BudgetExceeded,), {})
    clock = time.monotonic
    if cpu and hasattr(time, "pthread_getcpuclockid"):
        cid = time.pthread_getcpuclockid(threading.get_ident())
        clock = lambda: time.clock_gettime(cid)  # noqa: E731
    watch = _Watch(max(seconds, 0.001), None, own, clock)
    watch.reserve = reserve
    try:
        try:
            _WATCHDOG.arm(watch)
            result = fn(*args)
        finally:
            late = _WATCHDOG.disarm(watch)
        if late is not None and not isinstance(late, own):
            raise late
        return True, result
    except own:
        return False, None


#: Seconds of the statement's time limit a report keeps for its text after the steps it cuts to
#: the limit (mode names, real answers: :func:`cut`).
REPORT_KEEP = 0.5


def cut(seconds: float, keep: float = 0.0) -> float:
    """``seconds``, or less: what is left of the running statement's time limit but ``keep``
    seconds (negative when not even that is left)."""
    left = remaining()
    return seconds if left is None else min(seconds, left - keep)


def limit_error(exc: BaseException, where: str = "") -> MechLimitError:
    """The error the user sees for ``exc`` (a :class:`LimitExceeded` or ``MemoryError``) raised in
    the statement running in this thread; ``where`` names the command it interrupted."""
    watch = getattr(_current, "watch", None)
    if isinstance(exc, TimeLimitExceeded) and watch is not None and watch.timeout:
        msg = f"time limit of {_seconds(watch.timeout)} s exceeded"
    elif watch is not None and watch.max_memory:
        msg = f"memory limit of {_seconds(watch.max_memory)} MB exceeded"
    else:
        msg = "out of memory"
    return MechLimitError(msg + (f" in {where}" if where else ""))


def _restore(interp: Any, saved: tuple) -> None:
    """The interpreter's state as before the statement (an interrupted cleanup may have left
    procedure frames or another basering behind)."""
    frames, depth, ring, source, stmt, argnames = saved
    del frames[depth:]
    interp.frames, interp.ring, interp.source, interp.stmt, interp.argnames = frames, ring, source, stmt, argnames
    interp._loading_lib = ""


# ---------------------------------------------------------------- the watchdog
class _Watch:
    """One armed statement: its thread, deadline, memory limit and address-space backstop."""

    def __init__(self, timeout: Optional[float], max_memory: Optional[float],
                 late: type[BaseException] = TimeLimitExceeded, clock: Callable[[], float] = time.monotonic) -> None:
        self.timeout, self.max_memory = timeout, max_memory
        self.late, self.clock = late, clock  # what the deadline raises; the clock it is measured on
        self.budget = issubclass(late, BudgetExceeded)  # a within() budget (else a statement)
        self.thread = threading.get_ident()
        self.deadline = clock() + timeout if timeout else None
        # a statement's deadline moves for a budget's reserve, never past ``hard``
        self.hard = self.deadline + overrun(timeout) if timeout and not self.budget else self.deadline
        self.reserve: Optional[float] = None  # a budget's: seconds the statement keeps after it
        self.grow = int(max_memory * 2**20) if max_memory else 0   # bytes the statement may add
        if max_memory:  # python-flint loads on first use (~9 MB): not the statement's memory
            lazy_modules.load("flint")
        self.max_rss = (_rss() or 0) + self.grow if max_memory else None
        self.fired = 0.0            # when LimitExceeded was last raised (0: never)
        self.saved_rlimit: Optional[tuple[int, int]] = None
        self.lock = threading.RLock()  # held by the watchdog while it raises, by the owner to end
        self.done = False


_current = threading.local()  # .watch: the statement being watched in this thread


class _Watchdog:
    """One daemon thread for the process, checking every armed statement each ``POLL`` seconds.

    The watched thread never holds a lock the watchdog waits for: an exception raised into it
    while it holds one (e.g. just after acquiring it) would leave that lock held.  It ends its
    watch under the watch's own lock, which the watchdog only ever tries without blocking."""

    def __init__(self) -> None:
        self._wake = threading.Event()
        self._watches: list[_Watch] = []
        self._thread: Optional[threading.Thread] = None
        self._start = threading.Lock()
        self._backstop: Optional[_Watch] = None

    def arm(self, watch: _Watch) -> None:
        with self._start:
            if self._thread is None or not self._thread.is_alive():
                self._thread = threading.Thread(target=self._loop, name="mech-limits", daemon=True)
                self._thread.start()
            if watch.max_rss and self._backstop is None:
                self._lower_rlimit(watch)
        self._watches.append(watch)
        self._wake.set()

    def disarm(self, watch: _Watch) -> Optional[BaseException]:
        """Stop watching; a LimitExceeded (or BudgetExceeded) that arrives meanwhile is returned,
        none is left pending."""
        late = None
        while not watch.done:
            try:
                with watch.lock:
                    if watch.fired and watch.reserve is not None:
                        _grant(watch.reserve)  # before done: the statement's limit waits until then
                    watch.done = True
            except (LimitExceeded, BudgetExceeded) as e:
                late = e
        while True:  # the watchdog raises no more: drop an exception that may still be pending
            try:
                if watch.fired:
                    _async_raise(watch.thread, None)
                break
            except (LimitExceeded, BudgetExceeded) as e:
                late = e
        if watch is self._backstop:
            self._restore_rlimit(watch)
        return late

    def _loop(self) -> None:
        while True:
            try:
                self._wake.clear()
                if not self._watches:
                    self._wake.wait()
                    continue
                self._check()
                time.sleep(POLL)
            except BaseException:  # noqa: BLE001 - e.g. MemoryError under RLIMIT_AS: keep watching
                time.sleep(POLL)

    def _check(self) -> None:
        now = time.monotonic()
        rss = _rss() if any(w.max_rss for w in self._watches) else None
        threads: dict[int, list[_Watch]] = {}
        for w in list(self._watches):
            if w.done:
                self._watches.remove(w)
            else:
                threads.setdefault(w.thread, []).append(w)  # in the order armed: outermost first
        for watches in threads.values():
            self._check_thread(watches, now, rss)

    def _check_thread(self, watches: list[_Watch], now: float, rss: Optional[int]) -> None:
        """The watches of one thread.  It holds one pending exception: a budget's is replaced
        only by an outer budget's (whose caller unwinds the inner one too) or by the memory limit,
        and the statement's time limit waits for it (until :func:`overrun` past its deadline)."""
        statement = next((w for w in watches if not w.budget), None)
        budgets = [w for w in watches if w.budget]
        if statement is None or not statement.fired:
            due = next((b for b in budgets if b.deadline is not None and b.clock() >= b.deadline), None)
            if due is not None and not (due.fired and now - due.fired < REFIRE):
                self._raise(due, due.late, now)
        if statement is None or (statement.fired and now - statement.fired < REFIRE):
            return
        if statement.max_rss and rss is not None and rss > statement.max_rss:
            self._raise(statement, MemoryLimitExceeded, now)
        elif statement.deadline is not None and now >= statement.deadline:
            if now < statement.hard and any(b.fired and not b.done for b in budgets):
                return  # a budget's exception is on its way: its caller reports first
            self._raise(statement, statement.late, now)

    @staticmethod
    def _raise(w: _Watch, exc: type[BaseException], now: float) -> None:
        if not w.lock.acquire(blocking=False):
            return  # its owner is ending the watch
        try:
            if not w.done:
                w.fired = now
                _async_raise(w.thread, exc)
        finally:
            w.lock.release()

    def _lower_rlimit(self, watch: _Watch) -> None:
        try:
            import resource
            soft, hard = resource.getrlimit(resource.RLIMIT_AS)
            size = _vsz()
            if size is None:
                return
            new = size + watch.grow + max(SLACK, watch.grow // 4)
            if hard != resource.RLIM_INFINITY:
                new = min(new, hard)
            if soft == resource.RLIM_INFINITY or new < soft:
                resource.setrlimit(resource.RLIMIT_AS, (new, hard))
                watch.saved_rlimit = (soft, hard)
                self._backstop = watch
        except (ImportError, OSError, ValueError):
            pass

    def _restore_rlimit(self, watch: _Watch) -> None:
        import resource
        self._backstop = None
        if watch.saved_rlimit is not None:
            resource.setrlimit(resource.RLIMIT_AS, watch.saved_rlimit)


def _grant(reserve: float) -> None:
    """The statement running in this thread may go on ``reserve`` seconds from now (within its
    bound), past its deadline if need be: a budget's caller reports what it finished."""
    watch = getattr(_current, "watch", None)
    if watch is not None and watch.deadline is not None:
        watch.deadline = max(watch.deadline, min(time.monotonic() + reserve, watch.hard))


def _async_raise(thread: int, exc: Optional[type]) -> None:
    """Raise ``exc`` in ``thread`` at its next bytecode (None: cancel a pending one)."""
    import ctypes
    ctypes.pythonapi.PyThreadState_SetAsyncExc(ctypes.c_ulong(thread),
                                               ctypes.py_object(exc) if exc is not None else None)


_PAGE = os.sysconf("SC_PAGE_SIZE") if hasattr(os, "sysconf") else 4096


def _statm() -> Optional[list[int]]:
    try:
        with open("/proc/self/statm", "rb") as fh:
            return [int(v) * _PAGE for v in fh.read().split()[:2]]
    except (OSError, ValueError):
        return None


def _rss() -> Optional[int]:
    """The process's resident memory in bytes (None where /proc is missing)."""
    m = _statm()
    return m[1] if m else None


def _vsz() -> Optional[int]:
    m = _statm()
    return m[0] if m else None


_WATCHDOG = _Watchdog()


def _unraisable(args: Any, previous: Callable[[Any], None] = sys.unraisablehook) -> None:
    """The watchdog's exception arrived where Python cannot raise it (a weakref callback such as
    the import system's, a ``__del__``): nothing printed, and it is raised again at the next check."""
    exc, me = args.exc_value, threading.get_ident()
    if not isinstance(exc, (LimitExceeded, BudgetExceeded)):
        previous(args)
        return
    for w in list(_WATCHDOG._watches):
        if w.thread == me and w.fired and isinstance(exc, w.late if w.budget else LimitExceeded):
            w.fired -= REFIRE


sys.unraisablehook = _unraisable


def _offload_state() -> tuple[bool, Optional[int], list]:
    """For :mod:`mech.kernel.offload`: whether a statement under limits runs in this thread, the
    resident memory it may reach, and the locks of the watches on this thread (limits and budgets)."""
    watch = getattr(_current, "watch", None)
    me = threading.get_ident()
    locks = [w.lock for w in list(_WATCHDOG._watches) if w.thread == me and not w.done]
    return watch is not None, watch.max_rss if watch is not None else None, locks


offload.watches = _offload_state


# ---------------------------------------------------------------- the language's command
_NAMES = {"timeout": "timeout", "--timeout": "timeout", "max-memory": "max_memory", "--max-memory": "max_memory"}


@command("limits")
def limits_command(ctx, what: str = "", value: Any = None) -> Any:
    """limits(): the time and memory limits of each statement; limits("timeout", s) sets the
    time limit to s seconds and limits("max-memory", mb) the memory limit to mb MB (0: none);
    limits("timeout") is the current value (0: none).

    Example:
      limits("timeout", 30);
      limits("timeout");
      → 30
      limits("timeout", 0);
    """
    lim: Limits = ctx.limits
    if not what:
        return lim.describe()
    attr = _NAMES.get(what)
    if attr is None:
        raise MechRuntimeError(f'unknown limit "{what}" (limits("timeout", s) or limits("max-memory", mb))')
    if value is None:
        current = getattr(lim, attr) or 0
        return int(current) if float(current).is_integer() else str(current)
    if isinstance(value, str):
        try:
            value = float(value)
        except ValueError:
            raise MechRuntimeError(f'limits("{what}", ...) needs a number of {"seconds" if attr == "timeout" else "MB"}') from None
    try:
        setattr(lim, attr, _positive(value, what))
    except ValueError as e:
        raise MechRuntimeError(f'limits("{what}", ...): {e}') from None
    return None
