"""Values of the mech language, Singular's conversions between them (and :func:`to_sympy`).

Ring-independent values are plain Python objects (``int``, ``str``) or :class:`IntVec`,
:class:`List` (of such), :class:`Proc`, :class:`Ring`.  Ring-dependent values refer to a kernel
:class:`~mech.kernel.PolyRing`: polynomials are kernel :class:`~mech.kernel.Poly` objects, the rest
are :class:`Number`, :class:`Ideal`, :class:`Matrix`, :class:`Map` and lists containing them.
Values are immutable: assigning into ``I[2]`` builds a new ideal and rebinds the variable.
Libraries add types of their own (:mod:`mech.dsl.types`); :func:`convert` converts to those too.
"""
from __future__ import annotations

import numbers
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Callable, Iterable, Optional, Sequence

from ..kernel import Poly, PolyRing
from .convert import number_fraction, poly_to_sympy
from .errors import MechRuntimeError, MechTypeError
from .types import find_type


class NoneValue:
    """Singular's ``none``: what a procedure without ``return`` value gives."""

    _instance: Optional["NoneValue"] = None

    def __new__(cls) -> "NoneValue":
        if cls._instance is None:
            cls._instance = super().__new__(cls)
        return cls._instance

    def __repr__(self) -> str:
        return "NONE"


NONE = NoneValue()
UNKNOWN = object()  # a list's ring not looked for yet


class Nothing:
    """What ``_`` holds after a top-level call of a procedure that returned nothing (Singular's
    ``typeof(_)`` is then ``?unknown type?``)."""

    type_name = "?unknown type?"

    def __repr__(self) -> str:
        return "NOTHING"


NOTHING = Nothing()


class BigInt(int):
    """Singular's bigint: an integer like int (mech's ints have any size too) whose ``div`` and
    ``mod`` are Euclidean (the remainder in [0, |b|)) where int's truncate; arithmetic with a
    bigint operand gives a bigint."""

    type_name = "bigint"
    __slots__ = ()

    def __neg__(self) -> "BigInt":
        return BigInt(-int(self))

    def __abs__(self) -> "BigInt":
        return BigInt(abs(int(self)))


class Number:
    """An element of the coefficient field of a ring (Singular's ``number``).

    From Python: ``int(n)`` and ``operator.index(n)`` for integers (in Z/p the symmetric
    representative, as Singular's ``int(n)``), ``float(n)`` and ``fractions.Fraction(n)`` over QQ,
    ``sympy.sympify(n)``; other conversions raise :class:`MechTypeError` saying why."""

    __slots__ = ("ring", "c")

    def __init__(self, ring: PolyRing, c: Any) -> None:
        self.ring = ring
        self.c = c

    def is_zero(self) -> bool:
        return self.c == 0

    def to_poly(self) -> Poly:
        return self.ring.const(self.c)

    def to_fraction(self) -> Fraction:
        """The number as a Python Fraction (over QQ; in Z/p its symmetric representative)."""
        return number_fraction(self)

    @property
    def numerator(self) -> int:
        return self.to_fraction().numerator

    @property
    def denominator(self) -> int:
        return self.to_fraction().denominator

    def as_integer_ratio(self) -> tuple[int, int]:
        f = self.to_fraction()
        return f.numerator, f.denominator

    def __int__(self) -> int:
        f = self.to_fraction()
        if f.denominator != 1:
            raise MechTypeError(f"cannot convert the number {f} to an int (it is not an integer)")
        return f.numerator

    __index__ = __int__

    def __float__(self) -> float:
        if self.ring.field.characteristic:
            raise MechTypeError(f"cannot convert a number of Z/{self.ring.field.characteristic} to a float")
        return float(self.to_fraction())

    def __bool__(self) -> bool:
        return not self.is_zero()

    def _sympy_(self) -> Any:
        return poly_to_sympy(self.to_poly())

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Number):
            return other.ring == self.ring and other.c == self.c
        if isinstance(other, (int, Fraction)) and not isinstance(other, bool):
            try:
                return self.c == self.ring.field(other)
            except (TypeError, ZeroDivisionError):
                return False
        return NotImplemented

    def __hash__(self) -> int:
        return hash(self.c)

    def __repr__(self) -> str:
        return f"Number({self.c})"



numbers.Rational.register(Number)  # fractions.Fraction(n) reads numerator and denominator


