"""Eliminating one variable from two polynomials over ZZ when one of them is monic in it, without
a Gröbner basis.

Let A = ZZ[the other variables] (a unique factorization domain), f monic of degree n in x and g
any polynomial.  A[x]/(f) is free over A on 1, x, ..., x^(n-1), multiplication by g acts on it by
an n x n matrix M over A, and h in A lies in (f, g) exactly when h e_0 = M v for some v in A^n
(e_0 the coordinates of 1).  When r = det M (the resultant of f and g) is not zero, v is
adj(M) h e_0 / r, so h lies in the ideal exactly when r divides h c_k for the entries c_k of the
first column of adj(M), that is when r / gcd(r, c_k) divides h for every k: (f, g) ∩ A is the
principal ideal of L = lcm_k r / gcd(r, c_k)."""
from __future__ import annotations

from fractions import Fraction
from math import gcd as igcd
from typing import Optional

from . import matrix as KM
from .factor import divide_exact
from .factor import gcd as qq_gcd
from .poly import Poly, PolyRing


def _coefficients(p: Poly, i: int) -> dict[int, Poly]:
    """p's coefficients as a polynomial in x_i (elements of the ring free of x_i)."""
    out: dict[int, dict] = {}
    for e, c in p.terms.items():
        out.setdefault(e[i], {})[e[:i] + (0,) + e[i + 1:]] = c
    return {k: Poly(p.ring, t) for k, t in out.items()}


def _reduce_mod(p: dict[int, Poly], f: dict[int, Poly], n: int, unit: Poly) -> dict[int, Poly]:
    """p mod f (f monic up to the sign ``unit`` in x of degree n), as coefficients."""
    p = dict(p)
    for d in sorted(p, reverse=True):
        if d < n:
            break
        c = p.pop(d)
        if c.is_zero():
            continue
        for k, fk in f.items():
            if k < n:
                p[d - n + k] = p.get(d - n + k, c.ring.zero()) - c * fk * unit
    return p


def _integral(p: Poly) -> tuple[Fraction, Poly]:
    """(content, primitive integral part with a positive lead coefficient) of a nonzero p (over QQ)."""
    coeffs = [Fraction(int(c.p), int(c.q)) for c in p.terms.values()]
    den = 1
    for c in coeffs:
        den = den * c.denominator // igcd(den, c.denominator)
    num = 0
    for c in coeffs:
        num = igcd(num, int(c * den))
    content = Fraction(num, den) * (1 if p.lc() > 0 else -1)
    f = p.ring.field
    return content, Poly(p.ring, {e: f(Fraction(int(c.p), int(c.q)) / content) for e, c in p.terms.items()})


def _zz_gcd(a: Poly, b: Poly) -> Poly:
    """The gcd over ZZ of two nonzero integral polynomials (content times the primitive gcd)."""
    ca, _ = _integral(a)
    cb, _ = _integral(b)
    _, g = _integral(qq_gcd(a, b))
    c = igcd(abs(ca.numerator), abs(cb.numerator))
    return g * g.ring.field(c)


def _zz_lcm(a: Poly, b: Poly) -> Poly:
    return divide_exact(a * b, _zz_gcd(a, b))


def eliminate_pair(f: Poly, g: Poly, i: int, ring: PolyRing) -> Optional[list[Poly]]:
    """A generator of (f, g) ∩ ZZ[the variables but x_i] when f or g has leading coefficient ±1 in
    x_i and their resultant is not zero (None otherwise: the caller computes a Gröbner basis)."""
    for a, b in ((f, g), (g, f)):
        ca = _coefficients(a, i)
        n = max(ca)
        lead = ca[n]
        if n >= 1 and lead.is_constant() and abs(lead.lc()) == 1:
            break
    else:
        return None
    unit = lead  # 1/lead = lead for ±1
    cb = _reduce_mod(_coefficients(b, i), ca, n, unit)
    cols = []
    power = {k: v for k, v in cb.items()}
    for j in range(n):
        cols.append([power.get(k, ring.zero()) for k in range(n)])
        shifted = {k + 1: v for k, v in power.items()}
        power = _reduce_mod(shifted, ca, n, unit)
    rows = [[cols[j][k] for j in range(n)] for k in range(n)]
    r = KM.det(KM.Matrix(ring, n, n, [p for row in rows for p in row]))
    if r.is_zero():
        return None
    L = ring.one()
    for k in range(n):  # c_k = adj(M)[k][0] = (-1)^k det(M without row 0 and column k)
        if n == 1:
            ck = ring.one()
        else:
            sub = [row[:k] + row[k + 1:] for row in rows[1:]]
            ck = KM.det(KM.Matrix(ring, n - 1, n - 1, [p for row in sub for p in row]))
        if ck.is_zero():
            continue
        part = divide_exact(r, _zz_gcd(r, ck))
        L = _zz_lcm(L, part)
    return [_integral(L)[1] * ring.field(abs(_integral(L)[0]))]
