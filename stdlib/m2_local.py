"""The LocalRings package in the Macaulay2 dialect: ``localRing(R, P)`` (also ``R_P``),
``promote``, ``liftUp``, ``isWellDefined``, ``frac`` (the residue field of ``R.residueMap``), ``length(R_P^1/I)``, and which commands are right on
ideals of a local ring (marked by :func:`~mech.dsl.m2_local.in_local_rings` where they are defined;
values and arithmetic: :mod:`mech.dsl.m2_local`)."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError, MechTypeError
from ..dsl.m2_local import LocalFraction, in_local_rings, local_ring, localized_at, to_global, to_local
from ..dsl.m2_modules import CyclicModule, FreeModule
from ..dsl.m2_rings import FractionField, M2Ring, exact_over_zz, fraction_field, in_quotients, integers, normal
from ..dsl.registry import command
from ..dsl.values import Ideal, List, Matrix
from ..kernel import Poly


@command("localRing", dialect="m2")
@in_local_rings
def local_ring_cmd(R: M2Ring, P: Ideal) -> M2Ring:
    """localRing(R, P): the localization of the polynomial ring R at the prime ideal P (as R_P)."""
    return local_ring(R, P)


def _move(v: Any, ring: Any, to: Any) -> Any:
    if isinstance(v, Poly):
        return to(v, ring)
    if isinstance(v, Ideal):
        return Ideal(ring.poly, [to(g, ring) for g in v.gens])
    if isinstance(v, Matrix):
        return Matrix(ring.poly, v.nrows, v.ncols, [to(g, ring) for g in v.entries])
    if isinstance(v, List):
        return List([_move(x, ring, to) for x in v.items])
    raise MechTypeError("expected a polynomial, ideal, matrix or list")


@command("frac", dialect="m2")
@in_local_rings
@in_quotients
def frac(R: M2Ring) -> FractionField:
    """frac R: the fraction field of a domain R (of R/P for a prime P, of R for a local ring R_P),
    as a name and a ring map's target: mech does not compute in it."""
    if localized_at(R) is not None:
        R = R.info["over"]
    if R.coeffs.characteristic is None:
        raise MechRuntimeError("frac of a ring over ZZ is not supported by mech")
    if R.quotient is not None:
        from ..kernel.primdec import is_prime
        if not is_prime(list(R.quotient.basis), R.ambient().poly):
            raise MechRuntimeError("frac R: R is not a domain")
    return fraction_field(R)


@command("promote", dialect="m2")
@in_local_rings
@exact_over_zz
def promote(v: Any, S: M2Ring) -> Any:
    """promote(I, R_P): an element, ideal or matrix of R in its local ring R_P."""
    P = localized_at(S)
    if P is None and isinstance(v, (Ideal, Matrix)) and getattr(v.ring, "owner", None) is integers():
        return _from_integers(v, S)  # integers of ZZ as elements of S
    if P is None:
        raise MechRuntimeError("promote(x, S) is supported for a local ring S = R_P (or integers of ZZ)")
    if getattr(v, "ring", None) not in (S.info["over"].poly, S.poly) and not isinstance(v, List):
        raise MechTypeError("promote(x, R_P) takes an element, ideal or matrix of R")
    return _move(v, S, lambda p, ring: to_local(p, ring))


def _from_integers(v: Any, S: M2Ring) -> Any:
    one = S.poly.one()
    out = [normal(one * int(p.lc().p)) if not p.is_zero() else S.poly.zero()
           for p in (v.nonzero() if isinstance(v, Ideal) else v.entries)]
    return Ideal(S.poly, out, is_std=not out) if isinstance(v, Ideal) else Matrix(S.poly, v.nrows, v.ncols, out)


@command("liftUp", dialect="m2")
@in_local_rings
def lift_up(v: Any) -> Any:
    """liftUp I: an ideal, element or matrix of R_P with the same generators in R (fractions refused)."""
    ring = getattr(v, "ring", None)
    S = getattr(ring, "owner", None)
    if S is None or localized_at(S) is None:
        raise MechRuntimeError("liftUp takes an element, ideal or matrix of a local ring")
    return _move(v, S.info["over"], lambda p, R: Poly(R.poly, dict(p.terms)))


@command("ring", dialect="m2")
@in_local_rings
def ring_of_fraction(f: LocalFraction) -> M2Ring:
    """ring f: the local ring of a fraction."""
    return f.num.ring.owner


@command("ring", dialect="m2")
@in_local_rings
@in_quotients
def ring_of_module(M: CyclicModule | FreeModule) -> M2Ring:
    """ring M: the ring of the module R^1/I (or R^n)."""
    return M.ring.owner if isinstance(M, CyclicModule) else M.ring


