"""Factorization and gcd over an algebraic extension QQ[a]/(m) (:mod:`.algext`), by sympy's
algebraic-field polynomials (Trager's norm method): the field is ``QQ<alpha>`` for a root ``alpha``
of ``m``, and an element ``c0 + c1*a + ...`` travels as the same coefficients on ``alpha``, so the
answer does not depend on which root sympy holds.  ``m`` must be irreducible (Singular assumes it);
over Z/p[a]/(m) these raise ``NotImplementedError``."""
from __future__ import annotations

from functools import lru_cache
from typing import Any

import flint

from .algext import AlgebraicField
from .algext_fq import fq_gcd
from .errors import NotSupported
from .poly import Poly, PolyRing


@lru_cache(maxsize=32)
def _domain(field: AlgebraicField) -> Any:
    if field.characteristic:
        raise NotImplementedError(f"factorization over {field!r} is not available")
    import sympy
    factors = field.modulus.factor()[1]
    if len(factors) != 1 or factors[0][1] != 1:
        raise NotImplementedError(f"the minimal polynomial of {field!r} is reducible: the coefficients do not "
                                  "form a field")
    t = sympy.Symbol("t")
    m = sympy.Poly([sympy.Rational(int(c.p), int(c.q)) for c in reversed(field.modulus.coeffs())], t)
    return sympy.QQ.algebraic_field(sympy.CRootOf(m, 0))


def _sympy_ring(ring: PolyRing) -> tuple[Any, Any]:
    from sympy.polys.rings import ring as sympy_ring
    K = _domain(ring.field)
    return sympy_ring([f"_x{i}" for i in range(ring.nvars)], K)[0], K


def _to_sympy(f: Poly, R: Any, K: Any) -> Any:
    return R({e: K(list(reversed(c.u.coeffs()))) for e, c in f.terms.items()})


def _from_sympy(p: Any, ring: PolyRing) -> Poly:
    field = ring.field
    return Poly(ring, {tuple(e): field.element(flint.fmpq_poly(list(reversed(c.to_list()))))
                       for e, c in p.terms()})


def factorize(f: Poly) -> tuple[Any, list[tuple[Poly, int]]]:
    """``(unit, [(g, m), ...])`` with monic irreducible factors ``g`` (leading coefficient 1 in the ring's
    ordering), ``f == unit * prod(g**m)``."""
    ring = f.ring
    R, K = _sympy_ring(ring)
    _, facs = _to_sympy(f, R, K).factor_list()
    out = [(_from_sympy(g, ring).monic(), int(m)) for g, m in facs]
    prod = ring.one()
    for g, m in out:
        prod = prod * g ** m
    return f.lc() / prod.lc(), out


def gcd(f: Poly, g: Poly) -> Poly:
    """The monic greatest common divisor (``gcd(0, 0) == 0``)."""
    if f.is_zero() and g.is_zero():
        return f
    if f.is_zero() or g.is_zero():
        return (g if f.is_zero() else f).monic()
    if f.ring.field.characteristic:
        h = fq_gcd(f, g)
        return euclid_gcd(f, g) if h is None else h
    R, K = _sympy_ring(f.ring)
    return _from_sympy(_to_sympy(f, R, K).gcd(_to_sympy(g, R, K)), f.ring).monic()


def euclid_gcd(f: Poly, g: Poly) -> Poly:
    """The monic gcd of two polynomials in one variable by Euclid's algorithm (any field: also the
    parameter fields K(a,...))."""
    used = f.variables() | g.variables()
    if len(used) > 1:
        raise NotSupported(f"gcd of polynomials in several variables over {f.ring.field!r} is not available")
    if not used:
        return f.ring.one()
    i = used.pop()
    while not g.is_zero():
        f, g = g, _remainder(f, g, i)
    return f.monic()


def _remainder(f: Poly, g: Poly, i: int) -> Poly:
    dg, inv = g.degree_in(i), g.ring.field.one / g.lc()
    while not f.is_zero() and f.degree_in(i) >= dg:
        k = f.degree_in(i) - dg
        e = [0] * f.ring.nvars
        e[i] = k
        f = f - g * (f.ring.monomial(tuple(e)) * (f.lc() * inv))
    return f


def divide_exact(f: Poly, g: Poly) -> Poly:
    """``f / g`` for a divisor ``g`` of ``f`` (ValueError otherwise)."""
    R, K = _sympy_ring(f.ring)
    q, r = _to_sympy(f, R, K).div(_to_sympy(g, R, K))
    if r:
        raise ValueError("the division is not exact")
    return _from_sympy(q, f.ring)
