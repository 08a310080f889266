"""Real branches of a curve at a point, exactly.

By Milnor's conic structure theorem (Milnor, "Singular points of complex hypersurfaces", 1968,
Thm. 2.10; for real sets Durfee, "Neighborhoods of algebraic sets", 1983) the real points of a
curve ``C`` in a small ball around ``p`` form a cone over the points on the sphere: the number of
real half-branches at ``p`` is ``#(C_R ∩ S(p, eps))``.  "Small" is certified: ``eps^2`` is below
every positive critical value of ``d = |x - p|^2`` on ``C`` (the Lagrange points: ``C`` and the
maximal minors of the Jacobian of ``(C, d)``, a zero-dimensional system, all of whose critical
values are roots of the characteristic polynomial of ``d``).  Then ``d`` has no critical point on
``C_R ∩ B(p, eps) \\ {p}`` (singular points of ``C`` included), every component of that set is an
arc from ``p`` to the sphere on which ``d`` increases, and each meets the sphere once,
transversally.  Each real branch has two half-branches.

The tangent ray of a half-branch is found exactly too: the real lines of the tangent cone are the
real points ``v_j`` of ``cone + (L - 1)`` for a linear form ``L`` not vanishing on the cone; with
a form ``W`` separating them and thresholds ``theta_k`` between the values ``W(v_j)``, the forms
``L`` and ``W - theta_k L`` vanish on no tangent direction, so each keeps one sign along a
half-branch near ``p`` - certified by taking ``eps`` below the distance from ``p`` to the other
real points of ``C`` on each hyperplane ``w(x - p) = 0`` - and the signs at the sphere point name
the ray.

Points may be algebraic: the conjugate points ``x = coords(t)``, ``e(t) = 0`` (``e`` irreducible),
handled all at once in ``Q[x, t]`` and told apart by the real root of ``e``.
"""
from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Sequence

import flint
from flint import fmpq, fmpq_poly, fmpz_poly

from . import offload_exact
from .groebner import groebner
from .ideals import dimension, dp_ring
from .local import AlgebraicPoint, centre_at, tangent_cone_over
from .matrix import Matrix, minors
from .order import Block, MonomialOrder
from .poly import Poly, PolyRing
from .real_chart import Chart
from .real_fibers import complete_intersection, curve_part, linear_poly
from .real_roots import RealRoot, RealSolvingError, isolate_real_roots, primitive, separate, sign_at
from .real_solve import (RUR, QuotientAlgebra, arb_bounds, ball_eval, from_fmpq_poly, rur, rur_of,
                         shape_representation, solution_boxes)

Box = list[tuple[fmpq, fmpq]]


@dataclass
class PointFamily:
    """Conjugate algebraic points ``x_i = coords[i](t)`` with ``poly(t) = 0`` (irreducible; for a
    rational point ``poly = t`` and constant coordinates)."""

    poly: fmpz_poly
    coords: list[fmpq_poly]

    @classmethod
    def rational(cls, point: Sequence[fmpq]) -> "PointFamily":
        return cls(fmpz_poly([0, 1]), [fmpq_poly([fmpq(c)]) for c in point])

    def real_roots(self) -> list[RealRoot]:
        return separate(isolate_real_roots(self.poly))


def point_families(prime: Sequence[Poly], ring: PolyRing) -> list[PointFamily]:
    """The points of a zero-dimensional ideal as families of conjugates (one per irreducible
    factor of its representation's polynomial)."""
    rep = rur(prime, ring)
    if rep.count == 0:
        return []
    out = []
    for f, _ in offload_exact.factor(rep.poly)[1]:
        f = primitive(f)
        out.append(PointFamily(f, [h % fmpq_poly(f) for h in rep.shape]))
    return out


@dataclass
class Branches:
    """The real branches of a curve at a real point: ``half_branches`` (points of the curve on a
    small sphere), ``branches`` (half of them), the real tangent lines ``tangents`` (direction
    boxes, normalised ``L(v) = 1``) with the half-branches on each ray ``rays[j] = (on +v_j,
    on -v_j)``, the ``kind`` of point and the certified squared radius ``radius2``."""

    point: Box
    half_branches: int
    branches: int
    smooth: bool
    kind: str
    tangents: list[Box]
    rays: list[tuple[int, int]]
    radius2: fmpq | None  # None: decided from the tangent cone (an ordinary point), no sphere


