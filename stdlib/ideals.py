"""The ideal toolbox: elimination, intersections, quotients, saturation, radicals and
homogenization, with Singular's names, argument order and output (results that Singular returns
as standard bases are reduced bases normalized by :func:`~mech.stdlib.standard.normalize`)."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.values import Ideal, IntVec, List
from ..kernel import Poly
from ..kernel import homog as _homog
from ..kernel import ideals as K
from .registry import command
from .standard import normalize


def _std_ideal(ring: Any, polys: list[Poly]) -> Ideal:
    return Ideal(ring, [normalize(p) for p in polys], is_std=True)


def _global(ctx: Any, I: Ideal, cmd: str) -> None:
    if not I.ring.order.is_global:
        raise MechRuntimeError(f"{cmd} needs a global ordering (dp, lp, ...), not a local one")


def _variables(m: Poly, cmd: str) -> list[int]:
    """The variables of a product of variables (Singular's second argument of eliminate)."""
    if len(m.terms) != 1:
        raise MechRuntimeError(f"{cmd}: the second argument must be a product of variables, e.g. x*y")
    (e, _), = m.terms.items()
    out = [i for i, k in enumerate(e) if k]
    if not out:
        raise MechRuntimeError(f"{cmd}: the second argument must be a product of variables, e.g. x*y")
    return out


@command("eliminate")
def eliminate(ctx, I: Ideal, m: Poly) -> Ideal:
    """eliminate(I, m): the elimination ideal of I with respect to the variables whose product
    is m (I intersected with the subring of the other variables), a standard basis in the
    basering."""
    _global(ctx, I, "eliminate")
    return _std_ideal(I.ring, K.eliminate(I.nonzero(), _variables(m, "eliminate"), ring=I.ring))


@command("intersect")
def intersect(ctx, I: Ideal, *more: Ideal) -> Ideal:
    """intersect(I1, I2, ...): the intersection of the ideals, a standard basis."""
    _global(ctx, I, "intersect")
    return _std_ideal(I.ring, K.intersect(*[J.nonzero() for J in (I, *more)], ring=I.ring))


@command("quotient")
def quotient(ctx, I: Ideal, J: Ideal) -> Ideal:
    """quotient(I, J): the ideal quotient I : J = {f : f*J in I}, a standard basis."""
    _global(ctx, I, "quotient")
    return _std_ideal(I.ring, K.quotient(I.nonzero(), J.nonzero(), ring=I.ring))


@command("sat", lib="elim.lib")
def sat(ctx, I: Ideal, J: Ideal) -> List:
    """sat(I, J): the list of the saturation I : J^infinity (a standard basis) and the least
    exponent k with I : J^k = I : J^(k+1)."""
    _global(ctx, I, "sat")
    result, k = K.saturate(I.nonzero(), J.nonzero(), ring=I.ring)
    return List([_std_ideal(I.ring, result), k])


@command("radical", lib="primdec.lib")
def radical(ctx, I: Ideal) -> Ideal:
    """radical(I): the radical of I (the intersection of its minimal associated primes)."""
    _global(ctx, I, "radical")
    return _std_ideal(I.ring, K.radical(I.nonzero(), ring=I.ring))


@command("homog")
def homog(I: Poly | Ideal) -> int:
    """homog(I): 1 if every generator of I (or the poly) is homogeneous for the ring's variable
    weights, else 0."""
    return int(_homog.is_homogeneous(I if isinstance(I, Poly) else list(I.gens)))


@command("homog")
def homogenize(I: Poly | Ideal, h: Poly) -> Any:
    """homog(I, h): I homogenized with the ring variable h (each term of a generator multiplied
    by the power of h that brings it to the generator's degree)."""
    i = _variables(h, "homog")
    if len(i) != 1 or h.lm()[i[0]] != 1:
        raise MechRuntimeError("homog: the second argument must be a ring variable")
    if isinstance(I, Poly):
        return _homog.homogenize(I, i[0])
    return Ideal(I.ring, _homog.homogenize(list(I.gens), i[0]))


@command("factorize")
def factorize(f: Poly, how: int = 0) -> Any:
    """factorize(f[, n]): the irreducible factors of f over QQ or Z/p: the list of the ideal of the
    factors (the unit first) and the intvec of their multiplicities; n = 1: the ideal of the
    distinct factors only, n = 2: the list without the unit."""
    from ..kernel.factor import factorize as _factorize
    ring = f.ring
    if how not in (0, 1, 2):
        raise MechRuntimeError(f"factorize(f, {how}): the second argument must be 0, 1 or 2")
    try:
        unit, factors = _factorize(f)
    except NotImplementedError:
        raise MechRuntimeError("factorize is available over QQ and Z/p only") from None
    if how == 1:
        return Ideal(ring, [g for g, _ in factors] or [ring.one()])
    if how == 2:
        return List([Ideal(ring, [g for g, _ in factors] or [ring.one()]),
                     IntVec([m for _, m in factors] or [1])])
    return List([Ideal(ring, [ring.const(unit)] + [g for g, _ in factors]),
                 IntVec([1] + [m for _, m in factors])])
