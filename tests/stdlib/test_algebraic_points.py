"""Local analysis at singular configurations with algebraic (non-rational) coordinates: a Galois
orbit of conjugate points, analysed over K = Q[t]/m(t) for a primitive element t; cones and local
components checked against Singular at one conjugate point (ring (0,t) with minpoly)."""
from __future__ import annotations

import subprocess
import sys

import pytest

from mech import Session
from mech.dsl.printing import poly_str
from mech.kernel import QQ, Block, MonomialOrder, PolyRing
from mech.kernel.errors import DomainError
from mech.kernel.factor import factorize
from mech.kernel.groebner import normal_form
from mech.kernel.ideals import ideals_equal
from mech.kernel.local import (centre_at, classify_algebraic_point, local_components_over,
                               primitive_element, stays_prime)
from mech.stdlib.analysis import analyze
from mech.stdlib.mechanism import parse_mechanism
from mech.stdlib.reports import report_data, report_text
from mech.stdlib.standard import normalize
from tests.util import ROOT, SINGULAR, ideal_blocks, parse_poly, run_singular

TILTED = "fix O; bar O A 1; bar A B 1; slider B 1 1 0"      # slide along x + y = 0
TILTED2 = "fix O; bar O A 1; bar A B 1; slider B 1 2 0"     # slide along x + 2y = 0
TILTED3 = "fix O; bar O A 1; bar A B 1; bar B C 2; slider C 1 1 0"
BODIES = "ground O A 1; body O B 1 1; bar B C 1; body C A 1 1"  # two links of length sqrt(2)
BODIES2 = "ground O A 1; body O B 1 2; bar B C 1; body C A 2 1"  # two links of length sqrt(5)

# mechanism -> (minimal polynomial of t, kind, number of local components)
EXPECTED = {
    TILTED: ("2*t^2-1", "components meet", 2),
    TILTED2: ("5*t^2-4", "components meet", 2),
    TILTED3: ("2*t^2-1", "singular", 1),
    BODIES: ("2*t^2-1", "components meet", 2),
    BODIES2: ("5*t^2-1", "components meet", 2),
}


def ring(names):
    return PolyRing(QQ, names, MonomialOrder([Block("dp", len(names))]))


def singular_at_point(gens, pt):
    """Singular at one conjugate point: tangentcone of the translated ideal over Q(t); and the
    number of minimal primes through the origin over Q(t), as minAssChar's primes of
    Q[x, t] containing m(t) and contained in (x, m(t)) (minAssGTZ over Q(t) takes minutes)."""
    n = pt.ring.nvars - 1
    names = ",".join(pt.ring.names[:n])
    images = ",".join(f"{x}+({poly_str(c)})" for x, c in zip(pt.ring.names, pt.coords))
    m = poly_str(normalize(pt.minpoly))
    J = ",".join(poly_str(g) for g in gens)
    out = run_singular(f"""LIB "sing.lib";
ring r = (0,t),({names}),ds; minpoly = {m}; short = 0;
ideal J = {J};
map f = r, {images};
tangentcone(f(J));
ring q = 0,({names},t),dp;
ideal J = {J};
map g = q, {images}, t;
ideal I = g(J), {m};
list L = minAssChar(I);
ideal origin = std(ideal({names}, {m}));
int k; int c;
for (k = 1; k <= size(L); k++) {{ if (size(reduce(L[k], origin)) == 0) {{ c++; }} }}
"components " + string(c);
""")
    cone = [parse_poly(pt.ring, g) for g in ideal_blocks(out)[0]]
    count = int(out.split("components ")[1].split()[0])
    return cone, count


def same_over_k(a, b, pt):
    return ideals_equal(list(a) + [pt.minpoly], list(b) + [pt.minpoly], pt.ring)


# ---------------------------------------------------------------- kernel
def test_primitive_element_is_a_variable_when_one_separates():
    R = ring(["x", "y"])
    x, y = R.gens()
    pt = primitive_element([x - 2 * y, 2 * y ** 2 - 3], R)
    assert pt.form.to_str() == "y" and normalize(pt.minpoly).to_str() == "2*t^2-3"
    assert [c.to_str() for c in pt.coords] == ["2*t", "t"]


def test_primitive_element_linear_form():
    R = ring(["x", "y"])
    x, y = R.gens()
    prime = [x ** 2 - 2, y ** 2 - 3]  # 4 points (+-sqrt2, +-sqrt3): no variable separates them
    pt = primitive_element(prime, R)
    assert pt.degree == 4 and len(factorize(pt.minpoly)[1]) == 1
    assert len([e for e in pt.form.terms]) == 2
    for g in prime:  # the coordinates are a root of the prime over K
        assert normal_form(g.compose(pt.coords, pt.ring), [pt.minpoly]).is_zero()


