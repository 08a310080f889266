"""A curve over a line, fibre by fibre, and its plane images.

``C`` is a curve of ``Q^n`` (radical ideal, every component of dimension 1) and ``l`` a linear form
finite on it (checked: no point of ``C`` at infinity lies on ``l = 0``).  Then ``Q[x]/I`` is a free
``Q[l]``-module of rank ``r`` (Cohen–Macaulay of dimension one, finite over ``Q[l]``): every fibre
``I + (l - a)`` is zero-dimensional of length ``r``, and every coordinate of a point of ``C`` grows at
most linearly with ``l``.  For a second form ``m`` the characteristic polynomial of ``m`` on the
fibre over ``a`` is ``prod (Y - m(p))^mult(p)``: monic of degree ``r`` in ``Y`` with the coefficient
of ``Y^(r-j)`` a polynomial of degree at most ``j`` in ``a``, so ``r + 1`` fibres determine the
polynomial ``g(X, Y)`` of the plane image ``(l, m)(C)`` (exact interpolation, checked on one more
fibre).  When ``g`` is squarefree the projection is birational onto its image and ``g`` is the
image's reduced equation (otherwise every fibre point would repeat).
"""
from __future__ import annotations

import math
from typing import Sequence

from flint import fmpq, fmpq_poly, fmpz_poly

from . import offload_exact
from .dimension import krull_dim
from .groebner import groebner
from .ideals import dimension, dp_ring, move
from .poly import Poly, PolyRing
from .real_roots import RealSolvingError, primitive, squarefree_part
from .real_solve import QuotientAlgebra

Biv = list[fmpq_poly]  # g(X, Y) = sum g[j](X) Y^j


def linear_poly(ring: PolyRing, form: Sequence[fmpq], const: fmpq = fmpq(0)) -> Poly:
    """``sum form[i] x_i + const``."""
    out = ring.const(const)
    for x, c in zip(ring.gens(), form):
        if c != 0:
            out = out + x * c
    return out


def is_finite(basis: Sequence[Poly], form: Sequence[fmpq]) -> bool:
    """Whether the linear form is finite on ``V(I)`` (``basis`` a Gröbner basis for a degree
    ordering): the top-degree forms of the basis generate the ideal of the points at infinity,
    and none of them may lie on ``form = 0``."""
    ring = basis[0].ring
    tops = []
    for g in basis:
        d = g.total_degree()
        tops.append(Poly(ring, {e: c for e, c in g.terms.items() if sum(e) == d}))
    cone = groebner(tops + [linear_poly(ring, form)], ring)
    return krull_dim([g.lm() for g in cone], ring.nvars) == 0


def _interpolate(xs: Sequence[fmpq], ys: Sequence[fmpq]) -> fmpq_poly:
    """The polynomial of degree < len(xs) through the points (Newton's divided differences)."""
    coef = list(ys)
    n = len(xs)
    for j in range(1, n):
        for i in range(n - 1, j - 1, -1):
            coef[i] = (coef[i] - coef[i - 1]) / (xs[i] - xs[i - j])
    out = fmpq_poly([coef[-1]])
    for i in range(n - 2, -1, -1):
        out = out * fmpq_poly([-xs[i], 1]) + coef[i]
    return out


