"""The real topology of an algebraic curve over QQ: its circuits (connected components of the
real points) with certified bounding boxes, isolated real points and unbounded branches, exactly.

The method is a sweep (cylindrical decomposition) of a generic plane image, in the spirit of
Gonzalez-Vega and El Kahoui ("An improved upper complexity bound for the topology computation of
a real algebraic plane curve", 1996), Gonzalez-Vega and Necula (2002) and, for space curves,
Gatellier, Labrouzy, Mourrain and Técourt ("Computing the topology of three-dimensional algebraic
curves", 2005); every generic-position assumption is checked, and a failed check means another
projection.  docs/real.md explains the steps; in short:

1. Linear equations of the curve are solved (an affine chart); the curve is made radical with its
   one-dimensional components (0-dimensional ones are isolated points), :func:`.real_fibers.curve_part`.
2. A linear form ``l`` finite on the curve; its critical points (the curve and the maximal minors
   of the Jacobian of ``n - 1`` combinations of the generators and ``l``), zero-dimensional, with
   ``l`` separating them (one per fibre).
3. A second form ``m``: the plane image ``g(X, Y) = 0`` of ``(l, m)`` (:class:`.real_fibers.Fibres`,
   squarefree: birational); its events are the real roots of the discriminant in ``Y``.  Between
   events the real arcs of the image do not cross, so an arc is named by its rank in ``Y``.
4. An event ``c`` where a critical point ``p`` of ``l`` maps to a critical point of the image: the
   arcs ending there are certified by :func:`.real_events.locate`; they belong to ``p``, their number
   must equal the real half-branches at ``p`` (2 if smooth, else
   :func:`.real_branches.half_branch_counts`), so no other real point maps there (else another ``m``).
5. At any other event every point over ``c`` is smooth and not critical for ``l``: each real arc goes
   on, possibly crossing others in the image; the two sides are matched through a window free of
   events of a second image ``(l, m2)``, by the ``m2``-order of the real points of the rational
   fibres at the window's ends.
6. With sample points asked for, the critical points of each coordinate are marks located on their
   arcs (:func:`.real_events.locate` again): a coordinate's extremes on a bounded circuit are at its
   critical points or at critical points of ``l`` (the singular points among them), so the box of all
   these points is a certified bounding box.
7. Arcs and critical points form a graph; its connected components are the circuits, critical
   points without arcs are isolated points, arcs over the two unbounded strips are unbounded ends.
"""
from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Sequence

import flint
from flint import fmpq, fmpq_poly, fmpz_poly, fmpz_mod_poly_ctx, fq_default_ctx

from .coeffs import QQ
from .groebner import groebner
from .ideals import dimension, dp_ring
from .matrix import Matrix, minors
from .poly import Poly, PolyRing
from .real_branches import PointFamily, half_branch_counts
from .real_chart import Chart
from .real_events import Degenerate, Event, Special, clear, locate, point_box, roots_at, same_point, special
from .real_fibers import (Biv, Fibres, at_x, complete_intersection, curve_part, event_polynomial, irreducible_factors,
                          is_finite, linear_poly)
from .real_roots import RealRoot, RealSolvingError, isolate_real_roots, separate, vanishes_at
from .real_solve import RUR, NotSeparatingError, QuotientAlgebra, arb_bounds, ball_eval, real_solutions, rur_of, \
    solution_boxes

Box = list[tuple[fmpq, fmpq]]


@dataclass
class Circuit:
    """A connected component of the real points: ``samples`` (boxes of a point on one of its arcs,
    of its critical points and of its coordinates' extreme points), ``box`` (their hull: a bounding
    box of the circuit when ``certified``), whether it is ``bounded``, its ends at infinity."""

    samples: list[Box]
    box: Box
    bounded: bool
    ends: int
    certified: bool = False


@dataclass
class CurveTopology:
    """The circuits and the isolated real points of a real algebraic curve."""

    circuits: list[Circuit]
    isolated: list[Box]

    @property
    def count(self) -> int:
        return len(self.circuits)

    @property
    def bounded(self) -> bool:
        return all(c.bounded for c in self.circuits)


# --- forms and critical points ----------------------------------------------------------------

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


