"""Matrices of polynomials: arithmetic, determinants, minors (in Singular's order), Jacobians.

Entries are :class:`Poly` of one :class:`PolyRing`, stored row by row (0-based internally;
``get``/``set`` take Singular's 1-based indices).  Determinants use a memoised Laplace
expansion for small sizes and fraction-free Bareiss elimination (exact polynomial division)
otherwise.
"""
from __future__ import annotations

from itertools import combinations
from math import comb
from typing import Any, Callable, Iterable, Sequence

import flint

from .coeffs import PrimeField, RationalField
from .errors import DivisionError, DomainError
from .poly import Poly, PolyRing, divides, sub_exp
from .powering import power


def exact_divide(a: Poly, b: Poly) -> Poly:
    """The quotient ``a / b`` when ``b`` divides ``a`` exactly; :class:`~.errors.DivisionError`
    otherwise.

    Divides leading terms (any monomial ordering is multiplicative, so the leading term of
    ``b`` divides that of every multiple of ``b``)."""
    if b.is_zero():
        raise ZeroDivisionError("division by the zero polynomial")
    ring = a.ring
    if len(b.terms) == 1:
        (be, bc), = b.terms.items()
        inv = ring.field.one / bc
        q = {}
        for e, c in a.terms.items():
            if not divides(be, e):
                raise DivisionError("the division is not exact")
            q[sub_exp(e, be)] = c * inv
        return Poly(ring, q)
    key = ring.order.key
    blm = b.lm()
    inv = ring.field.one / b.terms[blm]
    btail = [(e, c) for e, c in b.terms.items() if e != blm]
    rem = dict(a.terms)
    q: dict = {}
    while rem:
        e = max(rem, key=key)
        if not divides(blm, e):
            raise DivisionError("the division is not exact")
        s = sub_exp(e, blm)
        f = rem.pop(e) * inv
        q[s] = f
        for te, tc in btail:
            t = tuple([x + y for x, y in zip(te, s)])
            v = rem.get(t)
            v = -f * tc if v is None else v - f * tc
            if v == 0:
                rem.pop(t, None)
            else:
                rem[t] = v
    return Poly(ring, q)


