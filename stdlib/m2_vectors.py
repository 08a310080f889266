"""Vectors of free modules in the Macaulay2 dialect (``dialect="m2"``): ``vector {a, b, c}``,
``entries v``, ``matrix v`` (its one-column matrix) and ``matrix {v1, v2, ...}`` (the matrix of
these columns); the values are :class:`mech.dsl.m2_vectors.Vector`."""
from __future__ import annotations

from ..dsl.errors import MechRuntimeError
from ..dsl.m2_modules import FreeModule, Map, source_degrees
from ..dsl.m2_rings import in_quotients
from ..dsl.m2_vectors import Vector
from ..dsl.registry import command
from ..dsl.values import List, Matrix
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


def columns_matrix(vectors: list[Vector]) -> Map:
    """The matrix whose columns are these vectors (of one free module)."""
    F = vectors[0].module
    if any(v.module != F for v in vectors):
        raise MechRuntimeError("matrix {v1, v2, ...} takes vectors of one free module")
    entries = [v.entries[i] for i in range(F.rank) for v in vectors]
    plain = Matrix(F.ring.poly, F.rank, len(vectors), entries)
    return Map(F, FreeModule(F.ring, source_degrees(plain, F.degrees)), entries)


@command("matrix", dialect="m2")
@in_quotients
def matrix_of_vector(v: Vector) -> Map:
    """matrix v: the one-column matrix of a vector."""
    return columns_matrix([v])


for _f in (vector, entries_vector, matrix_of_vector):
    _f.zz_ok = True
