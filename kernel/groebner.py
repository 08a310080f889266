"""Gröbner bases for global orderings: Buchberger's algorithm with the Gebauer–Möller
pair criteria and the sugar selection strategy; normal forms and reduced bases.

The public entry point is :func:`groebner`; engines are registered in :data:`ENGINES`
by name so faster ones (F4) can be swapped in behind the same interface.
"""
from __future__ import annotations

import heapq
from operator import add as _add, sub as _sub
from typing import Any, Callable, Sequence

from .poly import Exp, Poly, PolyRing, divides, lcm_exp


class OrderingError(ValueError):
    """Raised when an algorithm needs a global ordering and the ring's is not."""


def _mask(e: Exp) -> int:
    m = 0
    for i, v in enumerate(e):
        if v:
            m |= 1 << i
    return m


class _Reducer:
    """A set of reducers (monic polynomials as dicts) with divisibility masks."""

    def __init__(self, ring: PolyRing, polys: Sequence[dict[Exp, Any]] = ()) -> None:
        self.ring = ring
        self.key = ring.order.key
        self.items: list[tuple[Exp, int, dict[Exp, Any]]] = []
        for p in polys:
            self.add(p)

    def add(self, p: dict[Exp, Any]) -> None:
        lm = max(p, key=self.key)
        self.items.append((lm, _mask(lm), p))

    def find(self, e: Exp, emask: int) -> tuple[Exp, dict[Exp, Any]] | None:
        for lm, m, p in self.items:
            if m & ~emask == 0 and divides(lm, e):
                return lm, p
        return None

    def reduce(self, f: dict[Exp, Any], full: bool = True) -> dict[Exp, Any]:
        """Normal form of ``f``; ``full`` reduces every term, otherwise only the top."""
        if not f:
            return {}
        key = self.ring.order.neg_key
        p = dict(f)
        heap = [(key(e), e) for e in p]
        heapq.heapify(heap)
        result: dict[Exp, Any] = {}
        while heap:
            e = heapq.heappop(heap)[1]
            c = p.get(e)
            if c is None:
                continue
            while heap and heap[0][1] == e:
                heapq.heappop(heap)
            hit = self.find(e, _mask(e))
            if hit is None:
                del p[e]
                result[e] = c
                if not full:
                    result.update(p)
                    return result
                continue
            lm, g = hit
            shift = tuple(map(_sub, e, lm))
            lc = g[lm]
            factor = c / lc
            for ge, gc in g.items():
                te = tuple(map(_add, ge, shift))
                v = p.get(te)
                if v is None:
                    p[te] = -factor * gc
                    heapq.heappush(heap, (key(te), te))
                else:
                    v = v - factor * gc
                    if v == 0:
                        del p[te]
                    else:
                        p[te] = v
        return result


def _monic(p: dict[Exp, Any], key: Callable) -> dict[Exp, Any]:
    lm = max(p, key=key)
    inv = 1 / p[lm]
    return {e: c * inv for e, c in p.items()}


