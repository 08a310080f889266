"""The gcd of polynomials in several variables over a parameter field K(a,...) (K = QQ or Z/p).

By Gauss's lemma the gcd over K(a,...)[x,...] of two polynomials with their denominators cleared is
their gcd in K[a,...,x,...] (flint's multivariate gcd) up to a factor in K[a,...], which the monic
normalization over K(a,...) removes."""
from __future__ import annotations

from typing import Any

import flint

from .poly import Poly
from .ratfunc import RationalFunctionField


def _joint_context(field: RationalFunctionField, nvars: int) -> Any:
    names = tuple(field.params) + tuple(f"_x{i}" for i in range(nvars))
    if field.characteristic:
        return flint.nmod_mpoly_ctx.get(names, ordering="lex", modulus=field.characteristic)
    return flint.fmpz_mpoly_ctx.get(names, ordering="lex")


def _cleared(f: Poly, ctx: Any) -> Any:
    """f times the lcm of its coefficients' denominators, as a polynomial of the joint context."""
    lcm = None
    for c in f.terms.values():
        lcm = c.den if lcm is None else lcm * c.den / lcm.gcd(c.den)
    terms: dict[tuple, Any] = {}
    for e, c in f.terms.items():
        for pe, k in (c.num * (lcm / c.den)).to_dict().items():
            terms[tuple(pe) + tuple(e)] = k
    return ctx.from_dict(terms)


def param_gcd(f: Poly, g: Poly) -> Poly:
    """The monic gcd of f and g, nonzero polynomials over a rational function field."""
    ring, field = f.ring, f.ring.field
    ctx = _joint_context(field, ring.nvars)
    h = _cleared(f, ctx).gcd(_cleared(g, ctx))
    m = len(field.params)
    coeffs: dict[tuple, dict] = {}
    for e, k in h.to_dict().items():
        coeffs.setdefault(tuple(e[m:]), {})[tuple(e[:m])] = k
    return Poly(ring, {e: field.from_polys(field.ctx.from_dict(c)) for e, c in coeffs.items()}).monic()
