"""More of Singular's primdec.lib around primary decompositions: ``equidimMax``, ``equidimMaxEHV``,
``radicalEHV``, ``prepareAss`` and ``testPrimary``.  The EHV variants name Singular's algorithm (by
Eisenbud, Huneke and Vasconcelos); mech computes the same ideals from its primary decomposition."""
from __future__ import annotations

from ..dsl.registry import command
from ..dsl.values import Ideal, List
from ..kernel import primdec as P
from ..kernel.ideals import dimension, ideals_equal, intersect
from .primdec import _global, _ideal, _run


@command("equidimMax", lib="primdec.lib")
def equidim_max(I: Ideal) -> Ideal:
    """equidimMax(I): the equidimensional part of I of maximal dimension (the intersection of its
    primary components of dimension dim(I)); the unit ideal for the unit ideal.

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y,z),dp;
      equidimMax(intersect(ideal(z), ideal(x,y), ideal(x2,z2)));
      → _[1]=z
    """
    _global(I, "equidimMax")
    return _ideal(I.ring, _run("equidimMax", P.equidim_max, I))


@command("equidimMaxEHV", lib="primdec.lib")
def equidim_max_ehv(I: Ideal) -> Ideal:
    """equidimMaxEHV(I): equidimMax(I) (Singular computes it by the algorithm of Eisenbud, Huneke and
    Vasconcelos).

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y,z),dp;
      equidimMaxEHV(intersect(ideal(z), ideal(x,y), ideal(x2,z2)));
      → _[1]=z
    """
    _global(I, "equidimMaxEHV")
    return _ideal(I.ring, _run("equidimMaxEHV", P.equidim_max, I))


@command("radicalEHV", lib="primdec.lib")
def radical_ehv(I: Ideal) -> Ideal:
    """radicalEHV(I): the radical of I (Singular computes it by the algorithm of Eisenbud, Huneke and
    Vasconcelos).

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y),dp;
      radicalEHV(ideal(x2, xy));
      → _[1]=x
    """
    _global(I, "radicalEHV")
    if not I.nonzero():
        return Ideal(I.ring, [I.ring.zero()])
    return _ideal(I.ring, _run("radicalEHV", P.radical, I))


@command("prepareAss", lib="primdec.lib")
def prepare_ass(I: Ideal) -> List:
    """prepareAss(I): for each codimension c of an associated prime of I (embedded ones included),
    from the largest down, the intersection of the associated primes of codimension c (the radicals
    of the equidimensional parts of I); the empty list for the unit ideal.

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y,z),dp;
      prepareAss(intersect(ideal(z), ideal(x2,y)));
      → [1]:
      →    _[1]=y
      →    _[2]=x
      → [2]:
      →    _[1]=z
    """
    _global(I, "prepareAss")
    ring = I.ring
    comps = _run("prepareAss", P.primdec_gtz, I)
    by_codim: dict[int, list] = {}
    for _, p in comps:
        by_codim.setdefault(ring.nvars - dimension(p, ring), []).append(p)
    return List([_ideal(ring, intersect(*by_codim[c], ring=ring)) for c in sorted(by_codim, reverse=True)])


@command("testPrimary", lib="primdec.lib")
def test_primary(pr: List, k: Ideal) -> int:
    """testPrimary(pr, k): 1 if the primary ideals of the decomposition pr (a result of primdecGTZ or
    primdecSY: pairs of a primary ideal and its prime) intersect to k, else 0.

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y),dp;
      ideal i = x2, xy;
      testPrimary(primdecGTZ(i), i);
      → 1
    """
    return _intersect_to(pr, k, "testPrimary")


@command("testPrimaryE", lib="primdec.lib")
def test_primary_e(pr: List, k: Ideal) -> int:
    """testPrimaryE(pr, k): testPrimary(pr, k), pr possibly empty (the decomposition of the unit ideal).

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y),dp;
      testPrimaryE(list(), ideal(1));
      → 1
    """
    return _intersect_to(pr, k, "testPrimaryE")


def _intersect_to(pr: List, k: Ideal, cmd: str) -> int:
    _global(k, cmd)
    ring = k.ring
    primaries = [c[0] if isinstance(c, List) else c for c in pr]
    meet = intersect(*[q.nonzero() for q in primaries], ring=ring) if primaries else [ring.one()]
    return int(ideals_equal(meet, k.nonzero(), ring=ring))


@command("equidim", lib="primdec.lib")
def equidim_ehv(I: Ideal, m: int) -> List:
    """equidim(I, 1): equidim(I) (Singular's second argument picks the algorithm of Eisenbud, Huneke
    and Vasconcelos; the parts of lower dimension, made of embedded components, are not unique)."""
    _global(I, "equidim")
    return List([_ideal(I.ring, a) for a in _run("equidim", P.equidim, I)])
