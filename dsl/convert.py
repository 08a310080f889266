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


def to_sympy(v: Any) -> Any:
    """A value of the language as sympy objects: polynomials and numbers as expressions, ideals and
    lists as Python lists, matrices as ``sympy.Matrix``; ints and strings stay as they are."""
    import sympy

    from .values import ExprList, Ideal, IntVec, List, Matrix, Number
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
