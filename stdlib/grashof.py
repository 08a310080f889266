"""Grashof classification of a planar four-bar linkage from its four link lengths.

With ``s`` the shortest, ``l`` the longest and ``p``, ``q`` the other two lengths, Grashof's
criterion (Grashof 1883; e.g. Norton, *Design of Machinery*, sec. 2.12) says: if
``s + l < p + q`` some link turns fully relative to the others, and which one is decided by
where the shortest link sits (next to the ground: a crank-rocker; the ground itself: a
double-crank or drag link; the coupler: a double-rocker); if ``s + l = p + q`` the linkage has
change points, configurations where all four links are aligned and two circuits meet; if
``s + l > p + q`` no link turns fully (a non-Grashof triple rocker).

:func:`four_bar` recognises a four-bar in a :class:`~mech.stdlib.mechanism.Mechanism`: two
fixed points (the ground link) and three links chained from one to the other, every length a
rational number (a body contributes the distance between its two jointed points).
"""
from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from math import isqrt
from typing import Optional

from .mechanism import Length, Mechanism

#: The five kinds, in the order they are discussed in docs/mechanisms.md.
KINDS = ("crank-rocker", "double-crank", "double-rocker", "change point", "non-Grashof")
_ROLES = ("ground", "crank", "coupler", "rocker")


@dataclass(frozen=True)
class GrashofType:
    """A four-bar's Grashof class: ``kind`` (one of :data:`KINDS`), the inequality with the
    lengths (``s + l < p + q: ...``), whether the Grashof condition ``s + l <= p + q`` holds, which
    link is the shortest, and a sentence saying which links turn fully."""

    kind: str
    inequality: str
    grashof: bool
    shortest: str = ""
    description: str = ""


def _fmt(x: Fraction) -> str:
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def grashof(ground: Fraction, crank: Fraction, coupler: Fraction, rocker: Fraction) -> GrashofType:
    """The Grashof class of the four-bar with these link lengths; ``crank`` is the input link
    (pivoted on the ground's first point), ``rocker`` the output link. Lengths must be positive."""
    lengths = [Fraction(ground), Fraction(crank), Fraction(coupler), Fraction(rocker)]
    if any(x <= 0 for x in lengths):
        raise ValueError("four-bar link lengths must be positive")
    s_i = min(range(4), key=lengths.__getitem__)
    l_i = max(range(4), key=lengths.__getitem__)
    if s_i == l_i:  # all four equal
        l_i = 1 if s_i == 0 else 0
    s, l = lengths[s_i], lengths[l_i]
    p, q = sorted(lengths[i] for i in range(4) if i not in (s_i, l_i))
    lhs, rhs = s + l, p + q
    rel = "<" if lhs < rhs else "=" if lhs == rhs else ">"
    inequality = (f"s + l {rel} p + q: {_fmt(s)} + {_fmt(l)} {rel} {_fmt(p)} + {_fmt(q)} "
                  f"(shortest {_ROLES[s_i]} {_fmt(s)}, longest {_ROLES[l_i]} {_fmt(l)})")
    shortest = _ROLES[s_i]
    if rel == "<":
        if shortest == "ground":
            kind, text = "double-crank", "drag link: the crank and the rocker both turn fully"
        elif shortest == "coupler":
            kind, text = "double-rocker", ("Grashof double-rocker: the coupler turns fully, "
                                           "the crank and the rocker only rock")
        elif shortest == "crank":
            kind, text = "crank-rocker", "the crank turns fully, the rocker rocks"
        else:
            kind, text = "crank-rocker", "rocker-crank: the output link turns fully, the input link rocks"
    elif rel == "=":
        kind, text = "change point", ("all four links can be aligned; there two real branches cross "
                                      "and the linkage can switch circuits")
    else:
        kind = "non-Grashof"
        if l > s + p + q:
            text = "the longest link exceeds the sum of the others: the linkage cannot be assembled"
        elif l == s + p + q:
            text = "the longest link equals the sum of the others: a single, stretched configuration"
        else:
            text = "triple rocker: no link turns fully"
    return GrashofType(kind, inequality, rel != ">", shortest, text)


