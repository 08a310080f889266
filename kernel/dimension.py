"""Krull dimension and independent sets from leading monomials of a Gröbner basis.

A set ``S`` of variables is independent modulo ``I`` when no leading monomial of a
Gröbner basis of ``I`` lies in ``K[S]``; ``dim K[x]/I`` is the size of a largest one.
"""
from __future__ import annotations

from typing import Sequence

from .order import Exp


def _supports(lms: Sequence[Exp]) -> list[int]:
    """Support bitmasks of the leading monomials, minimal under inclusion."""
    masks = {sum(1 << i for i, v in enumerate(e) if v) for e in lms}
    return [m for m in masks if not any(o != m and o & m == o for o in masks)]


def independent_sets(lms: Sequence[Exp], nvars: int, maximal_only: bool = True) -> list[frozenset[int]]:
    """Independent sets of variable indices, largest first.

    With ``maximal_only`` the result lists every independent set of maximal size
    (the sets giving the dimension); otherwise every inclusion-maximal one.
    Empty list for the unit ideal (a constant leading monomial).
    """
    supports = _supports(lms)
    if 0 in supports:
        return []
    found: list[int] = []

    def grow(chosen: int, start: int) -> None:
        extended = False
        for i in range(start, nvars):
            m = chosen | (1 << i)
            if all(s & ~m for s in supports):  # no support inside m
                extended = True
                grow(m, i + 1)
        if not extended or not maximal_only:
            if not any(f & chosen == chosen for f in found):
                found.append(chosen)

    grow(0, 0)
    sets = [frozenset(i for i in range(nvars) if m >> i & 1) for m in found]
    sets = [s for s in sets if not any(s < t for t in sets)]
    if maximal_only and sets:
        best = max(len(s) for s in sets)
        sets = [s for s in sets if len(s) == best]
    return sorted(set(sets), key=lambda s: (-len(s), sorted(s)))


def krull_dim(lms: Sequence[Exp], nvars: int) -> int:
    """``dim K[x]/I`` from the leading monomials of a Gröbner basis; -1 for the unit ideal."""
    supports = _supports(lms)
    if 0 in supports:
        return -1
    best = 0

    def grow(chosen: int, size: int, start: int) -> None:
        nonlocal best
        best = max(best, size)
        if size + (nvars - start) <= best:
            return
        for i in range(start, nvars):
            m = chosen | (1 << i)
            if all(s & ~m for s in supports):
                grow(m, size + 1, i + 1)

    grow(0, 0, 0)
    return best
