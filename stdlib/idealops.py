"""Singular's commands that rewrite generating sets of ideals: ``interred``, ``simplify``,
``minbase``, ``std(I, f)`` / ``std(I, J)`` (adding elements to a standard basis), the lazy
``reduce(f, I, 1)`` / ``NF(f, I, 1)``, ``indepSet``, ``preimage`` and ``unitmat`` (matrix.lib)."""
from __future__ import annotations

from itertools import combinations
from typing import Any, Optional

from ..dsl import ast as A
from ..dsl.errors import MechRuntimeError, MechTypeError
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, List, Map, Matrix, Ring
from ..kernel import Poly
from ..kernel.dimension import krull_dim
from ..kernel.ideals import _drop, _lift, _prefixed, eliminate, independent_set, move, with_order
from ..kernel.order import Block, MonomialOrder
from ..kernel.poly import divides, sub_exp
from ..kernel.engines import standard_basis as kernel_standard_basis
from .standard import _nf, normalize, standard_basis, std


# ---------------------------------------------------------------- interreduction
def _top_reduce(f: Poly, others: list[Poly]) -> Poly:
    """f with its leading term reduced by the others' as long as one divides it."""
    while not f.is_zero():
        lm = f.lm()
        for g in others:
            if divides(g.lm(), lm):
                f = f - f.ring.monomial(sub_exp(lm, g.lm()), f.lc() / g.lc()) * g
                break
        else:
            return f
    return f


@command("interred")
def interred(ctx, I: Ideal) -> Ideal:
    """interred(I): the generators of I reduced against each other until no leading monomial divides
    another (tails too with option(redSB)); zeros dropped, sorted by increasing leading monomial.
    In a local ordering a standard basis.

    Example:
      ring r = 0,(x,y,z),dp;
      interred(ideal(2x2+4y, 3x2+y, 6xy, x3+y2));
      → _[1]=y
      → _[2]=x2+2y
    """
    ring = I.ring
    if not ring.order.is_global:
        return Ideal(ring, standard_basis(I))
    key = ring.order.key
    polys = [normalize(p) for p in I.nonzero()]
    changed = True
    while changed:  # an element is reduced by the others, of equal leading monomial only by earlier ones
        changed = False
        for k, p in enumerate(polys):
            reducers = polys[:k] + [q for q in polys[k + 1:] if q.lm() != p.lm()]
            q = _top_reduce(p, reducers)
            if q is not p:
                polys = polys[:k] + [normalize(q)] * (not q.is_zero()) + polys[k + 1:]
                changed = True
                break
    polys.sort(key=lambda p: key(p.lm()))
    if "redSB" in ctx.options:
        polys = [normalize(p.lt() + _nf(p - p.lt(), polys)) for p in polys]
    return Ideal(ring, polys)


# ---------------------------------------------------------------- simplify
def _scalar_multiple(a: Any, b: Any) -> bool:
    """b = c*a for a constant c (polynomials or vectors, by their terms)."""
    ta, tb = (a.terms if isinstance(a, Poly) else a.terms()), (b.terms if isinstance(b, Poly) else b.terms())
    if ta.keys() != tb.keys():
        return False
    first = next(iter(ta))
    c = tb[first] / ta[first]
    return all(tb[t] == c * ta[t] for t in ta)


def simplify_generators(gens: list[Any], flag: int, lead: Any, lead_divides: Any, monic: Any) -> list[Any]:
    """Singular's clean-ups of a generating set (polynomials or vectors), by the bits of ``flag``: 32
    deletes generators whose leading term is divisible by another's, 16 those with the leading term of
    an earlier one, 8 scalar multiples of earlier ones, 4 copies of earlier ones (deleted generators
    become 0), 2 drops the zeros, 1 makes the leading coefficients 1; ``zero`` stands for 0."""
    g: list[Any] = list(gens)
    n = len(g)
    live = lambda k: g[k] is not None and not g[k].is_zero()  # noqa: E731
    if flag & 32:
        for i in range(n):
            if not live(i):
                continue
            for j in range(i + 1, n):
                if not live(j):
                    continue
                if lead_divides(lead(g[i]), lead(g[j])):
                    g[j] = None
                elif lead_divides(lead(g[j]), lead(g[i])):
                    g[i] = None
                    break

    def drop_later(same: Any) -> None:
        for i in range(n):
            if not live(i):
                continue
            for j in range(i + 1, n):
                if live(j) and same(g[i], g[j]):
                    g[j] = None
    if flag & 16:
        drop_later(lambda a, b: lead(a) == lead(b))
    if flag & 8:
        drop_later(_scalar_multiple)
    elif flag & 4:
        drop_later(lambda a, b: a == b)
    kept = [(k, g[k]) for k in range(n)]
    if flag & 2:
        kept = [(k, p) for k, p in kept if p is not None and not p.is_zero()]
    return [None if p is None else monic(p) if flag & 1 and not p.is_zero() else p for _, p in kept]