def buchberger(gens: Sequence[Poly], ring: PolyRing) -> list[dict[Exp, Any]]:
    """A (non-reduced) Gröbner basis as dicts, by Buchberger's algorithm with the
    Gebauer–Möller criteria and the sugar strategy."""
    key = ring.order.key
    basis: list[dict[Exp, Any]] = []
    lms: list[Exp] = []
    sugar: list[int] = []
    active: list[bool] = []
    pairs: list[tuple[int, int, Exp, int]] = []  # (i, j, lcm, sugar)
    reducer = _Reducer(ring)

    def update(h: dict[Exp, Any], s: int) -> None:
        nonlocal pairs
        hlm = max(h, key=key)
        k = len(basis)
        basis.append(h)
        lms.append(hlm)
        sugar.append(s)
        active.append(True)
        reducer.add(h)
        new = []
        for i in range(k):
            if active[i]:
                lc = lcm_exp(lms[i], hlm)
                ps = max(sugar[i] + sum(lc) - sum(lms[i]), s + sum(lc) - sum(hlm))
                new.append((i, k, lc, ps))
        # criterion M / F: keep a pair only if no other new pair's lcm properly divides it,
        # and among equal lcms keep one (preferring a coprime pair, which is then dropped)
        kept = []
        for a in new:
            if any(b is not a and divides(b[2], a[2]) and b[2] != a[2] for b in new):
                continue
            kept.append(a)
        by_lcm: dict[Exp, tuple] = {}
        for a in kept:
            prev = by_lcm.get(a[2])
            coprime = a[2] == tuple(x + y for x, y in zip(lms[a[0]], hlm))
            if prev is None or coprime:
                by_lcm[a[2]] = a
        final = []
        for lc, a in by_lcm.items():
            if lc == tuple(x + y for x, y in zip(lms[a[0]], hlm)):
                continue  # product criterion
            final.append(a)
        # criterion B on old pairs
        old = []
        for (i, j, lc, ps) in pairs:
            if divides(hlm, lc) and lcm_exp(lms[i], hlm) != lc and lcm_exp(lms[j], hlm) != lc:
                continue
            old.append((i, j, lc, ps))
        pairs = old + final
        for i in range(k):
            if active[i] and divides(hlm, lms[i]):
                active[i] = False

    for g in gens:
        if g.terms:
            r = reducer.reduce(g.terms)
            if r:
                update(_monic(r, key), g.total_degree())
    while pairs:
        best = min(range(len(pairs)), key=lambda t: (pairs[t][3], key(pairs[t][2])))
        i, j, lc, ps = pairs.pop(best)
        f, g = basis[i], basis[j]
        spoly = _spoly(f, lms[i], g, lms[j], lc)
        r = reducer.reduce(spoly)
        if r:
            if ring.zero_exp in r and len(r) == 1:
                return [{ring.zero_exp: ring.field.one}]
            update(_monic(r, key), ps)
    return [b for b, a in zip(basis, active) if a]


def _spoly(f: dict, lf: Exp, g: dict, lg: Exp, lc: Exp) -> dict:
    sf = tuple([x - y for x, y in zip(lc, lf)])
    sg = tuple([x - y for x, y in zip(lc, lg)])
    cf, cg = f[lf], g[lg]
    out: dict = {}
    for e, c in f.items():
        out[tuple([x + y for x, y in zip(e, sf)])] = c * cg
    for e, c in g.items():
        te = tuple([x + y for x, y in zip(e, sg)])
        v = out.get(te)
        v = -c * cf if v is None else v - c * cf
        if v == 0:
            out.pop(te, None)
        else:
            out[te] = v
    return out


def reduce_basis(basis: Sequence[dict[Exp, Any]], ring: PolyRing) -> list[dict[Exp, Any]]:
    """The reduced Gröbner basis (monic, minimal, tails reduced) of a Gröbner basis."""
    key = ring.order.key
    items = [(max(b, key=key), b) for b in basis if b]
    minimal = []
    for idx, (lm, b) in enumerate(items):
        if any(divides(l2, lm) and (l2 != lm or j < idx) for j, (l2, _) in enumerate(items) if j != idx):
            continue
        minimal.append(b)
    out = []
    for idx, b in enumerate(minimal):
        others = _Reducer(ring, [m for j, m in enumerate(minimal) if j != idx])
        lm = max(b, key=key)
        tail = {e: c for e, c in b.items() if e != lm}
        r = others.reduce(tail)
        r[lm] = b[lm]
        out.append(_monic(r, key))
    out.sort(key=lambda p: key(max(p, key=key)))
    return out


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
    run = ENGINES[engine]
    basis = run(gens, ring)
    if not getattr(run, "returns_reduced", False):
        basis = reduce_basis(basis, ring)
        return [Poly(ring, b) for b in basis]
    out = []
    for b in basis:
        p = Poly(ring, b)
        p._lm = next(iter(b))
        out.append(p)
    return out


def normal_form(f: Poly, basis: Sequence[Poly], full: bool = True) -> Poly:
    """Remainder of ``f`` on division by ``basis`` (a Gröbner basis for a unique result)."""
    red = _Reducer(f.ring, [b.terms for b in basis if not b.is_zero()])
    return Poly(f.ring, red.reduce(f.terms, full))


def contains(basis: Sequence[Poly], f: Poly) -> bool:
    """Ideal membership of ``f`` given a Gröbner basis."""
    return normal_form(f, basis).is_zero()


def leading_monomials(basis: Sequence[Poly]) -> list[Exp]:
    return [b.lm() for b in basis if not b.is_zero()]
