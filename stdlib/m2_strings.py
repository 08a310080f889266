"""Iterators and strings in the Macaulay2 dialect: ``iterator``, ``next``, ``concatenate``,
``toUpper``, ``toLower`` (``apply``, ``select``, ``toList`` and ``join`` take iterators in
:mod:`mech.stdlib.m2_lists`)."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechTypeError
from ..dsl.m2_values import Iterator, Symbol
from ..dsl.registry import command
from ..dsl.values import NONE, ExprList, List, typeof
from .m2_lists import Seq, _items


@command("concatenate", dialect="m2")
def concatenate(*xs: Any) -> str:
    """concatenate(x, ...): the strings, symbols and integers joined (lists and sequences
    flattened, null as nothing)."""
    out: list[str] = []

    def visit(x: Any) -> None:
        if isinstance(x, (List, ExprList)):
            for y in x.items:
                visit(y)
        elif isinstance(x, (str, int, Symbol)) and not isinstance(x, bool):
            out.append(x.name if isinstance(x, Symbol) else str(x))
        elif x is not NONE:
            raise MechTypeError(f"concatenate takes strings, symbols and integers, not a {typeof(x)}")
    visit(ExprList(list(xs)))
    return "".join(out)


@command("iterator", dialect="m2")
def iterator(x: Seq) -> Iterator:
    """iterator x: an iterator over the entries of a list, sequence or string (itself for an iterator)."""
    return x if isinstance(x, Iterator) else Iterator(_items(x))


@command("next", dialect="m2")
def next_(it: Iterator) -> Any:
    """next it: the iterator's next value (the symbol StopIteration at its end)."""
    return next(it.source, Symbol("StopIteration"))


@command("toUpper", dialect="m2")
def to_upper(s: str) -> str:
    """toUpper s: the string in upper case."""
    return s.upper()


@command("toLower", dialect="m2")
def to_lower(s: str) -> str:
    """toLower s: the string in lower case."""
    return s.lower()

