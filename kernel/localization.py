"""Localization of a polynomial ring at a prime ideal P: ideals of ``R_P`` through their
contractions to ``R``.

For an ideal I of R, ``I R_P ∩ R`` is the intersection of the primary components of I whose
primes lie in P (Atiyah–Macdonald, Prop. 4.9), so two ideals are equal in ``R_P`` exactly when
their contractions are, and ``I R_P`` is the unit ideal when no associated prime of I lies in P.
Sums, products, intersections, quotients and saturations commute with localization, so they are
computed in R.  The length of ``R_P / I R_P`` comes from the P-primary component Q of I (0 when P is not
associated to I): ``dim_K R/Q / dim_K R/P`` for a maximal P, ``deg Q / deg P`` otherwise."""
from __future__ import annotations

from typing import Sequence

from .errors import NotSupported
from .groebner import groebner, normal_form
from .hilbert import mult, vdim
from .ideals import dimension, dp_ring, intersect, move
from .poly import Poly, PolyRing
from .primdec import is_prime, primdec_gtz


def _inside(polys: Sequence[Poly], basis: Sequence[Poly]) -> bool:
    return all(normal_form(p, basis).is_zero() for p in polys)


def contraction(ideal: Sequence[Poly], prime: Sequence[Poly], ring: PolyRing) -> list[Poly]:
    """A Gröbner basis of ``I R_P ∩ R`` (``[1]`` when ``I R_P`` is the unit ideal)."""
    gens = [p for p in ideal if not p.is_zero()]
    if not gens:
        return []
    P = groebner(list(prime), ring)
    keep = [q for q, p in primdec_gtz(gens, ring) if _inside(p, P)]
    if not keep:
        return [ring.one()]
    return groebner(intersect(*keep, ring=ring) if len(keep) > 1 else list(keep[0]), ring)


def local_equal(a: Sequence[Poly], b: Sequence[Poly], prime: Sequence[Poly], ring: PolyRing) -> bool:
    """Whether ``a R_P == b R_P``."""
    return contraction(a, prime, ring) == contraction(b, prime, ring)


def local_subset(a: Sequence[Poly], b: Sequence[Poly], prime: Sequence[Poly], ring: PolyRing) -> bool:
    """Whether ``a R_P`` lies in ``b R_P``."""
    return _inside([p for p in a if not p.is_zero()], contraction(b, prime, ring))


def is_local_unit(f: Poly, prime: Sequence[Poly], ring: PolyRing) -> bool:
    """Whether ``f`` is a unit of ``R_P`` (not in P)."""
    return not normal_form(f, groebner(list(prime), ring)).is_zero()


def local_length(ideal: Sequence[Poly], prime: Sequence[Poly], ring: PolyRing) -> int:
    """The length of ``R_P / I R_P`` for a prime P: for the P-primary contraction Q of I (P minimal
    over it; otherwise the length is infinite), ``dim_K R/Q / dim_K R/P`` when P is maximal, else
    ``deg Q / deg P`` (degrees of the projective closures, by the associativity formula for
    multiplicities: Q's closure is primary to P's, with the same length at its generic point)."""
    P = groebner(list(prime), ring)
    if not is_prime(P, ring):
        raise NotSupported("the length of R_P/I needs a prime ideal P")
    local = contraction(ideal, P, ring)
    if any(p.is_constant() and not p.is_zero() for p in local):
        return 0
    residue = vdim([p.lm() for p in P], ring.nvars)
    if residue > 0:
        n = vdim([p.lm() for p in local], ring.nvars)
        if n < 0:
            raise NotSupported("R_P/I has infinite length")
        return n // residue
    if dimension(local, ring) != dimension(P, ring):
        raise NotSupported("R_P/I has infinite length (P is not a minimal prime of I)")
    dp = dp_ring(ring)
    e_local, e_prime = (mult([p.lm() for p in groebner(move(G, dp), dp)], ring.nvars) for G in (local, P))
    return e_local // e_prime