class Matrix:
    """An ``nrows x ncols`` matrix of polynomials of ``ring`` (mutable, like Singular's)."""

    __slots__ = ("ring", "nrows", "ncols", "rows")

    def __init__(self, ring: PolyRing, nrows: int, ncols: int, entries: Iterable[Any] = ()) -> None:
        """``entries`` fill the matrix row by row (polynomials or scalars); the rest is zero."""
        if nrows < 0 or ncols < 0:
            raise DomainError("matrix dimensions must be non-negative")
        self.ring, self.nrows, self.ncols = ring, nrows, ncols
        flat = [_as_poly(ring, e) for e in entries]
        if len(flat) > nrows * ncols:
            raise DomainError(f"{len(flat)} entries for a {nrows} x {ncols} matrix")
        flat += [ring.zero()] * (nrows * ncols - len(flat))
        self.rows = [flat[i * ncols:(i + 1) * ncols] for i in range(nrows)]

    @classmethod
    def from_rows(cls, ring: PolyRing, rows: Sequence[Sequence[Any]]) -> "Matrix":
        ncols = len(rows[0]) if rows else 0
        if any(len(r) != ncols for r in rows):
            raise DomainError("rows of different lengths")
        return cls(ring, len(rows), ncols, [e for r in rows for e in r])

    @classmethod
    def identity(cls, ring: PolyRing, n: int) -> "Matrix":
        m = cls(ring, n, n)
        for i in range(n):
            m.rows[i][i] = ring.one()
        return m

    # access
    def __getitem__(self, ij: tuple[int, int]) -> Poly:
        i, j = ij
        return self.rows[i][j]

    def __setitem__(self, ij: tuple[int, int], value: Any) -> None:
        i, j = ij
        self.rows[i][j] = _as_poly(self.ring, value)

    def get(self, i: int, j: int) -> Poly:
        """Entry ``M[i,j]`` with 1-based indices."""
        self._check(i, j)
        return self.rows[i - 1][j - 1]

    def set(self, i: int, j: int, value: Any) -> None:
        """``M[i,j] = value`` with 1-based indices."""
        self._check(i, j)
        self.rows[i - 1][j - 1] = _as_poly(self.ring, value)

    def _check(self, i: int, j: int) -> None:
        if not (1 <= i <= self.nrows and 1 <= j <= self.ncols):
            raise IndexError(f"index [{i},{j}] out of range for a {self.nrows} x {self.ncols} matrix")

    def entries(self) -> list[Poly]:
        """All entries row by row (Singular's ``ideal(M)``)."""
        return [e for r in self.rows for e in r]

    def row(self, i: int) -> list[Poly]:
        return list(self.rows[i])

    def col(self, j: int) -> list[Poly]:
        return [r[j] for r in self.rows]

    def submatrix(self, rows: Sequence[int], cols: Sequence[int]) -> "Matrix":
        """The matrix on the given (0-based) rows and columns."""
        return Matrix(self.ring, len(rows), len(cols), [self.rows[i][j] for i in rows for j in cols])

    def copy(self) -> "Matrix":
        return Matrix(self.ring, self.nrows, self.ncols, self.entries())

    # algebra
    def transpose(self) -> "Matrix":
        return Matrix(self.ring, self.ncols, self.nrows, [self.rows[i][j] for j in range(self.ncols)
                                                          for i in range(self.nrows)])

    def _same_shape(self, other: "Matrix") -> None:
        if (self.nrows, self.ncols) != (other.nrows, other.ncols):
            raise DomainError(f"matrices of sizes {self.nrows} x {self.ncols} and "
                             f"{other.nrows} x {other.ncols}")

    def __add__(self, other: "Matrix") -> "Matrix":
        if not isinstance(other, Matrix):
            return NotImplemented
        self._same_shape(other)
        return Matrix(self.ring, self.nrows, self.ncols,
                      [a + b for a, b in zip(self.entries(), other.entries())])

    def __sub__(self, other: "Matrix") -> "Matrix":
        if not isinstance(other, Matrix):
            return NotImplemented
        self._same_shape(other)
        return Matrix(self.ring, self.nrows, self.ncols,
                      [a - b for a, b in zip(self.entries(), other.entries())])

    def __neg__(self) -> "Matrix":
        return Matrix(self.ring, self.nrows, self.ncols, [-a for a in self.entries()])

    def __mul__(self, other: Any) -> "Matrix":
        if isinstance(other, Matrix):
            if self.ncols != other.nrows:
                raise DomainError(f"cannot multiply a {self.nrows} x {self.ncols} matrix by a "
                                 f"{other.nrows} x {other.ncols} matrix")
            cols = [other.col(j) for j in range(other.ncols)]
            out = []
            for r in self.rows:
                for c in cols:
                    s = self.ring.zero()
                    for a, b in zip(r, c):
                        if a.terms and b.terms:
                            s = s + a * b
                    out.append(s)
            return Matrix(self.ring, self.nrows, other.ncols, out)
        p = _as_poly(self.ring, other)
        return Matrix(self.ring, self.nrows, self.ncols, [a * p for a in self.entries()])

    def __rmul__(self, other: Any) -> "Matrix":
        p = _as_poly(self.ring, other)
        return Matrix(self.ring, self.nrows, self.ncols, [p * a for a in self.entries()])

    def __pow__(self, k: int) -> "Matrix":
        if self.nrows != self.ncols:
            raise DomainError("only square matrices have powers")
        if not isinstance(k, int) or k < 0:
            raise DomainError("exponent must be a non-negative integer")
        return power(self, k, Matrix.identity(self.ring, self.nrows))

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Matrix):
            return NotImplemented
        return (self.ring == other.ring and self.nrows == other.nrows
                and self.ncols == other.ncols and self.rows == other.rows)

    __hash__ = None  # mutable

    def __repr__(self) -> str:
        return "Matrix([" + ", ".join("[" + ", ".join(e.to_str() for e in r) + "]"
                                      for r in self.rows) + "])"

    def is_zero(self) -> bool:
        return all(e.is_zero() for e in self.entries())

    def det(self) -> Poly:
        return det(self)


