"""Normal forms for local and mixed orderings: Singular's ``reduce``/``NF`` (a weak normal form
by Mora's normal form, then tail reduction) and an exact normal form through the homogenized
ideal (:mod:`.lazard`)."""
from __future__ import annotations

from functools import lru_cache
from typing import Sequence

from .errors import DomainError
from .groebner import groebner, normal_form
from .hilbert import kbase
from .lazard import dehomogenize, homogenize, homogenized_ring
from .mora import Budget, BudgetExceeded, Elem, Terms, cancel_unit, elems, mora_normal_form, reduce_by
from .order import Exp
from .poly import Poly, PolyRing, divides


def weak_normal_form(f: Poly, basis: Sequence[Poly], bad_ecart: bool = False) -> Poly:
    """Singular's ``reduce``/``NF`` for a local or mixed ordering: a weak normal form ``h`` of
    ``f`` (``u f - h`` in the ideal for a unit ``u``, and ``h = 0`` or ``LM(h)`` not in
    ``L(basis)``), so zero iff ``f`` lies in the ideal of ``K[x]_>`` when ``basis`` is a
    standard basis.  Mora's normal form (leading terms, then a leading-monomial unit factor
    cancelled: ``x^a u -> x^a``, then :func:`tail_reduce`), as Singular computes it; for a local degree
    ordering (``ds Ds ws Ws``) past its :class:`Budget` the exact normal form of
    :func:`homogenized_normal_form`.  The result is determined up to a unit and modulo the
    ideal, not term by term.  ``bad_ecart`` (Singular's ``reduce(f, I, 2)``): the division
    algorithm of global orderings instead, every term from the largest down reduced by any element
    whose leading monomial divides it (no unit cancelled; see :func:`tail_reduce`)."""
    if f.is_zero():
        return f
    if bad_ecart:
        return Poly(f.ring, tail_reduce(dict(f.terms), basis, True, True))
    key = f.ring.order.key
    degree_first = all(v < 0 for v in f.ring.order.first_row())
    try:
        h = mora_normal_form(dict(f.terms), elems(basis), key, Budget() if degree_first else None)
    except BudgetExceeded:
        return homogenized_normal_form(f, basis)
    if not h:
        return Poly(f.ring, h)
    return Poly(f.ring, tail_reduce(cancel_unit(h, key), basis))


def highest_corner(basis: Sequence[Poly]) -> Exp | None:
    """The highest corner of a standard basis for a local ordering: the smallest monomial
    outside the leading ideal, when there are finitely many; every smaller monomial lies in
    the ideal of the local ring (its normal form is a combination of smaller standard
    monomials).  None when the quotient is infinite-dimensional or the ordering not local."""
    basis = [b for b in basis if not b.is_zero()]
    if not basis or not basis[0].ring.order.is_local:
        return None
    ring = basis[0].ring
    std = kbase([b.lm() for b in basis], ring.nvars)
    return min(std, key=ring.order.key) if std else None


BAD_ECART_STEPS = 10_000
"""Tail reductions with bad ecart allowed before :func:`tail_reduce` gives up (they need not end
for a local ordering: ``x`` by ``x - x^2``)."""


def tail_reduce(h: Terms, basis: Sequence[Poly], bad_ecart: bool = False, whole: bool = False) -> Terms:
    """Reduce the terms after the leading one, from the largest down, as Singular's ``reduce``
    mostly does: drop those below the highest corner (:func:`highest_corner`: they lie in the
    ideal); reduce a term ``t`` by the first basis element (smallest leading monomial first)
    whose leading monomial divides it, any element when there is a highest corner (finitely
    many monomials lie above it), else only an element whose ecart is at most that of the
    tail from ``t`` on (its degree minus ``deg t``: the degrees of the tail never exceed
    their first maximum, so this ends).  The leading term and the class modulo the ideal do
    not change.  With ``bad_ecart`` every divisible term is reduced (the division algorithm of
    global orderings), with ``whole`` the leading term too; :class:`~.errors.DomainError` after
    :data:`BAD_ECART_STEPS` reductions."""
    ring = basis[0].ring if basis else None
    if ring is None or len(h) < (1 if whole else 2):
        return h
    key = ring.order.key
    corner = highest_corner(basis)
    pool = [Elem(dict(b.terms), key) for b in sorted(basis, key=lambda b: key(b.lm())) if not b.is_zero()]
    h = dict(h)
    done = set() if whole else {max(h, key=key)}
    steps = 0
    while True:
        if corner is not None:
            bound = key(corner)
            h = {e: c for e, c in h.items() if key(e) >= bound}
        rest = [e for e in h if e not in done]
        if not rest:
            return h
        t = max(rest, key=key)
        kt = key(t)
        ecart = max(sum(e) for e in h if key(e) <= kt) - sum(t)
        g = next((g for g in pool if divides(g.lm, t) and (bad_ecart or corner is not None or g.ecart <= ecart)),
                 None)
        if g is None:
            done.add(t)
        else:
            steps += 1
            if steps > BAD_ECART_STEPS:
                raise DomainError(f"the tail reduction with bad ecart did not end within {BAD_ECART_STEPS} steps")
            h = reduce_by(h, t, g)


@lru_cache(maxsize=32)
def _homogenized_basis(basis: tuple[Poly, ...]) -> tuple[PolyRing, list[Poly]]:
    hring = homogenized_ring(basis[0].ring)
    return hring, groebner([homogenize(b, hring) for b in basis], hring)


def homogenized_normal_form(f: Poly, basis: Sequence[Poly]) -> Poly:
    """A normal form with ``f - h`` in the ideal (no unit) and ``h = 0`` or ``LM(h)`` not in
    ``L(basis)``: the global normal form of ``t^k f^h`` modulo a Gröbner basis of the
    homogenized generators (ordering :func:`homogenized_order`) with ``t = 1``, for the
    first ``k = 0, 1, 3, 7, ...`` whose result has a leading monomial outside ``L(basis)``.
    Such a ``k`` exists when the ordering is a local degree ordering (its first weight row
    negative): the leading monomials of all ``h`` congruent to ``f`` whose leading monomial
    lies in ``L(basis)`` have bounded degree, and for ``k`` beyond that bound plus the ecarts
    of the basis, ``t^k`` times such a monomial is a leading monomial of the homogenized
    ideal.  For other orderings the loop need not end."""
    basis = [b for b in basis if not b.is_zero()]
    if f.is_zero() or not basis:
        return f
    ring, key = f.ring, f.ring.order.key
    hring, hbasis = _homogenized_basis(tuple(basis))
    lms = [b.lm() for b in basis]
    t = hring.gen(ring.nvars)
    fh, k = homogenize(f, hring), 0
    while True:
        h = dehomogenize(normal_form(fh * t ** k, hbasis))
        if not h or not any(divides(m, max(h, key=key)) for m in lms):
            return Poly(ring, h)
        k = 2 * k + 1
