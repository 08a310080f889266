"""Commands of Singular's matrix.lib: building matrices (``concat``, ``diag``, ``dsum``, ``outer``,
``submat``, ``headStand``, ``power``), elementary row and column operations (``addcol``, ``addrow``,
``multcol``, ``multrow``, ``permcol``, ``permrow``), Gaussian elimination by constant pivots
(``rowred``, ``colred``), removing unit rows and columns (``rm_unitcol``, ``rm_unitrow``) and the
basis of a symmetric power (``symmetricBasis``), the entries of a matrix as an ideal (``flatten``) and
deleting zero columns (``compress``).
(``unitmat`` is in :mod:`mech.stdlib.idealops`.)"""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.intmat import IntMat
from ..dsl.registry import command
from ..dsl.rings import make_ring
from ..dsl.values import Ideal, IntVec, List, Matrix, OrderBlock, Ring
from ..kernel import Poly

LIB = "matrix.lib"


def _transpose(A: Matrix) -> Matrix:
    return Matrix(A.ring, A.ncols, A.nrows, [A.get(i, j) for j in range(1, A.ncols + 1)
                                             for i in range(1, A.nrows + 1)])


def _from_rows(ring, rows: list[list[Poly]], ncols: int) -> Matrix:
    return Matrix(ring, len(rows), ncols, [p for r in rows for p in r])


def _check_index(k: int, n: int, what: str, cmd: str) -> None:
    if not 1 <= k <= n:
        raise MechRuntimeError(f"{cmd}: {what} {k} out of range (1..{n})")


@command("concat", lib=LIB)
def concat(*mats: Matrix | Ideal | Any) -> Matrix:
    """concat(A1, A2, ...): the matrices side by side (the columns of A1, then of A2...); the result
    has as many rows as the tallest, shorter columns filled with zeros (a module, vector or ideal as
    its matrix).

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[2][2] = 1,2,3,4;
      matrix B[1][1] = x;
      print(concat(A, B));
      → 1,2,x,
      → 3,4,0
    """
    if not mats:
        raise MechRuntimeError("concat needs at least one matrix")
    from ..dsl.values import to_matrix
    from ..dsl.values_modules import Module, Vector
    mats = tuple(to_matrix(Module(m.ring, [m]) if isinstance(m, Vector) else m, m.ring)
                 if isinstance(m, (Ideal, Module, Vector)) else m for m in mats)
    if not all(isinstance(m, Matrix) for m in mats):
        raise MechRuntimeError("concat: matrices, modules, vectors or ideals expected")
    ring = mats[0].ring
    n = max(m.nrows for m in mats)
    cols = [[m.get(i, j) if i <= m.nrows else ring.zero() for i in range(1, n + 1)]
            for m in mats for j in range(1, m.ncols + 1)]
    return Matrix(ring, n, len(cols), [c[i] for i in range(n) for c in cols])


@command("diag", lib=LIB)
def diag_poly(p: Poly, n: int) -> Matrix:
    """diag(p, n): p times the n x n unit matrix; diag(A): the diagonal matrix of all entries of the
    matrix A, row by row.

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      print(diag(x, 2));
      → x,0,
      → 0,x
      matrix A[1][2] = 1,y;
      print(diag(A));
      → 1,0,
      → 0,y
    """
    ring = p.ring
    return Matrix(ring, n, n, [p if i == j else ring.zero() for i in range(n) for j in range(n)])


@command("diag", lib=LIB)
def diag_matrix(A: Matrix) -> Matrix:
    ring, ents = A.ring, A.entries
    n = len(ents)
    return Matrix(ring, n, n, [ents[i] if i == j else ring.zero() for i in range(n) for j in range(n)])


