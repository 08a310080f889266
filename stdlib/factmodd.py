"""Singular's built-in ``factmodd``: Hensel lifting of a factorization h = f0*g0 mod x to one modulo
x^(d+1) (von zur Gathen–Gerhard, *Modern Computer Algebra*, 15.4): with s*g0 + t*f0 = 1 in K[y], the
error e_k (the coefficient of x^k of h - f*g) is split as a*g0 + b*f0 with deg a < deg f0, and f, g grow
by x^k*a, x^k*b.  The lifted factors are unique under these degree bounds."""
from __future__ import annotations

import flint

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import List
from ..kernel import Poly
from ..kernel.coeffs import PrimeField, RationalField


def _univariate(field, coeffs: dict[int, object]):
    n = max(coeffs, default=-1) + 1
    vals = [coeffs.get(i, field.zero) for i in range(n)]
    if isinstance(field, PrimeField):
        return flint.nmod_poly([int(v) for v in vals], field.characteristic)
    return flint.fmpq_poly([flint.fmpq(v) for v in vals])


def _split(p: Poly, xi: int, yi: int) -> dict[int, object]:
    """p as a dict x-degree -> flint polynomial in y."""
    parts: dict[int, dict[int, object]] = {}
    for e, c in p.terms.items():
        if any(k for i, k in enumerate(e) if i not in (xi, yi)):
            raise MechRuntimeError("factmodd: the polynomials may involve only the two variables")
        parts.setdefault(e[xi], {})[e[yi]] = c
    return {k: _univariate(p.ring.field, v) for k, v in parts.items()}


def _join(parts: dict[int, object], ring, xi: int, yi: int) -> Poly:
    field = ring.field
    terms = {}
    for k, u in parts.items():
        for j, c in enumerate(u.coeffs()):
            if c != 0:
                e = [0] * ring.nvars
                e[xi], e[yi] = k, j
                terms[tuple(e)] = field(int(c)) if isinstance(field, PrimeField) else c
    return Poly(ring, terms)


@command("factmodd")
def factmodd(h: Poly, d: int, f0: Poly, g0: Poly, xvar: int = 1, yvar: int = 2) -> List:
    """factmodd(h, d, f0, g0[, i, j]): the list of f, g with h = f*g modulo x^(d+1), f = f0 and g = g0
    modulo x, for x = var(i) and y = var(j) (default var(1), var(2)), where f0, g0 are coprime
    polynomials in y with h = f0*g0 modulo x; f - f0 has lower degree in y than f0 (f0 monic: f monic).

    Example:
      ring r = 0,(x,y),dp;
      poly h = y2+xy-1+x2;
      poly f0 = y-1;
      poly g0 = y+1;
      factmodd(h, 2, f0, g0);
      → [1]:
      →    3/8x2+1/2x+y-1
      → [2]:
      →    -3/8x2+1/2x+y+1
    """
    ring = h.ring
    if not isinstance(ring.field, (RationalField, PrimeField)):
        raise MechRuntimeError("factmodd is supported over QQ and Z/p")
    xi, yi = xvar - 1, yvar - 1
    if not (0 <= xi < ring.nvars and 0 <= yi < ring.nvars) or xi == yi:
        raise MechRuntimeError("factmodd: the variables must be two different ones of the ring")
    H, F0, G0 = _split(h, xi, yi), _split(f0, xi, yi), _split(g0, xi, yi)
    if set(F0) - {0} or set(G0) - {0}:
        raise MechRuntimeError("factmodd: f0 and g0 must not involve x")
    fz, gz = F0.get(0), G0.get(0)
    if fz is None or gz is None:
        raise MechRuntimeError("factmodd: f0 and g0 must be nonzero")
    if H.get(0, fz * 0) != fz * gz:
        raise MechRuntimeError("factmodd: h is not f0*g0 modulo x")
    g, s, t = fz.xgcd(gz) if hasattr(fz, "xgcd") else (None, None, None)
    if g is None or g.degree() != 0:
        raise MechRuntimeError("factmodd: f0 and g0 must be coprime")
    s, t = s / g[0], t / g[0]  # s*f0 + t*g0 = 1
    f, gg = {0: fz}, {0: gz}
    for k in range(1, d + 1):
        e = H.get(k, fz * 0)
        for i, fi in f.items():
            gj = gg.get(k - i)
            if gj is not None:
                e = e - fi * gj
        if e == 0:
            continue
        a = (e * t) % fz  # a*g0 + b*f0 = e with deg a < deg f0
        b = (e - a * gz) // fz
        if a != 0:
            f[k] = a
        if b != 0:
            gg[k] = b
    return List([_join(f, ring, xi, yi), _join(gg, ring, xi, yi)])
