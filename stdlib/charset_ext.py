"""Factoring the top polynomial of an ascending set over the finite field that the one non-linear
polynomial below it defines (:mod:`.charsets`): f in the variables v and y over Z/p[v]/(A(v)), with A
irreducible, is a univariate polynomial in y over F_q, factored by flint.  The factors are monic in y with
coefficients reduced modulo A (written back as polynomials in v), sorted as Singular's factory sorts
factors (by multiplicity, then by its order of polynomials: v below y, so the coefficients in F_q compare
as polynomials in v)."""
from __future__ import annotations

from functools import cmp_to_key
from typing import Optional

import flint

from ..kernel import Poly
from .charset_ops import degree, level, normalize
from .factorize import _compare


def _variables(f: Poly) -> set[int]:
    return {i + 1 for e in f.terms for i, k in enumerate(e) if k}


def finite_field_factors(f: Poly, below: list[Poly]) -> Optional[list[tuple[Poly, int]]]:
    """The factors of f over Z/p[v]/(A) when the polynomials below f have exactly one non-linear element
    A, in its variable v alone, and f involves only v and its main variable; None otherwise."""
    p = f.ring.field.characteristic
    star = [g for g in below if degree(g) > 1]
    if not p or len(star) != 1:
        return None
    A = star[0]
    v, y = level(A), level(f)
    if _variables(A) != {v} or not _variables(f) <= {v, y}:
        return None
    m = flint.nmod_poly([int(A.coeff_of(_exp(f, v, k))) for k in range(degree(A) + 1)], p)
    ctx = flint.fq_default_ctx(p, modulus=flint.fmpz_mod_poly_ctx(p)([int(c) for c in m.coeffs()]))
    coeffs = [ctx(0)] * (degree(f, y) + 1)
    for e, c in f.terms.items():
        x = [0] * (e[v - 1] + 1)
        x[e[v - 1]] = int(c)
        coeffs[e[y - 1]] += ctx(x)
    _, facs = flint.fq_default_poly_ctx(ctx)(coeffs).factor()
    ring = f.ring
    out = []
    for g, mult in facs:
        terms: dict = {}
        for k, c in enumerate(g.coeffs()):
            for j, a in enumerate(c.to_list()):
                if int(a):
                    e = [0] * ring.nvars
                    e[y - 1], e[v - 1] = k, j
                    terms[tuple(e)] = ring.field(int(a))
        out.append((normalize(Poly(ring, terms)), int(mult)))
    out.sort(key=cmp_to_key(lambda s, t: (s[1] > t[1]) - (s[1] < t[1]) or _compare(s[0].terms, t[0].terms, p)))
    return out


def _exp(f: Poly, v: int, k: int) -> tuple[int, ...]:
    e = [0] * f.ring.nvars
    e[v - 1] = k
    return tuple(e)
