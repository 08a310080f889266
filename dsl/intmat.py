"""Singular's ``intmat``: matrices of integers (declared ``intmat m[2][3] = 1,2,3,4,5,6;``), their
printing, conversions and arithmetic."""
from __future__ import annotations

from typing import Any, Iterable

from .errors import MechRuntimeError, MechTypeError
from .types import register_type
from .values import ExprList, IntVec, List


class IntMat:
    """An ``nrows x ncols`` matrix of Python ints, entries row by row."""

    type_name = "intmat"
    __slots__ = ("nrows", "ncols", "values")

    def __init__(self, nrows: int, ncols: int, values: Iterable[int] = ()) -> None:
        vals = [int(v) for v in values]
        if len(vals) > nrows * ncols:
            vals = vals[:nrows * ncols]
        self.nrows, self.ncols = nrows, ncols
        self.values = vals + [0] * (nrows * ncols - len(vals))

    def get(self, i: int, j: int) -> int:
        if not (1 <= i <= self.nrows and 1 <= j <= self.ncols):
            raise MechRuntimeError(f"index [{i},{j}] out of range for a {self.nrows} x {self.ncols} intmat")
        return self.values[(i - 1) * self.ncols + j - 1]

    def with_entry(self, i: int, j: int, v: int) -> "IntMat":
        self.get(i, j)
        vals = list(self.values)
        vals[(i - 1) * self.ncols + j - 1] = v
        return IntMat(self.nrows, self.ncols, vals)

    def rows(self) -> list[list[int]]:
        n = self.ncols
        return [self.values[k * n:(k + 1) * n] for k in range(self.nrows)]

    def transpose(self) -> "IntMat":
        return IntMat(self.ncols, self.nrows, [self.values[i * self.ncols + j]
                                               for j in range(self.ncols) for i in range(self.nrows)])

    def __eq__(self, other: object) -> bool:
        return isinstance(other, IntMat) and (self.nrows, self.ncols, self.values) == \
            (other.nrows, other.ncols, other.values)

    def __len__(self) -> int:
        return len(self.values)

    def __str__(self) -> str:
        """As Singular prints an intmat (``m;``): rows of comma-separated entries."""
        if self.ncols == 1:
            return ",".join(map(str, self.values))
        return ",\n".join(",".join(map(str, r)) for r in self.rows()) + " "

    def string_form(self) -> str:
        """``string(m)``: the entries row by row."""
        return ",".join(map(str, self.values))

    def print_form(self) -> str:
        """``print(m)``: each entry right-aligned after a blank, in five places."""
        return "\n".join("".join(f" {v:>5}" for v in r) for r in self.rows())

    def listvar_text(self) -> str:
        return f"intmat {self.nrows} x {self.ncols}"


def _ints(v: Any) -> list[int]:
    if isinstance(v, bool):
        return [int(v)]
    if isinstance(v, int):
        return [v]
    if isinstance(v, IntVec):
        return list(v.values)
    if isinstance(v, IntMat):
        return list(v.values)
    if isinstance(v, (ExprList, List)):
        return [x for item in v.items for x in _ints(item)]
    raise MechTypeError(f"cannot convert {getattr(type(v), 'type_name', type(v).__name__)} to intmat")


def to_intmat(v: Any, nrows: int = 0, ncols: int = 0) -> IntMat:
    """A value as an intmat: an intmat keeps its shape unless one is given, an intvec becomes a column,
    ints fill the given shape row by row."""
    if v is None:
        return IntMat(nrows or 1, ncols or 1)
    if isinstance(v, IntMat) and not nrows:
        return v
    if isinstance(v, IntVec) and not nrows:
        return IntMat(len(v.values), 1, v.values)
    vals = _ints(v)
    if not nrows:
        nrows, ncols = 1, 1
    return IntMat(nrows, ncols, vals)


def intmat_op(op: str, a: Any, b: Any) -> Any:
    """``a op b`` with an intmat operand: + - of equal shapes (an intvec is a column; an int on the diagonal... as
    Singular: added to every diagonal entry), products with ints, intmats and intvecs."""
    if op in ("+", "-"):
        sign = 1 if op == "+" else -1
        a, b = (IntMat(len(x.values), 1, x.values) if isinstance(x, IntVec) else x for x in (a, b))  # a column
        if isinstance(a, IntMat) and isinstance(b, IntMat):
            if (a.nrows, a.ncols) != (b.nrows, b.ncols):
                raise MechRuntimeError(f"intmat size not compatible: {a.nrows} x {a.ncols} and {b.nrows} x {b.ncols}")
            return IntMat(a.nrows, a.ncols, [x + sign * y for x, y in zip(a.values, b.values)])
        if isinstance(a, IntMat) and isinstance(b, int):
            return _diag_add(a, sign * b)
        if isinstance(a, int) and isinstance(b, IntMat):
            return _diag_add(IntMat(b.nrows, b.ncols, [sign * x for x in b.values]), a)
    if op == "*":
        if isinstance(a, int):
            return IntMat(b.nrows, b.ncols, [a * x for x in b.values])
        if isinstance(b, int):
            return IntMat(a.nrows, a.ncols, [x * b for x in a.values])
        if isinstance(b, IntVec):
            b = IntMat(len(b.values), 1, b.values)
            prod = intmat_op("*", a, b)
            return IntVec(prod.values)
        if isinstance(a, IntMat) and isinstance(b, IntMat):
            if a.ncols != b.nrows:
                raise MechRuntimeError(f"intmat sizes do not match: {a.nrows} x {a.ncols} times {b.nrows} x {b.ncols}")
            bt = b.transpose().rows()
            return IntMat(a.nrows, b.ncols, [sum(x * y for x, y in zip(r, c)) for r in a.rows() for c in bt])
    if op in ("div", "/") and isinstance(a, IntMat) and isinstance(b, int) and b:
        return IntMat(a.nrows, a.ncols, [euclid_div(x, b) for x in a.values])
    if op in ("mod", "%") and isinstance(a, IntMat) and isinstance(b, int) and b:
        return IntMat(a.nrows, a.ncols, [x % abs(b) for x in a.values])
    raise MechTypeError(f"operator {op} is not defined for {_name(a)} and {_name(b)}")


def euclid_div(a: int, b: int) -> int:
    """Singular's division of intvec and intmat entries: the quotient whose remainder lies in [0, |b|)."""
    if b == 0:
        raise MechRuntimeError("division by 0")
    return (a - a % abs(b)) // b


def _diag_add(m: IntMat, c: int) -> IntMat:
    vals = list(m.values)
    for i in range(min(m.nrows, m.ncols)):
        vals[i * m.ncols + i] += c
    return IntMat(m.nrows, m.ncols, vals)


def _name(v: Any) -> str:
    return getattr(type(v), "type_name", {int: "int", IntVec: "intvec"}.get(type(v), type(v).__name__))


def det(m: IntMat) -> int:
    """The determinant (Bareiss' fraction-free elimination)."""
    if m.nrows != m.ncols:
        raise MechRuntimeError(f"det of a {m.nrows} x {m.ncols} intmat: the matrix must be square")
    import flint
    return int(flint.fmpz_mat(m.rows()).det()) if m.nrows else 1


register_type("intmat", to_intmat, default=lambda: IntMat(1, 1))
