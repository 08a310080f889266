"""Singular's ``factorize`` over QQ and Z/p (with parameters: :mod:`.factorize_params`), with Singular
4.3.1's choice of signs and order.

The factors come from :mod:`mech.kernel.factor`; what Singular prints follows its factory library:

* a monomial ``c*x^a*y^b`` gives ``c, x, y`` with exponents ``1, a, b``;
* otherwise ``f`` is first made primitive with positive leading coefficient (over QQ); a
  homogeneous ``f`` in two or more variables is dehomogenized by setting ``xn = 1`` (``xn`` the last
  variable of highest degree), factored and the factors homogenized again (with ``xn`` as a factor
  of the remaining multiplicity);
* each factor is scaled to positive (QQ) or unit (Z/p) leading coefficient for the lexicographic
  ordering in which the *last* variable is the largest -- except a univariate ``f`` of degree 1 over
  QQ, which keeps its sign;
* the factors are sorted by multiplicity, then by factory's comparison of polynomials (recursive in
  the variable of highest index: degree, then coefficients from the top; a shorter polynomial is
  smaller); the unit ``f / prod(factors)`` comes first.
"""
from __future__ import annotations

from functools import cmp_to_key
from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.values import Ideal, IntVec, List
from ..kernel import Poly
from ..dsl.registry import command
from ..kernel.algext_fq import fq_factors
from .factorize_params import param_factorization
from .standard import normalize

Factors = list[tuple[Poly, int]]


def _revlex_lead(p: Poly) -> Any:
    """The coefficient of the largest term in the lexicographic ordering with the last variable largest."""
    return p.terms[max(p.terms, key=lambda e: e[::-1])]


def _scale(g: Poly) -> Poly:
    """A factor as factory returns it: integer primitive (QQ) with positive, or monic (Z/p),
    leading coefficient with respect to :func:`_revlex_lead`."""
    if hasattr(g.ring.field, "modulus"):  # QQ[a]/(m): monic in the ring's ordering; Z/p[a]/(m): as Z/p
        return g * (g.ring.field.one / _revlex_lead(g)) if g.ring.field.characteristic else g.monic()
    g = normalize(g)
    if g.ring.field.characteristic:
        return g * (g.ring.field.one / _revlex_lead(g))
    return -g if _revlex_lead(g) < 0 else g


def _homogenize(g: Poly, i: int) -> Poly:
    top = g.total_degree()
    terms = {}
    for e, c in g.terms.items():
        e2 = list(e)
        e2[i] += top - sum(e)
        terms[tuple(e2)] = c
    return Poly(g.ring, terms)


def _factory(F: Poly) -> Factors:
    """The non-constant factors of ``F`` with their multiplicities, scaled as factory does."""
    from ..kernel.factor import factorize as kernel_factorize
    ring = F.ring
    variables = sorted(F.variables())
    if len(variables) >= 2 and F.is_homogeneous():
        degrees = {v: F.degree_in(v) for v in variables}
        top = max(degrees.values())
        xn = max(v for v in variables if degrees[v] == top)
        left = degrees[xn]
        dehomogenized = Poly(ring, {e[:xn] + (0,) + e[xn + 1:]: c for e, c in F.terms.items()})  # no terms merge
        out = []
        for g, m in _factory(dehomogenized):
            h = _homogenize(g, xn)
            if hasattr(ring.field, "modulus") and ring.field.characteristic:
                h = _scale(h)  # Z/p[a]/(m): Singular prints the homogenized factor with revlex lead 1
            left -= h.degree_in(xn) * m
            out.append((h, m))
        if left:
            out.append((ring.gen(xn), left))
        return out
    if len(variables) == 1 and F.total_degree() == 1 and not ring.field.characteristic \
            and not getattr(ring.field, "params", ()):
        g = normalize(F)
        return [(g if F.lc() > 0 else -g, 1)]
    if hasattr(ring.field, "modulus") and ring.field.characteristic:
        return [(_scale(g), m) for g, m in fq_factors(F)]
    return [(_scale(g), m) for g, m in kernel_factorize(F)[1]]


def _level(terms: dict) -> int:
    return max((i + 1 for e in terms for i, k in enumerate(e) if k), default=0)


