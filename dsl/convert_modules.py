"""Singular's conversions to ``vector`` and ``module`` (registered with :func:`mech.dsl.values.register_converter`,
so that declarations and assignments convert), and ``matrix(m)`` of a module."""
from __future__ import annotations

from typing import Any, Optional

from ..kernel import Poly, PolyRing
from .values import (ExprList, Ideal, List, Matrix, _cannot, _check_ring, _need_ring, register_converter,
                     to_poly)
from .values_modules import Module, Vector, from_poly, matrix_entries


def to_vector(v: Any, ring: Optional[PolyRing]) -> Vector:
    """Singular's conversions to vector: a vector, or a poly/number/int p as p*gen(1)."""
    ring = _need_ring(ring, "vector")
    if isinstance(v, ExprList) and len(v.items) == 1:
        v = v.items[0]
    if isinstance(v, Vector):
        _check_ring(v, ring)
        return v
    if isinstance(v, ExprList):  # vector v = p, q;: Singular sums the values (vector(p) + vector(q))
        out: list[Poly] = []
        for x in v.items:
            w = to_vector(x, ring)
            out = [a + b for a, b in zip(w.padded(max(len(out), w.nrows)),
                                        out + [ring.zero()] * (w.nrows - len(out)))]
        return Vector(ring, out)
    try:
        return from_poly(to_poly(v, ring))
    except Exception:
        raise _cannot(v, "vector") from None


def to_module(v: Any, ring: Optional[PolyRing]) -> Module:
    """Singular's conversions to module: vectors and polys (p as p*gen(1)) one generator each, an
    ideal's generators, a matrix's columns (rank: its rows), a module."""
    ring = _need_ring(ring, "module")
    if isinstance(v, Module):
        _check_ring(v, ring)
        return v
    if isinstance(v, Matrix):
        _check_ring(v, ring)
        return Module(ring, [Vector(ring, [v.get(i, j) for i in range(1, v.nrows + 1)])
                             for j in range(1, v.ncols + 1)], v.nrows)
    if isinstance(v, Ideal):
        _check_ring(v, ring)
        return Module(ring, [from_poly(g) for g in v.gens])
    if isinstance(v, (ExprList, List)):
        gens: list[Vector] = []
        rank = 0
        for x in v.items:
            if isinstance(x, (Module, Ideal, Matrix)):
                m = to_module(x, ring)
                gens.extend(m.gens)
                rank = max(rank, m.rank)
            else:
                gens.append(to_vector(x, ring))
        return Module(ring, gens, rank)
    try:
        return Module(ring, [to_vector(v, ring)])
    except Exception:
        raise _cannot(v, "module") from None


def module_matrix(m: Module | Vector) -> Any:
    """matrix(m): the generators as columns (a vector: one column)."""
    return Matrix(m.ring, *matrix_entries(m))


register_converter("vector", to_vector)
register_converter("module", to_module)
