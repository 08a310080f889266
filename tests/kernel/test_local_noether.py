"""Singular's noether (kernel/local_noether.py): the monomials below the declared corner and the
truncated standard bases, by hand (Singular 4.3.1 prints the same for these ideals)."""
import pytest
from tests.util import parse_poly

from mech.kernel import GF, Block, MonomialOrder, PolyRing
from mech.kernel.engines import standard_basis
from mech.kernel.errors import NotSupported
from mech.kernel.local_noether import below, noether_basis, truncate


def ring(kind="ds", names=("x", "y", "z")):
    return PolyRing(GF(32003), list(names), MonomialOrder([Block(kind, len(names))]))


def test_monomials_below_the_corner():
    R = ring(names=("x", "y"))
    # ds on (x, y): of degree 2, xy and y2 lie below x2 (reverse lexicographic), and all of degree 3
    assert sorted(below((2, 0), R)) == sorted([(1, 1), (0, 2), (3, 0), (2, 1), (1, 2), (0, 3)])
    assert sorted(below((0, 2), R)) == sorted([(3, 0), (2, 1), (1, 2), (0, 3)])
    with pytest.raises(NotSupported):
        below((2, 0), ring("ls", ("x", "y")))


def test_truncated_standard_bases():
    R = ring()
    gens = [parse_poly(R, p) for p in ("z+x^11+y^11", "y^12", "x^12", "y+x^10*y")]
    got = noether_basis(gens, R, (11, 0, 0), lambda g: standard_basis(g, R))
    # y + x^10 y = y (1 + x^10); y^11 < x^11 is dropped, x^11 (the corner) stays; y^12, x^12 vanish
    assert sorted(p.to_str() for p in got) == sorted(["y", "z+x^11"])
    two = [parse_poly(R, "x^2+y^12"), parse_poly(R, "y^13")]
    assert [p.to_str() for p in noether_basis(two, R, (11, 0, 0), lambda g: standard_basis(g, R))] == ["x^2"]
    assert truncate(parse_poly(R, "z+x^5+x^4*y+x^3*y^2"), (5, 0, 0)) == parse_poly(R, "z+x^5")
