"""Macaulay2's graded free modules and the matrices between them (``R^3``, ``R^{-2,0}``,
``map(R^2, R^3, ...)``), and the cyclic modules ``R^1/I``.

A free module ``R^{d1,...,dn}`` has generators of degrees ``-d1, ..., -dn`` (``R^n``: all 0).  A
matrix is a map ``source -> target`` of some degree ``d``: :class:`Map` keeps the degrees its
constructor gave; a plain :class:`~mech.dsl.values.Matrix` (``matrix {{...}}``) has Macaulay2's
default ones: target degrees 0, each source degree the largest degree of its column's entries
(so the matrix is homogeneous of degree 0 when it can be).  Degrees are the first component of
Macaulay2's (multi)degrees."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional, Sequence

from ..kernel import Poly
from .m2_rings import M2Ring, degree_vectors, term_degree
from .errors import MechRuntimeError, MechTypeError
from .values import Ideal, Matrix


@dataclass(frozen=True, eq=False)
class FreeModule:
    """``R^n`` with generators of the given degrees."""
    ring: M2Ring
    degrees: tuple[int, ...]

    @property
    def rank(self) -> int:
        return len(self.degrees)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, FreeModule) and other.ring is self.ring and other.degrees == self.degrees

    def __hash__(self) -> int:
        return hash((id(self.ring), self.degrees))


@dataclass(frozen=True, eq=False)
class CyclicModule:
    """``R^1/I``: the quotient of the free module of rank 1 by the ideal ``I``."""
    ideal: Ideal

    @property
    def ring(self) -> Any:
        return self.ideal.ring


class Map(Matrix):
    """A matrix with its target and source modules and its degree."""

    __slots__ = ("target", "source", "degree")
    type_name = "matrix"

    def __init__(self, target: FreeModule, source: FreeModule, entries: Sequence[Poly], degree: int = 0) -> None:
        super().__init__(target.ring.poly, target.rank, source.rank, entries)
        self.target, self.source, self.degree = target, source, degree


def poly_degree(p: Poly) -> Optional[int]:
    """The largest first-component degree of p's terms (None for 0)."""
    if p.is_zero():
        return None
    ring = getattr(p.ring, "owner", None)
    vecs = degree_vectors(ring) if ring is not None else [(1,)] * p.ring.nvars
    return max(term_degree(e, vecs)[0] for e in p.terms)


def source_degrees(M: Matrix, target: Sequence[int], degree: int = 0) -> tuple[int, ...]:
    """Macaulay2's source degrees for a matrix given without them: each column's largest
    ``degree of entry + target degree - degree`` (0 for a zero column)."""
    out = []
    for j in range(M.ncols):
        degs = [poly_degree(M.get(i + 1, j + 1)) for i in range(M.nrows)]
        found = [d + t - degree for d, t in zip(degs, target) if d is not None]
        out.append(max(found) if found else 0)
    return tuple(out)


def with_default_degrees(M: Matrix) -> Map:
    """``matrix {{...}}``: the matrix as a map with Macaulay2's default degrees."""
    target = FreeModule(M.ring.owner, (0,) * M.nrows)
    return Map(target, FreeModule(M.ring.owner, source_degrees(M, target.degrees)), M.entries)


def _known(M: Matrix) -> Map:
    if not isinstance(M, Map):
        raise MechRuntimeError("the degrees of this matrix are not known to mech (only of matrices made by "
                               "matrix, map, id_ and their products with ring elements)")
    return M


def target_of(M: Matrix) -> FreeModule:
    return _known(M).target


def source_of(M: Matrix) -> FreeModule:
    return _known(M).source


def map_degree(M: Matrix) -> int:
    return _known(M).degree


def scaled(M: Matrix, r: Any, result: Matrix) -> Matrix:
    """``r * M`` (``result``) as a map: M's source and target, degree raised by r's degree."""
    if not isinstance(M, Map):
        return result
    d = poly_degree(r) if isinstance(r, Poly) else 0
    if isinstance(r, Poly) and len({term_degree(e, degree_vectors(M.ring.owner))[0] for e in r.terms}) > 1:
        return result  # an inhomogeneous factor: Macaulay2's degree is not tracked
    return Map(M.target, M.source, result.entries, M.degree + (d or 0))


def is_homogeneous_map(M: Matrix) -> bool:
    """Whether every entry (i, j) is homogeneous of degree source_j + degree - target_i."""
    tgt, src, d = target_of(M).degrees, source_of(M).degrees, map_degree(M)
    ring = M.ring.owner
    vecs = degree_vectors(ring)
    for i in range(M.nrows):
        for j in range(M.ncols):
            p = M.get(i + 1, j + 1)
            if any(term_degree(e, vecs)[0] != src[j] + d - tgt[i] for e in p.terms):
                return False
    return True


def quotient_module(F: FreeModule, I: Any) -> CyclicModule:
    """``R^1 / I``."""
    if F.rank != 1 or any(F.degrees):
        raise MechRuntimeError("mech's modules R^n / I are the quotients of R^1 by an ideal")
    if not isinstance(I, Ideal) or I.ring is not F.ring.poly:
        raise MechTypeError("R^1 / I takes an ideal of R")
    return CyclicModule(I)


def columns(M: Matrix, cols: Sequence[int]) -> Map:
    """``M_{j1, j2, ...}``: the columns (from 0, negative from the end)."""
    cols = [_index(j, M.ncols, "column") for j in cols]
    entries = [M.get(i + 1, j + 1) for i in range(M.nrows) for j in cols]
    if not isinstance(M, Map):
        return Matrix(M.ring, M.nrows, len(cols), entries)
    src = M.source
    return Map(M.target, FreeModule(src.ring, tuple(src.degrees[j] for j in cols)), entries, M.degree)


def rows(M: Matrix, rows_: Sequence[int]) -> Map:
    """``M^{i1, i2, ...}``: the rows (from 0, negative from the end)."""
    rows_ = [_index(i, M.nrows, "row") for i in rows_]
    entries = [M.get(i + 1, j + 1) for i in rows_ for j in range(M.ncols)]
    if not isinstance(M, Map):
        return Matrix(M.ring, len(rows_), M.ncols, entries)
    tgt = M.target
    return Map(FreeModule(tgt.ring, tuple(tgt.degrees[i] for i in rows_)), M.source, entries, M.degree)


def _index(i: int, n: int, what: str) -> int:
    if not -n <= i < n:
        raise MechRuntimeError(f"{what} {i} out of range (the matrix has {n}, counted from 0)")
    return i % n
