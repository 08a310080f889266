"""Motion modes by parts: the minimal primes of ``J`` from those of groups of its generators.

When ``J = G_1 + ... + G_k`` (every generator of ``J`` in some group ``G_i``), ``V(J)`` is the
intersection of the ``V(G_i)``, so the union of ``V(p_1 + ... + p_k)`` over one minimal prime ``p_i``
of each group: the minimal primes of ``J`` are the minimal ones among the minimal primes of these
sums.  They are built one group at a time (the minimal primes of ``G_1 + ... + G_j`` combined with
those of ``G_(j+1)``), keeping only the minimal ones at each step (a sum with a larger prime lies
in the sum with the smaller).  The groups are the loops of a planar linkage: the closure
equations that meet the same circles ``c^2 + s^2 - r`` of the bars' direction variables, with
those circles (a loop's two closure equations, x and y).  A linkage with equal bars (a rhombus, a
degenerate four-bar) has loops whose own ideals split; their parts make each sum simpler than
``J`` (Peaucellier's inversor: three loops, whose minimal primes take seconds in all, where
``minAssGTZ(J)`` did not finish in minutes, in Singular neither).

Each minimal-prime computation first removes the variables that are linear functions of the others
(:mod:`mech.stdlib.analysis_linear`: the loops' bar identities ``u_i = u_j`` leave small rings).
"""
from __future__ import annotations

from typing import Optional, Sequence

from mech.kernel import Poly, PolyRing
from mech.kernel.ideals import is_subset
from mech.stdlib.analysis_linear import min_ass_reduced


def _variables(p: Poly) -> set[int]:
    return {i for e in p.terms for i, k in enumerate(e) if k}


def _is_circle(p: Poly) -> bool:
    """``a x^2 + b y^2 + c`` (two variables, pure squares, a constant)."""
    squares = [e for e in p.terms if sum(e) == 2 and max(e) == 2]
    return len(p.terms) == 3 and len(squares) == 2 and any(sum(e) == 0 for e in p.terms)


def loop_groups(J: Sequence[Poly]) -> list[list[Poly]] | None:
    """The generators grouped by loop: the non-circle generators meeting the same circles, each
    group with those circles; generators in no group form groups of their own.  None when there
    are fewer than two groups (nothing to split)."""
    circles = [g for g in J if _is_circle(g)]
    cvars = [_variables(c) for c in circles]
    groups: dict[frozenset[int], list[Poly]] = {}
    alone: list[list[Poly]] = []
    for g in J:
        if _is_circle(g):
            continue
        vs = _variables(g)
        sup = frozenset(k for k, c in enumerate(cvars) if vs & c)
        if not sup:
            alone.append([g])
            continue
        groups.setdefault(sup, []).append(g)
    out = [gs + [circles[k] for k in sorted(sup)] for sup, gs in groups.items()] + alone
    used = {k for sup in groups for k in sup}
    out += [[c] for k, c in enumerate(circles) if k not in used]
    return out if len(out) >= 2 else None


def minimal(primes: list[list[Poly]], ring: PolyRing) -> list[list[Poly]]:
    """The distinct primes not containing another one of the list."""
    out: list[list[Poly]] = []
    for P in sorted(primes, key=lambda b: (len(b), sum(len(p.terms) for p in b))):
        if any(is_subset(Q, P, ring) for Q in out):
            continue
        out = [Q for Q in out if not is_subset(P, Q, ring)] + [P]
    return out


def modes_by_parts(J: Sequence[Poly], ring: PolyRing) -> Optional[list[list[Poly]]]:
    """The minimal primes of ``J`` from its loops' (None when it has fewer than two loops)."""
    groups = loop_groups(J)
    if groups is None:
        return None
    parts = sorted((min_ass_reduced(G, ring) for G in groups), key=len)
    current: list[list[Poly]] = [[]]
    for primes in parts:
        current = minimal([P for Q in current for p in primes for P in min_ass_reduced(list(Q) + list(p), ring)],
                          ring)
    return current
