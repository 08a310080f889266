"""``factorize`` over a rational function field QQ(a,...) or Z/p(a,...), as Singular's factory does it.

Factory reads the parameters as variables above the ring's variables: ``f`` (its denominators
cleared) is factored over QQ or Z/p in the variables followed by the parameters
(:func:`mech.stdlib.factorize.factory_factors`: the same scaling and order as without
parameters); the factors free of the ring's variables join the unit ``f / prod(factors)``.
"""
from __future__ import annotations

from typing import Any, Callable

from ..kernel import Poly, PolyRing
from ..kernel.coeffs import GF, QQ
from ..kernel.order import Block, MonomialOrder

Factors = list[tuple[Poly, int]]


def _big_ring(ring: PolyRing) -> PolyRing:
    """The ring of the variables followed by the parameters over the prime field."""
    field = ring.field
    names = list(ring.names) + list(field.params)
    base = GF(field.characteristic) if field.characteristic else QQ
    return PolyRing(base, names, MonomialOrder([Block("lp", len(names))]))


def _lift(f: Poly, big: PolyRing) -> Poly:
    """``f`` times the lcm of its coefficients' denominators, in the variables and parameters."""
    field = f.ring.field
    den = field.ctx.constant(1)
    for c in f.terms.values():
        den = den * c.den // den.gcd(c.den)
    terms: dict = {}
    lcm = field.from_polys(den)
    for e, c in f.terms.items():
        num = (c * lcm).num
        for pe, pc in zip(num.monoms(), num.coeffs()):
            terms[tuple(e) + tuple(pe)] = big.field(int(pc))
    return Poly(big, terms)


def _drop(g: Poly, ring: PolyRing) -> Poly:
    """A polynomial of the big ring back in ``ring`` (its parameters into the coefficients)."""
    field, n = ring.field, ring.nvars
    parts: dict = {}
    for e, c in g.terms.items():
        parts.setdefault(e[:n], []).append((e[n:], c))
    ctx = field.ctx
    terms = {}
    for e, pts in parts.items():
        num = ctx.from_dict({pe: int(c) for pe, c in pts})
        terms[e] = field.from_polys(num)
    return Poly(ring, terms)


def param_factorization(f: Poly, factory_factors: Callable[[Poly], Factors]) -> tuple[Any, Factors]:
    """``(unit, [(factor, multiplicity), ...])`` of ``f`` over a field with parameters."""
    ring = f.ring
    big = _big_ring(ring)
    n = ring.nvars
    factors = [(g, m) for g, m in factory_factors(_lift(f, big)) if any(any(e[:n]) for e in g.terms)]
    out = [(_drop(g, ring), m) for g, m in factors]
    lead = ring.field.one
    for g, m in out:
        lead = lead * g.lc() ** m
    return f.lc() / lead, out

