"""The exact number of real circuits of a one-dimensional motion mode, computed once: the report's
real answers (:mod:`~mech.stdlib.mechanism_real`) and the exported configurations
(:mod:`~mech.stdlib.configurations`) ask for the same modes of the same (cached) analysis.

Kept per (ring, generators): the count, or the refusal of the exact methods (re-raised), or how long
a computation ran (CPU time) before a budget stopped it (a caller with no more time need not start again)."""
from __future__ import annotations

import time
from typing import Any, Sequence

from mech.dsl.limits import LimitExceeded
from mech.kernel.real_roots import RealSolvingError

#: Modes remembered (the oldest go first).
MAX_KEPT = 256

_COUNTS: dict[tuple, Any] = {}   # key -> the count or the RealSolvingError
_TRIED: dict[tuple, float] = {}  # key -> seconds run before a budget stopped it (the longest)


def _key(prime: Sequence[Any], ring: Any) -> tuple:
    return ring, tuple(prime)


def _keep(table: dict, key: tuple, value: Any) -> None:
    if key not in table and len(table) >= MAX_KEPT:
        table.pop(next(iter(table)))
    table[key] = value


def circuit_count(prime: Sequence[Any], ring: Any, is_prime: bool = False) -> int:
    """The number of real circuits of the curve ``V(prime)`` (``prime`` a one-dimensional ideal's
    generators in ``ring``, a prime ideal's when ``is_prime``: a motion mode, whose minimal primes
    are then not computed); raises the exact methods' RealSolvingError when they refuse it."""
    key = _key(prime, ring)
    known = _COUNTS.get(key)
    if isinstance(known, RealSolvingError):
        raise known
    if known is not None:
        return known
    from mech.kernel.real_curve import curve_topology
    start = time.thread_time()
    try:
        n = curve_topology(list(prime), ring, None, is_prime).count
    except RealSolvingError as e:
        _keep(_COUNTS, key, e)
        raise
    except (Exception, KeyboardInterrupt, LimitExceeded):  # nothing learnt about the mode
        raise
    except BaseException:  # a budget's watchdog stopped it
        _keep(_TRIED, key, max(_TRIED.get(key, 0.0), time.thread_time() - start))
        raise
    _keep(_COUNTS, key, n)
    return n


def time_tried(prime: Sequence[Any], ring: Any) -> float:
    """Seconds of CPU time a computation of this count ran before a budget stopped it (0 if none did)."""
    return _TRIED.get(_key(prime, ring), 0.0)
