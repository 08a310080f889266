"""Mechanisms beyond planar linkages with a fixed pivot: the examples (trammel, Whitworth, Bennett,
spatial 4R, spherical 4R, Bricard, Stewart–Gough) run, and their mobility and motion modes agree with
ideals written independently here in point coordinates (axes as points and unit directions,
platform points), decided by real Singular."""
from __future__ import annotations

import json
import subprocess
import sys
from fractions import Fraction as F

import pytest

from mech.dsl.printing import poly_str
from mech.stdlib.mechanism import parse_mechanism
from tests.util import ROOT, SINGULAR, run_singular

EXAMPLES = ROOT / "examples"


def example(name: str, tmp_path) -> dict:
    """The JSON report the example prints (its last statement is analyze(m, "json"))."""
    r = subprocess.run([sys.executable, "-m", "mech", str(EXAMPLES / f"{name}.mech")], cwd=tmp_path,
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout.splitlines()[-1])


def description(name: str) -> str:
    """The mechanism's description in the example file (the string after 'mechanism m =')."""
    text = (EXAMPLES / f"{name}.mech").read_text()
    return text.split('mechanism m = "', 1)[1].split('"', 1)[0]


@pytest.mark.parametrize("name, mobility, modes, configurations", [
    ("trammel", 1, 1, None),
    ("whitworth", 1, 1, None),
    ("bennett", 1, 1, None),
    ("spatial4r", 0, 2, 2),
    ("spherical4r", 1, 1, None),
    ("stewart33", 0, 1, 16),
    ("spatial_slider", 1, 1, None),
    ("twoloops", 1, 1, None),
    ("screw", 2, 1, None),  # the helical coupling is not in the ideal: the screw itself has one freedom
])
def test_examples(name, mobility, modes, configurations, tmp_path):
    d = example(name, tmp_path)
    assert (d["mobility"], len(d["motion_modes"]), d.get("complex_configurations")) == (mobility, modes,
                                                                                        configurations)
    assert all(m["real_points"] for m in d["motion_modes"])
    if name == "trammel":
        assert d["singular"] == []  # the trammel has no singular configuration
    if name == "bennett":
        assert (d["gruebler_kutzbach"], d["overconstrained"]) == (-2, True)


# ---------------------------------------------------------------- independent ideals in Singular
def _cross(a, b):
    return [f"(({a[1]})*({b[2]})-({a[2]})*({b[1]}))", f"(({a[2]})*({b[0]})-({a[0]})*({b[2]}))",
            f"(({a[0]})*({b[1]})-({a[1]})*({b[0]}))"]


def loop_ideal(links: list[tuple]) -> tuple[list[str], list[str]]:
    """A loop of revolute joints with offsets 0, link i (length a_i, twist (c_i, s_i)) from axis i to
    axis i+1: axis i is a point P_i and a unit direction u_i with a_i u_i x u_{i+1} = s_i (P_{i+1} - P_i)
    and u_i.u_{i+1} = c_i.  Link n is the ground: axis 1 the z-axis, axis n through (-a_n, 0, 0) along
    (0, s_n, c_n)."""
    n = len(links)
    an, (cn, sn) = links[-1]
    P = {1: ("0", "0", "0"), n: (str(-an), "0", "0")}
    U = {1: ("0", "0", "1"), n: ("0", str(sn), str(cn))}
    names: list[str] = []
    for i in range(2, n):
        P[i], U[i] = tuple(f"p{i}{x}" for x in "xyz"), tuple(f"u{i}{x}" for x in "xyz")
        names += list(P[i]) + list(U[i])
    eqs = []
    for i in range(1, n):
        a, (c, s) = links[i - 1]
        x = _cross(U[i], U[i + 1])
        eqs += [f"({a})*{x[k]}-({s})*(({P[i + 1][k]})-({P[i][k]}))" for k in range(3)]
        eqs.append("+".join(f"({U[i][k]})*({U[i + 1][k]})" for k in range(3)) + f"-({c})")
    eqs += ["+".join(f"({u})^2" for u in U[i]) + "-1" for i in range(2, n)]
    return names, eqs


