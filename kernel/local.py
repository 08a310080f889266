"""Local algebra at the origin and at points: tangent cones, local dimension and
multiplicity, Milnor and Tjurina numbers, local components, classification of points.

Everything "local" is computed in the local ring ``K[x]_<x>`` at the origin with a standard
basis for ``ds`` (:mod:`.mora`), whatever the ordering of the input's ring; results are
polynomials of the input's ring.  The point-based functions move the point to the origin
(``x_i -> x_i + p_i``) and answer in those centred coordinates, as the paper does.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Sequence

from .dimension import krull_dim
from .mora import standard_basis
from .order import Block, Exp, MonomialOrder
from .poly import Poly, PolyRing, divides


def _ring_of(gens: Sequence[Poly], ring: PolyRing | None) -> PolyRing:
    ring = ring or (gens[0].ring if gens else None)
    if ring is None:
        raise ValueError("an empty list of generators needs its ring")
    return ring


def with_order(ring: PolyRing, kind: str) -> PolyRing:
    """The same variables and field with a one-block ordering (``"ds"``, ``"dp"``, ...)."""
    return PolyRing(ring.field, ring.names, MonomialOrder([Block(kind, ring.nvars)]))


def _move(polys: Sequence[Poly], ring: PolyRing) -> list[Poly]:
    return [Poly(ring, dict(p.terms)) for p in polys if not p.is_zero()]


def local_standard_basis(gens: Sequence[Poly], ring: PolyRing | None = None) -> list[Poly]:
    """A standard basis of the ideal in the local ring at the origin (ordering ``ds``),
    as polynomials of the input's ring."""
    ring = _ring_of(gens, ring)
    local = with_order(ring, "ds")
    return _move(standard_basis(_move(gens, local), local), ring)


