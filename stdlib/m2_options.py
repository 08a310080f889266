"""Macaulay2's option tables (``options R`` of a polynomial ring, ``options sort``), ``newRing``
(a ring like another with some options changed) and ``sort`` of a matrix's columns."""
from __future__ import annotations

from functools import cmp_to_key
from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.m2_modules import FreeModule
from ..dsl.m2_orders import _items
from ..dsl.m2_printing import to_string
from ..dsl.m2_ringcons import OPTIONS, make_ring
from ..dsl.m2_rings import degree_vectors, in_group_rings, in_quotients, integers, normal
from ..dsl.m2_values import CommandRef, Opt, OptionTable, Symbol, VerticalList
from ..dsl.registry import command
from ..dsl.values import NONE, List, Matrix, Ring
from .m2_lists import _compare


#: the options of Macaulay2's functions mech has, with their defaults
FUNCTION_OPTIONS = {"sort": [("MonomialOrder", Symbol("Ascending")), ("DegreeOrder", NONE)]}


@command("options", dialect="m2")
@in_group_rings
def options(f: Any) -> OptionTable:
    """options R: the options a polynomial ring was made with (all of them, defaults too);
    options f: a function's options with their defaults."""
    if isinstance(f, Ring):
        return _ring_options(f)
    name = f.command.name if isinstance(f, CommandRef) else None
    if name not in FUNCTION_OPTIONS:
        raise MechRuntimeError(f"options of {name or 'this value'} is not supported by mech")
    return OptionTable(list(FUNCTION_OPTIONS[name]))


def _ring_options(R: Ring) -> OptionTable:
    owner = getattr(R.poly, "owner", None)
    if owner is None or owner.parent is not None or isinstance(owner.base, Ring) or "m2_order" not in owner.info \
            or "multidegrees" in owner.info or owner.info.get("localized_at") is not None:
        raise MechRuntimeError("options R of a quotient ring, tower, local or multigraded ring is not supported by mech")
    n = R.poly.nvars
    spec, size = owner.info["m2_order"]
    degrees = [d[0] for d in degree_vectors(owner)]
    return OptionTable([  # in the order Macaulay2 shows them
        ("DegreeGroup", FreeModule(integers(), (0,))), ("Variables", List([normal(R.poly.gen(i)) for i in range(n)])),
        ("DegreeLift", NONE), ("DegreeRank", 1), ("Inverses", False), ("Global", R.poly.order.is_global),
        ("MonomialOrder", monomial_order(spec, n, degrees, size)), ("WeylAlgebra", List([])),
        ("Degrees", List([List([d]) for d in degrees])), ("Join", NONE), ("Local", False), ("Heft", List([1])),
        ("Constants", False), ("SkewCommutative", List([])), ("DegreeMap", NONE)])


@command("newRing", dialect="m2")
def new_ring(ctx, R: Ring) -> Ring:
    """newRing(R, Option => v, ...): a polynomial ring like R (its coefficient ring, variables and
    options: the monomial order as options R shows it) with these options changed."""
    owner = getattr(R.poly, "owner", None)
    if owner is None or owner.parent is not None or "m2_options" not in owner.info:
        raise MechRuntimeError("newRing of a quotient or local ring is not supported by mech")
    options = dict(owner.info["m2_options"])
    options.pop("Weights", None)  # part of the monomial order below
    options["MonomialOrder"] = _ring_options(R).m2_fields["MonomialOrder"]
    options.update(ctx.m2_options)
    return make_ring(owner.base, list(owner.own), options, to_string)


new_ring.m2_options = OPTIONS


