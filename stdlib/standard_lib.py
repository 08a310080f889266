"""Commands of Singular's standard.lib beyond the standard bases (:mod:`mech.stdlib.standard`):
``max`` and ``min`` of ints, intvecs or polynomials, the monomials of one weighted degree outside a
leading ideal (``weightKB``) and ``stdfglm`` from a given ordering.  Singular loads standard.lib at
start; mech has weightKB and stdfglm built in and max and min after ``LIB "standard.lib";`` (so that
they stay free as variable names)."""
from __future__ import annotations

from functools import cmp_to_key
from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.rings import parse_ordering
from ..dsl.values import Ideal, IntVec, List
from ..dsl.values_modules import Module
from ..kernel import Poly

LIB = "standard.lib"


def _compare(a: Any, b: Any) -> int:
    """Singular's comparison: ints by value, intvecs entry by entry, polynomials by their leading
    monomials in the ring's ordering (then leading coefficients)."""
    if isinstance(a, int) and isinstance(b, int):
        return (a > b) - (a < b)
    if isinstance(a, IntVec) and isinstance(b, IntVec):
        return (a.values > b.values) - (a.values < b.values)
    if isinstance(a, Poly) and isinstance(b, Poly):
        if a.is_zero() or b.is_zero():
            return (not a.is_zero()) - (not b.is_zero())
        c = a.ring.order.compare(a.lm(), b.lm())
        return c
    raise MechRuntimeError("max and min compare ints, intvecs or polynomials, all of one type")


def _extreme(xs: tuple[Any, ...], sign: int) -> Any:
    items = list(xs[0].items) if len(xs) == 1 and isinstance(xs[0], List) else list(xs)
    if not items:
        raise MechRuntimeError("max and min need at least one argument")
    best = items[0]
    for x in items[1:]:
        if sign * _compare(x, best) > 0:
            best = x
    return best


@command("max", lib=LIB)
def max_(*xs: Any) -> Any:
    """max(a, b, ...): the largest argument: of ints, intvecs (compared entry by entry) or
    polynomials (by their leading monomials).

    Example:
      LIB "standard.lib";
      max(1, 4, 3);
      → 4
      ring r = 0,x,dp;
      max(x+1, x2);
      → x2
    """
    return _extreme(xs, 1)


@command("min", lib=LIB)
def min_(*xs: Any) -> Any:
    """min(a, b, ...): the smallest argument: of ints, intvecs (compared entry by entry) or
    polynomials (by their leading monomials).

    Example:
      LIB "standard.lib";
      min(intvec(1,2), intvec(0,5));
      → 0,5
    """
    return _extreme(xs, -1)


