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

import re
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, ClassVar, Union

from mech.dsl.errors import MechRuntimeError, MechTypeError
from mech.dsl.types import register_type
from mech.dsl.values import typeof
from mech.kernel import QQ, Block, MonomialOrder, Poly, PolyRing

Length = Union[int, Fraction, str]  # a number or the name of a symbolic length


class MechanismError(MechRuntimeError):
    """An ill-formed mechanism (a user error of the language)."""


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
    """Joint points (some fixed), links between them, and sliders (the language's type
    ``mechanism``)."""

    type_name: ClassVar[str] = "mechanism"
    name: str = "mechanism"
    fixed: dict[str, tuple[Length, Length]] = field(default_factory=dict)
    links: list[Link] = field(default_factory=list)
    sliders: list[Slider] = field(default_factory=list)

    def __str__(self) -> str:
        def f(v: Length) -> str:
            return str(v)
        lines = [f"fix {p} {f(x)} {f(y)}" for p, (x, y) in self.fixed.items()]
        for k in self.links:
            if k.prismatic:
                lines.append(f"prismatic {k.points[0]} {k.points[1]}")
            elif len(k.points) == 2 and k.local[0][1] == 0:
                lines.append(f"bar {k.points[0]} {k.points[1]} {f(k.local[0][0])}")
            else:
                rest = " ".join(f"{p} {f(u)} {f(v)}" for p, (u, v) in zip(k.points[1:], k.local))
                lines.append(f"body {k.points[0]} {rest}")
        lines += [f"slider {s.point}" + ("" if s.line == (0, 1, 0) else " " + " ".join(f(t) for t in s.line))
                  for s in self.sliders]
        return "; ".join(lines)

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

    def with_values(self, values: dict[str, Length]) -> "Mechanism":
        """The same mechanism with some symbolic lengths replaced by numbers."""
        def sub(v: Length) -> Length:
            return values.get(v, v) if isinstance(v, str) else v
        return Mechanism(
            self.name, {p: (sub(x), sub(y)) for p, (x, y) in self.fixed.items()},
            [Link(list(k.points), [(sub(u), sub(v)) for u, v in k.local], k.prismatic) for k in self.links],
            [Slider(s.point, tuple(sub(t) for t in s.line)) for s in self.sliders])

    def points(self) -> list[str]:
        """Joint points in order of first appearance."""
        seen = list(self.fixed)
        for link in self.links:
            seen += [p for p in link.points if p not in seen]
        return seen

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

    def positions(self, R: PolyRing, values: dict[str, Length] | None = None
                  ) -> tuple[dict[str, tuple[Poly, Poly]], list[Poly]]:
        """Each joint point's coordinates as polynomials of ``R`` (walking the links from the
        fixed points) and the closure polynomials of the loops and sliders."""
        return self._walk(R, values or {})

    def constraints(self, values: dict[str, Length] | None = None) -> tuple[PolyRing, list[Poly]]:
        """The constraint ideal's ring and generators (loop/point constraints, then circles)."""
        values = values or {}
        if not self.links:
            raise MechanismError(f"{self.name}: a mechanism needs at least one link")
        if not self.fixed:
            raise MechanismError(f"{self.name}: nothing is fixed (add a ground point)")
        R = self.ring(values)
        pos, closures = self._walk(R, values)
        gens = dict(zip(R.names, R.gens()))
        circles = [gens[f"c{i}"] ** 2 + gens[f"s{i}"] ** 2 - 1 for i in range(1, len(self.links) + 1)]
        return R, [p for p in closures if not p.is_zero()] + circles

    def _walk(self, R: PolyRing, values: dict[str, Length]
              ) -> tuple[dict[str, tuple[Poly, Poly]], list[Poly]]:
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
                c, s = gens[f"c{i}"], gens[f"s{i}"]

                def offset(u: Length, v: Length) -> tuple[Poly, Poly]:
                    pu = gens[prism_of[i]] if link.prismatic else val(u)
                    pv = val(v)
                    return pu * c - pv * s, pu * s + pv * c
                if anchor not in pos:  # placed from another point of the link, if one is placed
                    placed = [(p, uv) for p, uv in zip(link.points[1:], link.local) if p in pos]
                    if not placed:
                        continue
                    p, (u, v) = placed[0]
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
                pending.remove(item)
                progress = True
            if not progress:
                loose = ", ".join(link.points[0] for _, link in pending)
                raise MechanismError(f"{self.name}: links at {loose} are not connected to a fixed point")
        for sl in self.sliders:
            if sl.point not in pos:
                raise MechanismError(f"{self.name}: slider point {sl.point} is not on any link")
            a, b, cc = (val(t) for t in sl.line)
            x, y = pos[sl.point]
            closures.append(a * x + b * y - cc)
        return pos, closures