def _critical_algebra(gens: list[Poly], ring: PolyRing, direction: list[fmpq]) -> QuotientAlgebra | None:
    """The algebra of the critical points of the linear form ``direction`` on the curve (the curve
    and the maximal minors of the Jacobian of ``n - 1`` generators or combinations of them, and the
    form); None when they are not isolated (the form is constant on a component).  ``n - 1``
    generators of least degree cutting out a curve (a mechanism's constraints within its mode's
    ideal) come first: their Jacobian has low degree, where random combinations of all the
    generators give a determinant of high degree and many spurious points."""
    n = ring.nvars
    for seed in ([None] if len(gens) == n - 1 else ["ci"] + list(range(4))):
        if seed == "ci":
            h = complete_intersection(gens, ring)
            if h is None:
                continue
        else:
            rnd = random.Random(seed)
            h = gens if seed is None else [sum((g * rnd.randint(-3, 3) for g in gens), ring.zero())
                                          for _ in range(n - 1)]
        rows = [[f.diff(i) for i in range(n)] for f in h] + [[ring.const(c) for c in direction]]
        det = [d for d in minors(Matrix(ring, n, n, [p for r in rows for p in r]), n) if not d.is_zero()]
        K = gens + det
        if dimension(K, ring) <= 0:
            return QuotientAlgebra(K, ring)
    return None


def _parametrised(A: QuotientAlgebra, ell: list[fmpq]) -> RUR:
    """The representation of the points of ``A`` with ``l`` as parameter (Degenerate unless ``l``
    separates them)."""
    try:
        return rur_of(A, ell)
    except NotSeparatingError:
        raise Degenerate() from None


