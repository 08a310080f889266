"""Commands of Singular's polylib.lib (and general.lib's ``lcm`` of ideals and intvecs): elementary
symmetric polynomials (``elemSymmPoly``, ``elemSymmId``), ``substitute``, the Newton diagram
(``newtonDiag``), the smallest and largest (weighted) degrees of the monomials whatever the ordering
(``mindeg``, ``mindeg1``, ``maxdeg``, ``maxdeg1``), the longest coefficient (``maxcoef``), the content
(``content``), generators divided by their leading coefficients (``normalize``), the Hilbert
polynomial (``hilbPoly``), radical membership (``rad_con``) and the Katsura ideals (``katsura``)."""
from __future__ import annotations

from itertools import combinations
from typing import Any, Callable

from ..dsl.errors import MechRuntimeError
from ..dsl.intmat import IntMat
from ..dsl.printing import coeff_str, is_short
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, Matrix, Number
from ..dsl.values_modules import Vector
from ..kernel import Poly
from .polyops import lcm_int, lcm_poly
from .standard import standard_basis

LIB = "polylib.lib"


@command("lcm", lib="general.lib")
def lcm_mixed(*xs: Ideal | Poly | IntVec | int) -> Any:
    """lcm of integers, intvecs (their entries), polynomials and ideals (their generators)."""
    flat: list[Any] = []
    for x in xs:
        flat.extend(x.gens if isinstance(x, Ideal) else x.values if isinstance(x, IntVec) else [x])
    if all(isinstance(x, int) for x in flat):
        return lcm_int(*flat)
    ring = next(x.ring for x in flat if isinstance(x, Poly))
    return lcm_poly(*[x if isinstance(x, Poly) else ring.const(x) for x in flat])


def _elem(ring, d: int, lo: int, hi: int) -> Poly:
    out = ring.zero()
    for idx in combinations(range(lo - 1, hi), d):
        out = out + ring.monomial(tuple(int(i in idx) for i in range(ring.nvars)))
    return out


@command("elemSymmPoly", lib=LIB)
def elem_symm_poly(ctx, d: int, lo: int, hi: int) -> Poly:
    """elemSymmPoly(d, lo, hi): the elementary symmetric polynomial of degree d in the variables
    var(lo), ..., var(hi).

    Example:
      LIB "polylib.lib";
      ring r = 0,(x,y,z),dp;
      elemSymmPoly(2, 1, 3);
      → xy+xz+yz
    """
    ring = ctx.basering().poly
    if not 1 <= lo <= hi <= ring.nvars and d:
        raise MechRuntimeError(f"elemSymmPoly: the variables {lo}..{hi} are not variables of the ring")
    if hi - lo + 1 < d:
        ctx.write("========================================================\n"
                  f"There is no elementary symmetric polynomial of degree {d}\n"
                  f"for just {hi - lo + 1} variables.\n"
                  "========================================================\n")
        return ring.zero()
    return _elem(ring, d, lo, hi)


@command("elemSymmId", lib=LIB)
def elem_symm_id(ctx, n: int) -> Ideal:
    """elemSymmId(n): the ideal of the elementary symmetric polynomials in the first n variables.

    Example:
      LIB "polylib.lib";
      ring r = 0,(x,y,z),dp;
      elemSymmId(2);
      → _[1]=x+y
      → _[2]=xy
    """
    ring = ctx.basering().poly
    if not 1 <= n <= ring.nvars:
        raise MechRuntimeError(f"elemSymmId({n}): the ring has {ring.nvars} variables")
    return Ideal(ring, [_elem(ring, d, 1, n) for d in range(1, n + 1)])


def _var(p: Poly, cmd: str) -> int:
    if len(p.terms) == 1:
        (e, c), = p.terms.items()
        if c == p.ring.field.one and sum(e) == 1:
            return e.index(1)
    raise MechRuntimeError(f"{cmd}: {p} is not a ring variable")


def _apply(x: Any, images: list[Poly]) -> Any:
    if isinstance(x, Poly):
        return x.compose(images)
    if isinstance(x, Ideal):
        return Ideal(x.ring, [g.compose(images) for g in x.gens])
    if isinstance(x, Matrix):
        return Matrix(x.ring, x.nrows, x.ncols, [g.compose(images) for g in x.entries])
    raise MechRuntimeError("substitute takes a poly, an ideal or a matrix")