class Ideal:
    """An ideal given by generators (at least one, possibly zero); ``is_std`` marks a standard basis.

    In Python: ``len(I)``, ``iter(I)`` and ``I[k]`` are its generators, indexed from 0 (the
    language's ``I[1]`` is ``I[0]`` here); ``I == J`` compares the ideals (equal reduced Gröbner
    bases in the polynomial ring, so other generators of the same ideal are equal), while
    :meth:`same_generators` compares the generators one by one, as the language's ``==`` does.
    ``sympy.sympify(I)`` is a sympy Tuple of the generators, :meth:`to_sympy` a list."""

    __slots__ = ("ring", "gens", "is_std")

    def __init__(self, ring: PolyRing, gens: Iterable[Poly], is_std: bool = False) -> None:
        self.ring = ring
        self.gens: tuple[Poly, ...] = tuple(gens) or (ring.zero(),)
        self.is_std = is_std

    def nonzero(self) -> list[Poly]:
        return [g for g in self.gens if not g.is_zero()]

    def to_sympy(self) -> list:
        """The generators as sympy expressions."""
        return [poly_to_sympy(g) for g in self.gens]

    def to_sympy_polys(self) -> list:
        """The generators as ``sympy.Poly`` objects in the ring's variables."""
        import sympy
        syms = [sympy.Symbol(n) for n in self.ring.names]
        return [sympy.Poly(e, *syms) for e in self.to_sympy()]

    def _sympy_(self) -> Any:
        import sympy
        return sympy.Tuple(*self.to_sympy())

    def __len__(self) -> int:
        return len(self.gens)

    def __iter__(self):
        return iter(self.gens)

    def __getitem__(self, i: Any) -> Any:
        return self.gens[i]

    def same_generators(self, other: object) -> bool:
        """Whether ``other`` is an ideal with the same generators in the same order."""
        return isinstance(other, Ideal) and other.gens == self.gens

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Ideal):
            return NotImplemented
        if other.gens == self.gens:
            return True
        if other.ring is not self.ring and other.ring != self.ring:
            return False
        from ..kernel.ideals import dp_ring, ideals_equal, move
        glob = dp_ring(self.ring)
        return ideals_equal(move(self.nonzero(), glob), move(other.nonzero(), glob), glob)

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return f"Ideal({', '.join(g.to_str() for g in self.gens)})"


class Matrix:
    """A matrix of polynomials, entries row by row."""

    __slots__ = ("ring", "nrows", "ncols", "entries")

    def __init__(self, ring: PolyRing, nrows: int, ncols: int, entries: Optional[Sequence[Poly]] = None) -> None:
        self.ring = ring
        self.nrows = nrows
        self.ncols = ncols
        n = nrows * ncols
        ents = list(entries or ())[:n]
        ents += [ring.zero()] * (n - len(ents))
        self.entries: tuple[Poly, ...] = tuple(ents)

    def get(self, i: int, j: int) -> Poly:
        """Entry in row ``i``, column ``j`` (1-based)."""
        return self.entries[(i - 1) * self.ncols + (j - 1)]

    def rows(self) -> list[list[Poly]]:
        return [list(self.entries[i * self.ncols:(i + 1) * self.ncols]) for i in range(self.nrows)]

    @property
    def shape(self) -> tuple[int, int]:
        return self.nrows, self.ncols

    def __getitem__(self, ij: tuple[int, int]) -> Poly:
        """``M[i, j]``: the entry in row ``i``, column ``j``, indexed from 0 as in Python."""
        i, j = ij
        if not (-self.nrows <= i < self.nrows and -self.ncols <= j < self.ncols):
            raise IndexError(f"index ({i}, {j}) out of range for a {self.nrows}x{self.ncols} matrix")
        return self.entries[(i % self.nrows) * self.ncols + j % self.ncols]

    def to_sympy(self) -> Any:
        """The matrix as a ``sympy.Matrix``."""
        import sympy
        return sympy.Matrix(self.nrows, self.ncols, [poly_to_sympy(g) for g in self.entries])

    def _sympy_(self) -> Any:
        return self.to_sympy().as_immutable()

    def __eq__(self, other: object) -> bool:
        return (isinstance(other, Matrix) and (other.nrows, other.ncols) == (self.nrows, self.ncols)
                and other.entries == self.entries)

    def __repr__(self) -> str:
        return f"Matrix({self.nrows}x{self.ncols})"


class IntVec:
    """A vector of integers (Singular's ``intvec``)."""

    __slots__ = ("values",)

    def __init__(self, values: Iterable[int]) -> None:
        self.values: tuple[int, ...] = tuple(values) or (0,)

    def __len__(self) -> int:
        return len(self.values)

    def __iter__(self):
        return iter(self.values)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, IntVec) and other.values == self.values

    def __repr__(self) -> str:
        return f"IntVec({list(self.values)})"


