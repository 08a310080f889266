"""primdec.lib's variants of the decompositions (:mod:`mech.stdlib.primdec`): ``minAss`` (the minimal
associated primes, as minAssGTZ) and the ``E`` forms (``primdecGTZE``, ``primdecSYE``, ``minAssGTZE``,
``minAssCharE``, ``minAssE``), which give the empty list for the unit ideal where the others give
the list of the unit ideal (primdecSYE does not, in Singular either)."""
from __future__ import annotations

from typing import Any, Callable

from ..dsl.registry import command
from ..dsl.values import Ideal, List
from .primdec import min_ass_char_options, min_ass_gtz_options, primdec_gtz_options, primdec_sy_options
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
