"""Local algebra at the origin and at points: tangent cones, local dimension and
multiplicity, Milnor and Tjurina numbers, local components, classification of points.

Everything "local" is computed in the local ring ``K[x]_<x>`` at the origin with a standard
basis for ``ds`` (:mod:`.mora`), whatever the ordering of the input's ring; results are
polynomials of the input's ring.  The point-based functions move the point to the origin
(``x_i -> x_i + p_i``) and answer in those centred coordinates, as the paper does.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Sequence

from .coeffs import PrimeField, RationalField
from .dimension import krull_dim
from .factor import normalize
from .hilbert import mult, vdim
from .ideals import intersect, move, with_order
from .mora import standard_basis, weak_normal_form
from .order import Block, Exp, MonomialOrder
from .poly import Poly, PolyRing
from .primdec import min_ass_gtz, primdec_gtz


def _ring_of(gens: Sequence[Poly], ring: PolyRing | None) -> PolyRing:
    ring = ring or (gens[0].ring if gens else None)
    if ring is None:
        raise ValueError("an empty list of generators needs its ring")
    return ring


def _reorder(ring: PolyRing, kind: str) -> PolyRing:
    """The same variables and field ordered by one block ``kind`` (``"ds"``, ``"dp"``)."""
    return with_order(ring, MonomialOrder([Block(kind, ring.nvars)]))


def _ds_basis(gens: Sequence[Poly], ring: PolyRing) -> list[Poly]:
    local = _reorder(ring, "ds")
    return standard_basis(move(gens, local), local)


def local_standard_basis(gens: Sequence[Poly], ring: PolyRing | None = None) -> list[Poly]:
    """A standard basis of the ideal in the local ring at the origin (ordering ``ds``),
    as polynomials of the input's ring."""
    ring = _ring_of(gens, ring)
    return move(_ds_basis(gens, ring), ring)


# Singular's reduce/NF in a local ring: a weak normal form, zero iff f lies in the ideal of
# the local ring, otherwise determined only up to a unit and modulo the ideal (see
# mora.weak_normal_form)
local_normal_form = weak_normal_form


def lowest_form(p: Poly) -> Poly:
    """The homogeneous part of least degree (``jet(p, mindeg(p))``)."""
    if p.is_zero():
        return p
    d = min(sum(e) for e in p.terms)
    return Poly(p.ring, {e: c for e, c in p.terms.items() if sum(e) == d})


def _primitive(p: Poly) -> Poly:
    """Singular's normalization of a ``std`` element over QQ and Z/p (others stay monic)."""
    return normalize(p) if isinstance(p.ring.field, (RationalField, PrimeField)) else p


def tangent_cone(gens: Sequence[Poly], ring: PolyRing | None = None,
                 scale: Callable[[Poly], Poly] = _primitive) -> list[Poly]:
    """The tangent cone at the origin as sing.lib's ``tangentcone`` computes it: the lowest
    forms of a ``ds`` standard basis (each element first normalized by ``scale``, by default
    as Singular's ``std`` does over QQ and Z/p), which generate the ideal of lowest forms of
    all elements of the ideal; ``[1]`` when the origin is not on the variety, ``[]`` for the
    zero ideal."""
    ring = _ring_of(gens, ring)
    return move([lowest_form(scale(g)) for g in _ds_basis(gens, ring)], ring)


def _leading(gens: Sequence[Poly], ring: PolyRing | None) -> tuple[list[Exp], int]:
    ring = _ring_of(gens, ring)
    return [g.lm() for g in _ds_basis(gens, ring)], ring.nvars


def local_dim(gens: Sequence[Poly], ring: PolyRing | None = None) -> int:
    """Krull dimension of the local ring ``K[x]_<x>/I`` at the origin; -1 when the origin is
    not on the variety (Singular's ``dim(std(I))`` in a ``ds`` ring)."""
    lms, n = _leading(gens, ring)
    return krull_dim(lms, n)