class _Setting:
    """The curve in ``Q[x, t]`` with ``e(t)`` and the squared distance to ``x = coords(t)``."""

    def __init__(self, curve: Sequence[Poly], ring: PolyRing, fam: PointFamily,
                 pull: list[list[fmpq]] | None = None) -> None:
        n = ring.nvars
        self.pull = pull  # the original coordinates as linear forms in these (a chart's), if any
        name = "t"
        while name in ring.names:
            name = "_" + name
        self.n = n
        self.ring = PolyRing(ring.field, list(ring.names) + [name], MonomialOrder([Block("dp", n), Block("dp", 1)]))
        xs = self.ring.gens()[:n]
        self.t = self.ring.gens()[n]
        self.curve = [Poly(self.ring, {e + (0,): c for e, c in g.terms.items()}) for g in curve]
        ci = complete_intersection(curve, ring)
        self.ci = None if ci is None else [Poly(self.ring, {e + (0,): c for e, c in g.terms.items()}) for g in ci]
        self.e = from_fmpq_poly(fmpq_poly(fam.poly), self.ring, n)
        self.centre = [from_fmpq_poly(c, self.ring, n) for c in fam.coords]
        self.diffs = [x - c for x, c in zip(xs, self.centre)]
        self.reweigh([1] * n)
        self.fam = fam
        self.roots = fam.real_roots()

    def forms(self, count: int) -> list[list[fmpq]]:
        """The candidate linear forms (of the original coordinates, pulled back to the chart's:
        the same tangent order and signs as without the chart)."""
        if self.pull is None:
            return _forms(self.n, count)
        out = [[sum((w * row[k] for w, row in zip(W, self.pull)), fmpq(0)) for k in range(self.n)]
               for W in _forms(len(self.pull), count)]
        return [f for f in out if any(f)]

    def reweigh(self, weights: list[int]) -> None:
        """The squared distance ``d = sum w_i (x_i - p_i)^2`` with these positive weights."""
        self.dist = sum((v * v * w for v, w in zip(self.diffs, weights)), self.ring.zero())

    def base(self) -> list[Poly]:
        return self.curve + [self.e]

    def combos(self, k: int, seed: int) -> list[Poly]:
        """``k`` random integer combinations of the curve's generators (the generators when
        there are exactly ``k``; for seed 0 ``k`` of them cutting out a curve when there are:
        a low-degree Jacobian, :func:`.real_fibers.complete_intersection`)."""
        if len(self.curve) == k:
            return list(self.curve)
        if seed == 0 and self.ci is not None and len(self.ci) == k:
            return list(self.ci)
        rnd = random.Random(seed)
        return [sum((g * rnd.randint(-3, 3) for g in self.curve), self.ring.zero()) for _ in range(k)]

    def root_index(self, rep, r: RealRoot) -> int:
        """Which real root of ``e`` the ``t`` of the solution at ``r`` is."""
        for j, c in enumerate(self.roots):
            lo, hi = (c.lo, c.hi)
            if rep.sign(self.t - lo, r) > 0 and rep.sign(self.t - hi, r) < 0:
                return j
        raise RealSolvingError("a solution's t is not a root of the point's polynomial")


def _smallest_positive(charpoly: fmpq_poly) -> fmpq | None:
    """A positive rational below every positive real root (None if there is none)."""
    for r in isolate_real_roots(charpoly):
        if r.exact is not None:
            if r.exact > 0:
                return r.exact / 2
            continue
        while r.lo < 0 < r.hi or r.lo == 0:
            r = r.refined((r.hi - r.lo) / 2)
            if r.exact is not None:
                break
        if r.exact is not None and r.exact > 0:
            return r.exact / 2
        if r.exact is None and r.lo > 0:
            return r.lo / 2
    return None


def _lagrange(S: _Setting, seed: int) -> list[Poly]:
    """The curve, ``e`` and the maximal minors of the Jacobian (in ``x``) of ``n - 1`` combinations
    of the generators and ``d``: every critical point of ``d`` on the curve (singular points
    included; combinations may add finitely many spurious points, which only lower ``eps``)."""
    h = S.combos(S.n - 1, seed)
    rows = [[f.diff(i) for i in range(S.n)] for f in h + [S.dist]]
    det = minors(Matrix(S.ring, S.n, S.n, [p for r in rows for p in r]), S.n)
    return S.base() + [d for d in det if not d.is_zero()]


