"""The reduced Gröbner basis over QQ of a Gröbner basis, by python-flint's autoreduction
(``fmpz_mpoly_vec.autoreduction``, compiled) for any global ordering.

flint orders monomials only by lex, deglex or degrevlex, so a monomial ``x^e`` of the ring is
embedded as ``t^(W e) x^e`` in twice as many variables ordered by lex, ``W`` the ring's
nonnegative weight matrix (:func:`.monomials.nonnegative_matrix`): lex on the embedded
exponents compares ``W e`` first, which is the ring's ordering.  Since ``W`` is nonnegative,
an embedded monomial divides another iff the ring's monomials divide, and the quotient is again
embedded, so every reduction step of the embedded polynomials is the image of one in the ring:
autoreduction (each element reduced by the others until none reduces) maps to the ring's, and
the autoreduction of a Gröbner basis is its reduced basis up to scalars.  (The embedded set is
no Gröbner basis of the ideal it generates -- lcms leave the image -- so only reduction is used.)
The embedding is read off the ring's packed monomials, whose bit fields are ``W e`` and ``e``.
"""
from __future__ import annotations

from math import gcd
from typing import Any, Sequence

import flint

from .monomials import packing
from .order import Exp
from .poly import PolyRing

FLINT_TERMS = 1000
"""Bases with at least this many terms go to flint; below it the conversions cost more than
Buchberger's reduction in Python saves (the four-bar coupler curve's basis, ~200 terms: 1.0 ms
in Python against 2.5 ms)."""


def reduce_basis_qq(basis: Sequence[dict[Exp, Any]], ring: PolyRing) -> list[dict[Exp, Any]]:
    """The reduced Gröbner basis (monic, leading exponent first in each dict, sorted by increasing
    leading monomial) of a Gröbner basis over QQ given as ``{exponent: fmpq}`` dicts.  As
    :func:`.buchberger.reduce_basis`: the minimal elements by increasing leading monomial, each
    reduced by the ones before it, already reduced."""
    polys = [b for b in basis if b]
    if not polys:
        return []
    n = ring.nvars
    top = max(sum(e) for b in polys for e in b)
    pk = packing(ring.order, max(8, 2 * top))
    fields = _fields(pk, n)
    ctx = flint.fmpz_mpoly_ctx.get([f"t{i}" for i in range(n)] + [f"x{i}" for i in range(n)], "lex")
    pack, guard = pk.pack, pk.guard
    leads = [max(pack(e) for e in b) for b in polys]
    minimal = sorted((lm, k) for k, lm in enumerate(leads)
                     if not any(((lm | guard) - l2) & guard == guard and (l2 != lm or j < k)
                                for j, l2 in enumerate(leads) if j != k))
    embedded: dict[Exp, tuple[int, ...]] = {}
    exponent: dict[tuple, Exp] = {}
    done: list[flint.fmpz_mpoly] = []
    out = []
    for _, k in minimal:
        b = polys[k]
        den = 1
        for c in b.values():
            q = int(c.q)
            if q != 1:
                den = den * q // gcd(den, q)
        d = {}
        for e, c in b.items():
            key = embedded.get(e)
            if key is None:
                m = pack(e)
                key = embedded[e] = tuple([(m >> s) & mask for s, mask in fields])
            d[key] = int(c.p) * (den // int(c.q))
        f = ctx.from_dict(d)
        if done:
            f = f.reduction_primitive_part(flint.fmpz_mpoly_vec(done, ctx))
        done.append(f)
        monoms, coeffs = f.monoms(), f.coeffs()
        lc = coeffs[0]
        exps = []
        for m in monoms:
            e = exponent.get(m)
            if e is None:
                e = exponent[m] = tuple(map(int, m[n:]))  # flint's exponents are fmpz
            exps.append(e)
        out.append({e: flint.fmpq(c, lc) for e, c in zip(exps, coeffs)})
    return out


def _fields(pk, n: int) -> list[tuple[int, int]]:
    """``(shift, mask)`` of the packed fields ``W e`` (the first ``n``) and ``e`` (the last ``n``)."""
    shifts = pk.weight_shifts[:n] + pk.eshifts
    widths = pk.weight_widths[:n] + [pk.ebits] * n
    return [(s, (1 << w) - 1) for s, w in zip(shifts, widths)]

