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
from ..dsl.printing import print_form, value_str
from ..dsl.values import (NONE, ExprList, Ideal, IntVec, List, Map, Matrix, Number, Ring, to_ideal, to_intvec,
                          to_matrix, to_number, to_poly)
from ..dsl.values import typeof as _typeof
from ..kernel import Poly
from ..kernel.dimension import krull_dim
from ..kernel.groebner import groebner as _groebner
from ..kernel.groebner import normal_form
from .registry import command

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
    ring = ideal.ring
    gens = ideal.nonzero()
    if ring.order.is_global:
        basis = _groebner(gens, ring)
    else:
        try:
            from ..kernel.mora import standard_basis as local_std
        except ImportError:
            raise MechRuntimeError("std for local and mixed orderings (ls, ds, ...) is not supported yet") from None
        basis = local_std(gens, ring)
    return [normalize(p) for p in basis]


@command("std")
def std(I: Ideal) -> Ideal:
    """std(I): a standard basis of the ideal I for the ring's ordering (for a global ordering the
    reduced Groebner basis, each element a primitive integer polynomial over QQ, monic over Z/p),
    sorted by increasing leading monomial."""
    return Ideal(I.ring, standard_basis(I), is_std=True)


@command("groebner")
def groebner(I: Ideal) -> Ideal:
    """groebner(I): a Groebner basis of I (the same as std(I))."""
    return Ideal(I.ring, standard_basis(I), is_std=True)


def _nf(f: Poly, basis: list[Poly]) -> Poly:
    if f.ring.order.is_global:
        return normal_form(f, basis)
    try:
        from ..kernel.mora import weak_normal_form
    except ImportError:
        raise MechRuntimeError("reduce for local and mixed orderings is not supported yet") from None
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
    basis I; the remainder is returned as it is (not normalized)."""
    return _reduce(ctx, f, I)


@command("NF")
def NF(ctx, f: Poly | Ideal | Matrix, I: Ideal) -> Any:
    """NF(f, I): the normal form of f with respect to the standard basis I (the same as reduce)."""
    return _reduce(ctx, f, I)


@command("dim")
def dim(ctx, I: Ideal) -> int:
    """dim(I): the Krull dimension of R/I for a standard basis I (-1 for the unit ideal)."""
    ctx.assume_std(I, 0)
    lms = [g.lm() for g in I.nonzero()]
    return krull_dim(lms, I.ring.nvars)


# ---------------------------------------------------------------- structure of polynomials


@command("size")
def size(x: Any) -> int:
    """size(x): terms of a poly, nonzero generators of an ideal, entries of a list, intvec or
    matrix, characters of a string."""
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
    """lead(f): the leading term of a poly, or the ideal of leading terms."""
    if isinstance(f, Poly):
        return f.ring.zero() if f.is_zero() else f.lt()
    return Ideal(f.ring, [g if g.is_zero() else g.lt() for g in f.gens])


@command("leadcoef")
def leadcoef(f: Poly) -> Number:
    """leadcoef(f): the leading coefficient of f (a number)."""
    return Number(f.ring, f.ring.field.zero if f.is_zero() else f.lc())


@command("leadmonom")
def leadmonom(f: Poly) -> Poly:
    """leadmonom(f): the leading monomial of f (coefficient 1)."""
    return f.ring.zero() if f.is_zero() else f.ring.monomial(f.lm())


@command("deg")
def deg(f: Poly | Ideal, w: IntVec | None = None) -> int:
    """deg(f) or deg(f, w): the (weighted) total degree of f, -1 for 0; for an ideal the maximum."""
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
    """diff(f, x): the partial derivative of f (poly, ideal or matrix) by the ring variable x."""
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
    (one row per generator)."""
    n = f.ring.nvars
    if isinstance(f, Poly):
        return Ideal(f.ring, [f.diff(i) for i in range(n)])
    return Matrix(f.ring, len(f.gens), n, [g.diff(i) for g in f.gens for i in range(n)])


@command("subst")
def subst(f: Poly | Ideal | Matrix, *pairs: Any) -> Any:
    """subst(f, x, g, ...): substitute g for the ring variable x in f (several pairs in turn)."""
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
    """maxideal(k): the ideal of all monomials of degree k."""
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
    """ncols(M): the number of columns (generators of an ideal)."""
    if isinstance(m, Matrix):
        return m.ncols
    if isinstance(m, Ideal):
        return len(m.gens)
    return 1


@command("nrows")
def nrows(m: Matrix | Ideal | IntVec) -> int:
    """nrows(M): the number of rows (1 for an ideal)."""
    if isinstance(m, Matrix):
        return m.nrows
    if isinstance(m, Ideal):
        return 1
    return len(m)


@command("transpose")
def transpose(m: Matrix) -> Matrix:
    """transpose(M): the transposed matrix."""
    return Matrix(m.ring, m.ncols, m.nrows, [m.get(i, j) for j in range(1, m.ncols + 1)
                                             for i in range(1, m.nrows + 1)])


# ---------------------------------------------------------------- type conversions


@command("ideal")
def ideal(ctx, *xs: Any) -> Ideal:
    """ideal(f1, ..., fn): the ideal generated by polys, ideals or matrix entries."""
    ring = ctx.basering().poly
    return to_ideal(ExprList(xs), ring) if xs else Ideal(ring, [])


@command("poly")
def poly(ctx, x: int | Number | Poly) -> Poly:
    """poly(x): x as a polynomial."""
    return to_poly(x, ctx.basering().poly)


@command("number")
def number(ctx, x: int | Number | Poly) -> Number:
    """number(x): x as a number (a constant polynomial's coefficient)."""
    return to_number(x, ctx.basering().poly)


