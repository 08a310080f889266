"""Vectors of free modules in the Macaulay2 dialect (``dialect="m2"``): ``vector {a, b, c}``,
``entries v``, ``matrix v`` (its one-column matrix) and ``matrix {v1, v2, ...}`` (the matrix of
these columns); the values are :class:`mech.dsl.m2_vectors.Vector`."""
from __future__ import annotations

from ..dsl.m2_modules import FreeModule, Map
from ..dsl.m2_rings import in_quotients
from ..dsl.m2_vectors import Vector, columns_matrix
from ..dsl.registry import command
from ..dsl.values import List
from .m2 import matrix


@command("vector", dialect="m2")
@in_quotients
def vector(ctx, entries: List) -> Vector:
    """vector {a, b, c}: the vector of these entries, an element of R^3 (R their ring; integers:
    as ``matrix`` takes them)."""
    col = matrix(ctx, List([List([x]) for x in entries.items]))
    return Vector(FreeModule(col.ring.owner, (0,) * col.nrows), col.entries)


@command("entries", dialect="m2")
@in_quotients
def entries_vector(v: Vector) -> List:
    """entries v: the entries of a vector."""
    return List(list(v.entries))


@command("matrix", dialect="m2")
@in_quotients
def matrix_of_vector(v: Vector) -> Map:
    """matrix v: the one-column matrix of a vector."""
    return columns_matrix([v])


for _f in (vector, entries_vector, matrix_of_vector):
    _f.zz_ok = True
