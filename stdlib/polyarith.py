"""Singular's built-ins ``sqrfree`` (a squarefree decomposition, grouped as Singular's factory groups
it) and ``extgcd`` (the extended Euclidean algorithm for integers and univariate polynomials)."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, List
from ..kernel import Poly
from ..kernel.factor import normalize
from .factorize import singular_factorization


def _level(f: Poly) -> int:
    """The last variable f involves (factory's main variable of f)."""
    return max(i for e in f.terms for i, k in enumerate(e) if k)


def _factory_normal(g: Poly) -> Poly:
    """g with its leading coefficient in factory's recursive order (the last variable first) positive
    (over QQ) or 1 (over Z/p)."""
    lead = g.terms[max(g.terms, key=lambda e: e[::-1])]
    if g.ring.field.characteristic == 0:
        return -g if lead < 0 else g
    return g * g.ring.const(g.ring.field.one / lead)


@command("sqrfree")
def sqrfree(f: Poly, how: int = 0) -> Any:
    """sqrfree(f[, n]): a squarefree decomposition of f: the list of the ideal of the unit and the
    factors and the intvec of their multiplicities, where a factor is the product of the irreducible
    factors of one multiplicity and one main (last) variable, as Singular's factory decomposes
    recursively by contents; n = 1: the ideal of the factors; n = 2: the list without the unit; n = 3:
    the product of the factors (the squarefree part).

    Example:
      ring r = 0,(x,y),dp;
      sqrfree(3*(x-y)^2*(x+y)^2*(x2+1));
      → [1]:
      →    _[1]=3
      →    _[2]=x2+1
      →    _[3]=x2-y2
      → [2]:
      →    1,1,2
    """
    if how not in (0, 1, 2, 3):
        raise MechRuntimeError(f"sqrfree(f, {how}): the second argument must be 0, 1, 2 or 3")
    ring = f.ring
    unit, factors = singular_factorization(f)
    groups: dict[tuple[int, int], Poly] = {}
    for g, m in factors:
        key = (_level(g), m)
        groups[key] = groups.get(key, ring.one()) * g
    keys = sorted(groups)
    polys = [_factory_normal(normalize(groups[k])) for k in keys]
    mults = [m for _, m in keys]
    lead = ring.field.one
    for p, m in zip(polys, mults):
        lead = lead * p.lc() ** m
    unit = (f.lc() / lead) if not f.is_zero() else ring.field.zero
    if how == 3:
        product = ring.const(unit)
        for p in polys:
            product = product * p
        return product if polys else ring.const(unit)
    if how == 1:
        return Ideal(ring, polys or [ring.const(unit)])
    if how == 2:
        return List([Ideal(ring, polys or [ring.const(unit)]), IntVec(mults or [1])])
    return List([Ideal(ring, [ring.const(unit)] + polys), IntVec([1] + mults)])


def _int_extgcd(a: int, b: int) -> tuple[int, int, int]:
    r0, r1, s0, s1, t0, t1 = abs(a), abs(b), 1, 0, 0, 1
    while r1:
        q = r0 // r1
        r0, r1, s0, s1, t0, t1 = r1, r0 - q * r1, s1, s0 - q * s1, t1, t0 - q * t1
    return r0, s0 * (1 if a >= 0 else -1), t0 * (1 if b >= 0 else -1)


def _divmod(f: Poly, g: Poly, v: int) -> tuple[Poly, Poly]:
    """Division with remainder of polynomials in the variable v alone."""
    ring = f.ring
    q, r = ring.zero(), f
    dg = max(e[v] for e in g.terms)
    lead = g.terms[tuple(dg if i == v else 0 for i in range(ring.nvars))]
    while not r.is_zero():
        dr = max(e[v] for e in r.terms)
        if dr < dg:
            break
        c = r.terms[tuple(dr if i == v else 0 for i in range(ring.nvars))] / lead
        t = Poly(ring, {tuple(dr - dg if i == v else 0 for i in range(ring.nvars)): c})
        q, r = q + t, r - t * g
    return q, r


@command("extgcd")
def extgcd_int(a: int, b: int) -> List:
    """extgcd(a, b): the list of g = gcd(a, b) and integers s, t with g = s*a + t*b; for univariate
    polynomials the monic gcd and the cofactors of least degree.

    Example:
      extgcd(24, 10);
      → [1]:
      →    2
      → [2]:
      →    -2
      → [3]:
      →    5
      ring r = 0,x,dp;
      extgcd(x2-1, x2+2x+1);
      → [1]:
      →    x+1
      → [2]:
      →    1/2
      → [3]:
      →    -1/2
    """
    return List(list(_int_extgcd(a, b)))


@command("extgcd")
def extgcd_poly(f: Poly, g: Poly) -> List:
    ring = f.ring
    used = {i for p in (f, g) for e in p.terms for i, k in enumerate(e) if k}
    if len(used) > 1:
        raise MechRuntimeError("extgcd: the polynomials must be univariate (in one and the same variable)")
    v = used.pop() if used else 0
    r0, r1, s0, s1, t0, t1 = f, g, ring.one(), ring.zero(), ring.zero(), ring.one()
    while not r1.is_zero():
        q, r = _divmod(r0, r1, v)
        r0, r1, s0, s1, t0, t1 = r1, r, s1, s0 - q * s1, t1, t0 - q * t1
    if r0.is_zero():
        return List([r0, s0, t0])
    c = max(r0.terms.items(), key=lambda kv: kv[0][v])[1]
    inv = ring.const(ring.field.one / c)
    return List([r0 * inv, s0 * inv, t0 * inv])
