"""The Macaulay2 dialect: its corpus (expected outputs from real Macaulay2 1.21, `M2 --script`),
parsing, errors, the Session / CLI / REPL hooks.

Corpus lines must match Macaulay2's byte for byte, except where Macaulay2's choice of generators or
of the order of components differs from mech's (minimal generators vs reduced bases, the order of
minimalPrimes' list): those lines are read back as Macaulay2 expressions and compared as ideals,
sets of ideals, polynomials.  ``INEXACT`` lists how many such lines each file has.
"""
from __future__ import annotations

import io
import shutil
import subprocess
from pathlib import Path

import pytest

from mech import Session
from mech.dsl import m2
from mech.dsl.errors import MechError, MechSyntaxError
from mech.dsl.values import Ideal, List, Matrix
from mech.kernel import Poly
from mech.kernel.ideals import std

from tests.util import ROOT

CORPUS = ROOT / "tests" / "corpus_m2"
SCRIPTS = sorted(CORPUS.glob("*.m2"))
M2 = shutil.which("M2")
#: lines (per file) where mech's output is mathematically, not textually, Macaulay2's
INEXACT = {"primdec.m2": 3, "local.m2": 1}


def chunks(text: str) -> list[str]:
    """The script's top-level statements as runnable pieces of whole lines (statements sharing a
    line stay together; comment lines are left out)."""
    lines = text.splitlines()
    spans: list[list[int]] = []
    for s in m2.parse(text).body:
        a, b = s.pos.line, s.pos.end_line
        if spans and a <= spans[-1][1]:
            spans[-1][1] = max(b, spans[-1][1])
        else:
            spans.append([a, b])
    return ["\n".join(lines[a - 1:b]) for a, b in spans]


def same(a, b) -> bool:
    """Equal as Macaulay2 values: ideals as ideals, lists of ideals as sets."""
    if isinstance(a, Ideal) and isinstance(b, Ideal):
        return std(a.nonzero(), ring=a.ring) == std(b.nonzero(), ring=b.ring)
    if isinstance(a, List) and isinstance(b, List):
        if len(a.items) != len(b.items):
            return False
        rest = list(b.items)
        for x in a.items:
            match = next((y for y in rest if same(x, y)), None)
            if match is None:
                return False
            rest.remove(match)
        return True
    if isinstance(a, Matrix) and isinstance(b, Matrix):
        return (a.nrows, a.ncols) == (b.nrows, b.ncols) and list(a.entries) == list(b.entries)
    return a == b


def run_corpus(path: Path) -> tuple[list[str], int]:
    """mech's output of the script and the number of lines equal only mathematically."""
    s = Session(dialect="m2")
    expected = path.with_suffix(".out").read_text().splitlines()
    got: list[str] = []
    inexact = 0
    for piece in chunks(path.read_text()):
        lines = s.execute(piece).splitlines()
        for line in lines:
            want = expected[len(got)] if len(got) < len(expected) else "<nothing>"
            if line != want:
                assert same(s.eval(line), s.eval(want)), f"{path.name}: got {line}, Macaulay2 printed {want}"
                inexact += 1
            got.append(line)
    assert len(got) == len(expected), f"{path.name}: {len(got)} lines, Macaulay2 printed {len(expected)}"
    return got, inexact


@pytest.mark.parametrize("path", SCRIPTS, ids=[p.name for p in SCRIPTS])
def test_corpus(path: Path) -> None:
    _, inexact = run_corpus(path)
    assert inexact == INEXACT.get(path.name, 0)


@pytest.mark.skipif(not M2, reason="Macaulay2 (M2) is not installed")
@pytest.mark.parametrize("path", SCRIPTS, ids=[p.name for p in SCRIPTS])
def test_corpus_live(path: Path) -> None:
    """The stored outputs are what the installed Macaulay2 prints."""
    run = subprocess.run([M2, "--script", path.name], cwd=CORPUS, capture_output=True, text=True, timeout=300)
    assert run.stdout + run.stderr == path.with_suffix(".out").read_text()