def monomials_of_degree(n: int, weights: list[int], d: int) -> list[tuple[int, ...]]:
    """The exponent vectors of weighted degree d in n variables of positive weights."""
    out: list[tuple[int, ...]] = []

    def rec(i: int, left: int, cur: list[int]) -> None:
        if i == n:
            if left == 0:
                out.append(tuple(cur))
            return
        for k in range(left // weights[i], -1, -1):
            rec(i + 1, left - k * weights[i], cur + [k])
    rec(0, d, [])
    return out


@command("weightKB")
def weight_kb(I: Ideal, d: int, w: IntVec | List) -> Ideal:
    """weightKB(I, d, w): the monomials of weighted degree d (the variables weighted by the positive
    intvec w) outside the leading ideal of the standard basis I: the degree-d part of a monomial
    basis of R/I.

    Example:
      ring r = 0,(x,y),wp(1,2);
      weightKB(std(ideal(x2)), 4, intvec(1,2));
      → _[1]=y2
    """
    ring = I.ring
    vec = w.items[0] if isinstance(w, List) and w.items else w
    if not isinstance(vec, IntVec):
        raise MechRuntimeError("weightKB(I, d, w): w must be an intvec of weights (or a list of them)")
    weights = list(vec.values)[:ring.nvars]
    if len(weights) < ring.nvars or any(v <= 0 for v in weights):
        raise MechRuntimeError("weightKB: the weights must be positive, one for each variable")
    leads = [g.lm() for g in I.nonzero()]
    mons = [e for e in monomials_of_degree(ring.nvars, weights, d)
            if not any(all(a <= b for a, b in zip(m, e)) for m in leads)] if d >= 0 else []
    mons.sort(key=cmp_to_key(ring.order.compare), reverse=True)
    return Ideal(ring, [ring.monomial(e) for e in mons] or [ring.zero()])


@command("stdfglm")
def stdfglm_from(I: Ideal, how: str) -> Ideal:
    """stdfglm(I, s): the reduced Groebner basis of the zero-dimensional ideal I for the basering's
    ordering, as stdfglm(I); s names the ordering (or "std"/"slimgb", the algorithm) standard.lib
    starts the FGLM conversion from: the result is the same.

    Example:
      ring r = 0,(x,y),lp;
      stdfglm(ideal(x2-y, y2-1), "std");
      → _[1]=y2-1
      → _[2]=x2-y
    """
    from .standard import stdfglm
    if how not in ("std", "slimgb"):
        parse_ordering(how, I.ring.nvars)  # the ordering must be one
    return stdfglm(I)


@command("qslimgb")
def qslimgb(I: Ideal | Module) -> Ideal | Module:
    """qslimgb(I): over a qring R/Q a standard basis of I + Q (of M + Q*R^r for a module M) computed in R
    and brought back unreduced (Q's elements stay), marked as a standard basis; over a polynomial ring
    slimgb(I).

    Example:
      ring R = 0,(x,y),dp;
      qring S = std(x2-y3);
      qslimgb(ideal(x+y2));
      → _[1]=y2+x
      → _[2]=x2+xy
    """
    from ..dsl.qrings import quotient_of
    from ..dsl.values_modules import Vector, _blocks_of, note_blocks
    from ..kernel import PolyRing
    from .module_commands import std as module_std
    from .standard import slimgb
    ring = I.ring
    q = quotient_of(ring)
    if q is None:
        return slimgb(I) if isinstance(I, Ideal) else module_std(I)
    plain = PolyRing(ring.field, ring.names, ring.order)
    note_blocks(plain, _blocks_of(ring))
    qs = [Poly(plain, g.terms) for g in q.basis]
    if isinstance(I, Ideal):
        found = slimgb(Ideal(plain, [Poly(plain, p.terms) for p in I.gens] + qs))
        return Ideal(ring, [Poly(ring, p.terms) for p in found.gens], is_std=True)
    gens = [Vector(plain, [Poly(plain, p.terms) for p in g.entries]) for g in I.gens]
    gens += [Vector(plain, [plain.zero()] * i + [g]) for g in qs for i in range(I.rank)]
    found = module_std(Module(plain, gens, I.rank))
    return Module(ring, [Vector(ring, [Poly(ring, p.terms) for p in g.entries]) for g in found.gens], I.rank, True)


def _param_poly(c: Any, field: Any, ring: Any, first: int) -> Any:
    """A coefficient of a parameter field as a polynomial of ``ring`` whose variables ``first``,
    ``first+1``... stand for the parameters (an error for a coefficient with a denominator)."""
    from ..kernel.algext import AlgebraicField
    n = ring.nvars
    if isinstance(field, AlgebraicField):
        return sum((ring.monomial(tuple(k if i == first else 0 for i in range(n)), ring.field(v))
                    for k, v in enumerate(c.u.coeffs()) if v), ring.zero())
    if c.den != 1:
        raise MechRuntimeError("par2varRing: a coefficient with a denominator in the parameters")
    out = ring.zero()
    for m, v in zip(c.num.monoms(), c.num.coeffs()):
        exp = tuple(m[i - first] if first <= i < first + len(m) else 0 for i in range(n))
        out = out + ring.monomial(exp, ring.field(int(v)))
    return out


@command("par2varRing")
def par2varRing(ctx, *args: Any) -> List:
    """par2varRing([l]): the list of a ring with the basering's parameters as new last variables (a block
    dp after the basering's blocks, before a last c/C block), exporting Id: the list of the ideals and
    modules l mapped there (with the minimal polynomial added, times each generator of the free module
    for a module); without parameters the basering itself.

    Example:
      ring R = (0,a),(x,y),dp;
      def P = par2varRing(ideal(a*x+1, y-a2))[1];
      setring P;
      Id[1];
      → _[1]=xa+1
      → _[2]=y-a2
    """
    from ..dsl.rings import make_ring
    from ..dsl.values import OrderBlock
    from ..dsl.values_modules import Module, Vector
    from ..kernel.algext import AlgebraicField
    from .ring_lib import export
    base = ctx.basering()
    ring = base.poly
    field = ring.field
    params = list(base.params)
    if not params:
        if ctx.sysvars.get("printlevel", 0) - len(ctx.frames) + 2 > 0:
            ctx.write("// ** no parameters, ring was not changed\n")
        export(base, "Id", "list", List(list(args)))
        return List([base])
    blocks = list(base.blocks)
    dp = OrderBlock("dp", len(params))
    if blocks and blocks[-1].kind in ("c", "C"):
        blocks = blocks[:-1] + [dp, blocks[-1]]
    else:
        blocks = blocks + [dp]
    new = make_ring(field.characteristic, (), list(ring.names) + params, blocks)
    P = new.poly
    first = ring.nvars

    def move(p: Any) -> Any:
        out = P.zero()
        for e, c in p.terms.items():
            out = out + P.monomial(tuple(e) + (0,) * len(params)) * _param_poly(c, field, P, first)
        return out
    mp = None
    if isinstance(field, AlgebraicField):
        coeffs = field.modulus.numer().coeffs() if field.characteristic == 0 else field.modulus.coeffs()
        mp = sum((P.monomial(tuple(k if i == first else 0 for i in range(P.nvars)), P.field(int(v)))
                  for k, v in enumerate(coeffs) if int(v)), P.zero())
    ids = []
    for x in args:
        if isinstance(x, Module):
            gens = [Vector(P, [move(p) for p in g.entries]) for g in x.gens]
            if mp is not None:
                gens += [Vector(P, [P.zero()] * i + [mp]) for i in range(x.rank)]
            ids.append(Module(P, gens, x.rank))
        elif isinstance(x, Ideal):
            ids.append(Ideal(P, [move(p) for p in x.gens] + ([mp] if mp is not None else [])))
        else:
            raise MechRuntimeError("par2varRing: ideals and modules expected")
    export(new, "Id", "list", List(ids))
    return List([new])


@command("quot")
def quot(a: Ideal | Module, b: Ideal | Module, *method: int) -> Ideal | Module:
    """quot(M, N[, n]): the quotient M : N as quotient gives it (an ideal for two modules or two ideals,
    a module for a module and an ideal); n (1..5) picks one of standard.lib's methods, which all give
    this quotient.

    Example:
      ring r = 0,(x,y),dp;
      quot(ideal(x2, xy), ideal(x), 2);
      → _[1]=y
      → _[2]=x
    """
    from ..dsl.values_modules import Vector
    from . import ideals, module_ops
    if method and not 1 <= method[0] <= 5:
        raise MechRuntimeError("quot: the method must be 1..5")
    if isinstance(a, Ideal) and isinstance(b, Ideal):
        return ideals.quotient(a, b)
    if isinstance(a, Ideal):
        a = Module(a.ring, [Vector(a.ring, [g]) for g in a.gens], 1)
    return module_ops.quotient(a, b)
