"""Commands of Singular's inout.lib: strings laid out for reading (``pmat``, ``lprint``, ``split``,
``tab``), reading Macaulay's format (``rMacaulay``), ``pause``, a polynomial shown in some of its
variables (``showrecursive``) and ``allprint``."""
from __future__ import annotations

import sys
from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.printing import poly_str
from ..dsl.registry import command
from ..dsl.values import Ideal, Matrix, NONE, to_matrix
from ..dsl.values_modules import Module
from ..kernel import Poly

LIB = "inout.lib"
#: Singular's default ``pagewidth``.
PAGEWIDTH = 80


@command("tab", lib=LIB)
def tab(n: int) -> str:
    """tab(n): a string of n spaces.

    Example:
      LIB "inout.lib";
      "[" + tab(3) + "]";
      → [   ]
    """
    return " " * max(n, 0)


def _cut(s: str, n: int) -> str:
    """``s`` in n places: padded with spaces, or its first n-2 characters and ``..``."""
    return s[:n - 2] + ".." if len(s) > n else s


@command("pmat", lib=LIB)
def pmat(M: Matrix | Module, n: int | None = None) -> str:
    """pmat(M[, n]): the matrix M (a module: its matrix) as a string in columns; with n > 1 each entry
    shown in at most n places (a cut entry ends in ``..``).

    Example:
      LIB "inout.lib";
      ring r = 0,(x,y),dp;
      matrix M[2][2] = x2+y,1,x,y3;
      pmat(M);
      → x2+y, 1,
      → x,    y3
      pmat(M, 2);
      → .., 1,
      → x,  y3
    """
    if isinstance(M, Module):
        M = to_matrix(M, M.ring)
    cells = [[poly_str(p) for p in row] for row in M.rows()]
    last_r, last_c = M.nrows - 1, M.ncols - 1
    if n is None:
        widths = [max(len(cells[r][c]) + 1 for r in range(M.nrows)) for c in range(M.ncols)]
        sep = "\n" if sum(widths) >= PAGEWIDTH else " "
        lines = []
        for r, row in enumerate(cells):
            parts = [(s + ",").ljust(w) for s, w in zip(row, widths)]
            if r == last_r:
                lines.append(sep.join(parts[:-1] + [row[-1]]))
            else:
                lines.append(sep.join(parts) + sep)
        return "\n".join(lines)
    if n <= 1:
        raise MechRuntimeError("pmat(M, n) needs n > 1")
    lines = []
    for r, row in enumerate(cells):
        parts = []
        for c, s in enumerate(row):
            if r == last_r and c == last_c:
                parts.append(_cut(s, n))
            elif len(s) > n:
                parts.append(_cut(s, n) + ", ")
            else:
                parts.append((s + ",").ljust(n + 1) + " ")
        lines.append("".join(parts))
    return "\n".join(lines)


def _lines_of(p: Poly, n: int) -> list[str]:
    """The polynomial broken into lines of at most n characters between its terms (each further line
    starts with its sign), as inout.lib's lprint; the first line indented two places."""
    text = poly_str(p)
    if 2 + len(text) <= n:
        return ["  " + text]
    terms = [p.ring.monomial(e, c) for e, c in p.sorted_terms()]
    out, head, first = [], terms[0], True
    for t in terms[1:]:
        if (2 if first else 0) + len(poly_str(head + t)) > n:
            out.append(_lead_line(poly_str(head), first))
            first, head = False, t
        else:
            head = head + t
    out.append(_lead_line(poly_str(head), first))
    return out


def _lead_line(s: str, first: bool) -> str:
    if first:
        return "  " + s
    return s if s.startswith("-") else "+" + s


@command("lprint", lib=LIB)
def lprint(x: Poly | Ideal | Matrix | Module, n: int = PAGEWIDTH) -> str:
    """lprint(f[, n]): the polynomial, ideal, module (its matrix) or matrix f as a string of lines of at most n - 3
    characters broken between terms, the entries column by column, separated by commas, the columns
    by a blank line (in the format matrix input reads).

    Example:
      LIB "inout.lib";
      ring r = 0,(x,y),dp;
      lprint((x+y)^5, 20);
      →   x5+5x4y+10x3y2
      → +10x2y3+5xy4+y5
    """
    if isinstance(x, Poly):
        x = Matrix(x.ring, 1, 1, [x])
    elif isinstance(x, Ideal):
        x = Matrix(x.ring, 1, len(x.gens), x.gens)
    elif isinstance(x, Module):
        x = to_matrix(x, x.ring)
    width = n - 3
    blocks = []
    for c in range(1, x.ncols + 1):
        entries = ["\n".join(_lines_of(x.get(r, c), width)) for r in range(1, x.nrows + 1)]
        blocks.append(",\n".join(entries))
    return ",\n\n".join(blocks)