@dataclass(frozen=True)
class FourBar:
    """A four-bar recognised in a mechanism: the lengths of the ground, the crank (pivoted at the
    first ground point ``pivots[0]``), the coupler and the rocker; the joint points in loop order
    ``(ground pivot of the crank, crank-coupler joint, coupler-rocker joint, ground pivot of the
    rocker)``; the indices (1-based, as in ``c_i, s_i``) of the crank, coupler and rocker links."""

    ground: Fraction
    crank: Fraction
    coupler: Fraction
    rocker: Fraction
    joints: tuple[str, str, str, str]
    links: tuple[int, int, int]

    def classify(self) -> GrashofType:
        return grashof(self.ground, self.crank, self.coupler, self.rocker)


def _rational(v: Length, values: dict[str, Length]) -> Optional[Fraction]:
    if isinstance(v, str):
        v = values.get(v, v)
    return None if isinstance(v, str) else Fraction(v)


def _sqrt(q: Fraction) -> Optional[Fraction]:
    """The rational square root of ``q >= 0``, if there is one."""
    n, d = isqrt(q.numerator), isqrt(q.denominator)
    return Fraction(n, d) if n * n == q.numerator and d * d == q.denominator else None


def _distance(a: tuple[Fraction, Fraction], b: tuple[Fraction, Fraction]) -> Optional[Fraction]:
    return _sqrt((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2)


def four_bar(m: Mechanism, values: Optional[dict[str, Length]] = None) -> Optional[FourBar]:
    """The four-bar in ``m`` (two fixed points, three revolute links chained between them, no
    sliders, every length rational after ``values``), or None if ``m`` is not one. A body may
    carry extra (tracer) points; only its two jointed points count."""
    values = values or {}
    if len(m.fixed) != 2 or len(m.links) != 3 or m.sliders or any(k.prismatic for k in m.links):
        return None
    fixed = {}
    for name, (x, y) in m.fixed.items():
        fx, fy = _rational(x, values), _rational(y, values)
        if fx is None or fy is None:
            return None
        fixed[name] = (fx, fy)
    # the points each link holds, with local coordinates (the near point at the origin)
    local: list[dict[str, tuple[Fraction, Fraction]]] = []
    for k in m.links:
        pts = {k.points[0]: (Fraction(0), Fraction(0))}
        for p, (u, v) in zip(k.points[1:], k.local):
            fu, fv = _rational(u, values), _rational(v, values)
            if fu is None or fv is None:
                return None
            pts[p] = (fu, fv)
        local.append(pts)
    count: dict[str, int] = {}
    for pts in local:
        for p in pts:
            count[p] = count.get(p, 0) + 1
    # joints: points shared by two links, or a fixed point on a link
    joints = {p for p, c in count.items() if c >= 2 or p in fixed}
    ends = [{p for p in pts if p in joints} for pts in local]
    if any(len(e) != 2 for e in ends) or not all(p in count for p in fixed):
        return None
    order = list(m.fixed)
    start, goal = order[0], order[1]
    path, links, at, used = [start], [], start, set()
    for _ in range(3):
        nxt = [i for i, e in enumerate(ends) if at in e and i not in used]
        if len(nxt) != 1:
            return None
        i = nxt[0]
        used.add(i)
        (at,) = ends[i] - {at}
        path.append(at)
        links.append(i)
    if at != goal or len(set(path)) != 4 or any(p in fixed for p in path[1:3]):
        return None
    lengths = [_distance(fixed[start], fixed[goal])]
    for i, a, b in zip(links, path, path[1:]):
        lengths.append(_distance(local[i][a], local[i][b]))
    if any(x is None or x == 0 for x in lengths):
        return None
    g, a, b, c = lengths
    return FourBar(g, a, b, c, tuple(path), tuple(i + 1 for i in links))
