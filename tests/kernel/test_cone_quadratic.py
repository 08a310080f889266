"""Tangent cones by linear algebra at smooth and corank-one quadratic points (kernel/cone_quadratic.py),
checked against the local standard basis (kernel.local.tangent_cone: sing.lib's tangentcone)."""
from __future__ import annotations

import random
from fractions import Fraction

import pytest

from mech.kernel.coeffs import QQ
from mech.kernel.cone_quadratic import linear_rank, quadratic_cone
from mech.kernel.ideals import ideals_equal
from mech.kernel.local import tangent_cone
from mech.kernel.order import Block, MonomialOrder
from mech.kernel.poly import Poly, PolyRing
from tests.util import parse_poly

R = PolyRing(QQ, ["x", "y", "z"], MonomialOrder([Block("dp", 3)]))


def polys(*texts):
    return [parse_poly(R, t) for t in texts]


@pytest.mark.parametrize("gens, cone", [
    (["y^2-x^2-x^3"], ["y^2-x^2"]),                       # node
    (["y^2-x^3"], ["y^2"]),                               # cusp: the double line
    (["x+y^2", "y^2-z^2+x*z+z^3"], ["x", "y^2-z^2+x*z"]),  # a node on the smooth surface x = -y^2
    (["x+y^2", "x+z^3+y*z"], ["x", "y*z-y^2"]),          # the dependent one minus the first: z^3+y*z-y^2
    (["x+y^2-z", "y+x*z"], ["x-z", "y"]),                # a smooth point: the tangent space
])
def test_cones_by_linear_algebra(gens, cone):
    got = quadratic_cone(polys(*gens), R)
    assert got is not None
    assert ideals_equal(got, polys(*cone), R)
    assert ideals_equal(got, tangent_cone(polys(*gens), R), R)


@pytest.mark.parametrize("gens", [
    ["x^3+y^3+z^3"],               # no quadratic part
    ["x+y^3", "x*y+z^3"],          # the quadratic part x*y vanishes on the tangent space x = 0
    ["x^2-y^2", "x*z", "y*z"],     # several generators without linear part
])
def test_other_points_need_a_standard_basis(gens):
    assert quadratic_cone(polys(*gens), R) is None


def test_random_corank_one_points_agree_with_the_standard_basis():
    rnd = random.Random(5)
    S = PolyRing(QQ, ["a", "b", "c", "d"], MonomialOrder([Block("dp", 4)]))
    monomials = [e for e in ((i, j, k, l) for i in range(3) for j in range(3) for k in range(3) for l in range(3))
                 if 1 <= sum(e) <= 3]
    done = 0
    for _ in range(40):
        gens = []
        for _ in range(rnd.randint(1, 3)):
            terms = {e: QQ(Fraction(rnd.randint(-3, 3), rnd.randint(1, 2))) for e in rnd.sample(monomials, 5)}
            gens.append(Poly(S, {e: c for e, c in terms.items() if c}))
        gens = [g for g in gens if not g.is_zero()]
        cone = quadratic_cone(gens, S) if gens else None
        if cone is None:
            continue
        done += 1
        assert ideals_equal(cone, tangent_cone(gens, S), S)
    assert done >= 10


def test_linear_rank_is_the_jacobian_rank_at_the_origin():
    from mech.kernel.local import jacobian_rank
    for gens in (["x+y^2", "2*x+z^3", "y-z+x*y"], ["x^2", "y*z"], ["x-y", "2*x-2*y+z^2"]):
        assert linear_rank(polys(*gens), R) == jacobian_rank(polys(*gens), [0, 0, 0])
