"""Real branches at a point: half-branches on a certified small sphere, tangent rays and the kind of
point, at rational and at algebraic points, and at the four-bar's change point."""
from __future__ import annotations

import pytest
from flint import fmpq

from mech.kernel import QQ, MonomialOrder, PolyRing
from mech.kernel.local import tangent_cone_at
from mech.kernel.real_branches import real_branches
from mech.kernel.real_roots import RealSolvingError

R2 = PolyRing(QQ, ["x", "y"], MonomialOrder.simple("dp", 2))
x, y = R2.gens()
R6 = PolyRing(QQ, ["c1", "s1", "c2", "s2", "c3", "s3"], MonomialOrder.simple("dp", 6))
c1, s1, c2, s2, c3, s3 = R6.gens()
ORIGIN = [fmpq(0), fmpq(0)]

# (curve, point, half-branches, kind, half-branches on (+v, -v) of each real tangent line)
CASES = [
    (x ** 2 - y ** 2, ORIGIN, 4, "node", [(1, 1), (1, 1)]),
    (x ** 3 - y ** 2, ORIGIN, 2, "cusp", [(2, 0)]),
    (x ** 2 + y ** 2, ORIGIN, 0, "isolated", []),
    (y ** 2 - x ** 4, ORIGIN, 4, "tacnode", [(2, 2)]),
    (x ** 2 + y ** 2 - 1, [fmpq(1), fmpq(0)], 2, "regular", [(1, 1)]),
    (y ** 3 - x ** 4, ORIGIN, 2, "singular", [(1, 1)]),            # one branch, singular, no cusp
    ((x ** 2 - y ** 2) * (y - 2 * x), ORIGIN, 6, "node", [(1, 1)] * 3),
    (y ** 2 + x ** 2 - x ** 3, ORIGIN, 0, "isolated", []),           # real tangent cone lines: none
    ((y ** 2 - x ** 3) * (y ** 2 + x ** 3), ORIGIN, 4, "tacnode", [(2, 2)]),  # opposite cusps
]


@pytest.mark.parametrize("f,point,half,kind,rays", CASES)
def test_branches_at_rational_points(f, point, half, kind, rays):
    (b,) = real_branches([f], R2, point)
    assert (b.half_branches, b.branches, b.kind) == (half, half // 2, kind)
    assert sorted(b.rays) == sorted(rays)
    assert len(b.tangents) == len(rays)
    # the nodes, the smooth point and the isolated points here are ordinary (distinct simple tangent lines,
    # over C): decided from the tangent cone alone; the others by the points on a certified sphere
    assert (b.radius2 is None) == (kind in ("node", "regular", "isolated"))
    assert b.radius2 is None or b.radius2 > 0


def test_branches_at_algebraic_points():
    f = (y ** 2 - 2) ** 2 - x ** 2 * (1 + x)     # nodes at (0, -sqrt 2) and (0, sqrt 2)
    found = real_branches([f], R2, [x, y ** 2 - 2])
    assert [(b.half_branches, b.kind) for b in found] == [(4, "node"), (4, "node")]
    assert sorted(round(float(b.point[1][0]), 6) for b in found) == [-1.414214, 1.414214]
    found = real_branches([(y ** 2 - 2) ** 2 + x ** 2 * (1 - x)], R2, [x, y ** 2 - 2])
    assert [b.kind for b in found] == ["isolated", "isolated"]


def test_fourbar_change_point():
    """ground 5, links 2, 4, 3 (s + l = p + q): at the folded configuration the tangent cone,
    restricted to the linear part, is 8 s2^2 + 24 s2 s3 + 3 s3^2 with discriminant 480 > 0: two
    real lines, and the curve has two real branches there."""
    I = [2 * c1 + 4 * c2 + 3 * c3 - 5, 2 * s1 + 4 * s2 + 3 * s3, c1 ** 2 + s1 ** 2 - 1, c2 ** 2 + s2 ** 2 - 1,
         c3 ** 2 + s3 ** 2 - 1]
    p = [fmpq(v) for v in (-1, 0, 1, 0, 1, 0)]
    cone = tangent_cone_at(I, p)
    on_plane = [g.compose([R6.zero(), -(4 * s2 + 3 * s3) * fmpq(1, 2), R6.zero(), s2, R6.zero(), s3]) for g in cone]
    assert 8 * s2 ** 2 + 24 * s2 * s3 + 3 * s3 ** 2 in [g * 2 for g in on_plane if not g.is_zero()]
    (b,) = real_branches(I, R6, p)
    assert (b.half_branches, b.branches, b.kind, b.rays) == (4, 2, "node", [(1, 1), (1, 1)])


def test_point_not_on_the_curve():
    with pytest.raises(RealSolvingError):
        real_branches([x ** 2 + y ** 2 - 1], R2, ORIGIN)


def test_double_point_counts():
    """Half-branch counts of the sweep at ordinary double points from the Hessian on the Jacobian's
    kernel (Morse), against the certified sphere; other points are left to the tangent cone."""
    from mech.kernel.real_branches import PointFamily, _critical_bound, _double_point_counts, _Setting, _sphere, \
        point_families
    rational = PointFamily.rational

    def on_sphere(curve, ring, fam):
        S = _Setting(curve, ring, fam)
        _, _, owners = _sphere(S, _critical_bound(S))
        return [owners.count(j) for j in range(len(S.roots))]
    assert _double_point_counts([x ** 2 - y ** 2], R2, rational(ORIGIN)) == [4]
    assert _double_point_counts([x ** 2 + y ** 2 - x ** 3], R2, rational(ORIGIN)) == [0]
    for f in (x ** 3 - y ** 2, y ** 2 - x ** 4, x ** 2 + y ** 2 - 1):
        assert _double_point_counts([f], R2, rational(ORIGIN if f != x ** 2 + y ** 2 - 1 else [1, 0])) is None
    (fam,) = point_families([x, y ** 2 - 2], R2)
    for f, counts in (((y ** 2 - 2) ** 2 - x ** 2 * (1 + x), [4, 4]), ((y ** 2 - 2) ** 2 + x ** 2 * (1 - x), [0, 0])):
        assert _double_point_counts([f], R2, fam) == counts == on_sphere([f], R2, fam)
    I = [2 * c1 + 4 * c2 + 3 * c3 - 5, 2 * s1 + 4 * s2 + 3 * s3, c1 ** 2 + s1 ** 2 - 1, c2 ** 2 + s2 ** 2 - 1,
         c3 ** 2 + s3 ** 2 - 1]   # the four-bar's change point (test_fourbar_change_point)
    p = rational([fmpq(v) for v in (-1, 0, 1, 0, 1, 0)])
    assert _double_point_counts(I, R6, p) == [4] == on_sphere(I, R6, p)
