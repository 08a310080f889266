"""general.lib's ``sort``: the generators of an ideal, or the entries of an intvec or list, sorted, with
the permutation that sorts them."""
from __future__ import annotations

from typing import Any

from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, List
from ..kernel import Poly
from .general_lib import LIB


def sortvec(I: Ideal) -> IntVec:
    """The positions of I's generators by increasing leading monomial (zeros last), as Singular's sortvec."""
    from functools import cmp_to_key
    order = I.ring.order
    nonzero = [i for i, g in enumerate(I.gens) if not g.is_zero()]
    nonzero.sort(key=cmp_to_key(lambda i, j: order.compare(I.gens[i].lm(), I.gens[j].lm())))
    return IntVec([i + 1 for i in nonzero] + [0] * (len(I.gens) - len(nonzero)))


def _permute(items: list, v: list[int]) -> tuple[list, list[int]]:
    """general.lib's reordering: the jj-th item becomes items[v[jj]] (v[jj] <= 0: jj itself)."""
    v = list(v)
    out = list(items)
    for jj in range(min(len(v), len(items))):
        if v[jj] <= 0:
            v[jj] = jj + 1
        out[jj] = items[v[jj] - 1]
    return out, v


@command("sort", lib=LIB)
def sort(ctx, x: Any, *opts: Any) -> List:
    """sort(id[, v][, o][, n]): the list of id sorted and the permutation (an intvec) that sorts it: the
    generators of an ideal (zeros dropped) by increasing leading monomial for the ring's ordering (or the
    ordering o, a string such as "ls"), or in the order the intvec v gives; the entries of an intvec or
    list increasingly; n != 0 reverses the order.

    Example:
      LIB "general.lib";
      ring r = 0,(x,y,z,t),lp;
      sort(ideal(x3, z3, xyz));
      → [1]:
      →    _[1]=z3
      →    _[2]=xyz
      →    _[3]=x3
      → [2]:
      →    2,3,1
    """
    if isinstance(x, (IntVec, List)):
        items = list(x.values if isinstance(x, IntVec) else x.items)
        pivot = sorted(range(len(items)), key=lambda k: items[k])
        ordered = [items[k] for k in pivot]
        return List([IntVec(ordered) if isinstance(x, IntVec) else List(ordered), IntVec([k + 1 for k in pivot])])
    if not isinstance(x, Ideal):
        return List([x, 0])
    ring = x.ring
    gens = x.nonzero() or [ring.zero()]
    I = Ideal(ring, gens)
    reverse = False
    if opts and isinstance(opts[0], str):
        from ..dsl.rings import make_ring
        from .ring_lib import parse_ordering
        base = ctx.basering()
        other = make_ring(base.characteristic, base.params, list(ring.names), parse_ordering(opts[0], ring.nvars)).poly
        v = list(sortvec(Ideal(other, [Poly(other, g.terms) for g in gens])).values)
        reverse = len(opts) > 1 and opts[1] != 0
    elif opts and isinstance(opts[0], IntVec):
        v = list(opts[0].values)
        reverse = len(opts) > 1 and opts[1] != 0
    elif all(g == gens[0] for g in gens):
        v = list(range(len(gens), 0, -1))
    else:
        v = list(sortvec(I).values)
    if reverse:
        v = v[::-1]
    out, v = _permute(gens, v)
    return List([Ideal(ring, out), IntVec(v)])
