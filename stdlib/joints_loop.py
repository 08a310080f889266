"""The joints of a closed loop of links, each with the Denavit–Hartenberg parameters of the link
after it: revolute, prismatic, cylindrical, universal and helical (:mod:`mech.stdlib.loops` turns
a loop into equations; :mod:`mech.stdlib.joints` registers the kinds).
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace
from fractions import Fraction
from typing import ClassVar, Optional, Sequence

from mech.stdlib.joint_base import (Element, Form, Length, MechanismError, Source, number, number_or_name, point_name,
                                    substitute, text_of)


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
