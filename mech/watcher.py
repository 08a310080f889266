"""The watcher outside the interpreter: ``mech FILE --timeout S`` (or ``--max-memory MB``) runs the
script in a child process and ends it when one statement overruns its limit by more than a grace.

The limits inside the process (:mod:`mech.dsl.limits`) stop a statement between two Python steps;
one long call into python-flint (a huge power, FGLM's exact solve) holds the interpreter until it
returns.  Here the parent process waits: the child tells it, through a page of shared memory, when
each top-level statement begins (with its position and its resident memory then) and ends.  When a
statement runs ``timeout + GRACE`` seconds, or stays ``MEMORY_GRACE`` seconds above its memory
limit, the parent kills the child and prints the usual error at the statement; output already
printed stays.  A child killed by a signal during a statement with a memory limit (GMP aborts when
its allocation hits the address-space cap) is reported as over its memory limit.
"""
from __future__ import annotations

import mmap
import os
import signal
import struct
import sys
import time
from typing import Callable, Optional

from .dsl import limits
from .dsl.errors import Source
from .dsl.limits import MechLimitError

POLL = 0.05          # seconds between the parent's checks
MEMORY_GRACE = 1.0   # seconds a statement may stay above its memory limit (the child's own check first)
INTERRUPT_GRACE = 2.0  # after Ctrl-C, seconds the child has to stop by itself


def grace(timeout: float) -> float:
    """Seconds past the time limit before the parent steps in (the child's own limit, which gives
    partial reports and may wait ``limits.overrun(timeout)`` past the limit for one, acts first)."""
    return 2.0 + min(timeout, 16.0) / 2


class Beacon:
    """The shared page: a sequence number (odd while the child writes), the start time of the
    running statement (``time.monotonic``; 0: none), its resident memory at the start, its position."""

    FORMAT = struct.Struct("<qdqiiii")

    def __init__(self) -> None:
        self.page = mmap.mmap(-1, mmap.PAGESIZE)  # anonymous and shared: both sides of a fork see it
        self.seq = 0

    def begin(self, pos: Optional[tuple], rss: int) -> None:
        self._write(time.monotonic(), rss, tuple(pos) if pos else (0, 0, 0, 0))

    def end(self) -> None:
        self._write(0.0, 0, (0, 0, 0, 0))

    def _write(self, start: float, rss: int, pos: tuple) -> None:
        self.seq += 1
        self.FORMAT.pack_into(self.page, 0, self.seq, 0.0, 0, 0, 0, 0, 0)  # odd: being written
        self.seq += 1
        self.FORMAT.pack_into(self.page, 0, self.seq, start, rss, *pos)

    def read(self) -> Optional[tuple]:
        """``(start, rss, pos)`` of the running statement, None between statements or mid-write."""
        seq, start, rss, *pos = self.FORMAT.unpack_from(self.page, 0)
        if seq % 2 or not start:
            return None
        return start, rss, tuple(pos)


def run_watched(work: Callable[[], int], name: str, text: str, timeout: Optional[float],
                max_memory: Optional[float]) -> int:
    """``work()`` (running the script ``text`` called ``name``; its exit status) in a child process
    under the watcher; the exit status."""
    if not (timeout or max_memory) or not hasattr(os, "fork"):
        return work()
    beacon = Beacon()
    for stream in (sys.stdout, sys.stderr):
        stream.flush()
    pid = os.fork()
    if pid == 0:  # the child: run, then leave without the parent's clean-up
        status = 1
        try:
            limits.OUTSIDE = beacon
            status = work()
        finally:
            for stream in (sys.stdout, sys.stderr):
                try:
                    stream.flush()
                except (OSError, ValueError):
                    pass
            os._exit(status)
    return _watch(pid, beacon, Source(name, text), timeout, max_memory)


def _watch(pid: int, beacon: Beacon, source: Source, timeout: Optional[float], max_memory: Optional[float]) -> int:
    interrupted: list[float] = []
    previous = signal.signal(signal.SIGINT, lambda *_: interrupted.append(time.monotonic()))
    over_since: Optional[float] = None
    try:
        while True:
            done, status = os.waitpid(pid, os.WNOHANG)
            if done:
                break
            now = time.monotonic()
            state = beacon.read()
            message = None
            if state is not None:
                start, base, pos = state
                if timeout and now - start > timeout + grace(timeout):
                    message = f"time limit of {timeout:g} s exceeded"
                elif max_memory:
                    rss = _rss(pid)
                    if rss is not None and rss - base > max_memory * 2**20:
                        over_since = over_since or now
                        if now - over_since > MEMORY_GRACE:
                            message = f"memory limit of {max_memory:g} MB exceeded"
                    else:
                        over_since = None
            if interrupted and now - interrupted[0] > INTERRUPT_GRACE:
                _kill(pid)
                sys.stdout.flush()
                sys.stderr.write(f"{source.name}: error: interrupted\n")
                return 130
            if message is not None:
                _kill(pid)
                return _report(message, state[2], source)
            time.sleep(POLL)
    finally:
        signal.signal(signal.SIGINT, previous)
    if os.WIFSIGNALED(status):
        state = beacon.read()  # the page outlives the child: was a statement running?
        sig = os.WTERMSIG(status)
        if sig == signal.SIGINT:
            return 130
        if max_memory and state is not None:
            return _report(f"memory limit of {max_memory:g} MB exceeded (the process was ended by signal {sig})",
                           state[2], source)
        sys.stdout.flush()
        sys.stderr.write(f"{source.name}: error: the process was ended by signal {sig}\n")
        return 1
    return os.waitstatus_to_exitcode(status)


def _report(message: str, pos: tuple, source: Source) -> int:
    """Print the limit error at the statement (``pos``: 0s when unknown); exit status 1."""
    from .dsl.ast import Pos
    error = MechLimitError(message + " (stopped from outside: the statement was inside one long computation)",
                           Pos(*pos) if pos[0] else None, source, underline=True)
    sys.stdout.flush()
    sys.stderr.write(error.format())
    return 1


def _kill(pid: int) -> None:
    try:
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
    except (ProcessLookupError, ChildProcessError):
        pass


def _rss(pid: int) -> Optional[int]:
    """The resident memory of process ``pid`` in bytes (None where /proc is missing)."""
    try:
        with open(f"/proc/{pid}/statm", "rb") as fh:
            return int(fh.read().split()[1]) * mmap.PAGESIZE
    except (OSError, ValueError, IndexError):
        return None
