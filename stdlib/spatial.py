"""Spatial mechanisms of points, bars and bodies: their variables and equations.

Points are in space.  A body (``body A B u v w ...``) turns with a rotation frame: the first two
columns ``(r11_i, r21_i, r31_i)`` and ``(r12_i, r22_i, r32_i)`` of its rotation matrix, orthonormal
(three quadrics), the third column their cross product — so every rotation, and only proper ones,
once each (no double cover as with quaternions, no missing half-turns as with a Cayley or Study
chart).  A body point is the body's origin plus the rotated local coordinates; bodies are placed
by walking from the fixed points (a body reaching a placed point closes with three polynomials).
A point no body places has coordinates of its own, ``x_P, y_P, z_P``.  A bar (spherical joints at
both ends) gives the polynomial ``|B - A|^2 - l^2``: its spin about its own axis, which moves
nothing, is not a variable; a prismatic bar (``prismatic A B``: spherical, prismatic, spherical)
has its length ``d_i`` as a variable, ``|B - A|^2 - d_i^2``.  With the platform's points in its
local x-y plane (w = 0) the equations of a Stewart–Gough platform are quadrics.  A slider
(``slider P A B``) keeps ``P`` on the line through two points of one link (a line that moves with
it) or two fixed points: ``(B - A) x (P - A) = 0``.

Constraint order: body closures, bars, sliders, then each body's orthonormality; variables: the
bodies' frames (in the order of the links), the prismatic bars' lengths, the free points'
coordinates, then the parameters as their own block.
"""
from __future__ import annotations

from fractions import Fraction

from mech.kernel import Poly, PolyRing
from mech.stdlib.joints import Body, Described, Length, LineSlider, MechanismError, where


Event = tuple[str, object]  # ("body", (i, link)) or ("free", point)
FRAME = ("r11", "r21", "r31", "r12", "r22", "r32")


def frame_names(i: int) -> list[str]:
    """The rotation-frame variables of link ``i`` (a body)."""
    return [f"{r}_{i}" for r in FRAME]


def walk(m: Described) -> list[Event]:
    """The order in which bodies are placed (passes, as in the plane; when stuck the origin of the
    first body not placed gets free coordinates), then the free points of the bars."""
    placed = set(m.fixed)
    pending = [(i, link) for i, link in enumerate(m.links, 1) if isinstance(link, Body)]
    events: list[Event] = []
    while pending:
        progress = False
        for item in list(pending):
            _, link = item
            if any(p in placed for p in link.points):
                placed.update(link.points)
                events.append(("body", item))
                pending.remove(item)
                progress = True
        if not progress:
            origin = pending[0][1].points[0]
            placed.add(origin)
            events.append(("free", origin))
    for link in m.links:
        for p in link.points:
            if p not in placed:
                placed.add(p)
                events.append(("free", p))
    return events


def variables(m: Described) -> list[str]:
    names: list[str] = []
    for i, link in enumerate(m.links, 1):
        if isinstance(link, Body):
            names += frame_names(i)
    names += [f"d{i}" for i, link in enumerate(m.links, 1) if link.prismatic]
    for kind, p in walk(m):
        if kind == "free":
            names += [f"{x}_{p}" for x in "xyz"]
    return names


def positions(m: Described, R: PolyRing, values: dict[str, Length]
              ) -> tuple[dict[str, tuple[Poly, ...]], list[Poly]]:
    """Each point's coordinates as polynomials of ``R``, and the bodies' closures and the bars'
    polynomials."""
    gens = dict(zip(R.names, R.gens()))

    def val(v: Length) -> Poly:
        if isinstance(v, str):
            v = values.get(v, v)
        return gens[v] if isinstance(v, str) else R.const(Fraction(v))

    pos: dict[str, tuple[Poly, ...]] = {p: tuple(val(t) for t in xyz) for p, xyz in m.fixed.items()}
    closures: list[Poly] = []
    for kind, what in walk(m):
        if kind == "free":
            pos[what] = tuple(gens[f"{x}_{what}"] for x in "xyz")  # type: ignore[index]
            continue
        i, link = what  # type: ignore[misc]
        r = [gens[n] for n in frame_names(i)]
        c1, c2 = r[:3], r[3:]
        c3 = [c1[1] * c2[2] - c1[2] * c2[1], c1[2] * c2[0] - c1[0] * c2[2], c1[0] * c2[1] - c1[1] * c2[0]]

        def turn(uvw: tuple[Length, ...]) -> list[Poly]:
            u, v, w = (val(t) for t in uvw)
            return [u * a + v * b + (w * c if not w.is_zero() else R.zero()) for a, b, c in zip(c1, c2, c3)]
        anchor = link.points[0]
        if anchor not in pos:
            p, uvw = next((p, uvw) for p, uvw in zip(link.points[1:], link.local) if p in pos)
            pos[anchor] = tuple(x - o for x, o in zip(pos[p], turn(uvw)))
        for point, uvw in zip(link.points[1:], link.local):
            x = tuple(a + o for a, o in zip(pos[anchor], turn(uvw)))
            if point in pos:
                closures += [a - b for a, b in zip(x, pos[point])]
            else:
                pos[point] = x
    for i, link in enumerate(m.links, 1):
        if isinstance(link, Body):
            continue
        a, b = pos[link.points[0]], pos[link.points[1]]
        length = gens[f"d{i}"] if link.prismatic else val(link.local[0][0])
        closures.append(sum(((q - p) ** 2 for p, q in zip(a, b)), R.zero()) - length ** 2)
    for sl in m.sliders:
        closures += _on_line(m, sl, pos)
    return pos, closures


