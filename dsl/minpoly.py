"""Singular's ``minpoly``: ``ring r = (0,a),(x,y),dp; minpoly = a2+1;`` makes the coefficients of
the basering the algebraic extension QQ[a]/(a^2+1) (:mod:`mech.kernel.algext`).

As in Singular, the assignment changes the basering in place: the ring keeps its name, ordering and
variables, and the ring-dependent objects declared in it before (their coefficients were in the
transcendental field) are killed.  Reading ``minpoly`` gives the minimal polynomial as a number
(``(a2+1)``), 0 in a ring without one."""
from __future__ import annotations

from fractions import Fraction
from typing import Any

from ..kernel import Poly, PolyRing
from ..kernel.algext import AlgebraicField
from ..kernel.ratfunc import RationalFunctionField
from .errors import MechRuntimeError
from .qrings import quotient_of
from .values import Number, Ring

_rings: dict[tuple, PolyRing] = {}


def extended(poly: PolyRing, m: Any) -> PolyRing:
    """``poly`` with its coefficients extended by the minimal polynomial ``m`` (a coefficient);
    equal data share one kernel ring, so their values mix."""
    field = AlgebraicField.over(poly.field, m)
    key = (field, poly.names, poly.order)
    hit = _rings.get(key)
    if hit is None:
        hit = _rings[key] = PolyRing(field, poly.names, poly.order)
    return hit


def set_minpoly(interp: Any, value: Any) -> None:
    """``minpoly = value;`` in the basering of the interpreter ``interp``."""
    ring: Ring | None = interp.ring
    if ring is None:
        raise MechRuntimeError("minpoly: no ring active")
    field = ring.poly.field
    if isinstance(value, Number):
        c = value.c
    elif isinstance(value, Poly) and value.is_constant():
        c = value.lc() if not value.is_zero() else field.zero
    elif isinstance(value, int) and not isinstance(value, bool):
        c = value
    else:
        raise MechRuntimeError("minpoly must be a number: a polynomial in the parameter")
    if c == 0:
        return
    if isinstance(field, AlgebraicField):
        raise MechRuntimeError("the ring already has a minimal polynomial")
    if not isinstance(field, RationalFunctionField):
        raise MechRuntimeError("minpoly needs a ring with a parameter, e.g. ring r = (0,a),(x,y),dp;")
    if len(field.params) != 1:
        raise MechRuntimeError("only a minimal polynomial in one parameter is allowed "
                               "(the ring has several parameters)")
    if quotient_of(ring.poly) is not None:
        raise MechRuntimeError("minpoly: set it before declaring a qring")
    new = extended(ring.poly, field(c))
    ring.poly = new
    ring.objects.clear()
    for frame in interp.frames:
        frame.ring_vars.pop(ring, None)


def get_minpoly(ring: Ring) -> Any:
    """What ``minpoly`` reads: the minimal polynomial as a number, 0 without one."""
    field = ring.poly.field
    if not isinstance(field, AlgebraicField):
        return Number(ring.poly, field.zero)
    transcendental = RationalFunctionField(field.characteristic, field.params)
    poly = PolyRing(transcendental, ring.poly.names, ring.poly.order)
    num = transcendental.ctx.from_dict({(e,): int(c) for e, c in enumerate(field.modulus.numer().coeffs()) if int(c)}) \
        if field.characteristic == 0 else \
        transcendental.ctx.from_dict({(e,): int(c) for e, c in enumerate(field.modulus.coeffs()) if int(c)})
    return Number(poly, transcendental.from_polys(num))


def compare_params(op: str, x: Any, y: Any) -> int:
    """``x op y`` for ``< <= > >=`` of numbers with parameters, as Singular orders them: in QQ[a]/(m) and
    Z/p[a]/(m) by degree in ``a``, then by leading coefficient (0 is above the numbers whose leading
    coefficient is negative); with transcendental parameters by the degree of numerator minus denominator,
    then by the quotient of their leading coefficients (terms by degree, then lexicographically)."""
    field = x.field
    if not isinstance(field, AlgebraicField):
        if not (x.is_constant() and y.is_constant()):
            if op in ("<", "<="):
                x, y = y, x
            return int(_greater_rational(x, y) or (op in ("<=", ">=") and x == y))
        if field.characteristic:
            p = field.characteristic
            x, y = field.to_fraction(x) % p, field.to_fraction(y) % p
        else:
            x, y = field.to_fraction(x), field.to_fraction(y)
        return int({"<": x < y, "<=": x <= y, ">": x > y, ">=": x >= y}[op])
    if op in ("<", "<="):
        x, y = y, x
    return int(_greater(x, y) or (op in ("<=", ">=") and x == y))


def _greater_rational(x: Any, y: Any) -> bool:
    """x > y in Singular's order of QQ(a,..) and Z/p(a,..) (x, y not both constants)."""
    def key(c: Any) -> tuple[int, Fraction]:
        (dn, cn), (dd, cd) = _lead_term(c.num), _lead_term(c.den)
        p = c.field.characteristic
        return dn - dd, (Fraction(cn % p * pow(cd, -1, p) % p) if p else Fraction(cn, cd))
    if not x:
        return y.field.characteristic == 0 and key(y)[1] < 0
    if not y:
        return x.field.characteristic != 0 or key(x)[1] > 0
    return key(x) > key(y)


def _lead_term(p: Any) -> tuple[int, int]:
    """Total degree and coefficient of the leading term of a flint polynomial (by degree, then lex)."""
    exp, c = max(zip(p.monoms(), p.coeffs()), key=lambda t: (sum(t[0]), t[0]))
    return sum(exp), int(c)


def _greater(x: Any, y: Any) -> bool:
    def lead(c: Any) -> Any:
        v = c.u.coeffs()[-1]
        return int(v) if c.field.characteristic else v
    if not x:
        return bool(y) and not lead(y) > 0
    if not y:
        return lead(x) > 0
    dx, dy = x.u.degree(), y.u.degree()
    return dx > dy if dx != dy else lead(x) > lead(y)
