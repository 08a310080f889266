"""The largest monomial ideal inside an ideal in the Macaulay2 dialect (``dialect="m2"``):
``monomialSubideal``."""
from __future__ import annotations

from ..dsl.errors import MechRuntimeError
from ..dsl.m2_rings import in_quotients, is_integral
from ..dsl.m2_values import MonomialIdeal
from ..dsl.registry import command
from ..dsl.values import Ideal
from ..kernel import Block, MonomialOrder, Poly, PolyRing
from ..kernel import ideals as K
from .m2 import _quotient_of
from .m2_ideals import monomial_ideal


def monomial_subideal_polys(gens: list[Poly], ring: PolyRing) -> list[Poly]:
    """Generators of the largest monomial ideal in the ideal of ``gens``: the intersection of the
    ideal's images under the torus (x_i -> y_i x_i), the ideal of the f(y_1 x_1, ..., y_n x_n) with
    the y inverted (a variable t with t y_1...y_n = 1) and then eliminated (Saito, Sturmfels and
    Takayama, *Gröbner deformations of hypergeometric differential equations*, Algorithm 4.4.2)."""
    n = ring.nvars
    big = PolyRing(ring.field, [f"_y{i}" for i in range(n)] + ["_t"] + list(ring.names),
                   MonomialOrder([Block("dp", n + 1), Block("dp", n)], 2 * n + 1))
    twisted = [Poly(big, {e + (0,) + e: c for e, c in f.terms.items()}) for f in gens]
    ys = big.one()
    for i in range(n):
        ys = ys * big.gen(i)
    kept = K.eliminate(twisted + [big.one() - big.gen(n) * ys], list(range(n + 1)), ring=big)
    return [Poly(ring, {e[n + 1:]: c for e, c in p.terms.items()}) for p in kept]


@command("monomialSubideal", dialect="m2")
@in_quotients
def monomial_subideal(ctx, I: Ideal) -> MonomialIdeal:
    """monomialSubideal I: the largest monomial ideal contained in I."""
    if is_integral(I.ring) or _quotient_of(I.ring) is not None or not I.ring.order.is_global:
        raise MechRuntimeError("monomialSubideal is supported for polynomial rings over a field with a global order")
    polys = monomial_subideal_polys(list(I.nonzero()), I.ring)
    if any(len(p.terms) != 1 for p in polys):  # the elimination ideal is monomial: its reduced basis too
        raise MechRuntimeError("monomialSubideal: the elimination gave a non-monomial ideal")
    return monomial_ideal(ctx, *polys) if polys else MonomialIdeal(I.ring, [])