def singular_dim_and_primes(names: list[str], eqs: list[str], primes: bool = True) -> tuple[int, int | None]:
    script = (f'LIB "primdec.lib"; ring r = 0, ({",".join(names)}), dp; ideal J = {", ".join(eqs)};\n'
              'print("dim " + string(dim(std(J))));\n')
    if primes:
        script += 'print("primes " + string(size(minAssGTZ(J))));\n'
    out = dict(line.split() for line in run_singular(script, timeout=300).splitlines() if line.strip())
    return int(out["dim"]), int(out["primes"]) if primes else None


R90, R35, R513 = (0, 1), (F(3, 5), F(4, 5)), (F(5, 13), F(12, 13))


@pytest.mark.singular
@pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")
@pytest.mark.parametrize("name, links, mobility, modes", [
    ("bennett", [(1, R90), (F(4, 5), R35), (1, R90), (F(4, 5), R35)], 1, 1),
    ("spatial4r", [(1, R90), (1, R35), (1, R90), (1, R35)], 0, 2),
    ("spherical4r", [(0, R90), (0, R35), (0, R90), (0, R513)], 1, 1),
])
def test_loops_against_axes_in_singular(name, links, mobility, modes, tmp_path):
    assert singular_dim_and_primes(*loop_ideal(links)) == (mobility, modes)
    d = example(name, tmp_path)
    assert (d["mobility"], len(d["motion_modes"])) == (mobility, modes)


@pytest.mark.singular
@pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")
def test_bricard_is_mobile_in_singular():
    """The line-symmetric Bricard 6R: its axes' ideal (24 variables) and mech's loop closure both have
    dimension 1 (mech's own analysis of this loop takes minutes: docs/mechanisms.md, Limits)."""
    links = [(1, R90), (2, R35), (3, R513)] * 2
    assert singular_dim_and_primes(*loop_ideal(links), primes=False) == (1, None)
    R, gens = parse_mechanism(description("bricard")).constraints()
    assert singular_dim_and_primes(list(R.names), [poly_str(g) for g in gens], primes=False) == (1, None)


def singular_primes_mod_p(names: list[str], eqs: list[str]) -> list[int]:
    """The dimensions of the minimal primes of the ideal over Z/32003 (Singular's minAssGTZ)."""
    script = (f'LIB "primdec.lib"; ring r = 32003, ({",".join(names)}), dp; ideal J = {", ".join(eqs)};\n'
              'list L = minAssGTZ(J); int i; for (i = 1; i <= size(L); i++) { print("dim " + string(dim(std(L[i])))); }\n')
    return sorted(int(line.split()[1]) for line in run_singular(script, timeout=600).splitlines() if line.strip())


@pytest.mark.slow
@pytest.mark.singular
@pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")
def test_bricard_two_modes_in_singular(tmp_path):
    """The line-symmetric Bricard 6R moves in two modes: two minimal primes of dimension 1 over Z/32003 for
    the axes' ideal (24 variables, written here) and for mech's loop closure (a prime over Q stays a union
    of primes modulo a good prime, so at most two over Q), and mech's motionModes finds two over Q."""
    links = [(1, R90), (2, R35), (3, R513)] * 2
    assert singular_primes_mod_p(*loop_ideal(links)) == [1, 1]
    R, gens = parse_mechanism(description("bricard")).constraints()
    assert singular_primes_mod_p(list(R.names), [poly_str(g) for g in gens]) == [1, 1]
    script = (f'LIB "mechanism.lib"; mechanism m = "{description("bricard")}"; def R = configurationRing(m); '
              'setring R; list L = motionModes(m); size(L); L[1][2]; L[2][2];')
    r = subprocess.run([sys.executable, "-m", "mech", "-c", script], cwd=tmp_path, capture_output=True, text=True,
                       timeout=1200)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["2", "1", "1"]


@pytest.mark.singular
@pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")
@pytest.mark.parametrize("name, names, eqs, mobility, modes", [
    ("trammel", ["xa", "ya", "xb", "yb"], ["ya", "xb", "(xb-xa)^2+(yb-ya)^2-4"], 1, 1),
    ("whitworth", ["xa", "ya", "xb", "yb", "xc", "yc"],
     ["xa^2+(ya-1)^2-1", "xb^2+(yb-1/2)^2-4", "xb*(ya-1/2)-(yb-1/2)*xa", "(xc-xb)^2+(yc-yb)^2-9", "yc"], 1, 1),
])
def test_planar_points_in_singular(name, names, eqs, mobility, modes, tmp_path):
    assert singular_dim_and_primes(names, eqs) == (mobility, modes)
    d = example(name, tmp_path)
    assert (d["mobility"], len(d["motion_modes"])) == (mobility, modes)