def _compare(a: dict, b: dict, char: int) -> int:
    """Factory's total order of polynomials (given as term dictionaries): a higher main variable
    is larger; with the same main variable the coefficients of its powers are compared from the
    highest power down (a higher power, or a larger coefficient, wins; a polynomial that runs out
    of terms first is smaller); numbers compare as rationals (QQ) or as 0..p-1 (Z/p)."""
    la, lb = _level(a), _level(b)
    if la != lb:
        return 1 if la > lb else -1
    if la == 0:
        x = next(iter(a.values()), 0)
        y = next(iter(b.values()), 0)
        x, y = _number_key(x, char), _number_key(y, char)
        return (x > y) - (x < y)
    v = la - 1
    ca, cb = _split(a, v), _split(b, v)
    for (ea, pa), (eb, pb) in zip(ca, cb):
        if ea != eb:
            return 1 if ea > eb else -1
        c = _compare(pa, pb, char)
        if c:
            return c
    return (len(ca) > len(cb)) - (len(ca) < len(cb))


def _number_key(c: Any, char: int) -> Any:
    """A number as factory compares it: a rational, a residue 0..p-1, or an element of QQ[a]/(m) by its
    degree in a and then its coefficients from the top."""
    u = getattr(c, "u", None)
    if u is None:
        return int(c) if char else c
    cs = [int(v) if char else v for v in u.coeffs()]
    return (len(cs), cs[::-1])


def _split(terms: dict, v: int) -> list[tuple[int, dict]]:
    """The coefficients of the powers of variable ``v``, highest power first."""
    parts: dict[int, dict] = {}
    for e, c in terms.items():
        parts.setdefault(e[v], {})[e[:v] + (0,) + e[v + 1:]] = c
    return sorted(parts.items(), key=lambda t: -t[0])


def factory_factors(f: Poly) -> Factors:
    """The non-constant factors of ``f`` with their multiplicities, scaled and sorted as factory does."""
    try:
        factors = _factory(normalize(f))
    except NotImplementedError:
        raise MechRuntimeError(f"factorize is not available over the coefficient field {f.ring.field!r}") from None
    char = f.ring.field.characteristic
    factors.sort(key=cmp_to_key(lambda s, t: (s[1] > t[1]) - (s[1] < t[1]) or _compare(s[0].terms, t[0].terms, char)))
    return factors


def singular_factorization(f: Poly) -> tuple[Any, Factors]:
    """``(unit, [(factor, multiplicity), ...])`` in Singular's order, ``f = unit * prod``."""
    ring = f.ring
    if len(f.terms) <= 1:
        unit = f.lc() if f.terms else ring.field.zero
        e = f.lm() if f.terms else ring.zero_exp
        return unit, [(ring.gen(i), k) for i, k in enumerate(e) if k]
    if getattr(ring.field, "params", ()) and not hasattr(ring.field, "modulus"):
        return param_factorization(f, factory_factors)
    factors = factory_factors(f)
    lead = ring.field.one
    for g, m in factors:
        lead = lead * g.lc() ** m
    return f.lc() / lead, factors


@command("factorize")
def factorize(f: Poly, how: int = 0) -> Any:
    """factorize(f[, n]): the factorization of f over QQ or Z/p: the list of the ideal of the unit
    and the irreducible factors and the intvec of their multiplicities; n = 1: the ideal of the
    factors only; n = 2: the list of the factors and multiplicities without the unit; n = 3: the
    product of the distinct factors.

    Example:
      ring r = 0,(x,y),dp;
      factorize(2x2-2y2);
      → [1]:
      →    _[1]=2
      →    _[2]=x-y
      →    _[3]=x+y
      → [2]:
      →    1,1,1
      factorize(x3-x, 1);
      → _[1]=x
      → _[2]=x-1
      → _[3]=x+1
    """
    if how not in (0, 1, 2, 3):
        raise MechRuntimeError(f"factorize(f, {how}): the second argument must be 0, 1, 2 or 3")
    ring = f.ring
    unit, factors = singular_factorization(f)
    polys = [g for g, _ in factors]
    mults = [m for _, m in factors]
    if how == 3:
        product = ring.zero() if f.is_zero() else ring.one()
        for g in polys:
            product = product * g
        return product
    if how == 1:
        return Ideal(ring, polys or [ring.zero() if f.is_zero() else ring.one()])
    if how == 2:
        return List([Ideal(ring, polys or [ring.zero() if f.is_zero() else ring.one()]), IntVec(mults or [1])])
    return List([Ideal(ring, [ring.const(unit)] + polys), IntVec([1] + mults)])
