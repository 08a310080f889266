"""primdec.lib's variants of the decompositions (:mod:`mech.stdlib.primdec`): ``minAss`` (the minimal
associated primes, as minAssGTZ) and the ``E`` forms (``primdecGTZE``, ``primdecSYE``, ``minAssGTZE``,
``minAssCharE``, ``minAssE``), which give the empty list for the unit ideal where the others give
the list of the unit ideal (primdecSYE does not, in Singular either); the decompositions of
zero-dimensional ideals ``zerodec``, ``zero_decomp`` and ``newZero_decomp``, and the maximal independent
sets as variable and ordering strings (``newMaxIndependSetDp``, ``newMaxIndependSetLp``)."""
from __future__ import annotations

from typing import Any, Callable

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, List
from ..kernel.dimension import krull_dim
from .idealops import indepSet
from .rings import ordstr
from .primdec import _primaries, min_ass_char_options, min_ass_gtz_options, primdec_gtz_options, primdec_sy_options
from .standard import standard_basis

LIB = "primdec.lib"


def _empty_for_unit(I: Ideal, decompose: Callable[..., List], *opts: Any) -> List:
    if any(g.is_constant() and not g.is_zero() for g in standard_basis(I)):
        return List()
    return decompose(I, *opts)


@command("minAss", lib=LIB)
def min_ass(I: Ideal, *opts: Any) -> List:
    """minAss(I): the list of the minimal associated primes of I (as minAssGTZ).

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y),dp;
      minAss(ideal(x2y));
      → [1]:
      →    _[1]=y
      → [2]:
      →    _[1]=x
    """
    return min_ass_gtz_options(I, *opts)


@command("minAssE", lib=LIB)
def min_ass_e(I: Ideal, *opts: Any) -> List:
    """minAssE(I): minAss(I), the empty list for the unit ideal.

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y),dp;
      minAssE(ideal(1));
      → empty list
    """
    return _empty_for_unit(I, min_ass_gtz_options, *opts)


@command("minAssGTZE", lib=LIB)
def min_ass_gtz_e(I: Ideal, *opts: Any) -> List:
    """minAssGTZE(I): minAssGTZ(I), the empty list for the unit ideal.

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y),dp;
      minAssGTZE(ideal(x, 1-y, y));
      → empty list
    """
    return _empty_for_unit(I, min_ass_gtz_options, *opts)


@command("minAssCharE", lib=LIB)
def min_ass_char_e(I: Ideal, c: int = 1) -> List:
    """minAssCharE(I): minAssChar(I), the empty list for the unit ideal.

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y),dp;
      minAssCharE(ideal(5));
      → empty list
    """
    return _empty_for_unit(I, min_ass_char_options, c)


@command("primdecGTZE", lib=LIB)
def primdec_gtz_e(I: Ideal, *opts: Any) -> List:
    """primdecGTZE(I): primdecGTZ(I), the empty list for the unit ideal.

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y),dp;
      primdecGTZE(ideal(1));
      → empty list
    """
    return _empty_for_unit(I, primdec_gtz_options, *opts)


@command("primdecSYE", lib=LIB)
def primdec_sy_e(I: Ideal, c: int = 1) -> List:
    """primdecSYE(I[, c]): primdecSY(I) (also for the unit ideal, as Singular, whatever its help says).

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y),dp;
      primdecSYE(ideal(x2));
      → [1]:
      →    [1]:
      →       _[1]=x2
      →    [2]:
      →       _[1]=x
    """
    return primdec_sy_options(I, c)


def _zero_dimensional(I: Ideal, cmd: str) -> bool:
    if not I.ring.order.is_global:
        raise MechRuntimeError(f"{cmd} needs a global ordering (dp, lp, ...), not a local one")
    basis = standard_basis(I)
    return krull_dim([g.lm() for g in basis], I.ring.nvars) == 0 and not any(g.is_constant() for g in basis)


@command("zerodec", lib=LIB)
def zerodec(I: Ideal) -> List:
    """zerodec(I): the primary components of the zero-dimensional ideal I (Singular computes them by
    Monico's algorithm, mech by primdecGTZ; the components are the same, their order may differ).

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y),dp;
      zerodec(ideal(x2-1, y-x));
      → [1]:
      →    _[1]=y-1
      →    _[2]=x-1
      → [2]:
      →    _[1]=y+1
      →    _[2]=x+1
    """
    if not _zero_dimensional(I, "zerodec"):
        raise MechRuntimeError("zerodec: the ideal must be zero-dimensional")
    return List([pair[0] for pair in _primaries("primdecGTZ", I)])


def _zero_decomp(cmd: str, j: Ideal, ser: Ideal, wr: int) -> List:
    """The flat list primary, prime, primary, prime... of the zero-dimensional j (wr = 1: each primary
    replaced by its prime); ideal(1), ideal(1) if j is not zero-dimensional.  ``ser``, an ideal of
    primdec.lib's internal recursion, does not change the answer (nor does it in Singular's runs)."""
    one = Ideal(j.ring, [j.ring.one()])
    if not _zero_dimensional(j, cmd):
        return List([one, one])
    out: list[Ideal] = []
    for q, p in _primaries("primdecGTZ", j):
        out += [p if wr else q, p]
    return List(out)


