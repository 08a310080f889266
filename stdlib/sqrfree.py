"""Singular's built-in ``sqrfree``: a squarefree decomposition, grouped as Singular's factory groups it
(the irreducible factors of one multiplicity and one main variable together)."""
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
      →    _[3]=-x2+y2
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
