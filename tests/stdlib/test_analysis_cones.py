"""The analysis' tangent cones at singular configurations by linear algebra (stdlib/analysis_linear.py over
Q[t]/m(t); kernel/cone_quadratic.py over Q): the same ideals as the local standard bases, and as Singular's
sing.lib ``tangentcone`` on a linkage."""
from __future__ import annotations

import pytest

from mech.dsl.printing import poly_str
from mech.kernel.coeffs import QQ
from mech.kernel.ideals import ideals_equal
from mech.kernel.local import (centre_at, primitive_element, shift_to_origin, tangent_cone, tangent_cone_over,
                               tangent_dim_over)
from mech.kernel.order import Block, MonomialOrder
from mech.kernel.poly import PolyRing
from mech.stdlib.analysis import analyze
from mech.stdlib.analysis_linear import component_cone_over, quadratic_cone_over, tangent_cone_over_reduced
from mech.stdlib.mechanism import parse_mechanism
from tests.util import SINGULAR, ideal_blocks, parse_poly, run_singular


def test_conjugate_points_over_their_field():
    """The nodes of y^2 = (x^2-2)^2 (x + 3) at x = +-sqrt 2 over Q[t]/(t^2 - 2): the same cone as the
    local standard basis over K."""
    S = PolyRing(QQ, ["x", "y"], MonomialOrder([Block("dp", 2)]))
    x, y = S.gens()
    f = y ** 2 - (x ** 2 - S.const(2)) ** 2 * (x + S.const(3))
    pt = primitive_element([x ** 2 - S.const(2), y], S)
    centred = centre_at([f], pt)
    cone = quadratic_cone_over(centred, pt)
    assert cone is not None
    assert ideals_equal(cone + [pt.minpoly], tangent_cone_over(centred, pt), pt.ring)


def test_translation_by_the_binomial_theorem():
    S = PolyRing(QQ, ["x", "y", "z"], MonomialOrder([Block("dp", 3)]))
    gens = [parse_poly(S, t) for t in ["x^3*y-2*z^2+x*y*z-1", "y^4+1/2*x", "z"]]
    point = [QQ(2), QQ(0), QQ(-1) / QQ(3)]
    images = [x + S.const(c) for x, c in zip(S.gens(), point)]
    assert shift_to_origin(gens, point) == [g.compose(images) for g in gens]


def test_smooth_components_over_their_field():
    """Primes over K = Q(sqrt 2) through the origin: at a smooth point the cone is the tangent line (linear
    algebra), at the cusp y^2 = t x^3 a local standard basis; the same ideals as tangent_cone_over."""
    S = PolyRing(QQ, ["x", "y"], MonomialOrder([Block("dp", 2)]))
    x, y = S.gens()
    pt = primitive_element([x ** 2 - S.const(2), y], S)
    X, Y, t = pt.ring.gens()
    m = pt.minpoly
    for comp in ([Y - X * t, m], [Y - X ** 2 - X * t, m], [X * Y + Y ** 2 - X, m], [Y ** 2 - t * X ** 3, m]):
        assert ideals_equal(component_cone_over(comp, pt, 1), tangent_cone_over_reduced(comp, pt), pt.ring)
    origin = [pt.ring.zero()] * 2
    comps = ([Y - X * t, m], [Y ** 2 - t * X ** 3, m], [X, Y, m])
    assert [tangent_dim_over(c, origin, pt.ring, m) for c in comps] == [1, 2, 0]
    assert [tangent_dim_over(c, origin, pt.ring, m, at_least=d) for c, d in zip(comps, (1, 1, 0))] == [1, 2, 0]


WATT = "ground O A 1; fix G 2 0; bar O B 1; bar B C 1; body A C 1 0 E 0 1; bar E F 1; bar F G 1"


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
def test_watt_cones_against_singular():
    """The Watt six-bar's singular configurations (two branches crossing): the analysis' cones, by linear
    algebra, equal sing.lib's tangentcone of J moved to each point."""
    a = analyze(parse_mechanism(WATT))
    points = [s for s in a.singular if s.point is not None][:4]
    assert len(points) == 4
    names = ",".join(a.ring.names)
    J = ",".join(poly_str(g) for g in a.ideal)
    script = ['LIB "sing.lib";', f"ring r = 0,({names}),ds; short = 0;", f"ideal J = {J};"]
    for k, s in enumerate(points):
        images = ",".join(f"{x}+({c})" for x, c in zip(a.ring.names, s.point))
        script.append(f"map f{k} = r, {images}; tangentcone(f{k}(J));")
    blocks = ideal_blocks(run_singular("\n".join(script)))
    assert len(blocks) == len(points)
    for s, block in zip(points, blocks):
        theirs = [parse_poly(a.ring, g) for g in block]
        assert ideals_equal(s.tangent_cone, theirs, a.ring)
        assert ideals_equal(s.tangent_cone, tangent_cone(shift_to_origin(a.ideal, s.point), a.ring), a.ring)