def _as_poly(ring: PolyRing, e: Any) -> Poly:
    if isinstance(e, Poly):
        if e.ring is not ring and e.ring != ring:
            raise DomainError("a polynomial of another ring")
        return e
    return ring.const(e)


# determinants

def det(m: Matrix) -> Poly:
    """The determinant of a square matrix."""
    if m.nrows != m.ncols:
        raise DomainError(f"the determinant of a non-square ({m.nrows} x {m.ncols}) matrix")
    n = m.nrows
    if n == 0:
        return m.ring.one()
    if n <= 4:
        return _laplace(m.rows, list(range(n)), list(range(n)), {})
    return _bareiss(m)


def _laplace(rows: list[list[Poly]], rs: list[int], cs: list[int], memo: dict) -> Poly:
    """Determinant of the submatrix on rows ``rs`` and columns ``cs`` (increasing), expanded
    along its last row; ``memo`` caches subdeterminants by (rows, columns)."""
    key = (tuple(rs), tuple(cs))
    hit = memo.get(key)
    if hit is not None:
        return hit
    k = len(rs)
    if k == 1:
        val = rows[rs[0]][cs[0]]
    elif k == 2:
        (a, b), (c, d) = [[rows[i][j] for j in cs] for i in rs]
        val = a * d if a.terms and d.terms else a.ring.zero()
        if b.terms and c.terms:
            val = val - b * c
    else:
        last, sub_rows = rows[rs[-1]], rs[:-1]
        val = rows[rs[0]][cs[0]].ring.zero()
        for t, c in enumerate(cs):
            e = last[c]
            if not e.terms:
                continue
            sub = _laplace(rows, sub_rows, cs[:t] + cs[t + 1:], memo)
            if sub.terms:
                term = e * sub
                val = val + term if (k - 1 + t) % 2 == 0 else val - term
    memo[key] = val
    return val


def _bareiss(m: Matrix) -> Poly:
    """Fraction-free Gaussian elimination (Bareiss): every division is exact.  Over QQ and
    Z/p the arithmetic runs on flint polynomials."""
    ring = m.ring
    ctx = _flint_context(ring)
    if ctx is None:
        return _bareiss_det([list(r) for r in m.rows], ring.zero(), ring.one(), exact_divide)
    rows = [[ctx.from_dict(e.terms) if e.terms else ctx.from_dict({}) for e in r] for r in m.rows]
    d = _bareiss_det(rows, ctx.from_dict({}), ctx.constant(1), lambda a, b: a / b)
    return Poly(ring, {tuple(int(v) for v in e): ring.field(c) for e, c in d.to_dict().items()})


def _flint_context(ring: PolyRing) -> Any:
    """A flint polynomial context for the ring's field (None if flint has none)."""
    names = tuple(f"v{i}" for i in range(ring.nvars))
    if not names:
        return None
    if isinstance(ring.field, RationalField):
        return flint.fmpq_mpoly_ctx.get(names, ordering="lex")
    if isinstance(ring.field, PrimeField):
        return flint.nmod_mpoly_ctx.get(names, ordering="lex", modulus=ring.field.characteristic)
    return None