def _critical_bound(S: _Setting) -> fmpq:
    """``eps^2`` below every positive critical value of the distance on the curve (from the
    characteristic polynomial of ``d`` on the Lagrange points).  When these are not isolated (a
    component on a sphere around the point) the distance is reweighted, ``sum w_i (x_i - p_i)^2``
    with random positive weights: the conic structure holds for it all the same."""
    rnd = random.Random(29)
    for attempt in range(8):
        for seed in range(1 if len(S.curve) == S.n - 1 else 4):
            lag = _lagrange(S, seed)
            if dimension(lag, S.ring) <= 0:
                A = QuotientAlgebra(lag, S.ring)
                bound = _smallest_positive(offload_exact.charpoly(A.poly_matrix(S.dist))) if A.dim else None
                return bound if bound is not None else fmpq(1)
        S.reweigh([rnd.randint(1, 9 + 4 * attempt) for _ in range(S.n)])
    raise RealSolvingError("the critical points of the distance to the point are not isolated")


def _sphere(S: _Setting, eps2: fmpq) -> tuple[object, list[RealRoot], list[int]]:
    """The real points of the curve on the sphere ``d = eps2``: representation, roots, and the
    real root of ``e`` (index) each belongs to."""
    A = QuotientAlgebra(S.base() + [S.dist - eps2], S.ring)
    rep = rur_of(A)
    roots = rep.real_roots()
    return rep, roots, [S.root_index(rep, r) for r in roots]


def half_branch_counts(curve: Sequence[Poly], ring: PolyRing, fam: PointFamily) -> list[int]:
    """The number of real half-branches of the curve (radical, every component of dimension
    one, generators of ``ring``) at each real point of the family (in the order of the real roots
    of ``fam.poly``)."""
    counts = _double_point_counts(curve, ring, fam)
    if counts is not None:
        return counts
    S = _Setting(curve, ring, fam)
    lines = _cone_lines(S, _cone(S))
    if lines.ordinary():  # one smooth branch per tangent line, real when its line is
        return [2 * len(lines.roots[j]) for j in range(len(S.roots))]
    _, _, owners = _sphere(S, _critical_bound(S))
    return [owners.count(j) for j in range(len(S.roots))]


def _double_point_counts(curve: Sequence[Poly], ring: PolyRing, fam: PointFamily) -> list[int] | None:
    """The half-branch counts when the curve is ``n - 1`` equations ``g`` whose Jacobian has rank
    ``n - 2`` at the points and the Hessian of ``h = lambda . g`` (``lambda`` spanning the left kernel
    of the Jacobian) is non-degenerate on its kernel ``T``: near ``p`` the curve is ``h = 0`` on a
    smooth surface tangent to ``T``, where ``h`` has a Morse critical point (its differential vanishes,
    so its Hessian on the surface is that of ``h`` on ``T``) - an ordinary double point, with two real
    branches (4 half-branches) where the binary form is indefinite and none where it is definite.
    None when this does not apply (then the tangent cone decides)."""
    from .real_field import RealAlgebraicField
    n = ring.nvars
    if len(curve) != n - 1:
        return None
    roots = fam.real_roots()
    if not roots:
        return []
    F = RealAlgebraicField(roots[0])  # exact arithmetic in Q[T]/(poly): every conjugate at once
    point = [F(c) for c in fam.coords]

    def at(q: Poly) -> fmpq_poly:
        return F.evaluate(q.terms, point)
    jac = [[at(g.diff(i)) for i in range(n)] for g in curve]
    right = F.kernel(jac)
    left = F.kernel([list(col) for col in zip(*jac)])
    if len(right) != 2 or len(left) != 1:
        return None
    lam = left[0]
    hess = [[F.zero] * n for _ in range(n)]
    for c, g in zip(lam, curve):
        if F.is_zero(c):
            continue
        for i in range(n):
            gi = g.diff(i)
            for j in range(i, n):
                v = F.mul(c, at(gi.diff(j)))
                hess[i][j] = F(hess[i][j] + v)
                if j != i:
                    hess[j][i] = F(hess[j][i] + v)

    def form(u: list[fmpq_poly], w: list[fmpq_poly]) -> fmpq_poly:
        out = F.zero
        for i in range(n):
            hu = F.zero
            for j in range(n):
                hu = F(hu + F.mul(hess[i][j], u[j]))
            out = F(out + F.mul(hu, w[i]))
        return out
    u, w = right
    a, b, c = form(u, u), form(u, w), form(w, w)
    disc = F(F.mul(b, b) - F.mul(a, c))
    if F.is_zero(disc):
        return None
    return [4 if sign_at(disc, r) > 0 else 0 for r in roots]


