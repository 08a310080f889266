"""The real topology of an algebraic curve over QQ: its circuits (connected components of the
real points), isolated real points and unbounded branches, exactly.

The method is a sweep (cylindrical decomposition) of a generic plane image, in the spirit of
Gonzalez-Vega and El Kahoui ("An improved upper complexity bound for the topology computation of
a real algebraic plane curve", 1996), Gonzalez-Vega and Necula (2002) and, for space curves,
Gatellier, Labrouzy, Mourrain and Técourt ("Computing the topology of three-dimensional algebraic
curves", 2005); every generic-position assumption is checked, and a failed check means another
projection.  docs/real.md explains the steps; in short:

1. Linear equations of the curve are solved (an affine chart), the curve is made radical with its
   one-dimensional components (0-dimensional ones are isolated points), :func:`.real_fibers.curve_part`.
2. A linear form ``l`` finite on the curve; its critical points ``K`` (``C`` and the maximal minors of
   the Jacobian of ``n - 1`` combinations of the generators and ``l``), zero-dimensional, with ``l``
   separating them (one critical point per fibre).
3. A second form ``m``: the plane image ``g(X, Y) = 0`` of ``(l, m)`` by interpolation of fibres
   (squarefree: birational); its events, the real roots ``c`` of the discriminant in ``Y``.  Between
   events the real arcs of the image do not cross, so an arc is named by its rank in ``Y``.
4. At an event ``c`` that is the value of a critical point ``p`` of ``l`` whose image ``(c, y_c)``
   is critical for ``g`` (``g_Y(c, y_c) = 0`` in ``Q(c)``): ``k`` the multiplicity of ``y_c`` in
   ``g(c, Y)`` and ``h = g(c, Y)/(Y - y_c)^k``, certified squarefree (ball root isolation: no other
   critical point of the image over ``c``, else another ``m``).  A rational window ``[a, b]``
   around ``c`` (no other event) and an interval ``J`` around ``y_c`` with ``h`` nonzero on ``J``
   (ball arithmetic) and ``g(X, ends of J) != 0`` on ``[a, b]`` (exact root counts): the real roots
   of ``g(a, Y)`` in ``J`` are exactly the arcs from the left ending at ``(c, y_c)``, those below
   and above ``J`` pass through the regular points in order (the sweep rule, certified); the
   same at ``b``.  The arcs at ``(c, y_c)`` belong to ``p``: their number must equal the number of
   half-branches of ``C`` at ``p`` (2 at a smooth point, else :func:`.real_branches.half_branch_counts`),
   so no other real point of ``C`` maps there (else another ``m``).
5. At any other event every point of ``C`` over ``c`` is smooth and not critical for ``l``: each
   real arc goes on through it.  The arcs on the two sides are matched through a window free of
   events of a second image ``(l, m2)``, by the ``m2``-order of the real points of the rational
   fibres at the window's ends (apparent crossings of the first image are undone here).
6. Arcs of the strips between events and the critical points form a graph; its connected
   components are the circuits (with points of their arcs and critical points as samples), critical
   points without arcs are isolated points, arcs over the two unbounded strips are unbounded ends.
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field
from typing import Sequence

import flint
from flint import arb, fmpq, fmpq_poly, fmpz_poly

from .coeffs import QQ
from .groebner import groebner
from .ideals import dimension, dp_ring
from .matrix import Matrix, minors
from .order import Block, MonomialOrder
from .poly import Poly, PolyRing
from .real_branches import PointFamily, half_branch_counts
from .real_field import RealAlgebraicField
from .real_fibers import (Biv, Fibres, at_x, at_y, curve_part, event_polynomial, irreducible_factors, is_finite,
                          linear_poly)
from .real_roots import RealRoot, RealSolvingError, isolate_real_roots, separate, sign_at
from .real_solve import (NotSeparatingError, QuotientAlgebra, arb_bounds, ball_eval, real_solutions, rur_of,
                         solution_boxes)

Box = list[tuple[fmpq, fmpq]]


class _Degenerate(Exception):
    """The projection is not in generic position: choose another."""


@dataclass
class Circuit:
    """A connected component of the real points: ``samples`` (boxes of a point on each of its
    arcs and of its critical points), ``box`` (their hull), whether it is ``bounded``, and the
    number of its ends at infinity."""

    samples: list[Box]
    box: Box
    bounded: bool
    ends: int


@dataclass
class CurveTopology:
    """The circuits and the isolated real points of a real algebraic curve."""

    circuits: list[Circuit]
    isolated: list[Box]
    critical_values: int = 0
    projection: list[list[fmpq]] = field(default_factory=list)

    @property
    def count(self) -> int:
        return len(self.circuits)

    @property
    def bounded(self) -> bool:
        return all(c.bounded for c in self.circuits)


# --- the affine chart of the linear equations ----------------------------------------------

class _Chart:
    """The affine subspace of the linear elements ``x_j - a_j(free)`` of a reduced ``dp`` basis:
    the curve is given in the free variables by the other generators restricted to it."""

    def __init__(self, gens: list[Poly], basis: list[Poly], ring: PolyRing) -> None:
        n = ring.nvars
        linear = {g.lm().index(1): g.monic() for g in basis if g.total_degree() == 1}
        self.free = [i for i in range(n) if i not in linear]
        self.ring = PolyRing(QQ, [ring.names[i] for i in self.free], MonomialOrder([Block("dp", len(self.free))]))
        xs = self.ring.gens()
        self.maps: list[tuple[fmpq, list[fmpq]]] = []
        images = []
        for i in range(n):
            if i in linear:
                g = linear[i]
                const = -g.coeff_of(ring.zero_exp)
                lin = [-g.coeff_of(tuple(int(k == j) for k in range(n))) for j in self.free]
            else:
                const, lin = fmpq(0), [fmpq(int(j == i)) for j in self.free]
            self.maps.append((const, lin))
            images.append(sum((x * c for x, c in zip(xs, lin) if c != 0), self.ring.const(const)))
        restricted = [g.compose(images, self.ring) for g in gens]
        self.gens = [g for g in restricted if not g.is_zero()]

    def lift(self, box: Box) -> Box:
        """The box of a point of the chart in all coordinates (exact interval arithmetic)."""
        out = []
        for const, lin in self.maps:
            lo = hi = const
            for c, (a, b) in zip(lin, box):
                lo, hi = (lo + c * a, hi + c * b) if c >= 0 else (lo + c * b, hi + c * a)
            out.append((lo, hi))
        return out


# --- forms ---------------------------------------------------------------------------------

def _forms(n: int, seed: int, count: int, start: int = 0) -> list[list[fmpq]]:
    """Pseudo-random integer linear forms, the ``k``-th with coefficients up to ``2^(1 + k/2)``:
    small ones first (small numbers, fast), larger ones when a symmetric curve (many rational
    special points) defeats them."""
    rnd = random.Random(seed)
    out: list[list[fmpq]] = []
    k = start
    while len(out) < count:
        size = 2 ** (1 + k // 2)
        f = [fmpq(rnd.randint(-size, size)) for _ in range(n)]
        if any(f):
            out.append(f)
        k += 1
    return out


def _critical(gens: list[Poly], ring: PolyRing, ell: list[fmpq]):
    """The representation of the critical points of ``l`` on the curve, parametrised by ``l``
    (_Degenerate unless they are isolated and ``l`` separates them)."""
    n = ring.nvars
    for seed in ([None] if len(gens) == n - 1 else range(4)):
        rnd = random.Random(seed)
        h = gens if seed is None else [sum((g * rnd.randint(-3, 3) for g in gens), ring.zero()) for _ in range(n - 1)]
        rows = [[f.diff(i) for i in range(n)] for f in h] + [[ring.const(c) for c in ell]]
        det = [d for d in minors(Matrix(ring, n, n, [p for r in rows for p in r]), n) if not d.is_zero()]
        K = gens + det
        if dimension(K, ring) <= 0:
            try:
                return rur_of(QuotientAlgebra(K, ring), ell)
            except NotSeparatingError:
                raise _Degenerate() from None
    raise _Degenerate()


# --- events ---------------------------------------------------------------------------------

@dataclass
class _Critical:
    """An irreducible factor ``e`` of the event polynomial whose roots are critical values of ``l``
    with the critical point ``psi`` (in ``Q(c)``) mapping to the critical point ``(c, y)`` of the
    image: ``y`` has multiplicity ``k`` in ``g(c, Y)``, ``h = g(c, Y)/(Y - y)^k``."""

    poly: fmpz_poly
    psi: list[fmpq_poly]
    y: fmpq_poly
    k: int
    h: list[fmpq_poly]


def _critical_data(g: Biv, e: fmpz_poly, root: RealRoot, crit, m: list[fmpq]) -> _Critical | None:
    """The data of a factor ``e`` of the events when the critical point of ``l`` over its roots
    maps to a critical point of the image (field operations without inversions), else None."""
    if not (fmpq_poly(crit.poly) % fmpq_poly(e)).is_zero():
        return None
    F = RealAlgebraicField(root)
    psi = [F(s) for s in crit.shape]
    y = F(sum((p * c for p, c in zip(psi, m)), fmpq_poly([])))
    h = [F(c) for c in g]
    k = 0
    while F.is_zero(_horner(F, h, y)):
        h = F.divide_linear(h, y)
        k += 1
    return _Critical(e, psi, y, k, h) if k >= 2 else None


def _horner(F: RealAlgebraicField, f: list[fmpq_poly], y: fmpq_poly) -> fmpq_poly:
    out = F.zero
    for c in reversed(f):
        out = F(F.mul(out, y) + c)
    return out


@dataclass
class _Event:
    root: RealRoot
    data: _Critical | None
    ylo: fmpq = fmpq(0)
    yhi: fmpq = fmpq(0)
    below: int = 0
    above: int = 0
    left: int = 0
    right: int = 0


def _root_gap(F: RealAlgebraicField, h: list[fmpq_poly], y: fmpq_poly, prec: int) -> fmpq | None:
    """A positive rational below the distance from ``y`` to every root of ``h`` (over Q(c)), with
    the roots of ``h`` certified simple by ball root isolation; None when that fails (``h`` not
    squarefree, or too little precision)."""
    if len(h) <= 1:
        return fmpq(1)
    with flint.ctx.workprec(prec):
        try:
            roots = flint.acb_poly([F.ball(c, prec) for c in h]).roots(maxprec=4 * prec)
        except ValueError:
            return None
        yb = flint.acb(F.ball(y, prec))
        gap = min(arb_bounds((r - yb).abs_lower())[0] for r in roots)
    return gap / 2 if gap > 0 else None


def _no_real_root(F: RealAlgebraicField, h: list[fmpq_poly], lo: fmpq, hi: fmpq, prec: int) -> bool:
    """Certified: ``h`` (over Q(c)) has no root in ``[lo, hi]`` (ball evaluation on pieces)."""
    if len(h) <= 1:
        return True
    with flint.ctx.workprec(prec):
        hb = flint.arb_poly([F.ball(c, prec) for c in h])
        pieces = [(lo, hi)]
        for _ in range(10):
            bad = []
            for a, b in pieces:
                v = hb(arb((a + b) / 2, (b - a) / 2))
                if not (v > 0 or v < 0):
                    bad.append((a, b))
            if not bad:
                return True
            if len(bad) > 64:
                return False
            pieces = [q for a, b in bad for q in ((a, (a + b) / 2), ((a + b) / 2, b))]
    return False


def _clear(p: fmpq_poly, a: fmpq, b: fmpq) -> bool:
    """Whether the polynomial has no root in the closed interval ``[a, b]``."""
    if p.degree() <= 0:
        return not p.is_zero()
    return p(a) != 0 and p(b) != 0 and not isolate_real_roots(p, a, b)


def _locate(g: Biv, ev: _Event) -> None:
    """The interval ``J = (ylo, yhi)`` around ``y_c`` with no other root of ``g(c, Y)`` in it, and a
    window ``[a, b]`` (the root's interval) over which no real point of the image crosses the ends
    of ``J`` (the module's step 4).  _Degenerate when ``h`` has a multiple root (another critical
    point of the image over ``c``)."""
    F = RealAlgebraicField(ev.root)
    for prec in (128, 256, 512, 1024, 2048):
        F.refine((F.root.hi - F.root.lo) / 2 ** (prec // 2))
        gap = _root_gap(F, ev.data.h, ev.data.y, prec)
        if gap is None:
            continue
        lo, hi = arb_bounds(F.ball(ev.data.y, prec))
        if hi - lo < gap / 4:
            mid = (lo + hi) / 2
            delta = _dyadic_below(gap / 2)
            if _no_real_root(F, ev.data.h, mid - delta, mid + delta, prec):
                break
    else:
        raise _Degenerate()
    ev.root, ev.ylo, ev.yhi = F.root, mid - delta, mid + delta
    ends = (at_y(g, ev.ylo), at_y(g, ev.yhi))
    while not all(_clear(p, ev.root.lo, ev.root.hi) for p in ends):
        ev.root = ev.root.refined((ev.root.hi - ev.root.lo) / 4)


def _dyadic_below(x: fmpq) -> fmpq:
    """A power of two in ``(x/2, x]`` (short numbers for the ends of ``J``)."""
    k = 0
    while fmpq(2) ** k > x:
        k -= 1
    while fmpq(2) ** (k + 1) <= x:
        k += 1
    return fmpq(2) ** k


def _split(g: Biv, x: fmpq, ylo: fmpq, yhi: fmpq) -> tuple[int, int, int]:
    """How many real roots of ``g(x, Y)`` lie below ``ylo``, in ``(ylo, yhi)``, above ``yhi``."""
    counts = [0, 0, 0]
    for r in isolate_real_roots(at_x(g, x)):
        while r.lo < ylo < r.hi or r.lo < yhi < r.hi:
            r = r.refined((r.hi - r.lo) / 4)
        counts[0 if r.hi <= ylo else 2 if r.lo >= yhi else 1] += 1
    return counts[0], counts[1], counts[2]


def _roots_at(g: Biv, x: fmpq) -> int:
    """The number of real roots of ``g(x, Y)`` (real points of the image over ``x``)."""
    p = at_x(g, x)
    return len(isolate_real_roots(p)) if p.degree() > 0 else 0


class _Union:
    def __init__(self) -> None:
        self.parent: list[int] = []

    def add(self) -> int:
        self.parent.append(len(self.parent))
        return len(self.parent) - 1

    def find(self, i: int) -> int:
        while self.parent[i] != i:
            self.parent[i] = self.parent[self.parent[i]]
            i = self.parent[i]
        return i

    def union(self, i: int, j: int) -> None:
        self.parent[self.find(i)] = self.find(j)


# --- the sweep ------------------------------------------------------------------------------

class _Sweep:
    """One attempt with the forms ``l`` and ``m`` (raises _Degenerate to ask for others)."""

    def __init__(self, gens: list[Poly], ring: PolyRing, fib: Fibres, crit, m: list[fmpq], width: fmpq | None) -> None:
        self.gens, self.ring, self.fib, self.crit, self.m, self.width = gens, ring, fib, crit, m, width
        self.g = fib.plane_curve(m)
        try:
            e = event_polynomial(self.g)
        except RealSolvingError:
            raise _Degenerate() from None
        found = []
        for f in irreducible_factors(e):
            rs = isolate_real_roots(f)
            if rs:
                data = _critical_data(self.g, f, rs[0], crit, m)
                found += [(r, data) for r in rs]
        self.events = [_Event(r, d) for r, d in _match(separate([r for r, _ in found]), found)]
        self.half: dict[int, list[int]] = {}
        self.minors: list[Poly] | None = None
        self.second: list[tuple[list[fmpq], fmpz_poly]] = []

    def topology(self) -> tuple[list[Circuit], list[Box]]:
        g, events = self.g, self.events
        for ev in events:
            if ev.data is not None:
                _locate(g, ev)
                ev.below, ev.left, ev.above = _split(g, ev.root.lo, ev.ylo, ev.yhi)
                below, ev.right, above = _split(g, ev.root.hi, ev.ylo, ev.yhi)
                if (below, above) != (ev.below, ev.above):
                    raise RealSolvingError("internal: the regular points differ on the two sides of an event")
        samples = [events[0].root.lo] + [ev.root.hi for ev in events] if events else [fmpq(0)]
        counts = [_roots_at(g, s) for s in samples]
        uf = _Union()
        arcs = [[uf.add() for _ in range(k)] for k in counts]
        points: dict[int, Box] = {}
        for j, ev in enumerate(events):
            if ev.data is None:
                self._through(ev, arcs[j], arcs[j + 1], uf)
            else:
                self._critical_point(ev, arcs[j], arcs[j + 1], uf, points)
        return self._components(samples, arcs, uf, points)

    def _through(self, ev: _Event, left: list[int], right: list[int], uf: _Union) -> None:
        """An event without critical point of ``l`` (step 5): every arc goes on."""
        if len(left) != len(right):
            raise RealSolvingError("internal: arcs end at an event without critical point")
        if len(left) == 1:
            uf.union(left[0], right[0])
        elif len(left) > 1:
            for i, k in enumerate(self._pairs(ev)):
                uf.union(left[i], right[k])

    def _critical_point(self, ev: _Event, left: list[int], right: list[int], uf: _Union,
                        points: dict[int, Box]) -> None:
        """An event at a critical point of ``l`` (step 4): the sweep rule."""
        b, L, R = ev.below, ev.left, ev.right
        if b + L + ev.above != len(left) or b + R + ev.above != len(right):
            raise RealSolvingError("internal: the arc counts differ within a strip")
        if L + R != self._half_branches(ev):
            raise _Degenerate()
        for i in range(b):
            uf.union(left[i], right[i])
        for i in range(ev.above):
            uf.union(left[b + L + i], right[b + R + i])
        node = uf.add()
        points[node] = self._point_box(ev)
        for i in range(L):
            uf.union(node, left[b + i])
        for i in range(R):
            uf.union(node, right[b + i])

    def _half_branches(self, ev: _Event) -> int:
        """The real half-branches at the critical point over the event (2 when it is smooth)."""
        data = ev.data
        F = RealAlgebraicField(ev.root)
        n = self.ring.nvars
        if self.minors is None:
            rows = [[f.diff(i) for i in range(n)] for f in self.gens]
            self.minors = [p for p in minors(Matrix(self.ring, len(rows), n, [p for r in rows for p in r]), n - 1)
                           if not p.is_zero()]
        if any(not F.is_zero(_eval_over(F, p, data.psi)) for p in self.minors):
            return 2
        key = id(data)
        if key not in self.half:
            self.half[key] = half_branch_counts(self.gens, self.ring, PointFamily(data.poly, data.psi))
        fam_roots = separate(isolate_real_roots(data.poly))
        r = ev.root
        while True:
            hits = [i for i, q in enumerate(fam_roots) if q.lo < r.hi and r.lo < q.hi]
            if len(hits) == 1:
                return self.half[key][hits[0]]
            r = r.refined((r.hi - r.lo) / 4)

    def _point_box(self, ev: _Event) -> Box:
        F = RealAlgebraicField(ev.root)
        prec = 128
        while True:
            box = [arb_bounds(F.ball(c, prec)) for c in ev.data.psi]
            if all(hi - lo <= (self.width or fmpq(1, 10 ** 6)) for lo, hi in box):
                return box
            F.refine((F.root.hi - F.root.lo) / 2 ** 32)
            prec += 64

    def _pairs(self, ev: _Event) -> list[int]:
        """For each arc left of the event (in ``m``-order) the arc right of it on the same branch:
        through a window free of events of a second image ``(l, m2)``, by the ``m2``-order of the
        real points of the fibres at the window's ends."""
        n = self.ring.nvars
        for attempt in range(8):
            if attempt == len(self.second):
                m2 = _forms(n, 700 + attempt, 1, 2 * attempt)[0]
                try:
                    self.second.append((m2, event_polynomial(self.fib.plane_curve(m2))))
                except RealSolvingError:
                    self.second.append((m2, fmpz_poly([0])))
            m2, e2 = self.second[attempt]
            if e2.is_zero() or sign_at(e2, ev.root) == 0:
                continue
            r = ev.root
            while not _clear(fmpq_poly(e2), r.lo, r.hi):
                r = r.refined((r.hi - r.lo) / 4)
            left, right = self._m2_ranks(r.lo, m2), self._m2_ranks(r.hi, m2)
            return [right.index(rank) for rank in left]
        raise _Degenerate()

    def _m2_ranks(self, a: fmpq, m2: list[fmpq]) -> list[int]:
        """For the real fibre points over ``a`` in ``m``-order, their ranks in ``m2``-order."""
        rep = rur_of(self.fib.algebra(a), self.m)
        roots = rep.real_roots()
        val = rep.value(linear_poly(rep.ring, m2))
        k = 64
        while True:
            encl = []
            for i, r in enumerate(roots):
                rr = r.refined(fmpq(1, 2 ** k)) if r.exact is None else r
                with flint.ctx.workprec(k + 64):
                    encl.append((arb_bounds(ball_eval(val, rr.ball(k + 64))), i))
            encl.sort()
            if all(p[0][1] < q[0][0] for p, q in zip(encl, encl[1:])):
                ranks = [0] * len(roots)
                for rank, (_, i) in enumerate(encl):
                    ranks[i] = rank
                return ranks
            k *= 2

    def _components(self, samples: list[fmpq], arcs: list[list[int]], uf: _Union,
                    points: dict[int, Box]) -> tuple[list[Circuit], list[Box]]:
        """Circuits from the classes of arcs (with a sample point on each arc unless the width
        is None), isolated points from the critical points without arcs."""
        members: dict[int, list[Box]] = {}
        ends: dict[int, int] = {}
        last = len(arcs) - 1
        for j, strip in enumerate(arcs):
            boxes: list[Box] = []
            if strip and self.width is not None:
                rep = rur_of(self.fib.algebra(samples[j]), self.m)
                boxes = [b for _, b in solution_boxes(rep, rep.real_roots(), self.width)]
            for i, node in enumerate(strip):
                root = uf.find(node)
                members.setdefault(root, []).extend(boxes[i:i + 1])
                if j in (0, last):
                    ends[root] = ends.get(root, 0) + 1
        isolated = []
        for node, box in points.items():
            root = uf.find(node)
            if root in members:
                members[root].append(box)
            else:
                isolated.append(box)
        circuits = [Circuit(boxes, _hull(boxes) if boxes else [], root not in ends, ends.get(root, 0))
                    for root, boxes in members.items()]
        return circuits, isolated


def _eval_over(F: RealAlgebraicField, p: Poly, coords: list[fmpq_poly]) -> fmpq_poly:
    """``p(coords)`` in ``Q(c)``."""
    out = F.zero
    for e, c in p.terms.items():
        t = fmpq_poly([c])
        for x, k in zip(coords, e):
            if k:
                t = F.mul(t, x ** k)
        out = out + t
    return F(out)


def _hull(boxes: list[Box]) -> Box:
    return [(min(b[i][0] for b in boxes), max(b[i][1] for b in boxes)) for i in range(len(boxes[0]))]


def _match(sep: list[RealRoot], found: list[tuple[RealRoot, _Critical | None]]) -> list[tuple[RealRoot, _Critical | None]]:
    """The separated roots with their factors' data (a separated root refines an original one:
    same polynomial, nested interval)."""
    return [(r, next(d for q, d in found if q.poly == r.poly and q.lo <= r.lo and r.hi <= q.hi)) for r in sep]


# --- the entry point -------------------------------------------------------------------------

def _topology(gens: list[Poly], ring: PolyRing, width: fmpq | None) -> tuple[list[Circuit], list[Box], int, list]:
    n = ring.nvars
    basis = groebner(gens, ring)
    for attempt, ell in enumerate(_forms(n, 1, 12)):
        if not is_finite(basis, ell):
            continue
        try:
            crit = _critical(gens, ring, ell)
        except _Degenerate:
            continue
        fib = Fibres(gens, ring, ell)
        for m in _forms(n, 100 + attempt, 4, attempt):
            if all(m[i] * ell[j] == m[j] * ell[i] for i in range(n) for j in range(i)):
                continue
            try:
                sweep = _Sweep(gens, ring, fib, crit, m, width)
                circuits, isolated = sweep.topology()
                return circuits, isolated, len(sweep.events), [ell, m]
            except _Degenerate:
                continue
    raise RealSolvingError("no projection of the curve in generic position found")


def curve_topology(gens: Sequence[Poly], ring: PolyRing | None = None, digits: int | None = 6) -> CurveTopology:
    """The circuits (connected components of the real points) and isolated real points of the
    curve ``V(gens)`` over QQ; a sample point on every arc of a circuit, in a box of width
    ``10^-digits`` (none when ``digits`` is None: counting is faster).  A 0-dimensional ideal gives
    only isolated points; RealSolvingError for a component of dimension two or more."""
    ring = ring or gens[0].ring
    if ring.field != QQ:
        raise RealSolvingError("real curves need rational coefficients (the field QQ)")
    R = dp_ring(ring)
    width = None if digits is None else fmpq(1, 10 ** digits)
    gens = [Poly(R, g.terms) for g in gens if not g.is_zero()]
    basis = groebner(gens, R)
    if any(g.is_constant() for g in basis):
        return CurveTopology([], [])
    if basis and dimension(basis, R) == 0:
        return CurveTopology([], [s.box for s in real_solutions(basis, R, digits or 6).real])
    chart = _Chart(gens, basis, R)
    if len(chart.free) == 1:
        origin = chart.lift([(fmpq(0), fmpq(0))])
        return CurveTopology([Circuit([origin], origin, False, 2)], [])
    curve, point_ideals = curve_part(chart.gens, chart.ring)
    isolated = [s.box for P in point_ideals for s in real_solutions(P, chart.ring, digits or 6).real]
    circuits, more, events, proj = _topology(curve, chart.ring, width)
    for c in circuits:
        c.samples = [chart.lift(b) for b in c.samples]
        c.box = chart.lift(c.box) if c.box else []
    return CurveTopology(circuits, [chart.lift(b) for b in isolated + more], events, proj)
