"""Singular's commands on single polynomials and integers: ``gcd``, ``lcm`` (general.lib),
``extgcd``, ``resultant``, ``coef``, ``coeffs``, ``prime``, ``find``, the ``cyclic`` ideal (polylib.lib),
``leadexp``, ``rvar``, ``jet``, ``cleardenom``."""
from __future__ import annotations

from math import gcd as int_gcd
from typing import Any
from ..dsl import ast as A
from ..dsl.errors import MechRuntimeError, MechTypeError
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, List, Matrix, typeof
from ..kernel import Poly
from ..kernel import factor
from ..kernel import matrix as KM


def _var_index(v: Poly, what: str) -> int:
    """The index of the ring variable ``v``."""
    if len(v.terms) == 1:
        (e, c), = v.terms.items()
        if sum(e) == 1 and c == v.ring.field.one:
            return e.index(1)
    raise MechRuntimeError(f"{what} takes a ring variable, not {v}")


@command("gcd")
def gcd_int(a: int, b: int) -> int:
    """gcd(a, b): the greatest common divisor of two integers or polynomials (a polynomial gcd is
    normalized as Singular's: primitive with positive leading coefficient over QQ, monic over Z/p).

    Example:
      gcd(12, 18);
      → 6
      ring r = 0,(x,y),dp;
      gcd(2x2-2, 4x-4);
      → x-1
    """
    return int_gcd(a, b)


@command("gcd")
def gcd_poly(f: Poly, g: Poly) -> Poly:
    if (f.is_zero() and g.is_constant()) or (g.is_zero() and f.is_constant()):  # as Singular: gcd(0, c)
        return g if f.is_zero() else f                                            # is c itself
    h = factor.gcd(f, g)
    if getattr(h.ring.field, "params", ()):  # with parameters Singular clears denominators, as std does
        from .standard import normalize
        return normalize(h)
    return h


@command("extgcd")
def extgcd_int(a: int, b: int) -> List:
    """extgcd(a, b): the list [g, s, t] with g = gcd(a, b) = s*a + t*b (integers, or univariate
    polynomials: g monic, s and t of the least degrees).

    Example:
      extgcd(12, 18);
      → [1]:
      →    6
      → [2]:
      →    -1
      → [3]:
      →    1
    """
    s0, t0, s1, t1 = 1, 0, 0, 1
    while b:
        q = a // b
        a, b = b, a - q * b
        s0, t0, s1, t1 = s1, t1, s0 - q * s1, t0 - q * t1
    sign = -1 if a < 0 else 1
    return List([sign * a, sign * s0, sign * t0])


@command("extgcd")
def extgcd_poly(f: Poly, g: Poly) -> List:
    ring = f.ring
    used = f.variables() | g.variables()
    if len(used) > 1:
        raise MechRuntimeError("extgcd takes univariate polynomials")
    i = used.pop() if used else 0
    a, b = f, g
    s0, t0, s1, t1 = ring.one(), ring.zero(), ring.zero(), ring.one()
    while not b.is_zero():
        q, r = _divmod_in(a, b, i)
        a, b = b, r
        s0, t0, s1, t1 = s1, t1, s0 - q * s1, t0 - q * t1
    if a.is_zero():
        return List([a, s0, t0])
    inv = ring.field.one / a.lc()
    return List([a * inv, s0 * inv, t0 * inv])


def _divmod_in(a: Poly, b: Poly, i: int) -> tuple[Poly, Poly]:
    """Quotient and remainder of univariate polynomials in the i-th variable."""
    ring, q, r = a.ring, a.ring.zero(), a
    eb = max(b.terms, key=lambda e: e[i])
    lb = b.terms[eb]
    while not r.is_zero() and r.degree_in(i) >= eb[i]:
        er = max(r.terms, key=lambda e: e[i])
        t = ring.monomial(tuple(x - y for x, y in zip(er, eb)), r.terms[er] / lb)
        q, r = q + t, r - t * b
    return q, r


@command("lcm", lib="general.lib")
def lcm_int(*xs: int) -> int:
    """lcm(a, b, ...): the least common multiple of integers, or of polynomials (their product
    divided by the gcd, as general.lib's lcm computes it).

    Example:
      LIB "general.lib";
      lcm(4, 6);
      → 12
      ring r = 0,(x,y),dp;
      lcm(x2, xy, y3);
      → x2y3
    """
    out = 1
    for x in xs:
        out = abs(out * x) // int_gcd(out, x) if x else 0
    return out


