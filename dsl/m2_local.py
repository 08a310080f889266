"""Macaulay2's local rings (the LocalRings package): ``localRing(R, P)``, ``R_P`` for a prime
ideal P of a polynomial ring R, and their elements.

A local ring is an :class:`~mech.dsl.m2_rings.M2Ring` on a kernel ring of its own with R's
variables and order; ``info["localized_at"]`` holds P (an ideal of R) and ``info["over"]`` R.
Its polynomials are the elements with denominator 1; ``f / g`` for ``g`` outside P is a
:class:`LocalFraction`.  An ideal of ``R_P`` is kept by numerators (denominators are units);
equality and containment go through contractions to R (:mod:`mech.kernel.localization`).
Commands not marked :func:`in_local_rings` refuse elements of local rings."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..kernel import Poly
from ..kernel.factor import divide_exact, gcd
from ..kernel.localization import is_local_unit
from .errors import MechRuntimeError, MechTypeError
from .m2_rings import FlatRing, M2Ring
from .values import Ideal, Number


def in_local_rings(fn: Any) -> Any:
    """Mark a command of the dialect as correct on elements of local rings."""
    fn.local_ok = True
    return fn


def localized_at(ring: Any) -> Any:
    """P for a local ring R_P (None for other rings)."""
    owner = getattr(ring, "owner", ring)
    info = getattr(owner, "info", None)
    return info.get("localized_at") if isinstance(info, dict) else None


def local_ring(R: M2Ring, P: Ideal) -> M2Ring:
    """``localRing(R, P)`` (the same ring again for the same R and P, as Macaulay2 caches it)."""
    if not isinstance(R, M2Ring) or R.quotient is not None or isinstance(R.base, M2Ring) \
            or localized_at(R) is not None or R.info.get("local") is not None:
        raise MechRuntimeError("localRing(R, P) takes a polynomial ring R over QQ or ZZ/p")
    if P.ring is not R.poly:
        raise MechTypeError("localRing(R, P): P is an ideal of R")
    cache = R.info.setdefault("localizations", {})
    key = tuple(P.gens)
    if key in cache:
        return cache[key]
    old = R.poly
    flat = FlatRing(old.field, old.names, old.order)
    S = M2Ring(flat, (), R.blocks, coeffs=R.coeffs, base=R.base, own=R.own, degrees=R.degrees,
               max_exponent=R.max_exponent, info={"localized_at": P, "over": R})
    flat.owner = S
    cache[key] = S
    return S


def to_local(p: Poly, S: M2Ring) -> Poly:
    """An element of R (or of R_P) as an element of ``S = R_P``."""
    return Poly(S.poly, dict(p.terms))


def to_global(p: Poly, S: M2Ring) -> Poly:
    """A polynomial of ``S = R_P`` as an element of R."""
    return Poly(S.info["over"].poly, dict(p.terms))


@dataclass(frozen=True, eq=False)
class LocalFraction:
    """``num / den`` in a local ring ``R_P`` (``den`` outside P, the fraction in lowest terms)."""
    num: Poly
    den: Poly

    @property
    def ring(self) -> Any:
        return self.num.ring

    @staticmethod
    def make(num: Poly, den: Poly) -> "LocalFraction | Poly":
        S = num.ring.owner
        P = localized_at(S)
        if den.is_zero():
            raise MechRuntimeError("division by 0")
        if not is_local_unit(to_global(den, S), list(P.nonzero()), S.info["over"].poly):
            raise MechRuntimeError("division by an element of the maximal ideal of a local ring")
        g = gcd(num, den) if not num.is_zero() else den
        num, den = divide_exact(num, g), divide_exact(den, g)
        lc = den.lc()
        num, den = num / lc, den / lc
        if den.is_constant():
            return num / den.lc()
        return LocalFraction(num, den)

    def __eq__(self, other: object) -> bool:
        n, d = parts(other) if isinstance(other, (Poly, LocalFraction)) else (None, None)
        return n is not None and self.num * d == n * self.den

    def __hash__(self) -> int:
        return hash(id(self))


def parts(v: Any) -> tuple[Poly, Poly]:
    """(numerator, denominator) of a local ring's element."""
    if isinstance(v, LocalFraction):
        return v.num, v.den
    return v, v.ring.one()


def local_arith(op: str, a: Any, b: Any, S: M2Ring) -> Any:
    """``a op b`` for elements of a local ring S (polynomials, numbers, fractions)."""
    def lift(v: Any) -> tuple[Poly, Poly]:
        if type(v) is int:
            return S.poly.const(S.poly.field(v)), S.poly.one()
        if isinstance(v, Number):
            return S.poly.const(v.c), S.poly.one()
        if isinstance(v, Poly) and v.ring is not S.poly:
            v = to_local(v, S)
        if isinstance(v, (Poly, LocalFraction)):
            return parts(v)
        raise MechTypeError(f"no operator {op} for an element of a local ring and this value")
    (p, q) = lift(a)
    if op == "^":
        if type(b) is not int:
            raise MechTypeError("an exponent is an integer")
        return LocalFraction.make(p ** b, q ** b) if b >= 0 else LocalFraction.make(q ** -b, p ** -b)
    (r, s) = lift(b)
    if op == "+":
        return LocalFraction.make(p * s + r * q, q * s)
    if op == "-":
        return LocalFraction.make(p * s - r * q, q * s)
    if op == "*":
        return LocalFraction.make(p * r, q * s)
    if op == "/":
        return LocalFraction.make(p * s, q * r)
    if op in ("==", "!="):
        return (p * s == r * q) == (op == "==")
    raise MechTypeError(f"no operator {op} on elements of a local ring")


def _global_gens(I: Ideal) -> list[Poly]:
    S = I.ring.owner
    return [to_global(g, S) for g in I.nonzero()]


def _prime(I: Ideal) -> list[Poly]:
    return list(localized_at(I.ring).nonzero())


def local_ideals_equal(I: Ideal, J: Ideal) -> bool:
    """``I == J`` for ideals of a local ring R_P."""
    from ..kernel.localization import local_equal
    return local_equal(_global_gens(I), _global_gens(J), _prime(I), I.ring.owner.info["over"].poly)


def local_ideal_subset(I: Ideal, J: Ideal) -> bool:
    """``isSubset(I, J)`` for ideals of a local ring R_P."""
    from ..kernel.localization import local_subset
    return local_subset(_global_gens(I), _global_gens(J), _prime(I), I.ring.owner.info["over"].poly)


def local_ideal_is_unit(I: Ideal) -> bool:
    """``I == 1`` in a local ring R_P."""
    from ..kernel.localization import contraction
    c = contraction(_global_gens(I), _prime(I), I.ring.owner.info["over"].poly)
    return any(p.is_constant() and not p.is_zero() for p in c)
