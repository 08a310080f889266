"""Planar mechanisms: the variables and equations of points in the plane joined by links.

Each link ``i`` (bar, body, prismatic bar) carries an orientation ``(c_i, s_i)`` with
``c_i^2 + s_i^2 - 1 = 0``; its far points are its origin plus its local coordinates rotated by
``(c_i, s_i)`` (a prismatic bar's length is the variable ``d_i``).  Points are placed by walking
the links from the fixed points; a link that reaches an already placed point closes a loop and
yields two polynomials (x and y).  When the walk is stuck, a point on a slider on a fixed line
gets coordinates of its own, ``x_P, y_P`` (a chain without a fixed pivot, such as the elliptic
trammel).  Sliders then give one polynomial each: on a fixed line ``a*x + b*y - c``, on the line
through two points of a link the cross product of the line's direction and ``P - A``.

Constraint order follows the paper: loop constraints, then sliders, then the circles; variables
``c1,s1,c2,s2,...``, prismatic lengths ``d_i``, free coordinates ``x_P,y_P``, and the symbolic
parameters last as their own block, so eliminating the configuration leaves the conditions on
the lengths.
"""
from __future__ import annotations

from fractions import Fraction

from mech.kernel import Poly, PolyRing
from mech.stdlib.joints import Described, Gear, Length, LineSlider, MechanismError, Slider, where


Event = tuple[str, object]  # ("link", (i, link)) or ("free", point)


def walk(m: Described) -> list[Event]:
    """The order in which the links place their points (passes over the links not yet placed,
    in order), with the points that get free coordinates when the walk is stuck."""
    placed = set(m.fixed)
    pending = list(enumerate(m.links, 1))
    events: list[Event] = []
    while pending:
        progress = False
        for item in list(pending):
            i, link = item
            if link.points[0] not in placed and not any(p in placed for p in link.points[1:]):
                continue
            placed.update(link.points)
            events.append(("link", item))
            pending.remove(item)
            progress = True
        if progress:
            continue
        loose = {p for _, link in pending for p in link.points}
        free = next((s.point for s in m.sliders if isinstance(s, Slider) and s.point in loose
                     and s.point not in placed), None)
        if free is None:
            names = ", ".join(link.points[0] for _, link in pending)
            raise MechanismError(f"{m.name}: links at {names} are not connected to a fixed point "
                                 "(nor to a slider on a fixed line)")
        placed.add(free)
        events.append(("free", free))
    return events


def free_points(m: Described) -> list[str]:
    return [p for kind, p in walk(m) if kind == "free"]  # type: ignore[misc]


def variables(m: Described) -> list[str]:
    names: list[str] = []
    for i, _ in enumerate(m.links, 1):
        names += [f"c{i}", f"s{i}"]
    names += [f"d{i}" for i, link in enumerate(m.links, 1) if link.prismatic]
    for p in free_points(m):
        names += [f"x_{p}", f"y_{p}"]
    return names


def positions(m: Described, R: PolyRing, values: dict[str, Length]
              ) -> tuple[dict[str, tuple[Poly, ...]], list[Poly]]:
    """Each point's coordinates as polynomials of ``R`` and the closure polynomials of the loops
    and sliders."""
    gens = dict(zip(R.names, R.gens()))

    def val(v: Length) -> Poly:
        if isinstance(v, str):
            v = values.get(v, v)
        if isinstance(v, str):
            return gens[v]
        return R.const(Fraction(v))

    pos: dict[str, tuple[Poly, ...]] = {p: tuple(val(t) for t in xy) for p, xy in m.fixed.items()}
    closures: list[Poly] = []
    prism = {i: gens[f"d{i}"] for i, link in enumerate(m.links, 1) if link.prismatic}
    for kind, what in walk(m):
        if kind == "free":
            p = what
            pos[p] = (gens[f"x_{p}"], gens[f"y_{p}"])  # type: ignore[index]
            continue
        i, link = what  # type: ignore[misc]
        c, s = gens[f"c{i}"], gens[f"s{i}"]

        def offset(u: Length, v: Length) -> tuple[Poly, Poly]:
            pu = prism[i] if link.prismatic else val(u)
            pv = val(v)
            return pu * c - pv * s, pu * s + pv * c
        anchor = link.points[0]
        if anchor not in pos:  # placed from another point of the link
            p, (u, v) = next((p, uv) for p, uv in zip(link.points[1:], link.local) if p in pos)
            ox, oy = offset(u, v)
            pos[anchor] = (pos[p][0] - ox, pos[p][1] - oy)
        ax, ay = pos[anchor]
        for point, (u, v) in zip(link.points[1:], link.local):
            ox, oy = offset(u, v)
            x, y = ax + ox, ay + oy
            if point in pos:
                px, py = pos[point]
                closures += [x - px, y - py]
            else:
                pos[point] = (x, y)
    for sl in m.sliders:
        if sl.point not in pos:
            raise MechanismError(f"{m.name}: slider point {sl.point} is not on any link")
        x, y = pos[sl.point]
        if isinstance(sl, Slider):
            a, b, cc = (val(t) for t in sl.line)
            closures.append(a * x + b * y - cc)
        else:
            dx, dy = _direction(m, sl, pos, gens, val)
            ax, ay = pos[sl.a]
            closures.append(dx * (y - ay) - dy * (x - ax))
    for g in m.gears:
        closures += _gear(m, g, gens, R)
    return pos, closures


