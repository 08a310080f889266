"""Matrices: their shape (``nrows``, ``ncols``), ``transpose``, and determinants and minors as
Singular's ``det`` and ``minor`` (``jacob`` is in :mod:`mech.stdlib.polynomials`, ``print`` in
:mod:`mech.stdlib.language`)."""
from __future__ import annotations

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, Matrix
from ..kernel import Poly
from ..kernel import matrix as KM


def _kernel(M: Matrix) -> KM.Matrix:
    return KM.Matrix(M.ring, M.nrows, M.ncols, M.entries)


@command("det")
def det(M: Matrix) -> Poly:
    """det(M): the determinant of the square matrix M.

    Example:
      ring r = 0,(x,y),dp;
      matrix M[2][2] = x,y,1,x;
      det(M);
      → x2-y
    """
    if M.nrows != M.ncols:
        raise MechRuntimeError(f"det of a {M.nrows} x {M.ncols} matrix: the matrix must be square")
    return KM.det(_kernel(M))


@command("minor")
def minor(M: Matrix, k: int) -> Ideal:
    """minor(M, k): the ideal of the k x k minors of M, in Singular's order (for k <= 2 or few
    variables with Singular's signs; the ideal is always the same as Singular's).

    Example:
      ring r = 0,(x,y,z),dp;
      matrix M[2][3] = x,y,z,1,2,3;
      minor(M, 2);
      → _[1]=3y-2z
      → _[2]=3x-z
      → _[3]=-2x+y
    """
    return Ideal(M.ring, KM.minors(_kernel(M), k))


@command("ncols")
def ncols(m: Matrix | Ideal | IntVec) -> int:
    """ncols(M): the number of columns (generators of an ideal).

    Example:
      ring r = 0,(x,y),dp;
      matrix M[2][3] = x,y,1,2,3,4;
      ncols(M);
      → 3
      ncols(ideal(x, y, 0));
      → 3
    """
    if isinstance(m, Matrix):
        return m.ncols
    if isinstance(m, Ideal):
        return len(m.gens)
    return 1


@command("nrows")
def nrows(m: Matrix | Ideal | IntVec) -> int:
    """nrows(M): the number of rows (1 for an ideal).

    Example:
      ring r = 0,(x,y),dp;
      matrix M[2][3] = x,y,1,2,3,4;
      nrows(M);
      → 2
      nrows(intvec(1,2,3));
      → 3
    """
    if isinstance(m, Matrix):
        return m.nrows
    if isinstance(m, Ideal):
        return 1
    return len(m)


@command("transpose")
def transpose(m: Matrix) -> Matrix:
    """transpose(M): the transposed matrix.

    Example:
      ring r = 0,(x,y),dp;
      matrix M[2][3] = x,y,1,2,3,4;
      print(transpose(M));
      → x,2,
      → y,3,
      → 1,4
    """
    return Matrix(m.ring, m.ncols, m.nrows, [m.get(i, j) for j in range(1, m.ncols + 1)
                                             for i in range(1, m.nrows + 1)])


@command("trace")
def trace(M: Matrix) -> Poly:
    """trace(M): the sum of the diagonal entries of M.

    Example:
      ring r = 0,(x),dp;
      matrix m[2][2] = 1,x,3,x2;
      trace(m);
      → x2+1
    """
    total = M.ring.zero()
    for i in range(min(M.nrows, M.ncols)):
        total = total + M.entries[i * M.ncols + i]
    return total
