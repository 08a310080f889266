"""Ring maps of the Macaulay2 dialect beyond their images: the change of coordinates a matrix of
numbers gives (``map(S, R, m)``), the degree map (``DegreeMap => f``) and homogeneity of a map."""
from __future__ import annotations

from typing import Any, Callable, Optional

from ..dsl.errors import MechRuntimeError
from ..dsl.m2_rings import degree_vectors, in_quotients, term_degree
from ..dsl.m2_values import RingMap
from ..dsl.registry import command
from ..dsl.values import ExprList, List, Matrix, Ring
from ..kernel import Poly


def degree_map(ctx) -> Optional[Callable[[tuple], tuple]]:
    """The option ``DegreeMap => f`` of ``map`` as a function of degree vectors (None without it)."""
    fn = ctx.m2_options.get("DegreeMap")
    return None if fn is None else (lambda d: tuple(int(x) for x in _seq(ctx.apply(fn, [List(list(d))]))))


def _seq(v: Any) -> list:
    if not isinstance(v, (List, ExprList)) or not all(type(x) is int for x in v.items):
        raise MechRuntimeError("DegreeMap => f: f takes a degree (a list of integers) to a degree")
    return list(v.items)


@command("isHomogeneous", dialect="m2")
@in_quotients
def is_homogeneous_map(f: RingMap) -> bool:
    """isHomogeneous f of a ring map: whether every variable's image is zero or homogeneous of the
    variable's degree (mapped by DegreeMap: by default the same degree)."""
    src, tgt = (degree_vectors(getattr(r.poly, "owner", r)) for r in (f.source, f.target))
    if f.degree_map is None and len(src[0]) != len(tgt[0]):
        raise MechRuntimeError("isHomogeneous of a map between rings of different degree lengths needs DegreeMap")
    for d, p in zip(src, f.images):
        want = f.degree_map(d) if f.degree_map else tuple(d)
        if not p.is_zero() and {tuple(term_degree(e, tgt)) for e in p.terms} != {tuple(want)}:
            return False
    return True


def change_of_coordinates(target: Ring, m: Matrix, n: int) -> list[Poly]:
    """map(S, R, m) for a matrix m of numbers: the linear change of coordinates, R's j-th variable
    to the sum over i of S's i-th variable times m_ij."""
    R = target.poly
    if getattr(getattr(R, "owner", None), "base", None) is not None and isinstance(R.owner.base, Ring) \
            or m.nrows != R.nvars or m.ncols != n:
        raise MechRuntimeError(f"map(S, R, m) for a matrix m of numbers takes {R.nvars} rows and {n} columns")
    rows = m.rows()
    return [sum((R.gen(i) * R.field(rows[i][j].lc()) for i in range(R.nvars) if not rows[i][j].is_zero()), R.zero())
            for j in range(n)]