def monomial_order(spec: Any, n: int, degrees: list[int], size: Any = None) -> VerticalList:
    """Macaulay2's normal form of ``MonomialOrder => spec`` (what ``options R`` shows): its
    blocks with their weights or sizes, GRevLex on the variables left over, ``Position => Up``."""
    out: list[Opt] = [Opt(Symbol("MonomialSize"), 32 if size is None else size)]
    covered = 0

    def grevlex(k: int) -> None:
        nonlocal covered
        out.append(Opt(Symbol("GRevLex"), List(list(degrees[covered:covered + k]))))
        covered += k

    for item in _items(spec):
        key = item.key.name if isinstance(item, Opt) and isinstance(item.key, Symbol) else None
        word = item.name if isinstance(item, Symbol) else None
        if word == "GRevLex" or type(item) is int:
            grevlex(n - covered if word else item)
        elif word in ("Lex", "RevLex"):
            out.append(Opt(Symbol(word), n - covered))
            covered = n
        elif word == "GLex":
            out += [Opt(Symbol("Weights"), List([1] * n)), Opt(Symbol("Lex"), n - covered)]
            covered = n
        elif key == "GRevLex" and isinstance(item.value, List):
            out.append(item)
            covered += len(item.value.items)
        elif key == "GRevLex":
            grevlex(item.value)
        elif key in ("Lex", "RevLex"):
            out.append(item)
            covered += item.value
        elif key == "ProductOrder":
            for k in _items(item.value):
                grevlex(k)
        elif key == "Weights":
            out.append(Opt(Symbol("Weights"), List(list(_items(item.value)))))
        elif key == "Eliminate":
            out.append(Opt(Symbol("Weights"), List([1] * item.value)))
        elif key in ("GroupLex", "GroupRevLex"):
            out.append(item)
            covered += item.value
        elif key == "Position":
            out.append(item)
        elif key == "MonomialSize":
            out[0] = item
        else:
            raise MechRuntimeError("options R of this monomial order is not supported by mech")
    if covered < n:
        grevlex(n - covered)
    if not any(isinstance(o, Opt) and o.key == Symbol("Position") for o in out):
        out.append(Opt(Symbol("Position"), Symbol("Up")))
    return VerticalList(out)


@command("sort", dialect="m2")
@in_quotients
def sort_matrix(ctx, m: Matrix) -> Matrix:
    """sort m: the columns of a one-row matrix in increasing monomial order (DegreeOrder =>
    Ascending or Descending: by degree first; MonomialOrder => Descending: decreasing)."""
    if m.nrows != 1:
        raise MechRuntimeError("sort of a matrix with several rows is not supported by mech")
    entries = list(m.entries)
    by_degree = ctx.m2_options.get("DegreeOrder", NONE)
    mono = ctx.m2_options.get("MonomialOrder", Symbol("Ascending"))
    if any(f.is_zero() for f in entries):
        raise MechRuntimeError("sort of a matrix with zero entries is not supported by mech")
    for v in (mono,) + (() if by_degree in (NONE, None) else (by_degree,)):
        if v not in (Symbol("Ascending"), Symbol("Descending")):
            raise MechRuntimeError("sort: DegreeOrder and MonomialOrder take Ascending or Descending")
    sign = -1 if mono == Symbol("Descending") else 1
    dsign = 0 if by_degree in (NONE, None) else -1 if by_degree == Symbol("Descending") else 1

    weights = degree_vectors(m.ring.owner) if getattr(m.ring, "owner", None) is not None else []
    if dsign and (len(weights) != m.ring.nvars or any(len(w) != 1 for w in weights)):
        raise MechRuntimeError("sort by degree in a multigraded ring is not supported by mech")
    deg = {id(f): {sum(a * w[0] for a, w in zip(e, weights)) for e in f.terms} for f in entries} if dsign else {}
    if any(len(d) != 1 for d in deg.values()):
        raise MechRuntimeError("sort by degree of a matrix with inhomogeneous entries is not supported by mech")

    def cmp(f: Any, g: Any) -> int:
        df, dg = (min(deg[id(f)]), min(deg[id(g)])) if dsign else (0, 0)
        d = (df > dg) - (df < dg)
        return dsign * d or sign * _compare(f, g)
    return Matrix(m.ring, 1, m.ncols, sorted(entries, key=cmp_to_key(cmp)))


sort_matrix.m2_options = ("DegreeOrder", "MonomialOrder")