@command("simplify")
def simplify(f: Poly | Ideal, flag: int) -> Any:
    """simplify(I, n): Singular's clean-ups of a generating set, by the bits of n: 32 deletes
    generators whose leading monomial is divisible by another's, 16 those with the leading monomial
    of an earlier one, 8 scalar multiples of earlier ones, 4 copies of earlier ones (deleted
    generators become 0), 2 drops the zeros, 1 makes the leading coefficients 1.

    Example:
      ring r = 0,(x,y),dp;
      simplify(ideal(0, 2x, x, 3x2+y), 11);
      → _[1]=x
      → _[2]=x2+1/3y
    """
    if isinstance(f, Poly):
        return f.monic() if flag & 1 and not f.is_zero() else f
    zero = f.ring.zero()
    out = simplify_generators(list(f.gens), flag, lambda p: p.lm(), divides, lambda p: p.monic())
    return Ideal(f.ring, [zero if p is None else p for p in out] or [zero])


# ---------------------------------------------------------------- minimal generators
def _member(f: Poly, gens: list[Poly]) -> bool:
    if not gens:
        return f.is_zero()
    basis = standard_basis(Ideal(f.ring, gens))
    return _nf(f, sorted(basis, key=lambda b: f.ring.order.key(b.lm()))).is_zero()


@command("minbase")
def minbase(I: Ideal) -> Ideal:
    """minbase(I): a minimal set of generators of I, for a homogeneous ideal or in a local ordering
    (no generator lies in the ideal of the others).

    Example:
      ring r = 0,(x,y),dp;
      minbase(ideal(x2, xy, x2+xy, x3, y2));
      → _[1]=y2
      → _[2]=xy
      → _[3]=x2
    """
    ring = I.ring
    gens = I.nonzero()
    if ring.order.is_global and not all(p.is_homogeneous() for p in gens):
        raise MechRuntimeError("minbase: the ideal must be homogeneous or the ordering local")
    gens.sort(key=lambda p: p.total_degree())
    kept = list(gens)
    for p in reversed(gens):
        rest = [q for q in kept if q is not p]
        if _member(p, rest):
            kept = rest
    kept.sort(key=lambda p: ring.order.key(p.lm()))
    return Ideal(ring, kept or [ring.zero()])


@command("mstd")
def mstd(I: Ideal) -> List:
    """mstd(I): the list of a standard basis S of the homogeneous ideal I and a minimal set of
    generators of I taken from S (by increasing degree, each element of S not in the ideal of those
    kept before).

    Example:
      ring r = 0,(x,y),dp;
      mstd(ideal(x2, xy, x2+xy, x3));
      → [1]:
      →    _[1]=xy
      →    _[2]=x2
      → [2]:
      →    _[1]=xy
      →    _[2]=x2
    """
    ring = I.ring
    if not ring.order.is_global or not all(p.is_homogeneous() for p in I.nonzero()):
        raise MechRuntimeError("mstd: only homogeneous ideals in a global ordering are supported")
    S = std(I)
    kept: list[Poly] = []
    for p in sorted(S.nonzero(), key=lambda p: p.total_degree()):  # stable: S's order within a degree
        if not _member(p, kept):
            kept.append(p)
    order = {id(p): k for k, p in enumerate(S.gens)}
    kept.sort(key=lambda p: order[id(p)])
    return List([S, Ideal(ring, kept or [ring.zero()])])


# ---------------------------------------------------------------- std and reduce variants
@command("std")
def std_add(ctx, I: Ideal, f: Poly | Ideal) -> Ideal:
    """std(I, f): a standard basis of I + f for a standard basis I and a poly or ideal f.

    Example:
      ring r = 0,(x,y,z),dp;
      ideal j = std(ideal(x2-y, xy-z));
      std(j, ideal(z3-x, y3));
      → _[1]=z
      → _[2]=y
      → _[3]=x
    """
    extra = [f] if isinstance(f, Poly) else list(f.gens)
    return Ideal(I.ring, standard_basis(Ideal(I.ring, list(I.gens) + extra)), is_std=True)


