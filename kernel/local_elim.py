"""Elimination in a local or mixed ordering (Singular's ``eliminate`` with a local basering): the
eliminated variables get a positive weight ahead of the ring's ordering, ``(a(w), ordering)``
with ``w_i = 1`` on them and 0 elsewhere, so that every element of a standard basis whose leading
monomial is free of them is free of them altogether; those elements generate the elimination
ideal in the localization of the remaining variables (Greuel–Pfister, *A Singular Introduction
to Commutative Algebra*, 1.8.2, for orderings with a global part)."""
from __future__ import annotations

from typing import Sequence

from .order import Block, MonomialOrder
from .poly import Poly, PolyRing


def elimination_order(ring: PolyRing, var_indices: Sequence[int]) -> MonomialOrder:
    """``(a(w), ring's ordering)`` with ``w`` the indicator of ``var_indices``."""
    chosen = set(var_indices)
    w = tuple(1 if i in chosen else 0 for i in range(ring.nvars))
    return MonomialOrder([Block("a", 0, w)] + list(ring.order.blocks), ring.nvars)


def eliminate_local(polys: Sequence[Poly], var_indices: Sequence[int], ring: PolyRing) -> list[Poly]:
    """The elements free of the variables ``var_indices`` of a standard basis of ``polys`` for
    :func:`elimination_order`, as polynomials of ``ring``."""
    from .engines import standard_basis
    if not var_indices:
        return standard_basis([p for p in polys if not p.is_zero()], ring)
    big = PolyRing(ring.field, ring.names, elimination_order(ring, var_indices))
    basis = standard_basis([Poly(big, p.terms) for p in polys if not p.is_zero()], big)
    return [Poly(ring, b.terms) for b in basis if not any(e[i] for e in b.terms for i in var_indices)]
