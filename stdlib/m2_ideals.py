"""Macaulay2's constructors and functions on polynomials, ideals and rings in the Macaulay2 dialect
(``dialect="m2"``): ``monomialIdeal``, ``vars``, ``genericMatrix``, ``monomialCurveIdeal``,
``trim``, ``mingens``, ``generators``, ``numcols``/``numrows``, ``support``, ``terms``, ``leadTerm``,
``leadMonomial``, ``leadCoefficient``, ``isHomogeneous``, ``homogenize``, ``substitute``, ``ring``,
ring maps (``map``, ``kernel``), ``resultant``, ``discriminant``, ``sylvesterMatrix``,
``singularLocus``."""
from __future__ import annotations

from typing import Any

from ..dsl.m2_local import in_local_rings, localized_at
from ..dsl.m2_rings import exact_over_zz
from ..dsl.errors import MechRuntimeError, MechTypeError
from ..dsl.m2_rings import (M2Ring, degree_vectors, in_quotients, is_integral, normal, quotient_ring, term_degree,
                             tower_terms)
from ..dsl.m2_values import MonomialIdeal, Opt, RingMap
from ..dsl.registry import command, operator
from ..dsl.values import ExprList, Ideal, List, Matrix, Number, Ring
from ..kernel import Block, MonomialOrder, Poly, PolyRing
from ..kernel import ideals as K
from .m2 import _first_ring, _gb, _indices, _minimal, _no_zz, _polys, _quotient_of, _trim, gens
from .m2_matrices import at_integers, sub
from .m2_ringmaps import change_of_coordinates, degree_map
from .standard import normalize


def _owner(ring: PolyRing) -> M2Ring:
    owner = getattr(ring, "owner", None)
    if owner is None:
        raise MechTypeError("expected an element of a Macaulay2 ring")
    return owner


# ---------------------------------------------------------------- constructors
@command("monomialIdeal", dialect="m2")
@in_quotients
@exact_over_zz
def monomial_ideal(ctx, *args: Any) -> MonomialIdeal:
    """monomialIdeal(m1, m2, ...) (a list or matrix too): the monomial ideal of their lead
    monomials; monomialIdeal I: of the lead monomials of a Gröbner basis of I (over ZZ: a strong
    one); on its minimal generators."""
    ring = _first_ring(args) or ctx.basering().poly
    items = args
    if len(args) == 1 and isinstance(args[0], Ideal) and not isinstance(args[0], MonomialIdeal):
        I = args[0]
        if is_integral(I.ring):  # the lead monomials of a strong Gröbner basis over ZZ
            from ..kernel.zz_groebner import strong_basis
            items = tuple(strong_basis(list(I.nonzero()), I.ring))
        else:
            items = _gb(I).gens
    monos = {p.lm() for p in _polys(ctx, tuple(items), ring) if not p.is_zero()}
    minimal = [m for m in monos if not any(o != m and all(a <= b for a, b in zip(o, m)) for o in monos)]
    return MonomialIdeal(ring, [ring.monomial(m) for m in sorted(minimal, reverse=True)])


@command("vars", dialect="m2")
@in_quotients
@exact_over_zz
def vars_(R: Ring | int | List | ExprList) -> Any:
    """vars R: the one-row matrix of R's variables; vars n, vars(0..3), vars(0..2, 7): Macaulay2's
    symbols number n (a..z, A..Z, then x0, x1, ...; X1, X2, ... for -1, -2, ...), values of the
    variables where a ring has them."""
    if not isinstance(R, Ring):
        from ..dsl.m2_values import Symbol

        def flat(v: Any) -> list:
            return [x for y in v.items for x in flat(y)] if isinstance(v, (List, ExprList)) else [v]
        out = []
        for n in flat(R):
            if type(n) is not int:
                raise MechRuntimeError("vars(n) takes integers n")
            out.append(Symbol(f"X{-n}" if n < 0 else chr(97 + n) if n < 26 else chr(65 + n - 26) if n < 52
                              else f"x{n - 52}"))
        return out[0] if type(R) is int else type(R)(out) if isinstance(R, List) else ExprList(out)
    xs = gens(R).items
    return Matrix(R.poly, 1, len(xs), xs)


