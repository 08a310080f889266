"""Factorization of univariate polynomials over a finite field Z/p[a]/(m) (m irreducible) by flint's
``fq_default`` polynomials (Singular's ``factorize`` in a ring like ``(32003,i),x`` with ``minpoly=i2+1``;
homogeneous polynomials in two or more variables come here dehomogenized)."""
from __future__ import annotations

from functools import lru_cache
from typing import Any

import flint

from ..kernel import Poly
from ..kernel.algext import AlgebraicField


@lru_cache(maxsize=16)
def _field(p: int, modulus: tuple[int, ...]) -> Any:
    m = flint.nmod_poly(list(modulus), p)
    _, factors = m.factor()
    if len(factors) != 1 or factors[0][1] != 1:
        raise NotImplementedError(f"the minimal polynomial {m} is reducible: the coefficients do not form a field")
    return flint.fq_default_ctx(p, modulus=flint.fmpz_mod_poly_ctx(p)(list(modulus)))


def fq_factors(f: Poly) -> list[tuple[Poly, int]]:
    """The monic irreducible factors of a polynomial in at most one variable over Z/p[a]/(m), with
    multiplicities (NotImplementedError for other fields or several variables)."""
    field = f.ring.field
    used = f.variables()
    if not isinstance(field, AlgebraicField) or not field.characteristic or len(used) != 1:
        raise NotImplementedError(f"factorization over {field!r} of this polynomial is not available")
    p = field.characteristic
    ctx = _field(p, tuple(int(c) for c in field.modulus.coeffs()))
    P = flint.fq_default_poly_ctx(ctx)
    i = next(iter(used))
    coeffs = [ctx(0)] * (f.degree_in(i) + 1)
    for e, c in f.terms.items():
        coeffs[e[i]] = ctx([int(x) for x in c.u.coeffs()])
    _, facs = P(coeffs).factor()
    ring = f.ring
    out = []
    for g, m in facs:
        terms = {}
        for k, c in enumerate(g.coeffs()):
            if not c.is_zero():
                e = [0] * ring.nvars
                e[i] = k
                terms[tuple(e)] = field.element(flint.nmod_poly([int(x) for x in c.to_list()], p))
        out.append((Poly(ring, terms).monic(), int(m)))
    return out
