"""Conversions between kernel polynomials and sympy expressions (sympy is imported lazily, in the functions)."""
from __future__ import annotations

import re
from fractions import Fraction
from typing import Any

from ..kernel import Poly, PolyRing
from .errors import MechTypeError


def _mpoly_to_sympy(m: Any, syms: list) -> Any:
    import sympy
    total = sympy.Integer(0)
    for e, c in m.to_dict().items():
        term = sympy.Integer(int(c))
        for s, k in zip(syms, e):
            term *= s ** k
        total += term
    return total


def _coeff_to_sympy(field: Any, c: Any) -> Any:
    """A coefficient as a sympy number, or over a parameter field (``ring r = (0,a),...``) a
    quotient of polynomials in symbols named like the parameters."""
    import sympy

    from ..kernel.ratfunc import RationalFunctionField
    if isinstance(field, RationalFunctionField):
        syms = [sympy.Symbol(n) for n in field.params]
        return _mpoly_to_sympy(c.num, syms) / _mpoly_to_sympy(c.den, syms)
    f = field.to_fraction(c)
    return sympy.Rational(f.numerator, f.denominator)


def poly_to_sympy(p: Poly) -> Any:
    """A kernel polynomial as a sympy expression in symbols named like the ring variables (and
    parameters)."""
    import sympy
    syms = [sympy.Symbol(n) for n in p.ring.names]
    total = sympy.Integer(0)
    for e, c in p.terms.items():
        term = _coeff_to_sympy(p.ring.field, c)
        for s, k in zip(syms, e):
            if k:
                term *= s ** k
        total += term
    return total


def sympy_to_poly(expr: Any, ring: PolyRing) -> Poly:
    """A sympy expression (polynomial in the ring's variable names with rational coefficients, or
    over a parameter field coefficients rational in the parameters) as a kernel polynomial of ``ring``."""
    import sympy

    from ..kernel.ratfunc import RationalFunctionField
    expr = sympy.sympify(expr)
    syms = [sympy.Symbol(n) for n in ring.names]
    field = ring.field
    params = [sympy.Symbol(n) for n in field.params] if isinstance(field, RationalFunctionField) else []
    extra = expr.free_symbols - set(syms) - set(params)
    if extra:
        names = ", ".join(sorted(str(s) for s in extra))
        raise MechTypeError(f"{names}: not a variable of the basering ({','.join(ring.names)})")
    try:
        sp = sympy.Poly(sympy.together(sympy.expand(expr)) if params else sympy.expand(expr), *syms)
    except sympy.PolynomialError as e:
        raise MechTypeError(f"not a polynomial: {expr}") from e
    terms = {}
    for monom, coeff in sp.terms():
        terms[tuple(int(k) for k in monom)] = _sympy_to_coeff(coeff, field, params)
    return ring.from_dict(terms)


def _sympy_to_coeff(coeff: Any, field: Any, params: list) -> Any:
    import sympy
    if coeff.is_Rational:
        return Fraction(int(coeff.p), int(coeff.q))
    if not params:
        raise MechTypeError(f"coefficient {coeff} is not a rational number")
    num, den = sympy.fraction(sympy.cancel(coeff))
    try:
        parts = [sympy.Poly(x, *params) for x in (num, den)]
    except sympy.PolynomialError as e:
        raise MechTypeError(f"coefficient {coeff} is not rational in the parameters") from e
    flint_polys = []
    for part in parts:
        d = {}
        for monom, c in part.terms():
            if not c.is_Rational:
                raise MechTypeError(f"coefficient {coeff} is not rational in the parameters")
            d[tuple(int(k) for k in monom)] = Fraction(int(c.p), int(c.q))
        flint_polys.append(d)
    return _ratfunc(field, *flint_polys)


def _ratfunc(field: Any, num: dict, den: dict) -> Any:
    """``num/den`` (dicts exponent -> Fraction) as an element of the parameter field."""
    from math import lcm
    scale = lcm(*(f.denominator for f in list(num.values()) + list(den.values())))
    if field.characteristic and scale % field.characteristic == 0:
        raise MechTypeError(f"a coefficient has a denominator divisible by {field.characteristic}")
    def mpoly(d: dict) -> Any:
        return field.ctx.from_dict({e: int(c * scale) for e, c in d.items()})
    return field.from_polys(mpoly(num), mpoly(den))


def is_sympy(x: Any) -> bool:
    mod = type(x).__module__ or ""
    return mod.startswith("sympy")


def number_fraction(n: Any) -> Fraction:
    """A :class:`~mech.dsl.values.Number` as a Fraction: over QQ its value, in Z/p its symmetric
    representative; over a parameter field only a constant."""
    field = n.ring.field
    if getattr(field, "params", ()):
        v = _coeff_to_sympy(field, n.c)
        if not v.is_Rational:
            raise MechTypeError(f"the number {v} depends on the parameters: it is not a rational number")
        return Fraction(int(v.p), int(v.q))
    return field.to_fraction(n.c)


def python_number(value: Any) -> Fraction:
    """A Python or sympy number as an exact Fraction: ints, Fractions, floats (their exact binary
    value: 0.1 is 3602879701896397/36028797018963968), sympy Integers, Rationals and Floats.
    Raises :class:`MechTypeError` for anything else (nan, infinities, complex numbers...)."""
    if isinstance(value, bool):
        return Fraction(int(value))
    if isinstance(value, (int, Fraction)):
        return Fraction(value)
    if isinstance(value, float):
        if value != value or value in (float("inf"), float("-inf")):
            raise MechTypeError(f"cannot convert the float {value} to a number (it is not finite)")
        return Fraction(value)
    if is_sympy(value) and getattr(value, "is_Number", False):
        if value.is_Rational:
            return Fraction(int(value.p), int(value.q))
        if value.is_Float and value.is_finite:
            import sympy
            r = sympy.Rational(value)   # the exact binary value of the float
            return Fraction(int(r.p), int(r.q))
    raise MechTypeError(f"cannot convert {value!r} to a rational number")


DECIMAL_EXPONENT = 10_000  # largest |exponent| of a decimal string such as "1e400"


def parse_decimal(text: str) -> Fraction:
    """An exact rational from a string ``"3"``, ``"-1/2"``, ``"0.25"`` or ``"1.5e3"``; exponents
    beyond ``DECIMAL_EXPONENT`` are refused (``Fraction("1e999999999")`` would compute a billion
    digits).  Raises ValueError for anything else."""
    m = _DECIMAL.fullmatch(text.strip())
    if m is None:
        raise ValueError(f"not a number: '{text}'")
    if m.group("exp") and abs(int(m.group("exp"))) > DECIMAL_EXPONENT:
        raise ValueError(f"'{text}': exponent too large (at most {DECIMAL_EXPONENT})")
    return Fraction(text.strip())


_DECIMAL = re.compile(r"[+-]?(?:\d+/\d+|(?:\d+\.?\d*|\.\d+)(?:[eE](?P<exp>[+-]?\d{1,12}))?)")