@command("genericMatrix", dialect="m2")
@in_quotients
@exact_over_zz
def generic_matrix(R: Ring, first: Poly | int, m: int, n: int | None = None) -> Matrix:
    """genericMatrix(R, x, m, n): the m x n matrix of R's variables from x on, filled by columns
    (genericMatrix(R, m, n): from the first variable)."""
    if n is None:
        first, m, n = R.poly.gen(0), first, m
    start = _indices(R.poly, first)[0]
    if start + m * n > R.poly.nvars:
        raise MechRuntimeError(f"genericMatrix: the ring has too few variables for a {m} x {n} matrix")
    cols = [[R.poly.gen(start + j * m + i) for i in range(m)] for j in range(n)]
    return Matrix(R.poly, m, n, [cols[j][i] for i in range(m) for j in range(n)])


@command("genericSymmetricMatrix", dialect="m2")
@in_quotients
def generic_symmetric_matrix(R: Ring, first: Poly | int, n: int | None = None) -> Matrix:
    """genericSymmetricMatrix(R, x, n): the symmetric n x n matrix whose upper triangle, row by row,
    holds R's variables from x on (genericSymmetricMatrix(R, n): from the first variable)."""
    if n is None:
        first, n = R.poly.gen(0), first
    start = _indices(R.poly, first)[0]
    if start + n * (n + 1) // 2 > R.poly.nvars:
        raise MechRuntimeError(f"genericSymmetricMatrix: the ring has too few variables for a {n} x {n} matrix")
    upper = {}
    k = start
    for i in range(n):
        for j in range(i, n):
            upper[i, j] = upper[j, i] = R.poly.gen(k)
            k += 1
    return Matrix(R.poly, n, n, [upper[i, j] for i in range(n) for j in range(n)])


@command("monomialCurveIdeal", dialect="m2")
def monomial_curve_ideal(R: Ring, exps: List) -> Ideal:
    """monomialCurveIdeal(R, {a1, ..., ak}): the ideal of the curve s^d, s^(d-a1)t^a1, ..., t^d
    (d the largest a_i) in R's first k+1 variables."""
    a = list(exps.items)
    if not a or not all(type(x) is int and x > 0 for x in a) or len(a) + 1 > R.poly.nvars:
        raise MechRuntimeError("monomialCurveIdeal(R, {a1,...,ak}) takes positive exponents and k+1 variables of R")
    d = max(a)
    ring = R.poly
    n = ring.nvars
    big = PolyRing(ring.field, ["_s", "_t"] + list(ring.names), MonomialOrder([Block("dp", n + 2)], n + 2))
    s, t = big.gen(0), big.gen(1)
    params = [s ** d] + [s ** (d - ai) * t ** ai for ai in a]
    rel = [big.gen(2 + i) - p for i, p in enumerate(params)]
    kept = K.eliminate(rel, [0, 1], ring=big)
    polys = [Poly(ring, {e[2:]: c for e, c in p.terms.items()}) for p in kept]
    I = Ideal(ring, polys)
    return _minimal(I, sorted(polys, key=lambda p: ring.order.key(p.lm())))


# ---------------------------------------------------------------- generators
@command("trim", dialect="m2")
@in_quotients
@exact_over_zz
@in_local_rings
def trim(I: Ideal) -> Ideal:
    """trim I: I on fewer generators, as Macaulay2 trims: the generators (normalized) by increasing
    lead monomial, each kept unless it lies in the ideal of those kept before it (in a local ring
    R_P: a minimal generating set of I R_P among I's generators)."""
    if localized_at(I.ring) is not None:
        from .m2_local import local_mingens
        return Ideal(I.ring, local_mingens(I))
    return _trim(I)


@command("generator", dialect="m2")
@in_quotients
@exact_over_zz
def generator(I: Ideal) -> Poly:
    """generator I: the one generator of a principal ideal (of trim I; 0 for the zero ideal)."""
    gens = trim(I).nonzero()
    if len(gens) > 1:
        raise MechRuntimeError("generator I: the ideal is not generated by one element")
    return gens[0] if gens else I.ring.zero()


@command("mingens", dialect="m2")
@in_quotients
@exact_over_zz
@in_local_rings
def mingens(I: Ideal) -> Matrix:
    """mingens I: the matrix of trim I's generators."""
    J = trim(I)
    return Matrix(I.ring, 1, len(J.gens), list(J.gens))


