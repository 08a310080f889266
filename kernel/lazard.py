"""Standard bases for any monomial ordering by Lazard's method (Greuel–Pfister, *A Singular
Introduction to Commutative Algebra*, 1.7): homogenize with a new variable ``t``, compute a
Gröbner basis for the global ordering "degree, then ``>`` on the ``x``-part"
(:func:`homogenized_order`), set ``t = 1``.  Every ``f`` in ``I`` has ``t^ecart f^h`` in the
homogenized ideal, whose leading monomial is ``t^e LM(f)``.  It computes a global object, so
it suffers from components away from the origin, but never from Mora's long detours.
"""
from __future__ import annotations

from fractions import Fraction
from typing import Callable, Sequence

from .hilbert import minimal_monomials
from .monomials import independent_row
from .mora import Terms, cancel_unit
from .order import Block, MonomialOrder
from .poly import Poly, PolyRing, divides


def homogenized_order(order: MonomialOrder) -> MonomialOrder:
    """The global ordering on ``(x, t)``: total degree first, then ``order`` on the x-part."""
    n = order.nvars
    blocks = [Block("a", 0, (1,) * (n + 1))]
    rows = [list(r) for r in order.matrix]
    blocks.append(Block("M", n, tuple(v for r in _square(rows, n) for v in r)))
    blocks.append(Block("lp", 1))
    return MonomialOrder(blocks)


def _square(rows: list[list[int]], n: int) -> list[list[int]]:
    """``n`` linearly independent rows of ``rows`` defining the same ordering (the first
    rows that raise the rank; later rows never matter once the rank is full)."""
    chosen: list[list[int]] = []
    echelon: list[list[Fraction]] = []
    for r in rows:
        if independent_row(echelon, r):
            chosen.append(r)
        if len(chosen) == n:
            break
    return chosen


def homogenized_ring(ring: PolyRing) -> PolyRing:
    """The ring with a last variable ``@t``, ordered by :func:`homogenized_order`."""
    return PolyRing(ring.field, ring.names + ("@t",), homogenized_order(ring.order))


def homogenize(p: Poly, hring: PolyRing) -> Poly:
    """``t^deg(p) p(x/t)`` in the homogenized ring."""
    d = p.total_degree()
    return Poly(hring, {e + (d - sum(e),): c for e, c in p.terms.items()})


def dehomogenize(p: Poly) -> Terms:
    """``p`` with ``t = 1``, as terms of the original ring."""
    out: Terms = {}
    for e, c in p.terms.items():
        out[e[:-1]] = out[e[:-1]] + c if e[:-1] in out else c
    return {e: c for e, c in out.items() if c != 0}


def lazard(gens: Sequence[Poly], ring: PolyRing,
           groebner: Callable[[list[Poly], PolyRing], list[Poly]]) -> list[Terms]:
    """A minimal standard basis (dicts, each with its leading monomial first) by Lazard's
    method: a homogeneous Gröbner basis of the homogenized ideal for :func:`homogenized_order`
    (computed by ``groebner(gens, ring)``), dehomogenized.  Unit factors ``x^a u`` of the generators are cancelled first (they only
    enlarge the global problem)."""
    key = ring.order.key
    hring = homogenized_ring(ring)
    hgens = [homogenize(Poly(ring, cancel_unit(g.terms, key)), hring) for g in gens if not g.is_zero()]
    hbasis = [h for h in groebner(hgens, hring) if not h.is_zero()]
    # LM(h with t = 1) is the x-part of LM(h): only elements with minimal ones are dehomogenized
    lms = [h.lm()[:-1] for h in hbasis]
    keep = set(minimal_monomials(lms))
    out = []
    for h, m in zip(hbasis, lms):
        if m in keep:
            keep.discard(m)
            p = dehomogenize(h)
            if all(divides(m, e) for e in p):  # p = x^m u with a unit u
                p = {m: p[m]}
            inv = 1 / p[m]
            out.append({m: p[m] * inv, **{e: c * inv for e, c in p.items()}})  # the leading monomial first
    return out
