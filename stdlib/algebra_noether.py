"""algebra.lib's ``noetherNormal``: a Noether normalization by a random lower triangular change of
coordinates, checked as algebra.lib checks it (in the ordering (dp(n-d), lp(d)), every one of the first
n-d variables is a pure power of a leading monomial of the standard basis: the ring is then finite over
the polynomial ring of the last d variables; another change is drawn until it is)."""
from __future__ import annotations

import random
from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Ideal, List
from ..kernel import MonomialOrder, Poly, PolyRing
from ..kernel.dimension import krull_dim
from ..kernel.engines import standard_basis
from ..kernel.maps import map_polys
from ..kernel.order import Block
from .algebra import LIB
from .algebra_subrings import _finiteness

#: The changes of coordinates come from this generator (the entries as algebra.lib's: 1..10).
_SEED = 2024
#: How many changes are tried (over a small prime field none may do).
_ATTEMPTS = 100


@command("noetherNormal", lib=LIB)
def noether_normal(I: Ideal, *sparse: Any) -> List:
    """noetherNormal(I[, p]): the list of an ideal m defining a change of coordinates (map phi =
    basering, m) and of an ideal J of d = dim(I) variables such that the basering modulo phi(I) is finite
    over K[J]: m is random, unit lower triangular (p, algebra.lib's percentage of zero entries, is
    accepted and not used); the zero ideal and maxideal(1) for the zero ideal, maxideal(1) and 0 for d = 0.

    Example:
      LIB "algebra.lib";
      ring r = 0,(x,y),dp;
      noetherNormal(ideal(x2-y3))[2];
      → _[1]=y
    """
    ring = I.ring
    n = ring.nvars
    gens = I.nonzero()
    maxideal = Ideal(ring, [ring.gen(i) for i in range(n)])
    if not gens:
        return List([maxideal, maxideal])
    dp = PolyRing(ring.field, ring.names, MonomialOrder.simple("dp", n))
    d = krull_dim([g.lm() for g in standard_basis([Poly(dp, g.terms) for g in gens], dp)], n)
    if d <= 0:
        return List([maxideal, Ideal(ring, [ring.zero()])])
    blocks = ([Block("dp", n - d)] if n > d else []) + [Block("lp", d)]
    mixed = PolyRing(ring.field, ring.names, MonomialOrder(blocks, n))
    rnd = random.Random(_SEED)
    for _ in range(_ATTEMPTS):
        images = []
        for k in range(n):
            p = ring.gen(k)
            for j in range(k):
                p = p + ring.const(ring.field(rnd.randint(1, 10))) * ring.gen(j)
            images.append(p)
        moved = map_polys(gens, [Poly(mixed, p.terms) for p in images], mixed)
        test = _finiteness(standard_basis(moved, mixed), mixed, list(range(1, n - d + 1)))
        free = [g for g in test.items[2].gens if not g.is_zero()]
        if test.items[0] == 1 and len(free) == d:
            return List([Ideal(ring, images), Ideal(ring, [Poly(ring, g.terms) for g in free])])
    raise MechRuntimeError(f"noetherNormal: no random change of coordinates in {_ATTEMPTS} tries put the ideal "
                           "in Noether position (the field may be too small)")