@command("generators", dialect="m2")
@in_quotients
@exact_over_zz
def generators(ctx, I: Ideal | Ring) -> Any:
    """generators I (gens I): the matrix of I's generators; generators R: R's variables
    (CoefficientRing => QQ or ZZ/p: with those of the rings below, down to it)."""
    base = ctx.m2_options.get("CoefficientRing")
    if isinstance(I, Ring) and base is not None:
        owner = getattr(I.poly, "owner", None)
        if owner is None or getattr(base, "characteristic", -1) != getattr(owner.coeffs, "characteristic", -2):
            raise MechRuntimeError("generators(R, CoefficientRing => K) takes the field at the bottom of R")
        return List([normal(I.poly.gen(i)) for i in range(I.poly.nvars)])
    return gens(I)


generators.m2_options = ("CoefficientRing",)


@command("numgens", dialect="m2")
@in_quotients
@exact_over_zz
def numgens_ring(R: Ring) -> int:
    """numgens R: the number of R's variables."""
    return len(gens(R).items)


@command("numcols", dialect="m2")
@in_quotients
@exact_over_zz
@in_local_rings
def numcols(M: Matrix) -> int:
    """numcols M: the number of columns."""
    return M.ncols


@command("numrows", dialect="m2")
@in_quotients
@exact_over_zz
@in_local_rings
def numrows(M: Matrix) -> int:
    """numrows M: the number of rows."""
    return M.nrows


# ---------------------------------------------------------------- polynomials
@command("support", dialect="m2")
@in_quotients
@exact_over_zz
def support(f: Poly | Ideal) -> List:
    """support f: the variables f involves, in the ring's order of variables."""
    polys = f.gens if isinstance(f, Ideal) else [f]
    used = sorted({i for p in polys for e in p.terms for i, k in enumerate(e) if k})
    ring = f.ring
    return List([ring.gen(i) for i in used])


@command("terms", dialect="m2")
@in_quotients
@exact_over_zz
def terms(f: Poly) -> List:
    """terms f: f's terms, from the largest down (in a tower A[x]: monomials in x times elements of A)."""
    split = tower_terms(f)
    if split is not None:
        return List([_tower_term(f.ring, e, c) for e, c in split])
    return List([f.ring.monomial(e, c) for e, c in f.sorted_terms()])


@command("terms", dialect="m2")
@in_quotients
@exact_over_zz
def terms_over(k: Any, f: Poly) -> List:
    """terms(k, f): f's terms with k (a ring f's ring is built on) as the coefficient ring."""
    below = k.poly.nvars if isinstance(k, M2Ring) else 0
    if isinstance(k, M2Ring) and (k.poly.names != f.ring.names[f.ring.nvars - below:]):
        raise MechRuntimeError("terms(k, f): f's ring is not built on k")
    own = f.ring.nvars - below
    groups: dict[tuple[int, ...], dict] = {}
    for e, c in f.sorted_terms():
        groups.setdefault(e[:own], {})[e[own:]] = c
    return List([Poly(f.ring, {e + k2: c for k2, c in sub.items()}) for e, sub in groups.items()])


def _tower_term(ring: PolyRing, e: tuple[int, ...], c: Poly) -> Poly:
    """The term ``c * x^e`` of a tower (``c`` in its coefficient ring)."""
    return Poly(ring, {e + k: v for k, v in c.terms.items()})


@command("leadTerm", dialect="m2")
@in_quotients
@exact_over_zz
def lead_term(f: Poly | Ideal | Matrix) -> Any:
    """leadTerm f: the largest term (in a tower A[x]: with its whole coefficient in A); leadTerm I:
    the matrix of the lead terms of a Gröbner basis; leadTerm M (one row): the lead term of each entry."""
    if isinstance(f, Matrix):
        if f.nrows != 1:
            raise MechRuntimeError("leadTerm of a matrix with several rows (module elements) is not supported")
        return Matrix(f.ring, 1, f.ncols, [lead_term(g) for g in f.entries])
    if isinstance(f, Ideal):
        _no_zz(f, "leadTerm")
        lts = [lead_term(g) for g in _gb(f).gens]
        return Matrix(f.ring, 1, len(lts), lts)
    if f.is_zero():
        return f
    split = tower_terms(f)
    return _tower_term(f.ring, *split[0]) if split is not None else f.lt()


@command("leadMonomial", dialect="m2")
@in_quotients
@exact_over_zz
def lead_monomial(f: Poly) -> Poly:
    """leadMonomial f: the largest monomial (without its coefficient; in a tower A[x]: a monomial in x)."""
    if f.is_zero():
        raise MechRuntimeError("leadMonomial of 0")
    split = tower_terms(f)
    if split is not None:
        return f.ring.monomial(split[0][0] + (0,) * (f.ring.nvars - len(split[0][0])))
    return f.ring.monomial(f.lm())