class _Union:
    """Union-find over the nodes of the graph (arcs and points)."""

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
    """One attempt with the forms ``l`` and ``m`` (raises Degenerate to ask for others).
    ``marks``: representations (parametrised by ``l``) of points to place on their circuits."""

    def __init__(self, gens: list[Poly], ring: PolyRing, fib: Fibres, crit: RUR, marks: list[RUR],
                 m: list[fmpq], width: fmpq | None) -> None:
        self.gens, self.ring, self.fib, self.m, self.width = gens, ring, fib, m, width
        self.g = fib.plane_curve(m)
        try:
            e = event_polynomial(self.g)
        except RealSolvingError:
            raise Degenerate() from None
        found: list[tuple[RealRoot, Special | None]] = []
        known: dict[tuple, Special | None] = {}  # by factor: the special points already placed
        for f in irreducible_factors(e):
            rs = isolate_real_roots(f)
            if rs:
                known[_key(f)] = special(self.g, f, rs[0], crit, m, False)
                found += [(r, known[_key(f)]) for r in rs]
        for rep in marks:
            for f in irreducible_factors(rep.poly):
                rs = isolate_real_roots(f)
                if not rs:
                    continue
                data = special(self.g, f, rs[0], rep, m, True)
                if _key(f) in known:  # a mark over an event: only the critical point itself is fine
                    if known[_key(f)] is None or not same_point(rs[0], known[_key(f)], data):
                        raise Degenerate()
                    continue
                known[_key(f)] = data
                found += [(r, data) for r in rs]
        self.events = [Event(r, d) for r, d in _match(separate([r for r, _ in found]), found)]
        self.half: dict[int, list[int]] = {}
        self.jacobian: list[list[list[Poly]]] | None = None  # of n - 1 generators, of all
        self.second: list[tuple[list[fmpq], fmpz_poly]] = []

    def topology(self) -> tuple[list[Circuit], list[Box]]:
        g, events = self.g, self.events
        for ev in events:
            if ev.data is not None:
                locate(g, ev)
        samples = [events[0].root.lo] + [ev.root.hi for ev in events] if events else [fmpq(0)]
        counts = [roots_at(g, s) for s in samples]
        uf = _Union()
        arcs = [[uf.add() for _ in range(k)] for k in counts]
        points: dict[int, Box] = {}
        for j, ev in enumerate(events):
            left, right = arcs[j], arcs[j + 1]
            sides = (ev.below + ev.left + ev.above, ev.below + ev.right + ev.above)
            if ev.data is not None and sides != (len(left), len(right)):
                raise RuntimeError("internal: the arc counts differ within a strip")
            if ev.data is None:
                self._through(ev, left, right, uf)
            elif ev.data.mark:
                self._mark(ev, left, right, uf, points)
            else:
                self._critical_point(ev, left, right, uf, points)
        return self._components(samples, arcs, uf, points)

    def _through(self, ev: Event, left: list[int], right: list[int], uf: _Union) -> None:
        """An event without critical point of ``l`` (step 5): every arc goes on."""
        if len(left) != len(right):
            raise RuntimeError("internal: arcs end at an event without critical point")
        if len(left) == 1:
            uf.union(left[0], right[0])
        elif len(left) > 1:
            for i, k in enumerate(self._pairs(ev)):
                uf.union(left[i], right[k])

    def _mark(self, ev: Event, left: list[int], right: list[int], uf: _Union, points: dict[int, Box]) -> None:
        """A mark on a regular fibre (no event of the image in the window): arcs keep their ranks,
        the mark lies on the arc of rank ``below``."""
        if (ev.left, ev.right) != (1, 1) or len(left) != len(right):
            raise RuntimeError("internal: a mark off its arc")
        for a, b in zip(left, right):
            uf.union(a, b)
        if self.width is not None:
            node = uf.add()
            points[node] = point_box(ev, self.width)
            uf.union(node, left[ev.below])

    def _critical_point(self, ev: Event, left: list[int], right: list[int], uf: _Union,
                        points: dict[int, Box]) -> None:
        """An event at a critical point of ``l`` (step 4): the sweep rule."""
        b, L, R = ev.below, ev.left, ev.right
        if L + R != self._half_branches(ev):
            raise Degenerate()
        for i in range(b):
            uf.union(left[i], right[i])
        for i in range(ev.above):
            uf.union(left[b + L + i], right[b + R + i])
        node = uf.add()
        points[node] = point_box(ev, self.width or fmpq(1, 10 ** 6))
        for i in range(L):
            uf.union(node, left[b + i])
        for i in range(R):
            uf.union(node, right[b + i])

    def _half_branches(self, ev: Event) -> int:
        """The real half-branches at the critical point over the event (2 when it is smooth)."""
        data = ev.data
        n = self.ring.nvars
        if self.jacobian is None:
            ci = complete_intersection(self.gens, self.ring) or []
            self.jacobian = [[[f.diff(i) for i in range(n)] for f in part] for part in (ci, self.gens)]
        if any(_rank_mod_p(rows, data.poly, data.psi) == n - 1 for rows in self.jacobian if rows):
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

    def _pairs(self, ev: Event) -> list[int]:
        """For each arc left of the event (in ``m``-order) the arc right of it on the same branch:
        through a window free of events of a second image ``(l, m2)``, by the ``m2``-order of the
        real points of the fibres at the window's ends."""
        n = self.ring.nvars
        for attempt in range(8):
            if attempt == len(self.second):
                m2 = _forms(n, 700 + attempt, 1, 2 * attempt)[0]
                try:
                    g2 = self.fib.plane_curve(m2)
                    self.second.append((m2, event_polynomial(g2), g2,
                                        self.fib.plane_curve([a + b for a, b in zip(self.m, m2)])))
                except RealSolvingError:
                    self.second.append((m2, fmpz_poly([0]), [], []))
            m2, e2, g2, g3 = self.second[attempt]
            if e2.is_zero() or vanishes_at(e2, ev.root):
                continue
            r = ev.root
            while not clear(fmpq_poly(e2), r.lo, r.hi):
                r = r.refined((r.hi - r.lo) / 4)
            left, right = (_plane_ranks(self.g, g2, g3, a) or self._m2_ranks(a, m2) for a in (r.lo, r.hi))
            return [right.index(rank) for rank in left]
        raise Degenerate()

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
        """Circuits from the classes of arcs, with a sample point on one of their arcs (unless the
        width is None) and their special points; isolated points from the critical points without
        arcs."""
        members: dict[int, list[Box]] = {}
        ends: dict[int, int] = {}
        last = len(arcs) - 1
        for j, strip in enumerate(arcs):
            roots = [uf.find(node) for node in strip]
            for root in roots:
                members.setdefault(root, [])
                if j in (0, last):
                    ends[root] = ends.get(root, 0) + 1
            if self.width is not None and any(not members[root] for root in roots):
                rep = rur_of(self.fib.algebra(samples[j]), self.m)
                for root, (_, box) in zip(roots, solution_boxes(rep, rep.real_roots(), self.width)):
                    if not members[root]:
                        members[root].append(box)
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


