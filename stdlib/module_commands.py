"""Singular's commands on vectors and modules: ``gen``, ``freemodule``, ``vector(...)``, ``module(...)``,
``nrows``/``ncols``/``size``, ``std``, ``reduce``/``NF``, ``syz``, ``liftstd``, ``modulo`` (``lift``: :mod:`.lift`),
and polylib.lib's ``id2mod``/``mod2id``.  Standard bases of submodules are Buchberger's algorithm for
modules (:mod:`mech.kernel.modules`) in the ring's module ordering (``(dp,C)``, ``(c,dp)``, ...), for
global orderings.  Over a qring R/Q a submodule M of (R/Q)^r is M + Q*R^r in R^r (:func:`q_columns`):
its standard basis is that of M + Q*R^r without the elements whose lead lies in lead(Q)*R^r, and
syzygies over R/Q are those over R of M's generators together with the q*e_i, cut to M's part.
"""
from __future__ import annotations

from math import gcd
from typing import Any, Optional

from ..dsl import ast as A
from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, Matrix, to_matrix, to_poly
from ..dsl.convert_modules import to_module, to_vector
from ..dsl.values_modules import Module, Vector, gen as make_gen, kernel_key, lead_term
from ..kernel import Poly, PolyRing
from ..kernel import modules as km
from ..kernel.module_mora import mora_normal_form


def _plain(ring: PolyRing, what: str) -> None:
    """Modules over a quotient ring (qring) are not supported: refuse rather than ignore the quotient."""
    from ..dsl.qrings import quotient_ideal
    if quotient_ideal(ring) is not None:
        raise MechRuntimeError(f"{what} of a module over a qring is not supported")


def q_columns(ring: PolyRing, rank: int) -> list[dict]:
    """In a qring R/Q the vectors q*e_i (q in Q's standard basis, i < rank), else none."""
    from ..dsl.qrings import quotient_of
    q = quotient_of(ring)
    if q is None:
        return []
    return [{(e, i): c for e, c in g.terms.items()} for g in q.basis for i in range(rank)]


def _outside_quotient(ring: PolyRing, basis: list[dict], key: Any) -> list[dict]:
    """The basis elements whose lead is not in lead(Q)*R^r (all of them over a polynomial ring)."""
    from ..dsl.qrings import quotient_of
    from ..kernel.poly import divides
    q = quotient_of(ring)
    if q is None:
        return basis
    qleads = [g.lm() for g in q.basis]
    return [g for g in basis if not any(divides(le, max(g, key=key)[0]) for le in qleads)]


def _global(ring: PolyRing, what: str) -> None:
    _plain(ring, what)
    if not ring.order.is_global:
        raise MechRuntimeError(f"{what} of a module in a local or mixed ordering is not supported")


_TWINS: dict[int, tuple[PolyRing, PolyRing]] = {}


def global_twin(ring: PolyRing) -> PolyRing:
    """The ring with a global ordering (dp): syzygies of polynomials do not depend on the ordering,
    and those over K[x] generate those over its localization."""
    if ring.order.is_global:
        return ring
    hit = _TWINS.get(id(ring))
    if hit is None or hit[0] is not ring:
        from ..kernel.order import MonomialOrder
        hit = _TWINS[id(ring)] = (ring, PolyRing(ring.field, ring.names, MonomialOrder.simple("dp", ring.nvars)))
    return hit[1]