@command("leadCoefficient", dialect="m2")
@in_quotients
@exact_over_zz
def lead_coefficient(f: Poly) -> Any:
    """leadCoefficient f: the coefficient of the largest term (in a tower A[x]: an element of A)."""
    if f.is_zero():
        return 0
    split = tower_terms(f)
    if split is not None:
        return split[0][1]
    return Number(f.ring, f.lc())


@command("degree", dialect="m2")
@in_quotients
@exact_over_zz
def degree_in(x: Poly, f: Poly) -> int:
    """degree(x, f): the largest power of the variable x in f."""
    i = _indices(f.ring, x)[0]
    if f.is_zero():
        raise MechRuntimeError("degree of the zero polynomial: -infinity (not a value of mech)")
    return max(e[i] for e in f.terms)


@command("degrees", dialect="m2")
@in_quotients
@exact_over_zz
def degrees(R: Ring) -> List:
    """degrees R: the degree (a list) of each of R's own variables."""
    vecs = degree_vectors(_owner(R.poly))[:len(R.own) or None]
    return List([List(list(v)) for v in vecs])


@command("isHomogeneous", dialect="m2")
@in_quotients
@exact_over_zz
def is_homogeneous(f: Poly | Ideal) -> bool:
    """isHomogeneous f: whether f (every generator of I) is homogeneous for the ring's degrees."""
    vecs = degree_vectors(_owner(f.ring))
    polys = f.gens if isinstance(f, Ideal) else [f]
    return all(len({term_degree(e, vecs) for e in p.terms}) <= 1 for p in polys)


def _homogenize(p: Poly, i: int, degs: tuple) -> Poly:
    if p.is_zero():
        return p
    weight = [sum(d * k for d, k in zip(degs, e)) for e in p.terms]
    top = max(weight)
    out = {}
    for (e, c), w in zip(p.terms.items(), weight):
        if (top - w) % degs[i]:
            raise MechRuntimeError("homogenize: the degrees do not allow it")
        e2 = list(e)
        e2[i] += (top - w) // degs[i]
        out[tuple(e2)] = c
    return Poly(p.ring, out)


@command("homogenize", dialect="m2")
@in_quotients
@exact_over_zz
def homogenize(f: Poly | Ideal | Matrix, v: Poly) -> Any:
    """homogenize(f, v): f made homogeneous with the variable v (in R/Q: its normal form, the result
    reduced); homogenize(I, v): the ideal of the homogenized Gröbner basis (a degree order: I's
    homogenization)."""
    i = _indices(f.ring, v)[0]
    degs = _owner(f.ring).degrees or (1,) * f.ring.nvars
    if isinstance(f, Poly):
        return normal(_homogenize(f, i, degs))
    if isinstance(f, Matrix):
        return Matrix(f.ring, f.nrows, f.ncols, [normal(_homogenize(p, i, degs)) for p in f.entries])
    if _quotient_of(f.ring) is not None:
        raise MechRuntimeError("homogenize of an ideal of a quotient ring R/I is not supported by mech")
    _no_zz(f, "homogenize")
    order = f.ring.order
    if not order.is_global or any(b.kind not in ("dp", "Dp", "wp", "Wp") for b in order.blocks) or len(order.blocks) != 1:
        raise MechRuntimeError("homogenize of an ideal needs a ring with a degree order (GRevLex, GLex)")
    hom = [normalize(_homogenize(p, i, degs)) for p in _gb(f).gens]
    return _minimal(f, sorted(hom, key=lambda p: f.ring.order.key(p.lm())))


@command("substitute", dialect="m2")
@in_quotients
@exact_over_zz
def substitute(ctx, f: Poly | Ideal | Matrix, where: List | Ring | Matrix) -> Any:
    """substitute(f, {x => a, ...}), substitute(f, S): as sub; substitute(f, matrix {{a, b, ...}}):
    the variables replaced by a, b, ..."""
    if isinstance(where, Matrix):
        from ..dsl.maps import map_value
        if _quotient_of(f.ring) is not None or _quotient_of(where.ring) is not None:
            raise MechRuntimeError("substitute(f, M) in quotient rings is not supported by mech")
        if where.nrows != 1 or where.ncols != f.ring.nvars:
            raise MechRuntimeError(f"substitute(f, M): M is one row of {f.ring.nvars} entries")
        if f.ring.field.characteristic and all(p.is_constant() for p in where.entries):
            if not isinstance(f, Poly):
                raise MechRuntimeError("substitute(I, matrix of integers) over ZZ/p is not supported by mech")
            return at_integers(f, [int(p.terms.get((), 0)) for p in where.entries])
        return map_value(f, list(where.entries), where.ring)
    return sub(ctx, f, where)