def _plane_ranks(g: Biv, g2: Biv, g3: Biv, a: fmpq) -> list[int] | None:
    """For the real fibre points over ``a`` in ``m``-order their ranks in ``m2``-order, from the
    plane images of ``(l, m)``, ``(l, m2)`` and ``(l, m + m2)`` alone (``a`` no event of the first
    two: their real roots over ``a`` are the values of the real points): the partner of the
    ``m``-value ``y`` is the one ``m2``-value ``z`` with ``y + z`` a root of ``g3(a, Y)``, certified
    when interval arithmetic excludes every other ``z``.  None when that stays ambiguous (a
    coincidence of values: the caller solves the fibre)."""
    polys = [at_x(h, a).numer() for h in (g, g2, g3)]
    for bits in (32, 64, 128, 256, 512):
        ys, zs, ws = (_real_root_balls(p, bits) for p in polys)
        if len(ys) != len(zs):
            return None
        if len(ys) <= 1:
            return list(range(len(ys)))
        ranks = []
        for y in ys:
            hits = [j for j, z in enumerate(zs) if any(y[0] + z[0] <= w[1] and w[0] <= y[1] + z[1] for w in ws)]
            if len(hits) != 1:
                break
            ranks.append(hits[0])
        else:
            if len(set(ranks)) == len(ranks):
                return ranks
    return None


def _real_root_balls(p: fmpz_poly, prec: int) -> list[tuple[fmpq, fmpq]]:
    """Certified enclosures ``(lo, hi)`` of the distinct real roots of ``p``, increasing: flint's
    complex root isolation (``arb_fmpz_poly_complex_roots``: isolating balls, the real roots
    with imaginary part exactly zero) at ``prec`` bits."""
    with flint.ctx.workprec(prec):
        found = [c.real for c, _ in p.complex_roots() if c.imag.is_zero()]
    return sorted(arb_bounds(r) for r in found)


def _rank_mod_p(rows: list[list[Poly]], poly: fmpz_poly, psi: list[fmpq_poly]) -> int:
    """A lower bound for the rank of the polynomial matrix at the points ``x = psi(c)``,
    ``poly(c) = 0``: its rank over ``F_q = F_p[T]/(h)`` for an irreducible factor ``h`` of
    ``poly`` modulo a prime ``p`` (``Z_(p)[T]/(poly) -> F_q`` is a ring map, so the minors vanishing
    at ``c`` vanish there; :mod:`.modular_rank`); 0 when every prime tried divides a denominator."""
    for prime in _PRIMES:
        if poly[poly.degree()] % prime == 0:
            continue
        _, facs = fmpz_mod_poly_ctx(prime)([int(c) for c in poly.coeffs()]).factor()
        h = min((f for f, _ in facs), key=lambda f: f.degree())
        F = fq_default_ctx(modulus=h, check_prime=False)
        t = F.gen()
        try:
            point = [_horner_mod(F, x.coeffs(), t, prime) for x in psi]
            table = [[_value_mod(F, p, point, prime) for p in row] for row in rows]
        except ZeroDivisionError:  # a denominator divisible by the prime
            continue
        return _rank(table)
    return 0


def _coeff_mod(c: fmpq, prime: int) -> int:
    q = int(c.q) % prime
    if q == 0:
        raise ZeroDivisionError
    return int(c.p) * pow(q, -1, prime) % prime


def _horner_mod(F, coeffs: list[fmpq], t, prime: int):
    out = F(0)
    for c in reversed(coeffs):
        out = out * t + F(_coeff_mod(c, prime))
    return out


def _value_mod(F, p: Poly, point: list, prime: int):
    out = F(0)
    for e, c in p.terms.items():
        v = F(_coeff_mod(c, prime))
        for x, k in zip(point, e):
            if k:
                v = v * x ** k
        out += v
    return out


