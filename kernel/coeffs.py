"""Coefficient fields: the rationals QQ and the prime fields Z/p.

Elements are python-flint scalars (``fmpq`` for QQ, ``nmod`` for Z/p): they support
``+ - * /`` and ``==`` directly, so generic algebra code uses plain operators and
asks the field only to convert, test and describe.
"""
from __future__ import annotations

from fractions import Fraction
from typing import Any

import flint

from .errors import DomainError, NotSupported


class Field:
    """Common interface of coefficient fields."""

    characteristic: int = 0
    zero: Any
    one: Any

    def __call__(self, x: Any) -> Any:
        raise NotImplementedError

    def is_zero(self, c: Any) -> bool:
        return c == self.zero

    def to_fraction(self, c: Any) -> Fraction:
        """The coefficient as a Python Fraction (its symmetric representative in Z/p)."""
        raise NotImplementedError


class RationalField(Field):
    """The field QQ of rational numbers."""

    characteristic = 0

    def __getattr__(self, name: str) -> Any:
        """``zero`` and ``one``, made on first use (QQ exists before python-flint is imported)."""
        if name not in ("zero", "one"):
            raise AttributeError(name)
        self.zero, self.one = flint.fmpq(0), flint.fmpq(1)
        return getattr(self, name)

    def __call__(self, x: Any) -> flint.fmpq:
        if isinstance(x, flint.fmpq):
            return x
        if isinstance(x, Fraction):
            return flint.fmpq(x.numerator, x.denominator)
        if isinstance(x, (int, flint.fmpz)):
            return flint.fmpq(x)
        if hasattr(x, "p") and hasattr(x, "q"):  # sympy Rational
            return flint.fmpq(int(x.p), int(x.q))
        raise TypeError(f"cannot convert {x!r} to a rational number")

    def to_fraction(self, c: flint.fmpq) -> Fraction:
        return Fraction(int(c.p), int(c.q))

    def __repr__(self) -> str:
        return "QQ"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, RationalField)

    def __hash__(self) -> int:
        return hash("QQ")


class PrimeField(Field):
    """The prime field Z/p."""

    def __init__(self, p: int) -> None:
        if p < 2 or not flint.fmpz(p).is_prime():
            raise DomainError(f"characteristic {p} is not a prime")
        if p >= 2**63:
            raise NotSupported(f"characteristic {p} is too large (at most 2^63)")
        self.characteristic = p
        self.zero = flint.nmod(0, p)
        self.one = flint.nmod(1, p)

    def __call__(self, x: Any) -> flint.nmod:
        p = self.characteristic
        if isinstance(x, flint.nmod):
            return x
        if isinstance(x, (int, flint.fmpz)):
            return flint.nmod(int(x), p)
        if isinstance(x, (Fraction, flint.fmpq)) or (hasattr(x, "p") and hasattr(x, "q")):
            num, den = (x.numerator, x.denominator) if isinstance(x, Fraction) else (int(x.p), int(x.q))
            if den % p == 0:
                raise ZeroDivisionError("division by zero")
            return flint.nmod(num, p) / flint.nmod(den, p)
        raise TypeError(f"cannot convert {x!r} to an element of Z/{p}")

    def symmetric(self, c: flint.nmod) -> int:
        """The representative of ``c`` in (-p/2, p/2], as Singular prints it."""
        v = int(c)
        return v - self.characteristic if v > self.characteristic // 2 else v

    def to_fraction(self, c: flint.nmod) -> Fraction:
        return Fraction(self.symmetric(c))

    def __repr__(self) -> str:
        return f"GF({self.characteristic})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, PrimeField) and other.characteristic == self.characteristic

    def __hash__(self) -> int:
        return hash(("GF", self.characteristic))


QQ = RationalField()


def GF(p: int) -> PrimeField:
    """The prime field Z/p."""
    return PrimeField(p)
