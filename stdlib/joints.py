"""The statements of a mechanism's description, one class per kind: the joint model's registry.

Each kind is a class (a subclass of :class:`Element`) with its keyword, its argument forms and
their meaning (the syntax help), :meth:`Element.parse` (one statement's words to elements),
its canonical text, its points and parameters.  :func:`statement` registers a class;
the parser (:func:`mech.stdlib.mechanism.parse_mechanism`), the block form's accepted words
(:func:`keywords`), the syntax help (:func:`syntax`) and the documentation's table come from
the registry.  The models that turn elements into variables and equations are
:mod:`mech.stdlib.planar` (points in the plane, links with orientations ``(c_i, s_i)``) and
:mod:`mech.stdlib.spatial` (points in space, bodies with rotation frames, loops of joints with
Denavit–Hartenberg parameters).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field, replace
from fractions import Fraction
from typing import ClassVar, Optional, Protocol, Sequence, Union

from mech.dsl.errors import MechRuntimeError

Length = Union[int, Fraction, str]  # a number or the name of a symbolic parameter

_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*$")
_NUM = re.compile(r"-?[0-9]+(/[0-9]+)?$")


class MechanismError(MechRuntimeError):
    """An ill-formed mechanism (a user error of the language)."""


@dataclass(frozen=True)
class Source:
    """Where an element comes from: statement ``index`` (1-based) of the description, its text."""

    index: int
    text: str

    def __str__(self) -> str:
        return f"statement {self.index} '{self.text}'"


def where(src: Optional[Source]) -> str:
    return str(src) if src is not None else "a statement"


@dataclass(frozen=True)
class Form:
    """One form of a statement: its arguments (``A B l``) and what it means."""

    args: str
    meaning: str
    dims: tuple[int, ...] = (2, 3)  # the dimensions the form exists in

    def arity(self) -> Optional[int]:
        """The number of words after the keyword (None: a variable number)."""
        return None if "[" in self.args or "..." in self.args else len(self.args.split())


def number_or_name(tok: str, src: Optional[Source]) -> Length:
    """A parameter: an integer, a fraction ``p/q`` or a name (symbolic)."""
    if _NUM.match(tok):
        try:
            v = Fraction(tok)
        except ZeroDivisionError:
            raise MechanismError(f"{where(src)}: '{tok}' divides by zero") from None
        return int(v) if v.denominator == 1 else v
    if _NAME.match(tok):
        return tok
    raise MechanismError(f"{where(src)}: '{tok}' is not a length (a number such as 2 or 1/2, or a name)")


def number(tok: str, src: Optional[Source], what: str) -> Fraction:
    v = number_or_name(tok, src)
    if isinstance(v, str):
        raise MechanismError(f"{where(src)}: {what} is a number, not the name '{tok}'")
    return Fraction(v)


def point_name(tok: str, src: Optional[Source]) -> str:
    if not _NAME.match(tok):
        raise MechanismError(f"{where(src)}: '{tok}' is not a point name")
    return tok


def text_of(v: Length) -> str:
    return str(v)


def substitute(v: Length, values: dict[str, Length]) -> Length:
    return values.get(v, v) if isinstance(v, str) else v


# ---------------------------------------------------------------- elements
@dataclass
class Element:
    """One parsed statement: a fixed point, a link or a joint."""

    keyword: ClassVar[str] = ""
    forms: ClassVar[tuple[Form, ...]] = ()
    group: ClassVar[int] = 0  # its place in the canonical text: fixed points, links, sliders, loop joints

    @classmethod
    def accepts(cls, args: Sequence[str], dim: int) -> bool:
        """Whether this class reads a statement of its keyword with these words (in ``dim``)."""
        return any(dim in f.dims and f.arity() in (None, len(args)) for f in cls.forms)

    @classmethod
    def parse(cls, args: Sequence[str], src: Source, dim: int) -> list["Element"]:
        raise NotImplementedError

    def text(self) -> str:
        """The canonical statement (what ``str(m)`` shows)."""
        raise NotImplementedError

    def mentions(self) -> list[str]:
        """The points the statement names."""
        return []

    def parameters(self) -> list[Length]:
        return []

    def with_values(self, values: dict[str, Length]) -> "Element":
        raise NotImplementedError

    @property
    def source(self) -> Optional[Source]:
        return getattr(self, "src", None)


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


# ---------------------------------------------------------------- joints of a loop (Denavit–Hartenberg)
@dataclass
class LoopJoint(Element):
    """A joint of a closed loop of links, with the Denavit–Hartenberg parameters of the link after
    it: its transformation is ``Rz(theta) Tz(d) Tx(a) Rx(twist)`` (``theta`` about the joint's axis
    z, ``d`` along it, ``a`` along the common normal x to the next joint's axis, ``twist`` about x);
    the loop closes when the product over its joints is the identity.  ``twist`` and ``theta`` are
    rational points ``(cos, sin)`` on the unit circle."""

    group: ClassVar[int] = 3
    keys: ClassVar[tuple[str, ...]] = ("d", "a", "twist")
    joint_variables: ClassVar[tuple[str, ...]] = ("theta",)  # what moves: theta, d, theta2 (universal)
    freedom: ClassVar[int] = 1
    name: str = ""
    a: Length = 0
    d: Length = 0
    twist: tuple[Fraction, Fraction] = (Fraction(1), Fraction(0))
    theta: tuple[Fraction, Fraction] = (Fraction(1), Fraction(0))
    src: Optional[Source] = field(default=None, compare=False, repr=False)

    @classmethod
    def parse(cls, args: Sequence[str], src: Source, dim: int) -> list[Element]:
        name = point_name(args[0], src)
        j = cls(name=name, src=src)
        i, seen = 1, set()
        while i < len(args):
            key = args[i]
            if key not in cls.keys:
                raise MechanismError(f"{src}: '{key}' is not a parameter of a {cls.keyword} joint "
                                     f"(its parameters: {', '.join(cls.keys)})")
            if key in seen:
                raise MechanismError(f"{src}: '{key}' is given twice")
            seen.add(key)
            n = 2 if key in ("twist", "theta") else 1
            vals = args[i + 1:i + 1 + n]
            if len(vals) < n:
                what = "its cosine and sine (such as 3/5 4/5)" if n == 2 else "a value"
                raise MechanismError(f"{src}: '{key}' needs {what}")
            if n == 2:
                c, s = number(vals[0], src, f"the cosine of {key}"), number(vals[1], src, f"the sine of {key}")
                if c * c + s * s != 1:
                    raise MechanismError(f"{src}: {key} {vals[0]} {vals[1]}: cos^2 + sin^2 = {c * c + s * s}, not 1 "
                                         "(give a rational point of the unit circle such as 3/5 4/5, or 0 1 for 90 "
                                         "degrees)")
                j = replace(j, **{key: (c, s)})
            else:
                v = number_or_name(vals[0], src)
                if key == "a" and not isinstance(v, str) and v < 0:
                    raise MechanismError(f"{src}: a is the distance between the joint axes (a length >= 0), "
                                         f"not {text_of(v)}")
                j = replace(j, **{key: v})
            i += 1 + n
        return [j]

    def text(self) -> str:
        parts = [self.keyword, self.name]
        for key in self.keys:
            v = getattr(self, key)
            if key in ("twist", "theta"):
                if v != (1, 0):
                    parts += [key, text_of(_small(v[0])), text_of(_small(v[1]))]
            elif v != 0:
                parts += [key, text_of(v)]
        return " ".join(parts)

    def parameters(self) -> list[Length]:
        return [getattr(self, k) for k in ("d", "a") if k in self.keys]

    def with_values(self, values: dict[str, Length]) -> Element:
        return replace(self, a=substitute(self.a, values), d=substitute(self.d, values))


def _small(v: Fraction) -> Length:
    return int(v) if v.denominator == 1 else v


@dataclass
class Revolute(LoopJoint):
    keyword: ClassVar[str] = "revolute"
    forms: ClassVar[tuple[Form, ...]] = (
        Form("J [d D] [a A] [twist C S]", "a revolute joint J of the loop (angle theta_J about its axis), "
                                          "then its link: offset d, length a, twist (cos, sin)", (3,)),)


@dataclass
class Prismatic(LoopJoint):
    keyword: ClassVar[str] = "prismatic"
    forms: ClassVar[tuple[Form, ...]] = (
        Form("J [theta C S] [a A] [twist C S]", "a prismatic joint J of the loop (sliding d_J along its "
                                                "axis, fixed angle theta), then its link", (3,)),)
    keys: ClassVar[tuple[str, ...]] = ("theta", "a", "twist")
    joint_variables: ClassVar[tuple[str, ...]] = ("d",)


@dataclass
class Cylindrical(LoopJoint):
    keyword: ClassVar[str] = "cylindrical"
    forms: ClassVar[tuple[Form, ...]] = (
        Form("J [a A] [twist C S]", "a cylindrical joint J of the loop (angle theta_J and sliding d_J along "
                                    "its axis), then its link", (3,)),)
    keys: ClassVar[tuple[str, ...]] = ("a", "twist")
    joint_variables: ClassVar[tuple[str, ...]] = ("theta", "d")
    freedom: ClassVar[int] = 2


@dataclass
class Universal(LoopJoint):
    keyword: ClassVar[str] = "universal"
    forms: ClassVar[tuple[Form, ...]] = (
        Form("J [d D] [a A] [twist C S]", "a universal joint J of the loop (angle theta_J about its axis, then "
                                          "theta2_J about the perpendicular axis x), then its link", (3,)),)
    joint_variables: ClassVar[tuple[str, ...]] = ("theta", "theta2")
    freedom: ClassVar[int] = 2


@dataclass
class Helical(LoopJoint):
    """A helical (screw) joint: it turns by ``theta_J`` and slides by ``d_J = pitch * theta_J``
    (theta in radians).  That coupling is not polynomial (a helix is not an algebraic curve): the
    loop's ideal is the one with the slide free, as at a cylindrical joint, which holds every
    configuration of the helical loop (docs/mechanisms.md, "Helical joints")."""

    keyword: ClassVar[str] = "helical"
    forms: ClassVar[tuple[Form, ...]] = (
        Form("J pitch P [a A] [twist C S]", "a helical joint J of the loop (angle theta_J and slide d_J = P * "
                                            "theta_J, theta in radians), then its link", (3,)),)
    keys: ClassVar[tuple[str, ...]] = ("pitch", "a", "twist")
    joint_variables: ClassVar[tuple[str, ...]] = ("theta", "d")
    pitch: Length = 0

    @classmethod
    def parse(cls, args: Sequence[str], src: Source, dim: int) -> list[Element]:
        (j,) = super().parse(args, src, dim)
        pitch = j.pitch  # type: ignore[attr-defined]
        if "pitch" not in args[1:]:
            raise MechanismError(f"{src}: a helical joint needs its pitch (helical J pitch P: the slide per radian "
                                 "of turn)")
        if isinstance(pitch, str):
            raise MechanismError(f"{src}: the pitch of a helical joint is a number, not the name '{pitch}'")
        if pitch == 0:
            raise MechanismError(f"{src}: a helical joint of pitch 0 does not slide: write revolute {j.name}")
        return [j]

    def with_values(self, values: dict[str, Length]) -> Element:
        return replace(self, a=substitute(self.a, values))


# ---------------------------------------------------------------- the registry
_REGISTRY: dict[str, list[type[Element]]] = {}


def statement(cls: type[Element]) -> type[Element]:
    """Register a statement class under its keyword (several classes may share one: the first
    that accepts the words reads them)."""
    _REGISTRY.setdefault(cls.keyword, []).append(cls)
    return cls


for _cls in (Ground, Fix, Bar, PrismaticBar, Body, Slider, LineSlider, Revolute, Prismatic, Cylindrical, Universal,
             Helical, Gear):
    statement(_cls)


def keywords() -> tuple[str, ...]:
    """The first words of the statements (what ``mechanism m { ... }`` accepts)."""
    return tuple(_REGISTRY)


def classes(keyword: str) -> list[type[Element]]:
    return _REGISTRY.get(keyword, [])


def all_forms() -> list[tuple[str, Form]]:
    """Every (keyword, form) in registration order."""
    return [(k, f) for k, cs in _REGISTRY.items() for c in cs for f in c.forms]


def arity_message(keyword: str, nargs: int) -> str:
    """What a statement with a wrong number of words is told: the forms it has."""
    forms = [f for c in classes(keyword) for f in c.forms]
    counts = sorted({f.arity() for f in forms if f.arity() is not None})
    usage = " | ".join(f"{keyword} {f.args}" for f in forms)
    if counts and all(f.arity() is not None for f in forms):
        n = ", ".join(map(str, counts[:-1])) + (" or " if len(counts) > 1 else "") + str(counts[-1])
        return f"'{keyword}' takes {n} arguments ({usage}), not {nargs}"
    return f"'{keyword}' cannot read {nargs} arguments ({usage})"


def syntax() -> str:
    """The description language's help, from the registry."""
    rows = [(f"{k} {f.args}", f.meaning) for k, f in all_forms()]
    width = max(len(a) for a, _ in rows) + 2
    lines = ["statements separated by ';' or new lines:"] + [f"  {a.ljust(width)}{m}" for a, m in rows]
    lines.append("lengths and coordinates are integers, fractions p/q or names (symbolic parameters);")
    lines.append("a description is spatial when a point is fixed with 3 coordinates or it has loop joints")
    return "\n".join(lines)


class Described(Protocol):
    """What the models and checks read of a mechanism (:class:`mech.stdlib.mechanism.Mechanism`)."""

    name: str
    dim: int
    elements: list[Element]

    @property
    def fixed(self) -> dict[str, tuple[Length, ...]]: ...

    @property
    def links(self) -> list[Link]: ...

    @property
    def sliders(self) -> list[Union[Slider, LineSlider]]: ...

    @property
    def joints(self) -> list[LoopJoint]: ...

    @property
    def gears(self) -> list[Gear]: ...

    def symbols(self) -> list[str]: ...
