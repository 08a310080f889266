"""Singular's output of vectors and modules (see :mod:`mech.dsl.values_modules`).

A vector prints as its terms by decreasing module ordering, ``x2*gen(3)+y*gen(1)-gen(2)``, or, when
the ring's ordering starts with ``c``, as ``[f1,f2,...]`` (``print(v)`` always so); a module as its
generators ``m[i]=...``, and ``print(m)`` as the matrix of its generators' columns.
"""
from __future__ import annotations

from typing import Optional

from .printing import _matrix_rows, poly_str
from .values_modules import Module, Vector, module_columns, module_order, sorted_terms


def _term_str(v: Vector, e: tuple, c: object, comp: int) -> str:
    s = poly_str(v.ring.monomial(e, c))
    if not any(e) and s in ("1", "-1"):
        return s[:-1] + f"gen({comp + 1})"
    return s + f"*gen({comp + 1})"


def gen_str(v: Vector) -> str:
    """``x*gen(1)+y2*gen(3)``: the terms by decreasing module ordering."""
    if v.is_zero():
        return "0"
    out: list[str] = []
    for (e, i), c in sorted_terms(v):
        s = _term_str(v, e, c, i)
        if out and not s.startswith("-"):
            out.append("+")
        out.append(s)
    return "".join(out)


def bracket_str(v: Vector) -> str:
    """``[f1,f2,...]`` up to the last nonzero entry."""
    return "[" + ",".join(poly_str(p) for p in v.entries) + "]" if not v.is_zero() else "0"


def vector_str(v: Vector) -> str:
    """A vector as Singular prints it in its ring."""
    return bracket_str(v) if module_order(v.ring)[1] else gen_str(v)


def module_render(m: Module, name: Optional[str] = None) -> str:
    n = name or "_"
    return "\n".join(f"{n}[{i}]={vector_str(g)}" for i, g in enumerate(m.gens, 1))


def module_string(m: Module) -> str:
    return ",".join(vector_str(g) for g in m.gens)


def module_print(m: Module, name: str = "_") -> str:
    """``print(m)``: the matrix whose columns are the generators."""
    cols = module_columns(m)
    rows = [[poly_str(cols[j][i]) for j in range(len(cols))] for i in range(m.rank)]
    return _matrix_rows(rows, name)