@command("ring", dialect="m2")
@in_quotients
@exact_over_zz
@in_local_rings
def ring(x: Poly | Ideal | Matrix | Number) -> Ring:
    """ring x: the ring of x."""
    return _owner(x.ring)


# ---------------------------------------------------------------- ring maps
@command("map", dialect="m2")
@in_quotients
@exact_over_zz
def map_(ctx, target: Ring, source: Ring, images: List | Matrix | None = None) -> RingMap:
    """map(S, R, {a, b, ...}): the ring map R -> S sending R's variables to a, b, ... (a tower R
    given images of its own variables only: its coefficient variables to themselves); map(S, R):
    variables to the variables of the same names (others to 0); map(S, R, m) for a matrix of
    numbers: the linear change of coordinates (vars S) * m."""
    n = source.poly.nvars
    opts = isinstance(images, List) and images.items and all(isinstance(x, Opt) for x in images.items)
    if images is None or opts:  # variables to those of the same names (others to 0); {x => f, ...}: x to f
        ims = [target.poly.gen(target.poly.names.index(x)) if x in target.poly.names else target.poly.zero()
               for x in source.poly.names]
        for o in images.items if opts else ():
            key = o.key
            if not (isinstance(key, Poly) and len(key.terms) == 1 and sum(key.lm()) == 1
                    and key.ring.names == source.poly.names):
                raise MechRuntimeError("map(S, R, {x => f, ...}) takes variables x of R")
            ims[key.lm().index(1)] = _polys(ctx, (o.value,), target.poly)[0]
    elif isinstance(images, Matrix) and images.nrows > 1 and all(p.is_zero() or not any(p.lm()) for p in images.entries):
        ims = change_of_coordinates(target, images, n)
    else:
        ims = _polys(ctx, (images,), target.poly)
        own = getattr(getattr(source.poly, "owner", None), "own", ())
        if len(ims) == len(own) < n and source.poly.names[len(own):] == target.poly.names[len(target.poly.names) - n + len(own):]:
            ims += [target.poly.gen(target.poly.names.index(x)) for x in source.poly.names[len(own):]]  # a tower's
            # coefficient variables: to themselves
        if len(ims) != n:
            raise MechRuntimeError(f"map(S, R, {{...}}) takes {n} images (one per variable of R)")
    return RingMap(target, source, tuple(normal(p) for p in ims), degree_map(ctx))


map_.m2_options = ("DegreeMap",)


@command("map", dialect="m2")
@in_quotients
def map_from_matrix(source: Ring, images: Matrix) -> RingMap:
    """map(R, m): the ring map from R to the ring of the one-row matrix m, R's variables to its entries."""
    target = _owner(images.ring)
    if images.nrows != 1 or images.ncols != source.poly.nvars:
        raise MechRuntimeError(f"map(R, m) takes a matrix of one row of {source.poly.nvars} entries")
    return RingMap(target, source, tuple(normal(p) for p in images.entries))


@command("id", dialect="m2")
@in_quotients
def identity_map(R: M2Ring) -> RingMap:
    """id_R: the identity map of the ring R."""
    return RingMap(R, R, tuple(normal(R.poly.gen(i)) for i in range(R.poly.nvars)))


identity_map.subscript_value = True


@operator("*", dialect="m2")
def compose(g: Any, f: Any) -> Any:
    """``g * f`` for ring maps R -> S -> T: the composite R -> T (x to g(f(x)))."""
    if not (isinstance(g, RingMap) and isinstance(f, RingMap)):
        return NotImplemented
    if f.target is not g.source:
        raise MechTypeError("g * f: f's target is not g's source")
    from ..dsl.m2_maps import apply_map
    return RingMap(g.target, f.source, tuple(apply_map(g, p) for p in f.images))


