"""Graded free modules and matrices as maps in the Macaulay2 dialect: ``map(M, N, ...)`` (lists,
``(i,j) => f`` entries, a function of ``(i, j)``, a matrix, a ring element; ``Degree => d``),
``id_M``, ``source``, ``target``, ``degrees``, ``rank``, ``isHomogeneous`` and ``degree`` of a
matrix, and ``degree``/``length`` of ``R^1/I`` (values: :mod:`mech.dsl.m2_modules`)."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError, MechTypeError
from ..dsl.m2_modules import (CyclicModule, FreeModule, Map, is_homogeneous_map, map_degree, source_degrees,
                              source_of, target_of)
from ..dsl.m2_rings import M2Ring, in_quotients, exact_over_zz
from ..dsl.m2_values import FUNCTIONS, Opt
from ..dsl.registry import command
from ..dsl.values import ExprList, List, Matrix, NoneValue, Number, to_int
from ..kernel import Poly
from .m2 import _polys


def _degree_option(ctx) -> int:
    d = ctx.m2_options.get("Degree", 0)
    if isinstance(d, (List, ExprList)):
        d = d.items[0] if d.items else 0
    return to_int(d)


def _entries(ctx, M: FreeModule, ncols: int, v: Any) -> list[Poly]:
    """The entries row by row of a ``M.rank x ncols`` matrix given as rows, ``(i,j) => f``, a
    function of (i, j), a matrix or a ring element (times the identity)."""
    ring, n = M.ring.poly, M.rank
    zero = ring.zero()
    if isinstance(v, FUNCTIONS):
        return _polys(ctx, tuple(ctx.apply(v, [i, j]) for i in range(n) for j in range(ncols)), ring)
    if isinstance(v, Matrix):
        if (v.nrows, v.ncols) != (n, ncols):
            raise MechRuntimeError(f"map: the matrix is {v.nrows} x {v.ncols}, the modules need {n} x {ncols}")
        return list(v.entries)
    if isinstance(v, (Poly, Number, int)):
        if n != ncols and not (type(v) is int and v == 0):
            raise MechRuntimeError("map(M, N, r): the modules need as many generators")
        r = _polys(ctx, (v,), ring)[0]
        return [r if i == j else zero for i in range(n) for j in range(ncols)]
    if isinstance(v, List) and v.items and all(isinstance(x, Opt) for x in v.items):
        out = [zero] * (n * ncols)
        for item in v.items:
            i, j = (to_int(k) for k in item.key.items)
            if not (0 <= i < n and 0 <= j < ncols):
                raise MechRuntimeError(f"map: the entry ({i},{j}) is outside a {n} x {ncols} matrix")
            out[i * ncols + j] = _polys(ctx, (item.value,), ring)[0]
        return out
    if isinstance(v, List):
        rows = v.items
        if len(rows) != n or any(not isinstance(r, List) or len(r.items) != ncols for r in rows):
            raise MechRuntimeError(f"map: expected {n} rows of {ncols} entries")
        return _polys(ctx, tuple(rows), ring)
    raise MechTypeError("map(M, N, v) takes rows, (i,j) => f entries, a function, a matrix or a ring element")


@command("map", dialect="m2")
@in_quotients
@exact_over_zz
def map_modules(ctx, M: FreeModule, N: FreeModule | int | NoneValue, v: Any) -> Map:
    """map(M, N, v): the matrix N -> M with entries v (rows, (i,j) => f, a function of (i,j), a
    matrix, r for r times the identity); N an integer or omitted: a free source of the degrees
    that make the map homogeneous; Degree => d: the map's degree."""
    d = _degree_option(ctx)
    if isinstance(N, FreeModule):
        return Map(M, N, _entries(ctx, M, N.rank, v), d)
    if isinstance(N, NoneValue):
        if isinstance(v, Matrix):
            N = v.ncols
        elif isinstance(v, List) and v.items and isinstance(v.items[0], List):
            N = len(v.items[0].items)
        else:
            raise MechRuntimeError("map(M, , v) takes a matrix or the rows of one")
    entries = _entries(ctx, M, N, v)
    plain = Matrix(M.ring.poly, M.rank, N, entries)
    return Map(M, FreeModule(M.ring, source_degrees(plain, M.degrees, d)), entries, d)


map_modules.m2_options = ("Degree",)


