"""Simple algebraic extensions K[a]/(m(a)) of QQ and Z/p: the coefficients of Singular rings with
one parameter and a ``minpoly``, ``ring r = (0,a),(x,y),dp; minpoly = a2+1;``.

An element is the remainder of a univariate polynomial in the parameter modulo the monic minimal
polynomial ``m`` (flint's ``fmpq_poly`` over QQ, ``nmod_poly`` over Z/p), so every element has one
representation.  Inverses come from the extended Euclidean algorithm; an element that shares a
factor with ``m`` (``m`` reducible) has no inverse and division by it is refused.

The field subclasses :class:`~.ratfunc.RationalFunctionField` and its elements :class:`~.ratfunc.RatFunc`
(``num/den``: an integer polynomial over a positive integer, computed on demand), so code written
for parameters (maps, printing, conversions) reads them unchanged.  Printing follows Singular: a
constant prints as a number, anything else as its polynomial in parentheses with rational
coefficients, ``(-1/2a+1/2)``.
"""
from __future__ import annotations

from fractions import Fraction
from typing import Any

import flint

from .errors import DomainError, NotSupported
from .powering import power
from .ratfunc import RatFunc, RationalFunctionField


class AlgebraicField(RationalFunctionField):
    """``K[a]/(m)`` for K = QQ (``characteristic`` 0) or Z/p and a univariate ``m`` of degree >= 1."""

    def __init__(self, characteristic: int, param: str, modulus: Any) -> None:
        super().__init__(characteristic, (param,))
        self.poly_type = flint.fmpq_poly if characteristic == 0 else (
            lambda cs: flint.nmod_poly([int(c) for c in cs], characteristic))
        m = self._univariate(modulus)
        if m.degree() < 1:
            raise DomainError("the minimal polynomial must have degree at least 1")
        self.modulus = m / m.coeffs()[-1] if characteristic == 0 else m * pow(int(m.coeffs()[-1]), -1, characteristic)
        self.degree = m.degree()
        self.zero = AlgNum(self, self.poly_type([0]))
        self.one = AlgNum(self, self.poly_type([1]))

    @classmethod
    def over(cls, field: RationalFunctionField, m: RatFunc) -> "AlgebraicField":
        """The extension of ``field`` (one parameter) by the number ``m``, a polynomial in the parameter."""
        if isinstance(field, AlgebraicField):
            raise DomainError("the ring already has a minimal polynomial")
        if len(field.params) != 1:
            raise NotSupported("a minimal polynomial needs a ring with exactly one parameter")
        if not m.den.is_constant():
            raise DomainError("the minimal polynomial must be a polynomial in the parameter")
        return cls(field.characteristic, field.params[0], _univ_coeffs(m.num, m.den, field.characteristic))

    def _univariate(self, coeffs: Any) -> Any:
        if isinstance(coeffs, (flint.fmpq_poly, flint.nmod_poly)):
            return coeffs
        p = self.characteristic
        if p == 0:
            return flint.fmpq_poly([flint.fmpq(c.numerator, c.denominator) if isinstance(c, Fraction) else c
                                    for c in coeffs])
        return flint.nmod_poly([int(c) % p if not isinstance(c, Fraction) else
                                c.numerator * pow(c.denominator, -1, p) % p for c in coeffs], p)

    def element(self, u: Any) -> "AlgNum":
        return AlgNum(self, u % self.modulus)

    # construction
    def gen(self, i: int = 0) -> "AlgNum":
        return self.element(self.poly_type([0, 1]))

    def from_polys(self, num: Any, den: Any = None) -> "AlgNum":
        n = self._from_mpoly(num)
        if den is None:
            return n
        return n / self._from_mpoly(den)

    def _from_mpoly(self, p: Any) -> "AlgNum":
        if isinstance(p, int):
            return self(p)
        return self.element(self._univariate(_univ_coeffs(p, None, self.characteristic)))

    def __call__(self, x: Any) -> "AlgNum":
        if isinstance(x, AlgNum):
            if x.field is self or x.field == self:
                return x
            raise TypeError(f"cannot convert an element of {x.field!r} to {self!r}")
        if isinstance(x, RatFunc):
            if x.field.characteristic == self.characteristic and x.field.params == self.params:
                return self.from_polys(x.num, x.den)
            raise TypeError(f"cannot convert an element of {x.field!r} to {self!r}")
        if isinstance(x, bool):
            x = int(x)
        p = self.characteristic
        if isinstance(x, (int, flint.fmpz)):
            return AlgNum(self, self.poly_type([int(x)]))
        if isinstance(x, flint.nmod):
            if p == 0:
                raise TypeError(f"cannot convert {x!r} to an element of {self!r}")
            return AlgNum(self, self.poly_type([int(x)]))
        if isinstance(x, (Fraction, flint.fmpq)) or (hasattr(x, "p") and hasattr(x, "q")):
            num, den = (x.numerator, x.denominator) if isinstance(x, Fraction) else (int(x.p), int(x.q))
            if p == 0:
                return AlgNum(self, flint.fmpq_poly([flint.fmpq(num, den)]))
            if den % p == 0:
                raise ZeroDivisionError("division by zero")
            return AlgNum(self, self.poly_type([num * pow(den, -1, p) % p]))
        if isinstance(x, str):
            if x in self.params:
                return self.gen()
            raise DomainError(f"{x!r} is not a parameter of {self!r}")
        if isinstance(x, (flint.fmpz_mpoly, flint.nmod_mpoly)) and x.context() is self.ctx:
            return self._from_mpoly(x)
        raise TypeError(f"cannot convert {x!r} to an element of {self!r}")

    # queries
    def is_constant(self, c: "AlgNum") -> bool:  # type: ignore[override]
        return c.u.degree() < 1

    def to_fraction(self, c: "AlgNum") -> Fraction:  # type: ignore[override]
        if c.u.degree() >= 1:
            raise DomainError(f"{self.format_element(c)} is not a constant")
        v = c.u.coeffs()[0] if c.u.degree() == 0 else 0
        if self.characteristic:
            return Fraction(self._symmetric(int(v)))
        v = flint.fmpq(v)
        return Fraction(int(v.p), int(v.q))

    def format_element(self, c: "AlgNum", short: bool | None = None) -> str:
        if short is None:
            short = all(len(n) == 1 for n in self.params)
        if c.u.degree() < 1:
            v = self.to_fraction(c)
            return str(v.numerator) if v.denominator == 1 else f"{v.numerator}/{v.denominator}"
        return "(" + _terms_str(c.u, self, short) + ")"

    def __repr__(self) -> str:
        base = "QQ" if self.characteristic == 0 else f"ZZ/{self.characteristic}"
        return f"{base}[{self.params[0]}]/({_terms_str(self.modulus, self, True)})"

    def __eq__(self, other: object) -> bool:
        return (isinstance(other, AlgebraicField) and other.characteristic == self.characteristic
                and other.params == self.params and other.modulus == self.modulus)

    def __hash__(self) -> int:
        return hash(("algext", self.characteristic, self.params, str(self.modulus)))


