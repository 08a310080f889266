"""Values of the Macaulay2 dialect that Singular's language lacks: symbols (names without a value),
options ``a => b``, arrays ``[a, b]``, sets, tallies, monomial ideals, ring maps, factorizations,
the coefficient rings ``QQ``, ``ZZ`` and ``ZZ/p`` as values, and functions (``(a,b) -> ...``,
commands used as values, compositions ``f @@ g`` and partial applications ``f_x``).

Lists are :class:`~mech.dsl.values.List` and sequences ``(a, b)`` are
:class:`~mech.dsl.values.ExprList`, as in the Singular dialect."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Iterable, Optional

from ..kernel import GF, QQ, Poly
from .errors import Source
from .values import Ideal, List, Matrix


@dataclass(frozen=True)
class Symbol:
    """A name without a value (``Lex``, ``a`` before any ring has a variable ``a``, ``symbol x``,
    ``x_1`` outside rings)."""
    name: str


@dataclass(frozen=True)
class Opt:
    """An option ``key => value``."""
    key: Any
    value: Any


class Array(List):
    """``[a, b]``: a list Macaulay2 keeps apart from ``{a, b}`` (``I^[2]``, ``apply([1,2], f)``)."""

    __slots__ = ()

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Array) and other.items == self.items

    def __repr__(self) -> str:
        return f"Array({list(self.items)!r})"


class VerticalList(List):
    """A list Macaulay2 shows one entry a line (a ring's monomial order): ``VerticalList{...}``."""

    __slots__ = ()


class OptionTable:
    """Option names with their values, in Macaulay2's order; ``(options R).MonomialOrder`` reads one."""

    __slots__ = ("entries",)
    type_name = "OptionTable"

    def __init__(self, entries: list[tuple[str, Any]]) -> None:
        self.entries = entries

    @property
    def m2_fields(self) -> dict[str, Any]:
        return dict(self.entries)


class Monoid:
    """``monoid[x, y]`` or ``monoid R``: the monoid of monomials in named variables, printed by the
    name it was first assigned to (``vars``, ``gens`` and ``numgens`` read it)."""

    __slots__ = ("names", "name")
    type_name = "Monoid"

    def __init__(self, names: Iterable[str]) -> None:
        self.names = tuple(names)
        self.name = ""


class M2Set:
    """``set {a, b}``: distinct elements (kept in the order first met) with their keys."""

    __slots__ = ("items", "keys")

    def __init__(self, items: Iterable[Any], key: Any) -> None:
        self.items: list[Any] = []
        self.keys: dict[Any, Any] = {}
        for x in items:
            k = key(x)
            if k not in self.keys:
                self.keys[k] = x
                self.items.append(x)


class Tally:
    """``tally L``: how often each element occurs (elements by their keys, in order first met)."""

    __slots__ = ("counts", "items")

    def __init__(self, items: Iterable[Any], key: Any) -> None:
        self.counts: dict[Any, int] = {}
        self.items: dict[Any, Any] = {}
        for x in items:
            k = key(x)
            self.counts[k] = self.counts.get(k, 0) + 1
            self.items.setdefault(k, x)


class MonomialIdeal(Ideal):
    """An ideal Macaulay2 knows to be monomial (``monomialIdeal``): minimal monomial generators."""

    __slots__ = ()


@dataclass(frozen=True)
class Factored:
    """The result of ``factor``: a unit and (factor, exponent) pairs, printed as a product."""
    unit: Any
    factors: tuple[tuple[Poly, int], ...]


@dataclass(eq=False)
class CoeffRing:
    """``QQ``, ``ZZ`` or ``ZZ/p`` as a value (``kk = ZZ/101``); ``characteristic`` None for ZZ."""
    characteristic: Optional[int]
    name: str = ""

    @property
    def field(self) -> Any:
        if self.characteristic is None:
            return None
        return QQ if self.characteristic == 0 else GF(self.characteristic)

    def describe(self) -> str:
        if self.characteristic is None:
            return "ZZ"
        return "QQ" if self.characteristic == 0 else f"ZZ/{self.characteristic}"


#: the rings QQ and ZZ (``ZZ/p`` values are made as needed)
QQ_RING = CoeffRing(0, "QQ")
ZZ_RING = CoeffRing(None, "ZZ")


@dataclass(eq=False)
class RingMap:
    """A ring map ``source -> target`` (``map(S, R, {...})``): the images of the source's variables
    (its flattened variables: a tower's coefficient variables too)."""
    target: Any
    source: Any
    images: tuple[Poly, ...]
    degree_map: Any = None  #: DegreeMap => d -> ...: degree -> degree (a Python function), None: identity

    @property
    def m2_fields(self) -> dict[str, Any]:
        """``F.matrix``: the one-row matrix of the images."""
        return {"matrix": Matrix(self.target.poly, 1, len(self.images), list(self.images))}


@dataclass(eq=False)
class M2Function:
    """A function ``(a, b) -> body``, named after the variable it was first assigned to."""
    params: list[str]
    body: Any
    source: Source
    captured: dict  # the enclosing function's variables when this one was made
    name: str = "-*Function*-"


@dataclass(eq=False)
class CommandRef:
    """A command used as a value (``apply(L, dim)``)."""
    command: Any

    @property
    def name(self) -> str:
        return self.command.name


@dataclass(eq=False)
class Composed:
    """``f @@ g``: x -> f(g(x))."""
    outer: Any
    inner: Any
    name: str = "-*Function*-"


@dataclass(eq=False)
class Partial:
    """``f_x`` for a function ``f``: y -> f(x, y) (``diff_x``)."""
    func: Any
    first: Any
    name: str = "-*Function*-"


FUNCTIONS = (M2Function, CommandRef, Composed, Partial, RingMap)


class Iterator:
    """``iterator x`` (and ``apply``/``select`` on one or on a string): a lazy stream of values that
    ``next`` takes one by one; printed by the name it was first assigned to, as Macaulay2 does."""

    __slots__ = ("source", "name")
    type_name = "Iterator"

    def __init__(self, source: Iterable[Any]) -> None:
        self.source = iter(source)
        self.name = "-*Function*-"


@dataclass(eq=False)
class IndexedTable:
    """The value of ``x`` once a ring has variables ``x_i``: its indexed variables by index."""
    name: str
    entries: dict = field(default_factory=dict)