@command("map", dialect="m2")
@in_quotients
def map_degree_changed(ctx, f: Matrix) -> Map:
    """map(f, Degree => d): f as a map of degree d, its source's degrees shifted to keep the
    entries' degrees (the same target and entries); map f: f."""
    src, e = source_of(f), map_degree(f)
    d = _degree_option(ctx) if "Degree" in ctx.m2_options else e
    return Map(target_of(f), FreeModule(src.ring, tuple(k + e - d for k in src.degrees)), list(f.entries), d)


map_degree_changed.m2_options = ("Degree",)


@command("map", dialect="m2")
@in_quotients
@exact_over_zz
def map_identity(M: FreeModule) -> Map:
    """map M of a free module: its identity map."""
    return identity(M)


@command("id", dialect="m2")
@in_quotients
@exact_over_zz
def identity(M: FreeModule) -> Map:
    """id_M: the identity map of a free module."""
    ring = M.ring.poly
    return Map(M, M, [ring.one() if i == j else ring.zero() for i in range(M.rank) for j in range(M.rank)])


identity.subscript_value = True


@command("source", dialect="m2")
@in_quotients
@exact_over_zz
def source(f: Matrix) -> FreeModule:
    """source f: the free module a matrix maps from."""
    return source_of(f)


@command("target", dialect="m2")
@in_quotients
@exact_over_zz
def target(f: Matrix) -> FreeModule:
    """target f: the free module a matrix maps to."""
    return target_of(f)


@command("degrees", dialect="m2")
@in_quotients
@exact_over_zz
def degrees(M: FreeModule | Matrix) -> List:
    """degrees F: the degrees of a free module's generators; degrees f: those of its target and source."""
    _singly_graded(M, "degrees")
    if isinstance(M, Matrix):
        return List([degrees(target_of(M)), degrees(source_of(M))])
    return List([List([d]) for d in M.degrees])


@command("rank", dialect="m2")
@in_quotients
@exact_over_zz
def rank(M: FreeModule) -> int:
    """rank F: the number of generators of a free module."""
    return M.rank


@command("numgens", dialect="m2")
@in_quotients
@exact_over_zz
def numgens(M: FreeModule) -> int:
    """numgens F: the number of generators of a free module."""
    return M.rank


@command("isHomogeneous", dialect="m2")
@in_quotients
@exact_over_zz
def is_homogeneous(f: Matrix) -> bool:
    """isHomogeneous f: whether each entry has the degree of its column minus its row's, plus f's degree."""
    _singly_graded(f, "isHomogeneous")
    return is_homogeneous_map(f)


@command("degree", dialect="m2")
@in_quotients
def degree(f: Matrix | CyclicModule) -> Any:
    """degree f: the degree of a map ({d}); degree(R^1/I): the degree of R/I."""
    if isinstance(f, CyclicModule):
        from .m2 import degree as ideal_degree
        return ideal_degree(f.ideal)
    _singly_graded(f, "degree")
    return List([map_degree(f)])


def _singly_graded(M: Any, what: str) -> None:
    """Refuse the degrees of modules over a multigraded ring (mech's modules keep one component)."""
    ring = getattr(M, "ring", None)
    ring = ring if isinstance(ring, M2Ring) else getattr(ring, "owner", None)
    if ring is not None and "multidegrees" in ring.ambient().info:
        raise MechRuntimeError(f"{what} of maps and modules over a multigraded ring is not supported by mech")


@command("transpose", dialect="m2")
@in_quotients
@exact_over_zz
def transpose(M: Matrix) -> Matrix:
    """transpose M: the dual map (target and source swapped, their degrees negated)."""
    entries = [M.get(i, j) for j in range(1, M.ncols + 1) for i in range(1, M.nrows + 1)]
    if not isinstance(M, Map):
        return Matrix(M.ring, M.ncols, M.nrows, entries)
    tgt, src = M.target, M.source
    return Map(FreeModule(src.ring, tuple(-d for d in src.degrees)), FreeModule(tgt.ring, tuple(-d for d in tgt.degrees)),
               entries, -map_degree(M))


@command("dual", dialect="m2")
@in_quotients
@exact_over_zz
def dual(M: Matrix) -> Matrix:
    """dual f of a map between free modules: its transpose."""
    return transpose(M)


@command("transpose", dialect="m2")
@in_quotients
@exact_over_zz
def transpose_table(T: List) -> List:
    """transpose T: a table (a list of lists of one length) with rows and columns swapped."""
    rows = T.items
    if not all(isinstance(r, List) for r in rows) or len({len(r.items) for r in rows}) > 1:
        raise MechRuntimeError("transpose T takes a table: lists of one length")
    n = len(rows[0].items) if rows else 0
    return List([List([r.items[j] for r in rows]) for j in range(n)])