def _bareiss_det(a: list[list[Any]], zero: Any, one: Any, divide: Callable[[Any, Any], Any]) -> Any:
    """Bareiss' determinant of the square matrix ``a`` (modified in place)."""
    n = len(a)
    sign, prev = 1, one
    for k in range(n - 1):
        if a[k][k] == 0:
            piv = next((i for i in range(k + 1, n) if a[i][k] != 0), None)
            if piv is None:
                return zero
            a[k], a[piv] = a[piv], a[k]
            sign = -sign
        p = a[k][k]
        for i in range(k + 1, n):
            for j in range(k + 1, n):
                v = p * a[i][j] - a[i][k] * a[k][j]
                a[i][j] = divide(v, prev) if v != 0 else v
            a[i][k] = zero
        prev = p
    d = a[n - 1][n - 1]
    return d if sign > 0 else -d


# minors

def minors(m: Matrix, k: int) -> list[Poly]:
    """All ``k x k`` minors as Singular's ``minor(M, k)`` lists them.

    ``k <= 0`` gives ``[1]``, ``k > min(nrows, ncols)`` gives ``[0]``; ``k = 1`` the nonzero
    entries, rows and columns from the last down, then zeros up to ``nrows * ncols``.
    Otherwise Singular chooses the algorithm by a heuristic, and the order, signs and zeros
    follow it:

    * fraction-free elimination (:func:`_bareiss_minors`) for k <= 2, for rings with at most
      2 variables, and for Z/p with 3 variables: nonzero minors first, in the
      elimination's order and up to sign, then zeros up to C(r,k)*C(c,k) entries;
    * otherwise Laplace expansion: the row sets in colexicographic order, for each the column
      sets in colexicographic order, true signs, zero minors dropped (``[0]`` if all vanish).

    The elimination picks pivots by Singular's size of coefficients; for parameter fields, and
    for non-integer rationals past the first elimination step, that size is approximated, so
    the order and signs may differ from Singular's there (the ideal never does).
    """
    r, c, ring = m.nrows, m.ncols, m.ring
    if k <= 0:
        return [ring.one()]
    if k > min(r, c):
        return [ring.zero()]
    if k == 1:
        vals = [m.rows[i][j] for i in reversed(range(r)) for j in reversed(range(c))]
        return _pad(vals, r * c, ring)
    p = ring.field.characteristic
    if k == 2 or ring.nvars <= 2 or (ring.nvars == 3 and p != 0):
        return _pad(_bareiss_minors(m, k), comb(r, k) * comb(c, k), ring)
    memo: dict = {}
    out = []
    for rs in _colex(r, k):
        for cs in _colex(c, k):
            v = _laplace(m.rows, list(rs), list(cs), memo)
            if v.terms:
                out.append(v)
    return out or [ring.zero()]


def _pad(vals: list[Poly], n: int, ring: PolyRing) -> list[Poly]:
    nz = [v for v in vals if v.terms]
    return nz + [ring.zero()] * (n - len(nz))


def _colex(n: int, k: int) -> list[tuple[int, ...]]:
    return sorted(combinations(range(n), k), key=lambda s: s[::-1])


def _size(c: Any, field: Any) -> int:
    """Singular's coefficient size: machine words of numerator and denominator (small
    integers count 1); 1 for elements of other fields."""
    if getattr(field, "characteristic", 0) != 0 or not hasattr(c, "p"):
        return 1

    def words(v: int) -> int:
        v = abs(v)
        return 1 if v < 2**62 else (v.bit_length() + 63) // 64
    num, den = int(c.p), int(c.q)
    return words(num) if den == 1 else words(num) + words(den)


def _weight(p: Poly) -> int:
    """Weight of a nonzero entry for pivot choice: coefficient size, +2 for a non-constant
    term; a sum of terms weighs the sum of (size + 2)."""
    field = p.ring.field
    if len(p.terms) == 1:
        (e, c), = p.terms.items()
        return _size(c, field) + (2 if any(e) else 0)
    return sum(_size(c, field) + 2 for c in p.terms.values())