def _univ_coeffs(num: Any, den: Any, p: int) -> list:
    """The coefficients (lowest first) of the univariate flint polynomial ``num / den``."""
    d = num.to_dict() if hasattr(num, "to_dict") else {(0,): num}
    deg = max((e[0] for e in d), default=0)
    out: list = [0] * (deg + 1)
    for e, c in d.items():
        out[e[0]] = int(c)
    if den is None or den.is_one():
        return out
    dv = int(den.leading_coefficient())
    if p:
        inv = pow(dv, -1, p)
        return [c * inv % p for c in out]
    return [Fraction(c, dv) for c in out]


def _terms_str(u: Any, field: AlgebraicField, short: bool) -> str:
    """The polynomial ``u`` in the parameter, highest power first, as Singular writes it."""
    name = field.params[0]
    out = []
    coeffs = u.coeffs()
    for e in range(len(coeffs) - 1, -1, -1):
        c = coeffs[e]
        if field.characteristic:
            c = Fraction(field._symmetric(int(c)))
        else:
            c = flint.fmpq(c)
            c = Fraction(int(c.p), int(c.q))
        if c == 0:
            continue
        mono = "" if e == 0 else name if e == 1 else (f"{name}{e}" if short else f"{name}^{e}")
        cs = str(c.numerator) if c.denominator == 1 else f"{c.numerator}/{c.denominator}"
        if not mono:
            s = cs
        elif c == 1:
            s = mono
        elif c == -1:
            s = "-" + mono
        else:
            s = f"{cs}{mono}" if short else f"{cs}*{mono}"
        out.append(s if not out or s.startswith("-") else "+" + s)
    return "".join(out) or "0"


