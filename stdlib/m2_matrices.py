"""The Macaulay2 dialect's commands on matrices and polynomials: jacobian, minors, det, diff, sub, factor."""
from __future__ import annotations

from fractions import Fraction
from typing import Any

from ..dsl.errors import MechRuntimeError, MechTypeError
from ..dsl.m2_modules import with_default_degrees
from ..dsl.m2_ops import lift_to
from ..dsl.m2_rings import in_quotients, is_integral, normal, exact_over_zz
from ..dsl.m2_values import Factored, Opt
from ..dsl.registry import command
from ..dsl.values import NONE, ExprList, Ideal, List, Matrix, Ring
from ..kernel import Poly
from ..kernel.matrix import apply_operator
from .m2 import _indices, _polys

@command("jacobian", dialect="m2")
@in_quotients
@exact_over_zz
def jacobian(I: Ideal | Matrix) -> Matrix:
    """jacobian I: the matrix of partial derivatives, one row per variable, one column per generator
    (not in a quotient ring: jacobian R of one is :func:`jacobian_ring`)."""
    if getattr(getattr(I.ring, "owner", None), "quotient", None) is not None:
        raise MechRuntimeError("jacobian on elements of a quotient ring R/I is not supported by mech")
    polys = I.gens if isinstance(I, Ideal) else I.entries
    R = getattr(I.ring, "owner", None)
    n = len(R.own) if R is not None and R.own else I.ring.nvars  # a tower: its own variables
    return Matrix(I.ring, n, len(polys), [f.diff(i) for i in range(n) for f in polys])


@command("jacobian", dialect="m2")
@in_quotients
def jacobian_ring(R: Ring) -> Matrix:
    """jacobian R of a quotient ring R = A/I: the jacobian of I's generators (by R's own variables), in R."""
    owner = getattr(R.poly, "owner", None)
    if owner is None or owner.parent is None:
        raise MechRuntimeError("jacobian R takes a quotient ring R = A/I")
    rels = [lift_to(g, owner) for g in owner.relations]
    n = len(owner.own) if owner.own else R.poly.nvars
    return Matrix(R.poly, n, len(rels), [normal(f.diff(i)) for i in range(n) for f in rels])


@command("minors", dialect="m2")
@in_quotients
@exact_over_zz
def minors(ctx, k: int, M: Matrix) -> Ideal:
    """minors(k, M): the ideal of the k x k minors of M (column subsets outermost, as Macaulay2
    lists them; zero minors left out; Limit => n: the first n; k <= 0: the unit ideal)."""
    from itertools import combinations

    from ..kernel import matrix as KM
    if k <= 0:
        return Ideal(M.ring, [M.ring.one()])
    if k > min(M.nrows, M.ncols):
        raise MechRuntimeError(f"minors: k must be between 1 and {min(M.nrows, M.ncols)}")
    found = []
    for cols in combinations(range(1, M.ncols + 1), k):
        for rows in combinations(range(1, M.nrows + 1), k):
            sub = KM.Matrix(M.ring, k, k, [M.get(i, j) for i in rows for j in cols])
            d = normal(KM.det(sub))  # in a quotient ring: the normal form
            if not d.is_zero():
                found.append(d)
    limit = ctx.m2_options.get("Limit")
    if type(limit) is int:
        found = found[:limit]
    return Ideal(M.ring, found, is_std=not found)


minors.m2_options = ("Limit",)


@command("permanents", dialect="m2")
@exact_over_zz
def permanents(k: int, M: Matrix) -> Ideal:
    """permanents(k, M): the ideal of the permanents of the k x k submatrices of M (the sums over
    permutations without signs; zero ones left out)."""
    from itertools import combinations, permutations
    if k <= 0:
        return Ideal(M.ring, [M.ring.one()])
    if k > min(M.nrows, M.ncols):
        raise MechRuntimeError(f"permanents: k must be between 1 and {min(M.nrows, M.ncols)}")
    found = []
    for rows in combinations(range(1, M.nrows + 1), k):
        for cols in combinations(range(1, M.ncols + 1), k):
            perm = M.ring.zero()
            for sigma in permutations(cols):
                term = M.ring.one()
                for i, j in zip(rows, sigma):
                    term = term * M.get(i, j)
                perm = perm + term
            if not perm.is_zero():
                found.append(perm)
    return Ideal(M.ring, found, is_std=not found)


