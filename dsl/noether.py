"""Singular's ``noether`` (a highest corner declared by the user, per ring): ``noether = x11;``
in the basering, read back as a polynomial (0 when unset).  std and reduce of the ring then drop
the terms below it (:mod:`mech.kernel.local_noether`); global orderings ignore it, as Singular does."""
from __future__ import annotations

from typing import Any, Optional

from ..kernel import Poly, PolyRing
from ..kernel.local_noether import supports_noether
from .errors import MechRuntimeError
from .values import Number

_NOETHER: dict[int, tuple[PolyRing, Poly]] = {}


def set_noether(ring: Any, value: Any) -> None:
    """``noether = value;`` in the basering ``ring`` (a dsl Ring; 0 unsets)."""
    if ring is None:
        raise MechRuntimeError("noether: no ring active")
    poly = ring.poly
    if isinstance(value, Number) or isinstance(value, int):
        if (value.c if isinstance(value, Number) else value) != 0:
            raise MechRuntimeError("noether must be a monomial")
        _NOETHER.pop(id(poly), None)
        return
    if not isinstance(value, Poly):
        raise MechRuntimeError("noether must be a monomial")
    if value.is_zero():
        _NOETHER.pop(id(poly), None)
        return
    if not poly.order.is_global and not supports_noether(poly):
        raise MechRuntimeError("noether other than 0 is supported for local degree orderings (ds, Ds, ws, Ws)")
    _NOETHER[id(poly)] = (poly, Poly(poly, {value.lm(): poly.field.one}))


def noether_poly(ring: PolyRing) -> Optional[Poly]:
    """The ring's ``noether`` monomial (None when unset)."""
    hit = _NOETHER.get(id(ring))
    return hit[1] if hit is not None and hit[0] is ring else None


def active_noether(ring: PolyRing) -> Optional[tuple]:
    """The exponent of ``noether`` when it applies (set, and the ordering not global)."""
    p = noether_poly(ring)
    return None if p is None or ring.order.is_global else p.lm()
