"""general.lib's ``sort``: the generators of an ideal or module, or the entries of an intvec or list,
sorted, with the permutation that sorts them."""
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


def _bubble(ctx, items: list) -> list[int]:
    """general.lib's bubble sort of an intvec's or list's entries by Singular's ``>`` (stable; for
    intvecs Singular's comparison, which general.lib warns is no order with negative entries)."""
    from ..dsl.ops import compare
    ring = ctx.basering().poly if ctx.ring is not None else None
    pivot = list(range(len(items)))
    done = False
    while not done:
        done = True
        for n in range(len(items) - 1):
            if compare(">", items[pivot[n]], items[pivot[n + 1]], ring):
                pivot[n], pivot[n + 1] = pivot[n + 1], pivot[n]
                done = False
    return pivot


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
        pivot = _bubble(ctx, items)
        ordered = [items[k] for k in pivot]
        return List([IntVec(ordered) if isinstance(x, IntVec) else List(ordered), IntVec([k + 1 for k in pivot])])
    from ..dsl.values_modules import Module
    if not isinstance(x, (Ideal, Module)):
        return List([x, 0])
    return _sort_generators(ctx, x, opts)


def _leads_order(ring: Any, gens: list) -> list[int]:
    """sortvec: the positions (from 1) of the generators by increasing leading term, zeros last as 0."""
    from functools import cmp_to_key
    from ..dsl.values_modules import Vector, kernel_key, lead_term
    if all(isinstance(g, Poly) for g in gens):
        return list(sortvec(Ideal(ring, [Poly(ring, g.terms) for g in gens])).values)
    key = kernel_key(ring)
    leads = [lead_term(Vector(ring, [Poly(ring, p.terms) for p in g.entries])) for g in gens]
    idx = [k for k in range(len(gens)) if leads[k] is not None]
    idx.sort(key=cmp_to_key(lambda a, b: -1 if key(leads[a]) < key(leads[b]) else int(key(leads[a]) > key(leads[b]))))
    return [k + 1 for k in idx] + [0] * (len(gens) - len(idx))


def _sort_generators(ctx, M: Any, opts: tuple) -> List:
    """sort of an ideal or module as general.lib does it: without options the nonzero generators by
    increasing leading term (reversed when all are equal); with an ordering (a string such as "c,dp")
    or an intvec all generators in that order (only the first size(M) places are filled), reversed
    when a second argument is nonzero."""
    from ..dsl.values_modules import Module
    ring = M.ring
    nonzero = M.nonzero()
    if not opts:
        gens = nonzero or [M.gens[0]]
        if len(gens) > 1 and all(g == gens[0] for g in gens):
            v = list(range(len(gens), 0, -1))
        else:
            v = _leads_order(ring, gens)
    else:
        gens = list(M.gens)
        if isinstance(opts[0], str):
            from ..dsl.rings import make_ring, parse_ordering
            base = ctx.basering()
            other = make_ring(base.characteristic, base.params, list(ring.names),
                              parse_ordering(opts[0], ring.nvars)).poly
            v = _leads_order(other, gens)
        else:
            v = list(opts[0].values) if isinstance(opts[0], IntVec) else [int(opts[0])]
        if len(opts) == 2 and opts[1] != 0:
            v = v[::-1]
    out = list(gens)
    for jj in range(min(len(v), len(nonzero))):
        if v[jj] <= 0:
            v[jj] = jj + 1
        out[jj] = gens[v[jj] - 1]
    if not any(v):
        v = [1]
    result = Ideal(ring, out) if isinstance(M, Ideal) else Module(ring, out, M.rank)
    return List([result, IntVec(v)])