def _lazy(f: Any, I: Ideal) -> Any:
    key = I.ring.order.key
    basis = sorted(I.nonzero(), key=lambda g: key(g.lm()))
    if I.ring.order.is_global:
        def red(p: Poly) -> Poly:
            return _top_reduce(p, basis)
    else:
        from ..kernel.localnf import weak_normal_form

        def red(p: Poly) -> Poly:
            return weak_normal_form(p, basis)
    if isinstance(f, Poly):
        return red(f)
    if isinstance(f, Ideal):
        return Ideal(f.ring, [red(g) for g in f.gens])
    return Matrix(f.ring, f.nrows, f.ncols, [red(g) for g in f.entries])


@command("reduce")
def reduce_lazy(ctx, f: Poly | Ideal | Matrix, I: Ideal, how: int) -> Any:
    """reduce(f, I, 1): reduce only the leading terms of f by I (no check that I is a standard basis);
    reduce(f, I, 0) is reduce(f, I).

    Example:
      ring r = 0,(x,y,z),dp;
      reduce(x3+y3+z, ideal(x2-y, xy-z), 1);
      → y3+xy+z
    """
    if how & 1:
        ctx.assume_std(I, 1)
        return _lazy(f, I)
    from .standard import _reduce
    return _reduce(ctx, f, I, bad_ecart=bool(how & 2))


@command("NF")
def NF_lazy(ctx, f: Poly | Ideal | Matrix, I: Ideal, how: int) -> Any:
    return reduce_lazy(ctx, f, I, how)


# ---------------------------------------------------------------- independent sets
def _independent(lms: list[tuple], subset: tuple[int, ...], n: int) -> bool:
    inside = set(subset)
    return not any(all(e[i] == 0 for i in range(n) if i not in inside) for e in lms)


def _all_independent(lms: list[tuple], n: int) -> list[tuple[int, ...]]:
    """The maximal (by inclusion) independent sets of variables, largest first, those of one size in
    colexicographic order (by the last variable, then the one before...), as Singular lists them."""
    found: list[set[int]] = []
    for k in range(n, -1, -1):
        for s in sorted(combinations(range(n), k), key=lambda c: c[::-1]):
            if _independent(lms, s, n) and not any(set(s) <= t for t in found):
                found.append(set(s))
    return [tuple(sorted(s)) for s in found]


@command("indepSet")
def indepSet(ctx, I: Ideal, which: int = -1) -> Any:
    """indepSet(I): an intvec marking a maximal independent set of variables (of size dim) for a
    standard basis I; indepSet(I, 1): the list of all maximal (by inclusion) independent sets,
    indepSet(I, 0): those of size dim.

    Example:
      ring r = 0,(x,y,z),dp;
      indepSet(std(ideal(xy, xz)));
      → 0,1,1
    """
    ctx.assume_std(I, 0)
    n = I.ring.nvars
    lms = [g.lm() for g in I.nonzero()]
    if which < 0:
        chosen = independent_set(I.nonzero(), n)
        return IntVec(1 if i in chosen else 0 for i in range(n))
    sets = _all_independent(lms, n)
    if any(len(e) == 0 or not any(e) for e in lms):
        sets = []
    if which == 0 and sets:
        top = max(len(s) for s in sets)
        sets = [s for s in sets if len(s) == top]
    return List(IntVec([1 if i in s else 0 for i in range(n)]) for s in sets)


# ---------------------------------------------------------------- preimage
@command("preimage", raw=True)
def preimage(ctx, ring_node: A.Expr, map_node: Optional[A.Expr] = None,
             ideal_node: Optional[A.Expr] = None) -> Ideal | Ring:
    """preimage(S, phi, J): the ideal of the basering R of the f with phi(f) in J, for a map phi from
    R to the ring S and an ideal J of S (kernel(phi) for J = 0); preimage(phi): the source ring of phi.

    Example:
      ring r = 0,(a,b),dp;
      ring s = 0,(x,y),dp;
      map phi = r, x2, xy;
      ideal zero;
      setring r;
      preimage(s, phi, zero);
      → _[1]=0
    """
    from .rings import _in_ring
    if map_node is None or ideal_node is None:
        phi = ctx.eval(ring_node)
        if map_node is not None or not isinstance(phi, Map):
            raise MechTypeError("preimage(phi) takes a map; preimage(S, phi, J) a ring, a map and an ideal")
        return phi.source
    source = ctx.basering().poly
    target_ring, phi = _in_ring(ctx, ring_node, map_node, "preimage")
    _, J = _in_ring(ctx, ring_node, ideal_node, "preimage")
    if not isinstance(target_ring, Ring) or not isinstance(phi, Map):
        raise MechTypeError("preimage(S, phi, J): S a ring, phi a map into it, J an ideal of S")
    if isinstance(J, Poly):
        J = Ideal(J.ring, [J])
    if not isinstance(J, Ideal):
        raise MechTypeError("preimage: the third argument must be an ideal of the target ring")
    images = list(phi.images) + [target_ring.poly.zero()] * (source.nvars - len(phi.images))
    out = preimage_polys(source, target_ring.poly, images[:source.nvars], J.nonzero())
    return Ideal(source, out or [source.zero()])