@command("kernel", dialect="m2")
@command("ker", dialect="m2")
def kernel(f: RingMap) -> Ideal:
    """kernel f (ker f): the ideal of the source mapped to 0."""
    return _preimage(f, [])


@command("preimage", dialect="m2")
@in_quotients
def preimage(f: RingMap, J: Ideal) -> Ideal:
    """preimage(f, J): the ideal of the source mapped into the ideal J of the target."""
    if J.ring is not f.target.poly:
        raise MechTypeError("preimage(f, J): J is an ideal of f's target")
    return _preimage(f, J.nonzero())


@command("isInjective", dialect="m2")
@in_quotients
def is_injective(f: RingMap) -> bool:
    """isInjective f: whether the ring map's kernel is zero."""
    return not _preimage(f, []).nonzero()


@command("coimage", dialect="m2")
@in_quotients
def coimage(f: RingMap) -> M2Ring:
    """coimage f: the source modulo the kernel (the source itself when f is injective)."""
    ker = _preimage(f, []).nonzero()
    return quotient_ring(f.source, ker) if ker else f.source


def _preimage(f: RingMap, extra: list[Poly]) -> Ideal:
    """The ideal of the source mapped into the ideal of ``extra`` (and the target's relations)."""
    R, S = f.source, f.target
    if R.quotient is not None:
        raise MechRuntimeError("kernel of a map from a quotient ring is not supported by mech")
    m, n = S.poly.nvars, R.poly.nvars
    names = [f"_t{i}" for i in range(m)] + list(R.poly.names)
    big = PolyRing(S.poly.field, names, MonomialOrder([Block("dp", m + n)], m + n))

    def up(p: Poly, shift: int) -> Poly:
        return Poly(big, {(0,) * shift + e + (0,) * (m + n - shift - len(e)): c for e, c in p.terms.items()})
    rel = [up(R.poly.gen(i), m) - up(img, 0) for i, img in enumerate(f.images)]
    rel += [up(q, 0) for q in list(S.quotient.basis if S.quotient is not None else []) + list(extra)]
    kept = K.eliminate(rel, list(range(m)), ring=big)
    polys = [Poly(R.poly, {e[m:]: c for e, c in p.terms.items()}) for p in kept]
    I = Ideal(R.poly, polys)
    return _minimal(I, sorted(polys, key=lambda p: R.poly.order.key(p.lm())))


# ---------------------------------------------------------------- eliminants
def _sylvester(f: Poly, g: Poly, i: int) -> list[list[Poly]]:
    ring = f.ring

    def coeffs(p: Poly) -> list[Poly]:
        d = p.degree_in(i)
        out = [ring.zero() for _ in range(d + 1)]
        for e, c in p.terms.items():
            e2 = list(e)
            k = e2[i]
            e2[i] = 0
            out[d - k] = out[d - k] + ring.monomial(tuple(e2), c)
        return out
    a, b = coeffs(f), coeffs(g)
    m, n = len(a) - 1, len(b) - 1
    size = m + n
    rows = [[ring.zero()] * k + a + [ring.zero()] * (size - m - 1 - k) for k in range(n)]
    rows += [[ring.zero()] * k + b + [ring.zero()] * (size - n - 1 - k) for k in range(m)]
    return rows


@command("sylvesterMatrix", dialect="m2")
@exact_over_zz
def sylvester_matrix(f: Poly, g: Poly, x: Poly) -> Matrix:
    """sylvesterMatrix(f, g, x): the Sylvester matrix of f and g in the variable x."""
    rows = _sylvester(f, g, _indices(f.ring, x)[0])
    if not rows:
        raise MechRuntimeError("sylvesterMatrix: f and g need a positive degree in x together")
    return Matrix(f.ring, len(rows), len(rows), [p for r in rows for p in r])


@command("resultant", dialect="m2")
@exact_over_zz
def resultant(f: Poly, g: Poly, x: Poly) -> Poly:
    """resultant(f, g, x): the resultant of f and g in the variable x."""
    from ..kernel import matrix as KM
    rows = _sylvester(f, g, _indices(f.ring, x)[0])
    if not rows:
        return f.ring.one()
    return KM.det(KM.Matrix(f.ring, len(rows), len(rows), [p for r in rows for p in r]))


