"""Local analysis (sing.lib and mech's own point commands): Milnor and Tjurina numbers, the
tangent cone at the origin, the singular locus, and, at a given point of a variety, its
tangent cone, local components, tangent space dimension and the kind of point
(:mod:`mech.kernel.local`).  docs/local.md describes the commands with examples.

A point is given as a list, an intvec or an ideal of its coordinates (numbers of the
basering's field, one per variable); it must lie on the variety.  Results at a point are in
coordinates centred at it (``x_i -> x_i + p_i`` moves it to the origin), as in the paper."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.values import Ideal, IntVec, List, Number
from ..kernel import Poly, PolyRing
from ..kernel import hilbert as H
from ..kernel import local as L
from ..kernel.dimension import krull_dim
from ..kernel.engines import standard_basis
from ..kernel.groebner import groebner
from ..kernel.ideals import intersect, move, with_order
from ..kernel.matrix import jacobian, minors
from ..kernel.order import Block, MonomialOrder
from ..kernel.primdec import equidim
from ..dsl.registry import command
from .standard import normalize


def _vdim(gens: list[Poly], ring: PolyRing) -> int:
    """Singular's ``vdim(std(I))`` for the ring's ordering (computed in ds for any local one:
    the same local ring at the origin)."""
    if ring.order.is_local:
        return L.local_vdim(gens, ring)
    basis = standard_basis(gens, ring)
    return H.vdim([g.lm() for g in basis], ring.nvars)


def _simplify(gens: list[Poly]) -> list[Poly]:
    """Singular's ``simplify(I, 10)``: drop zeros and generators proportional to an earlier one."""
    kept: list[Poly] = []
    for g in gens:
        if g.is_zero() or any(h.lm() == g.lm() and h * g.lc() == g * h.lc() for h in kept):
            continue
        kept.append(g)
    return kept


@command("milnor", lib="sing.lib")
def milnor(ctx, I: Ideal) -> int:
    """milnor(I): the Milnor number of the hypersurface or complete intersection I for the
    basering's ordering (in a local ring: at the origin; in a global one: summed over all
    critical points); -1 when infinite (not an isolated singularity, or an ICIS not in generic
    form).  With printlevel >= 1 sing.lib's comments: the discriminant numbers, or why -1.

    Example:
      LIB "sing.lib";
      ring r = 0,(x,y,z),ds;
      milnor(x3+y5+z2);
      → 8
    """
    ring = I.ring

    def comment(*lines: str, depth: int = 0) -> None:  # sing.lib's comment, shown when printlevel >= 1
        if ctx.sysvars.get("printlevel", 0) - len(ctx.frames) - depth + 2 > 0:
            ctx.write("".join(line + "\n" for line in lines))
    gens = _simplify(list(I.gens))
    if len(gens) <= 1:
        f = gens[0] if gens else ring.zero()
        mu = _vdim([d for d in L.jacobian_ideal(f) if not d.is_zero()], ring)
        if mu < 0:
            comment("// Milnor number is infinite", depth=1)
        return mu
    # the ICIS formula (Le-Greuel): mu = sum of alternating discriminant numbers
    mu = 0
    disc = [0] * len(gens)
    for l in range(len(gens), 0, -1):
        first = gens[:l]
        t = [m for m in minors(jacobian(first, ring), l) if not m.is_zero()]
        q = _vdim(first[:-1] + t, ring)
        disc[l - 1] = q
        if q == -1:
            comment("// not in generic form or no ICIS; use proc nf_icis to put",
                    "// generators in generic form and then try milnor again!", depth=1)
            return -1
        mu = q - mu
    comment("//sequence of discriminant numbers: " + ",".join(map(str, disc)), depth=1)
    return abs(mu)


@command("tjurina", lib="sing.lib")
def tjurina(I: Ideal) -> int:
    """tjurina(f): the Tjurina number dim R/<f, df/dx_1, ..., df/dx_n> of the hypersurface f for
    the basering's ordering (in a local ring: at the origin); -1 when infinite.

    Example:
      LIB "sing.lib";
      ring r = 0,(x,y,z),ds;
      tjurina(x5+y5+x2y2+z2);
      → 10
    """
    gens = _simplify(list(I.gens))
    if len(gens) > 1:
        from .sing_modules import tjurina_ci
        return tjurina_ci(gens, I.ring)
    f = gens[0] if gens else I.ring.zero()
    return _vdim([g for g in [f] + L.jacobian_ideal(f) if not g.is_zero()], I.ring)


@command("tangentcone", lib="sing.lib")
def tangentcone(I: Ideal, n: int = 0) -> Ideal:
    """tangentcone(I[, n]): the tangent cone of I at the origin: the lowest homogeneous parts of
    the elements of a standard basis of I in the ordering ds (n = 0 or 1 give the same ideal).

    Example:
      LIB "sing.lib";
      ring r = 0,(x,y),dp;
      tangentcone(ideal(y2-x2-x3));
      → _[1]=x2-y2
    """
    if n not in (0, 1):
        raise MechRuntimeError(f"tangentcone(I, {n}): the second argument must be 0 or 1")
    return Ideal(I.ring, L.tangent_cone(I.nonzero(), I.ring, normalize))


def _dp(ring: PolyRing) -> PolyRing:
    return ring if ring.order.is_global else with_order(ring, MonomialOrder([Block("dp", ring.nvars)]))


