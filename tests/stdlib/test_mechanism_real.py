"""The real answers of the mechanism report (stdlib/mechanism_real.py): assembly modes of a 3-RPR
checked against Singular on an independent formulation, circuits and Grashof classes of four-bars,
real branches at a change point, the budget."""
from __future__ import annotations

import json
import math
import re
import subprocess
import sys
import time

import numpy as np
import pytest

from mech import Session
from mech.kernel import QQ, Block, MonomialOrder, PolyRing
from mech.stdlib import mechanism_real
from mech.stdlib.analysis import analyze
from mech.stdlib.mechanism import parse_mechanism
from mech.stdlib.reports import report_data, report_text
from tests.util import ROOT, parse_poly, run_singular

# base A1 = (0,0), A2 = (6,0), A3 = (0,5); platform B1, B2 = B1 + 5 (c,s), B3 = B1 + R (4,3); legs 5, 7, 4
RPR = "fix A1; fix A2 6 0; fix A3 0 5; bar A1 B1 5; bar A2 B2 7; bar A3 B3 4; body B1 B2 5 0 B3 4 3"
CRANK_ROCKER = "ground O A 5; bar O B 2; bar B C 5; bar C A 4"
CHANGE_POINT = "ground O A 5; bar O B 2; bar B C 4; bar C A 3"


def test_rpr_assembly_modes():
    a = analyze(parse_mechanism(RPR))
    d = report_data(a)["assembly_modes"]
    assert (d["complex"], d["real"], len(d["poses"])) == (6, 6, 6)
    for pose in d["poses"]:  # each pose closes the legs and keeps the platform rigid
        p = {k: np.array([float(x) for x in v]) for k, v in pose["points"].items()}
        dist = lambda u, v: float(np.linalg.norm(u - v))  # noqa: E731
        assert abs(dist(p["B1"], np.zeros(2)) - 5) < 1e-3
        assert abs(dist(p["B2"], np.array([6, 0])) - 7) < 1e-3
        assert abs(dist(p["B3"], np.array([0, 5])) - 4) < 1e-3
        assert abs(dist(p["B1"], p["B2"]) - 5) < 1e-3 and abs(dist(p["B1"], p["B3"]) - 5) < 1e-3
        assert abs(dist(p["B2"], p["B3"]) - math.sqrt(10)) < 1e-3
    text = report_text(a)
    assert "  assembly modes: 6 complex, 6 real\n" in text and "    [6] B1 = (" in text


@pytest.mark.singular
def test_rpr_against_singular():
    """Singular counts the solutions of the platform-pose formulation (B1 = (x, y), orientation
    (c, s)) and eliminates to B1's x: its real roots are the poses' x coordinates."""
    out = run_singular("""LIB "rootsmr.lib";
ring r = 0,(x,y,c,s),dp; short = 0;
ideal I = x2+y2-25, (x+5c-6)^2+(y+5s)^2-49, (x+4c-3s)^2+(y+4s+3c-5)^2-16, c2+s2-1;
ideal G = std(I);
vdim(G); nrRootsDeterm(I);
ideal E = eliminate(I, y*c*s);
print(E[1]);""")
    lines = out.split()
    assert lines[0] == "6" and lines[1] == "6"
    f = parse_poly(PolyRing(QQ, ["x"], MonomialOrder([Block("dp", 1)])), lines[2])
    deg = max(e[0] for e in f.terms)
    coeffs = [float(f.terms.get((k,), 0)) for k in range(deg, -1, -1)]
    xs = sorted(r.real for r in np.roots(coeffs) if abs(r.imag) < 1e-7)
    mine = sorted(float(p["points"]["B1"][0]) for p in report_data(analyze(parse_mechanism(RPR)))
                  ["assembly_modes"]["poses"])
    assert len(xs) == 6 and all(abs(u - v) < 1e-3 for u, v in zip(xs, mine))


def test_crank_rocker():
    d = report_data(analyze(parse_mechanism(CRANK_ROCKER)))
    assert d["grashof"]["kind"] == "crank-rocker" and d["grashof"]["grashof"]
    assert d["real_circuits"] == [{"mode": 1, "circuits": 2}]
    assert d["real_branches"] == [] and "assembly_modes" not in d


def test_change_point():
    a = analyze(parse_mechanism(CHANGE_POINT))
    d = report_data(a)
    assert d["grashof"]["kind"] == "change point" and "2 + 5 = 3 + 4" in d["grashof"]["inequality"]
    assert d["real_circuits"] == [{"mode": 1, "circuits": 1}]
    [b] = d["real_branches"]
    assert (b["configuration"], b["count"], b["half_branches"], b["type"]) == ("q1", 2, 4, "node")
    assert b["point"] == ["-1.0000", "0.0000", "1.0000", "0.0000", "1.0000", "0.0000"]
    # the tangents lie on the tangent cone 8 s2^2 + 24 s2 s3 + 3 s3^2 = 0, 2 s1 + 4 s2 + 3 s3 = 0
    for t in b["tangents"]:
        c1, s1, c2, s2, c3, s3 = (float(x) for x in t)
        assert c1 == c2 == c3 == 0
        assert abs(8 * s2 ** 2 + 24 * s2 * s3 + 3 * s3 ** 2) < 1e-3 and abs(2 * s1 + 4 * s2 + 3 * s3) < 1e-3
    assert "two real branches cross: the linkage can switch" in report_text(a)


