"""Macaulay2 1.21's one-line output format (what its ``toString`` gives) for mech's values.

Polynomials list their terms from the largest down with ``*`` and ``^`` (``-(1/2)*x^2+3*y-1``;
``ZZ/p`` coefficients as representatives in ``-(p-1)/2 .. (p-1)/2``), ideals print as
``ideal(f,g)`` (one generator that is a power of a variable or a nonnegative integer: ``ideal x``),
matrices as ``matrix {{a, b}, {c, d}}``, lists as ``{a, b}``, sequences as ``(a,b)``.
"""
from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from ..kernel import Poly
from .values import NONE, ExprList, Ideal, List, Matrix, Number, Ring


@dataclass(frozen=True)
class Opt:
    """An option ``key => value``."""
    key: Any
    value: Any


@dataclass(frozen=True)
class Symbol:
    """A Macaulay2 symbol without a value of mech's (``Lex``, ``GRevLex``, ``Eliminate``...)."""
    name: str


@dataclass(frozen=True)
class Factored:
    """The result of ``factor``: a unit and (factor, exponent) pairs, printed as a product."""
    unit: Any
    factors: tuple[tuple[Poly, int], ...]


def coeff_str(field: Any, c: Any) -> str:
    if field.characteristic:
        return str(field.symmetric(c))
    return str(c)


def _monomial(names: tuple[str, ...], e: tuple[int, ...]) -> str:
    return "*".join(n if k == 1 else f"{n}^{k}" for n, k in zip(names, e) if k)


def poly_str(p: Poly) -> str:
    if not p.terms:
        return "0"
    ring = p.ring
    out = []
    for e, c in p.sorted_terms():
        s = coeff_str(ring.field, c)
        neg = s.startswith("-")
        if neg:
            s = s[1:]
        mono = _monomial(ring.names, e)
        if not mono:
            term = s
        elif s == "1":
            term = mono
        else:
            term = f"({s})*{mono}" if "/" in s else f"{s}*{mono}"
        out.append(("-" if neg else ("+" if out else "")) + term)
    return "".join(out)


def _atomic(s: str) -> bool:
    """Whether ``ideal s`` needs no parentheses (a power of a variable or a nonnegative integer)."""
    return all(ch.isalnum() or ch in "_^" for ch in s)


def to_string(v: Any) -> str:
    """``toString v`` in Macaulay2."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, str, Fraction)):
        return str(v)
    if isinstance(v, Poly):
        return poly_str(v)
    if isinstance(v, Number):
        return coeff_str(v.ring.field, v.c)
    if isinstance(v, Ideal):
        if v.is_std and not v.nonzero():
            return "ideal()"
        gens = [poly_str(g) for g in v.gens]
        if len(gens) == 1 and _atomic(gens[0]):
            return f"ideal {gens[0]}"
        return f"ideal({','.join(gens)})"
    if isinstance(v, Matrix):
        rows = ", ".join("{" + ", ".join(poly_str(p) for p in row) + "}" for row in v.rows())
        return f"matrix {{{rows}}}"
    if isinstance(v, List):
        return "{" + ", ".join(to_string(x) for x in v.items) + "}"
    if isinstance(v, ExprList):
        return "(" + ",".join(to_string(x) for x in v.items) + ")"
    if isinstance(v, Opt):
        return f"{to_string(v.key)} => {to_string(v.value)}"
    if isinstance(v, Symbol):
        return v.name
    if isinstance(v, Factored):
        parts = [f"({poly_str(f)})" + (f"^{k}" if k > 1 else "") for f, k in v.factors]
        if v.unit != 1 or not parts:
            parts.append(f"({to_string(v.unit)})")
        return "*".join(parts)
    if isinstance(v, Ring):
        return v.name or ring_str(v)
    if v is NONE:
        return ""
    name = getattr(v, "name", None)
    return name or type(v).__name__


def ring_str(r: Ring) -> str:
    char = r.characteristic
    base = "QQ" if char == 0 else f"ZZ/{char}"
    return f"{base}[{', '.join(r.names)}]"
