"""Strong Gröbner bases over ZZ (kernel/zz_groebner.py): lead terms of minimal strong bases (checked
against Macaulay2 1.21's ``gb`` over ZZ) and the ideal operations built on them, checked by hand."""
from __future__ import annotations

from mech.kernel import Block
from mech.kernel import zz_groebner as Z
from tests.util import ring


def _setup():
    R = ring(["x", "y"], [Block("dp", 2)])
    return R, R.gens()


def _lead_terms(basis):
    return sorted((g.lm(), int(g.lc().p)) for g in basis)


def test_strong_basis_of_an_elliptic_curve_singularity_ideal() -> None:
    # Macaulay2 1.21: gens gb ideal(F, diff(x,F), diff(y,F)) over ZZ[x,y], F = y^2-(x^3+3x+5), is
    # {174, 2y, 6x-72, y^2+87, 3x^2+3, x^2y+y, x^3+3x-82}
    R, (x, y) = _setup()
    F = y**2 - (x**3 + 3 * x + 5)
    G = Z.strong_basis([F, F.diff(0), F.diff(1)], R)
    m2 = [R.const(174), 2 * y, 6 * x - 72, y**2 + 87, 3 * x**2 + 3, x**2 * y + y, x**3 + 3 * x - 82]
    assert _lead_terms(G) == _lead_terms(m2)
    assert all(Z.contains(G, f) for f in m2)
    assert all(Z.contains(Z.strong_basis(m2, R), g) for g in G)


def test_membership_needs_integral_combinations() -> None:
    R, (x, y) = _setup()
    G = Z.strong_basis([2 * x, 3 * y], R)
    assert not Z.contains(G, x)           # x is in (2x, 3y) over QQ, not over ZZ
    assert Z.contains(G, 4 * x + 9 * x * y)
    G = Z.strong_basis([2 * x, 3 * x], R)  # the G-polynomial x = 3x - 2x
    assert Z.contains(G, x)


def test_intersection_quotient_saturation_elimination() -> None:
    R, (x, y) = _setup()
    one = R.one()
    # (2, x) ∩ (3, y) = (6, 3x, 2y, xy)
    meet = Z.intersect([2 * one, x], [3 * one, y], R)
    expected = Z.strong_basis([6 * one, 3 * x, 2 * y, x * y], R)
    assert all(Z.contains(expected, g) for g in meet) and all(Z.contains(meet, g) for g in expected)
    # (6x, 4y) : 2 = (3x, 2y)
    q = Z.quotient([6 * x, 4 * y], [2 * one], R)
    assert _lead_terms(q) == _lead_terms(Z.strong_basis([3 * x, 2 * y], R))
    # (4xy, 6x^2) : x^infinity = (4y, 6x) : x = (6, 4y)... checked: 6 lies in it, 2 does not
    sat = Z.saturate([4 * x * y, 6 * x**2], [x], R)
    assert Z.contains(sat, 6 * one) and Z.contains(sat, 4 * y) and not Z.contains(sat, 2 * one)
    # (x - 2y, y^2 - 3) ∩ ZZ[x] = (x^2 - 12)
    elim = Z.eliminate([x - 2 * y, y**2 - 3], [1], R)
    assert [str(g) for g in elim] == [str(x**2 - 12)]
