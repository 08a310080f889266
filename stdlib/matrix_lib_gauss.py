"""matrix.lib's ``gauss_col`` and ``gauss_row``: the column (row) reduced form of a matrix by
interreduction of its columns as vectors in the module ordering (C,dp) (the leading entry of a column
its last nonzero one, then the dp-largest term), each leading coefficient made 1, and the
transformation matrix that produces it; over constants (parameters included) the reduced echelon form."""
from __future__ import annotations

from typing import Any, Optional

from ..dsl.registry import command
from ..dsl.values import List, Matrix
from ..kernel import Poly
from ..kernel.order import MonomialOrder
from .matrix_lib import LIB, _transpose

Vec = list[Poly]


def _lead(v: Vec, key) -> Optional[tuple[int, tuple]]:
    """(component, exponent) of the leading term in (C,dp): the last nonzero entry's dp-largest term."""
    for c in range(len(v) - 1, -1, -1):
        if not v[c].is_zero():
            return c, max(v[c].terms, key=key)
    return None


def _sub(v: Vec, w: Vec, factor: Poly) -> Vec:
    return [a - factor * b for a, b in zip(v, w)]


def _reduce_term(v: Vec, tv: Vec, c: int, e: tuple, g: Vec, tg: Vec, lg: tuple[int, tuple]) -> tuple[Vec, Vec]:
    """v minus the multiple of g that cancels v's term x^e in component c (lead of g divides it)."""
    ring = v[c].ring
    gc, ge = lg
    coeff = v[c].terms[e] / g[gc].terms[ge]
    mono = Poly(ring, {tuple(a - b for a, b in zip(e, ge)): coeff})
    return _sub(v, g, mono), _sub(tv, tg, mono)


def interred_columns(cols: list[Vec]) -> tuple[list[Vec], list[Vec]]:
    """The interreduced columns (redSB: tails reduced too, leading coefficients 1), sorted by leading
    term, and for each the combination of the given columns that gives it."""
    if not cols:
        return [], []
    ring = cols[0][0].ring
    key = MonomialOrder.simple("dp", ring.nvars).key
    m = len(cols)
    track = [[ring.one() if i == j else ring.zero() for i in range(m)] for j in range(m)]
    vecs = [(v, t) for v, t in zip(cols, track) if _lead(v, key) is not None]

    def sort_key(vt):
        c, e = _lead(vt[0], key)
        return c, key(e)
    changed = True
    while changed:
        changed = False
        vecs.sort(key=sort_key)
        for i in range(len(vecs)):
            v, tv = vecs[i]
            lv = _lead(v, key)
            for j in range(i):
                g, tg = vecs[j]
                lg = _lead(g, key)
                if lg[0] == lv[0] and all(a <= b for a, b in zip(lg[1], lv[1])):
                    v, tv = _reduce_term(v, tv, lv[0], lv[1], g, tg, lg)
                    changed = True
                    break
            if changed:
                vecs[i] = (v, tv)
                vecs = [vt for vt in vecs if _lead(vt[0], key) is not None]
                break
    out_v, out_t = [], []
    for i, (v, tv) in enumerate(vecs):
        done = False
        while not done:
            done = True
            for j, (g, tg) in enumerate(vecs):
                if j == i:
                    continue
                lg = _lead(g, key)
                hit = next((e for e in v[lg[0]].terms if all(a <= b for a, b in zip(lg[1], e))), None)
                if hit is not None:
                    v, tv = _reduce_term(v, tv, lg[0], hit, g, tg, lg)
                    done = False
                    break
        c, e = _lead(v, key)
        inv = ring.const(ring.field.one / v[c].terms[e])
        out_v.append([p * inv for p in v])
        out_t.append([p * inv for p in tv])
        vecs[i] = (out_v[-1], out_t[-1])
    return out_v, out_t


def _columns(A: Matrix) -> list[Vec]:
    return [[A.get(i, j) for i in range(1, A.nrows + 1)] for j in range(1, A.ncols + 1)]


def _matrix(ring, cols: list[Vec], nrows: int, ncols: int) -> Matrix:
    cols = cols + [[ring.zero()] * nrows for _ in range(ncols - len(cols))]
    return Matrix(ring, nrows, ncols, [cols[j][i] for i in range(nrows) for j in range(ncols)])


@command("gauss_col", lib=LIB)
def gauss_col(A: Matrix, *flag: Any) -> Matrix | List:
    """gauss_col(A): the column-reduced form of A: its columns interreduced in the ordering (C,dp)
    (no division by polynomials; for a constant matrix the reduced column echelon form, pivots in the
    last rows), each leading coefficient 1, zero columns at the end; gauss_col(A, e): the list of that
    form B and the transformation matrix T with B = A*T.

    Example:
      LIB "matrix.lib";
      ring r = 0,x,(c,dp);
      matrix A[3][3] = 1,2,3,4,5,6,7,8,9;
      print(gauss_col(A));
      → 2,-1,0,
      → 1,0, 0,
      → 0,1, 0
    """
    ring = A.ring
    cols, track = interred_columns(_columns(A))
    B = _matrix(ring, cols, A.nrows, A.ncols)
    if not flag:
        return B
    return List([B, _matrix(ring, track, A.ncols, A.ncols)])


@command("gauss_row", lib=LIB)
def gauss_row(A: Matrix, *flag: Any) -> Matrix | List:
    """gauss_row(A): the row-reduced form of A, the transpose of gauss_col(transpose(A));
    gauss_row(A, e): gauss_col(transpose(A), e) (the list of the transposed form and the matrix T with
    transpose(T)*A = transpose of the form).

    Example:
      LIB "matrix.lib";
      ring r = 0,x,(c,dp);
      matrix A[2][3] = 1,2,3,4,5,6;
      print(gauss_row(A));
      → 2, 1,0,
      → -1,0,1
    """
    if flag:
        return gauss_col(_transpose(A), *flag)
    return _transpose(gauss_col(_transpose(A)))
