"""LaTeX for the values of the language (notebooks show ideals, matrices and polynomials with
MathJax): ``x^{2} y - \\frac{1}{2} z``, ideals as ``\\langle f, g \\rangle``, matrices as
``pmatrix``, lists as stacked rows.  Variables written ``x(3)`` or ``c12`` get subscripts."""
from __future__ import annotations

import re
from typing import Any

from ..kernel import Poly
from .values import Ideal, IntVec, List, Matrix, Number

MAX_TERMS = 2000   # a longer polynomial is shown as text, not typeset


def _name(n: str) -> str:
    m = re.fullmatch(r"([A-Za-z]+)\(?(\d+)\)?", n)
    if m:
        base = m.group(1) if len(m.group(1)) == 1 else rf"\mathit{{{m.group(1)}}}"
        return f"{base}_{{{m.group(2)}}}"
    return n if len(n) == 1 else rf"\mathit{{{n}}}"


def _coeff(field: Any, c: Any) -> tuple[bool, str]:
    """``(negative, body)`` of a coefficient; over a parameter field the body is parenthesized
    when it has several terms."""
    from .convert import _coeff_to_sympy
    if getattr(field, "params", ()):
        import sympy
        expr = _coeff_to_sympy(field, c)
        text = sympy.latex(expr, symbol_names={sympy.Symbol(p): _name(p) for p in field.params})
        neg = text.startswith("-") and not expr.is_Add
        text = text[1:] if neg else text
        return neg, (f"\\left({text}\\right)" if expr.is_Add else text)
    f = field.to_fraction(c)
    neg, f = f < 0, abs(f)
    return neg, (str(f.numerator) if f.denominator == 1 else rf"\frac{{{f.numerator}}}{{{f.denominator}}}")


def poly_latex(p: Poly) -> str:
    """A polynomial, terms from the largest down."""
    if not p.terms:
        return "0"
    if len(p.terms) > MAX_TERMS:
        from .printing import poly_str
        return rf"\text{{{poly_str(p)[:200]}}}\dots"
    names = [_name(n) for n in p.ring.names]
    out = []
    for e, c in p.sorted_terms():
        neg, body = _coeff(p.ring.field, c)
        mono = " ".join(n if k == 1 else f"{n}^{{{k}}}" for n, k in zip(names, e) if k)
        if mono and body == "1":
            body = ""
        term = f"{body} {mono}".strip() if mono else body
        out.append(("- " if neg else "+ " if out else "") + term)
    return " ".join(out)


def latex(v: Any) -> str:
    """LaTeX (without ``$``) of a value; plain text of values without a mathematical form."""
    if isinstance(v, Poly):
        return poly_latex(v)
    if isinstance(v, Number):
        return poly_latex(v.to_poly())
    if isinstance(v, Ideal):
        return r"\left\langle " + ",\\; ".join(poly_latex(g) for g in v.gens) + r" \right\rangle"
    if isinstance(v, Matrix):
        rows = [" & ".join(poly_latex(g) for g in row) for row in v.rows()]
        return r"\begin{pmatrix} " + r" \\ ".join(rows) + r" \end{pmatrix}"
    if isinstance(v, IntVec):
        return r"\left(" + ", ".join(map(str, v.values)) + r"\right)"
    if isinstance(v, List):
        items = [latex(x) for x in v.items]
        return r"\begin{array}{l} " + r" \\ ".join(f"[{k}]\\colon\\; {x}" for k, x in enumerate(items, 1)) \
            + r" \end{array}" if items else r"\left[\,\right]"
    if isinstance(v, bool) or isinstance(v, int):
        return str(int(v))
    return r"\text{" + str(v).replace("\\", r"\backslash ").replace("{", r"\{").replace("}", r"\}") + "}"


def has_latex(v: Any) -> bool:
    """Whether a value is shown with LaTeX in notebooks: ring elements, ideals, matrices, and
    lists of them (with integers beside them)."""
    if isinstance(v, (Poly, Number, Ideal, Matrix)):
        return True
    if not isinstance(v, List):
        return False
    plain = [x for x in v.items if isinstance(x, (int, IntVec))]
    return len(plain) < len(v.items) and all(has_latex(x) for x in v.items if not isinstance(x, (int, IntVec)))


def bundle(values: list[Any], text: str) -> dict[str, str]:
    """The MIME bundle of an expression statement's values (``text``: what it prints): LaTeX when
    every value has a mathematical form."""
    out = {"text/plain": text}
    if values and all(has_latex(v) for v in values):
        out["text/latex"] = "$" + r",\quad ".join(latex(v) for v in values) + "$"
    return out