# ---------------------------------------------------------------- the description language
#: The first words of the description's statements (what ``mechanism m { ... }`` accepts).
STATEMENTS = ("ground", "fix", "bar", "prismatic", "body", "slider")

SYNTAX = """statements separated by ';' or new lines:
  ground A B g           A fixed at the origin, B at (g, 0): the ground link of length g
  fix P [x y]            P fixed at (x, y) (default the origin)
  bar A B l              a bar of length l from A to B (orientation c_i, s_i)
  prismatic A B          a bar whose length d_i is a configuration variable
  body A B u v [C u v]   a rigid body: B at local coordinates (u, v) from A, ...
  slider P [a b c]       P on the line a*x + b*y = c (default the x-axis)
lengths are integers, fractions p/q or names (symbolic lengths)"""

_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*$")
_NUM = re.compile(r"-?[0-9]+(/[0-9]+)?$")


def _length(tok: str, where: str) -> Length:
    if _NUM.match(tok):
        try:
            v = Fraction(tok)
        except ZeroDivisionError:
            raise MechanismError(f"{where}: '{tok}' divides by zero") from None
        return int(v) if v.denominator == 1 else v
    if _NAME.match(tok):
        return tok
    raise MechanismError(f"{where}: '{tok}' is not a length (a number such as 2 or 1/2, or a name)")


def _point(tok: str, where: str) -> str:
    if not _NAME.match(tok):
        raise MechanismError(f"{where}: '{tok}' is not a point name")
    return tok


def parse_mechanism(text: str, name: str = "mechanism") -> Mechanism:
    """A :class:`Mechanism` from its description (see ``SYNTAX``)."""
    m = Mechanism(name)
    statements = [s.strip() for s in re.split(r"[;\n]", text) if s.strip()]
    if not statements:
        raise MechanismError("empty mechanism description")
    for k, stmt in enumerate(statements, 1):
        words = stmt.split()
        op, args = words[0], words[1:]
        where = f"statement {k} '{stmt}'"
        counts = {"ground": (3,), "fix": (1, 3), "bar": (3,), "prismatic": (2,), "slider": (1, 4)}
        if op == "body":
            if len(args) < 4 or (len(args) - 1) % 3:
                raise MechanismError(f"{where}: body A B u v [C u v ...]")
            pts = [_point(args[0], where)] + [_point(a, where) for a in args[1::3]]
            local = [(_length(u, where), _length(v, where)) for u, v in zip(args[2::3], args[3::3])]
            m.body(pts, local)
            continue
        if op not in counts:
            raise MechanismError(f"{where}: unknown statement '{op}' (expected {', '.join(STATEMENTS[:-1])} "
                                 f"or {STATEMENTS[-1]})")
        if len(args) not in counts[op]:
            n = " or ".join(str(c) for c in counts[op])
            raise MechanismError(f"{where}: '{op}' takes {n} arguments")
        if op == "ground":
            a, b = _point(args[0], where), _point(args[1], where)
            m.fix(a, 0, 0).fix(b, _length(args[2], where), 0)
        elif op == "fix":
            p = _point(args[0], where)
            m.fix(p, *(_length(t, where) for t in args[1:]))
        elif op == "bar":
            m.bar(_point(args[0], where), _point(args[1], where), _length(args[2], where))
        elif op == "prismatic":
            m.bar(_point(args[0], where), _point(args[1], where), 0, prismatic=True)
        else:
            line = tuple(_length(t, where) for t in args[1:]) or (0, 1, 0)
            m.slide(_point(args[0], where), line)
    return m


def to_mechanism(v: Any) -> Mechanism:
    """A value of type ``mechanism``: a mechanism, or a description string parsed."""
    if isinstance(v, Mechanism):
        return v
    if not isinstance(v, str):
        raise MechTypeError(f"cannot convert {typeof(v)} to mechanism (give its description as a string)")
    try:
        return parse_mechanism(v)
    except MechanismError as e:
        raise MechRuntimeError(f"mechanism: {e}") from None


register_type("mechanism", to_mechanism,
              default='a mechanism is declared with its description: mechanism m = "fix O; bar O A l1";',
              statements=STATEMENTS)
