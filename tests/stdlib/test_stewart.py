"""The generic 6-6 Stewart–Gough platform (examples/stewart.mech): mech counts its assembly modes
exactly over Q (40 complex, 2 real) with ``analyze``; Singular counts 40 on an ideal written here independently, in
the world coordinates of three platform points."""
from __future__ import annotations

import json
import re
import subprocess
import sys
from fractions import Fraction as F

import pytest

from tests.util import ROOT, SINGULAR, run_singular

EXAMPLE = ROOT / "examples" / "stewart.mech"


def design() -> tuple[list[tuple[int, ...]], list[tuple[int, ...]], list[int]]:
    """Base points, platform points (local, P1 at the origin) and leg lengths, read off the example's
    text (not through mech's parser)."""
    text = EXAMPLE.read_text()
    base = [tuple(map(int, re.search(rf"fix B{i} (-?\d+) (-?\d+) (-?\d+)", text).groups())) for i in range(1, 7)]
    plat = [(0, 0, 0)] + [tuple(map(int, re.search(rf"P{i} (-?\d+) (-?\d+) (-?\d+)", text).groups()))
                          for i in range(2, 7)]
    legs = [int(re.search(rf"bar B{i} P{i} (\d+)", text).group(1)) for i in range(1, 7)]
    return base, plat, legs


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _det(c1, c2, c3):
    return sum(x * y for x, y in zip(c1, _cross(c2, c3)))


def frame_coordinates(q, u, v):
    """``(a, b, c)`` with ``q = a u + b v + c (u x v)`` (Cramer's rule)."""
    w = _cross(u, v)
    d = F(_det(u, v, w))
    return _det(q, v, w) / d, _det(u, q, w) / d, _det(u, v, q) / d


def point_ideal() -> tuple[list[str], list[str]]:
    """Unknowns: P1, P2, P3 in world coordinates; P4..P6 are P1 + a (P2-P1) + b (P3-P1) + c (P2-P1) x
    (P3-P1).  Equations: the three distances of P1 P2 P3 and the six legs."""
    base, plat, legs = design()
    P = [tuple(f"{x}{i}" for x in "XYZ") for i in (1, 2, 3)]
    U = [f"({P[1][k]}-{P[0][k]})" for k in range(3)]
    V = [f"({P[2][k]}-{P[0][k]})" for k in range(3)]
    W = [f"({U[1]}*{V[2]}-{U[2]}*{V[1]})", f"({U[2]}*{V[0]}-{U[0]}*{V[2]})", f"({U[0]}*{V[1]}-{U[1]}*{V[0]})"]
    u, v = [F(a - b) for a, b in zip(plat[1], plat[0])], [F(a - b) for a, b in zip(plat[2], plat[0])]
    for q in plat[3:]:
        a, b, c = frame_coordinates([F(x - y) for x, y in zip(q, plat[0])], u, v)
        P.append(tuple(f"({P[0][k]}+({a})*{U[k]}+({b})*{V[k]}+({c})*{W[k]})" for k in range(3)))

    def sq(p, q):
        return "+".join(f"({a}-({b}))^2" for a, b in zip(p, q))
    eqs = [f"{sq(P[i], P[j])}-{sum((x - y) ** 2 for x, y in zip(plat[i], plat[j]))}" for i, j in ((0, 1), (0, 2), (1, 2))]
    eqs += [f"{sq(P[i], base[i])}-{legs[i] ** 2}" for i in range(6)]
    return [x for p in P[:3] for x in p], eqs


def test_home_pose_is_an_assembly():
    """The platform unrotated with P1 = (3, 0, 6) fits the legs (the data are consistent)."""
    base, plat, legs = design()
    for b, q, l in zip(base, plat, legs):
        assert sum((x + o - y) ** 2 for x, o, y in zip(q, (3, 0, 6), b)) == l * l


def test_example_analysis_counts_40_assembly_modes(tmp_path):
    """analyze(m, "json") goes the zero-dimensional way: mobility 0, J radical (40 distinct = vdim), two
    Galois orbits over Q (the home pose and 39 conjugates), 2 real poses, the Jacobian of full rank 9 at all
    40 configurations, no singular configuration."""
    r = subprocess.run([sys.executable, "-m", "mech", str(EXAMPLE)], cwd=tmp_path, capture_output=True,
                       text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    d = json.loads(r.stdout.splitlines()[-1])
    assert (d["dimension"], d["mobility"], d["radical"], d["complex_configurations"]) == (0, 0, True, 40)
    am = d["assembly_modes"]
    assert (am["complex"], am["real"], am["with_multiplicity"], len(am["poses"])) == (40, 2, 40, 2)
    assert [(o["configurations"], o["real"], o["jacobian_rank"]) for o in d["assembly_orbits"]] == [(1, 1, 9), (39, 1, 9)]
    assert [m["dimension"] for m in d["motion_modes"]] == [0, 0] and d["singular"] == [] and d["unfinished"] == []
    home = {"P1": ["3.0000", "0.0000", "6.0000"], "P2": ["0.0000", "3.0000", "7.0000"], "P3": ["2.0000", "-3.0000", "6.0000"]}
    assert sum(all(p["points"][k] == v for k, v in home.items()) for p in am["poses"]) == 1


@pytest.mark.singular
@pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")
def test_40_in_singular_on_point_coordinates():
    """Singular's std over Z/32003 of the independent ideal: dimension 0, 40 solutions with multiplicity
    (mech's count above is over Q and of distinct solutions)."""
    names, eqs = point_ideal()
    out = run_singular(f'ring r = 32003, ({",".join(names)}), dp; ideal I = {", ".join(eqs)};\n'
                       'ideal G = std(I); print("dim " + string(dim(G))); print("vdim " + string(vdim(G)));',
                       timeout=300)
    assert dict(line.split() for line in out.splitlines() if line.strip()) == {"dim": "0", "vdim": "40"}


@pytest.mark.singular
@pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")
def test_no_singular_configuration_in_singular():
    """The Jacobian determinant of the independent ideal vanishes at none of its 40 solutions (over Z/32003:
    J + <det> is the unit ideal), as mech's exact rank check on each Galois orbit finds (full rank 9)."""
    names, eqs = point_ideal()
    out = run_singular(f'ring r = 32003, ({",".join(names)}), dp; ideal I = {", ".join(eqs)};\n'
                       'ideal G = std(I); poly D = reduce(det(jacob(I)), G); print("dim " + string(dim(std(G + D))));',
                       timeout=600)
    assert out.split() == ["dim", "-1"]