@command("lcm", lib="general.lib")
def lcm_poly(*fs: Poly) -> Poly:
    out = fs[0]
    for f in fs[1:]:
        g = factor.gcd(out, f)
        out = out.ring.zero() if g.is_zero() else factor.divide_exact(out * f, g)
    return out


@command("resultant")
def resultant(f: Poly, g: Poly, v: Poly) -> Poly:
    """resultant(f, g, x): the resultant of f and g with respect to the variable x (the determinant
    of their Sylvester matrix).

    Example:
      ring r = 0,(x,y),dp;
      resultant(2x2+y, 3x-y, x);
      → 2y2+9y
    """
    i = _var_index(v, "resultant")
    fc, gc = _coeffs_in(f, i), _coeffs_in(g, i)
    m, n = len(fc) - 1, len(gc) - 1
    ring = f.ring
    if m < 0 or n < 0:
        return ring.zero()
    if m == 0 and n == 0:
        return ring.one()
    size = m + n
    rows: list[Poly] = []
    for k in range(n):  # n shifted rows of f's coefficients, highest first
        rows += [ring.zero()] * k + fc[::-1] + [ring.zero()] * (size - k - m - 1)
    for k in range(m):
        rows += [ring.zero()] * k + gc[::-1] + [ring.zero()] * (size - k - n - 1)
    return KM.det(KM.Matrix(ring, size, size, rows))


def _coeffs_in(f: Poly, i: int) -> list[Poly]:
    """The coefficients of f as a polynomial in the i-th variable, from degree 0 up ([] for 0)."""
    if f.is_zero():
        return []
    deg = max(e[i] for e in f.terms)
    parts: list[dict] = [{} for _ in range(deg + 1)]
    for e, c in f.terms.items():
        parts[e[i]][e[:i] + (0,) + e[i + 1:]] = c
    return [Poly(f.ring, p) for p in parts]


@command("coeffs", raw=True)
def coeffs(ctx, f_node: A.Expr, v_node: A.Expr, *t_node: A.Expr) -> Matrix:
    """coeffs(f, x): the coefficients of f as a polynomial in the variable x, a column from x^0 up;
    for an ideal one column per generator, for a vector the entries' columns (as long as the longest)
    one under another; coeffs(f, x, T) also sets the matrix T to the row of powers 1, x, x2, ...
    (T*coeffs(f, x, T) == f).

    Example:
      ring r = 0,(x,y,z),dp;
      print(coeffs(3x2y+2xz-z, x));
      → -z,
      → 2z,
      → 3y
    """
    from ..dsl.values_modules import Module, Vector
    f, v = ctx.eval(f_node), ctx.eval(v_node)
    if isinstance(f, (Ideal, Module)) and isinstance(v, (Ideal, Module)) and len(t_node) == 1:
        m = ctx.eval(t_node[0])
        if isinstance(m, Poly):
            return _coeffs_in_basis(f, v, m)
    if isinstance(f, Vector) and isinstance(v, Poly) and not t_node:  # each entry's column, one under another
        cols = _coeffs(Ideal(f.ring, list(f.entries) or [f.ring.zero()]), v)
        return Matrix(v.ring, cols.nrows * cols.ncols, 1,
                      [cols.get(r, c) for c in range(1, cols.ncols + 1) for r in range(1, cols.nrows + 1)])
    if len(t_node) > 1 or not isinstance(f, (Poly, Ideal)) or not isinstance(v, Poly):
        got = ", ".join(typeof(a) for a in (f, v)) + ", matrix" * len(t_node)
        raise MechTypeError(f"wrong arguments for coeffs: got ({got}), expected coeffs(poly|ideal, poly[, matrix])")
    m = _coeffs(f, v)
    if t_node:
        i = _var_index(v, "coeffs")
        x = v.ring.gen(i)
        ctx.assign(t_node[0], Matrix(v.ring, 1, m.nrows, [x ** k for k in range(m.nrows)]))
    return m