def _interpolate_range(ys: Sequence[fmpq]) -> fmpq_poly:
    """The polynomial of degree < len(ys) taking the values ``ys`` at ``0, 1, 2, ...``: Newton's
    forward differences ``D^j y_0`` (in integers, after clearing the denominators) give it as
    ``sum_j D^j y_0 X(X-1)...(X-j+1)/j!``."""
    den = math.lcm(*(int(y.q) for y in ys))
    diffs = [int(y.p) * (den // int(y.q)) for y in ys]
    tops = []
    while diffs:
        tops.append(diffs[0])
        diffs = [b - a for a, b in zip(diffs, diffs[1:])]
    fact = [1]
    for j in range(1, len(tops)):
        fact.append(fact[-1] * j)
    out = fmpq_poly([fmpq(tops[-1], fact[-1])])
    for i in range(len(tops) - 2, -1, -1):
        out = out * fmpq_poly([-i, 1]) + fmpq(tops[i], fact[i])
    return out / den


class Fibres:
    """The fibres of the curve ``gens`` over the linear form ``form``."""

    def __init__(self, gens: Sequence[Poly], ring: PolyRing, form: Sequence[fmpq]) -> None:
        self.ring = dp_ring(ring)
        self.gens = move(gens, self.ring)
        self.form = [fmpq(c) for c in form]
        self.ell = linear_poly(self.ring, self.form)
        self._cache: dict[fmpq, QuotientAlgebra] = {}
        self.degree = self.algebra(fmpq(0)).dim

    def algebra(self, a: fmpq) -> QuotientAlgebra:
        """``Q[x]/(I + (l - a))``."""
        a = fmpq(a)
        if a not in self._cache:
            A = QuotientAlgebra(self.gens + [self.ell - a], self.ring)
            if hasattr(self, "degree") and A.dim != self.degree:
                raise RealSolvingError("the projection is not finite on the curve")
            self._cache[a] = A
        return self._cache[a]

    def charpoly(self, a: fmpq, m: Sequence[fmpq]) -> fmpq_poly:
        return offload_exact.charpoly(self.algebra(a).linear_matrix(m))

    def plane_curve(self, m: Sequence[fmpq]) -> Biv:
        """``g(X, Y)``: the characteristic polynomial of ``m`` on the fibre over ``X``."""
        r = self.degree
        xs = [fmpq(k // 2 + 1) * (1 if k % 2 else -1) if k else fmpq(0) for k in range(r + 2)]
        polys = [self.charpoly(a, m) for a in xs]
        g = [_interpolate(xs[:r + 1], [p.coeffs()[j] if j < len(p.coeffs()) else fmpq(0) for p in polys[:r + 1]])
             for j in range(r + 1)]
        if at_x(g, xs[-1]) != polys[-1]:
            raise RealSolvingError("the plane image does not interpolate (the projection is not finite)")
        return g


def at_x(g: Biv, a: fmpq) -> fmpq_poly:
    """``g(a, Y)``."""
    return fmpq_poly([c(a) for c in g])


def at_y(g: Biv, b: fmpq) -> fmpq_poly:
    """``g(X, b)``."""
    out = fmpq_poly([])
    for c in reversed(g):
        out = out * b + c
    return out


def discriminant(g: Biv) -> fmpq_poly:
    """The discriminant of ``g`` (monic of degree ``r`` in ``Y``, the coefficient of ``Y^(r-j)`` of
    degree at most ``j`` in ``X``) in ``Y``: weighted homogeneous of weight ``r(r-1)``, so of degree
    at most ``r(r-1)`` in ``X`` - interpolated from its values at ``r(r-1) + 1`` rationals and checked
    at one more.  Zero when ``g`` has a repeated factor."""
    r = len(g) - 1
    bound = r * (r - 1)
    xs = [fmpq(k) for k in range(bound + 2)]
    vals = [at_x(g, a).discriminant() if r > 0 else fmpq(1) for a in xs]
    disc = _interpolate_range(vals[:-1])
    if disc(xs[-1]) != vals[-1]:
        raise RuntimeError("internal: the discriminant does not interpolate")
    return disc


def event_polynomial(g: Biv) -> fmpz_poly:
    """The squarefree part of the discriminant: its roots are the ``X`` over which the plane
    curve has a singular point or a vertical tangent.  RealSolvingError if it vanishes."""
    disc = discriminant(g)
    if disc.is_zero():
        raise RealSolvingError("the plane image is not reduced")
    return squarefree_part(disc) if disc.degree() > 0 else fmpz_poly([1])


def irreducible_factors(p: fmpz_poly) -> list[fmpz_poly]:
    """The distinct irreducible factors (primitive, positive leading coefficient)."""
    if p.degree() <= 0:
        return []
    _, facs = offload_exact.factor(p)
    return [primitive(f) for f, _ in facs]


def complete_intersection(gens: Sequence[Poly], ring: PolyRing) -> list[Poly] | None:
    """``n - 1`` of the generators, the least degrees first, whose variety is a curve (every
    component of dimension one: a complete intersection containing ``V(gens)``), or None."""
    n = ring.nvars
    h = sorted((g for g in gens if not g.is_zero()), key=lambda g: (g.total_degree(), len(g.terms)))[:n - 1]
    if len(h) < n - 1 or any(g.is_constant() for g in h):
        return None
    return h if dimension(h, ring) == 1 else None


def curve_part(gens: Sequence[Poly], ring: PolyRing, prime: bool = False) -> tuple[list[Poly], list[list[Poly]]]:
    """``(C, points)``: the radical of the union of the one-dimensional components of ``V(gens)``
    and the zero-dimensional minimal primes (isolated points).  A complete intersection of
    dimension one whose Jacobian has full rank on a dense set (the singular scheme is finite) is
    already radical and unmixed (Serre's criterion: Cohen–Macaulay and generically reduced);
    otherwise the minimal primes (:func:`.primdec.min_ass_gtz`) decide (not for a ``prime`` ideal,
    as the caller knows a motion mode to be: its minimal primes took minutes on a six-bar's mode of
    degree 16).  RealSolvingError for a component of dimension two or more."""
    from .ideals import dimension, intersect
    from .matrix import jacobian, minors
    from .primdec import min_ass_gtz
    R = dp_ring(ring)
    gens = [g for g in move(gens, R)]
    n = R.nvars
    basis = groebner(gens, R)
    d = krull_dim([g.lm() for g in basis], n) if basis else n
    if d > 1:
        raise RealSolvingError(f"not a curve: the variety has dimension {d}")
    if prime and d == 1:
        return gens, []
    if len(gens) == n - 1 and d == 1:
        sing = gens + [p for p in minors(jacobian(gens, R), n - 1) if not p.is_zero()]
        if dimension(sing, R) <= 0:
            return gens, []
    primes = min_ass_gtz(gens, R) if basis else []
    curve, points = [], []
    for P in primes:
        k = dimension(P, R)
        if k > 1:
            raise RealSolvingError(f"not a curve: a component has dimension {k}")
        (curve if k == 1 else points).append(P)
    C = (intersect(*curve, ring=R) if len(curve) > 1 else curve[0]) if curve else []
    return C, points
