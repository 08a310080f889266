"""Singular's built-in ``monomial(v)``: the monomial with exponent vector v (entries beyond the number of
variables are ignored, except that an entry n+1 gives a module component, which needs vectors)."""
from __future__ import annotations

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import IntVec
from ..kernel import Poly


@command("monomial")
def monomial(ctx, v: IntVec) -> Poly:
    """monomial(v): the monomial of the basering with exponent vector v.

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
    if len(e) == n + 1 and e[n]:
        raise MechRuntimeError("monomial with a module component (a vector) is not supported")
    e = (e + [0] * n)[:n]
    return ring.monomial(tuple(e))
