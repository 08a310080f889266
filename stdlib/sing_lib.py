"""Commands of Singular's sing.lib beyond :mod:`mech.stdlib.local`: ``codim`` of two standard bases,
the dimension of the singular locus (``dim_slocus``), complete intersections and isolated
singularities by dimension sequences (``is_ci``, ``is_is``), non-zerodivisors (``is_reg``),
standard bases for a local degree ordering by homogenizing (``locstd``) and the spectrum of a
weighted homogeneous singularity (``qhspectrum``)."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.printing import field_params
from ..dsl.qrings import with_quotient
from ..dsl.registry import command
from ..dsl.values import NONE, Ideal, IntVec
from ..kernel import MonomialOrder, Poly, PolyRing
from ..kernel import hilbert as H
from ..kernel.dimension import krull_dim
from ..kernel.order import Block
from .idealops import minbase
from .ideals import quotient
from .local import slocus
from .standard import _nf, normalize, standard_basis

LIB = "sing.lib"


def comment(ctx, *lines: str, depth: int = 0) -> None:
    """A library procedure's comments, shown when printlevel-voice+3 > 0 (voice: the procedure's
    level, ``depth`` calls below the command's)."""
    if ctx.sysvars.get("printlevel", 0) - len(ctx.frames) - depth + 2 > 0:
        for line in lines:
            ctx.write(line + "\n")


def _std_dim(gens: list[Poly], ring: PolyRing) -> int:
    basis = standard_basis(Ideal(ring, gens or [ring.zero()]))
    lms = [g.lm() for g in with_quotient(basis, ring)]
    return krull_dim(lms, ring.nvars)


def _vdim(I: Ideal) -> int:
    return H.vdim([g.lm() for g in with_quotient(I.nonzero(), I.ring)], I.ring.nvars)


@command("codim", lib=LIB)
def codim(ctx, I: Ideal, J: Ideal) -> int:
    """codim(I, J): for standard bases I and J with J inside I, the vector space dimension of I/J; -1
    if it is infinite, -2 if J is not inside I (by leading ideals).

    Example:
      LIB "sing.lib";
      ring r = 0,(x,y),ds;
      ideal m = std(ideal(x,y));
      ideal j = std(ideal(x2,y3));
      codim(m, j);
      → 5
    """
    for k, X in enumerate((I, J)):
        if not X.is_std:
            ctx.write(f"{'first' if k == 0 else 'second'} argument of codim is not a SB\n")
    ring = I.ring
    lead_i = [g.lm() for g in I.nonzero()]
    if any(not any(all(a <= b for a, b in zip(m, g.lm())) for m in lead_i) for g in J.nonzero()):
        return -2
    di = krull_dim(lead_i, ring.nvars)
    dj = krull_dim([g.lm() for g in J.nonzero()], ring.nvars)
    if di < 0:
        return 0 if dj < 0 else _vdim(J) if dj == 0 else -1
    if di != dj:
        return -1
    if dj <= 0:
        return _vdim(J) - _vdim(I)
    return _codim_by_hilbert(lead_i, [g.lm() for g in J.nonzero()], ring.nvars)


def _codim_by_hilbert(lead_i: list, lead_j: list, n: int) -> int:
    """dim I/J of monomial ideals of the same positive dimension: the difference of the first Hilbert
    series numerators divided by (1-t)^n is a polynomial, its coefficients sum to dim I/J (-1 when
    the division leaves a remainder: I/J is infinite)."""
    num_i, _, _ = H.hilbert_numerators(lead_i, n)
    num_j, _, _ = H.hilbert_numerators(lead_j, n)
    size = max(len(num_i), len(num_j))
    diff = [(num_j[k] if k < len(num_j) else 0) - (num_i[k] if k < len(num_i) else 0) for k in range(size)]
    for _ in range(n):  # divide by (1 - t)
        if sum(diff) != 0:
            return -1
        quot, acc = [], 0
        for c in diff[:-1]:
            acc += c
            quot.append(acc)
        diff = quot
    return sum(diff)


@command("dim_slocus", lib=LIB)
def dim_slocus(I: Ideal) -> int:
    """dim_slocus(I): the dimension of the singular locus of I (in a local ordering: at the origin).

    Example:
      LIB "sing.lib";
      ring r = 0,(x,y,z),ds;
      dim_slocus(ideal(x2+y3+z5));
      → 0
    """
    return _std_dim(slocus(I).nonzero(), I.ring)


