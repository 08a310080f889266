"""Univariate gcd over a finite field Z/p[a]/(m) (m irreducible) with flint's ``fq_default``
polynomials: Euclid's algorithm on mech's polynomials is quadratic with slow coefficient
arithmetic, flint's is fast (Singular's test gcd_univar_p_alpha_s has degrees near 1000)."""
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


def fq_gcd(f: Poly, g: Poly) -> Optional[Poly]:
    """The monic gcd of two polynomials in at most one variable over Z/p[a]/(m), or None when the
    field is not of that kind (characteristic 0, m reducible) or they have several variables."""
    field = f.ring.field
    if not isinstance(field, AlgebraicField) or not field.characteristic:
        return None
    used = f.variables() | g.variables()
    if len(used) > 1 or f.is_zero() or g.is_zero():
        return None
    ctx = _context(field.characteristic, tuple(int(c) for c in field.modulus.coeffs()))
    if ctx is None:
        return None
    i = used.pop() if used else 0
    P = flint.fq_default_poly_ctx(ctx)

    def to_fq(h: Poly) -> Any:
        coeffs = [ctx(0)] * (h.degree_in(i) + 1)
        for e, c in h.terms.items():
            coeffs[e[i]] = ctx([int(x) for x in c.u.coeffs()])
        return P(coeffs)

    d = to_fq(f).gcd(to_fq(g))
    ring = f.ring
    terms = {}
    for k, c in enumerate(d.coeffs()):
        if not c.is_zero():
            e = [0] * ring.nvars
            e[i] = k
            terms[tuple(e)] = field.element(flint.nmod_poly([int(x) for x in c.to_list()], field.characteristic))
    return Poly(ring, terms).monic()
