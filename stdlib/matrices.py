"""Determinants and minors of matrices, as Singular's ``det`` and ``minor`` (``nrows``, ``ncols``,
``transpose``, ``jacob`` and ``print`` are in :mod:`mech.stdlib.standard`)."""
from __future__ import annotations

from ..dsl.errors import MechRuntimeError
from ..dsl.values import Ideal, Matrix
from ..kernel import Poly
from ..kernel import matrix as KM
from ..dsl.registry import command


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
