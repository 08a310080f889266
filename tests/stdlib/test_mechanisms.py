"""Mechanisms as values: the paper's three examples and four others, checked against the paper's
reference runs and against Singular."""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from mech import Session
from mech.dsl.errors import MechError
from mech.kernel.ideals import ideals_equal
from mech.stdlib.analysis import analyze, global_analysis, local_analysis
from mech.stdlib.realpoints import has_real_points
from mech.stdlib.reports import report_data, report_text
from mech.stdlib.mechanism import parse_mechanism
from tests.util import ROOT, SINGULAR, ideal_blocks, parse_poly, run_singular

SLIDER2 = "fix O; bar O A l1; bar A B l2; slider B"
SLIDER3 = "fix O; bar O A l1; bar A B l2; bar B C l3; slider C"
FOURBAR = "ground O A 1; bar O B l1; bar B C l2; bar C A l3"
OFFSET = "fix O; bar O A l1; bar A B l2; slider B 0 1 e"
KITE = "ground O A 1; bar O B 1; bar B C 2; bar C A 2"
FIVEBAR = "ground O A 2; bar O B 1; bar B C 1; bar C D 1; bar D A 1"
WATT = "ground O A 1; fix G 2 0; bar O B 1; bar B C 1; body A C 1 0 E 0 1; bar E F 1; bar F G 1"
STEPHENSON = "ground O A 1; fix G 2 0; bar O B 1; body B C 1 0 E 0 1; bar C A 1; bar E F 1; bar F G 1"

def polys(ring, texts):
    return [parse_poly(ring, t) for t in texts]


def same(a, b, ring):
    return ideals_equal(a, b, ring)


def same_sets(primes, others, ring):
    return len(primes) == len(others) and all(any(same(p, q, ring) for q in others) for p in primes)


def numeric(text, *values):
    m = parse_mechanism(text)
    return m.with_values(dict(zip(m.symbols(), values)))


# ---------------------------------------------------------------- the paper (Section 4)
@pytest.mark.parametrize("text, paper", [
    (SLIDER2, ["l1*s1+l2*s2", "c1^2+s1^2-1", "c2^2+s2^2-1"]),
    (SLIDER3, ["l1*s1+l2*s2+l3*s3", "c1^2+s1^2-1", "c2^2+s2^2-1", "c3^2+s3^2-1"]),
    (FOURBAR, ["l1*c1+l2*c2+l3*c3-1", "l1*s1+l2*s2+l3*s3", "c1^2+s1^2-1", "c2^2+s2^2-1", "c3^2+s3^2-1"]),
])
def test_constraints_are_the_papers(text, paper):
    R, gens = parse_mechanism(text).constraints()
    assert gens == polys(R, paper)  # the same polynomials, in the paper's order
    n = len(R.names) - len(parse_mechanism(text).symbols())
    assert [b.kind for b in R.order.blocks] == ["dp", "dp"] and R.order.blocks[0].size == n


def test_links_walk_from_either_end():
    R, gens = parse_mechanism("ground O A 1; bar O B l1; bar C B l2; bar A C l3").constraints()
    assert gens[:2] == polys(R, ["-l1*c1+l2*c2+l3*c3+1", "-l1*s1+l2*s2+l3*s3"])


def test_slider2_paper():
    a = analyze(parse_mechanism(SLIDER2))
    R = a.ring
    assert (a.dim, a.mobility, a.radical, len(a.length_components)) == (3, 1, True, 6)
    assert sorted(f.to_str() for f in a.length_factors) == ["l1+l2", "l1-l2"]
    a = analyze(numeric(SLIDER2, 1, 1))
    R = a.ring
    assert same_sets([m.prime for m in a.modes], [polys(R, ["c1-c2", "s1+s2", "c2^2+s2^2-1"]),
                                                  polys(R, ["c1+c2", "s1+s2", "c2^2+s2^2-1"])], R)
    assert all(m.real and m.dim == 1 for m in a.modes)
    assert sorted(s.point for s in a.singular) == [(0, -1, 0, 1), (0, 1, 0, -1)]
    for s in a.singular:  # the reference's cone V(s1, s2, c1^2-c2^2) at both points
        assert same(s.tangent_cone, polys(R, ["s1", "s2", "c1^2-c2^2"]), R)
        assert s.kind == "components meet" and len(s.local_components) == 2 and s.modes == [1, 2]
        assert "cannot pass" in s.transition  # Remark 2