@command("int")
def int_(x: int | Number | Poly | str) -> int:
    """int(x): x as an int (a number must be an integer)."""
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
    """intvec(a, b, ...): the vector of the ints a, b, ...."""
    return to_intvec(ExprList(xs)) if xs else IntVec([0])


@command("list")
def list_(*xs: Any) -> List:
    """list(a, b, ...): the list of the values a, b, ...."""
    return List(xs)


@command("string")
def string(*xs: Any) -> str:
    """string(x, ...): the values written on one line and concatenated."""
    return "".join(value_str(x) for x in xs)


@command("matrix")
def matrix(ctx, x: Any, nr: int = 0, nc: int = 0) -> Matrix:
    """matrix(I) or matrix(M, r, c): a matrix from an ideal (one row) or resized."""
    return to_matrix(x, ctx.basering().poly, nr, nc) if nr else to_matrix(x, ctx.basering().poly)


@command("typeof", raw=True)
def typeof(ctx, *nodes: A.Expr) -> str:
    """typeof(x): the type name of x ("?unknown type?" for an undefined name)."""
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
    """print(x): print x (a matrix as aligned rows, an ideal or intvec as a column)."""
    if x is NONE:
        return
    ctx.write(print_form(x) + "\n")


# ---------------------------------------------------------------- rings


@command("nvars")
def nvars(r: Ring) -> int:
    """nvars(r): the number of ring variables."""
    return len(r.names)


@command("npars")
def npars(r: Ring) -> int:
    """npars(r): the number of parameters of the coefficient field."""
    return len(r.params)


@command("var")
def var(ctx, i: int) -> Poly:
    """var(i): the i-th ring variable."""
    ring = ctx.basering()
    if not 1 <= i <= len(ring.names):
        raise MechRuntimeError(f"var({i}): the ring has {len(ring.names)} variables")
    return ring.poly.gen(i - 1)


@command("par")
def par(ctx, i: int) -> Number:
    """par(i): the i-th parameter of the coefficient field."""
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
    """varstr(r): the variable names separated by commas; varstr(i) or varstr(r, i): the i-th."""
    return _name_list(ctx, r, i, "variables")


@command("parstr")
def parstr(ctx, r: Ring | int, i: int | None = None) -> str:
    """parstr(r): the parameter names separated by commas; parstr(i): the i-th."""
    return _name_list(ctx, r, i, "parameters")


@command("charstr")
def charstr(r: Ring) -> str:
    """charstr(r): the coefficient field: QQ, ZZ/p, or 0,a,b with parameters."""
    return _charstr(r)


@command("char")
def char(r: Ring) -> int:
    """char(r): the characteristic of the coefficient field."""
    return r.characteristic


@command("ordstr")
def ordstr(r: Ring) -> str:
    """ordstr(r): the monomial ordering, e.g. dp(4),dp(2),C."""
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
    of the same name (to 0 if the basering has none)."""
    from ..dsl.interpreter import map_value
    src, v = _in_ring(ctx, ring_node, obj_node, "imap")
    target = ctx.basering()
    images = []
    for n in src.names:
        i = target.var_index(n)
        images.append(target.poly.gen(i) if i is not None else target.poly.zero())
    return map_value(v, images, target.poly)


@command("fetch", raw=True)
def fetch(ctx, ring_node: A.Expr, obj_node: A.Expr) -> Any:
    """fetch(r, f): the object f of ring r mapped into the basering, the i-th variable to the i-th."""
    from ..dsl.interpreter import map_value
    src, v = _in_ring(ctx, ring_node, obj_node, "fetch")
    target = ctx.basering()
    if len(src.names) > len(target.names):
        raise MechRuntimeError(f"fetch: {src.name or 'the source ring'} has more variables than the basering")
    return map_value(v, [target.poly.gen(i) for i in range(len(src.names))], target.poly)


# ---------------------------------------------------------------- interpreter commands


@command("defined", raw=True)
def defined(ctx, node: A.Expr) -> int:
    """defined(x): 0 if x is undefined, -1 for a ring variable, else 1 + the level it was declared at."""
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
    """nameof(x): the name of the variable x ("" for an expression)."""
    return node.id if isinstance(node, A.Name) else ""


@command("execute")
def execute(ctx, code: str) -> None:
    """execute(s): run the string s as mech code."""
    ctx.execute(code, ctx.source.name)


@command("option", raw=True)
def option(ctx, *nodes: A.Expr) -> None:
    """option(name, ...): set options (option(redSB); option(noredSB) clears one); option() prints them."""
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
    """system("--ticks-per-sec", n): the unit of timer and rtimer (ticks per second)."""
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
    """export(x): make a procedure's variable x global (with its ring)."""
    for n in nodes:
        if not isinstance(n, A.Name):
            raise MechTypeError("export needs variable names")
        ctx.export(n.id)


@command("delete")
def delete(L: List, i: int) -> List:
    """delete(L, i): the list L without its i-th entry."""
    if not 1 <= i <= len(L):
        raise MechRuntimeError(f"delete: index {i} out of range (the list has {len(L)} entries)")
    return List(L.items[:i - 1] + L.items[i:])


@command("insert")
def insert(L: List, v: Any, i: int = 0) -> List:
    """insert(L, v) or insert(L, v, i): the list L with v inserted after position i (default 0)."""
    if not 0 <= i <= len(L):
        raise MechRuntimeError(f"insert: position {i} out of range (the list has {len(L)} entries)")
    return List(L.items[:i] + (v,) + L.items[i:])

