"""The Macaulay2 conformance runner (benchmarks/m2_examples.py, m2_sources.py) on synthetic sources and outputs:
reading Macaulay2's strings and doc formats, the selection rule, the classification of results and
the report; with Macaulay2 installed, its judge of mech's values."""
from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest

from tests.util import ROOT


def _load(name: str):
    """A module of benchmarks/ (not a package: its scripts import each other by name)."""
    spec = importlib.util.spec_from_file_location(name, ROOT / "benchmarks" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module  # dataclasses and m2_examples look it up
    spec.loader.exec_module(module)
    return module


S = _load("m2_sources")
R = _load("m2_examples")
INFO = {"private": {"checkIt", "H"}, "globals": {"monomialIdeal": "function", "Strategy": "Symbol",
                                                "elapsedTime": "Keyword"}, "version": "1.21"}


# ---------------------------------------------------------------- reading sources
@pytest.mark.parametrize("text, value, end", [
    ('"a\\"b\\nc" rest', 'a"b\nc', 9),
    ("///x\ny/// rest", "x\ny", 9),
    ("///a////b", "a/", 8),          # a run of n > 3 slashes ends the string after n - 3 slashes
    ("///a/b///", "a/b", 9),
])
def test_strings(text: str, value: str, end: int) -> None:
    assert S.read_string(text, 0) == (value, end)


def test_tokens_skip_comments_and_strings() -> None:
    code = 'f(x) -- g(y)\n-* h *- "k(z)" ///m/// x_1..x_3 1.5'
    assert [t for _, t in S.tokens(code)] == ["f", "(", "x", ")", '"', '"', "x", "_", "1", ".", ".", "x", "_", "3",
                                             "1.5"]
    assert S.closing("a(b[c], (d)) e", 1) == 12


def test_document_examples_and_key() -> None:
    body = '''{ Key => {(resultant, RingElement, RingElement), resultant},
        "text with EXAMPLE in a string",
        EXAMPLE { "R = QQ[x]", "f = x^2 -- a comment" },
        EXAMPLE "g = x",
        EXAMPLE lines ///
            h = f + g
              + 1
        ///,
        EXAMPLE { /// a = 1 /// } }'''
    assert S.document_key(body) == "(resultant, RingElement, RingElement)"
    assert S.document_key('{ Key => "polynomial rings", EXAMPLE "x" }') == "polynomial rings"
    assert S.old_style_examples(body) == ["R = QQ[x]", "f = x^2 -- a comment", "g = x", "h = f + g\n  + 1",
                                          "a = 1"]


SIMPLEDOC = """
Node
  Key
    saturate
    (saturate, Ideal)
  Headline
    saturation
  Description
    Text
      Example follows.
    Example
      R = QQ[x,y]
      I = ideal(x^2,
          x*y)
    Text
      More.
    CannedExample
      not run
    Example
      saturate I
Node
  Key
    "no examples"
  Description
    Text
      nothing
Node
  Key
    "template"
  Description
    Example
Node
  Key
    "ideal quotients"
  Description
    Example
      x
"""


def test_simpledoc_nodes() -> None:
    assert S.simpledoc_nodes(SIMPLEDOC) == [
        ("saturate", ["R = QQ[x,y]\nI = ideal(x^2,\n    x*y)", "saturate I"], 1),
        ("ideal quotients", ["x"], 31)]


def test_cases_in_a_file(tmp_path: Path) -> None:
    (tmp_path / "other.m2").write_text("assert(1 == 1)\n")
    (tmp_path / "pkg.m2").write_text(
        'document { Key => foo, EXAMPLE { "foo 1" } }\n'
        "doc ///\n" + SIMPLEDOC + "///\n"
        "TEST ///\n  assert(2 == 2)\n///\n"
        'TEST get(currentFileDirectory | "other.m2")\n'
        "BENCHMARK ///\n  slow()\n///\n"
        "SIMPLETEST = str -> TEST str\n"
        "end--\n"
        "TEST ///\n  after the end\n///\n")
    cases = S.cases_in(tmp_path / "pkg.m2", "Pkg/pkg.m2", "Pkg", "")
    assert [(c.where, c.kind, c.name, c.code) for c in cases] == [
        ("Pkg/pkg.m2:1", "example", "foo", "foo 1"),
        ("Pkg/pkg.m2:4", "example", "saturate", "R = QQ[x,y]\nI = ideal(x^2,\n    x*y)\nsaturate I"),
        ("Pkg/pkg.m2:34", "example", "ideal quotients", "x"),
        ("Pkg/pkg.m2:41", "test", "TEST", "assert(2 == 2)"),
        ("Pkg/pkg.m2:44", "test", "TEST", "assert(1 == 1)"),
        ("Pkg/pkg.m2:45", "test", "TEST", "slow()")]
    assert cases[-1].excluded.startswith("a MinimalPrimes BENCHMARK")


def test_loaded_files(tmp_path: Path) -> None:
    (tmp_path / "Pkg").mkdir()
    (tmp_path / "Pkg.m2").write_text('load "./Pkg/a.m2"\n-- load "./Pkg/c.m2"\n')
    (tmp_path / "Pkg" / "a.m2").write_text('x = 1\n  load "./b.m2"\n')
    (tmp_path / "Pkg" / "b.m2").write_text("")
    assert [p.name for p in S.loaded_files(tmp_path / "Pkg.m2")] == ["Pkg.m2", "a.m2", "b.m2"]


@pytest.mark.parametrize("code, reason", [
    ("R = QQ[x]; I = ideal x; minimalPrimes I", ""),
    ('needsPackage "LocalRings"; R = QQ[x]', ""),
    ("x_0..x_3", ""),
    ("-- Ext in a comment\n\"Hom in a string\"", ""),
    ("C = res I; betti C; prune coker f", ""),
    ("E = Ext^1(M, N)", "modules, resolutions, chain complexes: Ext"),
    ("R = ZZ[x]", ""),
    ("f = 1.5*x", "real and complex numbers: 1.5"),
    ("random(2, R)", "random values: random"),
    ("I.cache", "hash tables and internals: cache"),
    ('needsPackage "Graphs"', "other packages: needsPackage Graphs"),
    ("R = QQ[x, SkewCommutative => true]", "non-commutative rings: SkewCommutative"),
])
def test_selection(code: str, reason: str) -> None:
    assert S.out_of_scope(code) == reason


def test_internals() -> None:
    case = S.Case("f:1", "Pkg", "test", "TEST", "H = 1\ncheckIt(H, x)")
    assert R.internals(case, INFO) == "checkIt"


# ---------------------------------------------------------------- classifying
@pytest.mark.parametrize("message, status, reason", [
    ("unknown identifier 'monomialIdeal'", "unsupported", "function monomialIdeal"),
    ("unknown identifier 'elapsedTime'", "unsupported", "Keyword elapsedTime"),
    ("unknown identifier 'a' (no ring is active)", "unsupported", "names without a value used as symbols"),
    ("unknown identifier 'assert'", "unsupported", "names without a value used as symbols"),
    ("wrong arguments for isPrimary: got (list), expected isPrimary(ideal)", "unsupported", "isPrimary(list)"),
    ("unknown ring option 'Degrees' (known: MonomialOrder, Global)", "unsupported", "ring option Degrees"),
    ("internal error: KeyError: 'x'", "crash", "KeyError: 'x'"),
    ("assertion failed", "differ", "assertion failed"),
    ("division by 0", "error", "division by 0"),
])
def test_blocking(message: str, status: str, reason: str) -> None:
    assert R.blocking(message, INFO) == (status, reason)


def test_mech_error_message() -> None:
    err = "case.m2:3:1: error: unknown identifier 'foo'\n  foo x\n  ^^^\n"
    assert R.mech_error(err) == ("unknown identifier 'foo'", 3, 1)
    assert R.mech_error("<string>: error: interrupted\n") == ("interrupted", 0, 0)


@pytest.mark.parametrize("line, col, construct", [
    ("assert(J === K)", 11, "operator ==="),
    ("R:=(ring J)[t]", 3, "operator :="),
    ("J = ideal I_*", 13, "operator _*"),
    ("f ** RP", 4, "operator **"),
    ("{1,2} | {3}", 7, "operator |"),
    ("R.maxIdeal", 2, "operator ."),
    ("try a^(2^15) else 0", 14, "try ... else"),
    ("I^[3]", 3, "operator ^[...]"),
    ("apply([1,3], f)", 7, "arrays [...]"),
    ("map(R^2,,m)", 9, "empty arguments f(a,,b)"),
    ("T = tally for i from 0 to 3 list i", 24, "'to'"),
])
def test_syntax_constructs(line: str, col: int, construct: str) -> None:
    assert R.syntax_construct(line, col) == construct
    assert R.blocking("unexpected '='", INFO, line, col) == ("unsupported", "syntax: " + construct)


def test_keyword_before_an_assignment() -> None:
    assert R.blocking("cannot assign to this expression", INFO, "elapsedTime C = f(x)", 1) == \
        ("unsupported", "Keyword elapsedTime")


def _mech(values: dict, prints=(), rc: int = 0, err: str = "", timeout: bool = False) -> dict:
    return {"values": values, "prints": list(prints), "rc": rc, "err": err, "seconds": 1.0, "timeout": timeout}


def _m2(values: dict, classes=("Ideal",), prints=(), rc: int = 0, error: str = "", timeout: bool = False) -> dict:
    return {"values": values, "classes": set(classes), "prints": list(prints), "rc": rc, "error": error,
            "seconds": 1.0, "timeout": timeout}


CASE = S.Case("f:1", "Pkg", "example", "node", "code")


@pytest.mark.parametrize("mech, m2, status, reason", [
    (_mech({1: "R", 2: "ideal(y,x)"}), _m2({1: ("R", "same"), 2: ("ideal(x,y)", "equal")}), "agree", ""),
    (_mech({2: "3"}), _m2({2: ("{3}", "differ")}), "differ", "o2: Macaulay2 '{3}', mech '3'"),
    (_mech({2: "??"}), _m2({2: ("x", "unreadable")}), "differ", "o2: Macaulay2 'x', mech '??' (mech's text unreadable)"),
    (_mech({1: "R"}), _m2({1: ("R", "same"), 2: ("x", "missing")}), "differ", "Macaulay2 prints o2 = 'x', mech nothing"),
    (_mech({1: "R", 3: "x"}), _m2({1: ("R", "same")}), "differ", "mech prints o3 = 'x', Macaulay2 nothing"),
    (_mech({}, prints=["1"]), _m2({}, prints=["2"]), "differ", "printed lines: Macaulay2 ['2'], mech ['1']"),
    (_mech({1: "R"}, rc=1, err="f:2:1: error: unknown identifier 'monomialIdeal'\n"),
     _m2({1: ("R", "same"), 2: ("x", "missing")}), "unsupported", "function monomialIdeal"),
    (_mech({}, rc=1, err="f:2:1: error: internal error: IndexError: list index out of range\n"), _m2({}),
     "crash", "IndexError: list index out of range"),
    (_mech({}, rc=-9, timeout=True), _m2({}), "timeout", "mech times out"),
    (_mech({}, rc=1, err="f:1:1: error: operator ^ is not defined for ring and int\n"), _m2({}),
     "unsupported", "operator ^ on ring and int"),
    (_mech({}, rc=1, err="f:1:5: error: unknown identifier 'ZZ' (no ring is active)\n"), _m2({}),
     "unsupported", "ZZ as a value"),
    (_mech({}), _m2({}, rc=1, error="stdio:1:1:(3): error: no method"), "excluded", "Macaulay2 1.21 fails on it"),
    (_mech({}), _m2({}, classes=("ChainComplex", "Ideal")), "excluded", "values outside mech's scope: ChainComplex"),
])
def test_classify(mech: dict, m2: dict, status: str, reason: str) -> None:
    r = R.classify(CASE, mech, m2, INFO)
    assert (r.status, r.reason) == (status, reason)


@pytest.mark.parametrize("unique, status, reason", [
    ("true", "agree", "compared by a unique value: an embedded component"),
    ("false", "differ", "o2: Macaulay2 '{1, 82}', mech '{1, 123}'"),
])
def test_classify_values_that_are_not_unique(monkeypatch, unique: str, status: str, reason: str) -> None:
    """A case of NOT_UNIQUE: its listed statements and first printed lines are judged by the check
    Macaulay2 runs on mech's own choice (its verdict in m2["unique"]); the other lines as usual."""
    monkeypatch.setitem(R.NOT_UNIQUE, "f:1", ("an embedded component", {2}, 1, "check"))
    mech = _mech({1: "R", 2: "{1, 123}"}, prints=["ideal(x^2,y)", "ideal x"])
    m2 = _m2({1: ("R", "same"), 2: ("{1, 82}", "differ")}, prints=["ideal(x^3,y)", "ideal x"])
    m2["unique"] = unique
    r = R.classify(CASE, mech, m2, INFO)
    assert (r.status, r.reason) == (status, reason)
    m2["prints"] = ["ideal(x^3,y)", "ideal y"]  # a line after the checked ones differs: it counts
    assert R.classify(CASE, mech, m2, INFO).status == "differ"


def test_functions_mech_lacks() -> None:
    info = {"globals": {"integralClosure": "function", "ideal": "function", "f": "function", "R": "Symbol"}}
    code = "R = QQ[x]; integralClosure x; ideal x; f = y -> y; f x"
    results = [R.Result(S.Case("f:1", "Pkg", "example", "n", code), "unsupported"),
               R.Result(S.Case("f:2", "Pkg", "example", "n", code), "agree")]
    assert R.mech_lacks(results, info) == {"integralClosure": 1}


def test_report_ranks_the_missing_features() -> None:
    cases = [S.Case(f"f:{k}", "Pkg", "example", f"n{k}", "x") for k in range(5)]
    results = [R.Result(cases[0], "agree"), R.Result(cases[1], "unsupported", "function monomialIdeal"),
               R.Result(cases[2], "unsupported", "function monomialIdeal"), R.Result(cases[3], "unsupported", "syntax: ':='"),
               R.Result(cases[4], "excluded", "random values: random")]
    text = R.report(results, {"date": "today", "seconds": 1.0, "jobs": 2, "timeout": 30, "m2_version": "1.21",
                              "source": "1.21", "mech": "abc", "lacks": {"monomialIdeal": 2}})
    assert "4 in scope, **1 agree (25%)**" in text
    assert "| function monomialIdeal | 2 | f:1 |\n| syntax: ':=' | 1 | f:3 |" in text
    assert "| **all** | 4 | 1 | 0 | 3 | 0 | 0 | 0 | 25% | 1 |" in text
    assert "| random values | 1 |" in text
    assert "use it (anywhere in their code, not only first):\n\nmonomialIdeal 2" in text


# ---------------------------------------------------------------- Macaulay2 judging mech's text
@pytest.mark.macaulay2
def test_macaulay2_judges_values(tmp_path: Path) -> None:
    code = ("R = QQ[x,y,z]\nideal(x*y, x*z)\nminimalPrimes ideal(x*y, x*z)\ndegree(x^2*y)\n"
            "S = QQ[a,b]; x\n{1, 2}\nprint ideal(x)\nprimaryDecomposition ideal(x^2, x*y)\n"
            "primaryDecomposition ideal(x^2, x*y)")
    mech = {2: "ideal(x*z,x*y)", 3: "{ideal(z,y), ideal x}", 4: "3", 6: "x", 7: "(1,2)",
            9: "{ideal x, ideal(y^2,x*y,x^2)}", 10: "{ideal x, ideal(y^2,x^2)}"}
    m2 = R.run_m2(S.Case("f:1", "Pkg", "example", "n", code), mech, 60, str(tmp_path))
    assert m2["values"] == {1: ("R", "missing"), 2: ("ideal(x*y,x*z)", "equal"),
                            3: ("{ideal x, ideal(z,y)}", "equal"), 4: ("{3}", "differ"), 6: ("x", "same"),
                            7: ("{1, 2}", "differ"), 9: ("{ideal x, ideal(y,x^2)}", "equivalent"),
                            10: ("{ideal x, ideal(y,x^2)}", "differ")}
    assert m2["prints"] == ["ideal x"] and m2["rc"] == 0 and "PolynomialRing" in m2["classes"]
