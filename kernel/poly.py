"""Sparse multivariate polynomials over a coefficient field.

A :class:`Poly` is an immutable map from exponent tuples to nonzero coefficients,
bound to a :class:`PolyRing` (field, variable names, monomial ordering).
"""
from __future__ import annotations

from math import comb
from operator import le as _le

from typing import Any, Iterator, Sequence

from . import flint_bridge
from .coeffs import Field
from .errors import DomainError
from .order import Exp, MonomialOrder
from .powering import power


class PolyRing:
    """The polynomial ring ``field[names]`` with a monomial ordering."""

    def __init__(self, field: Field, names: Sequence[str], order: MonomialOrder) -> None:
        if order.nvars != len(names):
            raise DomainError(f"the ordering has {order.nvars} variables, the ring {len(names)}")
        if len(set(names)) != len(names):
            raise DomainError("variable names must be distinct")
        self.field = field
        self.names = tuple(names)
        self.order = order
        self.nvars = len(names)
        self.zero_exp: Exp = (0,) * self.nvars

    def __eq__(self, other: object) -> bool:
        return (isinstance(other, PolyRing) and self.field == other.field
                and self.names == other.names and self.order == other.order)

    def __hash__(self) -> int:
        return hash((self.field, self.names, self.order))

    def __repr__(self) -> str:
        return f"PolyRing({self.field!r}, {list(self.names)!r}, {self.order!r})"

    # constructors
    def zero(self) -> "Poly":
        return Poly(self, {})

    def one(self) -> "Poly":
        return Poly(self, {self.zero_exp: self.field.one})

    def const(self, c: Any) -> "Poly":
        c = self.field(c)
        return Poly(self, {self.zero_exp: c} if c != 0 else {})

    def gen(self, i: int) -> "Poly":
        e = [0] * self.nvars
        e[i] = 1
        return Poly(self, {tuple(e): self.field.one})

    def gens(self) -> list["Poly"]:
        return [self.gen(i) for i in range(self.nvars)]

    def monomial(self, exp: Exp, coeff: Any = None) -> "Poly":
        c = self.field.one if coeff is None else self.field(coeff)
        return Poly(self, {tuple(exp): c} if c != 0 else {})

    def from_dict(self, terms: dict[Exp, Any]) -> "Poly":
        """A polynomial from ``{exponent: coefficient}``, converting and dropping zeros."""
        conv = {}
        for e, c in terms.items():
            c = self.field(c)
            if c != 0:
                conv[tuple(e)] = c
        return Poly(self, conv)

    def index(self, name: str) -> int:
        return self.names.index(name)


