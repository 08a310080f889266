"""elim.lib's ``elimRing``: a ring with an elimination ordering for some of the variables (they come
first, under a weight block ``a`` or a block of their own), as elim.lib prepares eliminations."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.minpoly import extended, get_minpoly
from ..dsl.qrings import make_qring, quotient_ideal
from ..dsl.registry import command
from ..dsl.rings import make_ring
from ..dsl.values import Ideal, IntVec, List, OrderBlock
from ..kernel import Poly
from ..kernel.algext import AlgebraicField
from .ring_lib import ringweights
from .standard import standard_basis

LIB = "elim.lib"


def _blocks(first: list[int], rest: list[int], weights: list[int], local: bool, kind: str) -> list[OrderBlock]:
    """elim.lib's two blocks: "a": a(w1, 0, ..., 0) then dp/wp (ls/ws when the first variable kept is
    local) with all the weights (in the basering's order of the variables, as elim.lib has them);
    "b": dp/wp for the eliminated variables, then dp/wp (ds/ws) for the others."""
    n = len(weights)
    if kind == "b":
        one = OrderBlock("dp", len(first)) if all(v == 1 for v in first) else OrderBlock("wp", len(first), tuple(first))
        if all(v == 1 for v in rest):
            two = OrderBlock("ds" if local else "dp", len(rest))
        else:
            two = OrderBlock("ws" if local else "wp", len(rest), tuple(rest))
        return [one, two, OrderBlock("C")]
    if all(v == 1 for v in weights):
        two = OrderBlock("ls" if local else "dp", n)
    else:
        two = OrderBlock("ws" if local else "wp", n, tuple(weights))
    return [OrderBlock("a", n, tuple(first) + (0,) * (n - len(first))), two, OrderBlock("C")]


@command("elimRing", lib=LIB)
def elim_ring(ctx, vars_: Poly, *opts: Any) -> List:
    """elimRing(vars[, w][, "a"|"b"]): the list of a ring with an elimination ordering for the variables
    of the monomial vars (they come first) and the intvec of the variables' weights (w, default the
    ring's weights; weights <= 0 made 1).  "a" (default): the blocks a(w of the eliminated, 0...)
    and wp(w) (dp if all weights are 1; ws/ls if the first variable kept is local); "b": wp/dp blocks
    for the eliminated variables and for the others.  A quotient ring keeps its ideal, as a standard
    basis for the new ordering (its variables mapped by name; Singular's elim.lib maps them by
    position, which changes the ideal when the variables move).

    Example:
      LIB "elim.lib";
      ring r = 0,(x,y,z),dp;
      def R = elimRing(y)[1];
      R;
      → // coefficients: QQ
      → // number of vars : 3
      → //        block   1 : ordering a
      → //                  : names    y x z
      → //                  : weights  1 0 0
      → //        block   2 : ordering dp
      → //                  : names    y x z
      → //        block   3 : ordering C
    """
    base = ctx.basering()
    ring = base.poly
    n = ring.nvars
    weights = list(ringweights(base).values)
    kind = "a"
    for o in opts:
        if isinstance(o, IntVec):
            weights = (list(o.values) + [1] * n)[:n]
        elif isinstance(o, str):
            kind = o
    weights = [v if v > 0 else 1 for v in weights]
    if len(vars_.terms) != 1:
        raise MechRuntimeError("elimRing: the first argument must be the product of the variables to eliminate")
    (mono,) = vars_.terms
    elim = [i for i in range(n) if mono[i]]
    keep = [i for i in range(n) if not mono[i]]
    if not elim:
        raise MechRuntimeError("## elimination of no variables?")
    if not keep:
        raise MechRuntimeError("## elimination of all variables is not possible")
    one = tuple(int(i == keep[0]) for i in range(n))
    local = ring.order.compare(one, ring.zero_exp) < 0
    blocks = _blocks([weights[i] for i in elim], [weights[i] for i in keep], weights, local, kind)
    order = elim + keep
    new = make_ring(base.characteristic, base.params, [ring.names[i] for i in order], blocks)
    if isinstance(ring.field, AlgebraicField):
        new.poly = extended(new.poly, get_minpoly(base).c)
    quotient = quotient_ideal(ring)
    if quotient:
        polys = [Poly(new.poly, {tuple(e[i] for i in order): c for e, c in g.terms.items()}) for g in quotient]
        new = make_qring(new, Ideal(new.poly, standard_basis(Ideal(new.poly, polys)), is_std=True))
    return List([new, IntVec(weights)])
