"""Elimination (kernel/local_elim.py) and radicals (kernel/local.py) in local orderings, by hand:
Singular's Manual/Elimination example (two transversal cusps), a unit factor, components away
from the origin."""
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


def test_radical_in_the_local_ring():
    # by hand: the components through the origin of V(x^2(x-1), y^3-x^2y, z(z-1)^2) are the
    # origin alone (x = 0 forces y = 0; z = 0), so the local radical is the maximal ideal; the
    # global radical's generators x(x-1), y(x-1), z(z-1) are x, y, z times units
    from mech.kernel.local import radical_local
    R = ring("ds", "xyz")
    got = radical_local([parse_poly(R, p) for p in ("x^2*(x-1)", "y^3-x^2*y", "z*(z-1)^2")], R)
    assert sorted(g.lm() for g in got) == [(0, 0, 1), (0, 1, 0), (1, 0, 0)]
    S = ring("ds", "xy")
    got = radical_local([parse_poly(S, "x^2*y"), parse_poly(S, "(y-1)^2*x^3")], S)
    assert [g.lm() for g in got] == [(1, 0)]  # (xy, x(y-1)) = (x)
