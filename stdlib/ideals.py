"""The ideal toolbox: elimination, intersections, quotients, saturation, radicals and
homogenization, with Singular's names, argument order and output (results that Singular returns
as standard bases are reduced bases normalized by :func:`~mech.stdlib.standard.normalize`)."""
from __future__ import annotations

from contextlib import contextmanager
from typing import Any, Iterator

from ..dsl.errors import MechRuntimeError
from ..dsl.values import Ideal, IntVec, List
from ..kernel import Poly
from ..kernel import homog as _homog
from ..kernel import ideals as K
from ..kernel import primdec as _primdec
from ..kernel.qhweight import qh_weights
from ..dsl.qrings import quotient_of, with_quotient
from ..dsl.registry import command
from .standard import normalize


@contextmanager
def _available(cmd: str, ring: Any) -> Iterator[None]:
    """Kernel algorithms that need factorization or exact division exist over QQ and Z/p only."""
    try:
        yield
    except NotImplementedError:
        raise MechRuntimeError(f"{cmd} is not available over the coefficient field {ring.field!r}") from None


def _std_ideal(ring: Any, polys: list[Poly]) -> Ideal:
    return Ideal(ring, [normalize(p) for p in polys], is_std=True)


def _unmarked(ring: Any, polys: list[Poly]) -> Ideal:
    """A standard basis Singular's command does not mark as one (listvar shows no ``(SB)``)."""
    return Ideal(ring, [normalize(p) for p in polys], is_std=False)


def _global(I: Ideal, cmd: str) -> None:
    if not I.ring.order.is_global:
        raise MechRuntimeError(f"{cmd} needs a global ordering (dp, lp, ...), not a local one")


def _eliminate(I: Ideal, variables: list[int]) -> Ideal:
    if not I.ring.order.is_global and quotient_of(I.ring) is None:
        from ..kernel.local_elim import eliminate_local
        return _unmarked(I.ring, eliminate_local(I.nonzero(), variables, I.ring))
    _global(I, "eliminate")
    return _std_ideal(I.ring, K.eliminate(I.nonzero(), variables, ring=I.ring))


@command("eliminate")
def eliminate(I: Ideal, m: Poly) -> Ideal:
    """eliminate(I, m): the elimination ideal of I for the variables whose product is m (those of
    its leading monomial; none for a constant): I intersected with the subring of the other
    variables, as a standard basis in the basering; eliminate(I, v) with an intvec v of variable
    indices.

    Example:
      ring r = 0,(t,x,y),dp;
      ideal I = x-t2, y-t3;
      eliminate(I, t);
      → _[1]=x3-y2
    """
    return _eliminate(I, [] if m.is_constant() else [i for i, k in enumerate(m.lm()) if k])


@command("eliminate")
def eliminate_indices(I: Ideal, v: IntVec) -> Ideal:
    for i in v:
        if not 1 <= i <= I.ring.nvars:
            raise MechRuntimeError(f"eliminate: no variable {i} in a ring with {I.ring.nvars} variables")
    return _eliminate(I, sorted({i - 1 for i in v}))


@command("intersect")
def intersect(I: Ideal, *more: Ideal) -> Ideal:
    """intersect(I1, I2, ...): the intersection of the ideals, a standard basis.

    Example:
      ring r = 0,(x,y),dp;
      intersect(ideal(x), ideal(y), ideal(x+y));
      → _[1]=x2y+xy2
    """
    if not I.ring.order.is_global:
        return _std_ideal(I.ring, K.intersect_local(*[J.nonzero() for J in (I, *more)], ring=I.ring))
    return _std_ideal(I.ring, K.intersect(*[J.nonzero() for J in (I, *more)], ring=I.ring))


