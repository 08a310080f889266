"""Local algebra at the origin and at points: tangent cones, local dimension and
multiplicity, Milnor and Tjurina numbers, local components, classification of points.

Everything "local" is computed in the local ring ``K[x]_<x>`` at the origin with a standard
basis for ``ds`` (:mod:`.engines`), whatever the ordering of the input's ring; results are
polynomials of the input's ring.  The point-based functions move the point to the origin
(``x_i -> x_i + p_i``) and answer in those centred coordinates, as the paper does; points with
algebraic coordinates (a zero-dimensional prime) are handled over ``Q[t]/m(t)`` for a primitive
element ``t`` (:func:`primitive_element`, :func:`classify_algebraic_point`).
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field
from fractions import Fraction
from math import comb
from typing import Any, Callable, Iterator, Sequence

from flint import fmpq, fmpq_mat, fmpq_poly, fmpz_poly

from . import offload_exact
from .buchberger import reduce_basis
from .coeffs import PrimeField, RationalField
from .cone_quadratic import row_rank
from .dimension import krull_dim
from .engines import standard_basis
from .errors import DomainError, NotSupported
from .factor import normalize
from .groebner import groebner, normal_form
from .hilbert import mult, vdim
from .ideals import dimension, dp_ring, independent_set, intersect, is_subset, move, std, with_order
from .localnf import weak_normal_form
from .modular_rank import jacobian_rank_mod
from .order import Block, Exp, MonomialOrder
from .poly import Poly, PolyRing
from .primdec import min_ass_gtz, primdec_gtz, radical
from .real_solve import QuotientAlgebra, RealSolvingError, rur_of


def _ring_of(gens: Sequence[Poly], ring: PolyRing | None) -> PolyRing:
    ring = ring or (gens[0].ring if gens else None)
    if ring is None:
        raise DomainError("an empty list of generators needs its ring")
    return ring


def _reorder(ring: PolyRing, kind: str) -> PolyRing:
    """The same variables and field ordered by one block ``kind`` (``"ds"``, ``"dp"``)."""
    return with_order(ring, MonomialOrder([Block(kind, ring.nvars)]))


def _ds_basis(gens: Sequence[Poly], ring: PolyRing) -> list[Poly]:
    local = _reorder(ring, "ds")
    return standard_basis(move(gens, local), local)


# Singular's reduce/NF in a local ring: a weak normal form, zero iff f lies in the ideal of
# the local ring, otherwise determined only up to a unit and modulo the ideal (see
# localnf.weak_normal_form)
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


def radical_local(gens: Sequence[Poly], ring: PolyRing | None = None) -> list[Poly]:
    """The radical of ``I K[x]_>`` as a standard basis: the global radical (localization commutes
    with radicals; components away from the origin become the unit ideal there)."""
    ring = _ring_of(gens, ring)
    target = _global(ring)
    return standard_basis(move(radical(move(gens, target), target), ring), ring)


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
        raise DomainError(f"the point has {len(point)} coordinates, the ring {ring.nvars} variables")
    return [ring.field(v) for v in point]


def shift_to_origin(gens: Sequence[Poly], point: Sequence[Any]) -> list[Poly]:
    """The generators with ``x_i`` replaced by ``x_i + p_i``: the point moves to the origin (expanded
    term by term by the binomial theorem)."""
    if not gens:
        return []
    ring = gens[0].ring
    field = ring.field
    p = _point(ring, point)
    out = []
    for g in gens:
        terms: dict[tuple, Any] = {}
        for e, c in g.terms.items():
            parts = [((), c)]
            for i, k in enumerate(e):
                if not k:
                    parts = [(f + (0,), v) for f, v in parts]
                elif not p[i]:
                    parts = [(f + (k,), v) for f, v in parts]
                else:
                    expansion = [(j, comb(k, j) * p[i] ** (k - j)) for j in range(k + 1)]
                    parts = [(f + (j,), v * w) for f, v in parts for j, w in expansion]
            for f, v in parts:
                terms[f] = terms.get(f, field.zero) + v
        out.append(Poly(ring, {f: v for f, v in terms.items() if v}))
    return out


def _centred(gens: Sequence[Poly], point: Sequence[Any]) -> list[Poly]:
    """Shifted generators; :class:`~.errors.DomainError` unless the point is on the variety."""
    if not gens:
        raise DomainError("no generators: give the ideal's generators")
    p = _point(gens[0].ring, point)
    bad = [g for g in gens if g.evaluate(p) != 0]
    if bad:
        raise DomainError(f"the point {tuple(point)} is not on the variety "
                         f"({bad[0].to_str()} does not vanish)")
    return shift_to_origin(gens, point)


def tangent_cone_at(gens: Sequence[Poly], point: Sequence[Any]) -> list[Poly]:
    """Tangent cone of ``V(gens)`` at the point, in coordinates centred at the point."""
    return tangent_cone(_centred(gens, point))


def jacobian_rank(gens: Sequence[Poly], point: Sequence[Any]) -> int:
    """Rank of the Jacobian matrix of ``gens`` at the point (exact, over the field)."""
    ring = gens[0].ring
    p = _point(ring, point)
    return row_rank([[g.diff(j).evaluate(p) for j in range(ring.nvars)] for g in gens], ring.field)


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
    multiplicity: int | None
    tangent_cone: list[Poly] = field(default_factory=list)
    components: list[list[Poly]] = field(default_factory=list)


def classify_point(gens: Sequence[Poly], point: Sequence[Any],
                   primes: Sequence[Sequence[Poly]] | None = None, cone: bool = True) -> PointInfo:
    """Classify a point of ``V(gens)``: "components meet" when several irreducible
    components pass through it (Theorem 3), otherwise "regular" when the tangent space of
    the one component through it has its dimension (Definition 3, the Jacobian criterion
    for its prime) and "singular" when it is larger.  ``primes``: the minimal primes of
    the ideal when they are known (a decomposition was made): those through the point are
    its local components, no decomposition is made again; then ``cone=False`` skips the local
    standard basis of ``gens`` (its multiplicity is None, its tangent cone []; the local dimension
    is the largest dimension of the primes through the point, a prime having its dimension at each
    of its points).  :class:`~.errors.DomainError` when the point is not on the variety."""
    centred = _centred(gens, point)
    ring = centred[0].ring
    target = _global(ring)
    if primes is None:
        comps = min_ass_local(centred)
    else:
        p = _point(ring, point)
        comps = [move(std(move(shift_to_origin(list(P), point), target), target), ring)
                 for P in primes if all(g.evaluate(p) == 0 for g in P)]
    radical = intersect(*(move(p, target) for p in comps), ring=target)
    t = ring.nvars - jacobian_rank(radical, [0] * ring.nvars)
    if primes is not None and not cone:
        d = max((dimension(move(c, target), target) for c in comps), default=-1)
        return PointInfo(_kind(len(comps), t, d), tuple(point), d, t, None, [], comps)
    d = local_dim(centred)
    return PointInfo(_kind(len(comps), t, d), tuple(point), d, t, local_mult(centred),
                     tangent_cone(centred), comps)


def _kind(components: int, tangent_dim: int, dim: int) -> str:
    """Theorem 3 and Definition 3: several components through the point, else regular iff
    the tangent space has the dimension of the one component."""
    return "components meet" if components > 1 else "regular" if tangent_dim == dim else "singular"


# --- points with algebraic coordinates --------------------------------------------------
# A zero-dimensional prime P of Q[x] that is not a rational point is a Galois orbit of conjugate
# points over K = Q[t]/m(t).  A primitive element t (a linear form separating the points) gives
# P + (t - form) the shape x_i - phi_i(t), m(t) (the shape lemma), and the analysis at all the
# conjugate points at once is the analysis over K at the origin of J(x + phi(t)) + (m) in
# Q[x, t]: every prime of Q[x, t] containing the irreducible m is a prime of K[x].

@dataclass
class AlgebraicPoint:
    """The conjugate points of a zero-dimensional prime: ``t = form`` with minimal polynomial
    ``minpoly(t)`` and coordinates ``x_i = coords[i](t)``, polynomials of ``ring`` (the input's
    variables then ``t``, ordered ``(dp(n), dp(1))``: Gröbner bases there are bases over K)."""

    ring: PolyRing
    form: Poly
    minpoly: Poly
    coords: list[Poly]

    @property
    def degree(self) -> int:
        """The number of conjugate points."""
        return self.minpoly.total_degree()


def _forms(ring: PolyRing, tries: int = 40) -> list[Poly]:
    """Candidate primitive elements: the variables (last first), then small integer forms."""
    rnd = random.Random(7)
    gens = ring.gens()
    out = gens[::-1]
    for _ in range(tries):
        out.append(sum((ring.const(rnd.randint(-3, 3)) * x for x in gens), ring.zero()))
    return [f for f in out if not f.is_constant()]


def primitive_element(prime: Sequence[Poly], ring: PolyRing | None = None,
                      name: str = "t") -> AlgebraicPoint:
    """A primitive element of the zero-dimensional prime (a variable if one separates the
    points, else a small integer linear form) and the shape basis ``x_i - phi_i(t), m(t)``.
    :class:`~.errors.DomainError` unless the prime is zero-dimensional."""
    ring = _ring_of(prime, ring)
    if dimension(prime, ring) != 0:
        raise DomainError("a primitive element needs a zero-dimensional prime")
    n = ring.nvars
    while name in ring.names:
        name += "_"
    big = PolyRing(ring.field, list(ring.names) + [name],
                   MonomialOrder([Block("dp", n), Block("dp", 1)]))
    xs, t = big.gens()[:n], big.gens()[n]
    lifted = [g.compose(xs, big) for g in prime]
    for form in _forms(ring):
        lform = form.compose(xs, big)
        basis = groebner(lifted + [t - lform], big)
        lead = {g.lm(): g for g in basis}
        if len(basis) != n + 1 or any(x.lm() not in lead for x in xs):
            continue
        coords = [x - lead[x.lm()] for x in xs]
        if all(_in_t(g, n) for g in [basis[0]] + coords):
            return AlgebraicPoint(big, lform, basis[0], coords)
    raise NotSupported("no primitive element found")


def _in_t(p: Poly, n: int) -> bool:
    """Whether ``p`` involves only the variables after the first ``n``."""
    return all(not any(e[:n]) for e in p.terms)


def _moved(gens: Sequence[Poly], point: AlgebraicPoint) -> list[Poly]:
    """``gens(x + phi(t))`` reduced modulo ``m(t)``, and ``m(t)``, in ``point.ring``."""
    ring, m = point.ring, point.minpoly
    n = ring.nvars - 1
    images = [x + c for x, c in zip(ring.gens()[:n], point.coords)]
    return [normal_form(g.compose(images, ring), [m]) for g in gens] + [m]


def centre_at(gens: Sequence[Poly], point: AlgebraicPoint) -> list[Poly]:
    """``gens(x + phi(t))`` reduced modulo ``m(t)``, and ``m(t)``: the conjugate points moved
    to the origin, in ``point.ring``.  :class:`~.errors.DomainError` unless the points are on
    the variety."""
    centred = _moved(gens, point)
    n = point.ring.nvars - 1
    at_zero = [point.ring.zero()] * n + point.ring.gens()[n:]
    if any(not g.compose(at_zero).is_zero() for g in centred[:-1]):
        raise DomainError("the points are not on the variety")
    return centred


def _lowest_in(p: Poly, n: int) -> Poly:
    """The part of least degree in the first ``n`` variables."""
    d = min(sum(e[:n]) for e in p.terms)
    return Poly(p.ring, {e: c for e, c in p.terms.items() if sum(e[:n]) == d})


def tangent_cone_over(centred: Sequence[Poly], point: AlgebraicPoint) -> list[Poly]:
    """The tangent cone at the origin over ``K = Q[t]/m(t)`` of an ideal of ``point.ring``
    containing ``m(t)``: the lowest forms in ``x`` of a standard basis for ``(ds(n), dp(1))``
    (local in ``x``, global in ``t``: the units are the elements with a non-zero rational
    constant term), which generate the ideal of lowest forms; returned as the reduced
    Gröbner basis in ``point.ring`` (``m(t)`` first, then the basis over K)."""
    ring = point.ring
    n = ring.nvars - 1
    mixed = with_order(ring, MonomialOrder([Block("ds", n), Block("dp", 1)]))
    basis = standard_basis(move(centred, mixed), mixed)
    return groebner([_lowest_in(g, n) for g in move(basis, ring)] + [point.minpoly], ring)


def tangent_dim_over(gens: Sequence[Poly], at: Sequence[Poly], ring: PolyRing, m: Poly,
                     at_least: int | None = None) -> int:
    """The dimension over ``K = Q[t]/m(t)`` of the Zariski tangent space of ``V(gens)`` (gens of
    ``ring = Q[x, t]``) at ``x = at(t)``: the kernel of the Jacobian there, as a linear ideal.
    ``at_least``: a known lower bound (the dimension of the variety at the point); when the
    Jacobian's rank modulo a prime reaches it (:mod:`.modular_rank`), it is the answer."""
    n = ring.nvars - 1
    if at_least is not None and isinstance(ring.field, RationalField):
        rank = jacobian_rank_mod(gens, at, m)
        if rank is not None and n - rank == at_least:
            return at_least
    images = list(at) + ring.gens()[n:]
    linear = [sum((normal_form(g.diff(i).compose(images), [m]) * x
                   for i, x in enumerate(ring.gens()[:n])), ring.zero()) for g in gens]
    return dimension(linear + [m], ring)


