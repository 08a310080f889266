"""Quotient rings (mech.kernel.quotient) against Singular 4.3.1's qring (outputs of real runs)."""
from __future__ import annotations

import pytest

from mech.kernel import QQ, Block, MonomialOrder, PolyRing
from mech.kernel.errors import DomainError
from mech.kernel.quotient import Quotient
from tests.util import parse_poly


def ring(order: str = "dp", names=("x", "y", "z")) -> PolyRing:
    return PolyRing(QQ, list(names), MonomialOrder([Block(order, len(names))]))


def polys(R, *texts):
    return [parse_poly(R, t) for t in texts]


def test_twisted_cubic_quotient_as_singular():
    # ring r=0,(x,y,z),dp; qring q = std(ideal(x2-y, xy-z));
    R = ring()
    q = Quotient.of(polys(R, "x^2-y", "x*y-z"), R)
    assert q.std(polys(R, "x^3", "y^2+z")) == polys(R, "z")          # std(I): _[1]=z
    assert q.dimension(polys(R, "x^3", "y^2+z")) == 0                # dim(std(I)): 0
    assert q.reduce(parse_poly(R, "x^4+y")) == parse_poly(R, "x*z+y")  # reduce(x4+y, std(0))
    assert q.std(polys(R, "x^3-z")) == []                            # std(J): _[1]=0
    assert q.dimension() == 1 and q.is_zero(parse_poly(R, "x^3-z"))
    assert q.contains(polys(R, "x"), parse_poly(R, "y")) and not q.contains(polys(R, "y"), parse_poly(R, "x"))


def test_local_quotient_as_singular():
    # ring s=0,(x,y),ds; qring qs = std(ideal(x2-y3)); std(ideal(x3,y)); -> _[1]=y
    R = ring("ds", ("x", "y"))
    q = Quotient.of(polys(R, "x^2-y^3"), R)
    assert q.std(polys(R, "x^3", "y")) == polys(R, "y")
    assert q.dimension() == 1


def test_zero_ring_and_foreign_ideals():
    R, S = ring(), ring("lp")
    assert Quotient.of(polys(R, "x", "x-1"), R).is_zero_ring and Quotient.of(polys(R, "x", "x-1"), R).dimension() == -1
    with pytest.raises(DomainError):
        Quotient.of(polys(S, "x"), R)
