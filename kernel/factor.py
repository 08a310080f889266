"""Multivariate factorization, gcd and squarefree parts over QQ and Z/p through python-flint.

Polynomials travel to flint's ``fmpq_mpoly`` / ``nmod_mpoly`` as exponent dictionaries (the
variables keep their positions; flint's own term order does not matter) and come back as
:class:`Poly` of the original ring.  Other coefficient fields raise ``NotImplementedError``.

Normalization (the convention of :func:`normalize`, used for every factor returned here):
over QQ a polynomial is scaled to an integer primitive one whose leading coefficient in the
ring's ordering is positive; over Z/p it is made monic.  ``factorize`` returns the unit
separately, so ``f == unit * prod(g**m)``.  A long flint call (by a rough estimate) runs in a
child process that an interrupt or a limit can stop (:mod:`.offload`).
"""
from __future__ import annotations

import math
from typing import Any

import flint

from . import algext_factor, flint_bridge, offload
from .algext import AlgebraicField
from .coeffs import PrimeField, RationalField
from .errors import DivisionError
from .poly import Poly


def to_flint(f: Poly) -> Any:
    """``f`` as a flint multivariate polynomial (variables by position)."""
    ctx = flint_bridge.context(f.ring.field, f.ring.nvars)
    if ctx is None:
        raise NotImplementedError(f"factorization over {f.ring.field!r} is not available")
    return flint_bridge.to_flint(ctx, f.terms, f.ring.nvars)


_PER_TERM = 1e-5  # rough seconds per term and ten degrees of flint's gcd and factorization


def _seconds(*fs: Poly) -> float:
    """A rough estimate of flint's time for a gcd, division or factorization of ``fs``."""
    terms = sum(len(f.terms) for f in fs)
    degree = int(max(max(map(sum, f.terms)) for f in fs if f.terms)) if terms else 0  # exponents may be fmpz
    size = max(flint_bridge.bits(f.ring.field, f.terms) for f in fs) / 64
    return _PER_TERM * terms * max(1.0, degree / 10) * max(1.0, size)


def _flint(f: Poly, op: Any, *others: Poly) -> Any:
    """``op(flint f, flint others...)`` with flint's polynomials turned back into terms (lists and
    tuples of them too) — in a child process when it may be long."""
    ring = f.ring

    def back(v: Any) -> Any:
        if isinstance(v, (list, tuple)):
            return type(v)(back(x) for x in v)
        if isinstance(v, (flint.fmpq_mpoly, flint.nmod_mpoly)):
            return flint_bridge.from_flint(v, ring.field, ring.nvars)
        return int(v) if isinstance(v, flint.fmpz) else v

    return offload.call(lambda: _seconds(f, *others), lambda: back(op(to_flint(f), *map(to_flint, others))))


def normalize(f: Poly) -> Poly:
    """Over QQ the integer primitive multiple with positive leading coefficient; over Z/p
    the monic multiple; zero stays zero."""
    if f.is_zero() or getattr(f.ring.field, "params", ()):  # Q(params): the caller's normal form
        return f
    if f.ring.field.characteristic:
        return f.monic()
    den, num = 1, 0
    for c in f.terms.values():
        q = int(c.q)
        den = den * q // math.gcd(den, q)
    for c in f.terms.values():
        num = math.gcd(num, int(c.p) * (den // int(c.q)))
    scale = flint.fmpq(den, num)
    if f.lc() * scale < 0:
        scale = -scale
    return f * scale


def factorize(f: Poly) -> tuple[Any, list[tuple[Poly, int]]]:
    """The factorization ``f = unit * prod(g**m)`` into irreducible factors ``g``.

    Returns ``(unit, [(g, m), ...])`` with ``unit`` a field element and each ``g``
    normalized by :func:`normalize` (over QQ integer primitive with positive leading
    coefficient in the ring's ordering; over Z/p monic).  Singular's ``factorize`` lists the
    unit first and the same factors up to sign: its signs come from factory's internals
    (e.g. ``-l1+l2-l3``) and are not reproduced.  Factors are sorted by multiplicity, then
    by increasing leading monomial.  A constant ``f`` gives ``(f, [])``.
    """
    ring = f.ring
    if f.is_constant():
        return (f.lc() if not f.is_zero() else ring.field.zero), []
    if isinstance(ring.field, AlgebraicField):
        return algext_factor.factorize(f)
    if f.total_degree() == 1 and isinstance(ring.field, (RationalField, PrimeField)):  # irreducible: no flint call
        g = normalize(f)
        return f.lc() / g.lc(), [(g, 1)]
    _, facs = _flint(f, lambda g: g.factor())
    out = []
    for t, m in facs:
        out.append((normalize(Poly(ring, t)), int(m)))
    lead = ring.field.one  # the product's leading coefficient: leading terms multiply in a monomial ordering
    for q, m in out:
        lead = lead * q.lc() ** m
    unit = f.lc() / lead
    key = ring.order.key
    out.sort(key=lambda t: (t[1], key(t[0].lm()), len(t[0])))
    return unit, out


def squarefree_part(f: Poly) -> Poly:
    """The product of the distinct irreducible factors of ``f``, normalized (a constant
    ``f`` gives 1, zero gives zero)."""
    if f.is_zero():
        return f
    if f.is_constant():
        return f.ring.one()
    _, facs = _flint(f, lambda g: g.factor_squarefree())
    result = f.ring.one()
    for t, _m in facs:
        result = result * Poly(f.ring, t)
    return normalize(result)


def gcd(f: Poly, g: Poly) -> Poly:
    """The greatest common divisor, normalized; ``gcd(0, 0) == 0``."""
    if isinstance(f.ring.field, AlgebraicField):
        return algext_factor.gcd(f, g)
    if getattr(f.ring.field, "params", ()) and not (f.is_zero() or g.is_zero()):
        if len(f.variables() | g.variables()) > 1:  # K(a,...): by Gauss's lemma in K[a,...,x,...]
            from .param_gcd import param_gcd
            return param_gcd(f, g)
        return algext_factor.euclid_gcd(f, g)  # K(a,...): Euclid in one variable
    if f.is_zero():
        return normalize(g)
    if g.is_zero():
        return normalize(f)
    return normalize(Poly(f.ring, _flint(f, lambda a, b: a.gcd(b), g)))


def divide_exact(f: Poly, g: Poly) -> Poly:
    """``f / g`` for a divisor ``g`` of ``f``; :class:`~.errors.DivisionError` when ``g`` does not divide ``f``."""
    if g.is_zero():
        raise ZeroDivisionError("division by zero")
    if isinstance(f.ring.field, AlgebraicField):
        try:
            return algext_factor.divide_exact(f, g)
        except ValueError:
            raise DivisionError("the division is not exact") from None
    q, r = _flint(f, divmod, g)
    if r:
        raise DivisionError("the division is not exact")
    return Poly(f.ring, q)