MinAss = Callable[[Sequence[Poly], PolyRing], list[list[Poly]]]  # min_ass_gtz or an equivalent


class SmoothSlices:
    """The Galois orbits of smooth points of ``V(prime)`` (a prime of ``Q[x]`` of positive dimension
    ``d``) on zero-dimensional rational slices ``x_i = c_i`` (``i`` in an independent set), each as the
    minimal polynomial of a separating linear form on it.  A slice's quotient algebra ``A`` (linear
    algebra: :mod:`.real_solve`) gives the characteristic polynomial of a separating form; an
    irreducible factor of multiplicity one is an orbit of points where ``A`` is reduced: there the
    Jacobian of ``prime`` and the ``d`` hyperplanes has rank ``n``, so the prime's has rank ``n - d``,
    the tangent space has the variety's dimension, the points are smooth.  The orbits do not depend
    on the point where the prime is looked at: computed on demand (one slice after another, at most
    ``tries``) and kept, one search serves every point."""

    def __init__(self, prime: Sequence[Poly], tries: int = 6) -> None:
        self.prime, self.tries = list(prime), tries
        self.orbits: list[fmpz_poly] = []
        self._rnd = random.Random(3)
        self._basis: list[Poly] | None = None
        self._free: list[int] = []

    def __iter__(self) -> Iterator[fmpz_poly]:
        k = 0
        while True:
            while k < len(self.orbits):
                yield self.orbits[k]
                k += 1
            if not self._next_slice():
                return

    def _next_slice(self) -> bool:
        """Cut the next slice and keep its smooth orbits; False when the tries are used up."""
        ring = _ring_of(self.prime, None)
        if self._basis is None:
            self._basis = std(self.prime, ring)
            if dimension(self._basis, ring) <= 0:
                self.tries = 0
            else:
                self._free = independent_set(self._basis, ring.nvars)
        if self.tries <= 0:
            return False
        self.tries -= 1
        rnd = self._rnd
        sliced = self._basis + [ring.gens()[i] - ring.const(Fraction(rnd.randint(-9, 9), rnd.randint(1, 9)))
                                for i in self._free]
        try:
            rep = rur_of(QuotientAlgebra(sliced, ring))
        except RealSolvingError:  # not zero-dimensional, or no separating form
            return True
        chi = rep.charpoly
        for f, _ in offload_exact.factor(rep.poly)[1]:
            if (chi % fmpq_poly(f)).is_zero() and not (chi % fmpq_poly(f) ** 2).is_zero():
                self.orbits.append(f)
        return True