def local_vdim(gens: Sequence[Poly], ring: PolyRing | None = None) -> int:
    """``dim_K K[x]_<x>/I``: the number of monomials outside the ``ds`` leading ideal;
    -1 when it is infinite, 0 when the origin is not on the variety (Singular's ``vdim``)."""
    return vdim(*_leading(gens, ring))


def local_mult(gens: Sequence[Poly], ring: PolyRing | None = None) -> int:
    """Multiplicity of ``K[x]_<x>/I`` (the degree of the tangent cone, Singular's
    ``mult(std(I))`` in a ``ds`` ring); 0 when the origin is not on the variety."""
    return mult(*_leading(gens, ring))


def jacobian_ideal(f: Poly) -> list[Poly]:
    """The partial derivatives of ``f``."""
    return [f.diff(i) for i in range(f.ring.nvars)]


def milnor(f: Poly) -> int:
    """Milnor number ``dim_K K[x]_<x>/<df/dx_i>`` of the hypersurface ``f`` at the origin;
    -1 when infinite (non-isolated critical point), 0 when the origin is not critical
    (sing.lib's ``milnor`` in a ``ds`` ring)."""
    return local_vdim(jacobian_ideal(f), f.ring)


def tjurina(f: Poly) -> int:
    """Tjurina number ``dim_K K[x]_<x>/<f, df/dx_i>`` of the hypersurface ``f`` at the
    origin; -1 when infinite, 0 when the origin is a smooth point or not on ``f = 0``."""
    return local_vdim([f] + jacobian_ideal(f), f.ring)


def vanishes_at_origin(gens: Sequence[Poly]) -> bool:
    """Whether the origin lies on ``V(gens)`` (no generator has a constant term)."""
    return all(g.ring.zero_exp not in g.terms for g in gens)


def _global(ring: PolyRing) -> PolyRing:
    """The ring itself if its ordering is global, else the same ring ordered by ``dp``."""
    return ring if ring.order.is_global else _reorder(ring, "dp")


def min_ass_local(gens: Sequence[Poly], ring: PolyRing | None = None) -> list[list[Poly]]:
    """The minimal associated primes of ``I K[x]_<x>``: the global minimal primes
    (:func:`primdec.min_ass_gtz`, in a ``dp`` ring when the ordering is not global) whose
    variety contains the origin, as polynomials of the input's ring (Singular's
    ``minAssGTZ`` in a ring with a local ordering)."""
    ring = _ring_of(gens, ring)
    target = _global(ring)
    return [move(p, ring) for p in min_ass_gtz(move(gens, target), target) if vanishes_at_origin(p)]


def primdec_local(gens: Sequence[Poly], ring: PolyRing | None = None
                  ) -> list[tuple[list[Poly], list[Poly]]]:
    """Primary decomposition of ``I K[x]_<x>``: the global (primary, prime) pairs
    (:func:`primdec.primdec_gtz`) whose prime's variety contains the origin (Singular's
    ``primdecGTZ`` in a ring with a local ordering)."""
    ring = _ring_of(gens, ring)
    target = _global(ring)
    return [(move(q, ring), move(p, ring)) for q, p in primdec_gtz(move(gens, target), target)
            if vanishes_at_origin(p)]


# --- points -----------------------------------------------------------------------------

def _point(ring: PolyRing, point: Sequence[Any]) -> list[Any]:
    if len(point) != ring.nvars:
        raise ValueError(f"the point has {len(point)} coordinates, the ring {ring.nvars} variables")
    return [ring.field(v) for v in point]


def shift_to_origin(gens: Sequence[Poly], point: Sequence[Any]) -> list[Poly]:
    """The generators with ``x_i`` replaced by ``x_i + p_i``: the point moves to the origin."""
    if not gens:
        return []
    ring = gens[0].ring
    p = _point(ring, point)
    images = [x + c for x, c in zip(ring.gens(), p)]
    return [g.compose(images) for g in gens]