def _coeffs_in_basis(f: Any, basis: Any, m: Poly) -> Matrix:
    """coeffs(M, K, m): the coefficients (polynomials in the variables not in the product m) of M's
    columns in the basis K of monomial vectors in the variables of m, each K[k] standing for its leading
    monomial; the terms of M with no such monomial are dropped (K*coeffs(M, K, m) is M only when K is a
    basis of all of them)."""
    from ..dsl.convert_modules import to_module
    from ..dsl.values_modules import lead_term
    ring = m.ring
    idx = _coef_vars(m)
    cols, ks = to_module(f, ring).gens, to_module(basis, ring).gens
    where = {lead_term(k): r for r, k in enumerate(ks) if not k.is_zero()}
    entries = [[ring.zero()] * len(cols) for _ in ks]
    for c, v in enumerate(cols):
        for (e, comp), a in v.terms().items():
            key = (tuple(x if i in idx else 0 for i, x in enumerate(e)), comp)
            r = where.get(key)
            if r is not None:
                entries[r][c] = entries[r][c] + ring.monomial(tuple(0 if i in idx else x for i, x in enumerate(e))) * a
    return Matrix(ring, len(ks), len(cols), [x for row in entries for x in row])


def _coeffs(f: Poly | Ideal, v: Poly) -> Matrix:
    i = _var_index(v, "coeffs")
    polys = [f] if isinstance(f, Poly) else list(f.gens)
    cols = [_coeffs_in(p, i) for p in polys]
    nrows = max([len(c) for c in cols] + [1])
    ring = v.ring
    entries = []
    for r in range(nrows):
        for c in cols:
            entries.append(c[r] if r < len(c) else ring.zero())
    return Matrix(ring, nrows, len(cols), entries)


@command("coef", raw=True)
def coef(ctx, f_node: A.Expr, m_node: A.Expr, *out: A.Expr) -> Any:
    """coef(f, m): a 2-row matrix: the monomials in the variables of the product m occurring in f (in
    decreasing order) over their coefficients (polynomials in the other variables); coef(v, m, C, M)
    for a vector v sets C and M to one row per entry: its coefficients and its monomials as coef(f, m)
    gives them (rows padded with zeros).

    Example:
      ring r = 0,(x,y,z),dp;
      print(coef(3x2y+2xz-z, x));
      → x2,x, 1,
      → 3y,2z,-z
    """
    from ..dsl.values import NONE
    from ..dsl.values_modules import Vector
    f, vs = ctx.eval(f_node), ctx.eval(m_node)
    if isinstance(f, Poly) and isinstance(vs, Poly) and not out:
        return _coef(f, vs)
    if isinstance(f, Vector) and isinstance(vs, Poly) and len(out) == 2:
        ring = f.ring
        idx = _coef_vars(vs)
        groups = [_coef_groups(p, idx) for p in f.entries] or [{}]
        keys = [_coef_order(ring, g) for g in groups]
        n, k = len(groups), max([len(ks) for ks in keys] + [1])
        coeffs, monos = [], []
        for g, ks in zip(groups, keys):
            coeffs += [Poly(ring, g[key]) for key in ks] + [ring.zero()] * (k - len(ks))
            monos += [ring.monomial(key) for key in ks] + [ring.zero()] * (k - len(ks))
        ctx.assign(out[0], Matrix(ring, n, k, coeffs))
        ctx.assign(out[1], Matrix(ring, n, k, monos))
        return NONE
    got = ", ".join(typeof(a) for a in (f, vs)) + ", matrix" * len(out)
    raise MechTypeError(f"wrong arguments for coef: got ({got}), expected coef(poly, poly) or "
                        "coef(vector, poly, matrix, matrix)")


def _coef_vars(vs: Poly) -> list[int]:
    if len(vs.terms) != 1:
        raise MechRuntimeError("coef takes a product of ring variables as its second argument")
    (mask, _), = vs.terms.items()
    return [i for i, k in enumerate(mask) if k]


def _coef_groups(f: Poly, idx: list[int]) -> dict[tuple, dict]:
    """f's terms grouped by their monomial in the variables idx: {that monomial: the coefficient's terms}."""
    groups: dict[tuple, dict] = {}
    for e, c in f.terms.items():
        key = tuple(e[i] if i in idx else 0 for i in range(len(e)))
        rest = tuple(0 if i in idx else e[i] for i in range(len(e)))
        groups.setdefault(key, {})[rest] = c
    return groups


