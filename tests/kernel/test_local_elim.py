"""Elimination in local orderings (kernel/local_elim.py): Singular's Manual/Elimination example
(two transversal cusps) by hand, and a mixed case."""
from tests.util import parse_poly

from mech.kernel import QQ, Block, MonomialOrder, PolyRing
from mech.kernel.local_elim import eliminate_local


def ring(kind, names):
    return PolyRing(QQ, list(names), MonomialOrder([Block(kind, len(names))]))


def _strs(polys):
    return sorted(p.monic().to_str() for p in polys)


def test_cusp_parametrization_in_ls():
    R = ring("ls", "txyz")
    # x = t^2, y = t^3, z = 0: the cusp y^2 = x^3 in the plane z = 0
    i1 = [parse_poly(R, p) for p in ("x-t^2", "y-t^3", "z")]
    assert _strs(eliminate_local(i1, [0], R)) == ["y^2-x^3", "z"]
    i2 = [parse_poly(R, p) for p in ("y-t^2", "z-t^3", "x")]
    assert _strs(eliminate_local(i2, [0], R)) == ["x", "z^2-y^3"]


def test_a_unit_factor_in_the_local_ring():
    R = ring("ds", "txy")
    # (1+x) t - y and t - x: t = x, so (1+x) x - y, i.e. y - x - x^2 (a unit does not matter)
    got = eliminate_local([parse_poly(R, "(1+x)*t-y"), parse_poly(R, "t-x")], [0], R)
    assert len(got) == 1 and got[0].monic() == parse_poly(R, "x+x^2-y").monic()