@command("exteriorPower", dialect="m2")
@exact_over_zz
def exterior_power(k: int, M: Matrix) -> Matrix:
    """exteriorPower(k, M): the matrix of M's k x k minors, rows and columns indexed by the k-subsets
    of M's rows and columns in Macaulay2's order (by their largest element, then the next...)."""
    from itertools import combinations

    from ..kernel import matrix as KM
    if k < 0:
        raise MechRuntimeError("exteriorPower(k, M) takes k >= 0")

    def subsets(n: int) -> list[tuple[int, ...]]:
        return sorted(combinations(range(1, n + 1), k), key=lambda s: s[::-1])
    rows, cols = subsets(M.nrows), subsets(M.ncols)
    entries = [KM.det(KM.Matrix(M.ring, k, k, [M.get(i, j) for i in r for j in c])) if k else M.ring.one()
               for r in rows for c in cols]
    return with_default_degrees(Matrix(M.ring, len(rows), len(cols), entries))


@command("det", dialect="m2")
@exact_over_zz
def det(M: Matrix) -> Poly:
    """det M: the determinant of a square matrix."""
    from ..kernel import matrix as KM
    if M.nrows != M.ncols:
        raise MechRuntimeError(f"det of a {M.nrows} x {M.ncols} matrix: the matrix must be square")
    return KM.det(KM.Matrix(M.ring, M.nrows, M.ncols, M.entries))


@command("diff", dialect="m2")
@exact_over_zz
def diff(x: Poly | Matrix, f: Poly | Ideal | Matrix) -> Any:
    """diff(x, f): the derivative of f by the variable x; diff(P, f) for a polynomial P: P's
    differential operator (x^2*y: d^3/dx^2dy) applied to f; diff(M, f): to each entry of M."""
    if isinstance(x, Poly) and x.ring is not f.ring and hasattr(f.ring, "owner"):  # a coefficient ring's variable
        x = lift_to(x, f.ring.owner)
    if isinstance(x, Matrix) and isinstance(f, Matrix):  # entry (i*r+k, j*s+l): diff(x_(i,j), f_(k,l))
        p, q, r, t = x.nrows, x.ncols, f.nrows, f.ncols
        return Matrix(f.ring, p * r, q * t, [apply_operator(x.entries[i * q + j], f.entries[k * t + m])
                                             for i in range(p) for k in range(r) for j in range(q) for m in range(t)])
    if isinstance(x, Matrix):
        if not isinstance(f, Poly):
            raise MechTypeError("diff(M, f) takes a matrix M and a polynomial f (or a matrix)")
        return Matrix(x.ring, x.nrows, x.ncols, [apply_operator(p, f) for p in x.entries])
    if isinstance(f, Poly):
        return apply_operator(x, f)
    entries = f.gens if isinstance(f, Ideal) else f.entries
    rows, cols = (1, len(f.gens)) if isinstance(f, Ideal) else (f.nrows, f.ncols)
    return Matrix(f.ring, rows, cols, [apply_operator(x, g) for g in entries])



@command("sub", dialect="m2")
@in_quotients
@exact_over_zz
def sub(ctx, f: Poly | Ideal | Matrix, where: List | Ring) -> Any:
    """sub(f, {x => a, y => b}): substitute for the variables; sub(f, S): the same polynomials
    (variables matched by name, the others sent to 0) in the ring S."""
    ring = f.ring
    if isinstance(where, Ring):
        target = where.poly
        images = []
        for name in ring.names:  # as map(S, R): variables S lacks go to 0
            images.append(target.gen(target.names.index(name)) if name in target.names else target.zero())
    else:
        target = ring
        images = [ring.gen(i) for i in range(ring.nvars)]
        for item in where.items:
            if not isinstance(item, Opt):
                raise MechTypeError("sub(f, {x => a, ...}) takes a list of options")
            i = _indices(ring, item.key)[0]
            images[i] = _polys(ctx, (item.value,))[0]
    from ..dsl.maps import map_value
    out = map_value(f, images, target)
    if is_integral(target) and any(getattr(c, "q", 1) != 1 for g in _polys(ctx, (out,), target) for c in g.terms.values()):
        raise MechRuntimeError("sub: the result has a fractional coefficient: it is not in a ring over ZZ")
    if getattr(getattr(target, "owner", None), "quotient", None) is not None:  # in R/Q: normal forms
        if isinstance(out, Poly):
            return normal(out)
        if isinstance(out, Ideal):
            return Ideal(out.ring, [g for g in (normal(p) for p in out.gens) if not g.is_zero()])
        if isinstance(out, Matrix):
            return Matrix(out.ring, out.nrows, out.ncols, [normal(p) for p in out.entries])
    return out