class List:
    """A Singular list; unset entries (after ``L[5] = ...`` on a shorter list) hold :data:`NONE`."""

    __slots__ = ("items", "_ring")

    def __init__(self, items: Iterable[Any] = (), ring: Any = UNKNOWN) -> None:
        self.items: tuple[Any, ...] = tuple(items)
        #: the kernel ring of its first ring-dependent entry (None: none), found once by ring_of
        #: (or given by who built the list); a list's entries never change
        self._ring: Any = ring

    def __len__(self) -> int:
        return len(self.items)

    def __reduce__(self) -> tuple:
        """Pickled and copied without the ring found (the copy finds its own)."""
        return type(self), (self.items,)

    def __iter__(self):
        return iter(self.items)

    def __getitem__(self, i: int) -> Any:
        return self.items[i]

    def __eq__(self, other: object) -> bool:
        return isinstance(other, List) and other.items == self.items

    def __repr__(self) -> str:
        return f"List({list(self.items)!r})"


class ExprList:
    """The value of a comma expression or of ``return(a, b)``: several values side by side."""

    __slots__ = ("items",)

    def __init__(self, items: Iterable[Any]) -> None:
        self.items: tuple[Any, ...] = tuple(items)

    def __repr__(self) -> str:
        return f"ExprList({list(self.items)!r})"


@dataclass(frozen=True)
class OrderBlock:
    """One block of a ring's ordering as written (``dp(4)``, ``wp(1,2)``, ``a(1,1)``, ``C``)."""

    kind: str
    size: int = 0
    weights: tuple[int, ...] = ()


@dataclass(eq=False)
class Ring:
    """A ring of the language: a kernel ring plus what Singular prints about it, and the
    ring-dependent variables declared at top level while it was the basering."""

    poly: PolyRing
    params: tuple[str, ...]
    blocks: tuple[OrderBlock, ...]
    name: str = ""
    objects: dict = field(default_factory=dict)
    attributes: dict = field(default_factory=dict)  #: attrib(r, name, value)

    @property
    def names(self) -> tuple[str, ...]:
        return self.poly.names

    @property
    def characteristic(self) -> int:
        return self.poly.field.characteristic

    def var_index(self, name: str) -> Optional[int]:
        idx = self.__dict__.get("_index")
        if idx is None:
            idx = self.__dict__["_index"] = {n: i for i, n in enumerate(self.poly.names)}
        return idx.get(name)

    def __repr__(self) -> str:
        return f"Ring({self.name or '?'}: {self.poly!r})"


@dataclass(eq=False)
class Map:
    """A ring map ``source -> target`` given by the images of the source's variables."""

    source: Ring
    ring: PolyRing
    images: tuple[Poly, ...]


@dataclass(eq=False)
class Proc:
    """A procedure: parameters (type or None, name), body, its doc string and source."""

    name: str
    params: Optional[list]
    body: list
    doc: Optional[str]
    source: Any
    lib: str = ""
    body_line: int = 0


@dataclass(frozen=True)
class LibCommand:
    """A library command used as a value (Singular's library procedures are values of type proc:
    ``testMinAss(minAssGTZ, I)``); calling it calls the command."""

    command: Any

    def __str__(self) -> str:
        return f"// the {self.command.lib} procedure {self.command.name}"


TYPE_NAMES = {int: "int", BigInt: "bigint", str: "string", Number: "number", Poly: "poly", Ideal: "ideal",
              Matrix: "matrix", IntVec: "intvec", List: "list", Ring: "ring", Map: "map", Proc: "proc", NoneValue: "none",
              LibCommand: "proc"}


def typeof(v: Any) -> str:
    """Singular's type name of a value."""
    t = TYPE_NAMES.get(type(v))
    if t is not None:
        return t
    if isinstance(v, bool):
        return "int"
    if isinstance(v, ExprList):
        return "list"
    return getattr(type(v), "type_name", type(v).__name__)


def same_value(a: Any, b: Any) -> bool:
    """The language's ``==`` on values: ideals generator by generator (Python's ``==`` on ideals
    compares the ideals), lists entry by entry, anything else by ``==``."""
    if isinstance(a, Ideal):
        return a.same_generators(b)
    if isinstance(a, (List, ExprList)):
        return (type(b) is type(a) and len(a.items) == len(b.items)
                and all(same_value(x, y) for x, y in zip(a.items, b.items)))
    return a == b