def _slocus_equidim(gens: list[Poly], ring: PolyRing) -> list[Poly]:
    """``I`` plus the c-minors of its Jacobian (c the codimension): the singular locus of an
    equidimensional ``I``; ``[1]`` for the zero ideal (smooth), the basis for the unit ideal."""
    basis = groebner(gens, ring)
    if not basis:
        return [ring.one()]
    if basis[0].total_degree() == 0:
        return [normalize(b) for b in basis]
    cod = ring.nvars - krull_dim([b.lm() for b in basis], ring.nvars)
    return gens + [m for m in minors(jacobian(gens, ring), cod) if not m.is_zero()]


@command("slocus", lib="sing.lib")
def slocus(I: Ideal) -> Ideal:
    """slocus(I): an ideal of the singular locus of V(I) (Jacobian criterion).  If I is
    equidimensional, I plus the c-minors of its Jacobian matrix (c = codim I); otherwise, with
    equidim's parts I_1..I_s, the intersection of their singular loci and of all I_j + I_k
    (where parts meet).  Computed with the ordering dp when the basering's is not global.

    Example:
      LIB "sing.lib";
      ring r = 0,(x,y,z),dp;
      slocus(ideal(xy, xz));
      → _[1]=z
      → _[2]=y
      → _[3]=x
    """
    ring = _dp(I.ring)
    gens = move(I.nonzero(), ring)
    parts = equidim(gens, ring) if gens else [[]]
    if len(parts) == 1:
        res = _slocus_equidim(gens, ring)
    else:
        pieces = [_slocus_equidim(p, ring) for p in parts]
        pieces += [a + b for j, a in enumerate(parts) for b in parts[j + 1:]]
        res = [normalize(p) for p in intersect(*pieces, ring=ring)]
    return Ideal(I.ring, move(res, I.ring))


# --- points --------------------------------------------------------------------------------

def _point(cmd: str, I: Ideal, p: Any) -> list[Any]:
    """The coordinates of the point ``p`` as elements of the field; errors for a wrong length,
    coordinates that are not numbers, or a point not on V(I)."""
    ring = I.ring
    if isinstance(p, IntVec):
        items: list[Any] = list(p.values)
    elif isinstance(p, (List, Ideal)):
        items = list(p.items if isinstance(p, List) else p.gens)
    else:
        raise MechRuntimeError(f"{cmd}: give the point as a list, intvec or ideal of coordinates")
    if len(items) != ring.nvars:
        raise MechRuntimeError(f"{cmd}: the point has {len(items)} coordinates, the ring "
                               f"{ring.nvars} variables")
    coords = []
    for k, v in enumerate(items, 1):
        if isinstance(v, int):
            coords.append(ring.field(v))
        elif isinstance(v, Number):
            coords.append(v.c)
        elif isinstance(v, Poly) and all(sum(e) == 0 for e in v.terms):
            coords.append(v.terms.get(ring.zero_exp, ring.field.zero))
        else:
            raise MechRuntimeError(f"{cmd}: coordinate {k} of the point is not a number")
    for g in I.nonzero():
        if g.evaluate(coords) != 0:
            raise MechRuntimeError(f"{cmd}: the point is not on the variety "
                                   f"({g.to_str()} does not vanish there)")
    if not I.nonzero():
        raise MechRuntimeError(f"{cmd}: the zero ideal has no local structure to analyse "
                               "(the whole space)")
    return coords


def _components(I: Ideal, p: list[Any]) -> list[list[Poly]]:
    return L.local_components_at(I.nonzero(), p)


@command("tangentConeAt")
def tangent_cone_at(I: Ideal, p: Any) -> Ideal:
    """tangentConeAt(I, p): the tangent cone of V(I) at the point p (a list, intvec or ideal of
    coordinates), in coordinates centred at p (tangentcone of I moved so that p is the origin).

    Example:
      ring r = 0,(x,y),dp;
      tangentConeAt(ideal(y-x2), list(1,1));
      → _[1]=2x-y
    """
    coords = _point("tangentConeAt", I, p)
    return Ideal(I.ring, L.tangent_cone(L.shift_to_origin(I.nonzero(), coords), I.ring, normalize))


@command("localComponentsAt")
def local_components_at(I: Ideal, p: Any) -> List:
    """localComponentsAt(I, p): the minimal primes of I in the local ring at p, i.e. the
    irreducible components of V(I) through p, in coordinates centred at p.

    Example:
      ring r = 0,(x,y),dp;
      localComponentsAt(ideal(y*(y-x2)), list(0,0));
      → [1]:
      →    _[1]=y
      → [2]:
      →    _[1]=x2-y
    """
    coords = _point("localComponentsAt", I, p)
    return List([Ideal(I.ring, [normalize(g) for g in c], is_std=True) for c in _components(I, coords)])


@command("tangentSpaceDim")
def tangent_space_dim(I: Ideal, p: Any) -> int:
    """tangentSpaceDim(I, p): the dimension n - rank J(p) of the Zariski tangent space at p of
    the scheme defined by the generators of I (of V(I) when I is radical).

    Example:
      ring r = 0,(x,y),dp;
      tangentSpaceDim(ideal(y2-x3), list(0,0));
      → 2
    """
    coords = _point("tangentSpaceDim", I, p)
    return L.tangent_space_dim(I.nonzero(), coords)


@command("pointType")
def point_type(I: Ideal, p: Any) -> str:
    """pointType(I, p): "regular", "components meet" (several irreducible components of V(I) pass
    through p: Theorem 3, motion modes meet) or "singular" (p is a singular point of the one
    component through it).

    Example:
      ring r = 0,(x,y),dp;
      pointType(ideal(xy), list(0,0));
      → components meet
    """
    coords = _point("pointType", I, p)
    return L.classify_point(I.nonzero(), coords).kind
