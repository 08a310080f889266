"""Modules imported on their first use (start-up time, issue 20).

``defer("flint")`` puts a stand-in for python-flint in ``sys.modules``: ``import flint`` then costs
nothing, and the first attribute read (``flint.fmpq``, ``from flint import nmod``, a submodule's
import) imports the real module, copies its namespace into the stand-in (later reads are plain
dictionary look-ups, as on a module) and runs the functions given to :func:`when_loaded`.  A script
without a ring never loads python-flint (about 50 ms)."""
from __future__ import annotations

import importlib
import sys
import threading
import types
from typing import Any, Callable

_HOOKS: dict[str, list[Callable[[], None]]] = {}
_LOCK = threading.RLock()


class _Deferred(types.ModuleType):
    """A module not imported yet: its first attribute read imports it."""

    def __getattr__(self, name: str) -> Any:
        return getattr(_load(self), name)


def defer(name: str) -> None:
    """Import the module ``name`` on its first use (no effect when it is imported already)."""
    if name not in sys.modules:
        sys.modules[name] = _Deferred(name)


def loaded(name: str) -> bool:
    """Whether the module ``name`` is imported (not only deferred)."""
    return name in sys.modules and type(sys.modules[name]) is not _Deferred


def load(name: str) -> types.ModuleType:
    """The module ``name``, imported now if it was deferred."""
    module = sys.modules.get(name)
    if type(module) is _Deferred:
        return _load(module)
    return importlib.import_module(name)


def when_loaded(name: str, hook: Callable[[], None]) -> None:
    """Run ``hook`` once the module ``name`` is imported (now, if it is)."""
    with _LOCK:
        if type(sys.modules.get(name)) is _Deferred:
            _HOOKS.setdefault(name, []).append(hook)
            return
    hook()


def _load(stand_in: _Deferred) -> types.ModuleType:
    name = stand_in.__name__
    with _LOCK:
        real = sys.modules.get(name)
        if real is stand_in or real is None:
            sys.modules.pop(name, None)
            try:
                real = importlib.import_module(name)
            except BaseException:
                sys.modules[name] = stand_in
                raise
            stand_in.__dict__.update(real.__dict__)
            for hook in _HOOKS.pop(name, []):
                hook()
    return real