@command("zero_decomp", lib=LIB)
def zero_decomp(j: Ideal, ser: Ideal, wr: int) -> List:
    """zero_decomp(j, ser, wr): the primary decomposition of the zero-dimensional ideal j as one list:
    each primary component followed by its prime (wr = 1: the primes only, each twice); the list
    ideal(1), ideal(1) if j is not zero-dimensional.

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y),lp;
      zero_decomp(std(ideal(x2, y-1)), ideal(0), 0);
      → [1]:
      →    _[1]=y-1
      →    _[2]=x2
      → [2]:
      →    _[1]=y-1
      →    _[2]=x
    """
    return _zero_decomp("zero_decomp", j, ser, wr)


@command("newZero_decomp", lib=LIB)
def new_zero_decomp(j: Ideal, ser: Ideal, wr: int, *nest: Any) -> List:
    """newZero_decomp(j, ser, wr): zero_decomp(j, ser, wr) (Singular's variant changes its method on
    hard inputs, not its answer).

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y),lp;
      newZero_decomp(std(ideal(x, y2)), ideal(0), 1);
      → [1]:
      →    _[1]=y
      →    _[2]=x
      → [2]:
      →    _[1]=y
      →    _[2]=x
    """
    return _zero_decomp("newZero_decomp", j, ser, wr)


def _max_independent(ctx, j: Ideal, block: Callable[[int, int], str], all_sets: bool) -> List:
    """For each maximal independent set of size dim (only the first unless ``all_sets``): the variables
    as a string, the others first ("var(2), var(3), var(1)"), the ordering string and the size."""
    ring = ctx.basering()
    sets = list(indepSet(ctx, j, 0))
    out = []
    for v in sets if all_sets else sets[:1]:
        marks = list(v.values) if isinstance(v, IntVec) else list(v)
        n = len(marks)
        di = sum(1 for m in marks if m)
        if di == 0:
            out.append(List([",".join(ring.names), ordstr(ring), 0]))
            continue
        order = [k for k in range(n) if not marks[k]] + [k for k in range(n) if marks[k]]
        out.append(List([", ".join(f"var({k + 1})" for k in order), block(n - di, di), di]))
    return List(out)


@command("newMaxIndependSetDp", lib=LIB)
def new_max_independ_set_dp(ctx, j: Ideal, *opts: Any) -> List:
    """newMaxIndependSetDp(j[, 0]): for each maximal independent set of size dim of the standard basis
    j (with 0: the first only) the list of the variables reordered with the set last ("var(2), var(1)"),
    the ordering "dp(n-d), dp(d)" making the set a block, and d, the set's size.

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y,z),dp;
      newMaxIndependSetDp(std(ideal(x, yz)));
      → [1]:
      →    [1]:
      →       var(1), var(3), var(2)
      →    [2]:
      →       dp(2), dp(1)
      →    [3]:
      →       1
      → [2]:
      →    [1]:
      →       var(1), var(2), var(3)
      →    [2]:
      →       dp(2), dp(1)
      →    [3]:
      →       1
    """
    return _max_independent(ctx, j, lambda a, b: f"dp({a}), dp({b})", not opts or opts[0] != 0)


@command("newMaxIndependSetLp", lib=LIB)
def new_max_independ_set_lp(ctx, j: Ideal, *opts: Any) -> List:
    """newMaxIndependSetLp(j[, "allIndep"]): as newMaxIndependSetDp with the ordering "lp" (any option
    other than "allIndep": the first set only).

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y,z),dp;
      newMaxIndependSetLp(std(ideal(x, y)));
      → [1]:
      →    [1]:
      →       var(1), var(2), var(3)
      →    [2]:
      →       lp
      →    [3]:
      →       1
    """
    return _max_independent(ctx, j, lambda a, b: "lp", not opts or opts[0] == "allIndep")


@command("Ann", lib="primdec.lib")
def ann(M: Any) -> Ideal:
    """Ann(M): the annihilator of coker(M) = R^n/M for a module M of rank n (over a qring of
    (R/Q)^n/M): the ideal quotient M : R^n, a standard basis.

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y,z),lp;
      Ann(module([1,x2],[y,x]));
      → _[1]=x2y-x
    """
    from ..dsl.values_modules import Module, Vector
    from .module_ops import quotient
    if not isinstance(M, Module):
        raise MechRuntimeError("Ann: a module expected")
    ring = M.ring
    free = Module(ring, [Vector(ring, [ring.zero()] * i + [ring.one()]) for i in range(M.rank)], M.rank)
    found = quotient(M, free)
    return Ideal(ring, found.gens)