def _bareiss_minors(m: Matrix, k: int) -> list[Poly]:
    """The nonzero ``k x k`` minors in the order of Singular's recursive fraction-free
    elimination (its ``minor`` for k = 2, and for k >= 3 in rings with few variables).

    On each level, for each row position from the bottom up: the nonzero row of least total
    weight (the lowest such on ties) is swapped into it; then, for the columns from the right,
    the entry of least weight in that row (the rightmost on ties) is swapped into the current
    column and is the pivot p.  The next level is the matrix of ``(p*a[i][j] -
    a[i][col]*a[last][j]) / d`` over the rows above and the columns to the left (``d`` the
    pivot of the level before, Sylvester's identity); on the last level its entries, from the
    last row and column backwards, are the minors.  A minor's sign is (-1)^(number of earlier
    pivots in the same row, summed over the levels)."""
    out: list[Poly] = []
    _bareiss_level(k - 1, [list(r) for r in m.rows], m.nrows, m.ncols, None, 0, out)
    return out


def _bareiss_level(ar: int, a: list[list[Poly]], nr: int, nc: int, div: Poly | None,
                   parity: int, out: list[Poly]) -> None:
    lr = nr - 1
    while lr >= ar:
        best, bw = None, 0
        for i in range(lr, -1, -1):
            w = sum(_weight(e) for e in a[i][:nc] if e.terms)
            if w and (best is None or w < bw):
                best, bw = i, w
        if best is None:
            return
        a[best], a[lr] = a[lr], a[best]
        prow = a[lr]
        k, step = nc - 1, 0
        while k >= ar:
            bj, bw = None, 0
            for j in range(k, -1, -1):
                if prow[j].terms:
                    w = _weight(prow[j])
                    if bj is None or w < bw:
                        bj, bw = j, w
            if bj is None:
                break
            for row in a[:lr + 1]:
                row[bj], row[k] = row[k], row[bj]
            p = prow[k]
            b = []
            for i in range(lr):
                ai, aik = a[i], a[i][k]
                bi = []
                for j in range(k):
                    v = p * ai[j] if ai[j].terms else p.ring.zero()
                    if aik.terms and prow[j].terms:
                        v = v - aik * prow[j]
                    if div is not None and v.terms:
                        v = exact_divide(v, div)
                    bi.append(v)
                b.append(bi)
            sign = (parity + step) % 2
            if ar > 1:
                _bareiss_level(ar - 1, b, lr, k, p, sign, out)
            else:
                for i in range(lr - 1, -1, -1):
                    for j in range(k - 1, -1, -1):
                        if b[i][j].terms:
                            out.append(-b[i][j] if sign else b[i][j])
            k -= 1
            step += 1
        lr -= 1


def jacobian(polys: Sequence[Poly], ring: PolyRing | None = None) -> Matrix:
    """Singular's ``jacob(I)``: row i holds the partial derivatives of ``polys[i]`` by each
    variable."""
    ring = ring or (polys[0].ring if polys else None)
    if ring is None:
        raise DomainError("the Jacobian of no polynomials needs a ring")
    return Matrix(ring, len(polys), ring.nvars, [f.diff(j) for f in polys for j in range(ring.nvars)])


def apply_operator(P: Poly, f: Poly) -> Poly:
    """The differential operator of the polynomial ``P`` applied to ``f`` (each monomial of P a
    product of partial derivatives: Singular's ``diff(ideal, ideal)``, Macaulay2's ``diff(M, N)``)."""
    out = f.ring.zero()
    for e, c in P.terms.items():
        g = f
        for i, k in enumerate(e):
            for _ in range(k):
                g = g.diff(i)
        out = out + g * c
    return out


def gradient(f: Poly) -> list[Poly]:
    """Singular's ``jacob(f)`` for a polynomial: its partial derivatives."""
    return [f.diff(j) for j in range(f.ring.nvars)]