@command("split", lib=LIB)
def split(s: str, n: int = PAGEWIDTH) -> str:
    """split(s[, n]): the string s with each line longer than n - 2 characters broken into pieces of
    n - 2 characters, each piece but the last of a line followed by a backslash.

    Example:
      LIB "inout.lib";
      split("abcdefgh", 5);
      → abc\\
      → def\\
      → gh
    """
    if n < 3:
        raise MechRuntimeError("split(s, n) needs n > 2")
    out = []
    for line in (s[:-1] if s.endswith("\n") else s).split("\n"):
        rest = line + "\n"
        while len(rest) >= n:
            out.append(rest[:n - 2])
            rest = rest[n - 2:]
        out.append(rest[:-1])
    return "\\\n".join(out)


def _macaulay_line(line: str) -> str:
    """One line of Macaulay's matrix or ideal format with the first blank of each run of blanks
    made a comma (the entries of a row)."""
    out, prev_blank = [], False
    for ch in line:
        out.append("," if ch == " " and not prev_blank else ch)
        prev_blank = ch == " "
    return "".join(out)


@command("rMacaulay", lib=LIB)
def r_macaulay(s: str, skip: int = 0) -> str:
    """rMacaulay(s[, n]): the polynomials, ideal or matrix written in Macaulay's format in the string s
    (after its first n lines), in Singular's input format: ``x[0]3`` becomes ``x(0)^3``, products get
    ``*``, entries of a row and rows are separated by commas.

    Example:
      LIB "inout.lib";
      rMacaulay("x[0]2-3x[0]x[1]");
      → x(0)^2-3*x(0)*x(1)
    """
    lines = s.split("\n")[skip:]
    text = "\n".join(lines).strip(" \n")
    rows = [ln.strip(" ").rstrip(" \\\n") for ln in text.split("\n") if ln.strip(" \n")]
    out = ",\n".join(_macaulay_line(r) for r in rows)
    res: list[str] = []
    for ch in out:  # a product before a variable with index: 3x[0]x[1] -> 3*x(0)*x(1)
        if ch == "[":
            if len(res) >= 2 and res[-2] not in "+-,\n":
                res.insert(len(res) - 1, "*")
            ch = "("
        res.append(ch)
    text, res = "".join(res), []
    for i, ch in enumerate(text):  # an exponent after the index: x[0]3 -> x(0)^3
        res.append(")" if ch == "]" else ch)
        if ch == "]" and (text[i + 1] if i + 1 < len(text) else ",") not in "+-,*":
            res.append("^")
    return "".join(res)


@command("pause", lib=LIB)
def pause(ctx, prompt: str = "pause>") -> object:
    """pause([prompt]): show the prompt and wait for a line of input (in a script without input it
    goes on at once).

    Example:
      LIB "inout.lib";
      int k = 1;
      k;
      → 1
    """
    ctx.write(prompt)
    sys.stdin.readline()
    return NONE


@command("showrecursive", lib=LIB)
def showrecursive(ctx, f: Poly, p: Poly, order: str = "dp") -> object:
    """showrecursive(f, p[, ord]): show f as a polynomial in the variables of the monomial p with
    coefficients in the other variables (made parameters; the ordering ord, default dp).

    Example:
      LIB "inout.lib";
      ring r = 0,(a,x,y),dp;
      showrecursive(ax2+x2y+y, x);
      → // poly, 2 monomial(s)
      → (a+y)*x2+(y)
    """
    from ..dsl.rings import make_ring, parse_ordering
    ring = f.ring
    if len(p.terms) != 1:
        raise MechRuntimeError("showrecursive(f, p): p must be a product of variables")
    (mono,) = p.terms
    keep = [i for i in range(ring.nvars) if mono[i]]
    made = [i for i in range(ring.nvars) if not mono[i]]
    base = ctx.basering()
    names = [ring.names[i] for i in keep]
    new = make_ring(base.characteristic, base.params + tuple(ring.names[i] for i in made), names,
                    parse_ordering(order, len(names))).poly
    field, k = new.field, len(base.params)
    terms: dict = {}
    for e, c in f.terms.items():
        coeff = field(c) if not k else c
        for j, i in enumerate(made):
            coeff = coeff * field.gen(k + j) ** e[i]
        key = tuple(e[i] for i in keep)
        terms[key] = terms[key] + coeff if key in terms else coeff
    g = Poly(new, {e: c for e, c in terms.items() if c != 0})
    ctx.write(f"// poly, {len(g.terms)} monomial(s)\n{poly_str(g)}\n")
    return NONE