def test_primitive_element_needs_dimension_zero():
    R = ring(["x", "y"])
    x, y = R.gens()
    with pytest.raises(DomainError, match="zero-dimensional"):
        primitive_element([x ** 2 - 2], R)
    pt = primitive_element([x ** 2 - 2, y], R)
    with pytest.raises(DomainError, match="not on the variety"):
        centre_at([x - 1], pt)


def test_non_real_orbit_two_parabolas():
    """y = x^2+1 and y = -x^2-1 meet at (+-i, 0): over K = Q(i) the cone is two lines
    (y^2+4x^2 splits), the components stay the two parabolas."""
    R = ring(["x", "y"])
    x, y = R.gens()
    J = [(y - x ** 2 - 1) * (y + x ** 2 + 1)]
    pt = primitive_element([x ** 2 + 1, y], R)
    info = classify_algebraic_point(J, pt)
    assert info.kind == "components meet" and len(info.components) == 2
    X, Y, _ = pt.ring.gens()
    assert same_over_k(info.tangent_cone, [Y ** 2 + 4 * X ** 2], pt)
    assert (info.local_dim, info.tangent_space_dim, info.multiplicity) == (1, 2, 2)


def test_components_from_the_modes_equal_the_decomposition_over_k():
    """The shortcut (a mode that stays prime over K is one component) agrees with the minimal
    primes of the translated ideal over K."""
    a = analyze(parse_mechanism(TILTED))
    pt = a.singular[0].algebraic
    centred = centre_at(a.ideal, pt)
    direct = local_components_over(centred, pt)
    via = local_components_over(centred, pt, [md.prime for md in a.modes])
    assert len(direct) == len(via) == 2
    assert all(any(ideals_equal(p, q, pt.ring) for q in direct) for p in via)
    assert all(stays_prime(md.prime, pt) for md in a.modes)


def test_stays_prime_is_false_when_the_mode_splits():
    """x^2 - 2y^2 is prime over Q but two lines over Q(sqrt2)."""
    R = ring(["x", "y"])
    x, y = R.gens()
    pt = primitive_element([x ** 2 - 2, y - 1], R)
    assert not stays_prime([x ** 2 - 2 * y ** 2], pt)
    comps = local_components_over(centre_at([x ** 2 - 2 * y ** 2], pt), pt, [[x ** 2 - 2 * y ** 2]])
    assert len(comps) == 1  # only the line through the point (sqrt2, 1)


# ---------------------------------------------------------------- mechanisms
@pytest.mark.parametrize("text", list(EXPECTED))
def test_mechanisms_local_analysis(text):
    minpoly, kind, ncomps = EXPECTED[text]
    a = analyze(parse_mechanism(text))
    [s] = a.singular
    assert s.point is None and s.algebraic is not None and s.real and s.dim == 0
    assert poly_str(normalize(s.algebraic.minpoly)) == minpoly
    assert (s.kind, len(s.local_components)) == (kind, ncomps)


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
@pytest.mark.parametrize("text", list(EXPECTED))
def test_mechanisms_against_singular(text):
    a = analyze(parse_mechanism(text))
    [s] = a.singular
    pt = s.algebraic
    cone, count = singular_at_point(a.ideal, pt)
    assert same_over_k(s.tangent_cone, cone, pt)
    assert count == len(s.local_components)


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
def test_two_parabolas_against_singular():
    R = ring(["x", "y"])
    x, y = R.gens()
    J = [(y - x ** 2 - 1) * (y + x ** 2 + 1)]
    pt = primitive_element([x ** 2 + 1, y], R)
    info = classify_algebraic_point(J, pt)
    cone, count = singular_at_point(J, pt)
    assert same_over_k(info.tangent_cone, cone, pt) and count == len(info.components) == 2


