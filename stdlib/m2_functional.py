"""Macaulay2's functions of functions in the Macaulay2 dialect (``dialect="m2"``): ``table``
(a list of lists of values) and ``ultimate`` (a function applied until its value stops changing)."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechError, MechRuntimeError
from ..dsl.m2_local import in_local_rings
from ..dsl.m2_rings import in_quotients
from ..dsl.registry import command
from ..dsl.values import ExprList, List
from .m2_lists import _fn, _items

#: how often ``ultimate`` applies its function before it gives up
ULTIMATE_LIMIT = 10000


def _range(a: Any) -> list:
    return list(range(a)) if type(a) is int else _items(a)


@command("table", dialect="m2")
@in_local_rings
@in_quotients
def table(ctx, rows: List | ExprList | int, cols: List | ExprList | int, f: Any) -> List:
    """table(rows, cols, f): the list of the lists {f(i, j) : j in cols} for i in rows (a number n
    for 0..n-1), as Macaulay2's ``apply(rows, i -> apply(cols, j -> f(i, j)))``."""
    _fn(f)
    cs = _range(cols)
    return List([List([ctx.apply(f, [i, j]) for j in cs]) for i in _range(rows)])


@command("ultimate", dialect="m2")
@in_local_rings
@in_quotients
def ultimate(ctx, f: Any, x: Any) -> Any:
    """ultimate(f, x): f applied to x, then to its value, ..., until the value is x again (the
    same object) or f fails on it: the last value (``ultimate(coefficientRing, R)``)."""
    _fn(f)
    for _ in range(ULTIMATE_LIMIT):
        try:
            y = ctx.apply(f, [x])
        except MechError:
            return x
        if y is x:
            return x
        x = y
    raise MechRuntimeError(f"ultimate: the value still changes after {ULTIMATE_LIMIT} applications")


table.zz_ok = ultimate.zz_ok = True