def _on_line(m: Described, sl: LineSlider, pos: dict[str, tuple[Poly, ...]]) -> list[Poly]:
    """``P`` on the line through ``A`` and ``B`` (two points of one link, or fixed): the cross
    product ``(B - A) x (P - A) = 0`` (three polynomials, two of them independent)."""
    if not any(sl.a in link.points and sl.b in link.points for link in m.links) \
            and not (sl.a in m.fixed and sl.b in m.fixed):
        raise MechanismError(f"{where(sl.source)}: {sl.a} and {sl.b} are neither points of one link (a line "
                             "that moves with it) nor fixed points")
    if sl.point not in pos:
        raise MechanismError(f"{m.name}: slider point {sl.point} is not on any link")
    a = pos[sl.a]
    d = [q - p for p, q in zip(a, pos[sl.b])]
    e = [q - p for p, q in zip(a, pos[sl.point])]
    return [d[1] * e[2] - d[2] * e[1], d[2] * e[0] - d[0] * e[2], d[0] * e[1] - d[1] * e[0]]


def constraints(m: Described, values: dict[str, Length]) -> tuple[PolyRing, list[Poly]]:
    R = m.ring(values)
    _, closures = positions(m, R, values)
    gens = dict(zip(R.names, R.gens()))
    frames: list[Poly] = []
    for i, link in enumerate(m.links, 1):
        if isinstance(link, Body):
            r = [gens[n] for n in frame_names(i)]
            frames += [r[0] ** 2 + r[1] ** 2 + r[2] ** 2 - 1, r[3] ** 2 + r[4] ** 2 + r[5] ** 2 - 1,
                       r[0] * r[3] + r[1] * r[4] + r[2] * r[5]]
    gens_ = [p for p in closures if not p.is_zero()]
    if any(p.is_constant() for p in gens_):
        raise MechanismError(f"{m.name}: a bar between two fixed points does not fit their distance")
    return R, gens_ + frames


def gruebler_kutzbach(m: Described) -> int:
    """The spatial count ``6 (n - 1) - 3 j3 - spins``: each link a body, a point where k bodies meet
    (the ground counting for a fixed point) k - 1 spherical joints, and each bar's spin about its
    own axis (a passive freedom that moves nothing) not counted.  Two rigid parts (bodies or the
    ground) sharing two points are hinged: a revolute joint, 5 constraints, not two spherical
    joints' 6; sharing ``k >= 3`` points they are welded, 6 constraints, not ``3 k``."""
    meet: dict[str, int] = {p: 1 for p in m.fixed}
    for link in m.links:
        for p in link.points:
            meet[p] = meet.get(p, 0) + 1
    spherical = sum(max(k - 1, 0) for k in meet.values())
    bars = sum(not isinstance(link, Body) for link in m.links)
    prismatic = sum(link.prismatic for link in m.links)
    parts = [set(m.fixed)] + [set(link.points) for link in m.links if isinstance(link, Body)]
    shared = [len(a & b) for i, a in enumerate(parts) for b in parts[i + 1:]]
    repeated = sum(1 if k == 2 else 3 * k - 6 for k in shared if k >= 2)
    return 6 * len(m.links) - 3 * spherical + repeated - bars + prismatic - 2 * len(m.sliders)
