"""Buchberger's algorithm with the Gebauer–Möller pair criteria and the sugar selection
strategy, and reduction of polynomials, on monomials packed into integers
(:class:`~.monomials.Packing`: a product of monomials is a sum of integers, the ordering compares
integers, divisibility is one masked subtraction).  A packing too narrow for a new monomial is
widened and the computation run again (:func:`packed`).

Polynomials are ``{packed monomial: coefficient}`` dicts inside, ``{exponent: coefficient}``
dicts outside; the orderings are global.
"""
from __future__ import annotations

import heapq
from typing import Any, Callable, Sequence

from .monomials import Packing, packing
from .poly import Exp, Poly, PolyRing


class Overflow(Exception):
    """A monomial outgrew the fields of its packing (start again with a wider one)."""


_INF = float("inf")


class TooLong(Exception):
    """Buchberger's algorithm reduced more S-polynomials than its budget allowed."""


PAIR_WORK = 2
"""Toward a budget, each S-polynomial counts this many reducer terms per basis element (its
reducer search and pair update loop over them): systems whose S-polynomials mostly reduce to
zero would otherwise spend their budget's worth of terms several times over in time
(benchmarks/cases.py's block (dp(3),dp(2)): 163 reductions, 89 to zero, 4775 terms)."""


def packed(ring: PolyRing, polys: Sequence[dict[Exp, Any]], run: Callable[[Packing], Any], maxdeg: int = 8) -> Any:
    """``run(packing)`` with a packing of the ring's ordering wide enough for ``polys`` (and
    degree ``maxdeg``), widened and run again whenever a monomial overflows it."""
    maxdeg = max(maxdeg, 2 * max((sum(e) for p in polys for e in p), default=0))
    while True:
        try:
            return run(packing(ring.order, maxdeg))
        except Overflow:
            maxdeg *= 4


def pack(pk: Packing, p: dict[Exp, Any]) -> dict[int, Any]:
    """A polynomial with packed monomials."""
    pk_pack = pk.pack
    return {pk_pack(e): c for e, c in p.items()}


def unpack(pk: Packing, p: dict[int, Any]) -> dict[Exp, Any]:
    """A polynomial with exponent tuples."""
    pk_unpack = pk.unpack
    return {pk_unpack(m): c for m, c in p.items()}


class Reducer:
    """A set of reducers: packed polynomials with their leading monomials."""

    def __init__(self, pk: Packing, polys: Sequence[dict[int, Any]] = ()) -> None:
        self.guard = pk.guard
        self.work = 0  # terms of the reducers used so far (in 64-bit words of the multiplier)
        self.limit: float = _INF  # TooLong beyond this much work
        self.items: list[tuple[int, dict[int, Any]]] = []
        for p in polys:
            self.add(p)

    def add(self, p: dict[int, Any]) -> None:
        self.items.append((max(p), p))

    def find(self, m: int) -> tuple[int, dict[int, Any]] | None:
        g = self.guard
        mg = m | g
        for lm, p in self.items:
            if (mg - lm) & g == g:
                return lm, p
        return None

    def reduce(self, f: dict[int, Any], full: bool = True) -> dict[int, Any]:
        """Normal form of ``f``; ``full`` reduces every term, otherwise only the top."""
        if not f:
            return {}
        guard = self.guard
        p = dict(f)
        heap = [-m for m in p]  # the largest monomial first
        heapq.heapify(heap)
        result: dict[int, Any] = {}
        while heap:
            m = -heapq.heappop(heap)
            c = p.get(m)
            if c is None:
                continue
            while heap and heap[0] == -m:
                heapq.heappop(heap)
            hit = self.find(m)
            if hit is None:
                del p[m]
                result[m] = c
                if not full:
                    result.update(p)
                    return result
                continue
            lm, g = hit
            shift = m - lm
            factor = c / g[lm]
            self.work += len(g)
            if self.work > self.limit:
                raise TooLong
            if self.limit != _INF and hasattr(factor, "height_bits"):
                self.work += len(g) * (factor.height_bits() >> 6)
            subtract_shifted(p, heap, g, shift, factor, guard)
        return result


def subtract_shifted(p: dict[int, Any], heap: list[int], g: dict[int, Any], shift: int, factor: Any,
                     guard: int) -> None:
    """``p -= factor * x^shift * g`` on packed monomials, in place; monomials new to ``p`` go on
    ``heap`` (negated: a max-heap); :class:`Overflow` when one leaves the packing."""
    for ge, gc in g.items():
        te = ge + shift
        v = p.get(te)
        if v is None:
            if te & guard:
                raise Overflow
            p[te] = -factor * gc
            heapq.heappush(heap, -te)
        else:
            v = v - factor * gc
            if v == 0:
                del p[te]
            else:
                p[te] = v


def _monic(p: dict, lm: Any) -> dict:
    inv = 1 / p[lm]
    return {e: c * inv for e, c in p.items()}


def buchberger(gens: Sequence[Poly], ring: PolyRing, budget: int | None = None) -> list[dict[Exp, Any]]:
    """A (non-reduced) Gröbner basis as dicts, by Buchberger's algorithm with the
    Gebauer–Möller criteria and the sugar strategy; :class:`TooLong` once the reductions
    have used more than ``budget`` terms of reducers (if given; each S-polynomial counts
    :data:`PAIR_WORK` terms per basis element more)."""
    polys = [g.terms for g in gens if g.terms]
    return packed(ring, polys, lambda pk: [unpack(pk, b) for b in _buchberger(polys, pk, budget)])


