"""Term dictionaries to python-flint's multivariate polynomials and back.

mech's :class:`~.poly.Poly` keeps ``{exponent tuple: coefficient}``; flint's ``fmpq_mpoly``
(QQ) and ``nmod_mpoly`` (Z/p) multiply, raise to powers, divide and take gcds in C.  The
variables keep their positions (names ``x0, x1, ...``; flint's own term order does not matter:
only sets of terms travel).  Converting costs a few microseconds a term, so :mod:`.poly`
sends a product here only when the schoolbook product would cost far more.
"""
from __future__ import annotations

from math import comb, log2, prod
from typing import Any

import flint

from . import offload
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
    """The terms of the product ``a * b`` computed by flint (None when ``field`` has no flint type);
    a long one in a child process that an interrupt or a limit can stop (:mod:`.offload`)."""
    ctx = context(field, nvars)
    if ctx is None:
        return None
    return offload.call(lambda: product_seconds(field, a, b), lambda: from_flint(
        to_flint(ctx, a, nvars) * to_flint(ctx, b, nvars), field, nvars))


def power(field: Field, nvars: int, a: Terms, k: int) -> Terms | None:
    """The terms of ``a ** k`` computed by flint (None when ``field`` has no flint type); a long
    one in a child process that an interrupt or a limit can stop (:mod:`.offload`)."""
    ctx = context(field, nvars)
    if ctx is None:
        return None
    return offload.call(lambda: power_seconds(field, a, k),
                        lambda: from_flint(to_flint(ctx, a, nvars) ** k, field, nvars))


# Rough times of flint's products, measured on python-flint 0.9 (seconds per pair of terms and
# per term of the result and word of its coefficients): only to tell calls of milliseconds from
# calls of minutes.
_PER_PAIR = 2e-9
_PER_TERM = 3e-8


def bits(field: Field, terms: Terms) -> int:
    """The bits of the largest coefficient of ``terms`` (numerator and denominator; 64 over Z/p)."""
    if not isinstance(field, RationalField) or not terms or not isinstance(next(iter(terms.values())), flint.fmpq):
        return 64
    return max(int(c.p).bit_length() + int(c.q).bit_length() for c in terms.values())


def _shape(terms: Terms) -> tuple[list[int], int]:
    """The largest exponent of each variable and the total degree of ``terms``."""
    return [int(max(col)) for col in zip(*terms)], int(max(map(sum, terms)))  # exponents may be fmpz


def _result_terms(degrees: list[int], total: int, pairs: int) -> int:
    """A bound on the terms of a product with these degrees (each variable's, the total)."""
    used = sum(d > 0 for d in degrees)
    return min(prod(d + 1 for d in degrees), comb(used + total, used), pairs)


def product_seconds(field: Field, a: Terms, b: Terms) -> float:
    """A rough estimate of flint's time for ``a * b``."""
    if not a or not b or not next(iter(a)):
        return 0.0
    (da, ta), (db, tb) = _shape(a), _shape(b)
    pairs = len(a) * len(b)
    out = _result_terms([x + y for x, y in zip(da, db)], ta + tb, pairs)
    return (pairs * _PER_PAIR + out * _PER_TERM) * max(1.0, (bits(field, a) + bits(field, b)) / 64)


def power_seconds(field: Field, a: Terms, k: int) -> float:
    """A rough estimate of flint's time for ``a ** k``."""
    if not a or not next(iter(a)):
        return 0.0
    degrees, total = _shape(a)
    n = len(a)
    out = _result_terms([d * k for d in degrees], total * k, comb(n + k - 1, min(k, n - 1)))
    size = 1.0 if not isinstance(field, RationalField) else max(1.0, k * (bits(field, a) + log2(n)) / 64)
    return out * n * size * _PER_TERM
