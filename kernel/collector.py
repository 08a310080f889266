"""Python's cyclic garbage collector around long computations.

The engines, the interpreter and the analysis allocate many short-lived objects that make no cycles
(freed by reference counting); each collection still walks the young objects and, through the older
generations, every object of the session (parser tables, values).  These context managers pause or
thin out the collections and restore the previous setting on exit, also on errors."""
from __future__ import annotations

import gc
from contextlib import contextmanager
from typing import Iterator

__all__ = ["paused", "relaxed"]


@contextmanager
def paused() -> Iterator[None]:
    """The collector disabled (F4 on noon-5 spent about half its time in collections)."""
    was = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was:
            gc.enable()


@contextmanager
def relaxed(young: int) -> Iterator[None]:
    """The young generation collected every ``young`` allocations (Python's default: 700) unless
    it already is at least that rarely; garbage is still collected, in larger batches."""
    old = gc.get_threshold()
    if old[0] >= young:
        yield
        return
    gc.set_threshold(young, *old[1:])
    try:
        yield
    finally:
        gc.set_threshold(*old)