@pytest.mark.singular
@pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")
@pytest.mark.parametrize("name, names, eqs, mobility, modes", [
    # the rail's point A = (ax, ay, 0) on the door's circle; X on the vertical line through it, |X - Q| = 2
    ("spatial_slider", ["ax", "ay", "x", "y", "z"], ["ax^2+ay^2-4", "x-ax", "y-ay", "(x-3)^2+y^2+z^2-4"], 1, 1),
    # the flap's hinge through A = (ax, ay, 0) along (-ay, ax, 0); E at 1 from A, square to the hinge, |E - Q| = 2
    ("twoloops", ["ax", "ay", "ex", "ey", "ez"],
     ["ax^2+ay^2-4", "(ex-ax)^2+(ey-ay)^2+ez^2-1", "-(ex-ax)*ay+(ey-ay)*ax", "ex^2+(ey-3)^2+(ez-1)^2-4"], 1, 1),
])
def test_spatial_points_in_singular(name, names, eqs, mobility, modes, tmp_path):
    assert singular_dim_and_primes(names, eqs) == (mobility, modes)
    d = example(name, tmp_path)
    assert (d["mobility"], len(d["motion_modes"])) == (mobility, modes)
    # a body hinged to the ground (or to another body) by two shared points is a revolute joint (5
    # constraints): the count equals the mobility, so the report has no count
    assert "gruebler_kutzbach" not in d


def stewart_ideal(base, platform, legs) -> tuple[list[str], list[str]]:
    """Platform points p1, p2, p3 as variables (their distances fixed), each leg |p - b|^2 = l^2."""
    names = [f"p{i}{x}" for i in (1, 2, 3) for x in "xyz"]
    eqs = []
    for i, j in ((1, 2), (1, 3), (2, 3)):
        (ui, vi), (uj, vj) = platform[i - 1], platform[j - 1]
        eqs.append("+".join(f"(p{i}{x}-p{j}{x})^2" for x in "xyz") + f"-{(ui - uj) ** 2 + (vi - vj) ** 2}")
    for b, p, length in legs:
        bx, by = base[b]
        eqs.append(f"(p{p}x-({bx}))^2+(p{p}y-({by}))^2+p{p}z^2-{length ** 2}")
    return names, eqs


@pytest.mark.singular
@pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")
def test_stewart_assembly_modes_in_singular(tmp_path):
    base = [(0, 0), (4, 0), (5, 3), (2, 6), (-1, 5), (-2, 1)]
    names, eqs = stewart_ideal(base, [(0, 0), (2, 0), (1, 2)],
                               [(0, 1, 5), (1, 1, 5), (2, 2, 6), (3, 2, 6), (4, 3, 5), (5, 3, 6)])
    script = (f'LIB "primdec.lib"; LIB "rootsmr.lib"; ring r = 0, ({",".join(names)}), dp; '
              f'ideal J = {", ".join(eqs)};\n'
              'ideal G = std(J); print(string(dim(G)) + " " + string(vdim(G)) + " " + '
              'string(vdim(std(radical(J)))) + " " + string(nrRootsDeterm(G)));\n')
    assert run_singular(script, timeout=300).split() == ["0", "16", "16", "8"]   # 8 real (Hermite's form)
    d = example("stewart33", tmp_path)
    assert (d["mobility"], d["complex_configurations"]) == (0, 16)
    modes = d["assembly_modes"]
    assert (modes["complex"], modes["real"], len(modes["poses"])) == (16, 8, 8)
    for pose in modes["poses"]:                 # each real pose: legs of the design's lengths (to 4 decimals)
        p1 = [float(c) for c in pose["points"]["P1"]]
        assert abs(sum(c * c for c in p1) - 25) < 1e-2