@command("substitute", lib=LIB)
def substitute(x: Poly | Ideal | Matrix, *pairs: Poly | Ideal) -> Any:
    """substitute(I, v, f[, v1, f1, ...]): I with the variable v replaced by f, then v1 by f1, ... (one
    after the other); substitute(I, V, F) with ideals: the variables V[i] by F[i] at once.

    Example:
      LIB "polylib.lib";
      ring r = 0,(x,y),dp;
      substitute(x2+y, x, y, y, 2);
      → 6
      substitute(x2+y, ideal(x,y), ideal(y,2));
      → y2+2
    """
    ring = x.ring
    gens = ring.gens()
    if len(pairs) == 2 and all(isinstance(p, Ideal) for p in pairs):
        vs, fs = pairs
        images = list(gens)
        for v, f in zip(vs.gens, fs.gens):
            images[_var(v, "substitute")] = f
        return _apply(x, images)
    if len(pairs) % 2 or not pairs:
        raise MechRuntimeError("substitute(I, v, f, ...) needs pairs of a variable and a polynomial")
    for v, f in zip(pairs[::2], pairs[1::2]):
        images = list(gens)
        images[_var(v, "substitute")] = f if isinstance(f, Poly) else ring.zero()
        x = _apply(x, images)
    return x


@command("newtonDiag", lib=LIB)
def newton_diag(f: Poly) -> IntMat:
    """newtonDiag(f): the intmat of the exponent vectors of the terms of f, from the leading term down.

    Example:
      LIB "polylib.lib";
      ring r = 0,(x,y),dp;
      print(newtonDiag(x2y+3y+1));
      →      2     1
      →      0     1
      →      0     0
    """
    n = f.ring.nvars
    exps = [e for e, _ in f.sorted_terms()] or [f.ring.zero_exp]
    return IntMat(len(exps), n, [k for e in exps for k in e])


def _degrees(p: Poly, w: list[int] | None) -> list[int]:
    return [sum(a * b for a, b in zip(e, w)) if w else sum(e) for e in p.terms]


def _per_entry(x: Poly | Ideal | Matrix, pick: Callable[[list[int]], int]) -> int | IntMat:
    if isinstance(x, Poly):
        return pick(_degrees(x, None)) if not x.is_zero() else -1
    m = x if isinstance(x, Matrix) else Matrix(x.ring, 1, len(x.gens), x.gens)
    return IntMat(m.nrows, m.ncols, [pick(_degrees(p, None)) if not p.is_zero() else -1 for p in m.entries])


def _overall(x: Poly | Ideal | Matrix, w: IntVec | None, pick: Callable[[list[int]], int]) -> int:
    polys = [x] if isinstance(x, Poly) else list(x.entries if isinstance(x, Matrix) else x.gens)
    ws = list(w.values) if w is not None else None
    return pick([pick(_degrees(p, ws)) if not p.is_zero() else -1 for p in polys])


@command("mindeg", lib=LIB)
def mindeg(x: Poly | Ideal | Matrix) -> int | IntMat:
    """mindeg(f): the smallest total degree of a monomial of f, whatever the ordering (-1 for 0); of an
    ideal or matrix, the intmat of those of its entries.

    Example:
      LIB "polylib.lib";
      ring r = 0,(x,y),ls;
      mindeg(x5+y2);
      → 2
    """
    return _per_entry(x, min)


@command("maxdeg", lib=LIB)
def maxdeg(x: Poly | Ideal | Matrix) -> int | IntMat:
    """maxdeg(f): the largest total degree of a monomial of f, whatever the ordering (-1 for 0); of an
    ideal or matrix, the intmat of those of its entries.

    Example:
      LIB "polylib.lib";
      ring r = 0,(x,y),wp(1,3);
      maxdeg(x2+y);
      → 2
    """
    return _per_entry(x, max)


@command("mindeg1", lib=LIB)
def mindeg1(x: Poly | Ideal | Matrix, w: IntVec | None = None) -> int:
    """mindeg1(f[, w]): the smallest (w-weighted) degree of a monomial of the entries of f (-1 counts
    for a zero entry).

    Example:
      LIB "polylib.lib";
      ring r = 0,(x,y),dp;
      mindeg1(x5+y2, intvec(1,-3));
      → -6
    """
    return _overall(x, w, min)


