"""elim.lib's selection of generators by the variables they contain: ``select`` (all of the given
variables), ``select1`` (at least one), ``nselect`` (none); zero generators are dropped.  A matrix is
treated column by column and a module generator by generator (a column or vector contains a variable
when one of its entries does)."""
from __future__ import annotations

from typing import Callable

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, Matrix
from ..dsl.values_modules import Module
from ..kernel import Poly

LIB = "elim.lib"


def _occurs(polys: list[Poly]) -> set[int]:
    return {i for p in polys for e in p.terms for i, k in enumerate(e) if k}


def _select(I: Ideal | Matrix | Module, v: IntVec | int, keep: Callable[[set[int], list[int]], bool], cmd: str):
    idx = [v] if isinstance(v, int) else list(v)
    n = I.ring.nvars
    if any(not 1 <= k <= n for k in idx):
        raise MechRuntimeError(f"{cmd}: variable index out of range 1..{n}")
    wanted = [k - 1 for k in idx]
    if isinstance(I, Ideal):
        return Ideal(I.ring, [g for g in I.gens if not g.is_zero() and keep(_occurs([g]), wanted)])
    if isinstance(I, Module):
        return Module(I.ring, [g for g in I.gens if not g.is_zero() and keep(_occurs(list(g.entries)), wanted)],
                      I.rank)
    cols = [[I.get(i, j) for i in range(1, I.nrows + 1)] for j in range(1, I.ncols + 1)]
    kept = [c for c in cols if any(not p.is_zero() for p in c) and keep(_occurs(c), wanted)]
    if not kept:
        return Matrix(I.ring, I.nrows, 1)
    return Matrix(I.ring, I.nrows, len(kept), [c[i] for i in range(I.nrows) for c in kept])


@command("select", lib=LIB)
def select(I: Ideal | Matrix | Module, v: IntVec | int) -> Ideal | Matrix | Module:
    """select(I, v): the generators (columns) of I that contain every variable with index in v.

    Example:
      LIB "elim.lib";
      ring r = 0,(x,y,z),dp;
      select(ideal(x2, xy, z), 1..2);
      → _[1]=xy
    """
    return _select(I, v, lambda occ, w: all(k in occ for k in w), "select")


@command("select1", lib=LIB)
def select1(I: Ideal | Matrix | Module, v: IntVec | int) -> Ideal | Matrix | Module:
    """select1(I, v): the generators (columns) of I that contain at least one variable with index in v.

    Example:
      LIB "elim.lib";
      ring r = 0,(x,y,z),dp;
      select1(ideal(x2, xy, z), 2..3);
      → _[1]=xy
      → _[2]=z
    """
    return _select(I, v, lambda occ, w: any(k in occ for k in w), "select1")


@command("nselect", lib=LIB)
def nselect(I: Ideal | Matrix | Module, v: IntVec | int) -> Ideal | Matrix | Module:
    """nselect(I, v): the generators (columns) of I that contain none of the variables with index in v.

    Example:
      LIB "elim.lib";
      ring r = 0,(x,y,z),dp;
      nselect(ideal(x2, xy, z, y3+1), 1);
      → _[1]=z
      → _[2]=y3+1
    """
    return _select(I, v, lambda occ, w: not any(k in occ for k in w), "nselect")
