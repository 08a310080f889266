"""Planar rigid mechanisms and their constraint ideals.

A mechanism is a set of named joint points joined by links. Each link ``i`` carries an
orientation ``(c_i, s_i)`` with ``c_i^2 + s_i^2 - 1 = 0``; its far point is its near point
plus ``length * (c_i, s_i)`` (a bar), or a rigid body's local coordinates rotated by
``(c_i, s_i)`` (a ternary link). Points are placed by walking the links from the fixed
points; a link that reaches an already placed point closes a loop and yields two
polynomials (x and y), a slider yields one (its coordinate across the line).

Constraint order follows the paper: loop and point constraints first, then the circle
equations; variables ``c1,s1,c2,s2,...`` (then prismatic lengths ``d1,...``), and the
symbolic link lengths last as their own block, so eliminating the angles leaves the
conditions on the lengths.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from typing import Union

from mech.kernel import QQ, Block, MonomialOrder, Poly, PolyRing

Length = Union[int, Fraction, str]  # a number or the name of a symbolic length


class MechanismError(ValueError):
    """An ill-formed mechanism description."""


@dataclass
class Link:
    """A rigid link: ``points[0]`` is the near point, the others sit at local coordinates
    (multiples of the orientation (c, s) and its normal (-s, c)); a bar has one far point
    at ``(length, 0)``. ``prismatic`` makes the length a configuration variable."""

    points: list[str]
    local: list[tuple[Length, Length]]
    prismatic: bool = False


@dataclass
class Slider:
    """A point constrained to the line ``a*x + b*y = c`` (the x-axis: a=0, b=1, c=0)."""

    point: str
    line: tuple[Length, Length, Length] = (0, 1, 0)


@dataclass
class Mechanism:
    """Joint points (some fixed), links between them, and sliders."""

    name: str = "mechanism"
    fixed: dict[str, tuple[Length, Length]] = field(default_factory=dict)
    links: list[Link] = field(default_factory=list)
    sliders: list[Slider] = field(default_factory=list)

    # building
    def fix(self, point: str, x: Length = 0, y: Length = 0) -> "Mechanism":
        self.fixed[point] = (x, y)
        return self

    def bar(self, a: str, b: str, length: Length, prismatic: bool = False) -> "Mechanism":
        self.links.append(Link([a, b], [(length, 0)], prismatic))
        return self

    def body(self, points: list[str], local: list[tuple[Length, Length]]) -> "Mechanism":
        if len(local) != len(points) - 1:
            raise MechanismError("a body needs local coordinates for each point after the first")
        self.links.append(Link(list(points), list(local)))
        return self

    def slide(self, point: str, line: tuple[Length, Length, Length] = (0, 1, 0)) -> "Mechanism":
        self.sliders.append(Slider(point, line))
        return self

    @classmethod
    def chain(cls, lengths: list[Length], name: str = "chain", slider: bool = False,
              ground: Length | None = None) -> "Mechanism":
        """An open chain of bars from a fixed pivot at the origin, its end point on the x-axis
        (``slider``) or pinned at ``(ground, 0)`` (a closed loop with a ground link)."""
        m = cls(name).fix("P0")
        for i, length in enumerate(lengths):
            m.bar(f"P{i}", f"P{i + 1}", length)
        end = f"P{len(lengths)}"
        if slider:
            m.slide(end)
        if ground is not None:
            m.fix(end, ground, 0)
        return m

    # constraint generation
    def symbols(self) -> list[str]:
        """Symbolic lengths (and coordinates) in order of first appearance."""
        seen: list[str] = []

        def note(v: Length) -> None:
            if isinstance(v, str) and v not in seen:
                seen.append(v)
        for x, y in self.fixed.values():
            note(x), note(y)
        for link in self.links:
            for u, v in link.local:
                note(u), note(v)
        for s in self.sliders:
            for v in s.line:
                note(v)
        return seen

    def variables(self) -> list[str]:
        names: list[str] = []
        for i, link in enumerate(self.links, 1):
            names += [f"c{i}", f"s{i}"]
        names += [f"d{i}" for i, link in enumerate(self.links, 1) if link.prismatic]
        return names

    def ring(self, values: dict[str, Length] | None = None) -> PolyRing:
        """``QQ[c1,s1,...,(d...),(lengths)]`` with the lengths as a trailing dp block
        (omitted when every length has a value)."""
        values = values or {}
        angles = self.variables()
        params = [p for p in self.symbols() if p not in values]
        blocks = [Block("dp", len(angles))] + ([Block("dp", len(params))] if params else [])
        return PolyRing(QQ, angles + params, MonomialOrder(blocks))

    def constraints(self, values: dict[str, Length] | None = None) -> tuple[PolyRing, list[Poly]]:
        """The constraint ideal's ring and generators (loop/point constraints, then circles)."""
        values = values or {}
        if not self.links:
            raise MechanismError(f"{self.name}: a mechanism needs at least one link")
        if not self.fixed:
            raise MechanismError(f"{self.name}: nothing is fixed (add a ground point)")
        R = self.ring(values)
        gens = dict(zip(R.names, R.gens()))

        def val(v: Length) -> Poly:
            if isinstance(v, str):
                v = values.get(v, v)
            if isinstance(v, str):
                return gens[v]
            return R.const(Fraction(v))

        pos: dict[str, tuple[Poly, Poly]] = {p: (val(x), val(y)) for p, (x, y) in self.fixed.items()}
        closures: list[Poly] = []
        pending = list(enumerate(self.links, 1))
        prism = iter(f"d{i}" for i, link in enumerate(self.links, 1) if link.prismatic)
        prism_of = {i: next(prism) for i, link in enumerate(self.links, 1) if link.prismatic}
        while pending:
            progress = False
            for item in list(pending):
                i, link = item
                anchor = link.points[0]
                if anchor not in pos:
                    continue
                c, s = gens[f"c{i}"], gens[f"s{i}"]
                ax, ay = pos[anchor]
                for point, (u, v) in zip(link.points[1:], link.local):
                    pu = gens[prism_of[i]] if link.prismatic else val(u)
                    pv = val(v)
                    x, y = ax + pu * c - pv * s, ay + pu * s + pv * c
                    if point in pos:
                        px, py = pos[point]
                        closures += [x - px, y - py]
                    else:
                        pos[point] = (x, y)
                pending.remove(item)
                progress = True
            if not progress:
                loose = ", ".join(link.points[0] for _, link in pending)
                raise MechanismError(f"{self.name}: links anchored at {loose} are not connected "
                                     "to a fixed point")
        for sl in self.sliders:
            if sl.point not in pos:
                raise MechanismError(f"{self.name}: slider point {sl.point} is not on any link")
            a, b, cc = (val(t) for t in sl.line)
            x, y = pos[sl.point]
            closures.append(a * x + b * y - cc)
        circles = [gens[f"c{i}"] ** 2 + gens[f"s{i}"] ** 2 - 1 for i in range(1, len(self.links) + 1)]
        return R, [p for p in closures if not p.is_zero()] + circles
