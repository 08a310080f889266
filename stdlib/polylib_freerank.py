"""polylib.lib's ``freerank``: the rank of coker(M) when it is a free module (-1 otherwise), by a
minimal presentation: minimal generators of M (graded), the relations with a unit entry pruned with
the generators they express; coker(M) is free exactly when no relation is left."""
from __future__ import annotations

from typing import Any

from ..dsl.convert_modules import to_module
from ..dsl.registry import command
from ..dsl.values import List
from ..dsl.values_modules import Module, Vector
from ..kernel import modules as km

LIB = "polylib.lib"


@command("freerank", lib=LIB)
def freerank(ctx: Any, M: Any, *rest: Any) -> int | List:
    """freerank(M): the rank of coker(M) (M a poly, ideal, vector, module or matrix, its columns the
    relations) if coker(M) is free, else -1; freerank(M, any): the list of that and minimal generators
    of M.

    Example:
      LIB "polylib.lib";
      ring r;
      freerank(module([x,0,1], [-x,0,-1]));
      → 2
      freerank(ideal(x));
      → -1
    """
    ring = ctx.basering().poly
    m = to_module(M, ring)
    rank = max(m.rank, 1)
    vecs = [v.terms() for v in m.gens if not v.is_zero()]
    degrees = [0] * rank
    homogeneous = all(km.is_homogeneous(v, degrees) for v in vecs)
    gens = km.minimal_generators(ring, rank, vecs, degrees if homogeneous else None)
    relations, components = km.drop_unit_relations(ring, gens, degrees)
    rk = len(components) if not any(relations) else -1
    if rest:
        return List([rk, Module(ring, [Vector.from_terms(ring, g) for g in gens] or [Vector(ring, [])], m.rank)])
    return rk