def _coef_order(ring: Any, keys: Any) -> list[tuple]:
    """As Singular: largest first in a global ordering, smallest first in a local or mixed one."""
    return sorted(keys, key=ring.order.key, reverse=ring.order.is_global)


def _coef(f: Poly, vs: Poly) -> Matrix:
    ring = f.ring
    idx = _coef_vars(vs)
    if f.is_zero():
        return Matrix(ring, 2, 1, [ring.zero(), ring.zero()])
    groups = _coef_groups(f, idx)
    keys = _coef_order(ring, groups)
    top = [ring.monomial(k) for k in keys]
    return Matrix(ring, 2, len(keys), top + [Poly(ring, groups[k]) for k in keys])


@command("prime")
def prime(n: int) -> int:
    """prime(n): the largest prime not above n (2 for n < 2... as Singular: n >= 2).

    Example:
      prime(100);
      → 97
    """
    import flint
    if n < 2:
        return 2
    while n > 2 and not flint.fmpz(n).is_prime():
        n -= 1
    return n


@command("find")
def find(s: str, t: str, start: int = 1) -> int:
    """find(s, t[, i]): the position of the first occurrence of t in s at or after position i (0: none).

    Example:
      find("abcabc", "c", 4);
      → 6
    """
    return s.find(t, max(start, 1) - 1) + 1


@command("cyclic", lib="polylib.lib")
def cyclic(ctx, n: int) -> Ideal:
    """cyclic(n): the cyclic n-roots ideal in the first n variables of the basering.

    Example:
      LIB "polylib.lib";
      ring r = 0,(x,y,z),dp;
      cyclic(3);
      → _[1]=x+y+z
      → _[2]=xy+xz+yz
      → _[3]=xyz-1
    """
    ring = ctx.basering().poly
    if not 1 <= n <= ring.nvars:
        raise MechRuntimeError(f"cyclic({n}) needs at least {n} variables")
    xs = ring.gens()[:n]
    gens = []
    for k in range(1, n):
        p = ring.zero()
        for s in range(n):
            t = ring.one()
            for j in range(k):
                t = t * xs[(s + j) % n]
            p = p + t
        gens.append(p)
    last = ring.one()
    for x in xs:
        last = last * x
    gens.append(last - ring.one())
    return Ideal(ring, gens)


@command("leadexp")
def leadexp(f: Poly) -> IntVec:
    """leadexp(f): the exponent vector of the leading monomial of f.

    Example:
      ring r = 0,(x,y,z),dp;
      leadexp(3x2y+z5);
      → 0,0,5
    """
    return IntVec(f.lm() if not f.is_zero() else (0,) * f.ring.nvars)


@command("rvar", raw=True)
def rvar(ctx, node: A.Expr) -> int:
    """rvar(x): the index of the ring variable x (a variable or its name), 0 if it is none (an
    undefined name too).

    Example:
      ring r = 0,(x,y,z),dp;
      rvar(y);
      → 2
      rvar("w");
      → 0
    """
    ring = ctx.basering()
    if isinstance(node, A.Name) and ring.var_index(node.id) is None and ctx.lookup(node.id) is None:
        return 0
    v = ctx.eval(node)
    if isinstance(v, str):
        i = ring.var_index(v)
        return 0 if i is None else i + 1
    if isinstance(v, Poly):
        try:
            return _var_index(v, "rvar") + 1
        except MechRuntimeError:
            return 0
    return 0


@command("jet")
def jet(f: Poly | Ideal, d: int) -> Any:
    """jet(f, d): the terms of f of total degree at most d (of each generator for an ideal).

    Example:
      ring r = 0,(x,y,z),dp;
      jet(x2+y3+z+1, 2);
      → x2+z+1
    """
    def cut(p: Poly) -> Poly:
        return Poly(p.ring, {e: c for e, c in p.terms.items() if sum(e) <= d})
    if isinstance(f, Poly):
        return cut(f)
    return Ideal(f.ring, [cut(p) for p in f.gens])


