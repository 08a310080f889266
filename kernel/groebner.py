"""Gröbner bases for global orderings: Buchberger's algorithm with the Gebauer–Möller
pair criteria and the sugar selection strategy; normal forms and reduced bases.

The public entry point is :func:`groebner`; engines are registered in :data:`ENGINES`
by name so faster ones (F4) can be swapped in behind the same interface.
"""
from __future__ import annotations

import heapq
from collections import OrderedDict
from typing import Any, Callable, Sequence

from .monomials import Packing
from .poly import Exp, Poly, PolyRing


class OrderingError(ValueError):
    """Raised when an algorithm needs a global ordering and the ring's is not."""


class _Overflow(Exception):
    """A monomial outgrew the fields of its packing (start again with a wider one)."""


def _packed(ring: PolyRing, polys: Sequence[dict[Exp, Any]], run: Callable[[Packing], Any]) -> Any:
    """``run(packing)`` with a packing of the ring's ordering wide enough for ``polys``,
    widened and run again whenever a monomial overflows it."""
    maxdeg = max(8, 2 * max((sum(e) for p in polys for e in p), default=0))
    while True:
        try:
            return run(Packing(ring.order, maxdeg))
        except _Overflow:
            maxdeg *= 4


def _pack(pk: Packing, p: dict[Exp, Any]) -> dict[int, Any]:
    pack = pk.pack
    return {pack(e): c for e, c in p.items()}


def _unpack(pk: Packing, p: dict[int, Any]) -> dict[Exp, Any]:
    unpack = pk.unpack
    return {unpack(m): c for m, c in p.items()}


class _Reducer:
    """A set of reducers: polynomials as ``{packed monomial: coefficient}`` with their
    leading monomials (see :class:`~.monomials.Packing`: a product of monomials is a sum of
    integers, the ordering compares integers, divisibility is one masked subtraction)."""

    def __init__(self, pk: Packing, polys: Sequence[dict[int, Any]] = ()) -> None:
        self.guard = pk.guard
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
            for ge, gc in g.items():
                te = ge + shift
                v = p.get(te)
                if v is None:
                    if te & guard:
                        raise _Overflow
                    p[te] = -factor * gc
                    heapq.heappush(heap, -te)
                else:
                    v = v - factor * gc
                    if v == 0:
                        del p[te]
                    else:
                        p[te] = v
        return result


def _monic(p: dict, lm: Any) -> dict:
    inv = 1 / p[lm]
    return {e: c * inv for e, c in p.items()}


def buchberger(gens: Sequence[Poly], ring: PolyRing) -> list[dict[Exp, Any]]:
    """A (non-reduced) Gröbner basis as dicts, by Buchberger's algorithm with the
    Gebauer–Möller criteria and the sugar strategy."""
    polys = [g.terms for g in gens if g.terms]
    return _packed(ring, polys, lambda pk: [_unpack(pk, b) for b in _buchberger(polys, pk)])


def _buchberger(polys: Sequence[dict[Exp, Any]], pk: Packing) -> list[dict[int, Any]]:
    basis: list[dict[int, Any]] = []
    lms: list[int] = []
    sugar: list[int] = []
    active: list[bool] = []
    pairs: list[tuple[int, int, int, int]] = []  # (sugar, lcm, i, j): ``min`` is the next pair
    reducer = _Reducer(pk)
    guard, degree, divides_, lcm = pk.guard, pk.degree, pk.divides, pk.lcm

    def update(h: dict[int, Any], s: int) -> None:
        nonlocal pairs
        hlm = max(h)
        hdeg = degree(hlm)
        k = len(basis)
        basis.append(h)
        lms.append(hlm)
        sugar.append(s)
        active.append(True)
        reducer.add(h)
        new = []
        for i in range(k):
            if active[i]:
                lc = lcm(lms[i], hlm)
                if lc & guard:
                    raise _Overflow
                d = degree(lc)
                new.append((max(sugar[i] + d - degree(lms[i]), s + d - hdeg), lc, i, k))
        # criterion M / F: keep a pair only if no other new pair's lcm properly divides it,
        # and among equal lcms keep one (none if one of them is coprime: product criterion)
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
        # criterion B on old pairs
        old = [a for a in pairs
               if not (divides_(hlm, a[1]) and lcm(lms[a[2]], hlm) != a[1] and lcm(lms[a[3]], hlm) != a[1])]
        pairs = old + list(kept.values())
        for i in range(k):
            if active[i] and divides_(hlm, lms[i]):
                active[i] = False

    for g in polys:
        r = reducer.reduce(_pack(pk, g))
        if r:
            update(_monic(r, max(r)), sum(max(g, key=sum)))
    while pairs:
        best = min(pairs)
        pairs.remove(best)
        ps, lc, i, j = best
        r = reducer.reduce(_spoly(basis[i], lms[i], basis[j], lms[j], lc))
        if r:
            if len(r) == 1 and 0 in r:  # a nonzero constant: the unit ideal
                return [_monic(r, 0)]
            update(_monic(r, max(r)), ps)
    return [b for b, a in zip(basis, active) if a]


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
    return _packed(ring, basis, lambda pk: [_unpack(pk, b) for b in _reduce_basis(basis, pk)])


