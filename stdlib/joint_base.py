"""The common ground of the joint model: a statement's source and argument forms, the parsing of
its words (numbers, names, points) and :class:`Element`, the class every kind of statement
derives from.  The kinds are in :mod:`mech.stdlib.joints_points` (points, links, sliders, gears)
and :mod:`mech.stdlib.joints_loop` (joints of a loop, with Denavit–Hartenberg parameters); the
registry that turns them into a language is :mod:`mech.stdlib.joints`.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from fractions import Fraction
from typing import ClassVar, Optional, Sequence, Union

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