def _cone(S: _Setting) -> list[Poly]:
    """The tangent cone at the points (over ``Q[t]/e(t)``)."""
    point = AlgebraicPoint(S.ring, S.t, S.e, S.centre)
    return tangent_cone_over(centre_at(S.curve, point), point)


def real_branches(gens: Sequence[Poly], ring: PolyRing, point: Sequence[fmpq] | Sequence[Poly]) -> list[Branches]:
    """The real branches of ``V(gens)`` (a curve over QQ) at a point: a rational point (a list of
    coordinates) or the real points of a zero-dimensional ideal (one result each)."""
    if point and isinstance(point[0], Poly):
        fams = point_families(list(point), ring)
    else:
        if len(point) != ring.nvars:
            raise RealSolvingError(f"the point has {len(point)} coordinates, the ring {ring.nvars} variables")
        fams = [PointFamily.rational([fmpq(c) for c in point])]
    chart, curve = _curve_in_chart(list(gens), ring)
    out = []
    for fam in fams:
        _check_on(gens, ring, fam)
        if chart is None:
            out += _family_branches(curve, ring, fam)
            continue
        # in the chart of the linear equations (fewer variables): same branches, lifted back
        sub = PointFamily(fam.poly, [fam.coords[i] for i in chart.free])
        pull = [lin for _, lin in chart.maps]
        for b, root in zip(_family_branches(curve, chart.ring, sub, pull), fam.real_roots()):
            b.point = _point_box(fam, root)
            b.tangents = [chart.lift_direction(t) for t in b.tangents]
            out.append(b)
    return out


#: The charts and curves of the last few curves (a report asks for the branches of one curve at
#: each of its singular points).
_CURVES: dict[tuple, tuple[Chart | None, list[Poly]]] = {}


def _curve_in_chart(gens: list[Poly], ring: PolyRing) -> tuple[Chart | None, list[Poly]]:
    """The chart of the linear equations of ``V(gens)`` (None when it leaves fewer than two
    variables) and the curve's part of dimension one in it (:func:`.real_fibers.curve_part`)."""
    key = (ring, tuple(gens))
    if key not in _CURVES:
        R = dp_ring(ring)
        G = [Poly(R, g.terms) for g in gens if not g.is_zero()]
        chart = Chart(G, groebner(G, R), R) if G else None
        if chart is None or len(chart.free) < 2:
            chart = None
        curve, _ = curve_part(chart.gens, chart.ring) if chart else curve_part(gens, ring)
        if len(_CURVES) >= 8:
            _CURVES.pop(next(iter(_CURVES)))
        _CURVES[key] = (chart, curve)
    return _CURVES[key]


def _check_on(gens: Sequence[Poly], ring: PolyRing, fam: PointFamily) -> None:
    f = fmpq_poly(fam.poly)
    for g in gens:
        val = fmpq_poly([])
        for e, c in g.terms.items():
            t = fmpq_poly([c])
            for x, k in zip(fam.coords, e):
                t = (t * x ** k) % f if k else t
            val += t
        if not (val % f).is_zero():
            raise RealSolvingError("the point is not on the variety")