@command("numerator", dialect="m2")
@in_local_rings
@exact_over_zz
def numerator(f: LocalFraction | Poly) -> Poly:
    """numerator f: the numerator of an element of a local ring (in lowest terms)."""
    return f.num if isinstance(f, LocalFraction) else f


@command("denominator", dialect="m2")
@in_local_rings
@exact_over_zz
def denominator(f: LocalFraction | Poly) -> Poly:
    """denominator f: the denominator of an element of a local ring (in lowest terms)."""
    return f.den if isinstance(f, LocalFraction) else f.ring.one()


@command("isWellDefined", dialect="m2")
@in_local_rings
def is_well_defined(S: M2Ring) -> bool:
    """isWellDefined R_P: whether P is a prime ideal."""
    P = localized_at(S)
    if P is None:
        raise MechRuntimeError("isWellDefined is supported for local rings R_P")
    from ..kernel.primdec import is_prime
    return is_prime(list(P.nonzero()), S.info["over"].poly)


@command("length", dialect="m2")
@in_local_rings
def length(M: CyclicModule) -> int:
    """length(R_P^1/I): the length of R_P/I (finite when P is a minimal prime of I)."""
    S = M.ring.owner
    P = localized_at(S)
    if P is None:
        raise MechRuntimeError("length of a module is supported over local rings R_P")
    from ..kernel.errors import NotSupported
    from ..kernel.localization import local_length
    try:
        return local_length([to_global(g, S) for g in M.ideal.nonzero()], list(P.nonzero()), S.info["over"].poly)
    except NotSupported as e:
        raise MechRuntimeError(str(e)) from None


def _locally_in(f: Poly, gens: list[Poly], P: list[Poly], ring: Any) -> bool:
    """Whether f lies in the ideal of R_P generated by gens: some element of (gens : f) is outside P."""
    from ..kernel import ideals as K
    from ..kernel.groebner import groebner, normal_form
    if not gens:
        return f.is_zero()
    basis = groebner(P, ring)
    return any(not normal_form(q, basis).is_zero() for q in K.quotient(gens, [f], ring=ring))


def local_mingens(I: Ideal) -> list[Poly]:
    """A minimal generating set of the ideal I of a local ring R_P among I's generators: each one
    dropped when it lies in the ideal of the others kept or not yet seen plus P I (then the others
    generate I R_P, by Nakayama's lemma)."""
    S = I.ring.owner
    ring, P = S.info["over"].poly, list(localized_at(S).nonzero())
    gens = [to_global(g, S) for g in I.nonzero()]
    PI = [p * g for p in P for g in gens]
    kept: list[Poly] = []
    for i, g in enumerate(gens):
        if not _locally_in(g, kept + gens[i + 1:] + PI, P, ring):
            kept.append(g)
    return [to_local(g, S) for g in kept]


@command("hilbertSamuelFunction", dialect="m2")
@in_local_rings
def hilbert_samuel_function(*args: Any) -> Any:
    """hilbertSamuelFunction([q,] M, n) (or n0, n1 for the list of values): the length of
    q^n M / q^(n+1) M for M = R_P^1/I (or R_P^1), q an ideal primary to P (default P)."""
    q = args[0] if args and isinstance(args[0], Ideal) else None
    rest = args[1:] if q is not None else args
    if len(rest) not in (2, 3) or not all(type(n) is int for n in rest[1:]):
        raise MechTypeError("hilbertSamuelFunction([q,] M, n) or ([q,] M, n0, n1)")
    M = rest[0]
    if isinstance(M, FreeModule) and M.rank == 1:
        M = CyclicModule(Ideal(M.ring.poly, []))
    if not isinstance(M, CyclicModule) or localized_at(M.ring.owner) is None:
        raise MechRuntimeError("hilbertSamuelFunction is supported for R_P^1/I over a local ring R_P")
    S = M.ring.owner
    ring, P = S.info["over"].poly, localized_at(S)
    base = [to_global(g, S) for g in M.ideal.nonzero()]
    qs = [to_global(g, S) if g.ring is not ring else g for g in (q.nonzero() if q is not None else P.nonzero())]
    from ..kernel import ideals as K
    from ..kernel.errors import NotSupported
    from ..kernel.localization import local_length
    lengths: dict[int, int] = {}

    def colength(k: int) -> int:  # length of M / q^k M
        if k <= 0:
            return 0
        if k not in lengths:
            try:
                lengths[k] = local_length(base + K.ideal_power(qs, k, ring=ring), list(P.nonzero()), ring)
            except NotSupported as e:
                raise MechRuntimeError(str(e)) from None
        return lengths[k]

    def h(n: int) -> int:
        return colength(n + 1) - colength(n) if n >= 0 else 0
    if len(rest) == 2:
        return h(rest[1])
    return List([h(n) for n in range(rest[1], rest[2] + 1)])