class Poly:
    """An element of a :class:`PolyRing`; ``terms`` maps exponents to nonzero coefficients."""

    __slots__ = ("ring", "terms", "_lm", "_hash")

    def __init__(self, ring: PolyRing, terms: dict[Exp, Any]) -> None:
        self.ring = ring
        self.terms = terms  # never changed after construction: the hash is kept
        self._lm: Exp | None = None
        self._hash: int | None = None

    # structure
    def is_zero(self) -> bool:
        return not self.terms

    def is_constant(self) -> bool:
        return not self.terms or (len(self.terms) == 1 and self.ring.zero_exp in self.terms)

    def lm(self) -> Exp:
        """Leading exponent with respect to the ring's ordering."""
        if self._lm is None:
            if not self.terms:
                raise DomainError("the zero polynomial has no leading monomial")
            self._lm = max(self.terms, key=self.ring.order.key)
        return self._lm

    def lc(self) -> Any:
        return self.terms[self.lm()]

    def lt(self) -> "Poly":
        e = self.lm()
        return Poly(self.ring, {e: self.terms[e]})

    def sorted_terms(self) -> list[tuple[Exp, Any]]:
        """Terms from the largest monomial down."""
        t = self.terms
        return [(e, t[e]) for e in sorted(t, key=self.ring.order.key, reverse=True)]

    def __iter__(self) -> Iterator[tuple[Exp, Any]]:
        return iter(self.sorted_terms())

    def __len__(self) -> int:
        return len(self.terms)

    def total_degree(self) -> int:
        """Largest total degree of a term (-1 for zero), Singular's ``deg``."""
        return max(map(sum, self.terms), default=-1)

    def degree_in(self, i: int) -> int:
        return max((e[i] for e in self.terms), default=-1)

    def variables(self) -> set[int]:
        return {i for e in self.terms for i, v in enumerate(e) if v}

    def is_homogeneous(self) -> bool:
        return len({sum(e) for e in self.terms}) <= 1

    def coeff_of(self, exp: Exp) -> Any:
        return self.terms.get(tuple(exp), self.ring.field.zero)

    # arithmetic
    def _coerce(self, other: Any) -> "Poly":
        if isinstance(other, Poly):
            if other.ring is not self.ring and other.ring != self.ring:
                raise DomainError("polynomials of different rings")
            return other
        return self.ring.const(other)

    def __add__(self, other: Any) -> "Poly":
        try:
            other = self._coerce(other)
        except TypeError:               # not a number of this field: let the other operand decide
            return NotImplemented
        t = dict(self.terms)
        for e, c in other.terms.items():
            v = t.get(e)
            if v is None:
                t[e] = c
            else:
                v = v + c
                if v == 0:
                    del t[e]
                else:
                    t[e] = v
        return Poly(self.ring, t)

    __radd__ = __add__

    def __neg__(self) -> "Poly":
        return Poly(self.ring, {e: -c for e, c in self.terms.items()})

    def __sub__(self, other: Any) -> "Poly":
        try:
            return self + (-self._coerce(other))
        except TypeError:
            return NotImplemented

    def __rsub__(self, other: Any) -> "Poly":
        try:
            return self._coerce(other) - self
        except TypeError:
            return NotImplemented

    def __mul__(self, other: Any) -> "Poly":
        if not isinstance(other, Poly):
            try:
                c = self.ring.field(other)
            except TypeError:
                return NotImplemented
            if c == 0:
                return self.ring.zero()
            return Poly(self.ring, {e: v * c for e, v in self.terms.items()})
        other = self._coerce(other)
        if len(self.terms) > len(other.terms):
            a, b = self.terms, other.terms
        else:
            a, b = other.terms, self.terms
        if len(b) == 1:  # a term times a polynomial (p*x in loops): no two products meet
            (eb, cb), = b.items()
            t = {}
            for ea, ca in a.items():
                c = ca * cb
                if c != 0:
                    t[tuple([x + y for x, y in zip(ea, eb)])] = c
            return Poly(self.ring, t)
        if len(a) * len(b) >= _FLINT_PAIRS and _collisions(a, b):
            t = flint_bridge.product(self.ring.field, self.ring.nvars, a, b)
            if t is not None:
                return Poly(self.ring, t)
        t = {}
        for eb, cb in b.items():
            for ea, ca in a.items():
                e = tuple([x + y for x, y in zip(ea, eb)])
                v = t.get(e)
                t[e] = ca * cb if v is None else v + ca * cb
        return Poly(self.ring, {e: c for e, c in t.items() if c != 0})

    __rmul__ = __mul__

    def __truediv__(self, other: Any) -> "Poly":
        if isinstance(other, Poly):
            if not other.is_constant() or other.is_zero():
                raise ZeroDivisionError("division by zero") if other.is_zero() else \
                    TypeError("division by a non-constant polynomial")
            other = other.lc()
        c = self.ring.field(other)
        if c == 0:
            raise ZeroDivisionError("division by zero")
        inv = self.ring.field.one / c
        return self * inv

    def __pow__(self, k: int) -> "Poly":
        if not isinstance(k, int) or k < 0:
            raise DomainError("exponent must be a non-negative integer")
        if len(self.terms) == 1:
            (e, c), = self.terms.items()
            return Poly(self.ring, {tuple(v * k for v in e): c ** k})
        if k > 1 and self.terms and len(self.terms) ** 2 * k >= _FLINT_PAIRS:
            t = flint_bridge.power(self.ring.field, self.ring.nvars, self.terms, k)
            if t is not None:
                return Poly(self.ring, t)
        return power(self, k, self.ring.one())

    def mul_term(self, exp: Exp, coeff: Any) -> "Poly":
        """``self * coeff * x^exp``."""
        return Poly(self.ring, {tuple([x + y for x, y in zip(e, exp)]): c * coeff
                                for e, c in self.terms.items()})

    def monic(self) -> "Poly":
        if not self.terms:
            return self
        return self * (self.ring.field.one / self.lc())

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Poly):
            return self.ring == other.ring and self.terms == other.terms
        if isinstance(other, (int,)):
            return self.terms == self.ring.const(other).terms
        return NotImplemented

    def __hash__(self) -> int:
        if self._hash is None:
            self._hash = hash(frozenset(self.terms.items()))
        return self._hash

    def __repr__(self) -> str:
        return f"Poly({self.to_str()})"

    def to_str(self) -> str:
        """A plain ``x^2*y-3*z`` rendering (the DSL has Singular's printer)."""
        if not self.terms:
            return "0"
        out = []
        for e, c in self.sorted_terms():
            mono = "*".join(n if k == 1 else f"{n}^{k}" for n, k in zip(self.ring.names, e) if k)
            cs = str(c)
            s = cs if not mono else (mono if cs == "1" else "-" + mono if cs == "-1" else f"{cs}*{mono}")
            out.append(s if s.startswith("-") or not out else "+" + s)
        return "".join(out)

    # evaluation and substitution
    def evaluate(self, values: Sequence[Any]) -> Any:
        """Value at a point given as field elements."""
        f = self.ring.field
        total = f.zero
        for e, c in self.terms.items():
            t = c
            for v, k in zip(values, e):
                if k:
                    t = t * f(v) ** k
            total = total + t
        return total

    def compose(self, images: Sequence["Poly"], target: PolyRing | None = None) -> "Poly":
        """Substitute ``images[i]`` (polynomials of ``target``) for the i-th variable."""
        target = target or self.ring
        result = target.zero()
        powers: dict[tuple[int, int], Poly] = {}
        for e, c in self.terms.items():
            t = target.const(c) if target.field == self.ring.field else target.const(
                self.ring.field.to_fraction(c))
            for i, k in enumerate(e):
                if k:
                    p = powers.get((i, k))
                    if p is None:
                        p = powers[(i, k)] = images[i] ** k
                    t = t * p
            result = result + t
        return result

    def diff(self, i: int) -> "Poly":
        """Partial derivative with respect to variable ``i``."""
        t = {}
        for e, c in self.terms.items():
            k = e[i]
            if k:
                c2 = c * k
                if c2 != 0:
                    e2 = list(e)
                    e2[i] -= 1
                    t[tuple(e2)] = c2
        return Poly(self.ring, t)