@pytest.mark.parametrize("text, kind, circuits", [
    ("ground O A 2; bar O B 5; bar B C 4; bar C A 6", "double-crank", 2),
    ("ground O A 5; bar O B 4; bar B C 2; bar C A 6", "double-rocker", 2),
    ("ground O A 7; bar O B 4; bar B C 3; bar C A 5", "non-Grashof", 1),
])
def test_other_grashof_types(text, kind, circuits):
    d = report_data(analyze(parse_mechanism(text)))
    assert d["grashof"]["kind"] == kind
    assert d["real_circuits"] == [{"mode": 1, "circuits": circuits}]


def test_parallelogram_nodes():
    """The rhombus 1,1,1: three modes (circles) meeting at three nodes: one circuit in all."""
    a = analyze(parse_mechanism("ground O A 1; bar O B 1; bar B C 1; bar C A 1"))
    d = report_data(a)
    assert [(c["mode"], c["circuits"]) for c in d["real_circuits"]] == [(None, 1), (1, 1), (2, 1), (3, 1)]
    assert "the configuration space has 1 circuit\n" in report_text(a)
    assert [(b["count"], b["type"]) for b in d["real_branches"]] == [(2, "node")] * 3


def test_over_budget(monkeypatch):
    monkeypatch.setattr(mechanism_real, "BUDGET", 1e-4)
    a = analyze(parse_mechanism("ground O A 5; bar O B 2; bar B C 5; bar C A 3"))
    text = report_text(a)
    assert "real circuits of mode 1: too expensive, not computed" in text
    assert report_data(a)["real_circuits"] == []


def test_budget_is_cpu_time(monkeypatch):
    """The real answers' budget counts CPU time: a step that waits (a busy machine) is not cut."""
    monkeypatch.setattr(mechanism_real, "BUDGET", 0.2)
    sec = mechanism_real.RealSections()
    assert mechanism_real._step(sec, "waiting", lambda: time.sleep(0.5) or 1) == 1 and not sec.lines


def test_json_command():
    s = Session()
    out = s.execute(f'LIB "mechanism.lib"; mechanism m = "{CRANK_ROCKER}"; analyze(m, "json");')
    d = json.loads(out)
    assert d["grashof"]["kind"] == "crank-rocker" and d["real_circuits"][0]["circuits"] == 2


def _real_answers_blocks():
    """The ```singular blocks of docs/mechanisms.md's "Real answers" section, each with the ```text
    block after it and whether that block is an excerpt."""
    text = (ROOT / "docs" / "mechanisms.md").read_text()
    section = text[text.index("## Real answers"):text.index("## Limits")]
    parts = re.split(r"```(\w*)\n(.*?)```", section, flags=re.S)
    out = []
    for k in range(1, len(parts) - 3, 3):
        if parts[k] == "singular":
            nxt_tag, nxt, between = parts[k + 3], parts[k + 4], parts[k + 2]
            out.append((parts[k + 1], nxt if nxt_tag == "text" else None, "excerpt" in between))
    return out


@pytest.mark.parametrize("code, expected, excerpt", _real_answers_blocks(), ids=lambda v: str(v)[:20])
def test_docs_real_answers(code, expected, excerpt, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # exportConfigurations writes its file here
    out = Session().execute(code)
    if expected is None:
        return
    if excerpt:
        lines = out.splitlines()
        assert all(line in lines for line in expected.splitlines()), out
    else:
        assert out == expected


def test_docs_pictures(tmp_path):
    """examples/real_answers.mech draws the pictures of docs/img (sampled plots: the same elements,
    dot counts within a few percent)."""
    r = subprocess.run([sys.executable, "-m", "mech", str(ROOT / "examples" / "real_answers.mech")],
                       cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert r.returncode == 0 and not r.stderr, r.stderr
    docs = ROOT / "docs" / "img"
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == sorted(p.name for p in docs.iterdir() if p.is_file()) and len(names) == 10
    text = (ROOT / "docs" / "mechanisms.md").read_text()
    for name in names:
        assert f"img/{name}" in text
        ours, theirs = (tmp_path / name).read_text(), (docs / name).read_text()
        assert re.findall(r'class="([\w-]+)"', ours) == re.findall(r'class="([\w-]+)"', theirs)
        a, b = ours.count("M"), theirs.count("M")
        assert abs(a - b) <= 0.05 * b, name
