"""Singular's built-in ``monomial(v)``: the monomial with exponent vector v (entries beyond the number of
variables are ignored, except that a nonzero entry n+1 gives a module component: a vector)."""
from __future__ import annotations

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import IntVec
from ..dsl.values_modules import Vector
from ..kernel import Poly


@command("monomial")
def monomial(ctx, v: IntVec) -> Poly | Vector:
    """monomial(v): the monomial of the basering with exponent vector v (with n+1 entries, n the number of
    variables, and a last one k > 0: the monomial times gen(k)).

    Example:
      ring r = 0,(x,y,z),dp;
      monomial(intvec(2,3));
      → x2y3
    """
    ring = ctx.basering().poly
    e = list(v)
    if any(k < 0 for k in e):
        raise MechRuntimeError("monomial: no negative exponent allowed")
    n = ring.nvars
    m = ring.monomial(tuple((e + [0] * n)[:n]))
    if len(e) == n + 1 and e[n]:
        return Vector.from_terms(ring, {(m.lm(), e[n] - 1): ring.field.one})
    return m