def preimage_polys(source: Any, target: Any, images: list[Poly], gens: list[Poly]) -> list[Poly]:
    """A Groebner basis (the source's ordering) of the f in ``source`` whose image under x_i -> images[i]
    lies in the ideal of ``target`` generated by ``gens``: eliminate the target's variables from
    (gens, x_i - images[i]) in the ring of both.  For a local or mixed ordering of the source, the
    preimage computed with a global ordering and then its standard basis in the source's ordering."""
    if not source.order.is_global:
        glob = with_order(source, MonomialOrder([Block("dp", source.nvars)], source.nvars))
        kernel = preimage_polys(glob, target, images, gens)
        return [normalize(p) for p in kernel_standard_basis(move(kernel, source), source)]
    k = target.nvars
    big = _prefixed(source, list(target.names))
    polys = [_lift_front(p, big, source.nvars) for p in gens]
    for i in range(source.nvars):
        polys.append(_lift(source.gen(i), big, k) - _lift_front(images[i], big, source.nvars))
    basis = eliminate(polys, range(k), ring=big)
    return [normalize(_drop(p, source, k)) for p in basis]


def _lift_front(p: Poly, big: Any, n_after: int) -> Poly:
    pad = (0,) * n_after
    return Poly(big, {e + pad: c for e, c in p.terms.items()})


# ---------------------------------------------------------------- matrices
@command("unitmat", lib="matrix.lib")
def unitmat(ctx, n: int) -> Matrix:
    """unitmat(n): the n x n identity matrix.

    Example:
      LIB "matrix.lib";
      ring r = 0,x,dp;
      print(unitmat(2));
      → 1,0,
      → 0,1
    """
    ring = ctx.basering().poly
    if n < 1:
        raise MechRuntimeError("unitmat(n) needs n >= 1")
    return Matrix(ring, n, n, [ring.one() if i == j else ring.zero() for i in range(n) for j in range(n)])


# ---------------------------------------------------------------- zero-dimensional ideals
@command("finduni")
def finduni(ctx, I: Ideal) -> Ideal:
    """finduni(I): for a zero-dimensional ideal I, a univariate polynomial in I for each variable (the
    i-th in the i-th variable, the generator of I's elimination ideal in it).

    Example:
      ring r = 0,(x,y,z),dp;
      finduni(std(ideal(x2-1, y2-x, z-y)));
      → _[1]=x2-1
      → _[2]=y4-1
      → _[3]=z4-1
    """
    ring = I.ring
    gens = I.nonzero()
    out = []
    for i in range(ring.nvars):
        basis = eliminate(gens, [j for j in range(ring.nvars) if j != i], ring=ring)
        uni = [p for p in basis if all(k == i or e[k] == 0 for e in p.terms for k in range(ring.nvars))]
        if not uni:
            raise MechRuntimeError("finduni: the ideal has to be zero-dimensional")
        out.append(normalize(min(uni, key=lambda p: p.total_degree())))
    return Ideal(ring, out)


@command("fglm", raw=True)
def fglm(ctx, ring_node: A.Expr, ideal_node: A.Expr) -> Ideal:
    """fglm(r, I): the reduced Groebner basis, for the basering's ordering, of the ideal I of the ring r
    (a reduced standard basis of a zero-dimensional ideal), its variables mapped by name.

    Example:
      ring r = 0,(x,y),dp;
      ideal I = std(ideal(x2-y, y2-1));
      ring s = 0,(x,y),lp;
      fglm(r, I);
      → _[1]=y2-1
      → _[2]=x2-y
    """
    from ..kernel.maps import imap as imap_polys
    from .rings import _in_ring
    source, I = _in_ring(ctx, ring_node, ideal_node, "fglm")
    if not isinstance(I, Ideal):
        raise MechTypeError("fglm(r, I): I must be an ideal of the ring r")
    if not I.is_std:
        name = ideal_node.id if isinstance(ideal_node, A.Name) else "_"
        raise MechRuntimeError(f"The ideal {name} has to be given by a reduced SB")
    if krull_dim([g.lm() for g in I.nonzero()], source.poly.nvars) != 0:
        name = ideal_node.id if isinstance(ideal_node, A.Name) else "_"
        raise MechRuntimeError(f"The ideal {name} has to be 0-dimensional")
    target = ctx.basering().poly
    mapped = Ideal(target, imap_polys(I.nonzero(), source.poly, target))
    return Ideal(target, standard_basis(mapped), is_std=True)
