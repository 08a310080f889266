"""Zero-dimensional real solving: the rational univariate representation against Hermite's quadratic
form (rank and signature), multiplicities, certified boxes, and the 3-RPR planar parallel robot
(six assembly modes)."""
from __future__ import annotations

import random

import pytest
from flint import fmpq

from mech.kernel import QQ, MonomialOrder, PolyRing
from mech.kernel.real_roots import RealSolvingError
from mech.kernel.real_solve import count_solutions, hermite_counts, real_solutions, rur

R2 = PolyRing(QQ, ["x", "y"], MonomialOrder.simple("dp", 2))
x, y = R2.gens()
R4 = PolyRing(QQ, ["x1", "y1", "x2", "y2"], MonomialOrder.simple("dp", 4))
x1, y1, x2, y2 = R4.gens()


def rpr(a2, a3, d2, u, v, r1, r2, r3):
    """The 3-RPR robot with locked legs in point coordinates: base joints A1 = (0, 0),
    A2 = (a2, 0), A3 = a3; platform joints B1 = (x1, y1), B2 = (x2, y2) at squared distance d2 and
    B3 = B1 + u (B2 - B1) + v J(B2 - B1) (J the quarter turn: the platform's orientation is fixed,
    its mirror image excluded); squared leg lengths r1, r2, r3."""
    b3x = x1 + u * (x2 - x1) - v * (y2 - y1)
    b3y = y1 + u * (y2 - y1) + v * (x2 - x1)
    return [x1 ** 2 + y1 ** 2 - r1, (x2 - a2) ** 2 + y2 ** 2 - r2, (x2 - x1) ** 2 + (y2 - y1) ** 2 - d2,
            (b3x - a3[0]) ** 2 + (b3y - a3[1]) ** 2 - r3]


#: designs with 6, 4, 2 and 0 real assembly modes (of 6 complex ones)
DESIGNS = [((5, (6, 6), 12, 2, fmpq(7, 4), 21, 10, 18), 6),
           ((6, (7, 7), 12, fmpq(3, 4), 2, 23, 8, 33), 4),
           ((11, (4, 7), 34, -1, 2, 32, 7, 21), 2),
           ((11, (9, 9), 9, fmpq(-1, 2), fmpq(1, 4), 1, 27, 28), 0)]


@pytest.mark.parametrize("design,real", DESIGNS)
def test_3rpr_assembly_modes(design, real):
    I = rpr(*design)
    sols = real_solutions(I, R4, 12)
    assert (sols.total, sols.complex_count, sols.real_count) == (6, 6, real)
    assert hermite_counts(I, R4) == (6, real)
    for s in sols.real:
        assert all(hi - lo <= fmpq(1, 10 ** 12) for lo, hi in s.box)
        p = s.midpoint()
        assert all(abs(g.evaluate(p)) < fmpq(1, 10 ** 9) for g in I)


def test_multiplicities_and_distinct_solutions():
    I = [(x - 1) ** 2, y ** 2 - 2]
    sols = real_solutions(I, R2, 10)
    assert (sols.total, sols.complex_count, sols.real_count) == (4, 2, 2)
    assert [s.multiplicity for s in sols.real] == [2, 2]
    assert sorted(s.decimals(10)[1] for s in sols.real) == ["-1.4142135624", "1.4142135624"]
    I = [x ** 3 - x, y ** 2 - x]  # (0,0) twice, (1, +-1), (-1, +-i)
    sols = real_solutions(I, R2)
    assert (sols.total, sols.complex_count, sols.real_count) == (6, 5, 3)
    assert sorted(s.multiplicity for s in sols.real) == [1, 1, 2]


@pytest.mark.parametrize("seed", range(8))
def test_rur_counts_agree_with_hermite(seed):
    rnd = random.Random(seed)

    def rand(deg):
        return sum((x ** i * y ** j * rnd.randint(-4, 4) for i in range(deg + 1) for j in range(deg + 1 - i)), R2.zero())
    I = [rand(2), rand(2)]
    if rnd.random() < 0.5:
        I = [I[0] * I[0], I[1]]  # a non-reduced system
    assert count_solutions(I, R2) == hermite_counts(I, R2)


def test_separating_form_is_checked():
    I = [x ** 2 - 1, y ** 2 - 1]  # x does not separate (1, 1) from (1, -1)
    with pytest.raises(RealSolvingError):
        rur(I, R2, [fmpq(1), fmpq(0)])
    rep = rur(I, R2)
    assert rep.count == 4 and len(rep.real_roots()) == 4


def test_no_solutions_and_positive_dimension():
    sols = real_solutions([x ** 2 + y ** 2 + 1, x - y], R2)
    assert (sols.complex_count, sols.real_count) == (2, 0)
    assert real_solutions([x - 1, x - 2], R2).total == 0
    with pytest.raises(RealSolvingError):
        real_solutions([x ** 2 + y ** 2 - 1], R2)


def test_signs_at_solutions():
    I = [x ** 2 + y ** 2 - 4, x * y - 1]
    rep = rur(I, R2)
    signs = sorted((rep.sign(x, r), rep.sign(y, r), rep.sign(x - y, r)) for r in rep.real_roots())
    assert signs == [(-1, -1, -1), (-1, -1, 1), (1, 1, -1), (1, 1, 1)]
    assert [rep.sign(x * y - 1, r) for r in rep.real_roots()] == [0, 0, 0, 0]