@command("maxdeg1", lib=LIB)
def maxdeg1(x: Poly | Ideal | Matrix, w: IntVec | None = None) -> int:
    """maxdeg1(f[, w]): the largest (w-weighted) degree of a monomial of the entries of f.

    Example:
      LIB "polylib.lib";
      ring r = 0,(x,y),dp;
      maxdeg1(x5+y2, intvec(1,3));
      → 6
    """
    return _overall(x, w, max)


@command("content", lib=LIB)
def content(f: Poly | Vector) -> Number:
    """content(f): the content of the polynomial or vector f, the constant c with f = c*cleardenom(f)
    (over Z/p 1; 1 for 0).

    Example:
      LIB "polylib.lib";
      ring r = 0,(x,y),dp;
      content(-3x2+6y);
      → -3
      content(1/2x+1/3y);
      → 1/6
    """
    from . import polyops, vector_commands
    field = f.ring.field
    if f.is_zero():
        return Number(f.ring, field.one)
    if isinstance(f, Poly):
        return Number(f.ring, f.lc() / polyops.cleardenom(f).lc())
    if getattr(field, "params", ()):
        raise MechRuntimeError("content of a vector over a parameter field is not supported")
    return Number(f.ring, vector_commands.leadcoef(f).c / vector_commands.leadcoef(vector_commands.cleardenom(f)).c)


@command("normalize", lib=LIB)
def normalize_lead(f: Poly | Ideal | Vector | Any) -> Any:
    """normalize(f): the polynomial, vector, ideal or module f with each generator divided by its
    leading coefficient (for the ring's ordering; a vector's leading term in the module ordering).

    Example:
      LIB "polylib.lib";
      ring r = 0,(x,y,z),ls;
      normalize(2x5+3y2+4z3);
      → z3+3/4y2+1/2x5
    """
    from ..dsl.values_modules import Module
    from .vector_commands import simplify
    if isinstance(f, Poly):
        return f if f.is_zero() else Poly(f.ring, {e: c / f.lc() for e, c in f.terms.items()})
    if isinstance(f, Ideal):
        return Ideal(f.ring, [normalize_lead(g) for g in f.gens])
    if isinstance(f, Vector):
        return simplify(f, 1)
    if isinstance(f, Module):
        return Module(f.ring, [simplify(g, 1) for g in f.gens], f.rank)
    raise MechRuntimeError("normalize: a poly, vector, ideal or module expected")


@command("is_zero", lib=LIB)
def is_zero(x: Any, *more: Any) -> Any:
    """is_zero(M[, any]): 1 if the module M (an ideal: R/I) is zero, else 0 (its dimension is -1); with
    a second argument the list of that and the dimension.

    Example:
      LIB "polylib.lib";
      ring r = 0,(x,y,z),dp;
      is_zero(module([x],[y],[1,z]), 1);
      → [1]:
      →    0
      → [2]:
      →    2
    """
    from ..dsl.values import List
    from ..dsl.values_modules import Module
    from .sing_regular import std_dimension
    if not isinstance(x, (Ideal, Module)):
        raise MechRuntimeError("is_zero: an ideal or module expected")
    d = std_dimension(x)
    return List([int(d == -1), d]) if more else int(d == -1)


@command("maxcoef", lib=LIB)
def maxcoef(x: Poly | Ideal | Matrix) -> int:
    """maxcoef(f): the length of the longest coefficient of f (of its string, without a sign).

    Example:
      LIB "polylib.lib";
      ring r = 0,(x,y),dp;
      maxcoef(123x-7/4y);
      → 3
    """
    polys = [x] if isinstance(x, Poly) else list(x.entries if isinstance(x, Matrix) else x.gens)
    best = 0
    for p in polys:
        for c in p.terms.values():
            s = coeff_str(p.ring.field, c, is_short(p.ring))
            best = max(best, len(s) - s.startswith("-"))
    return best


