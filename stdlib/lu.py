"""LU decompositions of constant matrices (Singular's ``ludecomp``, ``lusolve``, ``luinverse``) and
their ``rank``: P*A = L*U by Gaussian elimination with row exchanges, the pivot of each column the
entry of least size (Singular's choice: small integers before fractions, the first of equal ones)."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import List, Matrix


def _constants(A: Matrix, cmd: str) -> list[list[Any]]:
    if not all(p.is_constant() for p in A.entries):
        raise MechRuntimeError(f"{cmd}: the matrix must have constant entries (numbers of the ground field)")
    zero = A.ring.field(0)
    return [[p.coeff_of(A.ring.zero_exp) if not p.is_zero() else zero for p in row] for row in A.rows()]


def _size(c: Any) -> int:
    """How large a pivot is, as Singular counts: 1 for an integer of one machine word, else its words."""
    num, den = getattr(c, "numerator", None), getattr(c, "denominator", None)
    if num is None or den is None:
        return 1
    num, den = int(num), int(den)
    if den == 1 and abs(num) < 1 << 62:
        return 1
    return (abs(num).bit_length() + 63) // 64 + (den.bit_length() + 63) // 64 + 1


def _matrix(ring: Any, rows: list[list[Any]]) -> Matrix:
    ncols = len(rows[0]) if rows else 0
    return Matrix(ring, len(rows), ncols, [ring.const(c) for r in rows for c in r])


def decompose(ring: Any, a: list[list[Any]]) -> tuple[list[int], list[list[Any]], list[list[Any]]]:
    """(perm, L, U) with rows perm of a = L*U: L unit lower triangular, U in row echelon form."""
    field = ring.field
    m, n = len(a), len(a[0])
    U = [list(r) for r in a]
    L = [[field(int(i == j)) for j in range(m)] for i in range(m)]
    perm = list(range(m))
    r = 0
    for c in range(n):
        if r == m:
            break
        rows = [i for i in range(r, m) if U[i][c] != 0]
        if not rows:
            continue
        k = min(rows, key=lambda i: _size(U[i][c]))
        U[r], U[k] = U[k], U[r]
        perm[r], perm[k] = perm[k], perm[r]
        for j in range(r):
            L[r][j], L[k][j] = L[k][j], L[r][j]
        for i in range(r + 1, m):
            if U[i][c] != 0:
                f = U[i][c] / U[r][c]
                L[i][r] = f
                U[i] = [x - f * y for x, y in zip(U[i], U[r])]
        r += 1
    return perm, L, U


@command("ludecomp")
def ludecomp(A: Matrix) -> List:
    """ludecomp(A): the list P, L, U of a permutation matrix P, a unit lower triangular L and an upper
    triangular (row echelon) U with P*A = L*U, for A with constant entries.

    Example:
      ring r = 0,x,dp;
      matrix A[2][2] = 1,2,3,4;
      list p = ludecomp(A);
      print(p[3]);
      → 1,2,
      → 0,-2
    """
    ring = A.ring
    perm, L, U = decompose(ring, _constants(A, "ludecomp"))
    m = A.nrows
    P = [[ring.field(int(perm[i] == j)) for j in range(m)] for i in range(m)]
    return List([_matrix(ring, P), _matrix(ring, L), _matrix(ring, U)])


def _solve(ring: Any, L: list[list[Any]], U: list[list[Any]], y: list[Any]) -> tuple[list[Any], list[list[Any]]] | None:
    """A solution of L*U*x = y (free variables 0) and a basis of the solutions of U*x = 0 (the free
    variables from the last, each set to -1 in turn), or None when there is no solution."""
    field = ring.field
    m, n = len(U), len(U[0])
    z: list[Any] = []
    for i in range(m):  # forward: L z = y
        z.append(y[i] - sum((L[i][j] * z[j] for j in range(i)), field(0)))
    pivots = []
    for i in range(m):
        c = next((j for j in range(n) if U[i][j] != 0), None)
        if c is None:
            if z[i] != 0:
                return None
        else:
            pivots.append((i, c))
    free = [j for j in range(n) if j not in {c for _, c in pivots}]

    def back(rhs: list[Any], x: list[Any]) -> list[Any]:
        for i, c in reversed(pivots):
            s = rhs[i] - sum((U[i][j] * x[j] for j in range(c + 1, n)), field(0))
            x[c] = s / U[i][c]
        return x
    particular = back(z, [field(0)] * n)
    kernel = []
    for f in reversed(free):
        x = [field(0)] * n
        x[f] = field(-1)
        kernel.append(back([field(0)] * m, x))
    return particular, kernel


@command("lusolve")
def lusolve(P: Matrix, L: Matrix, U: Matrix, b: Matrix) -> List:
    """lusolve(P, L, U, b): for P*A = L*U (ludecomp) the list [1, x, K] of a solution x of A*x = b and a
    matrix K whose columns span the solutions of A*x = 0 (the 1 x 1 zero matrix if there is only x),
    or [0] when A*x = b has no solution.

    Example:
      ring r = 0,x,dp;
      matrix A[2][3] = 1,2,3,0,0,1;
      matrix b[2][1] = 1,2;
      list L = ludecomp(A);
      list Q = lusolve(L[1], L[2], L[3], b);
      print(Q[2]);
      → -5,
      → 0,
      → 2
      print(Q[3]);
      → 2,
      → -1,
      → 0
    """
    ring = U.ring
    p, l, u = (_constants(M, "lusolve") for M in (P, L, U))
    rhs = _constants(b, "lusolve")
    if b.ncols != 1 or b.nrows != U.nrows:
        raise MechRuntimeError(f"lusolve: the right-hand side must be a {U.nrows} x 1 matrix")
    y = [sum((p[i][j] * rhs[j][0] for j in range(len(rhs))), ring.field(0)) for i in range(len(p))]
    found = _solve(ring, l, u, y)
    if found is None:
        return List([0])
    x, kernel = found
    K = _matrix(ring, [[v[i] for v in kernel] for i in range(U.ncols)]) if kernel else Matrix(ring, 1, 1, [])
    return List([1, _matrix(ring, [[v] for v in x]), K])


@command("luinverse")
def luinverse(A: Matrix) -> List:
    """luinverse(A): the list [1, the inverse of A] for an invertible square matrix A of constants,
    else [0].

    Example:
      ring r = 0,x,dp;
      matrix A[2][2] = 1,2,3,4;
      print(luinverse(A)[2]);
      → -2, 1,
      → 3/2,-1/2
    """
    if A.nrows != A.ncols:
        raise MechRuntimeError("luinverse: the matrix must be square")
    ring, n = A.ring, A.nrows
    perm, L, U = decompose(ring, _constants(A, "luinverse"))
    if any(U[i][i] == 0 for i in range(n)):
        return List([0])
    cols = []
    for k in range(n):
        y = [ring.field(int(perm[i] == k)) for i in range(n)]
        x, _ = _solve(ring, L, U, y)
        cols.append(x)
    return List([1, _matrix(ring, [[c[i] for c in cols] for i in range(n)])])


@command("rank")
def rank(A: Matrix) -> int:
    """rank(A): the rank of the matrix A of constants.

    Example:
      ring r = 0,x,dp;
      matrix A[2][3] = 1,2,3,2,4,6;
      rank(A);
      → 1
    """
    if A.nrows == 0 or A.ncols == 0:
        return 0
    _, _, U = decompose(A.ring, _constants(A, "rank"))
    return sum(1 for row in U if any(c != 0 for c in row))