# ---------------------------------------------------------------- syntax
def test_statements_end_at_line_breaks_and_semicolons() -> None:
    s = Session(dialect="m2")
    out = s.execute("R = QQ[x,y]\nI = ideal(x^2 - y,\n  x*y);  -- continued inside brackets\nJ = I +\n ideal(y)\n"
                    "dim J; numgens J")
    assert out == "o1 = R\no3 = ideal(x^2-y,x*y,y)\no5 = 3\n"


def test_comments_sequences_and_options() -> None:
    s = Session(dialect="m2")
    out = s.execute("-* a\nblock *- R = QQ[a..c]; (1, a) -- a comment\n{a => 1, 2}\n(print 1; 2)\n(print 3;)")
    assert out == "o2 = (1,a)\no3 = {a => 1, 2}\n1\no4 = 2\n3\n"


def test_rational_numbers_without_a_ring() -> None:
    assert Session(dialect="m2").execute("1/2 + 1\n(2/3)^2\n3/4 * 4") == "o1 = 3/2\no2 = 4/9\no3 = 3\n"


def test_indexed_variables_and_entries() -> None:
    s = Session(dialect="m2")
    out = s.execute("R = ZZ/7[x_1..x_3];\nf = x_1^2 + 8*x_3 - 4\nL = {x_2, f}; L_1 == L#-1\nx_(1+1)")
    assert out == "o2 = x_1^2+x_3+3\no4 = true\no5 = x_2\n"


def test_functions_close_over_their_arguments() -> None:
    s = Session(dialect="m2")
    out = s.execute("add = a -> (b -> a + b); add3 = add 3; add3 4\n"
                    "fact = n -> if n <= 1 then 1 else n * fact(n - 1); fact 6\n"
                    "g = n -> (for i from 1 to n do if i == 3 then return i; 0); g 5")
    assert out == "o3 = 7\no5 = 720\no7 = 3\n"


def test_monomial_orders() -> None:
    s = Session(dialect="m2")
    s.execute("R = QQ[a,b,c, MonomialOrder => {Weights => {1,2,3}, Lex}];")
    assert [b.kind for b in s.ring.blocks] == ["a", "lp", "C"]
    s.execute("R = QQ[a,b,c,d, MonomialOrder => {Eliminate 1, GRevLex => 1, Lex => 2}];")
    assert [(b.kind, b.size, b.weights) for b in s.ring.blocks][:3] == [("a", 0, (1, 0, 0, 0)), ("dp", 1, ()),
                                                                     ("lp", 2, ())]
    s.execute("L = QQ[a,b, MonomialOrder => {Weights => {-1,-1}}, Global => false];")
    assert s.ring.poly.order.is_local


@pytest.mark.parametrize("code, message", [
    ("R = QQ[x]; ideal(x) +", "1:22: error: unexpected end of input"),
    ("R = QQ[x]; y^2", "1:12: error: unknown identifier 'y'"),
    ("ideal(1/2)", "no ring active"),
    ("R = QQ[x,x]", "distinct variables"),
    ("R = QQ[x, MonomialOrder => RevLex]", "the monomial order is not global"),
    ("R = QQ[x, MonomialOrder => Foo]", "unknown monomial order Foo"),
    ("R = QQ[x,y, MonomialOrder => {Weights => {-1,-1}}]", "not global"),
    ("R = QQ[x]; eliminate(3, ideal(x))", "expected ring variables, got 3"),
    ("R = QQ[x]; eliminate(ideal(x), \"x\")", "wrong arguments for eliminate"),
    ("R = QQ[x]; {1,2}_5", "index 5 out of range"),
    ("R = QQ[x]; if x then 1", "a condition is true or false"),
    ("R = QQ[x]; minors(3, matrix {{x}})", "minors: k must be between 1 and 1"),
    ("R = QQ[x]; std ideal(x)", "unknown identifier 'std'"),
    ("x = 1 $ 2", "unexpected character '$'"),
])
def test_errors(code: str, message: str) -> None:
    with pytest.raises(MechError) as e:
        Session(dialect="m2").execute(code)
    assert message in e.value.format()