@pytest.mark.singular
@pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")
def test_screw_against_a_cylindrical_joint_in_singular(tmp_path):
    """The screw's ideal is that of the same loop with a cylindrical joint (written here in the angles of
    screw and nut and the slides): dimension 2, one prime; the helical coupling takes one freedom off."""
    names = ["c1", "s1", "c2", "s2", "h", "t"]  # screw angle, nut-on-screw angle and slide, nut slide
    eqs = ["c1^2+s1^2-1", "c2^2+s2^2-1", "c1*c2-s1*s2-1", "s1*c2+c1*s2", "h+t"]  # the nut does not turn
    assert singular_dim_and_primes(names, eqs) == (2, 1)
    d = example("screw", tmp_path)
    assert (d["mobility"], len(d["motion_modes"])) == (2, 1)


@pytest.mark.slow
@pytest.mark.singular
@pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")
def test_geared_fivebar_in_singular(tmp_path):
    """The geared five-bar in the points: A on the unit circle about O, B - Q = conj(A - O)^2 (the gear at Q
    turns twice as fast, the other way), |C - A| = |C - B| = 2: dimension 1, one prime; mech's analysis agrees
    (about a minute: the gears' relation has degree 2)."""
    names = ["a1", "a2", "b1", "b2", "x", "y"]
    eqs = ["a1^2+a2^2-1", "b1-(a1^2-a2^2)", "b2+2*a1*a2", "(x-a1)^2+(y-a2)^2-4", "(x-2-b1)^2+(y-b2)^2-4"]
    assert singular_dim_and_primes(names, eqs) == (1, 1)
    d = example("geared_fivebar", tmp_path)
    assert (d["mobility"], len(d["motion_modes"])) == (1, 1)
    assert "gruebler_kutzbach" not in d  # shown only when it differs from the mobility: the count is 1 too


def test_sliders_and_prismatic_legs_in_space():
    """In space a slider keeps its point on the line of two points of one link (three cross-product
    polynomials), a prismatic bar's length d_i is a variable (|B - A|^2 = d_i^2), and a slider on
    two points of different links is refused, naming the statement."""
    m = parse_mechanism("fix O 0 0 0; fix Q 1 0 0; prismatic O A; bar Q A 1")
    R, gens = m.constraints()
    assert m.variables() == ["d1", "x_A", "y_A", "z_A"] and m.gruebler_kutzbach() == 2
    assert [poly_str(g) for g in gens] == ["-d1^2+x_A^2+y_A^2+z_A^2", "x_A^2+y_A^2+z_A^2-2*x_A"]
    from mech import Session
    shown = Session().execute(f'LIB "mechanism.lib"; mechanism m = "{m}"; jointAngles(m, list(2, 2, 0, 0));')
    assert shown == "d1 2\n"  # A = (2, 0, 0): the leg's length 2
    m = parse_mechanism("fix O 0 0 0; fix P 2 0 0; bar O X 3; slider X O P")  # X on the x-axis: X = (+-3, 0, 0)
    R, gens = m.constraints()
    assert [poly_str(g) for g in gens] == ["x_X^2+y_X^2+z_X^2-9", "-2*z_X", "2*y_X"]  # the x-component is 0
    with pytest.raises(Exception) as e:
        parse_mechanism("fix O 0 0 0; fix P 2 0 0; bar O X 3; bar P Y 1; slider X O Y").constraints()
    assert "statement 5 'slider X O Y': O and Y are neither points of one link" in str(e.value)


@pytest.mark.slow
def test_bricard_local_analysis_finishes(tmp_path):
    """Bricard's four singular configurations (where its two modes meet) are classified from the modes:
    two local components each, meeting transversally; the tangent cone of J there (a local standard basis
    that Singular does not finish in a minute either) is given as a set and said so (about 2 min of CPU)."""
    d = example("bricard", tmp_path)
    assert (d["mobility"], len(d["motion_modes"]), len(d["singular"])) == (1, 2, 4)
    for s in d["singular"]:
        assert (s["kind"], s["modes"], len(s["local_components"])) == ("components meet", [1, 2], 2)
        assert s["transition"].startswith("the local components meet transversally")
        assert s.get("tangent_cone_note", "").startswith("as a set") or "tangent_cone_note" not in s
    assert not any(u.startswith(("local components", "tangent cone")) for u in d["unfinished"])
