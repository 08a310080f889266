"""The pieces that let the real topology of a six-bar's motion mode finish: the complete
intersection among a curve's generators, Jacobian ranks at algebraic points modulo a prime, the
pairing of fibre points from three plane images, signs at roots and multiplication matrices of
short polynomials - each checked against a hand derivation."""
from __future__ import annotations

from flint import fmpq, fmpq_poly, fmpz_poly

from mech.kernel import QQ, MonomialOrder, PolyRing
from mech.kernel.real_curve import _plane_ranks, _rank_mod_p
from mech.kernel.real_fibers import Fibres, complete_intersection
from mech.kernel.real_roots import isolate_real_roots, sign_at
from mech.kernel.real_solve import QuotientAlgebra
from mech.kernel.real_chart import Chart
from mech.kernel.groebner import groebner

R2 = PolyRing(QQ, ["x", "y"], MonomialOrder.simple("dp", 2))
x, y = R2.gens()
R3 = PolyRing(QQ, ["x", "y", "z"], MonomialOrder.simple("dp", 3))
X, Y, Z = R3.gens()


def test_complete_intersection_takes_the_low_degrees():
    """The circle x^2 + y^2 = 1 on the surface z = x y, given with the redundant cubic
    x z - x^2 y: the two generators of least degree cut out the curve; a lone surface does not."""
    gens = [X * Z - X * X * Y, X * X + Y * Y - 1, Z - X * Y]
    assert complete_intersection(gens, R3) == [Z - X * Y, X * X + Y * Y - 1]
    assert complete_intersection([X * X + Y * Y + Z * Z - 1, (X * X + Y * Y + Z * Z - 1) * Z], R3) is None


def test_jacobian_rank_at_conjugate_points():
    """y^2 = (x^2 - 2)^2 (two parabolas crossing at x = +-sqrt 2, y = 0): its gradient
    (-4x(x^2 - 2), 2y) vanishes at the crossings, rank 0; the circle x^2 + y^2 = 4 at
    (t, t), t^2 = 2, has gradient (2t, 2t): rank 1."""
    t2 = fmpz_poly([-2, 0, 1])
    at = [fmpq_poly([0, 1]), fmpq_poly([0])]
    f = y * y - (x * x - 2) ** 2
    assert _rank_mod_p([[f.diff(0), f.diff(1)]], t2, at) == 0
    c = x * x + y * y - 4
    assert _rank_mod_p([[c.diff(0), c.diff(1)]], t2, [fmpq_poly([0, 1]), fmpq_poly([0, 1])]) == 1


def test_fibre_pairing_from_plane_images():
    """The circle x^2 + y^2 = 1 in the plane z = x + 2 y over l = x: at x = 1/2 its real points
    are p+- = (1/2, +-s, 1/2 +- 2 s), s = sqrt(3)/2.  In m = y order they are p-, p+; m2 = z - 3 y
    = 1/2 - y orders them p+, p-: the ranks are [1, 0]."""
    gens = [X * X + Y * Y - 1, Z - X - 2 * Y]
    fib = Fibres(gens, R3, [1, 0, 0])
    m, m2 = [0, 1, 0], [0, -3, 1]
    g, g2, g3 = (fib.plane_curve(f) for f in (m, m2, [a + b for a, b in zip(m, m2)]))
    assert _plane_ranks(g, g2, g3, fmpq(1, 2)) == [1, 0]
    assert _plane_ranks(g, g2, g3, fmpq(3, 1)) == []  # no real point over x = 3


def test_sign_at_a_root_close_to_zero():
    """sqrt 2 = 1.41421356237309504880168...: 10^20 x - 141421356237309504880 is positive there
    (by 1.7e-1 of its scale), 10^20 x - 141421356237309504881 negative; x^2 - 2 vanishes."""
    [_, root] = isolate_real_roots(fmpz_poly([-2, 0, 1]))
    assert sign_at(fmpq_poly([-141421356237309504880, 10 ** 20]), root) == 1
    assert sign_at(fmpq_poly([-141421356237309504881, 10 ** 20]), root) == -1
    assert sign_at(fmpq_poly([-2, 0, 1]), root) == 0


def test_short_polynomial_matrix():
    """In Q[x, y]/(x^2 - 2, y^2 - 3) the multiplication by x y + 1 has the eigenvalues
    1 +- sqrt 6 (twice each): characteristic polynomial ((T - 1)^2 - 6)^2."""
    A = QuotientAlgebra([x * x - 2, y * y - 3], R2)
    M = A.poly_matrix(x * y + 1)
    assert fmpq_poly(M.charpoly().coeffs()) == fmpq_poly([-5, -2, 1]) ** 2


def test_chart_lifts_points_and_directions():
    """The line x = 2 + t, y = 1 - 2 t, z = t in the chart of its linear equations: one free
    variable; a point and a direction lifted back."""
    gens = [X - Z - 2, Y + 2 * Z - 1]
    chart = Chart(gens, groebner(gens, R3), R3)
    assert [R3.names[i] for i in chart.free] == ["z"]
    assert chart.lift([(fmpq(1), fmpq(1))]) == [(3, 3), (-1, -1), (1, 1)]
    assert chart.lift_direction([(fmpq(1), fmpq(1))]) == [(1, 1), (-2, -2), (1, 1)]
