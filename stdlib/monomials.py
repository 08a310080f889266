"""Singular's ``ord`` (the weighted degree of the leading monomial in the ring's ordering) and
``contract`` (the contraction of polynomials by others, term by term)."""
from __future__ import annotations

from ..dsl.registry import command
from ..dsl.values import Ideal, Matrix
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


def _contract(f: Poly, g: Poly) -> Poly:
    """The contraction of g by f: the sum over the terms c*t of f and d*m of g with t dividing m of
    c*d*(m/t)."""
    terms: dict = {}
    for t, c in f.terms.items():
        for m, d in g.terms.items():
            if all(a <= b for a, b in zip(t, m)):
                e = tuple(b - a for a, b in zip(t, m))
                terms[e] = terms.get(e, 0) + c * d
    return Poly(f.ring, {e: c for e, c in terms.items() if c != 0})


@command("contract")
def contract(I: Ideal, J: Ideal) -> Matrix:
    """contract(I, J): the matrix of the contractions of the generators of J by those of I: entry
    (i, j) is the sum of c*d*(m/t) over the terms c*t of I[i] and d*m of J[j] with t dividing m.

    Example:
      ring r = 0,(a,b,c),dp;
      print(contract(ideal(a, b2), ideal(a2b2+a, b3)));
      → ab2+1,0,
      → a2,   b
    """
    return Matrix(I.ring, len(I.gens), len(J.gens), [_contract(f, g) for f in I.gens for g in J.gens])
