"""The Jacobian's rank at algebraic points modulo a prime (kernel/modular_rank.py): a lower bound
for the rank over K = Q[t]/m(t), equal to it at smooth points, and the tangent dimension it
certifies (kernel/local.tangent_dim_over) equal to the exact one."""
from __future__ import annotations

from fractions import Fraction

from mech.kernel import QQ, Block, MonomialOrder, PolyRing
from mech.kernel.local import tangent_dim_over, primitive_element
from mech.kernel.modular_rank import jacobian_rank_mod

R = PolyRing(QQ, ["x", "y", "t"], MonomialOrder([Block("dp", 2), Block("dp", 1)]))
x, y, t = R.gens()
M = t * t - 2  # t = ±sqrt(2)


def test_smooth_point_full_rank():
    """The circle x^2 + y^2 = 4 at (t, t): gradient (2t, 2t), rank 1 over K and modulo p."""
    assert jacobian_rank_mod([x * x + y * y - 4], [t, t], M) == 1


def test_singular_point_rank_zero():
    """y^2 = (x^2 - 2)^2 is two parabolas crossing at (±sqrt(2), 0): the gradient
    (-4x(x^2 - 2), 2y) vanishes there."""
    f = y * y - (x * x - 2) ** 2
    assert jacobian_rank_mod([f], [t, R.zero()], M) == 0
    assert tangent_dim_over([f], [t, R.zero()], R, M) == 2


def test_two_equations_and_denominators():
    """x - t y = 0 and x^2/3 + y^2/3 = 1 at (t, 1): the Jacobian's rows (1, -t) and
    (2t/3, 2/3) have determinant (2 + 2t^2)/3 = 2: rank 2."""
    third = R.const(Fraction(1, 3))
    gens = [x - t * y, (x * x + y * y) * third - 1]
    assert jacobian_rank_mod(gens, [t, R.one()], M) == 2


def test_certified_dimension_equals_the_exact_one():
    """A point of a curve in the plane given by a prime over Q: with the lower bound 1 (the
    curve's dimension) the modular rank certifies the tangent dimension the linear ideal gives."""
    S = PolyRing(QQ, ["x", "y"], MonomialOrder([Block("dp", 2)]))
    u, v = S.gens()
    pt = primitive_element([u * u - 2, v - 1], S)
    X, Y = pt.ring.gens()[:2]
    curve = [X * X - 2 * Y * Y]
    exact = tangent_dim_over(curve, pt.coords, pt.ring, pt.minpoly)
    assert exact == tangent_dim_over(curve, pt.coords, pt.ring, pt.minpoly, at_least=1) == 1