@command("is_ci", lib=LIB)
def is_ci(ctx, I: Ideal) -> IntVec:
    """is_ci(I): the dimensions of the ideals of the first 1, 2, ... generators of a minimal basis of I;
    I is a complete intersection if the last one is nvars - size (with a comment).

    Example:
      LIB "sing.lib";
      ring r = 0,(x,y,z),ds;
      is_ci(ideal(xy, yz));
      → // no complete intersection
      → // dim-sequence:
      → 2,2
    """
    return _is_ci(ctx, I, 0)


def _is_ci(ctx, I: Ideal, depth: int) -> IntVec:
    ring = I.ring
    gens = list(minbase(I).gens)
    dims = [_std_dim(gens[:k], ring) for k in range(1, len(gens) + 1)]
    if dims[-1] + len(gens) == ring.nvars:
        comment(ctx, f"// complete intersection of dim {dims[-1]}", depth=depth)
    else:
        comment(ctx, "// no complete intersection", depth=depth)
    comment(ctx, "// dim-sequence:", depth=depth)
    return IntVec(dims)


@command("is_is", lib=LIB)
def is_is(ctx, I: Ideal) -> IntVec:
    """is_is(I): the dimensions of the singular loci of the ideals of the first 1, 2, ... generators
    of I; I has an isolated singularity if the last one is 0 (with a comment).

    Example:
      LIB "sing.lib";
      ring r = 0,(x,y,z),ds;
      is_is(ideal(xy+yz));
      → // dim of singular locus = 1
      → // isolated singularity if last number is 0 in dim-sequence:
      → 1
    """
    return _is_is(ctx, I, 0)


def _is_is(ctx, I: Ideal, depth: int) -> IntVec:
    ring = I.ring
    dims = [_std_dim(slocus(Ideal(ring, list(I.gens[:k]))).nonzero(), ring) for k in range(1, len(I.gens) + 1)]
    comment(ctx, f"// dim of singular locus = {dims[-1]}",
            "// isolated singularity if last number is 0 in dim-sequence:", depth=depth)
    return IntVec(dims)


def _invertible(rows: list[list[int]]) -> bool:
    """Whether the integer matrix is invertible over QQ."""
    from fractions import Fraction
    a = [[Fraction(v) for v in row] for row in rows]
    n = len(a)
    for c in range(n):
        pivot = next((r for r in range(c, n) if a[r][c] != 0), None)
        if pivot is None:
            return False
        a[c], a[pivot] = a[pivot], a[c]
        for r in range(c + 1, n):
            f = a[r][c] / a[c][c]
            a[r] = [x - f * y for x, y in zip(a[r], a[c])]
    return True


@command("nf_icis", lib=LIB)
def nf_icis(ctx, I: Ideal) -> Ideal:
    """nf_icis(I): for an isolated complete intersection singularity, generic linear combinations of
    the generators (random, invertible: the same ideal) whose partial ideals all have isolated
    singularities, as milnor needs them; I itself if it is no complete intersection or no isolated
    singularity (with sing.lib's comments).

    Example:
      LIB "sing.lib";
      ring r = 0,(x,y,z),ds;
      nf_icis(ideal(xy, xz, yz));
      → // no complete intersection
      → _[1]=xy
      → _[2]=xz
      → _[3]=yz
    """
    import random
    from .local import _simplify
    ring = I.ring
    gens = _simplify(list(I.gens))
    n = len(gens)
    J = Ideal(ring, gens or [ring.zero()])
    sl = _is_ci(ctx, J, 1)
    if n + sl.values[-1] != ring.nvars:
        comment(ctx, "// no complete intersection")
        return J
    sl = _is_is(ctx, J, 1)
    if sl.values[-1] != 0:
        comment(ctx, "// no isolated singularity")
        return J
    rnd = random.Random(n)
    loops, bound = 0, 0
    while sum(sl.values) != 0:
        if loops == 100:
            raise MechRuntimeError("nf_icis: no generic combination found in 100 tries (the field may be too small)")
        loops, bound = loops + 1, bound + 10
        while True:
            rows = [[rnd.randint(1, bound) for _ in range(n)] for _ in range(n)]
            if _invertible(rows):
                break
        combos = []
        for row in rows:
            g = ring.zero()
            for a, f in zip(row, gens):
                g = g + ring.const(ring.field(a)) * f
            combos.append(g)
        J = Ideal(ring, combos)
        sl = _is_is(ctx, J, 1)
    comment(ctx, f"// ICIS in generic form after {loops} genericity loop(s)")
    return J


