"""Localization at a prime (kernel/localization.py): contractions, equality in R_P, lengths."""
from __future__ import annotations

from mech.kernel import Block
from mech.kernel import localization as L
from tests.util import ring


def _setup():
    R = ring(["x", "y", "z"], [Block("dp", 3)])
    return R, R.gens()


def test_contraction_keeps_the_components_inside_the_prime() -> None:
    R, (x, y, z) = _setup()
    I = [x * (x - 1), x * y]       # components (x) and (x - 1, y)
    assert L.contraction(I, [x, y], R) == [x]
    assert L.contraction(I, [x - 1, y], R) == [y, x - 1]
    assert L.contraction(I, [x - 1, y - 1], R) == [R.one()]  # no component through (1, 1)
    assert L.contraction([(z - 1) * x], [x, y], R) == [x]      # z - 1 is a unit of R_P
    assert L.contraction([x + 1], [x, y], R) == [R.one()]  # x + 1 is a unit of R_P


def test_equality_and_containment_in_the_local_ring() -> None:
    R, (x, y, z) = _setup()
    P = [x, y]
    assert L.local_equal([x * (y + 1)], [x], P, R)          # y + 1 is a unit
    assert not L.local_equal([x * y], [x], P, R)
    assert L.local_subset([x * y], [x], P, R) and not L.local_subset([x], [x * y], P, R)
    assert L.is_local_unit(z, P, R) and not L.is_local_unit(x + y, P, R)


def test_length_at_a_point_is_the_intersection_multiplicity() -> None:
    R = ring(["x", "y"], [Block("dp", 2)])
    x, y = R.gens()
    # the parabola y = x^2 meets the line y = 0 twice at the origin, not at (1, 1)
    assert L.local_length([y - x**2, y], [x, y], R) == 2
    assert L.local_length([y - x**2, y], [x - 1, y - 1], R) == 0
    # the parabola and the line y = x meet once at the origin and once at (1, 1)
    assert L.local_length([y - x**2, y - x], [x, y], R) == 1
    assert L.local_length([y - x**2, y - x], [x - 1, y - 1], R) == 1
