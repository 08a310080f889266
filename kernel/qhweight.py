"""Weights that make an ideal's generators quasi-homogeneous (Singular's ``qhweight``).

A weight vector w makes f quasi-homogeneous when every term of f has the same weighted degree, that is
when w is orthogonal to the differences between the exponent of f's leading term and those of its other
terms.  Those differences form a linear system; its echelon form over Q names pivot and free variables.
As Singular does, variables before the first pivot get weight 0 and the others a positive integer
solution with the smallest sum (lexicographically smallest among equal sums); with one free variable
that is the primitive kernel vector (free entry positive, whatever the pivots' signs).  No difference
at all, or no free variable after the first pivot, gives the zero vector.
"""
from __future__ import annotations

import itertools
from fractions import Fraction
from math import gcd, lcm
from typing import Optional, Sequence

SEARCH_LIMIT = 200_000  # free-value vectors tried before settling for the sum of the kernel's basis


def difference_rows(polys: Sequence) -> list[list[int]]:
    """exp(lead) - exp(t) for every other term t of every generator (terms in the ring's ordering)."""
    rows = []
    for f in polys:
        terms = [e for e, _ in f.sorted_terms()]
        for e in terms[1:]:
            rows.append([a - b for a, b in zip(terms[0], e)])
    return rows


def _echelon(rows: list[list[int]], n: int) -> tuple[list[list[Fraction]], list[int]]:
    """Reduced row echelon form over Q and its pivot columns."""
    m = [[Fraction(x) for x in r] for r in rows]
    pivots: list[int] = []
    r = 0
    for c in range(n):
        k = next((i for i in range(r, len(m)) if m[i][c]), None)
        if k is None:
            continue
        m[r], m[k] = m[k], m[r]
        piv = m[r][c]
        m[r] = [x / piv for x in m[r]]
        for i in range(len(m)):
            if i != r and m[i][c]:
                f = m[i][c]
                m[i] = [a - f * b for a, b in zip(m[i], m[r])]
        pivots.append(c)
        r += 1
    return m[:r], pivots


def _solution(ech: list[list[Fraction]], pivots: list[int], free: list[int], values: Sequence[int],
              n: int) -> list[Fraction]:
    w = [Fraction(0)] * n
    for c, v in zip(free, values):
        w[c] = Fraction(v)
    for row, p in zip(ech, pivots):
        w[p] = -sum(row[c] * w[c] for c in free)
    return w


def _primitive(w: Sequence[Fraction]) -> list[int]:
    den = lcm(*(x.denominator for x in w))
    ints = [int(x * den) for x in w]
    g = gcd(*ints) or 1
    return [x // g for x in ints]


def qh_weights(polys: Sequence, n: int) -> list[int]:
    """Singular's qhweight of the generators ``polys`` of a ring with ``n`` variables."""
    rows = difference_rows(polys)
    if not rows:
        return [0] * n
    ech, pivots = _echelon(rows, n)
    free = [c for c in range(pivots[0] + 1, n) if c not in pivots]
    if not free:
        return [0] * n
    if len(free) == 1:
        return _primitive(_solution(ech, pivots, free, [1], n))
    best = _smallest_positive(ech, pivots, free, n)
    if best is None:  # no positive solution found: the sum of the kernel's basis vectors
        best = [sum(col) for col in zip(*(_solution(ech, pivots, [c], [1], n) for c in free))]
    return _primitive(best)


def _smallest_positive(ech: list[list[Fraction]], pivots: list[int], free: list[int],
                       n: int) -> Optional[list[Fraction]]:
    """The integer solution with positive entries after the first pivot and the smallest sum, searched
    by increasing sum of the free entries (the full sum is at least that)."""
    best: Optional[list[Fraction]] = None
    tried = 0
    k = len(free)
    for s in itertools.count(k):
        if best is not None and s >= sum(best):
            return best
        for values in _compositions(s, k):
            tried += 1
            if tried > SEARCH_LIMIT:
                return best
            w = _solution(ech, pivots, free, values, n)
            if all(x.denominator == 1 and x > 0 for x in w[pivots[0]:]):
                if best is None or (sum(w), w) < (sum(best), best):
                    best = w


def _compositions(s: int, k: int):
    """Vectors of k positive integers with sum s."""
    if k == 1:
        yield (s,)
        return
    for first in range(1, s - k + 2):
        for rest in _compositions(s - first, k - 1):
            yield (first,) + rest