def stays_prime(prime: Sequence[Poly], point: AlgebraicPoint, tries: int = 6,
                slices: SmoothSlices | None = None) -> bool:
    """A sufficient test that a prime of ``Q[x]`` of positive dimension stays prime over
    ``K = Q[t]/m(t)``: a zero-dimensional slice has a Galois orbit ``Z`` of smooth points of
    ``V(prime)`` (:class:`SmoothSlices`; ``slices``: those of ``prime``, shared across points) that
    stays one orbit over K.  Then ``Gal(Qbar/K)`` moves the points of ``Z`` transitively; each lies
    on exactly one geometric component (it is smooth) and every geometric component holds one
    (``Gal(Qbar/Q)`` permutes them transitively, ``prime`` is prime over Q), so ``Gal(Qbar/K)``
    permutes the components transitively."""
    m = _univariate(point.minpoly)
    return any(_field_product(m, fmpq_poly(mu)) for mu in (slices or SmoothSlices(prime, tries)))


def _univariate(p: Poly) -> fmpq_poly:
    """A polynomial in the last variable only, as flint's ``fmpq_poly``."""
    coeffs = [0] * (max(e[-1] for e in p.terms) + 1)
    for e, c in p.terms.items():
        coeffs[e[-1]] = c
    return fmpq_poly(coeffs)


