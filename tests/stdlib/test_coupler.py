"""Coupler curves (stdlib/coupler.py): the implicit equation against points sampled from the
linkage, its tricircular top-degree part, Singular's elimination, the example and the errors."""
from __future__ import annotations

import re
import subprocess
import sys

import pytest

from mech.kernel import QQ, Block, MonomialOrder, PolyRing
from mech.stdlib.coupler import coupler_curve, coupler_path
from mech.stdlib.mechanism import parse_mechanism
from tests.util import ROOT, error, parse_poly, run_singular

FOURBAR = "ground O A 5; bar O B 2; body B C 5 0 F 5/2 2; bar C A 4"


def _value(p, x, y):
    terms = [float(c.p) / float(c.q) * x ** e[0] * y ** e[1] for e, c in p.terms.items()]
    return sum(terms), sum(abs(t) for t in terms)


def test_sextic_through_sampled_points():
    m = parse_mechanism(FOURBAR)
    [c] = coupler_curve(m, "F")
    assert c.total_degree() == 6
    xy, configs = coupler_path(m, "F", 400)
    assert len(xy) > 300
    for x, y in xy:
        value, size = _value(c, x, y)
        assert abs(value) < 1e-9 * size
    # a point of the plane off the path is not on the curve
    assert abs(_value(c, 0.0, 0.0)[0]) > 1


def test_tricircular():
    """The top-degree part of a four-bar coupler curve is a multiple of (x^2 + y^2)^3."""
    [c] = coupler_curve(parse_mechanism(FOURBAR), "F")
    R = c.ring
    top = {e: v for e, v in c.terms.items() if sum(e) == 6}
    x, y = R.gens()
    circ = (x * x + y * y) ** 3
    k = top[(6, 0)]
    assert top == {e: v * k for e, v in circ.terms.items()}


@pytest.mark.singular
def test_against_singular():
    out = run_singular("""ring r = 0,(c1,s1,c2,s2,c3,s3,x,y),dp; short = 0;
ideal J = 2*c1+5*c2+4*c3-5, 2*s1+5*s2+4*s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1,
  x-(2*c1+5/2*c2-2*s2), y-(2*s1+5/2*s2+2*c2);
ideal E = eliminate(J, c1*s1*c2*s2*c3*s3);
size(E); print(E[1]);""")
    size, poly = out.split()
    R = PolyRing(QQ, ["x", "y"], MonomialOrder([Block("dp", 2)]))
    theirs = parse_poly(R, poly)
    [mine] = coupler_curve(parse_mechanism(FOURBAR), "F")
    assert size == "1"
    ratio = theirs.terms[(6, 0)] / mine.terms[(6, 0)]
    assert theirs == mine * R.const(ratio)


def test_slider_crank_paths():
    m = parse_mechanism("fix O; bar O A 1; bar A B 2; slider B")
    x, y = PolyRing(QQ, ["x", "y"], MonomialOrder([Block("dp", 2)])).gens()
    assert coupler_curve(m, "A") == [x * x + y * y - 1]
    assert coupler_curve(m, "B") == [y]


def test_example(tmp_path):
    r = subprocess.run([sys.executable, "-m", "mech", str(ROOT / "examples" / "coupler.mech")], cwd=tmp_path,
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    assert lines[0].startswith("1600x6+4800x4y2+4800x2y4+1600y6-") and lines[1:] == ["6", "2"]
    svg = (tmp_path / "coupler.svg").read_text()
    path = re.search(r'<path class="path" d="([^"]*)"', svg).group(1)
    assert path.count("M") > 500  # one dot per sampled position


@pytest.mark.parametrize("code, message", [
    ('couplerCurve(m, "O");', "O is fixed"),
    ('couplerCurve(m, "Z");', "has no point Z"),
    ('mechanism s = "ground O A 5; bar O B a; bar B C 5; bar C A 4";\ncouplerCurve(s, "B");',
     "needs numeric lengths"),
    ('mechanism s = "fix O; bar O A 1; bar A B 1";\ncouplerCurve(s, "B");', "sweeps a region"),
    ('mechanism s = "ground O A 2; bar O B 1; bar B A 1";\ncouplerCurve(s, "B");', "not a plane curve"),
    ('plotCouplerCurve(m, "F", "p.svg", 0);', "number of samples"),
])
def test_errors(code, message):
    e = error(f'LIB "mechanism.lib"; mechanism m = "{FOURBAR}"; ring r = 0,(x,y),dp;\n{code}')
    assert message in str(e)


def test_basering_needs_x_y():
    e = error(f'LIB "mechanism.lib"; mechanism m = "{FOURBAR}"; ring r = 0,(u,v),dp;\ncouplerCurve(m, "F");')
    assert "needs the variables x and y" in str(e)
