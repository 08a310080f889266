"""Rational function fields QQ(a,b,...) and Z/p(a,...): the coefficients of Singular rings
with parameters, ``ring r = (0,a,b),(x,y),dp;``.

An element is a normalized fraction ``num/den`` of flint polynomials in the parameters
(lexicographic, the first parameter largest): over QQ both have integer coefficients,
``gcd(num, den) = 1`` in Z[a,...] (integer content included) and ``den`` has a positive
leading coefficient; over Z/p ``den`` is monic.  This is Singular's normal form, so
:func:`format_coeff` prints elements as Singular does.
"""
from __future__ import annotations

from fractions import Fraction
from typing import Any, Sequence

import flint

from .coeffs import Field
from .errors import DomainError, NotSupported


class RationalFunctionField(Field):
    """``K(params)`` with ``K`` = QQ (``characteristic`` 0) or Z/p."""

    def __init__(self, characteristic: int, params: Sequence[str]) -> None:
        params = tuple(params)
        if not params:
            raise DomainError("a rational function field needs at least one parameter")
        if len(set(params)) != len(params):
            raise DomainError("parameter names must be distinct")
        p = characteristic
        if p == 0:
            self.ctx = flint.fmpz_mpoly_ctx.get(params, ordering="lex")
        else:
            if p < 2 or not flint.fmpz(p).is_prime():
                raise DomainError(f"characteristic {p} is not a prime")
            if p >= 2**63:
                raise NotSupported(f"characteristic {p} is too large (at most 2^63)")
            self.ctx = flint.nmod_mpoly_ctx.get(params, ordering="lex", modulus=p)
        self.characteristic = p
        self.params = params
        self.zero = RatFunc(self, self.ctx.constant(0), self.ctx.constant(1))
        self.one = RatFunc(self, self.ctx.constant(1), self.ctx.constant(1))

    # construction
    def gen(self, i: int) -> "RatFunc":
        return RatFunc(self, self.ctx.gen(i), self.ctx.constant(1))

    def gens(self) -> list["RatFunc"]:
        return [self.gen(i) for i in range(len(self.params))]

    def from_polys(self, num: Any, den: Any = None) -> "RatFunc":
        """``num/den`` from flint polynomials of :attr:`ctx` (or integers), normalized."""
        one = self.ctx.constant(1)
        num = self.ctx.constant(num) if isinstance(num, int) else num
        den = one if den is None else self.ctx.constant(den) if isinstance(den, int) else den
        return _normalize(self, num, den)

    def __call__(self, x: Any) -> "RatFunc":
        if isinstance(x, RatFunc):
            if x.field is self or x.field == self:
                return x
            raise TypeError(f"cannot convert an element of {x.field!r} to {self!r}")
        if isinstance(x, bool):
            x = int(x)
        if isinstance(x, (int, flint.fmpz)):
            return RatFunc(self, self.ctx.constant(self._int(int(x))), self.ctx.constant(1))
        if isinstance(x, flint.nmod):
            if self.characteristic == 0:
                raise TypeError(f"cannot convert {x!r} to an element of {self!r}")
            return self(int(x))
        if isinstance(x, (Fraction, flint.fmpq)) or (hasattr(x, "p") and hasattr(x, "q")):
            num, den = (x.numerator, x.denominator) if isinstance(x, Fraction) else (int(x.p), int(x.q))
            if self.characteristic and den % self.characteristic == 0:
                raise ZeroDivisionError("division by zero")
            return self.from_polys(self.ctx.constant(self._int(num)), self.ctx.constant(self._int(den)))
        if isinstance(x, str):
            if x in self.params:
                return self.gen(self.params.index(x))
            raise DomainError(f"{x!r} is not a parameter of {self!r}")
        if isinstance(x, (flint.fmpz_mpoly, flint.nmod_mpoly)) and x.context() is self.ctx:
            return RatFunc(self, x, self.ctx.constant(1))
        raise TypeError(f"cannot convert {x!r} to an element of {self!r}")

    def _int(self, n: int) -> int:
        return n % self.characteristic if self.characteristic else n

    # queries
    def is_constant(self, c: "RatFunc") -> bool:
        return c.num.is_constant() and c.den.is_constant()

    def to_fraction(self, c: "RatFunc") -> Fraction:
        """The element as a Fraction (symmetric representative over Z/p) when it is constant."""
        if not self.is_constant(c):
            raise DomainError(f"{format_coeff(c)} is not a constant")
        num, den = _const(c.num), _const(c.den)
        if self.characteristic:
            return Fraction(self._symmetric(num * pow(den, -1, self.characteristic)))
        return Fraction(num, den)

    def _symmetric(self, v: int) -> int:
        p = self.characteristic
        v %= p
        return v - p if v > p // 2 else v

    def __repr__(self) -> str:
        base = "QQ" if self.characteristic == 0 else f"GF({self.characteristic})"
        return f"{base}({','.join(self.params)})"

    def __eq__(self, other: object) -> bool:
        return (type(other) is type(self) and other.characteristic == self.characteristic
                and other.params == self.params)

    def __hash__(self) -> int:
        return hash(("ratfunc", self.characteristic, self.params))


