"""Primary decomposition (Singular's primdec.lib): minimal associated primes, primary
decompositions, equidimensional parts.  Components are reduced bases normalized as Singular's
std returns them (:func:`~mech.stdlib.standard.normalize`), ordered by decreasing dimension,
then by leading monomials (Singular's order of components follows its internal splitting and
is not reproduced).  In a ring with a local ordering the decomposition is that of the local
ring at the origin: the components through the origin (:mod:`mech.kernel.local`)."""
from __future__ import annotations

from typing import Any, Callable

from ..dsl.errors import MechRuntimeError
from ..dsl.values import Ideal, List
from ..kernel import Poly
from ..kernel import local as _local
from ..kernel import primdec as P
from ..dsl.registry import command
from .standard import normalize


def _ideal(ring: Any, basis: list[Poly]) -> Ideal:
    return Ideal(ring, [normalize(p) for p in basis], is_std=True)


def _run(cmd: str, func: Callable, I: Ideal) -> Any:
    """Call a kernel decomposition with Singular-like error messages."""
    try:
        return func(I.nonzero(), I.ring)
    except NotImplementedError:
        raise MechRuntimeError(f"{cmd} is not available over the coefficient field {I.ring.field!r}") from None
    except RuntimeError as e:
        raise MechRuntimeError(f"{cmd}: {e}") from None


def _primes(cmd: str, I: Ideal) -> List:
    """The minimal primes; for the unit ideal Singular's list(ideal(1)) (globally) or the
    empty list (locally)."""
    if not I.ring.order.is_global:
        return List([_ideal(I.ring, p) for p in _run(cmd, _local.min_ass_local, I)])
    primes = _run(cmd, P.min_ass_gtz if cmd == "minAssGTZ" else P.min_ass_char, I)
    return List([_ideal(I.ring, p) for p in primes or [[I.ring.one()]]])


def _primaries(cmd: str, I: Ideal) -> List:
    """The (primary, prime) pairs; for the unit ideal Singular's list(list(ideal(1),
    ideal(1))) (globally) or the empty list (locally)."""
    if not I.ring.order.is_global:
        comps = _run(cmd, _local.primdec_local, I)
    else:
        comps = _run(cmd, P.primdec_gtz if cmd == "primdecGTZ" else P.primdec_sy, I)
        comps = comps or [([I.ring.one()], [I.ring.one()])]
    return List([List([_ideal(I.ring, q), _ideal(I.ring, p)]) for q, p in comps])


def _global(I: Ideal, cmd: str) -> None:
    if not I.ring.order.is_global:
        raise MechRuntimeError(f"{cmd} needs a global ordering (dp, lp, ...), not a local one")


@command("minAssGTZ", lib="primdec.lib")
def min_ass_gtz(I: Ideal) -> List:
    """minAssGTZ(I): the list of the minimal associated primes of I (Gianni-Trager-Zacharias);
    in a ring with a local ordering, those of the local ring at the origin.

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y,z),dp;
      minAssGTZ(ideal(xz, yz));
      → [1]:
      →    _[1]=z
      → [2]:
      →    _[1]=y
      →    _[2]=x
    """
    return _primes("minAssGTZ", I)


@command("minAssChar", lib="primdec.lib")
def min_ass_char(I: Ideal) -> List:
    """minAssChar(I): the list of the minimal associated primes of I (the same primes as
    minAssGTZ, computed without the factorizing pre-split; Singular lists them in another
    order).

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y,z),dp;
      minAssChar(ideal((x-y)^2, z3));
      → [1]:
      →    _[1]=z
      →    _[2]=x-y
    """
    return _primes("minAssChar", I)


@command("primdecGTZ", lib="primdec.lib")
def primdec_gtz(I: Ideal) -> List:
    """primdecGTZ(I): an irredundant primary decomposition of I (Gianni-Trager-Zacharias), a
    list of pairs [primary component, its prime], embedded components included.

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y,z),dp;
      primdecGTZ(ideal(x2, xz));
      → [1]:
      →    [1]:
      →       _[1]=x
      →    [2]:
      →       _[1]=x
      → [2]:
      →    [1]:
      →       _[1]=z
      →       _[2]=x2
      →    [2]:
      →       _[1]=z
      →       _[2]=x
    """
    return _primaries("primdecGTZ", I)


