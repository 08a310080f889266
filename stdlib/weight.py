"""``weight(I)``: Singular's "optimal" weight vector of the variables for an ideal, the weights that make
the generators as close to weighted-homogeneous as a bounded integer search can.

The search follows the description of Singular's ecart-weight heuristic: each generator with at least
two terms contributes the spread of the weighted degrees of its terms; the functional to minimise is

    F(w) = sum_i (max_i / m_i)^2 * h / (w_1 * ... * w_n)^(2/n)

where max_i is the largest weighted degree of generator i, m_i its largest ordinary degree, and h a
penalty ``(1 - g^2) / 0.75`` applied when every generator is nearly homogeneous (g = the smallest ratio
min_i / max_i, when g > 1/2).  A first search enumerates every integer vector with entries >= 1 and
sum at most n + 6 + 21 div n (the last entry taking the rest), keeping the first strict minimum; the
best vector is scaled by 16 and a descent then lowers one or two entries at a time while F decreases.
If no vector beats the all-ones vector, the answer is all ones; else the best vector divided by the gcd
of its entries.  Floating point is IEEE double as in the original, so ties break the same way.
"""
from __future__ import annotations

import math
from functools import reduce
from typing import Sequence

from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec

Exp = Sequence[int]


class _Search:
    """The exponent matrix of the generators with >= 2 terms and the running weighted degrees."""

    def __init__(self, polys: list[list[Exp]], n: int) -> None:
        self.n = n
        self.lens = [len(p) for p in polys]
        self.cols = [[e[v] for p in polys for e in p] for v in range(n)]  # exponent of variable v per term
        self.deg = [0] * sum(self.lens)
        maxdeg = []
        k = 0
        for ln in self.lens:
            tot = [sum(self.cols[v][k + j] for v in range(n)) for j in range(ln)]
            maxdeg.append(max(tot))
            k += ln
        self.rel = [1.0 / float(m * m) for m in maxdeg]
        self.expo = 2.0 / n

    def add(self, v: int, c: int) -> None:
        col = self.cols[v - 1]
        self.deg = [d + c * a for d, a in zip(self.deg, col)]

    def functional(self, wx: float) -> float:
        gfmax, ghom, k = 0.0, 1.0, 0
        for ln, r in zip(self.lens, self.rel):
            part = self.deg[k:k + ln]
            k += ln
            lo, hi = min(part), max(part)
            ratio = float(lo) / float(hi)
            if ratio < ghom:
                ghom = ratio
            gfmax += float(hi * hi) * r
        if ghom > 0.5:
            gfmax *= (1.0 - ghom * ghom) / 0.75
        return gfmax / math.pow(wx, self.expo)


def _first_search(S: _Search, fopt: float) -> tuple[float, list[int]]:
    """Enumerate the integer vectors (entries >= 1, sum <= n + 6 + 21 div n, the last entry the rest)."""
    n = S.n
    xn = n + 6 + 21 // n
    x = [0] * (n + 1)
    y = [0] * n
    pr = [1.0] * n
    best: list[int] = []
    fy = fopt
    t = 1
    while True:
        while t < n:
            xx = x[t] + 1
            wx = pr[t - 1] * float(xx)
            y1 = y[t - 1] + xx
            if y1 + n - t <= xn:
                pr[t], y[t], x[t] = wx, y1, xx
                if xx > 1:
                    S.add(t, 1)
                t += 1
            else:
                xx = x[t] - 1
                x[t] = 0
                if xx:
                    S.add(t, -xx)
                t -= 1
                if t == 0:
                    return fy, best
        xx = xn - y[t - 1]
        wx = pr[t - 1] * float(xx)
        x[t] = xx
        xx -= 1
        if xx:
            S.add(t, xx)
        fmax = S.functional(wx)
        if xx:
            S.add(t, -xx)
        if fmax < fy:
            fy = fmax
            best = x[1:]
        t -= 1


def _product(x: list[int]) -> float:
    y = float(x[-1])
    for v in reversed(x[1:-1]):
        y *= float(v)
    return y


def _estimate(S: _Search, x: list[int], wx: float) -> tuple[float, int, int, int]:
    """The best decrease of one entry (s0) or of two (s1, s2) by 1, with its functional."""
    n = S.n
    fo1 = fo2 = 1.0e10
    k0 = k1 = k2 = 0
    for i1 in range(n, 0, -1):
        if x[i1] > 1:
            S.add(i1, -1)
            wx1 = wx - wx / float(x[i1])
            x[i1] -= 1
            fmax = S.functional(wx1)
            if fmax < fo1:
                fo1, k0 = fmax, i1
            for i2 in range(i1, 0, -1):
                if x[i2] > 1:
                    S.add(i2, -1)
                    wx2 = wx1 - wx1 / float(x[i2])
                    fmax = S.functional(wx2)
                    if fmax < fo2:
                        fo2, k1, k2 = fmax, i1, i2
                    S.add(i2, 1)
            S.add(i1, 1)
            x[i1] += 1
    if fo1 < fo2:
        return fo1, k0, k1, k2
    return fo2, 0, k1, k2


def _second_search(S: _Search, x: list[int], fk: float, best: list[int]) -> tuple[float, list[int]]:
    fopt = fk * 0.999999999999
    wx = _product(x)
    while True:
        fx, s0, s1, s2 = _estimate(S, x, wx)
        if fx > fopt:
            if s0:
                x[s0] -= 1
            elif s1:
                x[s1] -= 1
                x[s2] -= 1
            else:
                break
        else:
            fopt = fx
            if s0:
                x[s0] -= 1
                best = x[1:]
                if not s1:
                    break
            elif s1:
                x[s1] -= 1
                x[s2] -= 1
                best = x[1:]
            else:
                break
        if s0:
            S.add(s0, -1)
        else:
            S.add(s1, -1)
            S.add(s2, -1)
        wx = _product(x)
    return fopt, best


def ecart_weights(polys: list[list[Exp]], n: int) -> list[int]:
    """The weight vector for the generators given by their exponent vectors (see the module doc)."""
    polys = [p for p in polys if len(p) > 1]
    if not polys:
        return [1] * n
    S = _Search(polys, n)
    for v in range(1, n + 1):
        S.add(v, 1)
    eps = S.functional(1.0)
    fx, best = _first_search(S, 2.0 * eps)
    if not best:
        best = [1] * n
    x = [0] + [16 * b for b in best]
    S.deg = [0] * len(S.deg)
    for v in range(n, 0, -1):
        S.add(v, x[v])
    fx, best = _second_search(S, x, fx, best)
    if fx >= eps:
        return [1] * n
    g = reduce(math.gcd, best)
    return [b // g for b in best]


@command("weight")
def weight(I: Ideal) -> IntVec:
    """weight(I): weights of the variables making the generators of I as close to weighted-homogeneous
    as Singular's bounded integer search finds (all ones when nothing does better).

    Example:
      ring r = 32003,(x,y,z),dp;
      weight(ideal(x5+y3, z2+xy));
      → 3,5,4
    """
    n = I.ring.nvars
    if not I.gens:
        return IntVec([1] * n)
    return IntVec(ecart_weights([list(p.terms) for p in I.gens if not p.is_zero()], n))
