"""Long python-flint calls in a forked child, so that an interrupt or a limit can stop them.

One call into python-flint (a huge power, gcd or factorization) holds the interpreter until it
returns: neither Ctrl-C nor the limits' watchdog (``mech.dsl.limits``) acts inside C code.  The
interactive front ends (the shell, the Jupyter kernel, ``mech.Session``) set :data:`INTERRUPTIBLE`;
then :func:`call` runs a call whose estimated time reaches :data:`THRESHOLD` seconds in a child
process made by ``os.fork`` (it shares the parent's memory as it was, so the arguments cost nothing
to send) and waits for its result, pickled in pieces into a file in memory.  Waiting is Python code:
Ctrl-C and the statement's time limit reach it at once, the child's memory is checked against the
statement's memory limit, and the child is killed (``SIGKILL``) before the exception goes on.  A
child that dies (GMP aborts when an allocation fails under the address-space cap) is reported as
``MemoryError``.  A statement under limits uses the child also in scripts.  Small calls, other
threads without limits and systems without ``fork`` stay in the process.
"""
from __future__ import annotations

import os
import threading
from typing import Any, Callable, Optional

from . import lazy_modules

#: Estimated seconds from which a call goes to a child (the fork, the pickling of the result and
#: its reading back cost about two conversions of the result; see docs/reliability.md "Limits").
THRESHOLD = 1.0

#: Whether an interactive front end runs in this process (set by the shell, the Jupyter kernel and
#: ``mech.Session``): then calls in the main thread go to a child even without limits.
INTERRUPTIBLE = False

#: Given by ``mech.dsl.limits``: ``() -> (limited, max_rss, locks)``: whether a statement under
#: limits runs in this thread, the resident memory (bytes) it may reach (None: no memory limit),
#: and the locks the watchdog takes before raising into this thread (limits and budgets).
watches: Callable[[], tuple[bool, Optional[int], list]] = lambda: (False, None, [])

POLL = 0.05          # seconds between the parent's checks while it waits
CHUNK = 1 << 16      # items of a dict or list pickled per piece (Ctrl-C is checked between them)


class ChildError(RuntimeError):
    """The child ended without a result (a signal other than the ones of running out of memory)."""


def possible() -> bool:
    """Whether a call may go to a child at all (before any estimate is worth computing)."""
    if not hasattr(os, "fork"):
        return False
    if INTERRUPTIBLE and threading.current_thread() is threading.main_thread():
        return True
    return watches()[0]


def call(estimate: Callable[[], float], fn: Callable[..., Any], *args: Any) -> Any:
    """``fn(*args)``, in a child process when :func:`possible` and ``estimate()`` (its time in
    seconds, a rough guess) reaches :data:`THRESHOLD`; the result must pickle."""
    if not possible() or estimate() < THRESHOLD:
        return fn(*args)
    return _Child(fn, args).result()