def _normalized(ring: PolyRing, terms: dict, lead: Any) -> dict:
    """A vector scaled as Singular's std returns it: over QQ primitive with integer coefficients and
    a positive leading coefficient, over Z/p with leading coefficient 1."""
    field = ring.field
    if getattr(field, "params", ()):
        return terms
    if field.characteristic:
        c = terms[lead]
        return {t: v / c for t, v in terms.items()}
    import flint
    den = 1
    for c in terms.values():
        q = int(c.q)
        den = den * q // gcd(den, q)
    g = 0
    for c in terms.values():
        g = gcd(g, int(c.p) * (den // int(c.q)))
    scale = flint.fmpq(den, g) * (-1 if terms[lead] < 0 else 1)
    return {t: v * scale for t, v in terms.items()}


def _basis(ring: PolyRing, rank: int, vecs: list[dict]) -> list[dict]:
    """The reduced standard basis (normalized, by increasing lead term) of the submodule of R^rank
    (over a qring: of (R/Q)^rank)."""
    key = kernel_key(ring)
    vecs = [v for v in vecs if v] + q_columns(ring, rank)
    if not ring.order.is_global:
        basis = km.local_standard_basis(ring, rank, vecs, key)  # Singular lists it by decreasing lead
        return [_normalized(ring, g, max(g, key=key)) for g in reversed(_outside_quotient(ring, basis, key))]
    gb = km.ModuleGB(ring, rank, key=key)
    gb.add(vecs)
    out = [(_normalized(ring, g, lt), lt) for g, lt in zip(gb.basis, gb.leads)]
    out.sort(key=lambda gl: key(gl[1]))
    return _outside_quotient(ring, [g for g, _ in out], key)


def _module(ring: PolyRing, vecs: list[dict], rank: int, is_std: bool = False) -> Module:
    return Module(ring, [Vector.from_terms(ring, v) for v in vecs], rank, is_std)


def _vecs(m: Module) -> list[dict]:
    return [g.terms() for g in m.gens]


@command("gen")
def gen(ctx, i: int) -> Vector:
    """gen(i): the i-th canonical generator of the free module (a vector).

    Example:
      ring r = 0,(x,y),dp;
      vector v = x*gen(1) + y2*gen(3);
      v;
      → y2*gen(3)+x*gen(1)
      print(v);
      → [x,0,y2]
    """
    return make_gen(ctx.basering().poly, i)


@command("freemodule")
def freemodule(ctx, n: int) -> Module:
    """freemodule(n): the free module of rank n, generated by gen(1), ..., gen(n).

    Example:
      ring r = 0,(x,y),dp;
      freemodule(2);
      → _[1]=gen(1)
      → _[2]=gen(2)
    """
    ring = ctx.basering().poly
    return Module(ring, [make_gen(ring, i) for i in range(1, n + 1)], n)


@command("vector")
def vector(ctx, *xs: Any) -> Vector:
    """vector(p): p as a vector (p*gen(1)); vector(v): v; [p1, p2, ...] (or vector(p1, p2, ...)):
    the vector with these entries.

    Example:
      ring r = 0,(x,y),dp;
      vector(x+y) + gen(2);
      → x*gen(1)+y*gen(1)+gen(2)
      [x, 0, y2];
      → y2*gen(3)+x*gen(1)
    """
    ring = ctx.basering().poly
    if len(xs) == 1:
        return to_vector(xs[0], ring)
    return Vector(ring, [to_poly(x, ring) for x in xs])


@command("module")
def module(ctx, *xs: Any) -> Module:
    """module(...): the module generated by vectors, polynomials (p*gen(1)), the columns of a matrix
    or the generators of ideals and modules.

    Example:
      ring r = 0,(x,y),dp;
      matrix A[2][2] = x,y,1,x2;
      module(A);
      → _[1]=x*gen(1)+gen(2)
      → _[2]=x2*gen(2)+y*gen(1)
    """
    from ..dsl.values import ExprList
    ring = ctx.basering().poly
    if not xs:
        return Module(ring, ())
    return to_module(xs[0] if len(xs) == 1 else ExprList(list(xs)), ring)


@command("nrows")
def nrows(m: Vector | Module) -> int:
    """nrows(m): the rank of the free module m lies in (a vector: its highest component).

    Example:
      ring r = 0,(x,y),dp;
      nrows([x,0,y]);
      → 3
    """
    return m.nrows if isinstance(m, Vector) else m.rank


@command("ncols")
def ncols(m: Module) -> int:
    return len(m.gens)


@command("size")
def size(m: Vector | Module) -> int:
    return len(m.terms()) if isinstance(m, Vector) else len(m.nonzero())


@command("std")
def std(m: Module) -> Module:
    """std(M): a standard basis of the module M for the ring's module ordering, sorted by increasing
    leading term (for a global ordering the reduced basis; for a local one Lazard's method).

    Example:
      ring r = 0,(x,y),(c,dp);
      module M = [x,y], [y,0], [0,x2];
      std(M);
      → _[1]=[0,x2]
      → _[2]=[y]
      → _[3]=[x,y]
    """
    out = _module(m.ring, _basis(m.ring, m.rank, _vecs(m)), m.rank, True)
    out.weights = m.weights  # as Singular: the components' weights stay
    return out


def _reduce_vec(ctx: Any, v: Vector, m: Module) -> Vector:
    key = kernel_key(m.ring)
    if not m.ring.order.is_global:  # Mora's normal form (over a qring, the quotient's columns as divisors)
        gens = [g for g in _vecs(m) if g] + q_columns(m.ring, max(m.rank, v.nrows))
        return Vector.from_terms(m.ring, mora_normal_form(v.terms(), gens, key))
    gb = km.ModuleGB(m.ring, m.rank, key=key)
    extra = q_columns(m.ring, max(m.rank, v.nrows))
    gb._set_basis([g for g in _vecs(m) if g] + extra, [lead_term(g) for g in m.nonzero()]
                  + [max(g, key=key) for g in extra])
    return Vector.from_terms(m.ring, gb.reduce(v.terms()))


@command("reduce")
def reduce(ctx, f: Vector | Module | Poly | Ideal, m: Module) -> Vector | Module:
    """reduce(v, M): the normal form of the vector v (each generator of a module) by the standard
    basis M (a warning when M is not marked as one); over a qring by M and the quotient's ideal; in a
    local or mixed ordering Mora's normal form (no tail reduced, as Singular's)."""
    if not m.is_std and len(m.nonzero()) > 1:  # as Singular: one generator is a standard basis
        ctx.warn(f"{ctx.argnames[1] if len(ctx.argnames) > 1 else '_'} is no standard basis")
    if isinstance(f, (Poly, Ideal)):
        f = to_vector(f, m.ring) if isinstance(f, Poly) else to_module(f, m.ring)
    if isinstance(f, Vector):
        return _reduce_vec(ctx, f, m)
    return Module(m.ring, [_reduce_vec(ctx, g, m) for g in f.gens], f.rank)


command("NF")(reduce)


@command("reduce")
def reduce_by_ideal(ctx, f: Vector | Module, i: Ideal) -> Vector | Module:
    """reduce(v, I): the normal form of a vector (each generator of a module) by the submodule I*R^n
    (n: the vector's rank), as in Singular; a standard basis I gives one of I*R^n."""
    n = max(1, f.nrows if isinstance(f, Vector) else f.rank)
    gens = [{(e, k): c for (e, _), c in g.items()} for g in _vecs(to_module(i, i.ring)) for k in range(n)]
    return reduce(ctx, f, _module(i.ring, gens, n, i.is_std or len(i.gens) == 1))


command("NF")(reduce_by_ideal)


@command("syz")
def syz(M: Ideal | Module) -> Module:
    """syz(M): the module of syzygies of the generators of M (a standard basis of it).

    Example:
      ring r = 0,(x,y),dp;
      syz(ideal(x, y));
      → _[1]=x*gen(2)-y*gen(1)
    """
    m = M if isinstance(M, Module) else to_module(M, M.ring)
    ring = m.ring
    n = len(m.gens)
    rel = km.syzygies(global_twin(ring), m.rank, _vecs(m) + q_columns(ring, m.rank))
    rel = [{t: c for t, c in r.items() if t[1] < n} for r in rel]
    basis = _basis(ring, n, rel)
    out = _module(ring, basis, len(m.gens), True)
    if isinstance(M, Ideal):  # as Singular: a homogeneous ideal's syzygies have its degrees as weights
        out.weights = _generator_degrees(ring, M)
    return out


def _generator_degrees(ring: PolyRing, I: Ideal) -> Optional[tuple[int, ...]]:
    """The (weighted) degrees of I's generators when each is homogeneous and none is zero, else None."""
    from .polynomials import _ring_weights
    ws = _ring_weights(ring) or [1] * ring.nvars
    degrees = []
    for g in I.gens:
        found = {sum(a * w for a, w in zip(e, ws)) for e in g.terms}
        if len(found) != 1:
            return None
        degrees.append(found.pop())
    return tuple(degrees)


def _lift_std(ring: PolyRing, m: Module) -> tuple[list[dict], list[dict], list[dict]]:
    """A standard basis of m, for each element its coefficients in m's generators, and the syzygies
    of m's generators (a standard basis of them)."""
    key, r, k = kernel_key(ring), m.rank, len(m.gens)
    gb = km.ModuleGB(ring, r + k, elim=r, key=lambda t: key(t) if t[1] < r else (t[1], key((t[0], 0))))
    zero = km.ring_zero_exp(ring)
    gb.add([{**g, (zero, r + j): ring.field.one} for j, g in enumerate(_vecs(m))])
    pairs, syz = [], []
    for g in gb.basis:
        part = {t: c for t, c in g.items() if t[1] < r}
        rest = {(e, i - r): c for (e, i), c in g.items() if i >= r}
        if not part:
            syz.append(rest)
            continue
        lead = max(part, key=key)
        scaled = _normalized(ring, part, lead)
        s = scaled[lead] / part[lead]
        pairs.append((lead, scaled, {t: c * s for t, c in rest.items()}))
    pairs.sort(key=lambda p: key(p[0]))
    return [p[1] for p in pairs], [p[2] for p in pairs], _basis(ring, k, syz)


@command("liftstd", raw=True)
def liftstd(ctx, m_node: A.Expr, t_node: A.Expr, *rest: A.Expr) -> Ideal | Module:
    """liftstd(M, T): a standard basis S of M, setting the matrix T with matrix(S) = matrix(M)*T;
    liftstd(M, T, U) also sets the module U of the syzygies of M's generators (a string argument, the
    algorithm, is ignored); with a last argument N, a module, a standard basis S of M + N with
    matrix(S) = matrix(M)*T modulo N, and U the syzygies of M's generators modulo N.

    Example:
      ring r = 0,(x,y),dp;
      matrix T;
      ideal S = liftstd(ideal(x2-y, xy), T);
      S;
      → S[1]=y2
      → S[2]=xy
      → S[3]=x2-y
      print(matrix(S) - matrix(ideal(x2-y, xy))*T);
      → 0,0,0
    """
    kinds = tuple(isinstance(r, A.StrLit) for r in rest)
    relative = kinds in ((False, False), (True, False), (False, True, False))  # a last module N
    if relative:
        kinds, n_node, rest = kinds[:-1], rest[-1], rest[:-1]
    if kinds not in ((), (False,), (True,), (False, True)):
        raise MechRuntimeError("liftstd takes (M, T), (M, T, S), (M, T, alg) or (M, T, S, alg), then maybe a module N")
    v = ctx.eval(m_node)
    ring = ctx.basering().poly
    m = to_module(v, ring)
    _global(ring, "liftstd")
    k = len(m.gens)
    if relative:  # a standard basis of M + N, T with M*T = it modulo N, S the syzygies of M modulo N
        n = to_module(ctx.eval(n_node), ring)
        basis, coeffs, syz = _lift_std(ring, Module(ring, list(m.gens) + list(n.gens), max(m.rank, n.rank)))
        coeffs = [{t: c for t, c in cf.items() if t[1] < k} for cf in coeffs]
        syz = _basis(ring, k, [{t: c for t, c in s.items() if t[1] < k} for s in syz])
    else:
        basis, coeffs, syz = _lift_std(ring, m)
    cols = [Vector.from_terms(ring, c).padded(k) for c in coeffs] or [[ring.zero()] * k]
    ctx.assign(t_node, Matrix(ring, k, len(cols), [cols[j][i] for i in range(k) for j in range(len(cols))]))
    if rest and not isinstance(rest[0], A.StrLit):
        ctx.assign(rest[0], _module(ring, syz, k, True))
    if isinstance(v, Module):
        return _module(ring, basis, m.rank, True)
    return Ideal(ring, [Vector.from_terms(ring, b).get(1) for b in basis], is_std=True)


@command("modulo")
def modulo(h1: Ideal | Module, h2: Ideal | Module) -> Module:
    """modulo(h1, h2): generators of the kernel of R^k -> R^n/<h2> sending e_i to the i-th generator
    of h1 (the c with h1*c in h2; over a qring R/Q in h2 + Q*R^n), a standard basis of it.

    Example:
      ring r = 0,(x,y),dp;
      modulo(ideal(x), ideal(x2, y));
      → _[1]=y*gen(1)
      → _[2]=x*gen(1)
    """
    ring = h1.ring
    a = h1 if isinstance(h1, Module) else to_module(h1, ring)
    b = h2 if isinstance(h2, Module) else to_module(h2, ring)
    rank, k = max(a.rank, b.rank), len(a.gens)
    rel = km.syzygies(global_twin(ring), rank, _vecs(a) + _vecs(b) + q_columns(ring, rank))
    kept = [{t: c for t, c in s.items() if t[1] < k} for s in rel]
    return _module(ring, _basis(ring, k, kept), k, True)


@command("modulo")
def modulo_lifting(ctx, h1: Ideal | Module, h2: Ideal | Module, T: Matrix, alg: str = "std") -> Module:
    """modulo(h1, h2, T, alg): modulo(h1, h2), setting the matrix variable T as liftstd(h1, T, h2) does
    (a standard basis of h1 + h2 equals h1*T modulo h2); the algorithm is ignored."""
    ring = h1.ring
    a, b = to_module(h1, ring), to_module(h2, ring)
    _global(ring, "modulo")
    k = len(a.gens)
    _, coeffs, _ = _lift_std(ring, Module(ring, list(a.gens) + list(b.gens), max(a.rank, b.rank)))
    cols = [Vector.from_terms(ring, {t: c for t, c in cf.items() if t[1] < k}).padded(k) for cf in coeffs] \
        or [[ring.zero()] * k]
    _set_output(ctx, 2, Matrix(ring, k, len(cols), [cols[j][i] for i in range(k) for j in range(len(cols))]))
    return modulo(h1, h2)


def _set_output(ctx: Any, k: int, value: Any) -> None:
    """Store ``value`` in the variable given as argument k (an output argument, as Singular's)."""
    name = ctx.argnames[k] if len(ctx.argnames) > k else "_"
    if name == "_" or ctx.lookup(name) is None:
        raise MechRuntimeError(f"argument {k + 1} must be a variable (it receives a matrix)")
    ctx.assign(A.Name(name), value)


@command("id2mod", lib="polylib.lib")
def id2mod(I: Ideal, vpos: IntVec | int) -> Module:
    """id2mod(I, vpos): the module whose i-th component is the coefficient of var(vpos[i]) in each
    generator (without the variables var(vpos[j])): mod2id's inverse (polylib.lib).

    Example:
      LIB "polylib.lib";
      ring r = 0,(e(1),e(2),x,y,z),(dp(2),ds(3));
      ideal i = e(2)^2, e(1)*e(2), e(1)^2, e(1)*y+e(2)*x;
      id2mod(i, intvec(2,1));
      → _[1]=x*gen(1)+y*gen(2)
    """
    ring = I.ring
    pos = [vpos] if isinstance(vpos, int) else list(vpos.values)
    idx = [p - 1 for p in pos]
    cols = []
    for g in I.gens:
        ents = []
        for j in idx:
            d = {}
            for e, c in g.terms.items():
                if e[j] == 1 and all(e[i] == 0 for i in idx if i != j):
                    d[e[:j] + (0,) + e[j + 1:]] = c
            ents.append(Poly(ring, d))
        cols.append(Vector(ring, ents))
    kept: list[Vector] = []
    for v in cols:  # Singular's simplify(., 10): no zero generators, no scalar multiples of earlier ones
        if v.is_zero() or any(_multiple(v, w) for w in kept):
            continue
        kept.append(v)
    return Module(ring, kept, len(pos))


def _multiple(v: Vector, w: Vector) -> bool:
    tv, tw = v.terms(), w.terms()
    if tv.keys() != tw.keys():
        return False
    t = next(iter(tv))
    q = tv[t] / tw[t]
    return all(tv[s] == q * tw[s] for s in tv)


@command("mod2id", lib="polylib.lib")
def mod2id(ctx, M: Module | Matrix | Vector, vpos: IntVec | int) -> Ideal:
    """mod2id(M, vpos): the ideal of the products var(vpos[i])*var(vpos[j]) and, for each column of
    M, the sum of its entries times var(vpos[i]) (polylib.lib).

    Example:
      LIB "polylib.lib";
      ring r = 0,(e(1),e(2),x,y,z),(dp(2),ds(3));
      module m = x*gen(1)+y*gen(2);
      mod2id(m, intvec(2,1));
      → _[1]=e(2)^2
      → _[2]=e(1)*e(2)
      → _[3]=e(1)^2
      → _[4]=e(1)*y+e(2)*x
    """
    ring = ctx.basering().poly
    pos = [vpos] if isinstance(vpos, int) else list(vpos.values)
    A = to_matrix(M, ring)
    xs = [ring.gen(p - 1) for p in pos]
    from ..dsl.ops import power
    squares = list(power(Ideal(ring, xs), 2).gens)
    cols = [sum((xs[i] * A.get(i + 1, j) for i in range(min(len(xs), A.nrows))), ring.zero())
            for j in range(1, A.ncols + 1)]
    return Ideal(ring, squares + cols)