def _gear(m: Described, g: Gear, gens: dict[str, Poly], R: PolyRing) -> list[Poly]:
    """The gear pair's relation ``z_b conj(z_c) = (conj(z_a) z_c)^n`` of the unit complex numbers
    ``z = c + i s`` of the gears' links and the carrier (the ground: 1), for n > 0 (external gears
    turn opposite ways relative to the carrier); ``z_b conj(z_c) = (z_a conj(z_c))^-n`` for n < 0:
    real and imaginary parts."""
    links = list(enumerate(m.links, 1))
    carrier = next((i for i, link in links if g.a in link.points and g.b in link.points), None)
    if carrier is None and not (g.a in m.fixed and g.b in m.fixed):
        raise MechanismError(f"{where(g.source)}: no link holds both centres {g.a} and {g.b} (a carrier) and they are "
                             "not both fixed")
    one: tuple[Poly, Poly] = (R.one(), R.zero())
    zc = (gens[f"c{carrier}"], gens[f"s{carrier}"]) if carrier else one

    def turning(p: str) -> tuple[Poly, Poly]:
        i = next((i for i, link in links if p in link.points and i != carrier), None)
        if i is None:
            raise MechanismError(f"{where(g.source)}: no link turns about {p} to carry its gear")
        return gens[f"c{i}"], gens[f"s{i}"]
    za, zb = turning(g.a), turning(g.b)
    base = _mul(_conj(za), zc) if g.ratio > 0 else _mul(za, _conj(zc))
    power = one
    for _ in range(abs(g.ratio)):
        power = _mul(power, base)
    left = _mul(zb, _conj(zc))
    return [left[0] - power[0], left[1] - power[1]]


def _mul(z: tuple[Poly, Poly], w: tuple[Poly, Poly]) -> tuple[Poly, Poly]:
    return z[0] * w[0] - z[1] * w[1], z[0] * w[1] + z[1] * w[0]


def _conj(z: tuple[Poly, Poly]) -> tuple[Poly, Poly]:
    return z[0], -z[1]


def _direction(m: Described, sl: LineSlider, pos: dict[str, tuple[Poly, ...]], gens: dict[str, Poly],
               val: object) -> tuple[Poly, Poly]:
    """The direction of the line through ``sl.a`` and ``sl.b``: the link's orientation turned to
    the two points' local difference (without its length, when it lies along a local axis), or
    the difference of two fixed points."""
    for i, link in enumerate(m.links, 1):
        if sl.a in link.points and sl.b in link.points:
            c, s = gens[f"c{i}"], gens[f"s{i}"]
            if link.prismatic:
                return c, s
            local = {p: uv for p, uv in zip(link.points[1:], link.local)} | {link.points[0]: (0, 0)}
            (ua, va), (ub, vb) = local[sl.a], local[sl.b]
            if isinstance(ua, str) or isinstance(ub, str) or isinstance(va, str) or isinstance(vb, str):
                u = val(ub) - val(ua)  # type: ignore[operator]
                v = val(vb) - val(va)  # type: ignore[operator]
            else:
                u, v = Fraction(ub) - Fraction(ua), Fraction(vb) - Fraction(va)
                if u == 0 and v == 0:
                    raise MechanismError(f"{where(sl.source)}: {sl.a} and {sl.b} are at the same place of the link")
                if v == 0:
                    return (c, s) if u > 0 else (-c, -s)
                if u == 0:
                    return (-s, c) if v > 0 else (s, -c)
            return u * c - v * s, u * s + v * c
    if sl.a in m.fixed and sl.b in m.fixed:
        (ax, ay), (bx, by) = pos[sl.a], pos[sl.b]
        return bx - ax, by - ay
    raise MechanismError(f"{where(sl.source)}: {sl.a} and {sl.b} are neither points of one link (a line that "
                         "moves with it) nor fixed points")


def constraints(m: Described, values: dict[str, Length]) -> tuple[PolyRing, list[Poly]]:
    """The constraint ideal's ring and generators (loop and slider constraints, then circles)."""
    R = m.ring(values)
    _, closures = positions(m, R, values)
    gens = dict(zip(R.names, R.gens()))
    circles = [gens[f"c{i}"] ** 2 + gens[f"s{i}"] ** 2 - 1 for i in range(1, len(m.links) + 1)]
    return R, [p for p in closures if not p.is_zero()] + circles


def gruebler_kutzbach(m: Described) -> int:
    """The planar Grübler–Kutzbach count ``3 (n - 1) - 2 j1``: each link a body (a prismatic bar
    two, with a prismatic joint between them), each slider a block with a revolute joint at its
    point and a prismatic joint along its line; a point where k bodies meet (the ground counting
    for a fixed point) is k - 1 revolute joints; two links (or a link and the ground) sharing
    ``k >= 2`` points are welded: 3 constraints, not ``2 k``."""
    bodies = len(m.links) + sum(link.prismatic for link in m.links) + len(m.sliders)
    meet: dict[str, int] = {p: 1 for p in m.fixed}
    for link in m.links:
        for p in link.points:
            meet[p] = meet.get(p, 0) + 1
    for sl in m.sliders:
        meet[sl.point] = meet.get(sl.point, 0) + 1
    revolute = sum(max(k - 1, 0) for k in meet.values())
    parts = [set(m.fixed)] + [set(link.points) for link in m.links]
    shared = [len(a & b) for i, a in enumerate(parts) for b in parts[i + 1:]]
    welded = sum(2 * k - 3 for k in shared if k >= 2)
    prismatic = sum(link.prismatic for link in m.links) + len(m.sliders)
    # a gear pair: a higher pair, one constraint
    return 3 * bodies - 2 * revolute + welded - 2 * prismatic - len(m.gears)