def singular_normalized(p: Poly) -> Poly:
    """``p`` as Singular's ``std`` stores it: over QQ a primitive integer polynomial with a
    positive leading coefficient, over Z/p monic."""
    if p.is_zero():
        return p
    if p.ring.field.characteristic:
        return p.monic()
    fracs = [p.ring.field.to_fraction(c) for c in p.terms.values()]
    from math import gcd, lcm
    den = lcm(*(f.denominator for f in fracs))
    num = gcd(*(f.numerator * den // f.denominator for f in fracs))
    scale = den / p.ring.field(num)
    return p * (scale if p.lc() * scale > 0 else -scale)


def lowest_form(p: Poly) -> Poly:
    """The homogeneous part of least degree (``jet(p, mindeg(p))``)."""
    if p.is_zero():
        return p
    d = min(sum(e) for e in p.terms)
    return Poly(p.ring, {e: c for e, c in p.terms.items() if sum(e) == d})


def tangent_cone(gens: Sequence[Poly], ring: PolyRing | None = None) -> list[Poly]:
    """The tangent cone at the origin as sing.lib's ``tangentcone`` computes it: the lowest
    forms of a ``ds`` standard basis (normalized as Singular's ``std`` does), which generate
    the ideal of lowest forms of all elements of the ideal; ``[1]`` when the origin is not
    on the variety, ``[]`` for the zero ideal."""
    ring = _ring_of(gens, ring)
    local = with_order(ring, "ds")
    basis = standard_basis(_move(gens, local), local)
    return _move([lowest_form(singular_normalized(g)) for g in basis], ring)


def _leading(gens: Sequence[Poly], ring: PolyRing | None) -> tuple[list[Exp], int]:
    ring = _ring_of(gens, ring)
    return [g.lm() for g in standard_basis(_move(gens, with_order(ring, "ds")))], ring.nvars


def local_dim(gens: Sequence[Poly], ring: PolyRing | None = None) -> int:
    """Krull dimension of the local ring ``K[x]_<x>/I`` at the origin; -1 when the origin is
    not on the variety (Singular's ``dim(std(I))`` in a ``ds`` ring)."""
    lms, n = _leading(gens, ring)
    return krull_dim(lms, n)


def hilbert_numerator(lms: Sequence[Exp], nvars: int) -> list[int]:
    """Coefficients (in t, from t^0) of the numerator ``K(t)`` of the Hilbert series
    ``K(t)/(1-t)^n`` of ``K[x]/<x^a : a in lms>`` (Bayer–Stillman pivoting)."""
    gens = _minimal_monomials([tuple(e) for e in lms])
    if any(sum(e) == 0 for e in gens):
        return [0]
    supports = [{i for i, v in enumerate(e) if v} for e in gens]
    if all(not (a & b) for k, a in enumerate(supports) for b in supports[k + 1:]):
        out = [1]
        for e in gens:
            d = sum(e)
            shifted = [0] * d + out
            out = [a - b for a, b in zip(out + [0] * d, shifted)]
        return out
    # pivot x_i^k with k an exponent of x_i in a generator involving several variables:
    # neither x_i^k nor the quotients m / x_i^k lie in the ideal, so both branches shrink
    mixed = [e for e, s in zip(gens, supports) if len(s) > 1]
    counts = [sum(1 for e in gens if e[j]) for j in range(nvars)]
    i = max((j for j in range(nvars) if any(e[j] for e in mixed)), key=lambda j: counts[j])
    powers = sorted(e[i] for e in mixed if e[i])
    k = powers[len(powers) // 2]
    pivot = tuple(k if j == i else 0 for j in range(nvars))
    plus = hilbert_numerator(gens + [pivot], nvars)
    colon = hilbert_numerator([tuple(max(0, v - k) if j == i else v for j, v in enumerate(e)) for e in gens],
                              nvars)
    out = [0] * max(len(plus), len(colon) + k)
    for d, c in enumerate(plus):
        out[d] += c
    for d, c in enumerate(colon):
        out[d + k] += c
    while len(out) > 1 and out[-1] == 0:
        out.pop()
    return out


def _minimal_monomials(exps: list[Exp]) -> list[Exp]:
    exps = sorted(set(exps), key=sum)
    out: list[Exp] = []
    for e in exps:
        if not any(divides(m, e) for m in out):
            out.append(e)
    return out


def _degree_and_length(lms: Sequence[Exp], nvars: int) -> tuple[int, int]:
    """(dimension, multiplicity) of ``K[x]/L`` for a monomial ideal ``L``: the numerator is
    divided by ``(1-t)`` as often as it vanishes at 1 and then evaluated at 1."""
    num = hilbert_numerator(lms, nvars)
    if num == [0]:
        return -1, 0
    dim = nvars
    while dim > 0 and sum(num) == 0:
        quotient, carry = [], 0  # num = (1 - t) * quotient
        for c in num[:-1]:
            carry += c
            quotient.append(carry)
        num, dim = quotient, dim - 1
    return dim, sum(num)


def local_vdim(gens: Sequence[Poly], ring: PolyRing | None = None) -> int:
    """``dim_K K[x]_<x>/I``: the number of monomials outside the ``ds`` leading ideal;
    -1 when it is infinite, 0 when the origin is not on the variety (Singular's ``vdim``)."""
    dim, length = _degree_and_length(*_leading(gens, ring))
    return -1 if dim > 0 else length


def local_mult(gens: Sequence[Poly], ring: PolyRing | None = None) -> int:
    """Multiplicity of ``K[x]_<x>/I`` (the degree of the tangent cone, Singular's
    ``mult(std(I))`` in a ``ds`` ring); 0 when the origin is not on the variety."""
    return _degree_and_length(*_leading(gens, ring))[1]


def jacobian_ideal(f: Poly) -> list[Poly]:
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
    return all(g.ring.zero_exp not in g.terms for g in gens)


def _global(gens: Sequence[Poly], ring: PolyRing) -> tuple[PolyRing, list[Poly]]:
    target = ring if ring.order.is_global else with_order(ring, "dp")
    return target, _move(gens, target)


def min_ass_local(gens: Sequence[Poly], ring: PolyRing | None = None) -> list[list[Poly]]:
    """The minimal associated primes of ``I K[x]_<x>``: the global minimal primes
    (:func:`primdec.min_ass_gtz`, in a ``dp`` ring when the ordering is not global) whose
    variety contains the origin, as polynomials of the input's ring (Singular's
    ``minAssGTZ`` in a ring with a local ordering)."""
    from .primdec import min_ass_gtz
    ring = _ring_of(gens, ring)
    target, moved = _global(gens, ring)
    return [_move(p, ring) for p in min_ass_gtz(moved, target) if vanishes_at_origin(p)]


def primdec_local(gens: Sequence[Poly], ring: PolyRing | None = None) -> list[tuple[list[Poly], list[Poly]]]:
    """Primary decomposition of ``I K[x]_<x>``: the global (primary, prime) pairs
    (:func:`primdec.primdec_gtz`) whose prime's variety contains the origin (Singular's
    ``primdecGTZ`` in a ring with a local ordering)."""
    from .primdec import primdec_gtz
    ring = _ring_of(gens, ring)
    target, moved = _global(gens, ring)
    return [(_move(q, ring), _move(p, ring)) for q, p in primdec_gtz(moved, target) if vanishes_at_origin(p)]


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
        raise ValueError(f"the point {tuple(point)} is not on the variety ({bad[0].to_str()} does not vanish)")
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
    """What :func:`classify_point` finds at a point of ``V(I)`` (centred coordinates).

    ``kind`` is ``"regular"``, ``"components meet"`` (several irreducible components pass
    through the point: the paper's Theorem 3, e.g. where two motion modes meet) or
    ``"singular"`` (a singular point of the one irreducible component through it)."""

    kind: str
    point: tuple
    local_dim: int
    tangent_space_dim: int
    multiplicity: int
    tangent_cone: list[Poly] = field(default_factory=list)
    components: list[list[Poly]] = field(default_factory=list)


def classify_point(gens: Sequence[Poly], point: Sequence[Any]) -> PointInfo:
    """Classify a point of ``V(gens)`` (generators of a radical ideal, as in the paper):
    regular when one component passes through it and ``dim T_p V = dim O_{V,p}``;
    "components meet" when several local components pass through it (Theorem 3);
    "singular" otherwise.  ValueError when the point is not on the variety."""
    centred = _centred(gens, point)
    comps = min_ass_local(centred)
    d = local_dim(centred)
    t = gens[0].ring.nvars - jacobian_rank(gens, point)
    if len(comps) > 1:
        kind = "components meet"
    elif t == d:
        kind = "regular"
    else:
        kind = "singular"
    return PointInfo(kind, tuple(point), d, t, local_mult(centred), tangent_cone(centred), comps)