class AlgNum(RatFunc):
    """An element of an :class:`AlgebraicField` (immutable): ``u`` reduced modulo the minimal polynomial."""

    __slots__ = ("u", "_nd")

    def __init__(self, field: AlgebraicField, u: Any) -> None:  # no super().__init__: it would set num/den
        self.field, self.u = field, u
        self._nd: tuple | None = None
        self._hash = None

    def _num_den(self) -> tuple:
        if self._nd is None:
            f, u = self.field, self.u
            ctx = f.ctx
            if f.characteristic:
                num = ctx.from_dict({(e,): int(c) for e, c in enumerate(u.coeffs()) if int(c)}) \
                    if u.degree() >= 0 else ctx.constant(0)
                self._nd = (num, ctx.constant(1))
            else:
                d = int(u.denom()) if u.degree() >= 0 else 1
                num = ctx.from_dict({(e,): int(c) for e, c in enumerate(u.numer().coeffs()) if int(c)}) \
                    if u.degree() >= 0 else ctx.constant(0)
                self._nd = (num, ctx.constant(d))
        return self._nd

    @property  # type: ignore[override]
    def num(self) -> Any:
        return self._num_den()[0]

    @property  # type: ignore[override]
    def den(self) -> Any:
        return self._num_den()[1]

    def _other(self, other: Any) -> "AlgNum | None":  # type: ignore[override]
        if isinstance(other, AlgNum):
            if other.field is self.field or other.field == self.field:
                return other
            raise TypeError(f"elements of {self.field!r} and {other.field!r}")
        if isinstance(other, (int, Fraction, flint.fmpz, flint.fmpq, flint.nmod, RatFunc)):
            return self.field(other)
        return None

    def __add__(self, other: Any) -> "AlgNum":
        o = self._other(other)
        if o is None:
            return NotImplemented
        return AlgNum(self.field, self.u + o.u)

    __radd__ = __add__

    def __neg__(self) -> "AlgNum":
        return AlgNum(self.field, -self.u)

    def __sub__(self, other: Any) -> "AlgNum":
        o = self._other(other)
        if o is None:
            return NotImplemented
        return AlgNum(self.field, self.u - o.u)

    def __rsub__(self, other: Any) -> "AlgNum":
        o = self._other(other)
        if o is None:
            return NotImplemented
        return AlgNum(self.field, o.u - self.u)

    def __mul__(self, other: Any) -> "AlgNum":
        o = self._other(other)
        if o is None:
            return NotImplemented
        if self.u.degree() < 1 or o.u.degree() < 1:
            return AlgNum(self.field, self.u * o.u)
        return self.field.element(self.u * o.u)

    __rmul__ = __mul__

    def inverse(self) -> "AlgNum":
        if self.u.is_zero():
            raise ZeroDivisionError("division by zero")
        if self.u.degree() == 0:
            return AlgNum(self.field, self._inv_const())
        g, s, _ = self.u.xgcd(self.field.modulus)
        if g.degree() != 0:
            raise DomainError(f"{self.field.format_element(self)} is not invertible: the minimal polynomial "
                              "is reducible")
        return self.field.element(s / g.coeffs()[0] if self.field.characteristic == 0 else
                                  s * pow(int(g.coeffs()[0]), -1, self.field.characteristic))

    def _inv_const(self) -> Any:
        c = self.u.coeffs()[0]
        if self.field.characteristic:
            return self.field.poly_type([pow(int(c), -1, self.field.characteristic)])
        return flint.fmpq_poly([1 / flint.fmpq(c)])

    def __truediv__(self, other: Any) -> "AlgNum":
        o = self._other(other)
        if o is None:
            return NotImplemented
        return self * o.inverse()

    def __rtruediv__(self, other: Any) -> "AlgNum":
        o = self._other(other)
        if o is None:
            return NotImplemented
        return o * self.inverse()

    def __pow__(self, k: int) -> "AlgNum":
        if not isinstance(k, int):
            return NotImplemented
        if k < 0:
            return self.inverse() ** (-k)
        return power(self, k, self.field.one)

    def __eq__(self, other: object) -> bool:
        try:
            o = self._other(other)
        except (TypeError, ZeroDivisionError, DomainError):
            return False
        if o is None:
            return NotImplemented
        return self.u == o.u

    def __bool__(self) -> bool:
        return not self.u.is_zero()

    def __hash__(self) -> int:
        if self._hash is None:
            if self.u.degree() < 1:
                self._hash = hash(self.field.to_fraction(self))
            else:
                self._hash = hash(("alg", str(self.u)))
        return self._hash

    def __str__(self) -> str:
        return self.field.format_element(self)

    def __repr__(self) -> str:
        return f"AlgNum({self})"