WATT_I_C = "ground O A 5; body O B 2 0 E 1 2; body B C 4 0 F 2 2; bar C A 3; bar E H 3; bar H F 2"


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
def test_watt_i_algebraic_point_against_singular():
    """A Watt I six-bar whose one singular configuration is a pair of real conjugate points
    (17 t^2 - 24 t + 8 = 0): J is prime and stays prime over K (one local component, the
    tangent dimension certified modulo a prime), a singular point; the tangent cone over K
    equals Singular's tangentcone in the ring (0,t) with that minpoly."""
    a = analyze(parse_mechanism(WATT_I_C))
    [s] = a.singular
    pt = s.algebraic
    assert poly_str(normalize(pt.minpoly)) == "17*t^2-24*t+8"
    assert (s.kind, len(s.local_components)) == ("singular", 1)
    n = pt.ring.nvars - 1
    images = ",".join(f"{x}+({poly_str(c)})" for x, c in zip(pt.ring.names, pt.coords))
    out = run_singular(f"""LIB "sing.lib";
ring r = (0,t),({",".join(pt.ring.names[:n])}),ds; minpoly = {poly_str(normalize(pt.minpoly))}; short = 0;
ideal J = {",".join(poly_str(g) for g in a.ideal)};
map f = r, {images};
tangentcone(f(J));
""")
    cone = [parse_poly(pt.ring, g) for g in ideal_blocks(out)[0]]
    assert same_over_k(s.tangent_cone, cone, pt)


def test_report_text():
    a = analyze(parse_mechanism(TILTED2))
    lines = report_text(a).splitlines()
    i = lines.index("singular configurations (Theorem 1: V(J + I_3(dJ))): 1")
    assert lines[i + 1:lines.index("real answers (exact real solving):")] == [
        "  q1 = (c1,s1,c2,s2) = (-1/2*t,-t,1/2*t,t) on modes 1, 2: components meet",
        "     where t = s2, 5*t^2-4 = 0: 2 conjugate points, 2 real",
        "     tangent cone (coordinates centred at q1, coefficients in Q(t)): <c2+2*s2, c1+2*s1, s1^2-s2^2>",
        "     local components (Theorem 3): 2: <s1+s2, c1+c2, c2^2+s2^2+c2*t+2*s2*t>, "
        "<5*s1+4*c2+3*s2, 5*c1-3*c2+4*s2, c2^2+s2^2+c2*t+2*s2*t>",
        "     the local components meet transversally (their tangent cones share no line): a regular "
        "motion cannot pass from one motion mode to another here"]
    [d] = report_data(a)["singular"]
    assert (d["point"], d["primitive_element"], d["minimal_polynomial"]) == (
        ["-1/2*t", "-t", "1/2*t", "t"], "s2", "5*t^2-4")
    assert d["tangent_cone"] == ["c2+2*s2", "c1+2*s1", "s1^2-s2^2"]


def test_quick_depth_gives_the_cone():
    out = Session().execute(f'LIB "mechanism.lib"; mechanism m = "{TILTED3}"; analyze(m, "text", "quick");')
    assert "  q1 = (c1,s1,c2,s2,c3,s3) = (-t,-t,-t,-t,t,t): singular point (local components not computed" in out
    assert "tangent cone (coordinates centred at q1, coefficients in Q(t)): <c3+s3, c2+s2, c1+s1, s1^2+s2^2-2*s3^2>" in out


def test_singular_points_command():
    out = Session().execute(f'''LIB "mechanism.lib"; mechanism m = "{TILTED}";
def r = configurationRing(m); setring r;
list S = singularPoints(m);
S[1][1]; S[1][2]; size(S[1][3]); size(S[1][4]);''')
    assert out.splitlines() == ["_[1]=c2-s2", "_[2]=s1+s2", "_[3]=c1+s2", "_[4]=2*s2^2-1",
                                "components meet", "0", "0"]


def test_example_runs(tmp_path):
    res = subprocess.run([sys.executable, "-m", "mech", str(ROOT / "examples" / "slider_tilted.mech")],
                         capture_output=True, text=True, cwd=tmp_path, timeout=300)
    assert res.returncode == 0, res.stderr
    assert "where t = s2, 2*t^2-1 = 0: 2 conjugate points, 2 real" in res.stdout
    assert "where t = s3, 2*t^2-1 = 0: 2 conjugate points, 2 real" in res.stdout


def test_docs_example():
    """The report excerpt in docs/mechanisms.md (an indented ```text block) is what analyze prints."""
    import re
    blocks = re.findall(r"```text\n(.*?)```", (ROOT / "docs" / "mechanisms.md").read_text(), re.S)
    [excerpt] = [b for b in blocks if "conjugate points" in b]
    lines = [line[3:] for line in excerpt.rstrip(" ").splitlines()]
    out = Session().execute(f'LIB "mechanism.lib"; mechanism m = "{TILTED}"; analyze(m);')
    assert "\n".join(lines) in out