@command("dsum", lib=LIB)
def dsum(*mats: Matrix) -> Matrix:
    """dsum(A1, A2, ...): the direct sum (block diagonal matrix) of the matrices.

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[1][2] = 1,2;
      matrix B[1][1] = x;
      print(dsum(A, B));
      → 1,2,0,
      → 0,0,x
    """
    if not mats:
        raise MechRuntimeError("dsum needs at least one matrix")
    ring = mats[0].ring
    n, m = sum(a.nrows for a in mats), sum(a.ncols for a in mats)
    rows = [[ring.zero()] * m for _ in range(n)]
    r0 = c0 = 0
    for a in mats:
        for i in range(a.nrows):
            for j in range(a.ncols):
                rows[r0 + i][c0 + j] = a.get(i + 1, j + 1)
        r0, c0 = r0 + a.nrows, c0 + a.ncols
    return _from_rows(ring, rows, m)


@command("outer", lib=LIB)
def outer(A: Matrix, B: Matrix) -> Matrix:
    """outer(A, B): the outer (Kronecker, tensor) product of A and B: the block matrix of the
    blocks A[i,j]*B.

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[1][2] = 1,2;
      matrix B[2][1] = x,y;
      print(outer(A, B));
      → x,2x,
      → y,2y
    """
    ring = A.ring
    if B.nrows * B.ncols == 0 or A.nrows == 0:
        return Matrix(ring, 0, 0, [])
    n, m = A.nrows * B.nrows, A.ncols * B.ncols
    return Matrix(ring, n, m, [A.get(i // B.nrows + 1, j // B.ncols + 1) * B.get(i % B.nrows + 1, j % B.ncols + 1)
                               for i in range(n) for j in range(m)])


@command("power", lib=LIB)
def power_matrix(A: Matrix, n: int) -> Matrix:
    """power(A, n): the n-th power of the square matrix or intmat A (the unit matrix for n <= 0).

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[2][2] = 0,x,y,0;
      print(power(A, 3));
      → 0,  x2y,
      → xy2,0
    """
    if A.nrows != A.ncols:
        raise MechRuntimeError("not a square matrix!")
    ring, k = A.ring, A.nrows
    rows = [[ring.one() if i == j else ring.zero() for j in range(k)] for i in range(k)]
    base = A.rows()
    for _ in range(max(n, 0)):
        rows = [[sum((rows[i][t] * base[t][j] for t in range(k)), ring.zero()) for j in range(k)]
                for i in range(k)]
    return _from_rows(ring, rows, k)


@command("power", lib=LIB)
def power_intmat(A: IntMat, n: int) -> IntMat:
    if A.nrows != A.ncols:
        raise MechRuntimeError("not a square matrix!")
    k = A.nrows
    rows = [[int(i == j) for j in range(k)] for i in range(k)]
    base = A.rows()
    for _ in range(max(n, 0)):
        rows = [[sum(rows[i][t] * base[t][j] for t in range(k)) for j in range(k)] for i in range(k)]
    return IntMat(k, k, [v for r in rows for v in r])


@command("submat", lib=LIB)
def submat(A: Matrix, r: IntVec, c: IntVec) -> Matrix:
    """submat(A, r, c): the submatrix of A of the rows in the intvec r and the columns in c (in
    that order).

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[2][3] = 1,2,3,x,y,0;
      print(submat(A, 2, 1..2));
      → x,y
    """
    for i in r:
        _check_index(i, A.nrows, "row", "submat")
    for j in c:
        _check_index(j, A.ncols, "column", "submat")
    return Matrix(A.ring, len(r), len(c), [A.get(i, j) for i in r for j in c])


@command("headStand", lib=LIB)
def head_stand(A: Matrix) -> Matrix:
    """headStand(A): A turned upside down and left to right (B[i,j] = A[n-i+1, m-j+1]).

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[2][2] = 1,2,x,y;
      print(headStand(A));
      → y,x,
      → 2,1
    """
    return Matrix(A.ring, A.nrows, A.ncols, list(reversed(A.entries)))


# ---------------------------------------------------------------- elementary operations
def _set_column(A: Matrix, j: int, col: list[Poly]) -> Matrix:
    rows = A.rows()
    for i in range(A.nrows):
        rows[i][j - 1] = col[i]
    return _from_rows(A.ring, rows, A.ncols)


@command("addcol", lib=LIB)
def addcol(A: Matrix, c1: int, p: Poly, c2: int) -> Matrix:
    """addcol(A, c1, p, c2): A with p times column c1 added to column c2.

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[2][2] = 1,2,3,4;
      print(addcol(A, 1, x, 2));
      → 1,x+2,
      → 3,3x+4
    """
    _check_index(c1, A.ncols, "column", "addcol")
    _check_index(c2, A.ncols, "column", "addcol")
    return _set_column(A, c2, [A.get(i, c2) + p * A.get(i, c1) for i in range(1, A.nrows + 1)])


@command("addrow", lib=LIB)
def addrow(A: Matrix, r1: int, p: Poly, r2: int) -> Matrix:
    """addrow(A, r1, p, r2): A with p times row r1 added to row r2.

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[2][2] = 1,2,3,4;
      print(addrow(A, 1, x, 2));
      → 1,  2,
      → x+3,2x+4
    """
    return _transpose(addcol(_transpose(A), r1, p, r2))


@command("multcol", lib=LIB)
def multcol(A: Matrix, c: int, p: Poly) -> Matrix:
    """multcol(A, c, p): A with column c multiplied by p.

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[2][2] = 1,2,3,4;
      print(multcol(A, 2, y));
      → 1,2y,
      → 3,4y
    """
    _check_index(c, A.ncols, "column", "multcol")
    return _set_column(A, c, [p * A.get(i, c) for i in range(1, A.nrows + 1)])


@command("multrow", lib=LIB)
def multrow(A: Matrix, r: int, p: Poly) -> Matrix:
    """multrow(A, r, p): A with row r multiplied by p.

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[2][2] = 1,2,3,4;
      print(multrow(A, 2, y));
      → 1, 2,
      → 3y,4y
    """
    return _transpose(multcol(_transpose(A), r, p))


@command("permcol", lib=LIB)
def permcol(A: Matrix, c1: int, c2: int) -> Matrix:
    """permcol(A, c1, c2): A with the columns c1 and c2 swapped.

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[2][2] = 1,x,3,y;
      print(permcol(A, 1, 2));
      → x,1,
      → y,3
    """
    _check_index(c1, A.ncols, "column", "permcol")
    _check_index(c2, A.ncols, "column", "permcol")
    col1 = [A.get(i, c1) for i in range(1, A.nrows + 1)]
    col2 = [A.get(i, c2) for i in range(1, A.nrows + 1)]
    return _set_column(_set_column(A, c1, col2), c2, col1)


@command("permrow", lib=LIB)
def permrow(A: Matrix, r1: int, r2: int) -> Matrix:
    """permrow(A, r1, r2): A with the rows r1 and r2 swapped.

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[2][2] = 1,2,x,y;
      print(permrow(A, 1, 2));
      → x,y,
      → 1,2
    """
    return _transpose(permcol(_transpose(A), r1, r2))


# ---------------------------------------------------------------- Gaussian elimination
def _is_unit(p: Poly) -> bool:
    return p.is_constant() and not p.is_zero()


def _row_reduce(A: Matrix, extra: int) -> list[list[Poly]]:
    """Gauss-Jordan elimination of the rows of A (with ``extra`` columns of the unit matrix appended)
    by constant pivots only, column by column, the first usable row as pivot, as matrix.lib's rowred."""
    ring, m, n = A.ring, A.nrows, A.ncols
    rows = [r + [ring.one() if i == j else ring.zero() for j in range(extra)] for i, r in enumerate(A.rows())]
    rk = 0
    for col in range(n):
        k = next((i for i in range(rk, m) if _is_unit(rows[i][col])), None)
        if k is None:
            continue
        rows[rk], rows[k] = rows[k], rows[rk]
        inv = ring.field.one / rows[rk][col].lc()
        rows[rk] = [p * inv for p in rows[rk]]
        for i in range(m):
            if i != rk and not rows[i][col].is_zero():
                f = rows[i][col]
                rows[i] = [a - f * b for a, b in zip(rows[i], rows[rk])]
        rk += 1
    return rows


@command("rowred", lib=LIB)
def rowred(A: Matrix, *flag: Any) -> Matrix | List:
    """rowred(A): the row-reduced form of A by Gaussian elimination with constant pivots (no division
    by polynomials); rowred(A, e): the list of that form and the transformation matrix T with
    form = T*A.

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[2][3] = 2,4,x,1,1,y;
      print(rowred(A));
      → 1,0,-1/2x+2y,
      → 0,1,1/2x-y
    """
    rows = _row_reduce(A, A.nrows if flag else 0)
    n = A.ncols
    red = _from_rows(A.ring, [r[:n] for r in rows], n)
    if not flag:
        return red
    return List([red, _from_rows(A.ring, [r[n:] for r in rows], A.nrows)])


@command("colred", lib=LIB)
def colred(A: Matrix, *flag: Any) -> Matrix | List:
    """colred(A): the column-reduced form of A by Gaussian elimination with constant pivots;
    colred(A, e): the list of that form and the transformation matrix T with form = A*T.

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[3][2] = 2,1,4,1,x,y;
      print(colred(A));
      → 1,       0,
      → 0,       1,
      → -1/2x+2y,1/2x-y
    """
    out = rowred(_transpose(A), *flag)
    if isinstance(out, Matrix):
        return _transpose(out)
    return List([_transpose(m) for m in out.items])


def _unit_index(vec: list[Poly]) -> int:
    """k if ``vec`` is the k-th unit vector (0-based), else -1."""
    nonzero = [i for i, p in enumerate(vec) if not p.is_zero()]
    if len(nonzero) == 1 and vec[nonzero[0]] == vec[nonzero[0]].ring.one():
        return nonzero[0]
    return -1


@command("rm_unitcol", lib=LIB)
def rm_unitcol(A: Matrix) -> Matrix | int:
    """rm_unitcol(A): for A row-reduced, A without its unit columns (the leading ones, e_1, e_2, ...)
    and the rows of their ones (0 when nothing is left).

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[2][2] = 1,x,0,y;
      print(rm_unitcol(A));
      → y
    """
    cols = [[A.get(i, j) for i in range(1, A.nrows + 1)] for j in range(1, A.ncols + 1)]
    units, keep = 0, []
    for j, col in enumerate(cols):
        if _unit_index(col) == units and units < A.nrows:
            units += 1
        else:
            keep.append(j + 1)
    if not keep:
        return 0
    return submat(A, IntVec(range(units + 1, A.nrows + 1)), IntVec(keep))


@command("rm_unitrow", lib=LIB)
def rm_unitrow(A: Matrix) -> Matrix | int:
    """rm_unitrow(A): for A column-reduced, A without its unit rows and the columns of their ones
    (0 when nothing is left).

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[2][2] = 1,0,x,y;
      print(rm_unitrow(A));
      → y
    """
    out = rm_unitcol(_transpose(A))
    return _transpose(out) if isinstance(out, Matrix) else out


@command("symmetricBasis", lib=LIB)
def symmetric_basis(n: int, k: int, name: str = "e") -> Ring:
    """symmetricBasis(n, k[, s]): the ring 0,(s(1..n)),dp holding the ideal ``symBasis`` of the monomials
    of degree k: a basis of the k-th symmetric power of an n-dimensional vector space.

    Example:
      LIB "matrix.lib";
      def R = symmetricBasis(2, 2);
      setring R;
      symBasis;
      → symBasis[1]=e(2)^2
      → symBasis[2]=e(1)*e(2)
      → symBasis[3]=e(1)^2
    """
    from .ring_lib import export
    from .standard_lib import monomials_of_degree
    if "(" in name or ")" in name:
        raise MechRuntimeError("Wrong optional argument: must be a string without brackets")
    ring = make_ring(0, (), [f"{name}({i})" for i in range(1, n + 1)], [OrderBlock("dp", n), OrderBlock("C")])
    poly = ring.poly
    mons = sorted(monomials_of_degree(n, [1] * n, k))  # as maxideal(k): increasing lexicographically
    export(ring, "symBasis", "ideal", Ideal(poly, [poly.monomial(e) for e in mons] or [poly.zero()]))
    return ring


@command("flatten", lib=LIB)
def flatten(A: Matrix) -> Ideal:
    """flatten(A): the ideal of the entries of the matrix A, row by row.

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[2][2] = 1,x,y,0;
      flatten(A);
      → _[1]=1
      → _[2]=x
      → _[3]=y
      → _[4]=0
    """
    return Ideal(A.ring, list(A.entries) or [A.ring.zero()])


@command("compress", lib=LIB)
def compress(A: Matrix | Ideal | IntMat | IntVec | Any) -> Any:
    """compress(A): A without its zero columns (matrix, intmat), generators (ideal, module) or entries
    (intvec); a 1 x 1 zero intmat when nothing is left.

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      matrix A[2][3] = x,0,1,y,0,2;
      print(compress(A));
      → x,1,
      → y,2
    """
    from ..dsl.values import to_matrix
    from ..dsl.values_modules import Module
    from .idealops import simplify
    from .vector_commands import simplify_module, simplify_matrix
    if isinstance(A, Matrix):
        return to_matrix(simplify_matrix(A, 2), A.ring)
    if isinstance(A, Ideal):
        return simplify(A, 2)
    if isinstance(A, Module):
        return simplify_module(A, 2)
    if isinstance(A, IntVec):
        return IntVec([v for v in A.values if v] or [0])
    if isinstance(A, IntMat):
        cols = [j for j in range(1, A.ncols + 1) if any(A.get(i, j) for i in range(1, A.nrows + 1))]
        if not cols:
            return IntMat(1, 1)
        return IntMat(A.nrows, len(cols), [A.get(i, j) for i in range(1, A.nrows + 1) for j in cols])
    raise MechRuntimeError(f"compress: a matrix, ideal, module, intmat or intvec expected, not {type(A).__name__}")


@command("linear_relations", lib=LIB)
def linear_relations(M: Any) -> Any:
    """linear_relations(M): the module of the linear relations with constant coefficients among the
    generators of the module M: a basis of the kernel of K^n -> R^r, e_j -> M[j], each relation with
    1 at one generator not determined by the ones before (as a null space read from the reduced row
    echelon form of the coefficients).  (Singular's matrix.lib reads relations off a basis with new
    variables and misses or invents some when generators have constant entries.)

    Example:
      LIB "matrix.lib";
      ring r = 0,(x,y),dp;
      print(linear_relations(module([x,y],[2x,2y],[y,x])));
      → -2,
      → 1
    """
    from ..dsl.values_modules import Module, Vector
    if not isinstance(M, Module):
        raise MechRuntimeError("linear_relations: a module expected")
    ring, field = M.ring, M.ring.field
    n = len(M.gens)
    terms = sorted({t for g in M.gens for t in g.terms()})
    rows = [[g.terms().get(t, field.zero) for g in M.gens] for t in terms]
    pivots: list[int] = []
    r = 0
    for c in range(n):
        p = next((i for i in range(r, len(rows)) if rows[i][c] != field.zero), None)
        if p is None:
            continue
        rows[r], rows[p] = rows[p], rows[r]
        inv = field.one / rows[r][c]
        rows[r] = [a * inv for a in rows[r]]
        for i in range(len(rows)):
            if i != r and rows[i][c] != field.zero:
                f = rows[i][c]
                rows[i] = [a - f * b for a, b in zip(rows[i], rows[r])]
        pivots.append(c)
        r += 1
    rels = []
    for free in (c for c in range(n) if c not in pivots):
        vec = [field.zero] * n
        vec[free] = field.one
        for i, c in enumerate(pivots):
            vec[c] = -rows[i][free]
        rels.append(Vector(ring, [ring.const(a) for a in vec]))
    return Module(ring, rels or [Vector(ring, [])])