def _field_product(m: fmpq_poly, mu: fmpq_poly) -> bool:
    """Whether ``Q[s, t]/(mu(s), m(t))`` is a field (``mu``, ``m`` irreducible), i.e. ``m`` stays
    irreducible over ``Q[s]/mu``: for ``w = s + k t`` with a squarefree characteristic polynomial
    ``r`` on the algebra (the tensor product of the companion matrices' algebras; then ``w`` is a
    primitive element) the algebra is ``Q[w]/r``, a field iff ``r`` is irreducible."""
    a, b = mu.degree(), m.degree()
    S, T = _companion(mu), _companion(m)
    for k in range(1, (a * b) ** 2 + 2):  # each pair of roots rules out at most one k
        W = fmpq_mat(a * b, a * b, [S[i // b, j // b] * (i % b == j % b) + k * T[i % b, j % b] * (i // b == j // b)
                                    for i in range(a * b) for j in range(a * b)])
        r = offload_exact.charpoly(W)
        if r.gcd(r.derivative()).degree() == 0:
            return len(offload_exact.factor(r)[1]) == 1
    raise NotSupported("no primitive element found")


def _companion(f: fmpq_poly) -> fmpq_mat:
    """The companion matrix of ``f`` (multiplication by the variable on ``Q[s]/f``)."""
    d, c = f.degree(), f.coeffs()
    return fmpq_mat(d, d, [(fmpq(int(i == j + 1)) if j < d - 1 else -c[i] / c[d]) for i in range(d) for j in range(d)])


def local_components_over(centred: Sequence[Poly] | None, point: AlgebraicPoint,
                          primes: Sequence[Sequence[Poly]] | None = None,
                          min_ass: MinAss = min_ass_gtz,
                          slices: Sequence[SmoothSlices] | None = None) -> list[list[Poly]]:
    """The minimal primes of ``centred`` (an ideal of ``point.ring`` containing ``m(t)``)
    through the origin over K (contained in ``(x, m(t))``): the local components at the
    point.  With ``primes``, the minimal primes over Q of the uncentred ideal (then ``centred``
    is not needed): each one through the point that :func:`stays_prime` over K gives one
    component directly, the others are decomposed (minimal primes over K are slow: linear
    algebra over K(u)); ``slices``: the primes' :class:`SmoothSlices`, kept across points."""
    ring = point.ring
    n = ring.nvars - 1
    origin = ring.gens()[:n] + [point.minpoly]
    if primes is None:
        if centred is None:
            raise DomainError("the local components need the centred ideal or the minimal primes")
        return [p for p in min_ass(centred, ring) if is_subset(p, origin, ring)]
    comps = []
    for k, P in enumerate(primes):
        if not vanishes_at(P, point):
            continue
        if stays_prime(P, point, slices=None if slices is None else slices[k]):
            comps.append(moved_basis(P, point))
        else:
            comps += [p for p in min_ass(_moved(P, point), ring) if is_subset(p, origin, ring)]
    return comps


def moved_basis(prime: Sequence[Poly], point: AlgebraicPoint) -> list[Poly]:
    """The reduced Gröbner basis of ``point.ring`` of ``prime(x + phi(t)) + (m(t))`` (``prime``: polynomials
    of ``Q[x]``) without a Buchberger step: ``x -> x + c`` keeps the highest-degree form of every
    polynomial, so it maps a ``dp`` basis over ``K = Q[t]/m(t)`` to a ``dp`` basis with the same leading
    monomials; those are free of ``t`` with rational coefficients, so with ``m(t)`` the images form a
    basis for ``(dp(x), dp(t))``, which only needs its tails reduced."""
    glob = dp_ring(_ring_of(prime, None))
    moved = _moved(std(move(list(prime), glob), glob), point)
    return [Poly(point.ring, t) for t in reduce_basis([g.terms for g in moved], point.ring)]


def dimension_over(basis: Sequence[Poly], point: AlgebraicPoint) -> int:
    """The dimension over ``K = Q[t]/m(t)`` of the ideal of a Gröbner basis of ``point.ring`` (its
    ordering puts ``x`` before ``t``) containing ``m(t)``: that of the leading monomials in ``x``."""
    n = point.ring.nvars - 1
    return krull_dim([g.lm()[:n] for g in basis if not _in_t(g, n)], n)


def vanishes_at(gens: Sequence[Poly], point: AlgebraicPoint) -> bool:
    """Whether the polynomials (of ``Q[x]``) vanish at the conjugate points: ``g(phi(t))`` is 0
    modulo ``m(t)``, computed with univariate polynomials."""
    m = _univariate(point.minpoly)
    coords = [_univariate(c) % m if not c.is_zero() else fmpq_poly([]) for c in point.coords]
    powers: dict[tuple[int, int], fmpq_poly] = {}
    for g in gens:
        value = fmpq_poly([])
        for e, c in g.terms.items():
            term = fmpq_poly([c])
            for i, k in enumerate(e):
                if k:
                    if (i, k) not in powers:
                        powers[i, k] = (coords[i] ** k) % m
                    term = (term * powers[i, k]) % m
            value += term
        if not (value % m).is_zero():
            return False
    return True


def classify_algebraic_point(gens: Sequence[Poly], point: AlgebraicPoint,
                             primes: Sequence[Sequence[Poly]] | None = None, min_ass: MinAss = min_ass_gtz,
                             cone_over: Callable[[Sequence[Poly], AlgebraicPoint], list[Poly]] | None = None
                             ) -> PointInfo:
    """:func:`classify_point` at the conjugate points (all alike: Galois conjugate), over K:
    components, cone and tangent space in coordinates centred at the point, in ``point.ring``;
    ``point`` of the result is ``coords``.  ``primes``: the minimal primes of ``gens`` over Q,
    if known (see :func:`local_components_over`); ``min_ass`` and ``cone_over``: functions computing
    what :func:`~.primdec.min_ass_gtz` and :func:`tangent_cone_over` do (the caller's faster ones)."""
    ring = point.ring
    n = ring.nvars - 1
    centred = centre_at(gens, point)
    comps = local_components_over(centred, point, primes, min_ass)
    if not comps:
        raise DomainError("no component through the points: primes must be the ideal's minimal primes")
    radical = intersect(*comps, ring=ring) if len(comps) > 1 else comps[0]
    d = max(dimension(c, ring) for c in comps)
    t = tangent_dim_over(radical, [ring.zero()] * n, ring, point.minpoly, d)
    cone = (cone_over or tangent_cone_over)(centred, point)
    lms = [g.lm()[:n] for g in cone if not _in_t(g, n)]
    return PointInfo(_kind(len(comps), t, d), tuple(point.coords), d, t, mult(lms, n), cone, comps)
