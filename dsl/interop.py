"""The hooks Python tools look for on the values of the language, in one place: ``_sympy_``
(``sympy.sympify(f)``, ``sympy.Symbol("x") + f``) on the kernel's polynomials, which know nothing
of sympy, and ``_repr_latex_`` (IPython and Jupyter show polynomials, numbers, ideals and
matrices with MathJax).  :mod:`mech` imports this module; the other
hooks (numbers as ``int``/``float``/``Fraction``, ideals compared as ideals) are methods in
:mod:`~mech.dsl.values`."""
from __future__ import annotations

from typing import Any

from ..kernel import Poly
from .convert import poly_to_sympy
from .latex import latex
from .values import Ideal, Matrix, Number


def _repr_latex_(value: Any) -> str:
    return f"${latex(value)}$"


for _cls in (Poly, Number, Ideal, Matrix):
    _cls._repr_latex_ = _repr_latex_    # type: ignore[attr-defined]
Poly._sympy_ = poly_to_sympy            # type: ignore[attr-defined]
