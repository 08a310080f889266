"""Conversions between mech values and sympy expressions (sympy is imported only here, lazily)."""
from __future__ import annotations

from fractions import Fraction
from typing import Any

from ..kernel import Poly, PolyRing
from .errors import MechTypeError


def poly_to_sympy(p: Poly) -> Any:
    """A kernel polynomial as a sympy expression in symbols named like the ring variables."""
    import sympy
    syms = [sympy.Symbol(n) for n in p.ring.names]
    total = sympy.Integer(0)
    for e, c in p.terms.items():
        f = p.ring.field.to_fraction(c)
        term = sympy.Rational(f.numerator, f.denominator)
        for s, k in zip(syms, e):
            if k:
                term *= s ** k
        total += term
    return total


def sympy_to_poly(expr: Any, ring: PolyRing) -> Poly:
    """A sympy expression (polynomial in the ring's variable names, rational coefficients) as a
    kernel polynomial of ``ring``."""
    import sympy
    expr = sympy.sympify(expr)
    syms = [sympy.Symbol(n) for n in ring.names]
    extra = expr.free_symbols - set(syms)
    if extra:
        names = ", ".join(sorted(str(s) for s in extra))
        raise MechTypeError(f"{names}: not a variable of the basering ({','.join(ring.names)})")
    try:
        sp = sympy.Poly(sympy.expand(expr), *syms) if syms else None
    except sympy.PolynomialError as e:
        raise MechTypeError(f"not a polynomial: {expr}") from e
    terms = {}
    for monom, coeff in sp.terms():
        if not coeff.is_Rational:
            raise MechTypeError(f"coefficient {coeff} is not a rational number")
        terms[tuple(int(k) for k in monom)] = Fraction(int(coeff.p), int(coeff.q))
    return ring.from_dict(terms)


def is_sympy(x: Any) -> bool:
    mod = type(x).__module__ or ""
    return mod.startswith("sympy")
