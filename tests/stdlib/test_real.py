"""The real-solving commands through the language: docs/real.md's examples, errors, and agreement
with real Singular (rootsur.lib's nrroots and sturmseq, rootsmr.lib's nrRootsDeterm, solve.lib's
solve) on samples."""
from __future__ import annotations

import random
import re

import pytest

from mech import Session
from tests.util import ROOT, SINGULAR, error, run, run_singular

DOC = ROOT / "docs" / "real.md"


def test_doc_examples():
    """Each ```singular block of docs/real.md prints the ```text block after it."""
    pairs = re.findall(r"```singular\n(.*?)```\s*```text\n(.*?)```", DOC.read_text(), re.S)
    assert len(pairs) >= 7
    for src, out in pairs:
        assert Session().execute(src) == out, src


def test_commands():
    out = run("ring r = 0,x,dp; realRoots(x2+1); countRealSolutions(ideal(x3-x)); "
              "realSolutions(ideal(x2+1));")
    assert out == "empty list\n3,3\nempty list\n"
    out = run("ring r = 0,(x,y),dp; realCircuits(ideal(x2+y2+1)); realCircuits(ideal(xy-1)); "
              "realBranches(ideal(x2+y2-1), list(1,0))[3];")
    assert out == "0\n2\nregular\n"


@pytest.mark.parametrize("src,message", [
    ('LIB "rootsur.lib"; ring r = 0,(x,y),dp; nrroots(xy);', "nrroots: the polynomial must be univariate"),
    ('LIB "rootsur.lib"; ring r = 0,x,dp; sturm(x2-1, 1, 2);', "sturm: neither a nor b can be roots of p"),
    ('LIB "rootsur.lib"; ring r = 0,x,dp; sturm(x2-1, 2, 1);', "sturm: a must be lower than b"),
    ('LIB "rootsmr.lib"; ring r = 0,(x,y),dp; nrRootsDeterm(ideal(x));', "nrRootsDeterm: the ideal is not zero-dimensional"),
    ('ring r = 32003,(x,y),dp; realSolutions(ideal(x,y));', "realSolutions: only over the rationals"),
    ('ring r = 0,(x,y,z),dp; realCircuits(ideal(x2+y2+z2-1));', "realCircuits: not a curve"),
    ('ring r = 0,(x,y),dp; realBranches(ideal(x2+y2-1), list(0,0));', "realBranches: the point is not on the variety"),
    ('ring r = 0,(x,y),dp; realBranches(ideal(x2+y2-1), list(1));', "realBranches: the point has 1 coordinates"),
])
def test_errors(src, message):
    assert message in error(src).format()


def _random_univariate(rnd: random.Random) -> str:
    factors = [f"({rnd.randint(-5, 5)}x2+{rnd.randint(-5, 5)}x+{rnd.randint(-5, 5)})" for _ in range(rnd.randint(1, 3))]
    return "*".join(factors) + f"*(x-{rnd.randint(-3, 3)})^{rnd.randint(1, 2)}".replace("--", "+")


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
def test_rootsur_agrees_with_singular():
    rnd = random.Random(11)
    polys = [p for p in (_random_univariate(rnd) for _ in range(30)) if "(0x2+0x+0)" not in p]
    script = 'LIB "rootsur.lib";\nring r = 0,x,dp;\n' + "".join(f"nrroots({p});\nsturmseq({p});\n" for p in polys)
    assert run(script) == run_singular(script)


RPR = ("ring r = 0,(x1,y1,x2,y2),dp;\n"
       "poly b3x = x1 + {u}*(x2-x1) - {v}*(y2-y1); poly b3y = y1 + {u}*(y2-y1) + {v}*(x2-x1);\n"
       "ideal I = x1^2+y1^2-{r1}, (x2-{a2})^2+y2^2-{r2}, (x2-x1)^2+(y2-y1)^2-{d2}, (b3x-{a3x})^2+(b3y-{a3y})^2-{r3};\n")
DESIGNS = [dict(a2=5, a3x=6, a3y=6, d2=12, u=2, v="7/4", r1=21, r2=10, r3=18),
           dict(a2=6, a3x=7, a3y=7, d2=12, u="3/4", v=2, r1=23, r2=8, r3=33),
           dict(a2=11, a3x=4, a3y=7, d2=34, u=-1, v=2, r1=32, r2=7, r3=21)]


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
def test_rootsmr_agrees_with_singular():
    rnd = random.Random(5)
    systems = [RPR.format(**d) + "nrRootsDeterm(I);\n" for d in DESIGNS]
    for _ in range(8):
        f, g = (f"{rnd.randint(-3, 3)}x2+{rnd.randint(-3, 3)}xy+{rnd.randint(-3, 3)}y2+{rnd.randint(-3, 3)}x-"
                f"{rnd.randint(-3, 3)}y+{rnd.randint(-3, 3)}" for _ in range(2))
        systems.append(f"ring r = 0,(x,y),dp; ideal I = {f}, {g};\nif (dim(std(I)) == 0) {{ nrRootsDeterm(I); }}\n")
    for script in systems:
        script = 'LIB "rootsmr.lib";\n' + script.replace("+-", "-").replace("--", "+")
        assert run(script) == run_singular(script), script


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
@pytest.mark.parametrize("design", DESIGNS)
def test_real_solutions_agree_with_singular_solve(design):
    """Singular's solve (Laguerre on a triangular decomposition, 12 digits) finds the same real
    assembly modes."""
    script = (RPR.format(**design) + 'LIB "solve.lib";\ndef S = solve(std(I), 12, 0, "nodisplay"); setring S;\n'
              "int i; int j; for (i=1; i<=size(SOL); i++) { string s = \"\"; "
              "for (j=1; j<=4; j++) { s = s + string(SOL[i][j]) + \" \"; } print(s); kill s; }\n")
    theirs = []
    for line in run_singular(script).splitlines():
        if line and not line.startswith("//") and "i*" not in line and "setring" not in line:
            theirs.append([float(v) for v in line.split()])
    ours = Session()
    ours.execute(RPR.format(**design) + "list L = realSolutions(I, 12);")
    points = [[float(v) for v in p.items] for p in ours.interpreter.lookup("L").value.items]
    assert len(points) == len(theirs)
    for p in points:
        assert any(max(abs(a - b) for a, b in zip(p, q)) < 1e-8 for q in theirs)
