"""mech.kernel.curve_ideals: the primes of a curve's components, interpolated modulo primes and
proved over QQ; a wrong candidate is never accepted."""
from __future__ import annotations

from mech.kernel.curve_ideals import _proved, ideal_of_components
from mech.kernel.ideals import ideals_equal, intersect, std
from mech.kernel.slices import curve_image
from mech.kernel import QQ, MonomialOrder, PolyRing
from tests.util import parse_poly


def _ring():
    return PolyRing(QQ, ["x", "y", "z"], MonomialOrder.simple("dp", 3))


def test_line_and_circle_by_hand():
    """J = <z - x, y (x^2 + y^2 - 1)>: the line y = 0 and the circle x^2 + y^2 = 1 in the plane
    z = x (by hand); the projection proves two modes of degrees 1 and 2, their ideals are those."""
    R = _ring()
    J = [parse_poly(R, "z-x"), parse_poly(R, "x^2*y+y^3-y")]
    image = curve_image(J, R)
    assert sorted(g.total_degree() for g in image.factors) == [1, 2]
    primes = ideal_of_components(J, R, image.forms, image.factors)
    line = [parse_poly(R, "z-x"), parse_poly(R, "y")]
    circle = [parse_poly(R, "z-x"), parse_poly(R, "x^2+y^2-1")]
    assert len(primes) == 2
    assert any(ideals_equal(P, line, R) for P in primes) and any(ideals_equal(P, circle, R) for P in primes)
    assert ideals_equal(intersect(*primes, ring=R), J, R)


def test_wrong_candidates_are_rejected():
    """The proof fails for a candidate with an extra point (the circle's ideal intersected with
    the point (2, 0, 2), on the line), for one with an embedded point, for a candidate that is one mode twice, and for one not
    containing J."""
    R = _ring()
    J = [parse_poly(R, "z-x"), parse_poly(R, "x^2*y+y^3-y")]
    line = std([parse_poly(R, "z-x"), parse_poly(R, "y")], R)
    circle = std([parse_poly(R, "z-x"), parse_poly(R, "x^2+y^2-1")], R)
    assert _proved(J, R, [line, circle])
    point = [parse_poly(R, "x-2"), parse_poly(R, "y"), parse_poly(R, "z-2")]
    with_point = std(intersect(circle, point, ring=R), R)
    assert not ideals_equal(with_point, circle, R)
    assert not _proved(J, R, [line, with_point])
    fat = [parse_poly(R, t) for t in ("z-x", "(x-1)^2", "(x-1)*y", "y^2")]  # embedded at (1, 0, 1)
    embedded = std(intersect(circle, fat, ring=R), R)
    assert not ideals_equal(embedded, circle, R) and not _proved(J, R, [line, embedded])
    assert not _proved(J, R, [line, line])
    assert not _proved(J, R, [line, std([parse_poly(R, "z"), parse_poly(R, "x^2+y^2-1")], R)])
