"""Singular 4.3.1's output format for every value of the language.

:func:`render` is what an expression statement prints (``I;`` prints ``I[1]=...``, an unnamed
ideal ``_[1]=...``), :func:`print_form` what ``print(...)`` prints, :func:`poly_str` a polynomial
(short form ``3x2y+1/2y-7`` when every variable and parameter name is one letter, otherwise
``3*xa^2*yb-1/2``; Z/p coefficients as symmetric representatives).
"""
from __future__ import annotations

from typing import Any, Optional

from ..kernel import Poly, PolyRing
from .qrings import quotient_ideal
from .values import NONE, ExprList, Ideal, IntVec, List, Map, Matrix, NoneValue, Number, Proc, Ring
from .values_modules import Module, Vector, module_columns, module_order, sorted_terms

_short_cache: dict[int, tuple[PolyRing, bool]] = {}


def field_params(field: Any) -> tuple[str, ...]:
    """Names of the parameters of a coefficient field (empty for QQ and Z/p)."""
    return tuple(getattr(field, "params", ()))


def is_short(ring: PolyRing) -> bool:
    """Whether Singular prints this ring's polynomials in short form (all names one letter)."""
    hit = _short_cache.get(id(ring))
    if hit is not None and hit[0] is ring:
        return hit[1]
    short = all(len(n) == 1 for n in ring.names) and all(len(n) == 1 for n in field_params(ring.field))
    _short_cache[id(ring)] = (ring, short)
    return short


def set_short(ring: PolyRing, on: bool) -> None:
    """Singular's ``short = 0;`` / ``short = 1;``: print the ring's polynomials in long form
    (``3*x^2*y``) or, when every name is one letter, in short form (``3x2y``)."""
    _short_cache.pop(id(ring), None)
    _short_cache[id(ring)] = (ring, bool(on) and is_short(ring))


def coeff_str(field: Any, c: Any, short: bool = True) -> str:
    """A coefficient as Singular prints a number of this field (``short``: the ring's short form)."""
    if field_params(field):
        from ..kernel.ratfunc import format_coeff
        return format_coeff(c, short)
    if field.characteristic:
        return str(field.symmetric(c))
    return str(c)


def number_str(n: Number) -> str:
    return coeff_str(n.ring.field, n.c, is_short(n.ring))


def _monomial(names: tuple[str, ...], e: tuple[int, ...], short: bool) -> str:
    if short:
        return "".join(n if k == 1 else f"{n}{k}" for n, k in zip(names, e) if k)
    return "*".join(n if k == 1 else f"{n}^{k}" for n, k in zip(names, e) if k)


_texts: dict[int, tuple[Poly, bool, str]] = {}
"""The last polynomials printed (``id`` → the polynomial, short form, text): a script prints
the same value again and again (``f;``, ``s = string(f);``); polynomials never change."""
_monomials: dict[tuple[tuple[str, ...], bool], dict[tuple[int, ...], str]] = {}


def poly_str(p: Poly) -> str:
    """A polynomial in Singular's format, terms from the largest down."""
    if not p.terms:
        return "0"
    ring = p.ring
    short = is_short(ring)
    hit = _texts.get(id(p))
    if hit is not None and hit[0] is p and hit[1] is short:
        return hit[2]
    params = bool(field_params(ring.field))
    field, names = ring.field, ring.names
    plain = not params and not field.characteristic  # QQ: the coefficient's own str
    monos = _monomials.get((names, short))
    if monos is None or len(monos) > 4096:
        monos = _monomials[(names, short)] = {}
    out = []
    for e, c in p.sorted_terms():
        cs = str(c) if plain else coeff_str(field, c, short)
        if not any(e):
            s = cs
        else:
            mono = monos.get(e)
            if mono is None:
                mono = monos[e] = _monomial(names, e, short)
            if cs == "1":
                s = mono
            elif cs == "-1":
                s = "-" + mono
            elif short and not params:
                s = cs + mono
            else:
                s = f"{cs}*{mono}"
        if out and s[0] != "-":
            out.append("+")
        out.append(s)
    text = "".join(out)
    if len(_texts) > 64:
        _texts.clear()
    _texts[id(p)] = (p, short, text)
    return text


def int_str(v: int) -> str:
    """An integer in decimal, also beyond Python's 4300-digit limit of ``str`` (through flint,
    in quasi-linear time)."""
    if v.bit_length() < 14000:
        return str(v)
    import flint
    return str(flint.fmpz(v))


