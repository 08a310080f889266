"""Macaulay2 1.21's one-line output format (what its ``toString`` gives) for mech's values.

Polynomials list their terms from the largest down with ``*`` and ``^`` (``-(1/2)*x^2+3*y-1``;
``ZZ/p`` coefficients as representatives in ``-(p-1)/2 .. (p-1)/2``; in a tower ``QQ[t][x]`` the
coefficients are polynomials in ``t``: ``(t+1)*x^2-t``), ideals print as ``ideal(f,g)`` (one
generator that is a power of a variable or a nonnegative integer: ``ideal x``), matrices as
``matrix {{a, b}, {c, d}}``, lists as ``{a, b}``, sequences as ``(a,b)``, rings by name (or as
``QQ[x..z]`` when they have none).
"""
from __future__ import annotations

from fractions import Fraction
from typing import Any

from ..kernel import Poly
from .m2_local import LocalFraction
from .m2_modules import CyclicModule, FreeModule
from .m2_vectors import Vector
from .m2_submodules import BettiTally, ChainComplex, Module, betti_to_string
from .m2_subquotients import ModuleElement, Subquotient
from .m2_rings import TEXT, FractionField, tower_terms
from .m2_values import (Array, CoeffRing, CommandRef, Composed, Factored, IndexedTable, Iterator, M2Function, M2Set, Monoid,
                        MonomialIdeal, Opt, OptionTable, Partial, RingMap, Symbol, Tally,
                        VerticalList)
from .values import NONE, ExprList, Ideal, List, Matrix, Number, Ring

__all__ = ["Opt", "Symbol", "Factored", "to_string", "poly_str", "coeff_str"]


def coeff_str(field: Any, c: Any) -> str:
    if field.characteristic:
        return str(field.symmetric(c))
    return str(c)


def _monomial(names: tuple[str, ...], e: tuple[int, ...]) -> str:
    return "*".join(n if k == 1 else f"{n}^{k}" if k > 0 else f"{n}^({k})" for n, k in zip(names, e) if k)


def _terms(p: Poly, names: tuple[str, ...], coeffs: list[tuple[tuple[int, ...], str, bool]]) -> str:
    """``c1*m1+c2*m2...`` from (exponent, coefficient text, coefficient is a sum) triples."""
    out = []
    for e, s, compound in coeffs:
        neg = s.startswith("-") and not compound
        if neg:
            s = s[1:]
        mono = _monomial(names, e)
        if not mono:
            term = s
        elif s == "1":
            term = mono
        else:
            term = f"({s})*{mono}" if compound or "/" in s else f"{s}*{mono}"
        out.append(("-" if neg else ("+" if out else "")) + term)
    return "".join(out)


def poly_str(p: Poly) -> str:
    if not p.terms:
        return "0"
    split = tower_terms(p)
    if split is not None:  # a tower: coefficients are polynomials of the coefficient ring
        names = p.ring.names[:len(split[0][0])]
        return _terms(p, names, [(e, poly_str(c), len(c.terms) > 1) for e, c in split])
    return _terms(p, p.ring.names, [(e, coeff_str(p.ring.field, c), False) for e, c in p.sorted_terms()])


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
        word = "monomialIdeal" if isinstance(v, MonomialIdeal) else "ideal"
        if (v.is_std or word == "monomialIdeal") and not v.nonzero():
            return f"{word}()"
        gens = [poly_str(g) for g in v.gens]
        if len(gens) == 1 and _atomic(gens[0]):
            return f"{word} {gens[0]}"
        return f"{word}({','.join(gens)})"
    if isinstance(v, Matrix):
        rows = ", ".join("{" + ", ".join(poly_str(p) for p in row) + "}" for row in v.rows())
        return f"matrix {{{rows}}}"
    if isinstance(v, VerticalList):
        return "VerticalList{" + ", ".join(to_string(x) for x in v.items) + "}"
    if isinstance(v, OptionTable):
        return "new OptionTable from {" + ", ".join(f"{k} => {to_string(x)}" for k, x in v.entries) + "}"
    if isinstance(v, Array):
        return "[" + ", ".join(to_string(x) for x in v.items) + "]"
    if isinstance(v, List):
        return "{" + ", ".join(to_string(x) for x in v.items) + "}"
    if isinstance(v, ExprList):
        if len(v.items) == 1:
            return f"1 : ({to_string(v.items[0])})"
        return "(" + ",".join(to_string(x) for x in v.items) + ")"
    if isinstance(v, Opt):
        return f"{to_string(v.key)} => {to_string(v.value)}"
    if isinstance(v, (Symbol, IndexedTable, Iterator)):
        return v.name
    if isinstance(v, Monoid):
        return v.name or f"monoid[{', '.join(v.names)}]"
    if isinstance(v, M2Set):  # in the order Macaulay2 shows small sets: numbers by value, others by text
        texts = sorted(((0, x, "") if type(x) is int else (1, 0, to_string(x)) for x in v.items))
        return "set {" + ", ".join(str(n) if k == 0 else t for k, n, t in texts) + "}"
    if isinstance(v, Tally):
        return "new Tally from {" + ", ".join(f"{to_string(v.items[k])} => {n}" for k, n in v.counts.items()) + "}"
    if isinstance(v, Factored):
        parts = [f"({poly_str(f)})" + (f"^{k}" if k > 1 else "") for f, k in v.factors]
        if v.unit != 1 or not parts:
            parts.append(f"({to_string(v.unit)})")
        return "*".join(parts)
    if isinstance(v, (Ring, CoeffRing, FractionField)):
        return v.name or v.describe() if hasattr(v, "describe") else v.name
    if isinstance(v, LocalFraction):
        num, den = poly_str(v.num), poly_str(v.den)
        return (f"({num})" if len(v.num.terms) > 1 else num) + "/" + (f"({den})" if len(v.den.terms) > 1 else den)
    if isinstance(v, Vector):
        return "vector {" + ", ".join(poly_str(p) for p in v.entries) + "}"
    if isinstance(v, FreeModule):
        base = to_string(v.ring)
        return f"{base if base.isidentifier() else f'({base})'}^{v.rank}"
    if isinstance(v, Subquotient):
        return f"subquotient({to_string(v.generators)},{to_string(v.relations)})"
    if isinstance(v, ModuleElement):
        return "vector {" + ", ".join(poly_str(p) for p in v.entries) + "}"
    if isinstance(v, Module):
        return f"{v.kind} {to_string(v.matrix)}"
    if isinstance(v, BettiTally):
        return betti_to_string(v)
    if isinstance(v, ChainComplex):  # Macaulay2's net, on one line
        return "  <--  ".join(to_string(F) for F in v.modules)
    if isinstance(v, CyclicModule):
        gens = ", ".join(poly_str(g) for g in v.ideal.gens)
        return f"cokernel matrix {{{{{gens}}}}}"
    if isinstance(v, RingMap):
        return f"map({to_string(v.target)},{to_string(v.source)},{{{', '.join(poly_str(p) for p in v.images)}}})"
    if isinstance(v, (M2Function, CommandRef, Composed, Partial)):
        return v.name
    if v is NONE or v is None:
        return "null"
    name = getattr(v, "name", None)
    return name or type(v).__name__


TEXT["value"] = to_string
