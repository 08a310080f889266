"""The polynomial and list operations of the characteristic-set method (:mod:`.charsets`), in the
recursive view of a polynomial that the method uses.

A polynomial's *level* is the index (1-based) of its highest variable, its *main variable*; a constant
has level 0.  ``LC`` is the leading coefficient as a polynomial in the main variable (or a given one),
``lc`` the coefficient of the lexicographically largest term with the last variable largest.  Every
set built by the method is normalized: over QQ integer primitive with positive ``lc``, over Z/p with
``lc`` 1.  Lists behave as ordered sets with the method's conventions: ``union(a, b)`` is ``b``
followed by the elements of ``a`` not in ``b`` (so ``union(acc, [x])`` puts a new ``x`` first), and
``difference(a, b)`` keeps ``a``'s order.
"""
from __future__ import annotations

from typing import Any, Sequence

from ..kernel import Poly
from ..kernel import factor as K
from .factorize import factory_factors


# ---------------------------------------------------------------- one polynomial
def level(f: Poly) -> int:
    return max((i + 1 for e in f.terms for i, k in enumerate(e) if k), default=0)


def degree(f: Poly, v: int = 0) -> int:
    """The degree in the variable of level ``v`` (default: the main variable); -1 for zero."""
    if f.is_zero():
        return -1
    v = v or level(f)
    return max(e[v - 1] for e in f.terms) if v else 0


def coeff(f: Poly, v: int, k: int) -> Poly:
    """The coefficient of ``x_v^k`` as a polynomial in the other variables."""
    return Poly(f.ring, {e[:v - 1] + (0,) + e[v:]: c for e, c in f.terms.items() if e[v - 1] == k})


def LC(f: Poly, v: int = 0) -> Poly:
    v = v or level(f)
    return coeff(f, v, degree(f, v)) if v else f


def var_power(f: Poly, v: int, k: int) -> Poly:
    e = [0] * f.ring.nvars
    e[v - 1] = k
    return f.ring.monomial(tuple(e))


def lc(f: Poly) -> Any:
    return f.terms[max(f.terms, key=lambda e: e[::-1])]


def normalize(f: Poly) -> Poly:
    if f.is_zero():
        return f
    if f.ring.field.characteristic:
        return f * (f.ring.field.one / lc(f))
    g = K.normalize(f)  # integer primitive
    return -g if lc(g) < 0 else g


def is_const(f: Poly) -> bool:
    return f.is_constant()


def divides(g: Poly, f: Poly) -> Poly | None:
    """``f / g`` when ``g`` divides ``f``, else None."""
    if f.is_zero():
        return f
    try:
        return K.divide_exact(f, g)
    except Exception:  # noqa: BLE001 - the kernel's DivisionError or an inexact quotient
        return None


def content(f: Poly, v: int = 0) -> Poly:
    """The gcd of the coefficients of the powers of the variable ``v`` (default: the main variable)."""
    v = v or level(f)
    if not v:
        return f
    g = f.ring.zero()
    for k in range(degree(f, v) + 1):
        c = coeff(f, v, k)
        if not c.is_zero():
            g = K.gcd(g, c)
            if g.is_constant():
                return g
    return g


def gcd(a: Poly, b: Poly) -> Poly:
    return K.gcd(a, b)


def sqrfree_part(f: Poly) -> Poly:
    return normalize(K.squarefree_part(f)) if not f.is_constant() else f.ring.one()


def factors(f: Poly) -> list[tuple[Poly, int]]:
    """The non-constant irreducible factors with multiplicities, in factory's sorted order."""
    return [] if f.is_constant() else factory_factors(f)


def size(f: Poly) -> int:
    return len(f.terms)


def prem(F: Poly, G: Poly) -> Poly:
    """The pseudo-remainder of F by G in G's main variable, dividing out the gcd of the leading
    coefficients at each step (up to a constant factor: callers normalize)."""
    lg = level(G)
    if level(F) < lg:
        return F
    v = lg
    dG, dF = degree(G, v), degree(F, v)
    f, g = F, G
    if dG <= dF:
        l = LC(G, v)
        g = G - l * var_power(G, v, dG)
    else:
        l = G.ring.one()
    while dG <= dF and not f.is_zero():
        lf = LC(f, v)
        test = gcd(l, lf)
        lu, lv = K.divide_exact(l, test), K.divide_exact(lf, test)
        t = g * lv * var_power(G, v, dF - dG)
        f = f.ring.zero() if dF == 0 else f - lf * var_power(f, v, dF)
        f = f * lu - t
        dF = degree(f, v)
    return f


def prem_list(f: Poly, L: Sequence[Poly]) -> Poly:
    rem = f
    for g in reversed(L):
        rem = normalize(prem(rem, g))
    return rem


def premb(f: Poly, L: Sequence[Poly]) -> Poly:
    """prem_list with a quicker zero test: the last step is skipped when the primitive part of L's
    first element divides the remainder."""
    rem = f
    for g in reversed(L[1:]):
        rem = normalize(prem(rem, g))
    first = L[0]
    if divides(K.divide_exact(first, content(first)), rem) is not None:
        return f.ring.zero()
    return normalize(prem(rem, first))


# ---------------------------------------------------------------- ordered sets
def union(a: Sequence, b: Sequence) -> list:
    out = list(b)
    out.extend(x for x in a if x not in b)
    return out


def difference(a: Sequence, b: Sequence) -> list:
    return [x for x in a if x not in b]


def is_subset(a: Sequence, b: Sequence) -> bool:
    return all(x in b for x in a)


# ---------------------------------------------------------------- ranks and factor sets
def lower_rank(F: Poly, G: Poly, ind: list[int]) -> bool:
    if is_const(F):
        if is_const(G):
            ind[0] = 1
        return True
    if is_const(G):
        return False
    lF, lG = level(F), level(G)
    if lF != lG:
        return lF < lG
    dF, dG = degree(F), degree(G)
    if dF != dG:
        return dF < dG
    return lower_rank(LC(F), LC(G), ind)


def lowest_rank(L: Sequence[Poly]) -> Poly:
    f = L[0]
    ind = [0]
    for g in L[1:]:
        if lower_rank(g, f, ind):
            if ind[0]:
                if size(g) < size(f):
                    f = g
                ind[0] = 0
            else:
                f = g
    return f


def factors_of_initials(L: Sequence[Poly]) -> list[Poly]:
    out: list[Poly] = []
    for f in L:
        for g, _ in factors(LC(f)):
            out = union(out, [normalize(g)])
    return out


def factor_set(PS: Sequence[Poly]) -> list[Poly]:
    out: list[Poly] = []
    for f in PS:
        for g, _ in factors(f):
            out = union(out, [normalize(g)])
    return out


def uni_gcd(L: Sequence[Poly]) -> list[Poly]:
    """The polynomials in the first variable alone replaced by their gcd when there are at least three."""
    uni = [f for f in L if level(f) == 1]
    if len(uni) <= 2:
        return list(L)
    g = uni[0]
    for f in uni[1:]:
        g = gcd(g, f)
    return union(difference(L, uni), [normalize(g)])
