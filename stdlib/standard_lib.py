"""Commands of Singular's standard.lib beyond the standard bases (:mod:`mech.stdlib.standard`):
``max`` and ``min`` of ints, intvecs or polynomials, the monomials of one weighted degree outside a
leading ideal (``weightKB``) and ``stdfglm`` from a given ordering.  Singular loads standard.lib at
start; mech has weightKB and stdfglm built in and max and min after ``LIB "standard.lib";`` (so that
they stay free as variable names)."""
from __future__ import annotations

from functools import cmp_to_key
from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, List
from ..kernel import Poly
from .ring_lib import parse_ordering

LIB = "standard.lib"


def _compare(a: Any, b: Any) -> int:
    """Singular's comparison: ints by value, intvecs entry by entry, polynomials by their leading
    monomials in the ring's ordering (then leading coefficients)."""
    if isinstance(a, int) and isinstance(b, int):
        return (a > b) - (a < b)
    if isinstance(a, IntVec) and isinstance(b, IntVec):
        return (a.values > b.values) - (a.values < b.values)
    if isinstance(a, Poly) and isinstance(b, Poly):
        if a.is_zero() or b.is_zero():
            return (not a.is_zero()) - (not b.is_zero())
        c = a.ring.order.compare(a.lm(), b.lm())
        return c
    raise MechRuntimeError("max and min compare ints, intvecs or polynomials, all of one type")


def _extreme(xs: tuple[Any, ...], sign: int) -> Any:
    items = list(xs[0].items) if len(xs) == 1 and isinstance(xs[0], List) else list(xs)
    if not items:
        raise MechRuntimeError("max and min need at least one argument")
    best = items[0]
    for x in items[1:]:
        if sign * _compare(x, best) > 0:
            best = x
    return best


@command("max", lib=LIB)
def max_(*xs: Any) -> Any:
    """max(a, b, ...): the largest argument: of ints, intvecs (compared entry by entry) or
    polynomials (by their leading monomials).

    Example:
      LIB "standard.lib";
      max(1, 4, 3);
      → 4
      ring r = 0,x,dp;
      max(x+1, x2);
      → x2
    """
    return _extreme(xs, 1)


@command("min", lib=LIB)
def min_(*xs: Any) -> Any:
    """min(a, b, ...): the smallest argument: of ints, intvecs (compared entry by entry) or
    polynomials (by their leading monomials).

    Example:
      LIB "standard.lib";
      min(intvec(1,2), intvec(0,5));
      → 0,5
    """
    return _extreme(xs, -1)


def monomials_of_degree(n: int, weights: list[int], d: int) -> list[tuple[int, ...]]:
    """The exponent vectors of weighted degree d in n variables of positive weights."""
    out: list[tuple[int, ...]] = []

    def rec(i: int, left: int, cur: list[int]) -> None:
        if i == n:
            if left == 0:
                out.append(tuple(cur))
            return
        for k in range(left // weights[i], -1, -1):
            rec(i + 1, left - k * weights[i], cur + [k])
    rec(0, d, [])
    return out


@command("weightKB")
def weight_kb(I: Ideal, d: int, w: IntVec | List) -> Ideal:
    """weightKB(I, d, w): the monomials of weighted degree d (the variables weighted by the positive
    intvec w) outside the leading ideal of the standard basis I: the degree-d part of a monomial
    basis of R/I.

    Example:
      ring r = 0,(x,y),wp(1,2);
      weightKB(std(ideal(x2)), 4, intvec(1,2));
      → _[1]=y2
    """
    ring = I.ring
    vec = w.items[0] if isinstance(w, List) and w.items else w
    if not isinstance(vec, IntVec):
        raise MechRuntimeError("weightKB(I, d, w): w must be an intvec of weights (or a list of them)")
    weights = list(vec.values)[:ring.nvars]
    if len(weights) < ring.nvars or any(v <= 0 for v in weights):
        raise MechRuntimeError("weightKB: the weights must be positive, one for each variable")
    leads = [g.lm() for g in I.nonzero()]
    mons = [e for e in monomials_of_degree(ring.nvars, weights, d)
            if not any(all(a <= b for a, b in zip(m, e)) for m in leads)] if d >= 0 else []
    mons.sort(key=cmp_to_key(ring.order.compare), reverse=True)
    return Ideal(ring, [ring.monomial(e) for e in mons] or [ring.zero()])


@command("stdfglm")
def stdfglm_from(I: Ideal, how: str) -> Ideal:
    """stdfglm(I, s): the reduced Groebner basis of the zero-dimensional ideal I for the basering's
    ordering, as stdfglm(I); s names the ordering (or "std"/"slimgb", the algorithm) standard.lib
    starts the FGLM conversion from: the result is the same.

    Example:
      ring r = 0,(x,y),lp;
      stdfglm(ideal(x2-y, y2-1), "std");
      → _[1]=y2-1
      → _[2]=x2-y
    """
    from .standard import stdfglm
    if how not in ("std", "slimgb"):
        parse_ordering(how, I.ring.nvars)  # the ordering must be one
    return stdfglm(I)
