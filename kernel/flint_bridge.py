"""Term dictionaries to python-flint's multivariate polynomials and back.

mech's :class:`~.poly.Poly` keeps ``{exponent tuple: coefficient}``; flint's ``fmpq_mpoly``
(QQ) and ``nmod_mpoly`` (Z/p) multiply, raise to powers, divide and take gcds in C.  The
variables keep their positions (names ``x0, x1, ...``; flint's own term order does not matter:
only sets of terms travel).  Converting costs a few microseconds a term, so :mod:`.poly`
sends a product here only when the schoolbook product would cost far more.
"""
from __future__ import annotations

from typing import Any

import flint

from .coeffs import Field, PrimeField, RationalField

Terms = dict[tuple[int, ...], Any]


def context(field: Field, nvars: int) -> Any:
    """flint's polynomial context for ``field[x0..x(nvars-1)]`` (at least one variable), or
    None for fields flint has no multivariate type for."""
    names = tuple(f"x{i}" for i in range(max(nvars, 1)))
    if isinstance(field, RationalField):
        return flint.fmpq_mpoly_ctx.get(names, ordering="lex")
    if isinstance(field, PrimeField):
        return flint.nmod_mpoly_ctx.get(names, ordering="lex", modulus=field.characteristic)
    return None


def to_flint(ctx: Any, terms: Terms, nvars: int) -> Any:
    """The flint polynomial of ``terms`` (exponent tuples of length ``nvars``) in ``ctx``."""
    if nvars == 0:
        return ctx.from_dict({(0,): c for c in terms.values()})
    return ctx.from_dict(terms)


def from_flint(g: Any, field: Field, nvars: int) -> Terms:
    """The terms of the flint polynomial ``g`` with coefficients in ``field``."""
    coeffs = g.coeffs()
    # flint's exponents are fmpz: mech's are Python ints
    monoms = [tuple(map(int, m)) for m in g.monoms()] if nvars else [()] * len(coeffs)
    if isinstance(field, PrimeField):
        p = field.characteristic
        nmod = flint.nmod
        coeffs = [nmod(c, p) for c in coeffs]
    return dict(zip(monoms, coeffs))


def product(field: Field, nvars: int, a: Terms, b: Terms) -> Terms | None:
    """The terms of the product ``a * b`` computed by flint (None when ``field`` has no flint type)."""
    ctx = context(field, nvars)
    if ctx is None:
        return None
    return from_flint(to_flint(ctx, a, nvars) * to_flint(ctx, b, nvars), field, nvars)


def power(field: Field, nvars: int, a: Terms, k: int) -> Terms | None:
    """The terms of ``a ** k`` computed by flint (None when ``field`` has no flint type)."""
    ctx = context(field, nvars)
    if ctx is None:
        return None
    return from_flint(to_flint(ctx, a, nvars) ** k, field, nvars)
