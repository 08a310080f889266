"""The foundation commands, always available: standard bases, normal forms, dimension, the
structure of polynomials and ideals, type conversions, ring information, printing, maps between
rings, options and the interpreter's own commands."""
from __future__ import annotations

from math import gcd
from typing import Any

from ..dsl import ast as A
from ..dsl.errors import MechNameError, MechRuntimeError, MechTypeError
from ..dsl.printing import charstr as _charstr
from ..dsl.printing import ordstr as _ordstr
from ..dsl.printing import print_form, render, value_str
from ..dsl.values import (NONE, ExprList, Ideal, IntVec, List, Map, Matrix, Number, Ring, to_ideal, to_intvec,
                          to_matrix, to_number, to_poly)
from ..dsl.values import typeof as _typeof
from ..kernel import Poly
from ..kernel.dimension import krull_dim
from ..kernel.engines import standard_basis as kernel_standard_basis
from ..kernel.groebner import normal_form
from ..dsl.registry import TOPICS, command

# ---------------------------------------------------------------- standard bases


def normalize(p: Poly) -> Poly:
    """A basis element as Singular's std returns it: over QQ (and QQ(a,..)) the primitive multiple
    without denominators and with positive leading coefficient; over Z/p monic (Z/p(a,..): the
    leading coefficient's leading term 1)."""
    if p.is_zero():
        return p
    field = p.ring.field
    if getattr(field, "params", ()):
        return _normalize_params(p)
    if field.characteristic:
        return p.monic()
    import flint
    den = 1
    for c in p.terms.values():
        q = int(c.q)
        den = den * q // gcd(den, q)
    g = 0
    for c in p.terms.values():
        g = gcd(g, int(c.p) * (den // int(c.q)))
    scale = flint.fmpq(den, g)
    return p * (-scale if p.lc() < 0 else scale)


def _normalize_params(p: Poly) -> Poly:
    field = p.ring.field
    lcm = None
    for c in p.terms.values():
        lcm = c.den if lcm is None else lcm * c.den // lcm.gcd(c.den)
    nums = {e: c.num * (lcm // c.den) for e, c in p.terms.items()}
    content = None
    for n in nums.values():
        content = n if content is None else content.gcd(n)
    nums = {e: n // content for e, n in nums.items()}
    lead = int(nums[p.lm()].leading_coefficient())
    if field.characteristic:
        inv = pow(lead, -1, field.characteristic)
        nums = {e: n * inv for e, n in nums.items()}
    elif lead < 0:
        nums = {e: -n for e, n in nums.items()}
    return Poly(p.ring, {e: field.from_polys(n) for e, n in nums.items()})


def standard_basis(ideal: Ideal) -> list[Poly]:
    """A standard basis of ``ideal`` (reduced for global orderings), normalized as Singular's std."""
    return [normalize(p) for p in kernel_standard_basis(ideal.nonzero(), ideal.ring)]


@command("std")
def std(I: Ideal) -> Ideal:
    """std(I): a standard basis of the ideal I for the ring's ordering (for a global ordering the
    reduced Groebner basis, each element a primitive integer polynomial over QQ, monic over Z/p),
    sorted by increasing leading monomial.

    Example:
      ring r = 0,(x,y,z),dp;
      ideal I = x2-y, xy-z;
      std(I);
      → _[1]=y2-xz
      → _[2]=xy-z
      → _[3]=x2-y
    """
    return Ideal(I.ring, standard_basis(I), is_std=True)


@command("groebner")
def groebner(I: Ideal) -> Ideal:
    """groebner(I): a Groebner basis of I (the same as std(I)).

    Example:
      ring r = 0,(x,y),lp;
      groebner(ideal(x2+y2-1, x-y));
      → _[1]=2y2-1
      → _[2]=x-y
    """
    return Ideal(I.ring, standard_basis(I), is_std=True)


def _nf(f: Poly, basis: list[Poly]) -> Poly:
    if f.ring.order.is_global:
        return normal_form(f, basis)
    from ..kernel.localnf import weak_normal_form
    return weak_normal_form(f, basis)


def _reduce(ctx: Any, f: Any, I: Ideal) -> Any:
    ctx.assume_std(I, 1)
    key = I.ring.order.key
    basis = sorted(I.nonzero(), key=lambda g: key(g.lm()))  # Singular tries reducers from the smallest
    if isinstance(f, Poly):
        return _nf(f, basis)
    if isinstance(f, Ideal):
        return Ideal(f.ring, [_nf(g, basis) for g in f.gens])
    return Matrix(f.ring, f.nrows, f.ncols, [_nf(g, basis) for g in f.entries])


@command("reduce")
def reduce(ctx, f: Poly | Ideal | Matrix, I: Ideal) -> Any:
    """reduce(f, I): the normal form of f (a poly, ideal or matrix) with respect to the standard
    basis I; the remainder is returned as it is (not normalized).

    Example:
      ring r = 0,(x,y),dp;
      ideal G = std(ideal(x2-y, y2-1));
      reduce(x3+y3, G);
      → xy+y
    """
    return _reduce(ctx, f, I)


@command("NF")
def NF(ctx, f: Poly | Ideal | Matrix, I: Ideal) -> Any:
    """NF(f, I): the normal form of f with respect to the standard basis I (the same as reduce).

    Example:
      ring r = 0,(x,y),dp;
      ideal G = std(ideal(x2-y, y2-1));
      NF(x4+xy, G);
      → xy+1
    """
    return _reduce(ctx, f, I)


@command("dim")
def dim(ctx, I: Ideal) -> int:
    """dim(I): the Krull dimension of R/I for a standard basis I (-1 for the unit ideal).

    Example:
      ring r = 0,(x,y,z),dp;
      dim(std(ideal(xy, xz)));
      → 2
    """
    ctx.assume_std(I, 0)
    order = I.ring.order
    if not order.is_global and not order.is_local:
        ctx.warn(f"dim({ctx.argnames[0]}) may be wrong because the mixed monomial ordering")
    lms = [g.lm() for g in I.nonzero()]
    return krull_dim(lms, I.ring.nvars)


# ---------------------------------------------------------------- structure of polynomials


@command("size")
def size(x: Any) -> int:
    """size(x): terms of a poly, nonzero generators of an ideal, entries of a list, intvec or
    matrix, characters of a string.

    Example:
      ring r = 0,(x,y),dp;
      size(x2+2xy-1);
      → 3
      size(ideal(x, 0, y));
      → 2
      size("mech");
      → 4
    """
    if isinstance(x, int):
        return 0 if x == 0 else 1
    if isinstance(x, Number):
        return 0 if x.is_zero() else 1
    if isinstance(x, Poly):
        return len(x.terms)
    if isinstance(x, Ideal):
        return len(x.nonzero())
    if isinstance(x, Matrix):
        return x.nrows * x.ncols
    if isinstance(x, (List, str, IntVec)):
        return len(x)
    if isinstance(x, Map):
        return len(x.images)
    if isinstance(x, Ring):
        return len(x.names)
    raise MechTypeError(f"size is not defined for {_typeof(x)}")


@command("lead")
def lead(f: Poly | Ideal) -> Any:
    """lead(f): the leading term of a poly, or the ideal of leading terms.

    Example:
      ring r = 0,(x,y),dp;
      lead(3x2y-x3+y);
      → -x3
      lead(ideal(x+y2, 2x-1));
      → _[1]=y2
      → _[2]=2x
    """
    if isinstance(f, Poly):
        return f.ring.zero() if f.is_zero() else f.lt()
    return Ideal(f.ring, [g if g.is_zero() else g.lt() for g in f.gens])


@command("leadcoef")
def leadcoef(f: Poly) -> Number:
    """leadcoef(f): the leading coefficient of f (a number).

    Example:
      ring r = 0,(x,y),dp;
      leadcoef(-3x2y+x3+y);
      → 1
    """
    return Number(f.ring, f.ring.field.zero if f.is_zero() else f.lc())


@command("leadmonom")
def leadmonom(f: Poly) -> Poly:
    """leadmonom(f): the leading monomial of f (coefficient 1).

    Example:
      ring r = 0,(x,y),dp;
      leadmonom(-3x2y+x3+y);
      → x3
    """
    return f.ring.zero() if f.is_zero() else f.ring.monomial(f.lm())


@command("deg")
def deg(f: Poly | Ideal, w: IntVec | None = None) -> int:
    """deg(f) or deg(f, w): the (weighted) total degree of f, -1 for 0; for an ideal the maximum.

    Example:
      ring r = 0,(x,y),dp;
      deg(x2y+y5);
      → 5
      deg(x2y+y5, intvec(3,1));
      → 7
      deg(0);
      → -1
    """
    def one(p: Poly) -> int:
        if p.is_zero():
            return -1
        if w is None:
            return p.total_degree()
        ws = list(w.values) + [0] * (p.ring.nvars - len(w))
        return max(sum(a * b for a, b in zip(e, ws)) for e in p.terms)
    if isinstance(f, Poly):
        return one(f)
    return max((one(g) for g in f.gens), default=-1)


@command("diff")
def diff(f: Poly | Ideal | Matrix, x: Poly) -> Any:
    """diff(f, x): the partial derivative of f (poly, ideal or matrix) by the ring variable x.

    Example:
      ring r = 0,(x,y),dp;
      diff(x3y2+xy, x);
      → 3x2y2+y
      diff(ideal(x2, xy), y);
      → _[1]=0
      → _[2]=x
    """
    i = _var_index(x, "diff")
    if isinstance(f, Poly):
        return f.diff(i)
    if isinstance(f, Ideal):
        return Ideal(f.ring, [g.diff(i) for g in f.gens])
    return Matrix(f.ring, f.nrows, f.ncols, [g.diff(i) for g in f.entries])


def _var_index(x: Poly, cmd: str) -> int:
    if len(x.terms) == 1:
        (e, c), = x.terms.items()
        if c == 1 and sum(e) == 1:
            return e.index(1)
    raise MechRuntimeError(f"{cmd}: the second argument must be a ring variable")


@command("jacob")
def jacob(f: Poly | Ideal) -> Any:
    """jacob(f): the ideal of partial derivatives of a poly; for an ideal the Jacobian matrix
    (one row per generator).

    Example:
      ring r = 0,(x,y),dp;
      jacob(x3+xy2);
      → _[1]=3x2+y2
      → _[2]=2xy
      print(jacob(ideal(x2+y2-1, x-y)));
      → 2x,2y,
      → 1, -1
    """
    n = f.ring.nvars
    if isinstance(f, Poly):
        return Ideal(f.ring, [f.diff(i) for i in range(n)])
    return Matrix(f.ring, len(f.gens), n, [g.diff(i) for g in f.gens for i in range(n)])


@command("subst")
def subst(f: Poly | Ideal | Matrix, *pairs: Any) -> Any:
    """subst(f, x, g, ...): substitute g for the ring variable x in f (several pairs in turn).

    Example:
      ring r = 0,(x,y,z),dp;
      subst(x2+yz, x, y+1);
      → y2+yz+2y+1
      subst(x2+yz, y, 2, z, x);
      → x2+2x
    """
    if not pairs or len(pairs) % 2:
        raise MechTypeError("subst(f, x, g): give a variable and its substitute")
    ring = f.ring
    for k in range(0, len(pairs), 2):
        x = to_poly(pairs[k], ring)
        g = to_poly(pairs[k + 1], ring)
        i = _var_index(x, "subst")
        images = ring.gens()
        images[i] = g
        if isinstance(f, Poly):
            f = f.compose(images)
        elif isinstance(f, Ideal):
            f = Ideal(ring, [p.compose(images) for p in f.gens])
        else:
            f = Matrix(ring, f.nrows, f.ncols, [p.compose(images) for p in f.entries])
    return f


@command("maxideal")
def maxideal(ctx, k: int) -> Ideal:
    """maxideal(k): the ideal of all monomials of degree k.

    Example:
      ring r = 0,(x,y),dp;
      maxideal(2);
      → _[1]=y2
      → _[2]=xy
      → _[3]=x2
    """
    ring = ctx.basering().poly
    if k <= 0:
        return Ideal(ring, [ring.one()])
    exps: list[tuple[int, ...]] = []

    def rec(i: int, left: int, cur: list[int]) -> None:
        if i == ring.nvars - 1:
            exps.append(tuple(cur + [left]))
            return
        for a in range(left, -1, -1):
            rec(i + 1, left - a, cur + [a])
    rec(0, k, [])
    return Ideal(ring, [ring.monomial(e) for e in sorted(exps)])  # Singular lists them in increasing lex order


# ---------------------------------------------------------------- matrices


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


# ---------------------------------------------------------------- type conversions


@command("ideal")
def ideal(ctx, *xs: Any) -> Ideal:
    """ideal(f1, ..., fn): the ideal generated by polys, ideals or matrix entries.

    Example:
      ring r = 0,(x,y),dp;
      ideal(x2, y-1, 0);
      → _[1]=x2
      → _[2]=y-1
      → _[3]=0
      ideal I = x, ideal(y2, x+y);
      I;
      → I[1]=x
      → I[2]=y2
      → I[3]=x+y
    """
    ring = ctx.basering().poly
    return to_ideal(ExprList(xs), ring) if xs else Ideal(ring, [])


@command("poly")
def poly(ctx, x: int | Number | Poly) -> Poly:
    """poly(x): x as a polynomial.

    Example:
      ring r = 0,(x,y),dp;
      poly(3);
      → 3
      typeof(poly(3));
      → poly
    """
    return to_poly(x, ctx.basering().poly)


@command("number")
def number(ctx, x: int | Number | Poly) -> Number:
    """number(x): x as a number (a constant polynomial's coefficient).

    Example:
      ring r = 0,(x,y),dp;
      number(3/4);
      → 3/4
      number(poly(5));
      → 5
    """
    return to_number(x, ctx.basering().poly)


@command("int")
def int_(x: int | Number | Poly | str) -> int:
    """int(x): x as an int (a number must be an integer).

    Example:
      ring r = 0,(x,y),dp;
      int(number(6));
      → 6
      int("42") + 1;
      → 43
    """
    if isinstance(x, int):
        return x
    if isinstance(x, str):
        try:
            return int(x.strip())
        except ValueError:
            raise MechRuntimeError(f"int: '{x}' is not an integer") from None
    n = x if isinstance(x, Number) else to_number(x, x.ring)
    frac = n.ring.field.to_fraction(n.c)
    if frac.denominator != 1:
        raise MechRuntimeError(f"int: {frac} is not an integer")
    return int(frac.numerator)


@command("intvec")
def intvec(*xs: int | IntVec) -> IntVec:
    """intvec(a, b, ...): the vector of the ints a, b, ....

    Example:
      intvec(1, 2, 3);
      → 1,2,3
      intvec(intvec(1,2), 5);
      → 1,2,5
    """
    return to_intvec(ExprList(xs)) if xs else IntVec([0])


@command("list")
def list_(*xs: Any) -> List:
    """list(a, b, ...): the list of the values a, b, ....

    Example:
      ring r = 0,(x,y),dp;
      list(1, "two", x+y);
      → [1]:
      →    1
      → [2]:
      →    two
      → [3]:
      →    x+y
    """
    return List(xs)


@command("string")
def string(*xs: Any) -> str:
    """string(x, ...): the values written on one line and concatenated.

    Example:
      ring r = 0,(x,y),dp;
      string(x2+1, " and ", 3);
      → x2+1 and 3
      string(ideal(x, y2));
      → x,y2
    """
    return "".join(value_str(x) for x in xs)


@command("matrix")
def matrix(ctx, x: Any, nr: int = 0, nc: int = 0) -> Matrix:
    """matrix(I) or matrix(M, r, c): a matrix from an ideal (one row) or resized.

    Example:
      ring r = 0,(x,y),dp;
      print(matrix(ideal(x, y, x+y)));
      → x,y,x+y
      matrix A[2][2] = 1,2,3,4;
      print(matrix(A, 3, 3));
      → 1,2,0,
      → 3,4,0,
      → 0,0,0
    """
    return to_matrix(x, ctx.basering().poly, nr, nc) if nr else to_matrix(x, ctx.basering().poly)


@command("typeof", raw=True)
def typeof(ctx, *nodes: A.Expr) -> str:
    """typeof(x): the type name of x ("?unknown type?" for an undefined name).

    Example:
      ring r = 0,(x,y),dp;
      typeof(x);
      → poly
      typeof(ideal(x));
      → ideal
      typeof(1);
      → int
      typeof(undefinedname);
      → ?unknown type?
    """
    if len(nodes) != 1:
        raise MechTypeError("typeof takes one argument")
    node = nodes[0]
    if isinstance(node, A.Name):
        try:
            return _typeof(ctx.eval(node))
        except MechNameError:
            return "?unknown type?"
    return _typeof(ctx.eval(node))


# ---------------------------------------------------------------- printing


@command("print")
def print_(ctx, x: Any) -> None:
    """print(x): print x (a matrix as aligned rows, an ideal or intvec as a column).

    Example:
      ring r = 0,(x,y),dp;
      matrix M[2][2] = x,y2,1,-1;
      print(M);
      → x,y2,
      → 1,-1
      print(ideal(x, y));
      → x,
      → y
    """
    if x is NONE:
        return
    if isinstance(x, Map):  # as Singular: a map prints as phi[i]=... under its name
        ctx.write(render(x, ctx.argnames[0] if ctx.argnames else None) + "\n")
        return
    ctx.write(print_form(x) + "\n")


# ---------------------------------------------------------------- rings


@command("nvars")
def nvars(r: Ring) -> int:
    """nvars(r): the number of ring variables.

    Example:
      ring r = 0,(x,y,z),dp;
      nvars(r);
      → 3
    """
    return len(r.names)


@command("npars")
def npars(r: Ring) -> int:
    """npars(r): the number of parameters of the coefficient field.

    Example:
      ring r = (0,a,b),(x,y),dp;
      npars(r);
      → 2
    """
    return len(r.params)


@command("var")
def var(ctx, i: int) -> Poly:
    """var(i): the i-th ring variable.

    Example:
      ring r = 0,(x,y,z),dp;
      var(2);
      → y
    """
    ring = ctx.basering()
    if not 1 <= i <= len(ring.names):
        raise MechRuntimeError(f"var({i}): the ring has {len(ring.names)} variables")
    return ring.poly.gen(i - 1)


@command("par")
def par(ctx, i: int) -> Number:
    """par(i): the i-th parameter of the coefficient field.

    Example:
      ring r = (0,a,b),(x,y),dp;
      par(2);
      → (b)
    """
    ring = ctx.basering()
    if not 1 <= i <= len(ring.params):
        raise MechRuntimeError(f"par({i}): the ring has {len(ring.params)} parameters")
    return ctx._param(ring, ring.params[i - 1])


def _name_list(ctx: Any, r: Ring | int, i: int | None, what: str) -> str:
    """The variable (``what="variables"``) or parameter names of a ring, or the i-th of them."""
    if isinstance(r, int):
        r, i = ctx.basering(), r
    seq = r.names if what == "variables" else r.params
    if i is None:
        return ",".join(seq)
    if not 1 <= i <= len(seq):
        raise MechRuntimeError(f"index {i} out of range: the ring has {len(seq)} {what}")
    return seq[i - 1]


@command("varstr")
def varstr(ctx, r: Ring | int, i: int | None = None) -> str:
    """varstr(r): the variable names separated by commas; varstr(i) or varstr(r, i): the i-th.

    Example:
      ring r = 0,(x,y,z),dp;
      varstr(r);
      → x,y,z
      varstr(2);
      → y
    """
    return _name_list(ctx, r, i, "variables")


@command("parstr")
def parstr(ctx, r: Ring | int, i: int | None = None) -> str:
    """parstr(r): the parameter names separated by commas; parstr(i): the i-th.

    Example:
      ring r = (0,a,b),(x,y),dp;
      parstr(r);
      → a,b
      parstr(1);
      → a
    """
    return _name_list(ctx, r, i, "parameters")


@command("charstr")
def charstr(r: Ring) -> str:
    """charstr(r): the coefficient field: QQ, ZZ/p, or 0,a,b with parameters.

    Example:
      ring r = 32003,(x,y),dp;
      charstr(r);
      → ZZ/32003
      ring s = (0,a),(x,y),dp;
      charstr(s);
      → 0,a
    """
    return _charstr(r)


@command("char")
def char(r: Ring) -> int:
    """char(r): the characteristic of the coefficient field.

    Example:
      ring r = 32003,(x,y),dp;
      char(r);
      → 32003
    """
    return r.characteristic


@command("ordstr")
def ordstr(r: Ring) -> str:
    """ordstr(r): the monomial ordering, e.g. dp(4),dp(2),C.

    Example:
      ring r = 0,(x,y,z),(dp(2),lp(1));
      ordstr(r);
      → dp(2),lp(1),C
    """
    return _ordstr(r)


def _in_ring(ctx: Any, ring_node: A.Expr, name_node: A.Expr, cmd: str) -> tuple[Ring, Any]:
    src = ctx.eval(ring_node)
    if not isinstance(src, Ring):
        raise MechTypeError(f"{cmd}: the first argument must be a ring, not {_typeof(src)}")
    if isinstance(name_node, A.Name):
        var = ctx.lookup_in_ring(src, name_node.id)
        if var is not None:
            return src, var.value
    saved = ctx.ring
    ctx.ring = src
    try:
        return src, ctx.eval(name_node)
    finally:
        ctx.ring = saved


@command("imap", raw=True)
def imap(ctx, ring_node: A.Expr, obj_node: A.Expr) -> Any:
    """imap(r, f): the object f of ring r mapped into the basering, each variable to the variable
    or parameter of the same name (to 0 if the basering has none), parameters likewise by name.

    Example:
      ring r = 0,(x,y,z),dp;
      poly f = x2+yz;
      ring s = 0,(z,x),dp;
      imap(r, f);
      → x2
    """
    from ..dsl.interpreter import map_value
    from ..kernel.maps import imap as imap_polys
    _, v = _in_ring(ctx, ring_node, obj_node, "imap")
    target = ctx.basering().poly
    return map_value(v, [], target, lambda polys, source: imap_polys(polys, source, target))


@command("fetch", raw=True)
def fetch(ctx, ring_node: A.Expr, obj_node: A.Expr) -> Any:
    """fetch(r, f): the object f of ring r mapped into the basering, the i-th variable to the i-th
    (to 0 if the basering has fewer), parameters likewise by position.

    Example:
      ring r = 0,(x,y,z),dp;
      poly f = x2+yz;
      ring s = 0,(a,b,c),dp;
      fetch(r, f);
      → a2+bc
    """
    from ..dsl.interpreter import map_value
    from ..kernel.maps import fetch as fetch_polys
    _, v = _in_ring(ctx, ring_node, obj_node, "fetch")
    target = ctx.basering().poly
    return map_value(v, [], target, lambda polys, source: fetch_polys(polys, source, target))


# ---------------------------------------------------------------- interpreter commands


@command("defined", raw=True)
def defined(ctx, node: A.Expr) -> int:
    """defined(x): 0 if x is undefined, -1 for a ring variable, else 1 + the level it was declared at.

    Example:
      ring r = 0,(x,y),dp;
      int n = 3;
      defined(n);
      → 1
      defined(x);
      → -1
      defined(m);
      → 0
    """
    if not isinstance(node, A.Name):
        return 0
    var = ctx.lookup(node.id)
    if var is not None:
        return var.level + 1
    ring = ctx.ring
    if ring is not None and (ring.var_index(node.id) is not None or node.id in ring.params):
        return -1
    return 0


@command("nameof", raw=True)
def nameof(ctx, node: A.Expr) -> str:
    """nameof(x): the name of the variable x ("" for an expression; for basering the ring's name).

    Example:
      ring r = 0,(x,y),dp;
      poly f = x+y;
      nameof(f);
      → f
    """
    if isinstance(node, A.Name) and node.id == "basering":
        return ctx.basering().name
    return node.id if isinstance(node, A.Name) else ""


@command("execute")
def execute(code: str) -> None:
    """execute(s): not provided: mech does not run code built at run time from strings (an error).

    Example:
      execute("int a = 1;");
      → <stdin>:1:1: error: execute is not provided: mech does not run code built from strings; write the statements into the script
      → execute("int a = 1;");
      → ^~~~~~~~~~~~~~~~~~~~~
    """
    raise MechRuntimeError("execute is not provided: mech does not run code built from strings; "
                           "write the statements into the script")


@command("option", raw=True)
def option(ctx, *nodes: A.Expr) -> None:
    """option(name, ...): set options (option(redSB); option(noredSB) clears one); option() prints them.

    Example:
      ring r = 0,(x,y),dp;
      option(redSB);
      option();
      → //options: redSB redTail redThrough intStrategy redefine usage prompt
    """
    from ..dsl.interpreter import OPTION_ORDER
    if not nodes:
        shown = [o for o in OPTION_ORDER if o in ctx.options]
        shown += sorted(o for o in ctx.options if o not in OPTION_ORDER)
        ctx.write("//options: " + " ".join(shown) + "\n")
        return
    for n in nodes:
        if not isinstance(n, A.Name):
            raise MechTypeError("option(...) takes option names, e.g. option(redSB)")
        name = n.id
        if name.startswith("no") and name[2:] in OPTION_ORDER:
            ctx.options.discard(name[2:])
            continue
        if name not in OPTION_ORDER:
            raise MechNameError(f"unknown option '{name}'")
        ctx.options.add(name)


@command("system")
def system(ctx, what: str, *args: Any) -> Any:
    """system("--ticks-per-sec", n): the unit of timer and rtimer (ticks per second).

    Example:
      system("--ticks-per-sec", 1000);
    """
    if what == "--ticks-per-sec":
        if args:
            n = args[0]
            if not isinstance(n, int) or n <= 0:
                raise MechRuntimeError('system("--ticks-per-sec", n) needs a positive int')
            ctx.ticks_per_sec = n
            return None
        return ctx.ticks_per_sec
    raise MechRuntimeError(f"system(\"{what}\") is not supported")


@command("export", raw=True)
def export(ctx, *nodes: A.Expr) -> None:
    """export(x): make a procedure's variable x global (with its ring).

    Example:
      proc mk() { int k = 7; export(k); }
      mk();
      k;
      → 7
    """
    for n in nodes:
        if not isinstance(n, A.Name):
            raise MechTypeError("export needs variable names")
        ctx.export(n.id)


@command("delete")
def delete(L: List, i: int) -> List:
    """delete(L, i): the list L without its i-th entry.

    Example:
      list L = 1, 2, 3;
      delete(L, 2);
      → [1]:
      →    1
      → [2]:
      →    3
    """
    if not 1 <= i <= len(L):
        raise MechRuntimeError(f"delete: index {i} out of range (the list has {len(L)} entries)")
    return List(L.items[:i - 1] + L.items[i:])


@command("insert")
def insert(L: List, v: Any, i: int = 0) -> List:
    """insert(L, v) or insert(L, v, i): the list L with v inserted after position i (default 0).

    Example:
      list L = 1, 2;
      insert(L, 5);
      → [1]:
      →    5
      → [2]:
      →    1
      → [3]:
      →    2
      insert(L, 5, 2);
      → [1]:
      →    1
      → [2]:
      →    2
      → [3]:
      →    5
    """
    if not 0 <= i <= len(L):
        raise MechRuntimeError(f"insert: position {i} out of range (the list has {len(L)} entries)")
    return List(L.items[:i] + (v,) + L.items[i:])



# ---------------------------------------------------------------- help topics of the language
TOPICS.update({
    "if": "if (cond) { ... } else { ... }: run the first block when the int cond is not 0, else the second.",
    "else": "if (cond) { ... } else { ... }: the block run when cond is 0.",
    "for": "for (init; cond; step) { ... }: run init, then the block and step while the int cond is not 0.",
    "while": "while (cond) { ... }: run the block while the int cond is not 0.",
    "break": "break;: leave the innermost for or while loop.",
    "continue": "continue;: go on with the next round of the innermost loop.",
    "proc": "proc name(type a, ..., list #) { ... }: define a procedure; its variables are local, "
            "return(...) gives its values.",
    "return": "return(v, ...);: leave the procedure with the values v, ...",
    "kill": "kill x, ...;: delete the variables x, ...",
    "export": "export x;: make the procedure's variable x a top-level variable (of its ring).",
    "keepring": "keepring r;: leave the procedure with r as the basering.",
    "setring": "setring r;: make the ring r the basering (objects of other rings become invisible).",
    "LIB": 'LIB "x.lib";: load the library x.lib (mech\'s own libraries or a file next to the script).',
    "quit": "quit;: end the script.",
    "exit": "exit;: end the script.",
    "help": "help NAME; or ?NAME;: what a command, procedure, type or keyword does; help; lists the commands.",
    "basering": "basering: the current ring.",
    "int": "int i = 3;: a machine integer (div, mod, % and / divide; comparisons give 0 or 1).",
    "bigint": "bigint b = 2^70;: an integer of any size (in mech the same as int).",
    "number": "number c = 3/4;: an element of the coefficient field of the basering.",
    "poly": "poly f = x2+y;: a polynomial of the basering.",
    "ring": "ring r = 0, (x,y,z), dp;: a polynomial ring (characteristic or (char, params), variables, "
            "ordering); it becomes the basering.",
    "map": "map phi = r, f1, ..., fn;: the map from ring r to the basering taking the i-th variable to fi.",
    "list": "list L = a, b, ...;: a list of values of any types; L[i] is the i-th entry.",
    "string": 'string s = "abc";: a string; + concatenates, s[i] is a character.',
    "intvec": "intvec v = 1, 2, 3..5;: a vector of ints.",
    "def": "def x = value;: a variable taking the type of its value.",
})