def value_str(v: Any) -> str:
    """A value on one line: Singular's ``string(v)``."""
    if isinstance(v, bool):
        return str(int(v))
    if isinstance(v, int):
        return int_str(v)
    if isinstance(v, str):
        return v
    if isinstance(v, Poly):
        return poly_str(v)
    if isinstance(v, Number):
        return number_str(v)
    if isinstance(v, Ideal):
        return ",".join(poly_str(g) for g in v.gens)
    if isinstance(v, Matrix):
        return ",".join(poly_str(g) for g in v.entries)
    if isinstance(v, Map):
        return ",".join(poly_str(g) for g in v.images)
    if isinstance(v, (Vector, Module)):
        return vector_str(v) if isinstance(v, Vector) else module_string(v)
    if isinstance(v, IntVec):
        return ",".join(str(x) for x in v.values)
    if isinstance(v, (List, ExprList)):
        return ",".join(value_str(x) for x in v.items if x is not NONE)
    if isinstance(v, Ring):
        return f"({charstr(v)}),({','.join(v.names)}),({ordstr(v)})"
    if isinstance(v, Proc):
        return v.name
    if isinstance(v, NoneValue):
        return ""
    if hasattr(v, "string_form"):  # intmat
        return v.string_form()
    return str(v)


def render(v: Any, name: Optional[str] = None) -> str:
    """What an expression statement prints for ``v`` (without the final newline); ``name`` is
    the variable's name when the expression was one (``I;`` prints ``I[1]=...``)."""
    if isinstance(v, Ideal):
        n = name or "_"
        return "\n".join(f"{n}[{i}]={poly_str(g)}" for i, g in enumerate(v.gens, 1))
    if isinstance(v, Map):
        n = name or "_"
        return "\n".join(f"{n}[{i}]={poly_str(g)}" for i, g in enumerate(v.images, 1))
    if isinstance(v, Matrix):
        n = name or "_"
        return "\n".join(f"{n}[{i},{j}]={poly_str(v.get(i, j))}"
                         for i in range(1, v.nrows + 1) for j in range(1, v.ncols + 1))
    if isinstance(v, List):
        return _render_list(v, "")
    if isinstance(v, Module):
        return module_render(v, name)
    if isinstance(v, Ring):
        return ring_str(v)
    if isinstance(v, Proc):
        return proc_str(v)
    if isinstance(v, ExprList):
        return join_outputs([(render(x), isinstance(x, List)) for x in v.items])
    if hasattr(v, "string_form"):  # intmat
        return str(v)
    return value_str(v)


def join_outputs(parts: list[tuple[str, bool]]) -> str:
    """Singular prints the values of ``a, b;`` side by side, separated by a blank, but a list
    ends its line; ``parts`` holds (text, is_list) pairs."""
    out = ""
    for i, (text, _) in enumerate(parts):
        if i:
            out += "\n" if parts[i - 1][1] else " "
        out += text
    return out


def _render_list(lst: List, indent: str) -> str:
    if not lst.items:
        return indent + "empty list"
    lines = []
    for i, x in enumerate(lst.items, 1):
        if x is NONE:
            continue
        lines.append(f"{indent}[{i}]:")
        sub = indent + "   "
        if isinstance(x, List):
            lines.append(_render_list(x, sub))
        elif isinstance(x, (str, Ring)):  # printed as one text: Singular indents only its first line
            lines.append(sub + render(x))
        elif getattr(x, "unindented", False):  # a coefficient ring (cring): Singular does not indent it
            lines.append(render(x))
        else:
            lines.extend(sub + line for line in render(x).split("\n"))
    return "\n".join(lines)


def print_form(v: Any, name: str = "_") -> str:
    """What ``print(v)`` prints: matrices as aligned rows (too long entries as ``name[i,j]``), ideals
    and intvecs as columns."""
    if isinstance(v, Matrix):
        return _matrix_rows([[poly_str(x) for x in row] for row in v.rows()], name)
    if isinstance(v, Ideal):
        return ",\n".join(poly_str(g) for g in v.gens)
    if isinstance(v, IntVec):
        return ",\n".join(str(x) for x in v.values) + " "
    if isinstance(v, (Vector, Module)):
        return bracket_str(v, "[0]") if isinstance(v, Vector) else module_print(v, name)
    if hasattr(v, "print_form"):  # intmat
        return v.print_form()
    if isinstance(v, Ring):
        order = v.poly.order
        kind = "global" if order.is_global else "local" if order.is_local else "mixed"
        return f"polynomial ring, over a field, {kind} ordering\n" + ring_str(v)
    return render(v)


PAGEWIDTH = 80