def _family_branches(curve: list[Poly], ring: PolyRing, fam: PointFamily,
                     pull: list[list[fmpq]] | None = None) -> list[Branches]:
    roots = fam.real_roots()
    S = _Setting(curve, ring, fam, pull) if curve else None
    if S is not None and not _passes(S):
        S = None
    smooth = S is not None and _smooth(S)
    lines = None
    if S is not None:
        lines = _cone_lines(S, _cone(S))
    if S is None:
        return [Branches(_point_box(fam, root), 0, 0, False, "isolated", [], [], fmpq(0)) for root in roots]
    at = [lines.at(j) for j in range(len(roots))]
    if lines.ordinary():  # every branch smooth, one per tangent line: the cone alone decides
        return [_ordinary_at(_point_box(fam, root), smooth, at[j][0]) for j, root in enumerate(roots)]
    eps2 = _critical_bound(S)  # one radius for all the conjugate points: one sphere
    for form in {tuple(w) for _, forms in at for w in forms}:
        eps2 = min(eps2, _hyperplane_bound(S, list(form)))
    sphere = _sphere(S, eps2)
    return [_branches_at(S, j, _point_box(fam, root), smooth, at[j], sphere, eps2) for j, root in enumerate(roots)]


def _point_box(fam: PointFamily, root: RealRoot) -> Box:
    return solution_boxes(shape_representation(fam.poly, fam.coords), [root], fmpq(1, 10 ** 12))[0][1]


def _passes(S: _Setting) -> bool:
    """Whether the curve passes through the points (conjugate points all do or all do not)."""
    basis = groebner(S.curve + [S.e] + S.diffs, S.ring)
    return not any(p.is_constant() for p in basis)