def _centred(gens: Sequence[Poly], point: Sequence[Any]) -> list[Poly]:
    """Shifted generators; ValueError unless the point is on the variety."""
    if not gens:
        raise ValueError("no generators: give the ideal's generators")
    p = _point(gens[0].ring, point)
    bad = [g for g in gens if g.evaluate(p) != 0]
    if bad:
        raise ValueError(f"the point {tuple(point)} is not on the variety "
                         f"({bad[0].to_str()} does not vanish)")
    return shift_to_origin(gens, point)


def tangent_cone_at(gens: Sequence[Poly], point: Sequence[Any]) -> list[Poly]:
    """Tangent cone of ``V(gens)`` at the point, in coordinates centred at the point."""
    return tangent_cone(_centred(gens, point))


def jacobian_rank(gens: Sequence[Poly], point: Sequence[Any]) -> int:
    """Rank of the Jacobian matrix of ``gens`` at the point (exact, over the field)."""
    ring = gens[0].ring
    p = _point(ring, point)
    rows = [[g.diff(j).evaluate(p) for j in range(ring.nvars)] for g in gens]
    rank = 0
    for col in range(ring.nvars):
        piv = next((r for r in range(rank, len(rows)) if rows[r][col] != 0), None)
        if piv is None:
            continue
        rows[rank], rows[piv] = rows[piv], rows[rank]
        for r in range(rank + 1, len(rows)):
            if rows[r][col] != 0:
                f = rows[r][col] / rows[rank][col]
                rows[r] = [a - f * b for a, b in zip(rows[r], rows[rank])]
        rank += 1
    return rank


def tangent_space_dim(gens: Sequence[Poly], point: Sequence[Any]) -> int:
    """Dimension of the Zariski tangent space at the point, ``n - rank J(p)`` (for the
    ideal the generators generate; the paper's Definition 3 assumes it radical)."""
    _centred(gens, point)
    return gens[0].ring.nvars - jacobian_rank(gens, point)


def local_components_at(gens: Sequence[Poly], point: Sequence[Any]) -> list[list[Poly]]:
    """The minimal primes of the ideal in the local ring at the point (the irreducible
    components of ``V(gens)`` through it), in coordinates centred at the point."""
    return min_ass_local(_centred(gens, point))


@dataclass
class PointInfo:
    """What :func:`classify_point` finds at a point ``p`` of ``V = V(I)``, in coordinates
    centred at ``p``.

    ``kind`` is ``"regular"``, ``"components meet"`` (several irreducible components pass
    through the point: the paper's Theorem 3, e.g. where two motion modes meet) or
    ``"singular"`` (a singular point of the one irreducible component through it).
    ``local_dim`` is ``dim O_{V,p}``, ``tangent_space_dim`` the dimension of the Zariski
    tangent space of ``V`` (from the local radical, the intersection of ``components``);
    ``multiplicity`` and ``tangent_cone`` are those of ``I`` itself (of ``V`` when ``I`` is
    radical, as in the paper)."""

    kind: str
    point: tuple
    local_dim: int
    tangent_space_dim: int
    multiplicity: int
    tangent_cone: list[Poly] = field(default_factory=list)
    components: list[list[Poly]] = field(default_factory=list)


def classify_point(gens: Sequence[Poly], point: Sequence[Any]) -> PointInfo:
    """Classify a point of ``V(gens)``: "components meet" when several irreducible
    components pass through it (Theorem 3), otherwise "regular" when the tangent space of
    the one component through it has its dimension (Definition 3, the Jacobian criterion
    for its prime) and "singular" when it is larger.  ValueError when the point is not on
    the variety."""
    centred = _centred(gens, point)
    ring = centred[0].ring
    comps = min_ass_local(centred)
    target = _global(ring)
    radical = intersect(*(move(p, target) for p in comps), ring=target)
    t = ring.nvars - jacobian_rank(radical, [0] * ring.nvars)
    d = local_dim(centred)
    kind = "components meet" if len(comps) > 1 else "regular" if t == d else "singular"
    return PointInfo(kind, tuple(point), d, t, local_mult(centred), tangent_cone(centred), comps)