def _reduce_basis(basis: Sequence[dict[Exp, Any]], pk: Packing) -> list[dict[int, Any]]:
    items = [(max(b), b) for b in (_pack(pk, b) for b in basis if b)]
    minimal = [(lm, b) for idx, (lm, b) in enumerate(items)
               if not any(pk.divides(l2, lm) and (l2 != lm or j < idx)
                          for j, (l2, _) in enumerate(items) if j != idx)]
    out = []
    for idx, (lm, b) in enumerate(minimal):
        others = _Reducer(pk, [m for j, (_, m) in enumerate(minimal) if j != idx])
        r = others.reduce({e: c for e, c in b.items() if e != lm})
        r[lm] = b[lm]
        out.append((lm, _monic(r, lm)))
    out.sort(key=lambda t: t[0])
    return [b for _, b in out]


ENGINES: dict[str, Callable[[Sequence[Poly], PolyRing], list[dict[Exp, Any]]]] = {
    "buchberger": buchberger,
}
"""Engines by name.  An engine maps nonzero generators and their ring to a Gröbner basis as
``{exponent: coefficient}`` dicts; one whose attribute ``returns_reduced`` is true returns the
reduced basis itself, sorted by increasing leading monomial with each leading exponent first
in its dict (the others are reduced here)."""


def _register_f4() -> None:
    from .f4 import f4, f4_auto
    ENGINES["f4"] = f4
    ENGINES["auto"] = f4_auto


_register_f4()


def groebner(gens: Sequence[Poly], ring: PolyRing | None = None, engine: str = "auto") -> list[Poly]:
    """The reduced Gröbner basis of the ideal generated by ``gens``, sorted by increasing
    leading monomial; ``[]`` for the zero ideal, ``[1]`` for the unit ideal.

    ``engine="auto"`` uses F4 over QQ (modular) and Z/p, and Buchberger for other coefficient
    fields and for systems too small for F4's overhead to pay off."""
    ring = ring or (gens[0].ring if gens else None)
    if ring is None:
        return []
    if not ring.order.is_global:
        raise OrderingError("Gröbner bases need a global ordering; use std for local orderings")
    gens = [g for g in gens if not g.is_zero()]
    if not gens:
        return []
    key = _key(gens, ring, engine)
    out = _CACHE.get(key)
    if out is None:
        out = _compute(gens, ring, ENGINES[engine])
        _CACHE[key] = out
        if len(_CACHE) > _CACHE_SIZE:
            _CACHE.popitem(last=False)
    else:
        _CACHE.move_to_end(key)
    return list(out)


def cached_groebner(gens: Sequence[Poly], ring: PolyRing, engine: str = "auto") -> list[Poly] | None:
    """The basis :func:`groebner` would return, if it is known already; else ``None``."""
    out = _CACHE.get(_key(gens, ring, engine))
    return None if out is None else list(out)


def _key(gens: Sequence[Poly], ring: PolyRing, engine: str) -> tuple:
    return ring, engine, frozenset(g for g in gens if not g.is_zero())


def clear_cache() -> None:
    """Forget the recent bases (benchmarks time computations, not look-ups)."""
    _CACHE.clear()


_CACHE: OrderedDict[tuple, list[Poly]] = OrderedDict()
"""Recent results by (ring, engine, set of generators): the algorithms built on :func:`groebner`
(dimension, containment, decomposition) ask for the same bases many times."""
_CACHE_SIZE = 256


def _compute(gens: list[Poly], ring: PolyRing, run: Callable) -> list[Poly]:
    basis = run(gens, ring)
    if not getattr(run, "returns_reduced", False):
        return [Poly(ring, b) for b in reduce_basis(basis, ring)]
    out = []
    for b in basis:
        p = Poly(ring, b)
        p._lm = next(iter(b))
        out.append(p)
    return out


def normal_form(f: Poly, basis: Sequence[Poly], full: bool = True) -> Poly:
    """Remainder of ``f`` on division by ``basis`` (a Gröbner basis for a unique result)."""
    if not f.ring.order.is_global:
        raise OrderingError("normal forms need a global ordering; use the weak normal form for local orderings")
    polys = [b.terms for b in basis if not b.is_zero()]

    def run(pk: Packing) -> dict[Exp, Any]:
        return _unpack(pk, _Reducer(pk, [_pack(pk, b) for b in polys]).reduce(_pack(pk, f.terms), full))
    return Poly(f.ring, _packed(f.ring, polys + [f.terms], run))


def contains(basis: Sequence[Poly], f: Poly) -> bool:
    """Ideal membership of ``f`` given a Gröbner basis."""
    return normal_form(f, basis).is_zero()