def test_slider3_paper():
    a = analyze(parse_mechanism(SLIDER3))
    assert (a.dim, a.mobility, a.radical, len(a.length_components)) == (5, 2, True, 11)
    assert sorted(f.to_str() for f in a.length_factors) == ["l1+l2+l3", "l1+l2-l3", "l1-l2+l3",
                                                            "l1-l2-l3"]
    a = analyze(numeric(SLIDER3, 2, 1, 1))
    R = a.ring
    assert len(a.modes) == 1 and a.modes[0].dim == 2 and a.modes[0].real
    assert sorted(s.point for s in a.singular) == [(0, -1, 0, 1, 0, 1), (0, 1, 0, -1, 0, -1)]
    for s in a.singular:
        assert same(s.tangent_cone, polys(R, ["s1", "s2", "s3", "2*c1^2-c2^2-c3^2"]), R)
        assert s.kind == "singular" and len(s.local_components) == 1


def test_fourbar_paper():
    a = analyze(parse_mechanism(FOURBAR))
    assert (a.dim, a.mobility, a.radical, len(a.length_components)) == (4, 1, True, 10)
    want = {f"l1{a}l2{b}l3{c}1" for a in "+-" for b in "+-" for c in "+-"}
    assert {f.to_str() for f in a.length_factors} == want  # eight factors, not nine
    a = analyze(numeric(FOURBAR, 1, 1, 1))
    R = a.ring
    assert len(a.modes) == 3 and all(m.real and m.dim == 1 for m in a.modes)
    assert sorted(s.point for s in a.singular) == [(-1, 0, 1, 0, 1, 0), (1, 0, -1, 0, 1, 0),
                                                   (1, 0, 1, 0, -1, 0)]
    q1 = next(s for s in a.singular if s.point == (-1, 0, 1, 0, 1, 0))
    assert same(q1.tangent_cone, polys(R, ["c1", "c2", "c3", "s1+s2+s3", "s2*s3"]), R)
    for s in a.singular:
        assert s.kind == "components meet" and len(s.local_components) == 2 and len(s.modes) == 2
        assert "cannot pass" in s.transition  # Remark 3