def _branches_at(S: _Setting, j: int, box: Box, smooth: bool, lines: tuple[list[Box], list[list[fmpq]]],
                 sphere: tuple[object, list[RealRoot], list[int]], eps2: fmpq) -> Branches:
    """The half-branches at the ``j``-th real point (its tangent ``lines`` and sign forms, the
    real points on a sphere of squared radius ``eps2`` small enough for each point), each on the
    tangent ray its signs name."""
    dirs, forms = lines
    rep, roots, owners = sphere
    mine = [r for r, o in zip(roots, owners) if o == j]
    rays = [[0, 0] for _ in dirs]
    for r in mine:
        side = rep.sign(_shifted(S, forms[0]), r)
        pos = sum(1 for w in forms[1:] if rep.sign(_shifted(S, w), r) == side)
        rays[pos][0 if side > 0 else 1] += 1
    half = len(mine)
    return Branches(box, half, half // 2, smooth, _kind(half, smooth, rays), dirs, [(a, b) for a, b in rays], eps2)


def _ordinary_at(box: Box, smooth: bool, dirs: list[Box]) -> Branches:
    """An ordinary point (``k`` distinct tangent lines, multiplicity ``k``: ``k`` smooth branches,
    one tangent to each line): the branch of a real line is real (complex conjugation fixes the
    line, so the branch) with one half-branch on each ray; the other branches have no real point
    but ``p`` (two on one real line would make it a double line)."""
    half = 2 * len(dirs)
    rays = [[1, 1] for _ in dirs]
    return Branches(box, half, len(dirs), smooth, _kind(half, smooth, rays), dirs, [(1, 1) for _ in dirs], None)


def _shifted(S: _Setting, form: list[fmpq]) -> Poly:
    """``form(x - p)`` in ``Q[x, t]``."""
    return sum((d * c for d, c in zip(S.diffs, form) if c != 0), S.ring.zero())


def _hyperplane_bound(S: _Setting, form: list[fmpq]) -> fmpq:
    """A squared radius below the distance from ``p`` to the other points of the curve on the
    hyperplane ``form(x - p) = 0``."""
    A = QuotientAlgebra(S.base() + [_shifted(S, form)], S.ring)
    bound = _smallest_positive(offload_exact.charpoly(A.poly_matrix(S.dist))) if A.dim else None
    return bound if bound is not None else fmpq(1)


def _smooth(S: _Setting) -> bool:
    """Whether the point is a smooth point of the curve (Jacobian of rank n - 1 there)."""
    from .real_field import RealAlgebraicField
    F = RealAlgebraicField(S.roots[0])
    coords = S.fam.coords
    rows = [[F.evaluate(g.diff(i).terms, coords) for i in range(S.n)] for g in S.curve]  # t: exponent 0
    return F.rank(rows) == S.n - 1


class _Lines:
    """The real tangent lines at the conjugate points: the real points ``v`` of
    ``cone + (L - 1)`` (directions with ``L(v) = 1``), by the real root of ``e`` they belong to."""

    def __init__(self, S: _Setting, cone: list[Poly], L: list[fmpq]) -> None:
        self.S, self.cone, self.L = S, cone, L
        self.rep = rur(cone + [linear_poly(S.ring, L) - 1], S.ring)
        roots = self.rep.real_roots()
        owners = [S.root_index(self.rep, r) for r in roots]
        self.roots = [[r for r, o in zip(roots, owners) if o == j] for j in range(len(S.roots))]

    def ordinary(self) -> bool:
        """Whether every tangent line is simple (the cone's degree, the point's multiplicity, is
        the number of lines): an ordinary point, smooth when there is one line."""
        return 0 < self.rep.poly.degree() == self.rep.charpoly.degree()

    def at(self, j: int) -> tuple[list[Box], list[list[fmpq]]]:
        """The tangent directions at the ``j``-th real point, ordered by a form ``W`` separating
        them, and the sign forms: ``L``, then ``W - theta L`` for thresholds ``theta`` between
        consecutive values of ``W``."""
        mine = self.roots[j]
        if len(mine) < 2:
            return self._boxes(mine), [self.L]
        for W in self.S.forms(40):
            order = _sorted_values(self.rep, mine, linear_poly(self.S.ring, W))
            if order is None:
                continue
            ranked, ths = order
            cands = [[w - th * l for w, l in zip(W, self.L)] for th in ths]
            if all(_transversal(self.S, self.cone, c) for c in cands):
                return self._boxes(ranked), [self.L] + cands
        raise RealSolvingError("no forms separating the tangent lines")

    def _boxes(self, roots: list[RealRoot]) -> list[Box]:
        return [b[:self.S.n] for _, b in solution_boxes(self.rep, roots, fmpq(1, 10 ** 12))] if roots else []


def _sorted_values(rep: RUR, roots: list[RealRoot], W: Poly) -> tuple[list[RealRoot], list[fmpq]] | None:
    """The roots ordered by the value of ``W`` at their solutions and rational thresholds
    between consecutive values (None when two values coincide)."""
    val = rep.value(W)
    for k in (64, 128, 256, 512, 1024):
        encl = []
        for r in roots:
            rr = r.refined(fmpq(1, 2 ** k)) if r.exact is None else r
            with flint.ctx.workprec(k + 64):
                encl.append((arb_bounds(ball_eval(val, rr.ball(k + 64))), r))
        encl.sort(key=lambda x: x[0][0])
        if all(a[0][1] < b[0][0] for a, b in zip(encl, encl[1:])):
            return [r for _, r in encl], [(a[0][1] + b[0][0]) / 2 for a, b in zip(encl, encl[1:])]
    return None


def _forms(n: int, count: int) -> list[list[fmpq]]:
    rnd = random.Random(97)
    out = [[fmpq(int(i == j)) for j in range(n)] for i in range(n)]
    out += [[fmpq(rnd.randint(-4, 4)) for _ in range(n)] for _ in range(count)]
    return [f for f in out if any(f)]


def _transversal(S: _Setting, cone: list[Poly], form: list[fmpq]) -> bool:
    """Whether ``form`` vanishes on no line of the tangent cone (over C) and its hyperplane through
    the point contains no component of the curve (one not through the point may lie in it)."""
    xs = S.ring.gens()[:S.n]
    w = sum((x * c for x, c in zip(xs, form) if c != 0), S.ring.zero())
    return dimension(cone + [w], S.ring) == 0 and dimension(S.base() + [_shifted(S, form)], S.ring) <= 0


def _cone_lines(S: _Setting, cone: list[Poly]) -> _Lines:
    for L in S.forms(40):
        if _transversal(S, cone, L):
            return _Lines(S, cone, L)
    raise RealSolvingError("no form transversal to the tangent cone")


def _kind(half: int, smooth: bool, rays: list[list[int]]) -> str:
    """regular, isolated, cusp, node, tacnode or singular (one branch through a singular point
    with its half-branches on opposite rays)."""
    if half == 0:
        return "isolated"
    if smooth:
        return "regular"
    per_line = [a + b for a, b in rays]
    if half == 2:
        return "cusp" if any(a == 2 or b == 2 for a, b in rays) else "singular"
    if all(k in (0, 2) for k in per_line) and all(a == b for a, b in rays):
        return "node"
    return "tacnode"
