"""The statements of points, links, sliders and gears: fixed points (``fix``, ``ground``), links
(``bar``, ``prismatic``, ``body``), sliders on fixed or moving lines (``slider``) and gear pairs
(``gear``), in the plane or in space (:mod:`mech.stdlib.joints` registers them).
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import ClassVar, Optional, Sequence

from mech.stdlib.joint_base import (Element, Form, Length, MechanismError, Source, number, number_or_name, point_name,
                                    substitute, text_of)


@dataclass
class Fix(Element):
    """A point of the ground at given coordinates (2 in the plane, 3 in space)."""

    keyword: ClassVar[str] = "fix"
    forms: ClassVar[tuple[Form, ...]] = (
        Form("P", "P fixed at the origin"),
        Form("P x y", "P fixed at (x, y)", (2,)),
        Form("P x y z", "P fixed at (x, y, z): a spatial mechanism", (3,)))
    group: ClassVar[int] = 0
    point: str = ""
    coords: tuple[Length, ...] = (0, 0)
    src: Optional[Source] = field(default=None, compare=False, repr=False)

    @classmethod
    def parse(cls, args: Sequence[str], src: Source, dim: int) -> list[Element]:
        p = point_name(args[0], src)
        coords = tuple(number_or_name(t, src) for t in args[1:]) or (0,) * dim
        return [cls(p, coords, src)]

    def text(self) -> str:
        return f"fix {self.point} " + " ".join(text_of(v) for v in self.coords)

    def mentions(self) -> list[str]:
        return [self.point]

    def parameters(self) -> list[Length]:
        return list(self.coords)

    def with_values(self, values: dict[str, Length]) -> Element:
        return replace(self, coords=tuple(substitute(v, values) for v in self.coords))


@dataclass
class Ground(Element):
    """The planar ground link: two fixed points on the x-axis (a statement, not an element)."""

    keyword: ClassVar[str] = "ground"
    forms: ClassVar[tuple[Form, ...]] = (Form("A B g", "the ground link: A fixed at the origin, B at (g, 0)", (2,)),)

    @classmethod
    def parse(cls, args: Sequence[str], src: Source, dim: int) -> list[Element]:
        a, b = point_name(args[0], src), point_name(args[1], src)
        g = number_or_name(args[2], src)
        if g == 0:
            raise MechanismError(f"{src}: the ground length is 0: {a} and {b} would be one point")
        return [Fix(a, (0, 0), src), Fix(b, (g, 0), src)]


@dataclass
class Link(Element):
    """A rigid link: ``points[0]`` is its origin, the others sit at local coordinates ``local``
    (in the plane multiples of its orientation (c, s) and the normal (-s, c)); a bar has one far
    point at ``(length, 0)``.  ``prismatic`` makes the length a configuration variable."""

    group: ClassVar[int] = 1
    points: list[str] = field(default_factory=list)
    local: list[tuple[Length, ...]] = field(default_factory=list)
    prismatic: bool = False
    src: Optional[Source] = field(default=None, compare=False, repr=False)

    def mentions(self) -> list[str]:
        return list(self.points)

    def parameters(self) -> list[Length]:
        return [v for uv in self.local for v in uv]

    def with_values(self, values: dict[str, Length]) -> Element:
        return replace(self, points=list(self.points),
                       local=[tuple(substitute(v, values) for v in uv) for uv in self.local])

    def text(self) -> str:
        if self.prismatic:
            return f"prismatic {self.points[0]} {self.points[1]}"
        if len(self.points) == 2 and all(v == 0 for v in self.local[0][1:]):
            return f"bar {self.points[0]} {self.points[1]} {text_of(self.local[0][0])}"
        rest = " ".join(f"{p} " + " ".join(text_of(v) for v in uv) for p, uv in zip(self.points[1:], self.local))
        return f"body {self.points[0]} {rest}"


@dataclass
class Bar(Link):
    """A bar between two points (in space: a link with spherical joints at both ends)."""

    keyword: ClassVar[str] = "bar"
    forms: ClassVar[tuple[Form, ...]] = (Form("A B l", "a bar of length l from A to B"),)

    @classmethod
    def parse(cls, args: Sequence[str], src: Source, dim: int) -> list[Element]:
        a, b = point_name(args[0], src), point_name(args[1], src)
        length = number_or_name(args[2], src)
        if a == b:
            raise MechanismError(f"{src}: a bar joins two different points, not {a} to itself")
        if not isinstance(length, str) and length <= 0:
            raise MechanismError(f"{src}: the length of a bar is positive, not {text_of(length)}")
        return [cls([a, b], [(length,) + (0,) * (dim - 1)], False, src)]


@dataclass
class PrismaticBar(Link):
    """A bar whose length ``d_i`` is a configuration variable (a prismatic joint inside it)."""

    keyword: ClassVar[str] = "prismatic"
    forms: ClassVar[tuple[Form, ...]] = (
        Form("A B", "a bar whose length d_i is a configuration variable (a prismatic joint inside it)"),)

    @classmethod
    def parse(cls, args: Sequence[str], src: Source, dim: int) -> list[Element]:
        a, b = point_name(args[0], src), point_name(args[1], src)
        if a == b:
            raise MechanismError(f"{src}: a prismatic bar joins two different points, not {a} to itself")
        return [cls([a, b], [(0,) * dim], True, src)]


@dataclass
class Body(Link):
    """A rigid body (a ternary or larger link): its points at local coordinates from its origin."""

    keyword: ClassVar[str] = "body"
    forms: ClassVar[tuple[Form, ...]] = (
        Form("A B u v [C u v ...]", "a rigid body: B at local coordinates (u, v) from A, ...", (2,)),
        Form("A B u v w [C u v w ...]", "in space: local coordinates (u, v, w) in the body's frame", (3,)))

    @classmethod
    def parse(cls, args: Sequence[str], src: Source, dim: int) -> list[Element]:
        k = dim + 1
        if len(args) < k + 1 or (len(args) - 1) % k:
            coords = "u v" if dim == 2 else "u v w"
            raise MechanismError(f"{src}: 'body' takes A B {coords} [C {coords} ...] (a point and {dim} local "
                                 f"coordinates for each point after the first), not {len(args)} arguments")
        pts = [point_name(args[0], src)] + [point_name(a, src) for a in args[1::k]]
        local = [tuple(number_or_name(t, src) for t in args[i + 1:i + k]) for i in range(1, len(args), k)]
        for p in pts:
            if pts.count(p) > 1:
                raise MechanismError(f"{src}: point {p} is listed twice in the body")
        for p, uv in zip(pts[1:], local):
            if all(v == 0 for v in uv):
                raise MechanismError(f"{src}: point {p} is at the body's origin {pts[0]} (local coordinates 0)")
        return [cls(pts, local, False, src)]


@dataclass
class Slider(Element):
    """A point constrained to the fixed line ``a*x + b*y = c`` (the x-axis: a=0, b=1, c=0)."""

    keyword: ClassVar[str] = "slider"
    forms: ClassVar[tuple[Form, ...]] = (
        Form("P", "P on the x-axis", (2,)),
        Form("P a b c", "P on the fixed line a*x + b*y = c", (2,)))
    group: ClassVar[int] = 2
    point: str = ""
    line: tuple[Length, Length, Length] = (0, 1, 0)
    src: Optional[Source] = field(default=None, compare=False, repr=False)

    @classmethod
    def parse(cls, args: Sequence[str], src: Source, dim: int) -> list[Element]:
        line = tuple(number_or_name(t, src) for t in args[1:]) or (0, 1, 0)
        if line[0] == 0 and line[1] == 0:
            raise MechanismError(f"{src}: a*x + b*y = c is no line when a = b = 0")
        return [cls(point_name(args[0], src), line, src)]  # type: ignore[arg-type]

    def text(self) -> str:
        return f"slider {self.point}" + ("" if self.line == (0, 1, 0) else " " + " ".join(map(text_of, self.line)))

    def mentions(self) -> list[str]:
        return [self.point]

    def parameters(self) -> list[Length]:
        return list(self.line)

    def with_values(self, values: dict[str, Length]) -> Element:
        return replace(self, line=tuple(substitute(v, values) for v in self.line))


@dataclass
class LineSlider(Element):
    """A point on the line through two points ``a``, ``b`` of one link (a slider on a moving
    line, a pin in a slot, a block sliding in a body) or through two fixed points."""

    keyword: ClassVar[str] = "slider"
    forms: ClassVar[tuple[Form, ...]] = (
        Form("P A B", "P on the line through A and B, two points of one link (a slider on a moving line, "
                      "a pin in a slot) or two fixed points; in space too"),)
    group: ClassVar[int] = 2
    point: str = ""
    a: str = ""
    b: str = ""
    src: Optional[Source] = field(default=None, compare=False, repr=False)

    @classmethod
    def parse(cls, args: Sequence[str], src: Source, dim: int) -> list[Element]:
        p, a, b = (point_name(t, src) for t in args)
        if a == b:
            raise MechanismError(f"{src}: a line needs two different points, not {a} twice")
        if p in (a, b):
            raise MechanismError(f"{src}: {p} is one of the line's points: it is on the line anyway")
        return [cls(p, a, b, src)]

    def text(self) -> str:
        return f"slider {self.point} {self.a} {self.b}"

    def mentions(self) -> list[str]:
        return [self.point, self.a, self.b]

    def with_values(self, values: dict[str, Length]) -> Element:
        return self


@dataclass
class Gear(Element):
    """Two meshing gears centred at ``a`` and ``b`` (planar): the gear at ``b`` turns ``ratio`` times
    as fast as the gear at ``a``, the other way (a negative ratio: ``b`` inside an internal gear at
    ``a``, the same way), relative to the link that holds both centres (the ground when both are
    fixed).  Each gear turns with the first other link written at its centre.  An integer ratio
    keeps the relation polynomial in the links' (cos, sin) pairs."""

    keyword: ClassVar[str] = "gear"
    forms: ClassVar[tuple[Form, ...]] = (
        Form("A B n", "gears centred at A and B meshing: the gear at B turns n times as fast as the one at A, the "
                      "other way (n < 0: inside an internal gear, the same way); n an integer", (2,)),)
    group: ClassVar[int] = 2
    a: str = ""
    b: str = ""
    ratio: int = 1
    src: Optional[Source] = field(default=None, compare=False, repr=False)

    @classmethod
    def parse(cls, args: Sequence[str], src: Source, dim: int) -> list[Element]:
        a, b = point_name(args[0], src), point_name(args[1], src)
        if a == b:
            raise MechanismError(f"{src}: two gears have two different centres, not {a} twice")
        ratio = number(args[2], src, "the gear ratio")
        if ratio.denominator != 1 or ratio == 0:
            raise MechanismError(f"{src}: the gear ratio is a non-zero integer (the number of turns of the gear at "
                                 f"{b} per turn of the one at {a}), not {args[2]}")
        if ratio == -1:
            raise MechanismError(f"{src}: an internal gear pair of ratio -1 would have two gears of one size, one "
                                 "inside the other")
        return [cls(a, b, int(ratio), src)]

    def text(self) -> str:
        return f"gear {self.a} {self.b} {self.ratio}"

    def mentions(self) -> list[str]:
        return [self.a, self.b]

    def with_values(self, values: dict[str, Length]) -> Element:
        return self
