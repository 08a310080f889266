"""Univariate gcd and factorization over a finite field Z/p[a]/(m) (m irreducible) with flint's
``fq_default`` polynomials: Euclid's algorithm on mech's polynomials is quadratic with slow coefficient
arithmetic, flint's is fast (Singular's test gcd_univar_p_alpha_s has degrees near 1000); Singular's
``factorize`` in a ring like ``(32003,i),x`` with ``minpoly=i2+1`` (homogeneous polynomials in two or
more variables come here dehomogenized)."""
from __future__ import annotations

from functools import lru_cache
from typing import Any, Optional

import flint

from .algext import AlgebraicField
from .poly import Poly


@lru_cache(maxsize=16)
def _context(p: int, modulus: tuple[int, ...]) -> Optional[Any]:
    """flint's field Z/p[a]/(m), None when m is reducible (Z/p[a]/(m) is no field)."""
    m = flint.nmod_poly(list(modulus), p)
    _, factors = m.factor()
    if len(factors) != 1 or factors[0][1] != 1:
        return None
    return flint.fq_default_ctx(p, modulus=flint.fmpz_mod_poly_ctx(p)(list(modulus)))


def _setup(f: Poly, used: set[int]) -> Optional[tuple[Any, Any, int]]:
    """flint's field and polynomial ring for f's coefficient field Z/p[a]/(m) and the index of the one
    variable in ``used`` (None: not such a field, m reducible, or several variables)."""
    field = f.ring.field
    if not isinstance(field, AlgebraicField) or not field.characteristic or len(used) > 1:
        return None
    ctx = _context(field.characteristic, tuple(int(c) for c in field.modulus.coeffs()))
    if ctx is None:
        return None
    return ctx, flint.fq_default_poly_ctx(ctx), next(iter(used)) if used else 0


def _to_fq(h: Poly, i: int, ctx: Any, P: Any) -> Any:
    coeffs = [ctx(0)] * (h.degree_in(i) + 1)
    for e, c in h.terms.items():
        coeffs[e[i]] = ctx([int(x) for x in c.u.coeffs()])
    return P(coeffs)


def _from_fq(d: Any, ring: Any, i: int) -> Poly:
    """The monic polynomial in variable i of ``ring`` with flint's coefficients ``d``."""
    field = ring.field
    terms = {}
    for k, c in enumerate(d.coeffs()):
        if not c.is_zero():
            e = [0] * ring.nvars
            e[i] = k
            terms[tuple(e)] = field.element(flint.nmod_poly([int(x) for x in c.to_list()], field.characteristic))
    return Poly(ring, terms).monic()


def fq_gcd(f: Poly, g: Poly) -> Optional[Poly]:
    """The monic gcd of two polynomials in at most one variable over Z/p[a]/(m), or None when the
    field is not of that kind (characteristic 0, m reducible) or they have several variables."""
    if f.is_zero() or g.is_zero():
        return None
    setup = _setup(f, f.variables() | g.variables())
    if setup is None:
        return None
    ctx, P, i = setup
    return _from_fq(_to_fq(f, i, ctx, P).gcd(_to_fq(g, i, ctx, P)), f.ring, i)


def fq_factors(f: Poly) -> list[tuple[Poly, int]]:
    """The monic irreducible factors of a polynomial in one variable over Z/p[a]/(m) (m irreducible), with
    multiplicities (NotImplementedError for other fields, a reducible m or several variables)."""
    field, used = f.ring.field, f.variables()
    setup = _setup(f, used) if len(used) == 1 else None
    if setup is None and len(used) == 1 and isinstance(field, AlgebraicField) and field.characteristic:
        m = flint.nmod_poly([int(c) for c in field.modulus.coeffs()], field.characteristic)
        raise NotImplementedError(f"the minimal polynomial {m} is reducible: the coefficients do not form a field")
    if setup is None:
        raise NotImplementedError(f"factorization over {field!r} of this polynomial is not available")
    ctx, P, i = setup
    _, facs = _to_fq(f, i, ctx, P).factor()
    return [(_from_fq(g, f.ring, i), int(m)) for g, m in facs]