def _matrix_rows(cells: list[list[str]], name: str = "_") -> str:
    """Rows of ``print(M)``: every entry but the last followed by a comma, each column padded to
    its widest such cell.  As Singular: an entry wider than the page is shown as ``name[i,j]``, and
    when the rows do not fit on the page, so is every entry wider than the page over the columns
    (at least 8 and the width of ``name[nrows,ncols]``)."""
    if not cells or not cells[0]:
        return ""
    nrows, ncols = len(cells), len(cells[0])

    def comma(i: int, j: int) -> str:
        return "" if (i, j) == (nrows - 1, ncols - 1) else ","

    def named(i: int, j: int) -> str:
        return f"{name}[{i + 1},{j + 1}]" + comma(i, j)
    vl = max(PAGEWIDTH // ncols, 8, len(f"{name}[{ncols},{nrows}]"))
    texts = [[s + comma(i, j) for j, s in enumerate(row)] for i, row in enumerate(cells)]
    for i in range(nrows):
        for j in range(ncols):
            if len(texts[i][j]) > PAGEWIDTH:
                texts[i][j] = named(i, j)
                if comma(i, j):
                    vl = max(vl, len(texts[i][j]))
    widths = [max(len(row[j]) for row in texts) for j in range(ncols)]
    if sum(widths) > PAGEWIDTH:
        texts = [[named(i, j) if len(t) > vl else t for j, t in enumerate(row)] for i, row in enumerate(texts)]
        widths = [max(len(row[j]) for row in texts) for j in range(ncols)]
    return "\n".join("".join(t.ljust(w) for t, w in zip(row, widths)) for row in texts)


# ---------------------------------------------------------------- rings
def charstr(r: Ring) -> str:
    """Singular's ``charstr``: ``QQ``, ``ZZ/32003`` or ``0,a,b`` with parameters."""
    p = r.characteristic
    if r.params:
        return ",".join([str(p)] + list(r.params))
    return f"ZZ/{p}" if p else "QQ"


def ordstr(r: Ring) -> str:
    """Singular's ``ordstr``: ``dp(4),dp(2),C``."""
    parts = []
    for b in r.blocks:
        if b.kind in ("c", "C"):
            parts.append(b.kind)
        elif b.weights:
            parts.append(f"{b.kind}({','.join(str(w) for w in b.weights)})")
        else:
            parts.append(f"{b.kind}({b.size})")
    return ",".join(parts)


def ring_str(r: Ring) -> str:
    """What ``r;`` prints: coefficients, number of variables, the ordering blocks."""
    p = r.characteristic
    coeffs = f"ZZ/{p}" if p else "QQ"
    if hasattr(r.poly.field, "modulus"):  # an algebraic extension: QQ[a]/(a2+1), a^2+1 if not short
        coeffs = repr(r.poly.field)
        if not is_short(r.poly):
            from ..kernel.algext import _terms_str
            coeffs = coeffs.split("/(")[0] + f"/({_terms_str(r.poly.field.modulus, r.poly.field, False)})"
    elif r.params:
        coeffs += f"({', '.join(r.params)})"
    lines = [f"// coefficients: {coeffs}", f"// number of vars : {len(r.names)}"]
    start = 0
    for k, b in enumerate(r.blocks, 1):
        lines.append(f"//        block {k:3d} : ordering {b.kind}")
        if b.kind in ("c", "C"):
            continue
        size = b.size
        lines.append("//                  : names    " + " ".join(r.names[start:start + size]))
        width = len(r.names[start + size - 1])  # as Singular: weights right-aligned in the width of
        if b.kind == "M":                         # the block's last name
            for i in range(size):
                row = b.weights[i * size:(i + 1) * size]
                lines.append("//                  : weights " + "".join(f" {w:>{width}}" for w in row))
        elif b.weights:
            lines.append("//                  : weights " + "".join(f" {w:>{width}}" for w in b.weights))
        if b.kind != "a":
            start += size
    gens = quotient_ideal(r.poly)  # a qring: its ideal
    if gens is not None:
        lines += ["// quotient ring from ideal"] + [f"_[{i}]={poly_str(g)}" for i, g in enumerate(gens, 1)]
    return "\n".join(lines)


def proc_str(p: Proc) -> str:
    return f"// libname  : {p.lib}\n// procname : {p.name}\n// type     : singular"


# ---------------------------------------------------------------- vectors and modules
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


def bracket_str(v: Vector, zero: str = "0") -> str:
    """``[f1,f2,...]`` up to the last nonzero entry (``zero`` for the zero vector: ``print`` and
    ``show`` say ``[0]``)."""
    return "[" + ",".join(poly_str(p) for p in v.entries) + "]" if not v.is_zero() else zero


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
