"""Special points of a curve on its plane image, located exactly (the sweep of :mod:`.real_curve`).

The plane image ``g(X, Y) = 0`` (``g`` monic in ``Y``) of a curve by ``(l, m)``; a special point is
a real point ``p`` of the curve over a real algebraic ``c = l(p)``, known in ``Q(c)`` (a factor of
a representation parametrised by ``l``): a critical point of ``l``, or a mark (a point to place on
its circuit, e.g. a critical point of a coordinate).  Its image ``(c, y)``, ``y = m(p)``, is a root
of ``g(c, Y)`` of multiplicity ``k``; ``h = g(c, Y)/(Y - y)^k``.

:func:`locate` certifies the position of ``(c, y)`` among the real points of the image over a
rational window ``[a, b]`` around ``c``: an interval ``J`` around ``y`` on which ``h`` has no root
(ball arithmetic, ``h`` checked squarefree by ball root isolation) and a window over which ``g(X,
ends of J)`` has no root (exact root counts).  Then the real roots of ``g(a, Y)`` inside ``J`` are
exactly the arcs arriving from the left at ``(c, y)``, those below and above ``J`` arrive at other
points (:func:`split` counts them); the same at ``b``.
"""
from __future__ import annotations

from dataclasses import dataclass

import flint
from flint import arb, fmpq, fmpq_poly, fmpz_poly

from .real_field import RealAlgebraicField
from .real_fibers import Biv, at_x, at_y
from .real_roots import RealRoot, isolate_real_roots
from .real_solve import RUR, arb_bounds


class Degenerate(Exception):
    """The projection is not in generic position here: choose another."""


@dataclass
class Special:
    """The special points over the roots of the irreducible ``poly``: coordinates ``psi`` and
    ``y = m(psi)`` in ``Q(c)``, ``y`` of multiplicity ``k`` in ``g(c, Y)``, ``h = g(c, Y)/(Y - y)^k``;
    ``mark`` for a point to place (not a critical point of ``l``)."""

    poly: fmpz_poly
    psi: list[fmpq_poly]
    y: fmpq_poly
    k: int
    h: list[fmpq_poly]
    mark: bool = False


def special(g: Biv, e: fmpz_poly, root: RealRoot, rep: RUR, m: list[fmpq], mark: bool) -> Special | None:
    """The special points over the roots of ``e`` (a factor of ``rep.poly``) with their image's
    multiplicity in ``g(c, Y)`` (field operations without inversions); None when ``e`` does not
    divide ``rep.poly`` or, for a critical point, when its image is not critical for ``g``."""
    if not (fmpq_poly(rep.poly) % fmpq_poly(e)).is_zero():
        return None
    F = RealAlgebraicField(root)
    psi = [F(s) for s in rep.shape]
    y = F(sum((p * c for p, c in zip(psi, m)), fmpq_poly([])))
    h = [F(c) for c in g]
    k = 0
    while F.is_zero(_horner(F, h, y)):
        h = F.divide_linear(h, y)
        k += 1
    if k == 0:
        raise RuntimeError("internal: a point of the curve off its plane image")
    if k < 2 and not mark:
        return None
    return Special(e, psi, y, k, h, mark)


def _horner(F: RealAlgebraicField, f: list[fmpq_poly], y: fmpq_poly) -> fmpq_poly:
    out = F.zero
    for c in reversed(f):
        out = F(F.mul(out, y) + c)
    return out


def same_point(root: RealRoot, a: Special, b: Special) -> bool:
    """Whether two special points over the same ``c`` coincide (exact, in ``Q(c)``)."""
    F = RealAlgebraicField(root)
    return all(F.is_zero(p - q) for p, q in zip(a.psi, b.psi))


@dataclass
class Event:
    """An event ``c`` of the sweep (its root's interval is the window), the special point over it
    if any, and once located: ``J = (ylo, yhi)`` and the real arcs below, inside (left, right)
    and above ``J``."""

    root: RealRoot
    data: Special | None
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


def clear(p: fmpq_poly, a: fmpq, b: fmpq) -> bool:
    """Whether the polynomial has no root in the closed interval ``[a, b]``."""
    if p.degree() <= 0:
        return not p.is_zero()
    return p(a) != 0 and p(b) != 0 and not isolate_real_roots(p, a, b)


def _dyadic_below(x: fmpq) -> fmpq:
    """A power of two in ``(x/2, x]`` (short numbers for the ends of ``J``)."""
    k = 0
    while fmpq(2) ** k > x:
        k -= 1
    while fmpq(2) ** (k + 1) <= x:
        k += 1
    return fmpq(2) ** k


def locate(g: Biv, ev: Event) -> None:
    """``J`` around ``y`` and the window around ``c``, then the counts at the window's ends.
    Degenerate when ``h`` has a multiple root (another special point of the image over ``c``)."""
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
        raise Degenerate()
    ev.root, ev.ylo, ev.yhi = F.root, mid - delta, mid + delta
    ends = (at_y(g, ev.ylo), at_y(g, ev.yhi))
    while not all(clear(p, ev.root.lo, ev.root.hi) for p in ends):
        ev.root = ev.root.refined((ev.root.hi - ev.root.lo) / 4)
    ev.below, ev.left, ev.above = split(g, ev.root.lo, ev.ylo, ev.yhi)
    below, ev.right, above = split(g, ev.root.hi, ev.ylo, ev.yhi)
    if (below, above) != (ev.below, ev.above):
        raise RuntimeError("internal: the regular points differ on the two sides of an event")


def split(g: Biv, x: fmpq, ylo: fmpq, yhi: fmpq) -> tuple[int, int, int]:
    """How many real roots of ``g(x, Y)`` lie below ``ylo``, in ``(ylo, yhi)``, above ``yhi``."""
    counts = [0, 0, 0]
    for r in isolate_real_roots(at_x(g, x)):
        while r.lo < ylo < r.hi or r.lo < yhi < r.hi:
            r = r.refined((r.hi - r.lo) / 4)
        counts[0 if r.hi <= ylo else 2 if r.lo >= yhi else 1] += 1
    return counts[0], counts[1], counts[2]


def roots_at(g: Biv, x: fmpq) -> int:
    """The number of real roots of ``g(x, Y)`` (real points of the image over ``x``)."""
    p = at_x(g, x)
    return len(isolate_real_roots(p)) if p.degree() > 0 else 0


def point_box(ev: Event, width: fmpq) -> list[tuple[fmpq, fmpq]]:
    """A box of width at most ``width`` around the special point of the event."""
    F = RealAlgebraicField(ev.root)
    prec = 128
    while True:
        box = [arb_bounds(F.ball(c, prec)) for c in ev.data.psi]
        if all(hi - lo <= width for lo, hi in box):
            return box
        F.refine((F.root.hi - F.root.lo) / 2 ** 32)
        prec += 64