def ring_of(v: Any) -> Optional[PolyRing]:
    """The kernel ring a value depends on (None for ring-independent values)."""
    if isinstance(v, (Poly, Number, Ideal, Matrix, Map)) or getattr(type(v), "type_name", "") in _MODULE_TYPES:
        return v.ring
    if type(v) is List:
        r = v._ring
        if r is UNKNOWN:  # found once per list: appending to a long list in a loop stays linear
            r = v._ring = _first_ring(v.items)
        return r
    if isinstance(v, (List, ExprList)):
        return _first_ring(v.items)
    return None


def _first_ring(items: tuple) -> Optional[PolyRing]:
    for x in items:
        if type(x) is int or type(x) is str:  # the common ring-free entries, without a call
            continue
        r = ring_of(x)
        if r is not None:
            return r
    return None


def is_ring_dependent(v: Any) -> bool:
    return ring_of(v) is not None


# ---------------------------------------------------------------- conversions
def to_sympy(v: Any) -> Any:
    """A value of the language as sympy objects: polynomials and numbers as expressions, ideals and
    lists as Python lists, matrices as ``sympy.Matrix``; ints and strings stay as they are."""
    import sympy

    if isinstance(v, Poly):
        return poly_to_sympy(v)
    if isinstance(v, Number):
        return poly_to_sympy(v.to_poly())
    if isinstance(v, Ideal):
        return [poly_to_sympy(g) for g in v.gens]
    if isinstance(v, Matrix):
        return sympy.Matrix(v.nrows, v.ncols, [poly_to_sympy(g) for g in v.entries])
    if isinstance(v, IntVec):
        return list(v.values)
    if isinstance(v, (List, ExprList)):
        return [to_sympy(x) for x in v.items]
    return v


def _need_ring(ring: Optional[PolyRing], what: str) -> PolyRing:
    if ring is None:
        raise MechRuntimeError(f"no ring active: a {what} needs a basering (declare one with ring r = ...;)")
    return ring


def _cannot(v: Any, target: str) -> MechTypeError:
    return MechTypeError(f"cannot convert {typeof(v)} to {target}")


def _check_ring(v: Any, ring: PolyRing) -> None:
    if v.ring is not ring and v.ring != ring:
        raise MechRuntimeError(f"{typeof(v)} of another ring (use fetch or imap to bring it into the basering)")


def to_int(v: Any) -> int:
    if isinstance(v, int):
        return int(v)
    if isinstance(v, Number):
        raise MechTypeError("cannot convert number to int (for integer division use div, e.g. 7 div 2)")
    raise _cannot(v, "int")


def to_number(v: Any, ring: Optional[PolyRing]) -> Number:
    if isinstance(v, Number):
        _check_ring(v, _need_ring(ring, "number"))
        return v
    if isinstance(v, int):
        r = _need_ring(ring, "number")
        return Number(r, r.field(int(v)))
    if isinstance(v, Poly) and v.is_constant():
        _check_ring(v, _need_ring(ring, "number"))
        return Number(v.ring, v.coeff_of(v.ring.zero_exp))
    raise _cannot(v, "number")


def to_poly(v: Any, ring: Optional[PolyRing]) -> Poly:
    if isinstance(v, Poly):
        _check_ring(v, _need_ring(ring, "poly"))
        return v
    if isinstance(v, Number):
        _check_ring(v, _need_ring(ring, "poly"))
        return v.to_poly()
    if isinstance(v, int):
        return _need_ring(ring, "poly").const(int(v))
    raise _cannot(v, "poly")


def to_ideal(v: Any, ring: Optional[PolyRing]) -> Ideal:
    ring = _need_ring(ring, "ideal")
    if isinstance(v, Ideal):
        _check_ring(v, ring)
        return v
    if isinstance(v, (ExprList, List)):
        gens: list[Poly] = []
        for x in v.items:
            if isinstance(x, (Ideal, Matrix)):
                gens.extend(to_ideal(x, ring).gens)
            else:
                gens.append(to_poly(x, ring))
        return Ideal(ring, gens)
    if isinstance(v, Matrix):
        _check_ring(v, ring)
        return Ideal(ring, v.entries)
    return Ideal(ring, [to_poly(v, ring)])