@command("factor", dialect="m2")
@exact_over_zz
def factor(f: Poly) -> Factored:
    """factor f: the factorization of f into irreducible factors (times a unit)."""
    from ..kernel.factor import factorize
    unit, factors = factorize(f)
    return Factored(_unit(f, unit), tuple((g, k) for g, k in factors))


def _unit(f: Poly, unit: Any) -> Any:
    field = f.ring.field
    if field.characteristic:
        return int(field.symmetric(unit))
    return int(unit.p) if unit.q == 1 else Fraction(int(unit.p), int(unit.q))


@command("value", dialect="m2")
@exact_over_zz
def value(F: Factored) -> Poly:
    """value F: the product a factorization stands for."""
    out = F.factors[0][0].ring.one() if F.factors else None
    for g, k in F.factors:
        out = out * g ** k
    if out is None:
        return F.unit
    return out * out.ring.field(F.unit) if F.unit != 1 else out


@command("symmetricPower", dialect="m2")
def symmetric_power(d: int, M: Matrix) -> Matrix:
    """symmetricPower(d, m) for a one-row matrix m: the row of the products of d of its entries
    (indices i1 <= ... <= id, in lexicographic order)."""
    from itertools import combinations_with_replacement
    if M.nrows != 1 or type(d) is not int or d < 0:
        raise MechRuntimeError("symmetricPower(d, m) is supported for a one-row matrix m and d >= 0")
    out = []
    for idx in combinations_with_replacement(range(M.ncols), d):
        p = M.ring.one()
        for i in idx:
            p = p * M.entries[i]
        out.append(p)
    return Matrix(M.ring, 1, len(out), out)


def _positions(L: Any, n: int, what: str, strict: bool = True) -> list[int] | None:
    """The indices 0 <= i < n a list gives ({0..2, 4} too; ``strict`` off: any integers); None for
    none given (an empty place)."""
    if L is NONE:
        return None
    if not isinstance(L, (List, ExprList)):
        raise MechTypeError(f"submatrix: the {what} are a list of numbers")
    out = [j for c in L.items for j in (c.items if isinstance(c, ExprList) else [c])]
    if not all(type(j) is int and (0 <= j < n or not strict) for j in out):
        raise MechRuntimeError(f"submatrix: {what} are numbers from 0 to {n - 1}")
    return out


def _submatrix(M: Matrix, rows: list[int], cols: list[int]) -> Matrix:
    return Matrix(M.ring, len(rows), len(cols), [M.get(i + 1, j + 1) for i in rows for j in cols])


@command("submatrix", dialect="m2")
@in_quotients
@exact_over_zz
def submatrix(M: Matrix, rows: Any, cols: Any = None) -> Matrix:
    """submatrix(M, {j1, j2, ...}): the columns j1, j2, ... (counted from 0); submatrix(M, rows,
    cols): those rows and columns (an empty place: all)."""
    if cols is None:
        rows, cols = NONE, rows
    i, j = _positions(rows, M.nrows, "rows"), _positions(cols, M.ncols, "columns")
    return _submatrix(M, range(M.nrows) if i is None else i, range(M.ncols) if j is None else j)


@command("submatrix'", dialect="m2")
@in_quotients
@exact_over_zz
def submatrix_without(M: Matrix, rows: Any, cols: Any = None) -> Matrix:
    """submatrix'(M, rows, cols): M without those rows and columns (an empty place: none);
    submatrix'(M, cols): without those columns."""
    if cols is None:
        rows, cols = NONE, rows
    i = set(_positions(rows, M.nrows, "rows", False) or ())
    j = set(_positions(cols, M.ncols, "columns", False) or ())
    return _submatrix(M, [k for k in range(M.nrows) if k not in i], [k for k in range(M.ncols) if k not in j])


def at_integers(f: Poly, values: list[int]) -> int:
    """f (over ZZ/p) at integers, as Macaulay2 substitutes into ZZ: each coefficient lifted to the
    integer of least absolute value (p/2 for -p/2), the value an integer."""
    p = f.ring.field.characteristic
    total = 0
    for e, c in f.terms.items():
        c = int(c) % p
        term = c - p if c > p // 2 else c
        for v, k in zip(values, e):
            term *= v ** k
        total += term
    return total
