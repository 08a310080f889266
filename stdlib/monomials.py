"""Singular's ``ord``: the (weighted) degree of the leading monomial in the ring's ordering."""
from __future__ import annotations

from ..dsl.registry import command
from ..kernel import Poly
from .polynomials import _ring_weights


@command("ord")
def ord_(f: Poly) -> int:
    """ord(f): the degree of the leading monomial of f in the ring's ordering, weighted by the
    ordering's weights (1 for each variable without; -1 for 0).

    Example:
      ring r = 0,(x,y,z),ls;
      ord(x5+y2+z3);
      → 3
      ring s = 0,(x,y),wp(2,3);
      ord(x2+y);
      → 4
    """
    if f.is_zero():
        return -1
    e = f.lm()
    ws = _ring_weights(f.ring)
    return sum(a * b for a, b in zip(e, ws)) if ws is not None else sum(e)