def _rank(m: list[list]) -> int:
    """The rank of a matrix over a finite field (Gaussian elimination)."""
    m = [list(r) for r in m]
    rank = 0
    for col in range(len(m[0]) if m else 0):
        pivot = next((i for i in range(rank, len(m)) if not m[i][col].is_zero()), None)
        if pivot is None:
            continue
        m[rank], m[pivot] = m[pivot], m[rank]
        inv = m[rank][col] ** -1
        for i in range(rank + 1, len(m)):
            if not m[i][col].is_zero():
                q = m[i][col] * inv
                m[i] = [a - q * b for a, b in zip(m[i], m[rank])]
        rank += 1
    return rank


#: Primes for the modular ranks.
_PRIMES = [2 ** 31 - 1, 2147483629, 2147483587, 2147483579, 2147483563, 2147483549, 2147483543, 2147483497]


def _key(f: fmpz_poly) -> tuple:
    return tuple(int(c) for c in f.coeffs())


def _hull(boxes: list[Box]) -> Box:
    return [(min(b[i][0] for b in boxes), max(b[i][1] for b in boxes)) for i in range(len(boxes[0]))]


def _match(sep: list[RealRoot], found: list[tuple[RealRoot, Special | None]]) -> list[tuple[RealRoot, Special | None]]:
    """The separated roots with their factors' data (a separated root refines an original one:
    same polynomial, nested interval)."""
    return [(r, next(d for q, d in found if q.poly == r.poly and q.lo <= r.lo and r.hi <= q.hi)) for r in sep]


# --- the entry point -------------------------------------------------------------------------

def _topology(gens: list[Poly], ring: PolyRing, width: fmpq | None,
              directions: list[list[fmpq]]) -> tuple[list[Circuit], list[Box], bool]:
    """Sweeps with forms ``l`` (finite, separating its critical points and the marks) and ``m``
    until one passes every check; the marks are the critical points of ``directions`` (when
    sample points are asked for).  Returns also whether the circuits' boxes are certified."""
    n = ring.nvars
    basis = groebner(gens, ring)
    algebras = [_critical_algebra(gens, ring, w) for w in (directions if width is not None else [])]
    for attempt, ell in enumerate(_forms(n, 1, 12)):
        if not is_finite(basis, ell):
            continue
        crit_algebra = _critical_algebra(gens, ring, ell)
        if crit_algebra is None:
            continue
        try:
            crit = _parametrised(crit_algebra, ell)
            marks = [_parametrised(A, ell) for A in algebras if A is not None]
        except Degenerate:
            continue
        fib = Fibres(gens, ring, ell)
        for m in _forms(n, 100 + attempt, 4, attempt):
            if all(m[i] * ell[j] == m[j] * ell[i] for i in range(n) for j in range(i)):
                continue
            try:
                circuits, isolated = _Sweep(gens, ring, fib, crit, marks, m, width).topology()
            except Degenerate:
                continue
            return circuits, isolated, width is not None and all(A is not None for A in algebras)
    raise RealSolvingError("no projection of the curve in generic position found")


def curve_topology(gens: Sequence[Poly], ring: PolyRing | None = None, digits: int | None = 6,
                   prime: bool = False) -> CurveTopology:
    """The circuits (connected components of the real points) and isolated real points of the
    curve ``V(gens)`` over QQ; sample points in boxes of width ``10^-digits`` and a certified
    bounding box for each bounded circuit (none when ``digits`` is None: counting is faster).  A
    0-dimensional ideal gives only isolated points; RealSolvingError for a component of dimension
    two or more.  ``prime``: the ideal is known to be prime (a motion mode), so its minimal primes
    are not computed."""
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
    chart = Chart(gens, basis, R)
    if len(chart.free) == 1:
        origin = chart.lift([(fmpq(0), fmpq(0))])
        return CurveTopology([Circuit([origin], origin, False, 2)], [])
    curve, point_ideals = curve_part(chart.gens, chart.ring, prime)
    isolated = [s.box for P in point_ideals for s in real_solutions(P, chart.ring, digits or 6).real]
    circuits, more, certified = _topology(curve, chart.ring, width, chart.directions())
    for c in circuits:  # the hull in the original coordinates (lifting a hull would widen it)
        c.samples = [chart.lift(b) for b in c.samples]
        c.box = _hull(c.samples) if c.samples else []
        c.certified = certified and c.bounded
    return CurveTopology(circuits, [chart.lift(b) for b in isolated + more])
