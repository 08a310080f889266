"""Progress of long computations: which stage runs and how far it is.

A listener is a callable taking an :class:`Event`; :func:`listening` installs one for a dynamic
extent (a context variable: each thread and each asyncio task has its own).  Code that may run
long opens a :func:`stage` (``with stage("decomposition", total=3) as s: ... s.step(k, "...")``)
or calls :func:`report`; with nobody listening both cost one context-variable lookup.  Stages
nest: an event carries the names of the stages around it (``path``).  The kernel imports nothing
above it; the language renders events (``mech.dsl.progress``), the Python API passes a callback
(``mech.Session(progress=...)``)."""
from __future__ import annotations

import contextlib
import time
from contextvars import ContextVar
from dataclasses import dataclass
from typing import Callable, Iterator, Optional


@dataclass(frozen=True)
class Event:
    """One progress event.  ``kind``: ``"start"`` (a stage opens), ``"step"`` (it advanced:
    ``done`` of ``total`` steps, ``detail`` saying what runs now) or ``"end"`` (it closed;
    ``status``: ``"done"``, ``"failed"``, ``"budget"`` (its time budget ran out, the caller
    goes on with another strategy) or ``"interrupted"``).  ``path`` names the enclosing stages,
    outermost first; ``elapsed`` is the stage's wall time so far in seconds."""

    kind: str
    stage: str
    path: tuple[str, ...] = ()
    done: Optional[int] = None
    total: Optional[int] = None
    detail: str = ""
    elapsed: float = 0.0
    status: str = ""


Listener = Callable[[Event], None]
_LISTENER: ContextVar[Optional[Listener]] = ContextVar("mech_progress_listener", default=None)
_PATH: ContextVar[tuple[str, ...]] = ContextVar("mech_progress_path", default=())


@contextlib.contextmanager
def listening(listener: Optional[Listener]) -> Iterator[None]:
    """Send the events of the ``with`` block to ``listener`` (None: to nobody)."""
    token = _LISTENER.set(listener)
    try:
        yield
    finally:
        _LISTENER.reset(token)


def active() -> bool:
    """Whether anyone listens (to skip preparing details nobody will read)."""
    return _LISTENER.get() is not None


class Stage:
    """An open stage (what :func:`stage` yields): :meth:`step` reports its advance."""

    __slots__ = ("name", "total", "start", "listener", "path", "status")

    def __init__(self, name: str, total: Optional[int], listener: Optional[Listener]) -> None:
        self.name, self.total, self.listener = name, total, listener
        self.start = time.monotonic()
        self.path = _PATH.get()
        self.status = "done"

    def step(self, done: Optional[int] = None, detail: str = "", total: Optional[int] = None) -> None:
        """``done`` of ``total`` (default: the stage's) steps finished; ``detail``: what runs now."""
        if self.listener is not None:
            if total is not None:
                self.total = total
            self.listener(Event("step", self.name, self.path, done, self.total, detail,
                                time.monotonic() - self.start))


@contextlib.contextmanager
def stage(name: str, total: Optional[int] = None, detail: str = "") -> Iterator[Stage]:
    """A stage named ``name`` (``total`` steps if known) for the ``with`` block.  It ends
    ``"done"``, or with the status set on it (``s.status = "budget"``), or ``"interrupted"``
    (a time limit, Ctrl-C) or ``"failed"`` (another exception) when the block raises."""
    listener = _LISTENER.get()
    s = Stage(name, total, listener)
    if listener is None:
        yield s
        return
    listener(Event("start", name, s.path, 0 if total else None, total, detail))
    token = _PATH.set(s.path + (name,))
    try:
        yield s
    except Exception:
        s.status = "failed"
        raise
    except BaseException:
        s.status = "interrupted"
        raise
    finally:
        _PATH.reset(token)
        listener(Event("end", name, s.path, s.total, s.total, "", time.monotonic() - s.start, s.status))


def report(name: str, done: Optional[int] = None, total: Optional[int] = None, detail: str = "") -> None:
    """A step event of stage ``name`` without opening it (for loops that know their count)."""
    listener = _LISTENER.get()
    if listener is not None:
        listener(Event("step", name, _PATH.get(), done, total, detail))
