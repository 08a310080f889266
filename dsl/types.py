"""Value types that libraries add to the language (plug-ins), beside the built-in ones of
:mod:`mech.dsl.values`.

A library registers a type with :func:`register_type`; from then on the type's name is a type
keyword (declarations ``T x = ...;``, parameters ``proc p(T x)``, highlighting, completion), and
a declaration converts its value with the type's converter::

    from mech.dsl.types import register_type

    register_type("graph", to_graph,                     # to_graph("node a; edge a b") -> a Graph
                  default="a graph is declared with its description: graph g = \"node a\";",
                  statements=("node", "edge"))

``convert(value)`` turns one value of the language into a value of the type (raise
``MechTypeError`` / ``MechRuntimeError`` from :mod:`mech.dsl.errors` when it cannot; a converter
with a ``warn`` parameter, ``convert(value, warn=None)``, is given the interpreter's warning
printer, ``warn(message)`` printing ``// ** message``, for mistakes that are not errors); the value's
Python class names the type by a class attribute ``type_name`` (what ``typeof`` prints) and prints
with ``str``.  ``default`` is what ``T x;`` declares: a function returning the value, or the error
message that a value is required.  A type with ``statements`` (the first words its description
language accepts, or a function returning them) may also be declared by a block of statements::

    T x { word word ...; word ...; }

which is ``T x = "word word ...; word ...";`` (a statement starting with another word is a syntax
error listing the accepted ones).
"""
from __future__ import annotations

import inspect
from dataclasses import dataclass
from typing import Any, Callable, Optional, Sequence, Union

Statements = Union[Sequence[str], Callable[[], Sequence[str]]]


@dataclass(frozen=True)
class LanguageType:
    """A registered type: its name, converter, declaration default and block statements."""

    name: str
    convert: Callable[[Any], Any]
    default: Union[Callable[[], Any], str]
    statements: Optional[Statements] = None

    def apply(self, value: Any, warn: Optional[Callable[[str], None]] = None) -> Any:
        """``convert(value)``, with ``warn`` when the converter takes it."""
        if warn is not None and "warn" in inspect.signature(self.convert).parameters:
            return self.convert(value, warn=warn)
        return self.convert(value)

    def block_statements(self) -> Optional[tuple[str, ...]]:
        """The first words of the statements a block ``T x { ... }`` accepts (None: no block form)."""
        s = self.statements
        if s is None:
            return None
        return tuple(s() if callable(s) else s)


_TYPES: dict[str, LanguageType] = {}


def register_type(name: str, convert: Callable[[Any], Any], default: Union[Callable[[], Any], str],
                  statements: Optional[Statements] = None) -> LanguageType:
    """Add (or replace) the language type ``name``; see the module's description."""
    if not name.isidentifier():
        raise ValueError(f"a type's name is an identifier, not {name!r}")
    t = _TYPES[name] = LanguageType(name, convert, default, statements)
    return t


def unregister_type(name: str) -> None:
    """Remove a registered type (tests registering their own)."""
    _TYPES.pop(name, None)


class _Deferred:
    """A type whose module is imported when the type is first used (:func:`defer_type`)."""

    def __init__(self, name: str, load: Callable[[], None], statements: bool) -> None:
        self.name, self.load = name, load
        self.statements = True if statements else None  # what block_types reads


def defer_type(name: str, load: Callable[[], None], statements: bool) -> None:
    """Name the type ``name`` (for the parser) before ``load`` registers it; ``statements``:
    whether it has a block form."""
    _TYPES.setdefault(name, _Deferred(name, load, statements))  # type: ignore[arg-type]


def find_type(name: str) -> Optional[LanguageType]:
    """The registered type ``name`` (None for built-in and unknown types)."""
    t = _TYPES.get(name)
    if type(t) is _Deferred:
        t.load()
        t = _TYPES.get(name)
        if type(t) is _Deferred:
            raise RuntimeError(f"the type {name} was not registered by its module")
    return t


def type_names() -> tuple[str, ...]:
    """The names of the registered types, in order of registration."""
    return tuple(_TYPES)


def block_types() -> tuple[str, ...]:
    """The registered types that a block of statements can declare."""
    return tuple(n for n, t in _TYPES.items() if t.statements is not None)