def to_matrix(v: Any, ring: Optional[PolyRing], nrows: int = 0, ncols: int = 0) -> Matrix:
    """A matrix from a matrix, ideal (one row), polynomial or list of entries; with dimensions
    given, entries fill row by row (missing ones are zero, extra ones dropped, as in Singular)."""
    ring = _need_ring(ring, "matrix")
    if getattr(type(v), "type_name", "") == "intmat":
        v = Matrix(ring, v.nrows, v.ncols, [ring.const(x) for x in v.values])
    if getattr(type(v), "type_name", "") in _MODULE_TYPES:  # matrix(m): the generators as columns
        _check_ring(v, ring)
        from .values_modules import matrix_entries
        v = Matrix(ring, *matrix_entries(v))
    if isinstance(v, Matrix):
        _check_ring(v, ring)
        if not nrows or (nrows, ncols) == (v.nrows, v.ncols):
            return v
        return Matrix(ring, nrows, ncols, [v.get(i, j) if i <= v.nrows and j <= v.ncols else ring.zero()
                                           for i in range(1, nrows + 1) for j in range(1, ncols + 1)])
    if isinstance(v, (ExprList, List)):
        entries: list[Poly] = []
        for x in v.items:
            entries.extend(to_matrix(x, ring).entries if isinstance(x, Matrix) else to_ideal(x, ring).gens)
    else:
        entries = list(to_ideal(v, ring).gens)
    if not nrows:
        return Matrix(ring, 1, len(entries), entries)
    return Matrix(ring, nrows, ncols, entries[:nrows * ncols])


def to_intvec(v: Any) -> IntVec:
    if isinstance(v, IntVec):
        return v
    if isinstance(v, int):
        return IntVec([int(v)])
    if isinstance(v, (ExprList, List)):
        out: list[int] = []
        for x in v.items:
            out.extend(to_intvec(x).values)
        return IntVec(out)
    raise _cannot(v, "intvec")


def to_list(v: Any) -> List:
    if isinstance(v, List):
        return v
    if isinstance(v, ExprList):
        return List(v.items)
    return List([v])


def to_string(v: Any) -> str:
    if isinstance(v, str):
        return v
    if isinstance(v, ExprList):
        return "".join(to_string(x) for x in v.items)
    raise _cannot(v, "string")


def convert(v: Any, typ: str, ring: Optional[PolyRing], warn: Optional[Callable[[str], None]] = None) -> Any:
    """``v`` as a value of the declared type ``typ`` (``def`` keeps it as it is; ``warn``: where a
    library type's converter reports mistakes that are not errors)."""
    if typ == "def":
        return List(v.items) if isinstance(v, ExprList) else v
    if typ == "int":
        v = _single(v, typ)
        if type(v) is BigInt:
            raise MechTypeError("int = bigint is not supported (as in Singular: int(b) converts)")
        return to_int(v)
    if typ == "bigint":
        return BigInt(to_int(_single(v, typ)))
    if typ == "number":
        return to_number(_single(v, typ), ring)
    if typ == "poly":
        return to_poly(_single(v, typ), ring)
    if typ == "ideal":
        return to_ideal(v, ring)
    if typ == "matrix":
        return to_matrix(v, ring)
    if typ in _CONVERTERS:
        return _CONVERTERS[typ](v, ring)
    if typ == "intvec":
        return to_intvec(v)
    if typ == "list":
        return to_list(v)
    if typ == "string":
        return to_string(v)
    if typ == "ring":
        if isinstance(_single(v, typ), Ring):
            return _single(v, typ)
        raise _cannot(v, "ring")
    if typ == "proc":
        if isinstance(_single(v, typ), Proc):
            return _single(v, typ)
        raise _cannot(v, "proc")
    if typ == "map":
        if isinstance(_single(v, typ), Map):
            return _single(v, typ)
        raise _cannot(v, "map")
    plugin = find_type(typ)  # a type a library registered (mech.dsl.types)
    if plugin is not None:
        return plugin.apply(_single(v, typ), warn)
    raise MechTypeError(f"type '{typ}' is not supported yet")


_MODULE_TYPES = ("vector", "module")
_CONVERTERS: dict[str, Callable[[Any, Optional[PolyRing]], Any]] = {}


def register_converter(typ: str, convert: Callable[[Any, Optional[PolyRing]], Any]) -> None:
    """The conversion of values to a built-in ring-dependent type defined in its own module
    (vector, module: mech.dsl.convert_modules)."""
    _CONVERTERS[typ] = convert


def _single(v: Any, typ: str) -> Any:
    if isinstance(v, ExprList):
        if len(v.items) == 1:
            return v.items[0]
        raise MechTypeError(f"cannot assign {len(v.items)} values to one {typ}")
    return v