def test_dialects_keep_their_commands() -> None:
    with pytest.raises(MechError, match="primaryDecomposition"):
        Session().execute("ring r = 0,(x,y),dp; primaryDecomposition(ideal(x));")
    s = Session(dialect="m2")
    s.execute("R = QQ[x,y]; I = ideal(x*y);")
    assert same(s.eval("minimalPrimes I"), List([Ideal(s.ring.poly, [g]) for g in s.ring.poly.gens()]))
    assert isinstance(s["I"], Ideal) and isinstance(s.eval("x + 1"), Poly)
    s["J"] = [s.eval("x^2"), s.eval("y")]
    s["n"] = 4
    assert s.execute("J + ideal(x)\nn + 1") == "o3 = ideal(x^2,y,x)\no4 = 5\n"
    with pytest.raises(MechSyntaxError):
        s.eval("1; 2")


# ---------------------------------------------------------------- command line and shell
def test_cli_runs_m2_files(tmp_path: Path, capsys: pytest.CaptureFixture) -> None:
    from mech.cli import main
    f = tmp_path / "a.m2"
    f.write_text("R = QQ[x,y]\ngens gb ideal(x^2 - y, x*y)\nprint toString dim ideal(x)\n")
    assert main([str(f)]) == 0  # a script prints what it prints, as M2 --script
    assert capsys.readouterr().out == "1\n"
    assert main(["--dialect", "m2", "-c", "R = QQ[t]; print factor(t^2 - 1)"]) == 0
    assert capsys.readouterr().out == "(t-1)*(t+1)\n"
    from mech.cli import run_text
    assert run_text("R = QQ[x,y]\ndim ideal(x)\n", "<stdin>", dialect="m2") == 0  # M2 < file: values too
    assert capsys.readouterr().out == "o1 = R\no2 = 1\n"
    assert main(["--dialect", "m2", "-c", "R = QQ[t]; t +"]) == 1
    assert "<string>:1:" in capsys.readouterr().err


def test_repl_numbers_inputs() -> None:
    inputs = iter(["R = QQ[x,y]", "I = ideal(x^2,", "  y);", "dim I", "bad )", "exit"])
    prompts: list[str] = []

    def read(prompt: str) -> str:
        prompts.append(prompt)
        return next(inputs)
    out = io.StringIO()
    assert m2.run_m2_repl(read=read, out=out) == 0
    assert [p.strip() for p in prompts] == ["i1 :", "i2 :", "", "i3 :", "i4 :", "i5 :"]
    text = out.getvalue()
    assert "o1 = R\n" in text and "o3 = 0\n" in text and "o2 =" not in text
    assert "<stdin>:1:" in text


# ---------------------------------------------------------------- documentation
def _doc_examples(text: str) -> list[tuple[str, str | None]]:
    """The ```m2 blocks of a document, each with the plain ``` block right after it (its output)."""
    import re
    blocks = re.findall(r"```(\w*)\n(.*?)```", text, re.S)
    out = []
    for k, (lang, code) in enumerate(blocks):
        if lang == "m2":
            nxt = blocks[k + 1] if k + 1 < len(blocks) else None
            out.append((code, nxt[1] if nxt and nxt[0] == "" else None))
    return out


def test_docs_examples_print_as_shown() -> None:
    root = ROOT
    examples = _doc_examples((root / "docs" / "m2.md").read_text()) + _doc_examples((root / "README.md").read_text())
    assert len(examples) >= 3
    for code, output in examples:
        got = Session(dialect="m2").execute(code)
        if output is not None:
            assert got == output