def _const(p: Any) -> int:
    """The integer value of a constant flint polynomial."""
    return int(p.leading_coefficient()) if not p.is_zero() else 0


def _normalize(field: RationalFunctionField, num: Any, den: Any) -> "RatFunc":
    if den.is_zero():
        raise ZeroDivisionError("division by zero")
    if num.is_zero():
        return field.zero
    if not den.is_one():
        g = num.gcd(den)
        if not g.is_one():
            num, den = num // g, den // g
        lc = int(den.leading_coefficient())
        if field.characteristic:
            if lc != 1:
                inv = pow(lc, -1, field.characteristic)
                num, den = num * inv, den * inv
        elif lc < 0:
            num, den = -num, -den
    return RatFunc(field, num, den)


class RatFunc:
    """An element ``num/den`` of a :class:`RationalFunctionField` (immutable, normalized)."""

    __slots__ = ("field", "num", "den", "_hash")

    def __init__(self, field: RationalFunctionField, num: Any, den: Any) -> None:
        self.field, self.num, self.den = field, num, den
        self._hash: int | None = None

    def _other(self, other: Any) -> "RatFunc | None":
        if isinstance(other, RatFunc):
            if other.field is self.field or other.field == self.field:
                return other
            raise TypeError(f"elements of {self.field!r} and {other.field!r}")
        if isinstance(other, (int, Fraction, flint.fmpz, flint.fmpq, flint.nmod)):
            return self.field(other)
        return None

    def __add__(self, other: Any) -> "RatFunc":
        o = self._other(other)
        if o is None:
            return NotImplemented
        if self.den == o.den:
            num = self.num + o.num
            if self.den.is_one():
                return RatFunc(self.field, num, self.den) if not num.is_zero() else self.field.zero
            return _normalize(self.field, num, self.den)
        g = self.den.gcd(o.den)
        a, b = self.den // g, o.den // g
        return _normalize(self.field, self.num * b + o.num * a, self.den * b)

    __radd__ = __add__

    def __neg__(self) -> "RatFunc":
        return RatFunc(self.field, -self.num, self.den)

    def __sub__(self, other: Any) -> "RatFunc":
        o = self._other(other)
        if o is None:
            return NotImplemented
        return self + (-o)

    def __rsub__(self, other: Any) -> "RatFunc":
        o = self._other(other)
        if o is None:
            return NotImplemented
        return o + (-self)

    def __mul__(self, other: Any) -> "RatFunc":
        o = self._other(other)
        if o is None:
            return NotImplemented
        if self.num.is_zero() or o.num.is_zero():
            return self.field.zero
        if self.den.is_one() and o.den.is_one():
            return RatFunc(self.field, self.num * o.num, self.den)
        g1, g2 = self.num.gcd(o.den), o.num.gcd(self.den)
        num = (self.num // g1) * (o.num // g2)
        den = (self.den // g2) * (o.den // g1)
        return _normalize(self.field, num, den)

    __rmul__ = __mul__

    def inverse(self) -> "RatFunc":
        if self.num.is_zero():
            raise ZeroDivisionError("division by zero")
        return _normalize(self.field, self.den, self.num)

    def __truediv__(self, other: Any) -> "RatFunc":
        o = self._other(other)
        if o is None:
            return NotImplemented
        return self * o.inverse()

    def __rtruediv__(self, other: Any) -> "RatFunc":
        o = self._other(other)
        if o is None:
            return NotImplemented
        return o * self.inverse()

    def __pow__(self, k: int) -> "RatFunc":
        if not isinstance(k, int):
            return NotImplemented
        if k < 0:
            return self.inverse() ** (-k)
        return RatFunc(self.field, self.num ** k, self.den ** k)

    def __eq__(self, other: object) -> bool:
        try:
            o = self._other(other)
        except (TypeError, ZeroDivisionError):
            return False
        if o is None:
            return NotImplemented
        return self.num == o.num and self.den == o.den

    def __ne__(self, other: object) -> bool:
        eq = self.__eq__(other)
        return eq if eq is NotImplemented else not eq

    def __bool__(self) -> bool:
        return not self.num.is_zero()

    def __hash__(self) -> int:
        if self._hash is None:
            if self.num.is_constant() and self.den.is_constant():
                self._hash = hash(self.field.to_fraction(self))
            else:
                self._hash = hash((tuple(sorted(self.num.to_dict().items())),
                                   tuple(sorted(self.den.to_dict().items()))))
        return self._hash

    def is_constant(self) -> bool:
        return self.field.is_constant(self)

    def __str__(self) -> str:
        return format_coeff(self)

    def __repr__(self) -> str:
        return f"RatFunc({format_coeff(self)})"


# printing

def _poly_str(p: Any, field: RationalFunctionField, short: bool) -> str:
    """A parameter polynomial as Singular prints it (terms in lex order, largest first)."""
    out = []
    for exps, c in p.terms():
        c = int(c)
        if field.characteristic:
            c = field._symmetric(c)
        mono = [(n, e) for n, e in zip(field.params, exps) if e]
        if short:
            m = "".join(n if e == 1 else f"{n}{e}" for n, e in mono)
        else:
            m = "*".join(n if e == 1 else f"{n}^{e}" for n, e in mono)
        if not m:
            s = str(c)
        elif c == 1:
            s = m
        elif c == -1:
            s = "-" + m
        else:
            s = f"{c}{m}" if short else f"{c}*{m}"
        out.append(s if not out or s.startswith("-") else "+" + s)
    return "".join(out)


def format_coeff(c: RatFunc, short: bool | None = None) -> str:
    """``c`` as Singular prints a coefficient of a ring with parameters.

    A constant prints as a number (``3``, ``-1/3``; over Z/p its symmetric representative).
    Otherwise the numerator prints in parentheses unless it is a constant (``(2a+1)``, ``1``,
    ``-2``), followed, if the denominator is not 1, by ``/`` and the denominator, in
    parentheses unless it is a constant: ``(-a)/(b)``, ``(a)/2``, ``1/(2a)``, ``-1/(a+b)``,
    ``(3a+2b)/6``.  ``short`` (Singular's ``short=1``, default: when every parameter name is
    one letter) writes ``a2b`` and ``2a`` instead of ``a^2*b`` and ``2*a``.  In a polynomial
    Singular writes ``*`` between such a coefficient and the monomial (``(a)*y2``, ``-2*y``)
    and omits coefficients 1 and -1.
    """
    f = c.field
    if hasattr(f, "format_element"):  # an algebraic extension (kernel/algext.py)
        return f.format_element(c, short)
    if short is None:
        short = all(len(n) == 1 for n in f.params)
    if c.num.is_constant() and c.den.is_constant():
        v = f.to_fraction(c)
        return str(v.numerator) if v.denominator == 1 else f"{v.numerator}/{v.denominator}"
    if c.num.is_constant():
        num = str(f._symmetric(_const(c.num)) if f.characteristic else _const(c.num))
    else:
        num = "(" + _poly_str(c.num, f, short) + ")"
    if c.den.is_one():
        return num
    if c.den.is_constant():
        return f"{num}/{_const(c.den)}"
    return f"{num}/({_poly_str(c.den, f, short)})"
