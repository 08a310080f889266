"""Singular's ``facstd``: the factorizing Gröbner algorithm (Czapor; Gräbe).

Whenever an element of a Gröbner basis factors, the ideal splits into one ideal per irreducible
factor (V(I) is the union of their zero sets); the leaves, whose bases have only irreducible
elements, are the result, without those containing another leaf or one of the polynomials that
must not vanish.  The union of the zero sets is V(I); the split is not unique (Singular's own
choice may differ in components, so the conformance run compares the lists as sets of ideals).
"""
from __future__ import annotations

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Ideal, List
from ..kernel import Poly
from ..kernel.factor import factorize
from ..kernel.ideals import contains_all, std

MAX_COMPONENTS = 10_000  # a bound on the leaves explored (each costs a Gröbner basis)


@command("facstd")
def facstd(I: Ideal, *nonzero: Poly) -> List:
    """facstd(I[, f1, ...]): a list of standard bases of ideals whose zero sets together make V(I),
    found by factorizing the elements of Gröbner bases (the f1, ... must not vanish: components
    containing one are dropped).

    Example:
      ring r = 32003,(x,y,z),(c,dp);
      facstd(ideal(xyz, x2z));
      → [1]:
      →    _[1]=z
      → [2]:
      →    _[1]=x
    """
    ring = I.ring
    if not ring.order.is_global:
        raise MechRuntimeError("facstd: only global orderings are supported")
    leaves: list[list[Poly]] = []
    todo = [[p for p in I.gens if not p.is_zero()]]
    seen = 0
    while todo:
        seen += 1
        if seen > MAX_COMPONENTS:
            raise MechRuntimeError(f"facstd: more than {MAX_COMPONENTS} components explored")
        basis = std(todo.pop(), ring)
        if any(p.is_constant() for p in basis) or any(contains_all(basis, [f]) for f in nonzero):
            continue
        split = _first_reducible(basis)
        if split is None:
            leaves.append(basis)
            continue
        todo.extend(basis + [g] for g in reversed(split))
    leaves = _minimal(leaves)
    return List([Ideal(ring, b or [ring.zero()], is_std=True) for b in leaves] or
                [Ideal(ring, [ring.one()], is_std=True)])


def _first_reducible(basis: list[Poly]) -> list[Poly] | None:
    """The distinct irreducible factors of the first element of ``basis`` that is not irreducible."""
    for p in basis:
        _, factors = factorize(p)
        if len(factors) > 1 or (factors and factors[0][1] > 1):
            return [g for g, _ in factors]
    return None


def _minimal(leaves: list[list[Poly]]) -> list[list[Poly]]:
    """The leaves that contain no other leaf (of equal ones the first)."""
    out: list[list[Poly]] = []
    for k, b in enumerate(leaves):
        bigger = any(j != k and contains_all(b, c) and (not contains_all(c, b) or j < k)
                     for j, c in enumerate(leaves))
        if not bigger:
            out.append(b)
    return out