@pytest.mark.parametrize("name", ["slider2", "slider3", "fourbar"])
def test_paper_examples_run(name, tmp_path):
    r = subprocess.run([sys.executable, "-m", "mech", str(ROOT / "examples" / f"{name}.mech")],
                       cwd=tmp_path, text=True, capture_output=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert "singularities need one of" in r.stdout and "tangent cone" in r.stdout
    assert {p.suffix for p in tmp_path.iterdir()} == {".svg"}


# ---------------------------------------------------------------- other mechanisms vs Singular
def singular_primes(ring_decl: str, ideal: str) -> list[list[str]]:
    out = run_singular(f'LIB "primdec.lib";\n{ring_decl}\n{ideal}\nlist L = minAssGTZ(J);\n'
                       'int i; for (i = 1; i <= size(L); i++) { print("---"); L[i]; }')
    return [b for b in ideal_blocks(out)]


def ring_decl(a) -> str:
    n, k = a.nvars, len(a.params)
    order = f"(dp({n}),dp({k}))" if k else "dp"
    return f"ring r = 0, ({','.join(a.ring.names)}), {order};"


def ideal_decl(name: str, gens) -> str:
    from mech.dsl.printing import poly_str
    return f"ideal {name} = " + ", ".join(poly_str(g) for g in gens) + ";"


def check_against_singular(a, modes: bool = True) -> None:
    R = a.ring
    decl = ring_decl(a)
    if modes:
        got = singular_primes(decl, ideal_decl("J", a.ideal))
        assert same_sets([m.prime for m in a.modes], [polys(R, b) for b in got], R)
    r = len(a.ideal) if a.complete_intersection else a.nvars - a.mobility
    script = ideal_decl("J0", a.ideal) + f"\nideal J = J0 + minor(jacob(J0), {r});"
    got = singular_primes(decl, script)
    assert same_sets([s.prime for s in a.singular], [polys(R, b) for b in got], R)
    for s in a.singular:
        if s.point is None:
            continue
        shift = ", ".join(f"{x}+({c})" for x, c in zip(R.names, s.point))
        out = run_singular(f'LIB "sing.lib";\n{decl}\n{ideal_decl("J", a.ideal)}\n'
                           f"map q = r, {shift};\ntangentcone(q(J));")
        assert same(s.tangent_cone, polys(R, ideal_blocks(out)[0]), R)


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular not installed")
@pytest.mark.parametrize("text, values", [(SLIDER2, (1, 1)), (SLIDER3, (2, 1, 1)), (FOURBAR, (1, 1, 1))],
                         ids=["slider2", "slider3", "fourbar"])
def test_paper_against_singular(text, values):
    """The Fitting ideal's primes and (J + P) ∩ Q[lengths] as in the reference runs; then the
    motion modes, singular points and tangent cones for the paper's lengths."""
    a = global_analysis(parse_mechanism(text))
    R = a.ring
    r, angles = a.fitting_size, "*".join(R.names[:a.nvars])
    script = ideal_decl("J0", a.ideal) + f"\nideal J = minor(jacob(J0), {r});"
    script = script.replace("jacob(J0)", f"submat(jacob(J0), 1..{len(a.ideal)}, 1..{a.nvars})")
    got = singular_primes(ring_decl(a), script)
    assert same_sets([c.prime for c in a.length_components], [polys(R, b) for b in got], R)
    for c in a.length_components:
        if c.elimination is None:
            continue
        out = run_singular(f"{ring_decl(a)}\n{ideal_decl('J', a.ideal)}\n{ideal_decl('P', c.prime)}\n"
                           f"eliminate(J + P, {angles});")
        assert same(c.elimination, polys(R, ideal_blocks(out)[0]), R)
    a = analyze(numeric(text, *values))
    check_against_singular(a)


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular not installed")
def test_offset_slider_crank_against_singular():
    a = analyze(parse_mechanism(OFFSET))
    assert sorted(f.to_str() for f in a.length_factors) == ["l1+l2+e", "l1+l2-e", "l1-l2+e", "l1-l2-e"]
    a = analyze(numeric(OFFSET, 1, 2, 1))
    assert len(a.modes) == 1 and [s.point for s in a.singular] == [(0, -1, 0, 1)]
    assert a.singular[0].kind == "singular"  # the one mode is singular there (Theorem 3)
    check_against_singular(a)


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular not installed")
def test_kite_against_singular():
    a = analyze(parse_mechanism(KITE))
    assert len(a.modes) == 2 and all(m.real for m in a.modes)
    assert sorted(s.point for s in a.singular) == [(1, 0, -1, 0, 1, 0), (1, 0, 1, 0, -1, 0)]
    assert all(s.kind == "components meet" for s in a.singular)
    check_against_singular(a)


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular not installed")
def test_fivebar_quick_against_singular():
    a = global_analysis(parse_mechanism(FIVEBAR), decompose=False)
    local_analysis(a)
    assert (a.mobility, a.radical, a.complete_intersection, len(a.singular)) == (2, True, True, 4)
    check_against_singular(a, modes=False)


def test_fivebar_one_mode(tmp_path):
    """primdecGTZ does not finish; a linear slice meeting V(J) in one Galois orbit proves J prime."""
    a = global_analysis(parse_mechanism(FIVEBAR))
    assert len(a.modes) == 1 and (a.modes[0].dim, a.modes[0].real) == (2, True)
    assert same(a.modes[0].prime, a.ideal, a.ring)
    r = subprocess.run([sys.executable, "-m", "mech", str(ROOT / "examples" / "fivebar.mech")],
                       cwd=tmp_path, text=True, capture_output=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert "motion modes (J is prime, certified by a linear slice): 1\n" in r.stdout
    assert r.stdout.count("on mode 1: singular\n") == 4  # the full analysis (local components too)


def test_symbolic_lengths_modes():
    """With symbolic lengths, the modes over Q(lengths) when a projection certifies them."""
    a = analyze(parse_mechanism(FOURBAR))
    assert [(m.dim, m.real) for m in a.modes] == [(1, None)]
    assert "  [1] dim 1: J is prime over Q(l1,l2,l3)\n" in report_text(a)
    data = report_data(a)
    assert [(m["dimension"], m["real_points"]) for m in data["motion_modes"]] == [(1, None)]


def test_motion_modes_command_with_symbolic_lengths():
    """motionModes gives the modes over Q(lengths) (real points -1: not decided), or says why not."""
    s = Session()
    out = s.execute('LIB "mechanism.lib"; mechanism m = "fix O; bar O A l1; bar A B l2; slider B";\n'
                    'def r = configurationRing(m); setring r;\n'
                    'list L = motionModes(m); size(L); L[1][2]; L[1][3]; L[1][1] == std(constraints(m));')
    assert out.split() == ["1", "1", "-1", "1"]
    with pytest.raises(MechError, match=r"modes over Q\(l1\) were not certified"):
        s.execute('mechanism f = "ground O A 2; bar O B l1; bar B C 1; bar C D 1; bar D A 1";\n'
                  'def r2 = configurationRing(f); setring r2; list L2 = motionModes(f);')


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular not installed")
def test_watt_against_singular():
    a = analyze(parse_mechanism(WATT))
    assert a.mobility == 1 and len(a.modes) == 8 and all(m.real for m in a.modes)
    assert len(a.singular) == 12 and all(s.kind == "components meet" for s in a.singular)
    check_against_singular(a)


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular not installed")
def test_stephenson_quick_against_singular():
    a = global_analysis(parse_mechanism(STEPHENSON), decompose=False)
    local_analysis(a)
    assert len(a.ideal) == 9 and a.mobility == 1 and len(a.singular) == 8
    assert [s.real for s in a.singular].count(False) == 1  # complex conjugate singular points
    check_against_singular(a, modes=False)


def test_prismatic_joint(tmp_path, monkeypatch):
    """An inverted slider-crank: B turns about O and slides along a line through A (length d2)."""
    m = parse_mechanism("fix O; fix A 2 0; bar O B 1; prismatic A B")
    R, gens = m.constraints()
    assert R.names == ("c1", "s1", "c2", "s2", "d2")
    assert gens[:2] == polys(R, ["c2*d2-c1+2", "s2*d2-s1"])
    a = analyze(m)
    assert a.mobility == 1 and len(a.modes) == 1 and a.modes[0].real and a.singular == []
    monkeypatch.chdir(tmp_path)
    Session().execute('LIB "mechanism.lib"; mechanism m = "fix O; fix A 2 0; bar O B 1; prismatic A B";'
                      'drawMechanism(m, list(1, 0, -1, 0, 1), "m.png");')
    assert (tmp_path / "m.png").stat().st_size > 0


# ---------------------------------------------------------------- real points
def test_real_points_exact():
    m = parse_mechanism("ground O A 1; bar O B 5; bar B C 1; bar C A 1")  # does not close
    R, J = m.constraints()
    assert not has_real_points(J, R)
    R, J = parse_mechanism(KITE).constraints()
    assert has_real_points(J, R)
    x, y = R.gens()[:2]
    assert not has_real_points([x ** 2 + 1, y], R)  # a conjugate pair of points
    assert has_real_points([x ** 2 - 2, y], R)  # irrational real points


# ---------------------------------------------------------------- the language
def test_language_commands():
    out = Session().execute('''LIB "mechanism.lib";
mechanism m = "fix O; bar O A l1; bar A B l2; slider B";
typeof(m); lengths(m); mobility(m);
def r = configurationRing(m); setring r;
constraints(m); lengthConditions(m);
mechanism m1 = setLengths(m, 1, 1);
def r1 = configurationRing(m1); setring r1;
list M = motionModes(m1); size(M); M[1][2]; M[1][3];
list S = singularPoints(m1); size(S); S[1][2]; S[1][3];
''')
    assert out.splitlines()[:6] == ["mechanism", "[1]:", "   l1", "[2]:", "   l2", "1"]
    assert "_[1]=s1*l1+s2*l2" in out and "_[1]=l1-l2\n_[2]=l1+l2" in out
    assert out.endswith("2\n1\n1\n2\ncomponents meet\n_[1]=s2\n_[2]=s1\n_[3]=c1^2-c2^2\n")


def test_report_formats():
    import json
    s = Session()
    s.execute('LIB "mechanism.lib"; mechanism m = "ground O A 1; bar O B 1; bar B C 2; bar C A 2";')
    data = json.loads(s.execute('analyze(m, "json");'))
    assert data["mobility"] == 1 and len(data["motion_modes"]) == 2 and len(data["singular"]) == 2
    tex = s.execute('analyze(m, "latex");')
    assert tex.startswith("\\begin{align*}") and "c_{1}^{2}+s_{1}^{2}-1" in tex


@pytest.mark.parametrize("script, message", [
    ('mechanism m = "fix O; bar O A";', "'bar' takes 3 arguments"),
    ('mechanism m = "fix O; wheel O";', "unknown statement 'wheel'"),
    ('mechanism m = "fix O; bar O A 1/0";', "divides by zero"),
    ('mechanism m = "fix O; bar O A 1.5";', "is not a length"),
    ('mechanism m = "";', "empty mechanism description"),
    ('mechanism m = "bar O A 1"; mobility(m);', "nothing is fixed"),
    ('mechanism m = "fix O; bar B C 1"; mobility(m);', "not connected to a fixed point"),
    ('mechanism m = "fix O; fix A 5 0; bar O A 1"; mobility(m);',
     "statement 3 'bar O A 1': both ends are fixed, 5 apart: a bar of length 1 does not fit"),
    ('mechanism m = "ground O A 1; bar O B 5; bar B C 1; bar C A 1"; mobility(m);', "does not close"),
    ('mechanism m = "fix O; bar O A l"; mechanism n = setLengths(m, 1, 2);', "1 symbolic lengths"),
    ('mechanism m = "fix O; bar O A l; bar A B 1; slider B"; singularPoints(m);', "needs numeric lengths"),
    ('mechanism m = 3;', "cannot convert int to mechanism"),
    ('mechanism m;', "declared with its description"),
    ('mechanism m = "fix O; bar O A 1; bar A B 1; slider B"; plotConfigurations(m, "x.pdf");', ".png or .svg"),
    ('mechanism m = "fix O; bar O A 1; bar A B 1; slider B"; drawMechanism(m, list(1, 0), "x.svg");',
     "4 values expected"),
    ('mechanism m = "fix O; bar O A 1; bar A B 1; slider B"; drawMechanism(m, list(1,0,1,1), "x.svg");',
     "not a configuration"),
])
def test_errors_are_clear(script, message):
    with pytest.raises(MechError) as e:
        Session().execute('LIB "mechanism.lib"; ' + script)
    assert message in str(e.value)


def test_cli_error_has_no_traceback(tmp_path):
    f = tmp_path / "bad.mech"
    f.write_text('LIB "mechanism.lib";\nmechanism m = "fix O; bar O A l; bar A B";\n')
    r = subprocess.run([sys.executable, "-m", "mech", str(f)], text=True, capture_output=True, timeout=120)
    assert r.returncode != 0 and "Traceback" not in r.stderr
    assert re.search(r"bad.mech:2:1: error: mechanism: statement 3 'bar A B'", r.stderr)


# ---------------------------------------------------------------- documentation
def code_blocks(path: Path) -> list[tuple[str, str | None]]:
    """The untagged (or ```mech) code blocks of a markdown file, each with the ```text block printed after it."""
    text = path.read_text()
    blocks = re.findall(r"```(\w*)\n(.*?)```", text, re.S)
    out = []
    for i, (tag, code) in enumerate(blocks):
        if tag in ("", "mech"):
            nxt = blocks[i + 1] if i + 1 < len(blocks) else None
            out.append((code, nxt[1] if nxt and nxt[0] == "text" else None))
    return out


def test_docs_examples(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    s = Session()
    blocks = code_blocks(ROOT / "docs" / "mechanisms.md")
    assert len(blocks) == 11
    for code, expected in blocks:
        out = s.execute(code)
        if expected is not None:
            assert out == expected
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bennett_AC.svg", "bennett_top.svg", "fourbar_13.png", "fourbar_modes.svg",
                                                          "q1.svg"]


def test_readme_example():
    code = next(c for c, _ in code_blocks(ROOT / "README.md") if "mechanism.lib" in c)
    out = Session().execute(code)
    assert "singularities need one of: l1-l2-l3-1 = 0" in out
    assert out.count(": components meet") == 3


def test_cli_json(tmp_path):
    r = subprocess.run([sys.executable, "-m", "mech", "--json", str(ROOT / "examples" / "kite.mech")],
                       cwd=tmp_path, text=True, capture_output=True, timeout=300)
    import json
    data = json.loads(r.stdout)
    assert data["mobility"] == 1 and [len(s["local_components"]) for s in data["singular"]] == [2, 2]
    assert (tmp_path / "kite_modes.png").exists()


def test_block_form_is_the_same_mechanism():
    s = Session()
    s.execute('LIB "mechanism.lib";\nmechanism a {\n  ground O A 1;\n  bar O B l1; bar B C l2;\n'
              '  bar C A l3;\n}\nmechanism b = "ground O A 1; bar O B l1; bar B C l2; bar C A l3";\n'
              'mechanism c { fix O -1/2 3; bar O P 2; slider P 0 1 -1/2; }')
    assert str(s["a"]) == str(s["b"]) and s.eval("typeof(a)") == "mechanism"
    assert "fix O -1/2 3" in str(s["c"])
    with pytest.raises(MechError) as e:
        s.execute("mechanism d {\n  ground O A 1;\n  rod O B 2;\n}")
    assert e.value.format().startswith("<string>:3:3: error: unknown mechanism statement 'rod'")
    with pytest.raises(MechError, match="declares a mechanism, not a int"):
        s.execute("int k { bar O B 1; }")
