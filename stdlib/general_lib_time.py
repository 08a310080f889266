"""general.lib's computations under a time limit: ``timeStd(I, d)`` (std(I) if it finishes within d
seconds, else I itself) and ``timeFactorize(p, d)`` (factorH(p) if it finishes within d seconds, else the
list ``list(list(1, p), intvec(1,1))`` that declares p irreducible); ``factorH(p)``: factorize with the
variable of lowest degree in p moved to the last place.  As in Singular the limit is wall-clock time,
so near the limit the answer depends on the machine's speed and load."""
from __future__ import annotations

from typing import Any

from ..dsl.limits import within
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, List
from ..kernel import Poly
from .factorize import factorize
from .standard import standard_basis

LIB = "general.lib"


def _limit(args: tuple[Any, ...]) -> int:
    """The time limit in seconds given as the optional int argument (0: none)."""
    return args[0] if args and isinstance(args[0], int) and not isinstance(args[0], bool) else 0


@command("timeStd", lib=LIB)
def time_std(I: Ideal, *args: Any) -> Ideal:
    """timeStd(I, d): std(I) if it finishes within d seconds, else I (without a limit: std(I)).

    Example:
      LIB "general.lib";
      ring r = 32003,(x,y,z),dp;
      timeStd(ideal(x2-y, xy-z), 10);
      → _[1]=y2-xz
      → _[2]=xy-z
      → _[3]=x2-y
    """
    d = _limit(args)
    if not d:
        return Ideal(I.ring, standard_basis(I), is_std=True)
    ok, basis = within(float(d), standard_basis, I)
    return Ideal(I.ring, basis, is_std=True) if ok else I


@command("factorH", lib=LIB)
def factor_h(p: Poly) -> List:
    """factorH(p): factorize(p) computed with the variable of lowest degree in p as the last one.

    Example:
      LIB "general.lib";
      ring r = 0,(x,y),dp;
      factorH(x2y-y3);
      → [1]:
      →    _[1]=1
      →    _[2]=y
      →    _[3]=x-y
      →    _[4]=x+y
      → [2]:
      →    1,1,1,1
    """
    ring = p.ring
    n = ring.nvars
    degs = [p.degree_in(i) if not p.is_zero() else 0 for i in range(n)]
    k = 0
    for i in range(n):
        if degs[k] > degs[i]:
            k = i
    images = ring.gens()
    images[k], images[n - 1] = images[n - 1], images[k]
    fac = factorize(p.compose(images))
    ideal, mults = fac.items
    return List([Ideal(ring, [g.compose(images) for g in ideal.gens]), mults])


@command("timeFactorize", lib=LIB)
def time_factorize(p: Poly, *args: Any) -> List:
    """timeFactorize(p, d): factorH(p) if it finishes within d seconds, else the list
    list(list(1, p), intvec(1,1)) (p taken as irreducible); without a limit factorH(p).

    Example:
      LIB "general.lib";
      ring r = 0,(x,y),dp;
      timeFactorize(x2-y2);
      → [1]:
      →    _[1]=-1
      →    _[2]=-x+y
      →    _[3]=x+y
      → [2]:
      →    1,1,1
    """
    d = _limit(args)
    if not d:
        return factor_h(p)
    ok, result = within(float(d), factor_h, p)
    return result if ok else List([List([1, p]), IntVec([1, 1])])
