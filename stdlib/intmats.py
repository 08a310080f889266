"""Commands on Singular's ``intmat`` (the type itself: :mod:`mech.dsl.intmat`): the conversion
``intmat(v, r, c)``, ``nrows``, ``ncols``, ``transpose``, ``det``, ``size``."""
from __future__ import annotations

from ..dsl.errors import MechRuntimeError
from ..dsl.intmat import IntMat, det as intmat_det, to_intmat
from ..dsl.registry import command
from ..dsl.values import IntVec


@command("intmat")
def intmat(v: IntVec | IntMat | int, nrows: int = 0, ncols: int = 0) -> IntMat:
    """intmat(v, r, c): the intvec (or intmat) v as an r x c intmat, filled row by row (missing entries
    0); intmat(v): an intvec as a column.

    Example:
      intmat m = intmat(intvec(1,2,3,4), 2, 2);
      print(m);
      →      1     2
      →      3     4
    """
    if nrows < 0 or ncols < 0 or (nrows and not ncols):
        raise MechRuntimeError("intmat(v, rows, cols) needs positive sizes")
    return to_intmat(v, nrows, ncols)


@command("nrows")
def nrows_intmat(m: IntMat) -> int:
    return m.nrows


@command("ncols")
def ncols_intmat(m: IntMat) -> int:
    return m.ncols


@command("transpose")
def transpose_intmat(m: IntMat) -> IntMat:
    return m.transpose()


@command("transpose")
def transpose_intvec(v: IntVec) -> IntMat:
    # an intvec is a column: its transpose is a 1 x n intmat (help shows transpose's matrix example)
    return IntMat(1, len(v.values), v.values)


@command("det")
def det_intmat(m: IntMat) -> int:
    return intmat_det(m)


@command("size")
def size_intmat(m: IntMat) -> int:
    return len(m.values)


@command("trace")
def trace_intmat(m: IntMat) -> int:
    """trace(m): the sum of the diagonal entries of the intmat m.

    Example:
      intmat m[2][2] = 1,2,3,4;
      trace(m);
      → 5
    """
    return sum(m.values[i * m.ncols + i] for i in range(min(m.nrows, m.ncols)))