@command("quotient")
def quotient(I: Ideal, J: Ideal) -> Ideal:
    """quotient(I, J): the ideal quotient I : J = {f : f*J in I}, a standard basis (not marked as one,
    as in Singular).

    Example:
      ring r = 0,(x,y),dp;
      quotient(ideal(x2, xy), ideal(x));
      → _[1]=y
      → _[2]=x
    """
    if not I.ring.order.is_global and quotient_of(I.ring) is None:
        with _available("quotient", I.ring):
            return _unmarked(I.ring, K.quotient_local(I.nonzero(), J.nonzero(), ring=I.ring))
    _global(I, "quotient")
    with _available("quotient", I.ring):
        found = K.quotient(with_quotient(I.nonzero(), I.ring), J.nonzero(), ring=I.ring)
        return _unmarked(I.ring, found if quotient_of(I.ring) is None else quotient_of(I.ring).std(found))


@command("sat", lib="elim.lib")
def sat(I: Ideal, J: Ideal) -> List:
    """sat(I, J): the list of the saturation I : J^infinity (a standard basis) and the least
    exponent k with I : J^k = I : J^(k+1).

    Example:
      LIB "elim.lib";
      ring r = 0,(x,y),dp;
      sat(ideal(x2y, xy2), ideal(x));
      → [1]:
      →    _[1]=y
      → [2]:
      →    2
    """
    _global(I, "sat")
    result, k = K.saturate(I.nonzero(), J.nonzero(), ring=I.ring)
    return List([_std_ideal(I.ring, result), k])


@command("radical", lib="primdec.lib")
def radical(I: Ideal) -> Ideal:
    """radical(I): the radical of I (the intersection of its minimal associated primes).

    Example:
      LIB "primdec.lib";
      ring r = 0,(x,y),dp;
      radical(ideal(x2, xy2));
      → _[1]=x
    """
    if not I.ring.order.is_global and quotient_of(I.ring) is None:
        from ..kernel.local import radical_local
        with _available("radical", I.ring):
            return _std_ideal(I.ring, radical_local(I.nonzero(), I.ring))
    _global(I, "radical")
    with _available("radical", I.ring):
        return _std_ideal(I.ring, _primdec.radical(I.nonzero(), ring=I.ring))


@command("homog")
def homog(ctx, I: Poly | Ideal) -> int:
    """homog(I): 1 if every generator of I (or the poly) is homogeneous for the ring's variable
    weights, else 0.

    Example:
      ring r = 0,(x,y),dp;
      homog(x2+xy);
      → 1
      homog(ideal(x2+y, y2));
      → 0
    """
    result = int(_homog.is_homogeneous(I if isinstance(I, Poly) else list(I.gens)))
    if result and isinstance(I, Ideal):
        mark_homogeneous(ctx, [0])
    return result


def mark_homogeneous(ctx: Any, weights: list[int]) -> None:
    """As Singular's homog: the variable given as the argument gets the attribute isHomog (the
    components' weights)."""
    var = ctx.lookup(ctx.argnames[0]) if ctx.argnames and ctx.argnames[0] != "_" else None
    if var is not None:
        var.attributes = {**(var.attributes or {}), "isHomog": IntVec(weights)}


@command("homog")
def homogenize(I: Poly | Ideal, h: Poly) -> Any:
    """homog(I, h): I homogenized with the ring variable h (each term of a generator multiplied
    by the power of h that brings it to the generator's degree)."""
    e = h.lm() if len(h.terms) == 1 else ()
    if sum(e) != 1 or h.lc() != 1:
        raise MechRuntimeError("homog: the second argument must be a ring variable")
    if isinstance(I, Poly):
        return _homog.homogenize(I, e.index(1))
    return Ideal(I.ring, _homog.homogenize(list(I.gens), e.index(1)))


@command("qhweight")
def qhweight(I: Poly | Ideal) -> IntVec:
    """qhweight(I): weights of the variables for which every generator of I is quasi-homogeneous, as
    Singular chooses them (0 for the variables before the first one the terms constrain, a positive
    solution with the smallest sum for the others; the zero vector when there is none).

    Example:
      ring r = 0,(t,x,y,z),dp;
      qhweight(ideal(x4+y3+z2));
      → 0,3,4,6
    """
    polys = [I] if isinstance(I, Poly) else list(I.gens)
    return IntVec(qh_weights([p for p in polys if not p.is_zero()], I.ring.nvars))
