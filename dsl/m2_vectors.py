"""Vectors of free modules in the Macaulay2 dialect: ``F_i`` (the i-th basis vector of ``F = R^n``),
``vector {a, b, c}``, their sums, differences, multiples and ``==``; printed ``vector {a, b, c}``
as Macaulay2's ``toString``."""
from __future__ import annotations

from fractions import Fraction
from typing import Any, Sequence

from ..kernel import Poly
from .errors import MechRuntimeError
from .m2_modules import FreeModule, Map, source_degrees
from .values import Matrix, Number


class Vector:
    """An element of a free module, by its entries (polynomials of the module's ring)."""

    __slots__ = ("module", "entries")
    type_name = "vector"

    def __init__(self, module: FreeModule, entries: Sequence[Poly]) -> None:
        self.module, self.entries = module, tuple(entries)

    @property
    def ring(self) -> Any:
        return self.module.ring.poly

    def __neg__(self) -> "Vector":
        return Vector(self.module, [-p for p in self.entries])

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Vector) and other.module == self.module and other.entries == self.entries

    __hash__ = None  # type: ignore[assignment]


def basis_vector(F: FreeModule, i: int) -> Vector:
    """``F_i``: the i-th basis vector (from 0)."""
    if not 0 <= i < F.rank:
        raise MechRuntimeError(f"index {i} out of range (the free module has {F.rank} generators, counted from 0)")
    ring = F.ring.poly
    return Vector(F, [ring.one() if j == i else ring.zero() for j in range(F.rank)])


def _scalar(c: Any, ring: Any) -> Poly | None:
    """A ring element, a number or an integer as an element of the vector's ring (None otherwise)."""
    if isinstance(c, Number):
        c = c.to_poly()
    if isinstance(c, Poly):
        if c.ring is ring:
            return c
        if c.is_constant():
            return ring.one() * c.terms.get((0,) * c.ring.nvars, 0)
        return None
    if type(c) is int or isinstance(c, Fraction):
        return ring.one() * c
    return None


def vector_arith(op: str, a: Any, b: Any) -> Any:
    """``a op b`` when one side is a vector (NotImplemented for operands it does not take)."""
    if isinstance(a, Vector) and isinstance(b, Vector):
        if op in ("==", "!="):
            return (a == b) == (op == "==")
        if op in ("+", "-"):
            if a.module != b.module:
                raise MechRuntimeError(f"{op} of vectors of different free modules")
            return Vector(a.module, [x + y if op == "+" else x - y for x, y in zip(a.entries, b.entries)])
        return NotImplemented
    if op == "*" and isinstance(b, Vector):
        c = _scalar(a, b.ring)
        if c is None:
            raise MechRuntimeError("a vector is multiplied by an element of its ring")
        return Vector(b.module, [c * x for x in b.entries])
    if op in ("==", "!=") and isinstance(a, Vector) and type(b) is int and b == 0:
        return all(p.is_zero() for p in a.entries) == (op == "==")
    return NotImplemented


def columns_matrix(vectors: list[Vector]) -> Map:
    """The matrix whose columns are these vectors (of one free module)."""
    F = vectors[0].module
    if any(v.module != F for v in vectors):
        raise MechRuntimeError("matrix {v1, v2, ...} takes vectors of one free module")
    entries = [v.entries[i] for i in range(F.rank) for v in vectors]
    plain = Matrix(F.ring.poly, F.rank, len(vectors), entries)
    return Map(F, FreeModule(F.ring, source_degrees(plain, F.degrees)), entries)
