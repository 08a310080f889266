"""elim.lib's ``elimRing``: a ring with an elimination ordering for some of the variables (they come
first, under a weight block ``a`` or a block of their own), as elim.lib prepares eliminations; and
``blowup0``: the blowup of the basering along a center C = <f_1..f_k>, presented by the Rees algebra:
the kernel of K[x, y_1..y_k] -> K[x, t], y_i -> t*f_i (Eisenbud, *Commutative Algebra*, 5.2), with the
total and strict transforms and the exceptional divisor of an ideal."""
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
from .ring_lib import export

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


def _saturation(I: list[Poly], C: list[Poly], ring) -> list[Poly]:
    """I : C^infinity, a standard basis; for a local or mixed ordering computed globally (saturation
    commutes with localization) and then made a standard basis for the ring's ordering."""
    from ..kernel.ideals import saturate, with_order
    from ..kernel.order import Block, MonomialOrder
    glob = ring if ring.order.is_global else with_order(ring, MonomialOrder([Block("dp", ring.nvars)], ring.nvars))
    found, _ = saturate([Poly(glob, p.terms) for p in I], [Poly(glob, p.terms) for p in C], ring=glob)
    return standard_basis(Ideal(ring, [Poly(ring, p.terms) for p in found]))


@command("blowup0", lib=LIB)
def blowup0(ctx, J: Ideal | Poly, C: Ideal, *ambient: Ideal) -> Any:
    """blowup0(J, C[, W]): the ring B of the blowup of the basering (of V(W)) along the center C =
    <f_1..f_k>, with the variables x(1..n), y(1..k) ordered by the basering's ordering and dp(k) (wp of
    the degrees when C is homogeneous), holding the ideals bR (the blown up basering: the relations of
    the f_i), aS (the blown up V(W)), tT (the total transform of J + W), eD (the exceptional divisor),
    sT (the strict transform: tT saturated by C), bM (the blowup map) and C, J, W.

    Example:
      LIB "elim.lib";
      ring r = 0,(x,y),dp;
      def B = blowup0(x2-y3, ideal(x,y));
      setring B;
      sT;
      → sT[1]=x(2)*y(2)^2-y(1)^2
      → sT[2]=x(1)*y(2)-x(2)*y(1)
      → sT[3]=x(2)^2*y(2)-x(1)*y(1)
      → sT[4]=x(2)^3-x(1)^2
    """
    from ..kernel.engines import standard_basis as kernel_std
    from ..kernel.order import MonomialOrder
    from ..kernel.poly import PolyRing
    from .idealops import interred, preimage_polys
    base = ctx.basering()
    ring = base.poly
    n = ring.nvars
    if isinstance(J, Poly):
        J = Ideal(ring, [J])
    W = ambient[0] if ambient else Ideal(ring, [ring.zero()])
    centre = list(C.gens)
    k = len(centre)
    plain = [b for b in base.blocks if b.kind not in ("c", "C")]
    module = [b for b in base.blocks if b.kind in ("c", "C")]
    degs = [p.total_degree() for p in centre]
    if all(p.is_homogeneous() and not p.is_zero() for p in centre) and any(d != 1 for d in degs):
        yblock = OrderBlock("wp", k, tuple(degs))
    else:
        yblock = OrderBlock("dp", k)
    names = [f"x({i + 1})" for i in range(n)] + [f"y({i + 1})" for i in range(k)]
    new = make_ring(base.characteristic, base.params, names, plain + [yblock] + module)
    if isinstance(ring.field, AlgebraicField):
        new.poly = extended(new.poly, get_minpoly(base).c)
    big = new.poly
    pad = (0,) * k

    def up(polys: list[Poly]) -> list[Poly]:
        return [Poly(big, {e + pad: c for e, c in p.terms.items()}) for p in polys]
    rees = PolyRing(ring.field, [f"@x({i + 1})" for i in range(n)] + ["@t"], MonomialOrder.simple("dp", n + 1))
    t = rees.gen(n)
    images = [rees.gen(i) for i in range(n)] + [t * Poly(rees, {e + (0,): c for e, c in f.terms.items()})
                                                for f in centre]
    bR = [p for p in preimage_polys(big, rees, images, []) if not p.is_zero()]
    Cb, Jb, Wb = up(centre), up(list(J.gens) + list(W.gens)), up(list(W.gens))
    if not big.order.is_global:
        bR = [p for p in kernel_std(bR, big)]

    def ideal(polys: list[Poly]) -> Ideal:
        polys = [p for p in polys if not p.is_zero()]
        return Ideal(big, polys or [big.zero()])
    tT = interred(ctx, ideal(Jb + bR))
    found = {
        "bR": ideal(bR), "C": Ideal(big, Cb), "J": Ideal(big, Jb), "W": Ideal(big, Wb),
        "aS": interred(ctx, ideal(bR + Wb)), "tT": tT,
        "eD": interred(ctx, ideal(Cb + Jb + bR)),
        "sT": ideal(_saturation(tT.nonzero(), [p for p in Cb if not p.is_zero()], big)),
        "bM": ideal([big.gen(i) for i in range(n)]),
    }
    for name, value in found.items():
        export(new, name, "ideal", value)
    return new
