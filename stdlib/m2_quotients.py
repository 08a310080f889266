"""Quotient rings of the Macaulay2 dialect as values: ``ambient R``, ``presentation R``, ``describe R``
(also of polynomial rings) and ``lift`` of elements and ideals to the polynomial ring."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.m2_rings import M2Ring, in_quotients
from ..dsl.registry import command
from ..dsl.values import Ideal, Matrix, OrderBlock
from ..kernel import Poly


@command("ambient", dialect="m2")
@in_quotients
def ambient_ring(R: M2Ring) -> M2Ring:
    """ambient R: the ring a quotient ring R = A/I is a quotient of (A)."""
    if R.parent is None:
        raise MechRuntimeError("ambient R: R is not a quotient ring")
    return R.parent


@command("describe", dialect="m2")
@in_quotients
def describe(R: M2Ring) -> str:
    """describe R: how R was made (a polynomial ring with the default order and degrees, or a quotient)."""
    if R.parent is not None:
        return R.describe()
    own = len(R.own)
    default = R.blocks[:1] == (OrderBlock("dp", own),) and len(R.blocks) == 2 and R.blocks[1].kind == "C"
    if set(R.info) - {"m2_options", "m2_order"} or not default or any(d != 1 for d in R.degrees[:own]) \
            or R.max_exponent is not None:
        raise MechRuntimeError("describe is supported for quotients and for polynomial rings with the default "
                               "order and degrees")
    degrees = f"{own}:1" if own > 1 else "1"
    return f"{R.describe()[:-1]}, Degrees => {{{degrees}}}, Heft => {{1}}]"


@command("lift", dialect="m2")
@in_quotients
def lift(x: Poly | Ideal, A: M2Ring) -> Any:
    """lift(f, A), lift(I, A): an element (its normal form) or ideal of a quotient ring R of A in A
    (an ideal with R's relations over A)."""
    R = getattr(x.ring, "owner", None)
    if R is None:
        raise MechRuntimeError("lift(x, A) takes an element or ideal of a Macaulay2 ring")
    r, rels = R, []
    while r is not A and r.parent is not None:
        rels.extend(Poly(A.poly, dict(g.terms)) for g in r.relations)
        r = r.parent
    if r is not A:
        raise MechRuntimeError("lift(x, A): A is not a ring R is a quotient of")
    if isinstance(x, Poly):
        return Poly(A.poly, dict(x.terms))
    return Ideal(A.poly, [Poly(A.poly, dict(g.terms)) for g in x.nonzero()] + rels)


@command("presentation", dialect="m2")
@in_quotients
def ring_presentation(R: M2Ring) -> Matrix:
    """presentation R: the relations of a quotient ring as one row over its polynomial ring (the
    last quotient's first)."""
    A = R.ambient()
    if R.parent is None or A.info.get("localized_at") is not None:
        raise MechRuntimeError("presentation R is supported for quotients of polynomial rings")
    rels: list[Poly] = []
    r = R
    while r.parent is not None:
        rels.extend(Poly(A.poly, dict(g.terms)) for g in r.relations)
        r = r.parent
    return Matrix(A.poly, 1, len(rels), rels)


@command("annihilator", dialect="m2")
@command("ann", dialect="m2")
@in_quotients
def annihilator_element(f: Poly) -> Ideal:
    """annihilator f: the ideal of the elements r with r f = 0 (0 : f; in R/Q: (Q : f) in R/Q)."""
    from .m2 import quotient
    out = quotient(Ideal(f.ring, []), f)
    return out if out.nonzero() else Ideal(f.ring, [], is_std=True)
