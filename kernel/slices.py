"""Minimal primes of a radical equidimensional ideal from zero-dimensional linear slices.

Let ``J ⊂ QQ[x1..xn]`` be radical and equidimensional of dimension ``d``, ``V = V(J)`` of degree
``D = deg V`` (the sum of its components' degrees).  Cut ``V`` by ``d`` affine hyperplanes
``L_i = a_i`` (small random integer forms): when ``Q[x]/(J + (L_i - a_i))`` has dimension ``D``
and the characteristic polynomial ``χ`` of multiplication by another form ``L`` there is
squarefree, the slice is ``D`` distinct points that ``L`` separates, and each irreducible factor
of ``χ`` over QQ is one Galois orbit of them.  By Bezout (refined) every component ``C`` of
``V`` meets the slice in at most ``deg C`` points and in at least one (the slice has ``D``
affine points, so none at infinity); a component defined over QQ is a union of orbits.

* :func:`slice_orbits`: the degrees of the orbits.  One orbit of ``D`` points proves ``J`` prime:
  the orbit lies in every component, so every component has degree ``D``, and the degrees add up
  to ``D`` (a proof, not a probabilistic answer; several orbits prove nothing alone).
* :func:`curve_image` (``d = 1``): the eliminant of the projection ``(L_1, L)`` to the plane
  without elimination.  ``G(y, t) = χ_y(t)``, the characteristic polynomial on the slice
  ``L_1 = y``, is monic of degree ``D`` in ``t`` with coefficients of degree ``<= D`` in ``y``
  (no point escapes to infinity), found by interpolation at ``D + 1`` values; ``G(L_1, L)``
  vanishes on ``V``, so on ``J`` (radical), and its zero set is the image.  Squarefree ``G`` of
  total degree ``D = deg V`` is the certificate of :mod:`.projection`: ``J`` has exactly as
  many minimal primes as ``G`` has irreducible factors, of their degrees; :func:`curve_primes`
  computes the primes from the factors (by saturation: the costly part).
"""
from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Sequence

import flint

from .dimension import krull_dim
from .factor import factorize
from .groebner import normal_form
from .hilbert import kbase
from .ideals import dp_ring, move, std
from .order import Block, MonomialOrder
from .poly import Poly, PolyRing
from .progress import report
from .projection import Projection, split_by_factors, variety_degree

_COEFFS = [c for c in range(-9, 10) if c]


def _random_form(ring: PolyRing, rnd: random.Random) -> Poly:
    return sum((x * rnd.choice(_COEFFS) for x in ring.gens()), ring.zero())


def _charpoly(basis: list[Poly], ring: PolyRing, form: Poly, deg: int) -> flint.fmpq_poly | None:
    """The characteristic polynomial of multiplication by ``form`` on ``ring/(basis)`` (a dp
    Gröbner basis), None unless that quotient has dimension ``deg``."""
    mons = kbase([g.lm() for g in basis], ring.nvars)
    if len(mons) != deg:
        return None
    index = {e: i for i, e in enumerate(mons)}
    M = flint.fmpq_mat(deg, deg)
    one = ring.field.one
    for j, e in enumerate(mons):
        for f, c in normal_form(form * Poly(ring, {e: one}), basis).terms.items():
            M[index[f], j] = c
    return M.charpoly()


def _slice_charpoly(J: list[Poly], ring: PolyRing, cuts: Sequence[Poly], values: Sequence[int],
                    form: Poly, deg: int) -> flint.fmpq_poly | None:
    basis = std(list(J) + [L - ring.const(a) for L, a in zip(cuts, values)], ring)
    return _charpoly(basis, ring, form, deg)


def _squarefree(f: flint.fmpq_poly) -> bool:
    return f.gcd(f.derivative()).degree() == 0