@command("primdecSY", lib="primdec.lib")
def primdec_sy(I: Ideal) -> List:
    """primdecSY(I): an irredundant primary decomposition of I (Shimoyama-Yokoyama), a list of
    pairs [primary component, its prime].

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y,z),dp;
      primdecSY(ideal(xy));
      → [1]:
      →    [1]:
      →       _[1]=y
      →    [2]:
      →       _[1]=y
      → [2]:
      →    [1]:
      →       _[1]=x
      →    [2]:
      →       _[1]=x
    """
    return _primaries("primdecSY", I)


#: The options of primdec.lib's decompositions: they choose among algorithms, not the result.
_OPTIONS = {"minAssGTZ": ({0, 1}, {"facstd", "noFacstd", "GTZ", "SL"}), "primdecGTZ": (set(), {"GTZ", "SL", "keep_comp"}),
            "primdecSY": ({0, 1, 2, 3}, set()), "minAssChar": ({0, 1, 2, 3}, set()),
            "radical": ({0}, {"fullRad", "KL", "SL", "facstd", "noFacstd"})}


def _options(cmd: str, opts: tuple) -> None:
    ints, words = _OPTIONS[cmd]
    for o in opts:
        if cmd == "radical" and o in (1, "equiRad"):
            raise MechRuntimeError("radical(I, 1): the equiradical is not supported")
        if o == "global":
            raise MechRuntimeError(f'{cmd}(I, "global"): the decomposition in the global ring is not supported')
        if not ((isinstance(o, int) and o in ints) or (isinstance(o, str) and o in words)):
            allowed = ", ".join([str(i) for i in sorted(ints)] + [f'"{w}"' for w in sorted(words)])
            raise MechRuntimeError(f"{cmd}: unknown option {o!r} (options: {allowed})")


@command("radical", lib="primdec.lib")
def radical_options(I: Ideal, *opts: Any) -> Ideal:
    """radical(I, "KL") and the other options of radical that choose an algorithm (not the result)."""
    from .ideals import radical
    _options("radical", opts)
    return radical(I)


@command("minAssGTZ", lib="primdec.lib")
def min_ass_gtz_options(I: Ideal, *opts: Any) -> List:
    _options("minAssGTZ", opts)
    return _primes("minAssGTZ", I)


@command("minAssChar", lib="primdec.lib")
def min_ass_char_options(I: Ideal, c: int) -> List:
    _options("minAssChar", (c,))
    return _primes("minAssChar", I)


@command("primdecGTZ", lib="primdec.lib")
def primdec_gtz_options(I: Ideal, *opts: Any) -> List:
    _options("primdecGTZ", opts)
    return _primaries("primdecGTZ", I)


@command("primdecSY", lib="primdec.lib")
def primdec_sy_options(I: Ideal, c: int) -> List:
    _options("primdecSY", (c,))
    return _primaries("primdecSY", I)


@command("equidim", lib="primdec.lib")
def equidim(I: Ideal) -> List:
    """equidim(I): equidimensional ideals intersecting to I, by increasing dimension; the last
    one is the top-dimensional part of I (the lower ones, made of embedded components, are not
    unique; Singular's may differ).

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y,z),dp;
      equidim(intersect(ideal(x), ideal(y,z)));
      → [1]:
      →    _[1]=z
      →    _[2]=y
      → [2]:
      →    _[1]=x
    """
    _global(I, "equidim")
    return List([_ideal(I.ring, a) for a in _run("equidim", P.equidim, I)])


@command("equiRadical", lib="primdec.lib")
def equi_radical(I: Ideal) -> Ideal:
    """equiRadical(I): the radical of the top-dimensional part of I (the intersection of the
    minimal primes of maximal dimension).

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y,z),dp;
      equiRadical(intersect(ideal(x2), ideal(y,z)));
      → _[1]=x
    """
    _global(I, "equiRadical")
    return _ideal(I.ring, _run("equiRadical", P.equi_radical, I))


@command("idealsEqual", lib="primdec.lib")
def ideals_equal(I: Ideal, J: Ideal) -> int:
    """idealsEqual(I, J): 1 if the ideals are equal, else 0 (a global ordering).

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y),dp;
      idealsEqual(ideal(x, x+y), ideal(x, y));
      → 1
    """
    _global(I, "idealsEqual")
    from ..kernel.ideals import ideals_equal as equal
    return int(equal(I.nonzero(), J.nonzero(), ring=I.ring))