def divides(a: Exp, b: Exp) -> bool:
    """Whether ``x^a`` divides ``x^b``."""
    return all(map(_le, a, b))


def lcm_exp(a: Exp, b: Exp) -> Exp:
    return tuple([x if x > y else y for x, y in zip(a, b)])


def sub_exp(a: Exp, b: Exp) -> Exp:
    return tuple([x - y for x, y in zip(a, b)])


def add_exp(a: Exp, b: Exp) -> Exp:
    return tuple([x + y for x, y in zip(a, b)])


def support_mask(e: Exp) -> int:
    """The bit mask of the variables in ``x^e`` (a quick test before ``divides``)."""
    m = 0
    for i, v in enumerate(e):
        if v:
            m |= 1 << i
    return m


_FLINT_PAIRS = 64
"""Products with at least this many pairs of terms may go to python-flint (see ``_collisions``)."""


def _collisions(a: dict[Exp, Any], b: dict[Exp, Any]) -> bool:
    """Whether the product of ``a`` and ``b`` has at most a third as many terms as pairs of
    terms (its monomials bounded by the degree box and the total degree): then flint's
    product in C beats the schoolbook loop even with the conversions, which cost about as
    much per term as the loop (measured: 10-25x faster with many collisions, 0.4-1x with none)."""
    if not a or not b or not next(iter(a)):
        return False
    box, used = 1, 0
    for da, db in zip(map(max, zip(*a)), map(max, zip(*b))):
        box *= da + db + 1
        used += da + db > 0
    degree = max(map(sum, a)) + max(map(sum, b))
    return 3 * min(box, comb(used + degree, used)) <= len(a) * len(b)