def slice_orbits(ideal: Sequence[Poly], ring: PolyRing, attempts: int = 3, seed: int = 1,
                 deg: int | None = None) -> list[int] | None:
    """The degrees of the Galois orbits of a slice of ``V(ideal)`` (radical, equidimensional,
    over QQ) by ``dim`` random hyperplanes, the first of ``attempts`` that gives ``deg V``
    points separated by a random form; None if none does.  ``[deg V]`` proves the ideal prime;
    ``len`` is an upper bound on the number of components."""
    dp = dp_ring(ring)
    J = std(move(list(ideal), dp), dp)
    d = krull_dim([g.lm() for g in J], dp.nvars)
    deg = variety_degree(J, dp) if deg is None else deg
    if d < 0 or deg <= 0:
        return None
    rnd = random.Random(seed)
    for k in range(attempts):
        cuts = [_random_form(dp, rnd) for _ in range(d)]
        values = [rnd.randint(-9, 9) for _ in range(d)]
        chi = _slice_charpoly(J, dp, cuts, values, _random_form(dp, rnd), deg)
        report("slice", k + 1, attempts, "a zero-dimensional slice")
        if chi is not None and _squarefree(chi):
            return sorted(g.degree() for g, _ in chi.factor()[1])
    return None


def _interpolate(xs: list[int], ys: list[flint.fmpq]) -> flint.fmpq_poly:
    """The polynomial of degree < len(xs) through the points (Newton's divided differences)."""
    coef = list(ys)
    for j in range(1, len(xs)):
        for i in range(len(xs) - 1, j - 1, -1):
            coef[i] = (coef[i] - coef[i - 1]) / (xs[i] - xs[i - j])
    x = flint.fmpq_poly([0, 1])
    out = flint.fmpq_poly([coef[-1]])
    for i in range(len(xs) - 2, -1, -1):
        out = out * (x - xs[i]) + coef[i]
    return out


@dataclass
class CurveImage:
    """A certified projection of a curve to the plane: ``forms`` (the two linear forms, in the
    caller's ring), ``degree`` (``deg V``), the irreducible factors of the eliminant in
    ``image_ring`` (``y1, y2``): one per minimal prime, of that prime's degree."""

    forms: list[Poly]
    degree: int
    image_ring: PolyRing
    factors: list[Poly]


def curve_image(ideal: Sequence[Poly], ring: PolyRing, attempts: int = 3, seed: int = 2) -> CurveImage | None:
    """The projection to the plane of a radical equidimensional ``ideal`` of dimension 1 over
    QQ whose eliminant, interpolated from slices, passes the degree test (squarefree of total
    degree ``deg V``): it proves that ``ideal`` has exactly as many minimal primes as the
    eliminant has irreducible factors, of their degrees.  None when no projection of
    ``attempts`` passes."""
    dp = dp_ring(ring)
    J = std(move(list(ideal), dp), dp)
    if krull_dim([g.lm() for g in J], dp.nvars) != 1:
        return None
    deg = variety_degree(J, dp)
    rnd = random.Random(seed)
    image = PolyRing(ring.field, ["y1", "y2"], MonomialOrder([Block("dp", 2)]))
    for _ in range(attempts):
        cut, form = _random_form(dp, rnd), _random_form(dp, rnd)
        xs, polys = list(range(-(deg // 2), deg - deg // 2 + 1)), []
        for k, a in enumerate(xs):
            chi = _slice_charpoly(J, dp, [cut], [a], form, deg)
            if chi is None or (k == 2 and not any(_squarefree(p) for p in polys + [chi])):
                break  # a point at infinity, or a form that does not separate the points
            polys.append(chi)
            report("projection", k + 1, len(xs), "the eliminant from slices")
        else:
            terms: dict[tuple[int, int], flint.fmpq] = {}
            for j in range(deg + 1):
                cj = _interpolate(xs, [p[j] for p in polys])
                for i in range(cj.degree() + 1):
                    if cj[i] != 0:
                        terms[(i, j)] = cj[i]
            G = Poly(image, terms)
            facs = factorize(G)[1]
            if all(k == 1 for _, k in facs) and G.total_degree() == deg:
                return CurveImage(move([cut, form], ring), deg, image, [g for g, _ in facs])
    return None


def curve_primes(ideal: Sequence[Poly], ring: PolyRing, attempts: int = 3,
                 seed: int = 2) -> Projection | None:
    """The minimal primes of a radical equidimensional ``ideal`` of dimension 1 over QQ (in
    ``ring``'s order), certified by :func:`curve_image` and split by its factors; None when
    no projection of ``attempts`` passes (the caller falls back)."""
    found = curve_image(ideal, ring, attempts, seed)
    if found is None:
        return None
    return split_by_factors(ideal, ring, found.forms, found.degree, found.image_ring, found.factors)
