"""The statements of a mechanism's description, one class per kind: the joint model's registry.

Each kind is a class (a subclass of :class:`Element`) with its keyword, its argument forms and
their meaning (the syntax help), :meth:`Element.parse` (one statement's words to elements),
its canonical text, its points and parameters.  :func:`statement` registers a class;
the parser (:func:`mech.stdlib.mechanism.parse_mechanism`), the block form's accepted words
(:func:`keywords`), the syntax help (:func:`syntax`) and the documentation's table come from
the registry.  The kinds live in :mod:`mech.stdlib.joints_points` and
:mod:`mech.stdlib.joints_loop`, their common ground in :mod:`mech.stdlib.joint_base`; the names are
re-exported here.  The models that turn elements into variables and equations are
:mod:`mech.stdlib.planar` (points in the plane, links with orientations ``(c_i, s_i)``) and
:mod:`mech.stdlib.spatial` (points in space, bodies with rotation frames, loops of joints with
Denavit–Hartenberg parameters).
"""
from __future__ import annotations

from typing import Protocol, Union

from mech.kernel import PolyRing

from mech.stdlib.joint_base import (Element, Form, Length, MechanismError, Source, number, number_or_name, point_name,
                                    substitute, text_of, where)
from mech.stdlib.joints_loop import Cylindrical, Helical, LoopJoint, Prismatic, Revolute, Universal
from mech.stdlib.joints_points import Bar, Body, Fix, Gear, Ground, LineSlider, Link, PrismaticBar, Slider

__all__ = ["Bar", "Body", "Cylindrical", "Described", "Element", "Fix", "Form", "Gear", "Ground", "Helical", "Length",
           "LineSlider", "Link", "LoopJoint", "MechanismError", "Prismatic", "PrismaticBar", "Revolute", "Slider",
           "Source", "Universal", "all_forms", "arity_message", "classes", "keywords", "number", "number_or_name",
           "point_name", "statement", "substitute", "syntax", "text_of", "where"]


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

    def ring(self, values: dict[str, Length] | None = None) -> PolyRing: ...