@command("hilbPoly", lib=LIB)
def hilb_poly(I: Ideal) -> IntVec:
    """hilbPoly(I): the Hilbert polynomial of R/I for a homogeneous ideal I as the intvec v_0, ...,
    v_r of its coefficients times r! (the polynomial is (v_0 + v_1 t + ... + v_r t^r)/r!); 0 when
    R/I has dimension <= 0.

    Example:
      LIB "polylib.lib";
      ring r = 0,(x,y,z),dp;
      hilbPoly(ideal(x2));
      → 1,2
    """
    from ..kernel import hilbert as H
    basis = I.nonzero() if I.is_std else standard_basis(I)
    _, second, s = H.hilbert_numerators([g.lm() for g in basis], I.ring.nvars)
    if s <= 0:
        return IntVec([0])
    hp = [0] * s  # coefficients of t^0 .. t^(s-1) of (s-1)! * sum_i h_i * binomial(t - i + s - 1, s - 1)
    for i, h in enumerate(second):
        term = [h]
        for j in range(1, s):  # times (t + j - i)
            term = [(term[k] * (j - i) if k < len(term) else 0) + (term[k - 1] if k else 0)
                    for k in range(len(term) + 1)]
        for k, c in enumerate(term):
            hp[k] += c
    return IntVec(hp)


@command("rad_con", lib=LIB)
def rad_con(g: Poly, I: Ideal) -> int:
    """rad_con(g, I): 1 if g lies in the radical of I (in a local ordering: of I in the local ring),
    else 0: whether I and g*z - 1 generate the unit ideal, z a new variable (Rabinowitsch).

    Example:
      LIB "polylib.lib";
      ring r = 0,(x,y),dp;
      rad_con(x, ideal(x3, y));
      → 1
      rad_con(x+1, ideal(x3, y));
      → 0
    """
    from ..kernel import MonomialOrder, PolyRing
    from ..kernel.order import Block
    ring = I.ring
    n = ring.nvars
    front = not ring.order.is_global  # z first, with its own dp block before a local ordering
    if front:
        big = PolyRing(ring.field, ["@z"] + list(ring.names), MonomialOrder([Block("dp", 1)] + list(ring.order.blocks)))
    else:
        big = PolyRing(ring.field, list(ring.names) + ["@z"], MonomialOrder([Block("dp", n + 1)]))
    z = big.gen(0 if front else n)

    def lift(p: Poly) -> Poly:
        return Poly(big, {((0,) + e if front else e + (0,)): c for e, c in p.terms.items()})
    gens = [lift(f) for f in I.nonzero()] + [lift(g) * z - big.one()]
    basis = standard_basis(Ideal(big, gens))
    return int(any(b.is_constant() and not b.is_zero() for b in basis))


@command("katsura", lib=LIB)
def katsura(ctx, n: int | None = None) -> Ideal:
    """katsura([n]): the n-th Katsura ideal in the first variables x_0, x_1, ... of the basering:
    x_0 + 2x_1 + ... + 2x_(n-1) - 1 and, for i < n-1, the sums of x_|j| x_|i-j| minus x_i (n generators;
    without n, n = nvars).  With fewer than n variables, katsura(n) first makes the ring
    32003,x(0..n),dp the basering (as polylib.lib).

    Example:
      LIB "polylib.lib";
      ring r = 0,(a,b),dp;
      katsura();
      → _[1]=a+2b-1
      → _[2]=a2+2b2-a
    """
    from ..dsl.rings import make_ring
    from ..dsl.values import OrderBlock
    if n is not None and (ctx.ring is None or len(ctx.ring.names) < n):
        new = make_ring(32003, (), [f"x({i})" for i in range(n + 1)], [OrderBlock("dp", n + 1), OrderBlock("C")])
        new.name = "katsura_ring"
        ctx.ring = new
    ring = ctx.basering().poly
    m = (n if n is not None else ring.nvars) - 1

    def kat(i: int) -> Poly:
        return ring.gen(abs(i)) if abs(i) <= m else ring.zero()
    gens = [sum((kat(i) for i in range(-m, m + 1)), ring.zero()) - ring.one()]
    for i in range(m):
        gens.append(sum((kat(j) * kat(i - j) for j in range(-m, m + 1)), ring.zero()) - kat(i))
    return Ideal(ring, gens)