def _buchberger(polys: Sequence[dict[Exp, Any]], pk: Packing, budget: int | None = None) -> list[dict[int, Any]]:
    basis: list[dict[int, Any]] = []
    lms: list[int] = []
    sugar: list[int] = []
    active: list[bool] = []
    pairs: list[tuple[int, int, int, int]] = []  # (sugar, lcm, i, j): ``min`` is the next pair
    reducer = Reducer(pk)
    if budget is not None:
        reducer.limit = budget
    degree = pk.degree

    def update(h: dict[int, Any], s: int) -> None:
        nonlocal pairs
        hlm = max(h)
        hdeg = degree(hlm)
        basis.append(h)
        lms.append(hlm)
        sugar.append(s)
        active.append(True)
        reducer.add(h)
        pairs = pair_update(pk, lms, active, pairs,
                            lambda i, d: max(sugar[i] + d - degree(lms[i]), s + d - hdeg))

    for g in polys:
        r = reducer.reduce(pack(pk, g))
        if r:
            update(_monic(r, max(r)), sum(max(g, key=sum)))
    while pairs:
        best = min(pairs)
        pairs.remove(best)
        ps, lc, i, j = best
        reducer.work += PAIR_WORK * len(basis)
        r = reducer.reduce(_spoly(basis[i], lms[i], basis[j], lms[j], lc))
        if r:
            if len(r) == 1 and 0 in r:  # a nonzero constant: the unit ideal
                return [_monic(r, 0)]
            update(_monic(r, max(r)), ps)
    return [b for b, a in zip(basis, active) if a]


def pair_update(pk: Packing, lms: list[int], active: list[bool], pairs: list[tuple],
                weight: Callable[[int, int], int]) -> list[tuple]:
    """The pairs after the element with leading monomial ``lms[-1]`` joined the basis, by the
    Gebauer–Möller criteria; deactivates the elements whose leading monomial it divides.

    Pairs are ``(weight, lcm, i, j)``, ``weight(i, degree of the lcm)`` the new pair's weight
    (its sugar, or its degree); entries with ``j < 0`` (generators waiting) are kept as they are.
    New pairs: criterion M/F (keep one pair per lcm, none when the lcm properly divides another
    new pair's, none for an lcm reached by a coprime pair: the product criterion); old pairs:
    criterion B."""
    guard, degree, divides_, lcm = pk.guard, pk.degree, pk.divides, pk.lcm
    k = len(lms) - 1
    hlm = lms[k]
    hdeg = degree(hlm)
    new = []
    for i in range(k):
        if active[i]:
            lc = lcm(lms[i], hlm)
            if lc & guard:
                raise Overflow
            new.append((weight(i, degree(lc)), lc, i, k))
    lcms = {a[1] for a in new}
    kept: dict[int, tuple] = {}
    coprime = set()
    for a in new:
        lc = a[1]
        if lc in kept or lc in coprime or any(b != lc and divides_(b, lc) for b in lcms):
            continue
        if degree(lc) == degree(lms[a[2]]) + hdeg:
            coprime.add(lc)
            kept.pop(lc, None)
        else:
            kept[lc] = a
    old = [a for a in pairs
           if a[3] < 0 or not (divides_(hlm, a[1]) and lcm(lms[a[2]], hlm) != a[1]
                               and lcm(lms[a[3]], hlm) != a[1])]
    for i in range(k):
        if active[i] and divides_(hlm, lms[i]):
            active[i] = False
    return old + list(kept.values())


def _spoly(f: dict[int, Any], lf: int, g: dict[int, Any], lg: int, lc: int) -> dict[int, Any]:
    sf, sg = lc - lf, lc - lg
    cf, cg = f[lf], g[lg]
    out = {e + sf: c * cg for e, c in f.items()}
    for e, c in g.items():
        te = e + sg
        v = out.get(te)
        v = -c * cf if v is None else v - c * cf
        if v == 0:
            out.pop(te, None)
        else:
            out[te] = v
    return out


def reduce_basis(basis: Sequence[dict[Exp, Any]], ring: PolyRing) -> list[dict[Exp, Any]]:
    """The reduced Gröbner basis (monic, minimal, tails reduced) of a Gröbner basis, sorted by
    increasing leading monomial."""
    return packed(ring, basis, lambda pk: [unpack(pk, b) for b in _reduce_basis(basis, pk)])


def _reduce_basis(basis: Sequence[dict[Exp, Any]], pk: Packing) -> list[dict[int, Any]]:
    """The elements of a minimal basis by increasing leading monomial, each tail reduced by
    the elements before it, already reduced (a leading monomial dividing a term is at most
    that term, so the later ones never apply; the reduced basis is unique, so this is the
    basis reducing by all others gives, with less work: reduced reducers bring no terms that
    reduce again)."""
    items = [(max(b), b) for b in (pack(pk, b) for b in basis if b)]
    minimal = [(lm, b) for idx, (lm, b) in enumerate(items)
               if not any(pk.divides(l2, lm) and (l2 != lm or j < idx)
                          for j, (l2, _) in enumerate(items) if j != idx)]
    minimal.sort(key=lambda t: t[0])
    done = Reducer(pk)
    out = []
    for lm, b in minimal:
        r = done.reduce({e: c for e, c in b.items() if e != lm})
        r[lm] = b[lm]
        r = _monic(r, lm)
        done.add(r)
        out.append(r)
    return out
