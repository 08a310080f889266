"""Singular's quotient rings: ``qring Q = I;`` (I a standard basis of the basering) declares the ring
R/I and makes it the basering.  Its polynomials stay polynomials of R (Singular reduces them only
when asked: ``reduce``, ``NF``); standard bases, dimensions, normal forms and quotients of ideals are
taken modulo I (:class:`mech.kernel.quotient.Quotient`).

A qring has its own kernel ring (equal to R's as a ring of polynomials); :func:`quotient_of` finds its
quotient from it, so the commands that must know (std, reduce, dim, vdim, kbase...) ask with the
ring of their argument."""
from __future__ import annotations

from typing import Any, Optional, Sequence

from ..kernel import Poly, PolyRing
from ..kernel.quotient import Quotient
from .errors import MechRuntimeError, MechTypeError
from .values import Ideal, Ring

_QUOTIENTS: dict[int, tuple[PolyRing, Quotient, list[Poly]]] = {}


def quotient_of(ring: PolyRing) -> Optional[Quotient]:
    """The quotient a qring's kernel ring stands for (None for a polynomial ring)."""
    hit = _QUOTIENTS.get(id(ring))
    return hit[1] if hit is not None and hit[0] is ring else None


def with_quotient(polys: Sequence[Poly], ring: PolyRing) -> list[Poly]:
    """``polys`` and, in a qring, the standard basis of its ideal (generators of I + Q)."""
    q = quotient_of(ring)
    out = list(polys)
    if q is not None:
        out += [Poly(ring, g.terms) for g in q.basis]
    return out


def make_qring(base: Ring, ideal: Any) -> Ring:
    """The qring ``base / ideal`` (a standard basis of the ideal in ``base``; in a qring the ideal is
    taken together with its ideal, as Singular does)."""
    if isinstance(ideal, Poly):
        ideal = Ideal(ideal.ring, [ideal])
    if not isinstance(ideal, Ideal):
        raise MechTypeError("qring Q = I; needs an ideal I of the basering")
    old = base.poly
    gens = with_quotient(ideal.nonzero(), old)
    ring = PolyRing(old.field, old.names, old.order)
    q = Quotient.of([Poly(ring, g.terms) for g in gens], ring)
    if q.is_zero_ring:
        raise MechRuntimeError("qring: the ideal is the whole ring (the quotient is the zero ring)")
    _QUOTIENTS[id(ring)] = (ring, q, [Poly(ring, g.terms) for g in gens])
    from .values_modules import note_blocks
    note_blocks(ring, base.blocks)
    return Ring(ring, base.params, base.blocks)


def quotient_ideal(ring: PolyRing) -> Optional[list[Poly]]:
    """The generators a qring was declared with (None for a polynomial ring)."""
    hit = _QUOTIENTS.get(id(ring))
    return hit[2] if hit is not None and hit[0] is ring else None