@command("jet")
def jet_weighted(f: Poly | Ideal, d: int, w: IntVec) -> Any:
    """jet(f, d, w): the terms of f of weighted degree at most d for the variables' weights w.

    Example:
      ring r = 0,(x,y),dp;
      jet(x3+xy+y2+x+1, 2, intvec(2,1));
      → xy+y2+x+1
    """
    ws = list(w.values) + [0] * (f.ring.nvars - len(w.values))

    def cut(p: Poly) -> Poly:
        return Poly(p.ring, {e: c for e, c in p.terms.items() if sum(a * b for a, b in zip(e, ws)) <= d})
    if isinstance(f, Poly):
        return cut(f)
    return Ideal(f.ring, [cut(p) for p in f.gens])


@command("jet")
def jet_unit(f: Poly | Ideal, u: Poly, d: int) -> Any:
    """jet(f, u, d): the d-jet of f/u for a unit u of the local ring (nonzero constant term): f times
    the power series of 1/u, cut at total degree d.  (The installed Singular 4.3.1 leaves terms above
    degree d in the product when f or u has several terms of positive degree; mech cuts as documented.)

    Example:
      ring r = 0,x,ds;
      jet(1, 1+x, 3);
      → 1-x+x2-x3
    """
    ring = u.ring
    c = u.terms.get(ring.zero_exp)
    if c is None or c == ring.field.zero:
        raise MechRuntimeError("jet(f, u, d): u must be a unit (a nonzero constant term)")
    h = jet(Poly(ring, {e: -v / c for e, v in u.terms.items() if e != ring.zero_exp}), d)
    inv, power = ring.one(), ring.one()
    for _ in range(d):
        power = jet(power * h, d)
        inv = inv + power
    inv = Poly(ring, {e: v / c for e, v in inv.terms.items()})
    if isinstance(f, Poly):
        return jet(f * inv, d)
    return Ideal(ring, [jet(g * inv, d) for g in f.gens])



@command("reduce")
def reduce_unit(ctx, f: Poly, u: Poly, I: Ideal, d: int) -> Poly:
    """reduce(f, u, I, d): the normal form of f/u with respect to I up to degree d, for a unit u of
    the local ring: the d-jet of f/u with every term reduced by the generators of I (a standard
    basis: the normal form of the power series, cut at degree d).

    Example:
      ring r = 0,x,ds;
      reduce(poly(1), 1+x, ideal(x3), 5);
      → 1-x+x2
    """
    if len(I.nonzero()) > 1 and not I.is_std:
        ctx.warn(f"{ctx.argnames[2] if len(ctx.argnames) > 2 else '_'} is no standard basis")
    divisors = [g for g in I.gens if not g.is_zero()]
    p, rest = jet_unit(f, u, d), {}
    while not p.is_zero():  # every term reduced; terms above degree d never reach those below
        e, c = p.lm(), p.lc()
        g = next((g for g in divisors if all(a >= b for a, b in zip(e, g.lm()))), None)
        if g is None:
            rest[e] = c
            p = p - p.ring.monomial(e, c)
        else:
            p = jet(p - g.mul_term(tuple(a - b for a, b in zip(e, g.lm())), c / g.lc()), d)
    return f.ring.from_dict(rest)

@command("cleardenom")
def cleardenom(f: Poly) -> Poly:
    """cleardenom(f): f times a constant so that its coefficients are coprime integers with a positive
    leading one (over QQ and QQ(parameters); over Z/p f itself; over Z/p(parameters) coprime
    polynomials in the parameters).

    Example:
      ring r = 0,(x,y),dp;
      cleardenom(1/2x2+1/3y);
      → 3x2+2y
    """
    from .standard import normalize
    field = f.ring.field
    if field.characteristic and getattr(field, "params", ()) and not hasattr(field, "modulus") and f.terms:
        return _cleardenom_params_mod_p(f)
    return f if field.characteristic else normalize(f)


def _cleardenom_params_mod_p(f: Poly) -> Poly:
    """Over Z/p(a,...) as Singular: times the lcm of the (monic) denominators, divided by the monic gcd
    of the numerators; constant factors stay."""
    from .standard import primitive_numerators
    field = f.ring.field
    return Poly(f.ring, {e: field.from_polys(n) for e, n in primitive_numerators(f).items()})