@command("allprint", lib=LIB)
def allprint(ctx, *xs: object) -> object:
    """allprint(a, b, ...): print each argument, when a variable named ALLprint is defined (and wait
    for input after them when it is > 0).

    Example:
      LIB "inout.lib";
      int ALLprint = 0;
      allprint("M =", 3);
      → M =
      → 3
    """
    from .language import print_
    var = ctx.lookup("ALLprint")
    if var is None:
        return NONE
    for x in xs:
        print_(ctx, x)
    if isinstance(var.value, int) and var.value > 0:
        pause(ctx)
    return NONE


def _show_lines(ctx, x: Any) -> list[str]:
    """inout.lib's show: a comment line with the type and size, then the value."""
    from ..dsl.intmat import IntMat
    from ..dsl.minpoly import get_minpoly
    from ..dsl.printing import charstr, number_str, ordstr, print_form, value_str
    from ..dsl.qrings import quotient_ideal
    from ..dsl.values import IntVec, List, Map, Number, Ring
    from .listvar import _line, _ring_vars, describe
    if isinstance(x, bool) or isinstance(x, int):
        return ["// int, size 1", str(x)]
    if isinstance(x, str):
        return [f"// string, size {len(x)}", x]
    if isinstance(x, IntVec):
        return [f"// intvec, size {len(x.values)}", value_str(x)]
    if isinstance(x, IntMat):
        return [f"// intmat, {x.nrows} rows, {x.ncols} columns", print_form(x)]
    if isinstance(x, Number):
        return ["// number", number_str(x)]
    if isinstance(x, Poly):
        return [f"// poly, {len(x.terms)} monomial(s)", poly_str(x)]
    if isinstance(x, Ideal):
        return [f"// ideal, {len(x.gens)} generator(s)", print_form(x)]
    if isinstance(x, Matrix):
        return [f"// matrix, {x.nrows}x{x.ncols}", print_form(x)]
    from ..dsl.values_modules import Module, Vector
    from ..dsl.printing import bracket_str
    if isinstance(x, Vector):
        return ["// vector", bracket_str(x, "[0]")]
    if isinstance(x, Module):
        return [f"// module, {len(x.gens)} generator(s)"] + [bracket_str(g, "[0]") for g in x.gens]
    if isinstance(x, Map):  # as Singular: the images under the name @map
        return ["// i-th variable of preimage ring is mapped to @map[i]", f"// @map map  from {x.source.name}"] + [
            f"@map[{i}]={poly_str(p)}" for i, p in enumerate(x.images, 1)]
    if isinstance(x, List):
        out = [f"// list, {len(x.items)} element(s):"]
        for i, item in enumerate(x.items, 1):
            head, *rest = _show_lines(ctx, item)
            out += [f"[{i}]:", "   " + head] + rest
        return out
    if isinstance(x, Ring):
        char = charstr(x)
        minpoly = get_minpoly(x)
        out = [f"// ring: ({char}),({','.join(x.names)}),({ordstr(x)});",
               f"// minpoly = {number_str(minpoly) if not minpoly.c == 0 else 0}"]
        q = quotient_ideal(x.poly)
        if q:
            out += ["// quotient ring from ideal:"] + [f"_[{i}]={poly_str(g)}" for i, g in enumerate(q, 1)]
        out.append("// objects belonging to this ring:")
        found = [var for f in sorted(ctx.frames, key=lambda f: -f.level)
                 for var in reversed(list(_ring_vars(ctx, f, x).values()))]
        kinds = (Poly, Ideal, Map, Matrix, Number)  # inout.lib lists these types first, in this order

        def rank(var: Any) -> int:
            return next((k for k, t in enumerate(kinds) if isinstance(var.value, t)), len(kinds))
        for var in sorted(found, key=rank):
            out.append(_line(var.name, var.level, describe(var.value, ctx.ring), False).rstrip("\n"))
        return out
    raise MechRuntimeError(f"show: the type {type(x).__name__} is not supported")


@command("show", lib=LIB)
def show(ctx, x: Any, *rest: Any) -> None:
    """show(x): x with a comment line before it saying its type and size (a ring: its coefficients,
    variables, ordering, minimal polynomial, quotient ideal and the objects belonging to it).

    Example:
      LIB "inout.lib";
      ring r = 0,(x,y),ds;
      show(r);
      → // ring: (QQ),(x,y),(ds(2),C);
      → // minpoly = 0
      → // objects belonging to this ring:
      show(ideal(x2, y));
      → // ideal, 2 generator(s)
      → x2,
      → y
      show(list(1, "a"));
      → // list, 2 element(s):
      → [1]:
      →    // int, size 1
      → 1
      → [2]:
      →    // string, size 1
      → a
    """
    lines = _show_lines(ctx, x)
    if rest and isinstance(rest[0], int) and lines:  # show(x, n): n spaces before the information line
        lines[0] = " " * rest[0] + lines[0]
    ctx.write("\n".join(lines) + "\n")