@command("discriminant", dialect="m2")
@exact_over_zz
def discriminant(f: Poly, x: Poly) -> Poly:
    """discriminant(f, x): resultant(f, f', x) divided by f's lead coefficient in x (Macaulay2's sign)."""
    i = _indices(f.ring, x)[0]
    n = f.degree_in(i)
    if n < 1:
        raise MechRuntimeError("discriminant: f needs a positive degree in x")
    r = resultant(f, f.diff(i), x)
    lead = f.ring.zero()
    for e, c in f.terms.items():
        if e[i] == n:
            e2 = list(e)
            e2[i] = 0
            lead = lead + f.ring.monomial(tuple(e2), c)
    from ..kernel.factor import divide_exact
    return divide_exact(r, lead)


@command("singularLocus", dialect="m2")
@in_quotients
def singular_locus(I: Ideal | Ring) -> Ring:
    """singularLocus I (or R/I): the ring R/(I + the codim-sized minors of I's Jacobian)."""
    from ..kernel import matrix as KM
    from itertools import combinations
    if isinstance(I, Ring):
        if I.parent is None:
            raise MechRuntimeError("singularLocus R takes a quotient ring R/I")
        from .m2_quotients import ring_presentation
        P = ring_presentation(I)  # R/I/J: all the relations, in the polynomial ring
        I = Ideal(P.ring, list(P.entries))
    R = _owner(I.ring)
    if R.quotient is not None:
        raise MechRuntimeError("singularLocus of an ideal of a quotient ring is not supported by mech")
    c = R.poly.nvars - K.dimension(I.nonzero(), ring=I.ring)
    gens_ = list(I.nonzero())
    jac = [[g.diff(j) for j in range(R.poly.nvars)] for g in gens_]
    minors = []
    for rows in combinations(range(len(gens_)), c):
        for cols in combinations(range(R.poly.nvars), c):
            d = KM.det(KM.Matrix(I.ring, c, c, [jac[r][k] for r in rows for k in cols]))
            if not d.is_zero():
                minors.append(d)
    S = quotient_ring(R, gens_ + minors)
    return S


def _parts(R: M2Ring) -> list[set[int]]:
    """The variables of each part of R's monomial order (a weight row: those of nonzero weight)."""
    parts: list[set[int]] = []
    covered = 0
    for b in R.blocks:
        if b.kind in ("c", "C"):
            continue
        if b.kind == "a":
            parts.append({covered + j for j, w in enumerate(b.weights) if w})
        else:
            parts.append(set(range(covered, covered + b.size)))
            covered += b.size
    return parts


@command("selectInSubring", dialect="m2")
@in_quotients
def select_in_subring(i: int, M: Matrix) -> Matrix:
    """selectInSubring(i, M): the columns of M free of the variables of the first i parts of the
    ring's monomial order (with an elimination order: the elements of the elimination ideal)."""
    banned = set().union(*_parts(_owner(M.ring))[:i]) if i > 0 else set()
    cols = [[M.get(r, c) for r in range(1, M.nrows + 1)] for c in range(1, M.ncols + 1)]
    keep = [col for col in cols if not any(e[v] for p in col for e in p.terms for v in banned)]
    return Matrix(M.ring, M.nrows, len(keep), [keep[c][r] for r in range(M.nrows) for c in range(len(keep))])


# ---------------------------------------------------------------- rings and maps as values
@command("target", dialect="m2")
@exact_over_zz
def target(f: RingMap) -> Ring:
    """target f: the ring a map goes to."""
    return f.target


@command("source", dialect="m2")
@exact_over_zz
def source(f: RingMap) -> Ring:
    """source f: the ring a map comes from."""
    return f.source


@command("coefficientRing", dialect="m2")
@in_quotients
@exact_over_zz
def coefficient_ring(R: Ring) -> Any:
    """coefficientRing R: the ring R's variables are over (QQ, ZZ/p, or the ring below in a tower)."""
    return _owner(R.poly).ambient().base


@command("baseName", dialect="m2")
@in_quotients
@exact_over_zz
def base_name(x: Any) -> Any:
    """baseName x: the symbol of a variable (a symbol itself)."""
    from ..dsl.m2_values import Symbol
    if isinstance(x, Symbol):
        return x
    i = _indices(x.ring, x)[0]
    return Symbol(x.ring.names[i])


@command("matrix", dialect="m2")
@in_quotients
@exact_over_zz
def matrix_of_map(f: RingMap) -> Matrix:
    """matrix f: the one-row matrix of the images of the source's variables."""
    return Matrix(f.target.poly, 1, len(f.images), list(f.images))