@command("is_reg", lib=LIB)
def is_reg(f: Poly, I: Ideal) -> int:
    """is_reg(f, I): 1 if multiplication by f is injective on R/I (f is no zero divisor), else 0.

    Example:
      LIB "sing.lib";
      ring r = 0,(x,y),ds;
      is_reg(x, ideal(xy));
      → 0
      is_reg(x+y, ideal(xy));
      → 1
    """
    if f.is_zero():
        return 0
    q = quotient(I, Ideal(I.ring, [f]))
    basis = standard_basis(I)
    basis = sorted(with_quotient(basis, I.ring), key=lambda g: I.ring.order.key(g.lm()))
    return int(all(_nf(g, basis).is_zero() for g in q.nonzero()))


@command("locstd", lib=LIB)
def locstd(I: Ideal) -> Ideal:
    """locstd(I): a standard basis of I for a local degree ordering: I homogenized by a new first
    variable t, its standard basis for (dp(1), dp), then t = 1.

    Example:
      LIB "sing.lib";
      ring r = 0,(x,y),ds;
      locstd(ideal(x2+y3, xy));
      → _[1]=xy
      → _[2]=y4
      → _[3]=x2+y3
    """
    ring = I.ring
    n = ring.nvars
    big = PolyRing(ring.field, ["@t@"] + list(ring.names), MonomialOrder([Block("dp", 1), Block("dp", n)]))
    homog = []
    for g in I.nonzero():
        d = g.total_degree()
        homog.append(Poly(big, {(d - sum(e),) + e: c for e, c in g.terms.items()}))
    basis = standard_basis(Ideal(big, homog))
    out = []
    for g in basis:
        terms: dict = {}
        for e, c in g.terms.items():
            terms[e[1:]] = terms.get(e[1:], 0) + c
        out.append(normalize(Poly(ring, {e: c for e, c in terms.items() if c != 0})))
    return Ideal(ring, out, is_std=True)


@command("qhspectrum", lib=LIB)
def qhspectrum(ctx, f: Poly, w: IntVec) -> Any:
    """qhspectrum(f, w): for f weighted homogeneous for the positive weights w with an isolated
    singularity, the intvec d, s_1, ..., s_u: d the weighted degree of f and s_i/d its spectral
    numbers (sum(w) - d plus the weighted degree of each monomial of a basis of the Milnor algebra).

    Example:
      LIB "sing.lib";
      ring r = 0,(x,y),ds;
      qhspectrum(x2y+y4, intvec(3,2));
      → 8,-3,-1,0,1,3
    """
    ring = f.ring
    weights = list(w.values)
    if field_params(ring.field) or hasattr(ring.field, "modulus"):
        ctx.write("// coefficient field must not have parameters!\n")
        return NONE
    if len(weights) != ring.nvars or any(v <= 0 for v in weights):
        raise MechRuntimeError("qhspectrum(f, w): w must hold one positive weight for each variable")
    graded = PolyRing(ring.field, ring.names, MonomialOrder([Block("wp", ring.nvars, tuple(weights))]))
    g = Poly(graded, f.terms)

    def wdeg(e: tuple[int, ...]) -> int:
        return sum(a * b for a, b in zip(e, weights))
    d = max(wdeg(e) for e in g.terms)
    basis = standard_basis(Ideal(graded, [h for h in (g.diff(i) for i in range(ring.nvars)) if not h.is_zero()]))
    lms = [b.lm() for b in basis]
    if H.vdim(lms, ring.nvars) < 0:
        ctx.write("// f is no isolated singularity!\n")
        return NONE
    shift = sum(weights) - d
    return IntVec([d] + sorted(shift + wdeg(e) for e in H.kbase(lms, ring.nvars)))