class _Child:
    """One forked computation and the parent's side of it."""

    def __init__(self, fn: Callable[..., Any], args: tuple) -> None:
        self.fn, self.args = fn, args
        self.pid = 0
        self.sigint: list[int] = []
        self.previous: Any = None

    def result(self) -> Any:
        import signal
        # what the child imports, imported here: another thread may hold a module's import lock at the fork
        import ctypes  # noqa: F401
        import faulthandler  # noqa: F401
        import pickle  # noqa: F401
        done, alive = os.pipe()  # the child holds ``alive`` open: its end wakes the parent at once
        data = _scratch()        # the result, written by the child in pieces (no pipe ping-pong)
        try:
            if threading.current_thread() is threading.main_thread():
                # Ctrl-C only noted while forking and waiting: raised by _check, where the child is known
                self.previous = signal.getsignal(signal.SIGINT)
                if self.previous is not None:
                    signal.signal(signal.SIGINT, lambda signum, frame: self.sigint.append(signum))
            self._fork(data)
            os.close(alive)
            alive = -1
            self._wait(done)
            return self._read(data)
        finally:
            self._kill()
            for fd in (done, alive, data):
                if fd >= 0:
                    os.close(fd)
            if self.previous is not None:
                signal.signal(signal.SIGINT, self.previous)
                if self.sigint:  # a Ctrl-C after the last check is not lost
                    self.sigint.clear()
                    _deliver(self.previous)

    def _fork(self, data: int) -> None:
        """Fork while the limits' watchdog cannot raise into this thread (it only raises holding
        the statement's lock), so the child's pid is never lost to an exception."""
        locks = watches()[2]
        taken = []
        try:
            for lock in locks:
                lock.acquire()
                taken.append(lock)
            _pending()  # an exception raised just before a lock was taken arrives here, before the fork
            pid = os.fork()
            if pid == 0:
                _run_child(self.fn, self.args, data)
            self.pid = pid
        finally:
            for lock in taken:
                lock.release()

    def _wait(self, done: int) -> None:
        """Until the child has ended (checking for Ctrl-C and the memory limit meanwhile)."""
        import select
        poller = select.poll()
        poller.register(done, select.POLLIN | select.POLLHUP)
        while True:
            self._check()
            if poller.poll(POLL * 1000) and not os.read(done, 1):
                return

    def _read(self, data: int) -> Any:
        """The child's result (or exception) from its pieces, checking for Ctrl-C between them."""
        import pickle
        import signal
        status = self._reap()
        if os.WIFSIGNALED(status) or os.waitstatus_to_exitcode(status) != 0:
            if os.WIFSIGNALED(status) and os.WTERMSIG(status) in (signal.SIGABRT, signal.SIGKILL, signal.SIGSEGV):
                raise MemoryError("the computation ran out of memory")
            raise ChildError(f"the computation ended without a result (status {status})")
        pieces: list[Any] = []
        with os.fdopen(data, "rb", closefd=False) as fh:
            fh.seek(0)
            while head := fh.read(8):
                pieces.append(pickle.loads(fh.read(int.from_bytes(head, "little"))))
                self._check()
        kind, value = pieces[0]
        if kind == "error":
            raise value
        if kind == "value":
            return value
        items = [item for piece in pieces[1:] for item in piece]
        return dict(items) if kind == "dict" else items

    def _check(self) -> None:
        """Ctrl-C noted, or the child above the statement's memory limit: raise (the caller kills it)."""
        if self.sigint:
            self.sigint.clear()
            _deliver(self.previous)
        max_rss = watches()[1]
        if max_rss is not None and self.pid:
            rss = _rss(self.pid)
            if rss is not None and rss > max_rss:
                raise MemoryError("the computation exceeded the memory limit")

    def _reap(self) -> int:
        pid, self.pid = self.pid, 0
        return os.waitpid(pid, 0)[1] if pid else 0

    def _kill(self) -> None:
        if self.pid:
            import signal
            try:
                os.kill(self.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            self._reap()


def _pending() -> None:
    """Nothing: entering a Python function lets a pending asynchronous exception arrive."""


def _deliver(previous: Any) -> None:
    """Act on a Ctrl-C noted while waiting as the handler before would have."""
    import signal
    if callable(previous):
        previous(signal.SIGINT, None)
    elif previous == signal.SIG_DFL:
        raise KeyboardInterrupt


def _scratch() -> int:
    """A file descriptor for the child's result: in memory (Linux's ``memfd``) or a temporary file."""
    if hasattr(os, "memfd_create"):
        try:
            return os.memfd_create("mech-offload")
        except OSError:
            pass
    import tempfile
    fh = tempfile.TemporaryFile()
    fd = os.dup(fh.fileno())
    fh.close()
    return fd


def _run_child(fn: Callable[..., Any], args: tuple, write: int) -> None:
    """The child: compute, send the result (or the exception) in pieces, leave without the
    parent's clean-up.  Nested ``finally`` blocks make sure it never returns into the parent's code."""
    try:
        try:
            try:
                _die_with_parent()
                _send(write, fn(*args))
            except BaseException as e:  # noqa: BLE001 - every outcome goes to the parent
                _send(write, e, error=True)
            finally:
                os._exit(0)
        finally:
            os._exit(1)
    finally:
        os._exit(1)


def _send(fd: int, value: Any, error: bool = False) -> None:
    import pickle

    def piece(obj: Any) -> None:
        data = pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL)
        for part in (len(data).to_bytes(8, "little"), data):
            view = memoryview(part)
            while view:
                view = view[os.write(fd, view):]

    if error:
        try:
            piece(("error", value))
        except Exception:  # noqa: BLE001 - an exception that does not pickle
            piece(("error", ChildError(f"{type(value).__name__}: {value}")))
        return
    if isinstance(value, (dict, list)) and len(value) > CHUNK:
        items = list(value.items()) if isinstance(value, dict) else value
        piece(("dict" if isinstance(value, dict) else "list", None))
        for k in range(0, len(items), CHUNK):
            piece(items[k:k + CHUNK])
    else:
        piece(("value", value))


def _die_with_parent() -> None:
    """Ask Linux to kill this child when its parent dies (a killed kernel leaves no computation
    behind); no Python traceback when GMP aborts it."""
    import faulthandler
    faulthandler.disable()
    parent = os.getppid()
    try:
        import ctypes
        ctypes.CDLL(None, use_errno=True).prctl(1, 9)  # PR_SET_PDEATHSIG, SIGKILL
    except (OSError, AttributeError):
        return
    if os.getppid() != parent:
        os._exit(1)


def _rss(pid: int) -> Optional[int]:
    """The resident memory of process ``pid`` in bytes (None where /proc is missing)."""
    try:
        with open(f"/proc/{pid}/statm", "rb") as fh:
            return int(fh.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return None


def _register_pickling() -> None:
    """python-flint's ``nmod``, polynomials and matrices do not pickle by themselves: by their
    values (the results of :mod:`.offload_exact`)."""
    import copyreg

    import flint
    copyreg.pickle(flint.nmod, lambda c: (flint.nmod, (int(c), c.modulus())))
    copyreg.pickle(flint.fmpz_poly, lambda p: (flint.fmpz_poly, ([int(c) for c in p.coeffs()],)))
    copyreg.pickle(flint.fmpq_poly, lambda p: (flint.fmpq_poly, ([int(c) for c in p.numer().coeffs()], int(p.denom()))))
    copyreg.pickle(flint.fmpq_mat, lambda m: (flint.fmpq_mat, (m.nrows(), m.ncols(), m.entries())))
    copyreg.pickle(flint.fmpz_mat, lambda m: (flint.fmpz_mat, (m.nrows(), m.ncols(), [int(x) for x in m.entries()])))


lazy_modules.when_loaded("flint", _register_pickling)
