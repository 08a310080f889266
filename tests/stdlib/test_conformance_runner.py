"""The Singular conformance runner (benchmarks/singular_tst.py): selection, harness stripping, output
parsing and comparison as values, classification of mech's failures; on synthetic inputs only."""
from __future__ import annotations

import binascii
import gzip
import sys

import pytest

from tests.util import ROOT, SINGULAR

sys.path.insert(0, str(ROOT / "benchmarks"))

from singular_tst import judge, singular_side  # noqa: E402
from tst_compare import (MARKER, Oracle, check_script, compare, long_form, normalize, parse, read_answers,  # noqa: E402
                         split_error)
from tst_report import Result, _ranking  # noqa: E402
from tst_source import (_MARK, Case, examples, instrument, mask, read_reference, scope_reason,  # noqa: E402
                        strip_harness)

RING = ("(QQ),(x,y),(dp(2),C)", "0", "0")


# ---------------------------------------------------------------- selection and scripts
def test_mask_blanks_strings_and_comments_only():
    text = 'string s = "module; // x"; // vector\nideal i; /* res(i)\n */ i;'
    masked = mask(text)
    assert len(masked) == len(text) and masked.count("\n") == 2
    assert "module" not in masked and "vector" not in masked and "res" not in masked
    assert masked.startswith('string s = "') and "ideal i;" in masked and masked.endswith(" i;")


def test_strip_harness_keeps_lines_and_stops_at_dollar():
    text = ('LIB "tst.lib"; tst_init();\nring r=0,x,dp;\ntst_ignore(string(memory(0)));\nx;\n'
            'tst_status(1);$\nmodule m;\n')
    out = strip_harness(text)
    assert out.count("\n") == 4 and "tst" not in out and "module" not in out and "memory" not in out
    assert out.splitlines()[1] == "ring r=0,x,dp;" and out.splitlines()[3] == "x;"


@pytest.mark.parametrize("script, reason", [
    ("ring r=0,(x,y),dp; ideal i=x; i;", None),
    ('ring r=0,(x,y),dp; "a module"; // vector\n', None),
    ('LIB "primdec.lib"; LIB "poly.lib"; ring r=(0,a),x,(c,ds);', None),
    ("ring r=32003,(x,y),dp; module m=[x,y];", None),
    ("ring r=0,(x,y),dp; ideal i=x; res(i,0);", "resolutions and homological algebra: res"),
    ("ring r=(real,10),(x,y),dp;", "real or complex coefficients"),
    ("ring r=integer,(x,y),dp;", "integer coefficients"),
    ("ring r=(49,a),(x,y),dp;", "Galois fields and Z/n with n not prime"),
    ("ring r=(7,a),(x,y),dp;", None),
    ('LIB "nctools.lib"; ring r=0,x,dp;', "library nctools.lib"),
    ('system("random", 1); module m;', "system(...) call: system"),
    ("option(prot); ring r=0,x,dp;", "protocol output (option(prot))"),
    ('ring r=0,x,dp; < "file.sing";', "links and files: <"),
    ("ring r=0,x,dp; def A = nc_algebra(1,0);", "noncommutative ring: nc_algebra"),
])
def test_scope_reason(script, reason):
    assert scope_reason(script) == reason


def test_examples_of_a_library():
    lib = ('proc f(int a)\n"USAGE: f(a)"\n{\n  return(a+1);\n}\nexample\n{ "EXAMPLE:"; echo = 2;\n  f(1);\n}\n'
           'static proc g()\n{\n}\nexample\n{ g(); }\n'
           'proc h()\n{ "}"; }\nexample\n{ "EXAMPLE:"; echo=2;\n  string s = "{"; h();\n}\n')
    got = list(examples(lib))
    assert [p for p, _ in got] == ["f", "h"]
    assert got[0][1].strip() == "f(1);" and got[1][1].strip() == 'string s = "{"; h();'


def test_instrument_marks_ring_changes_outside_strings():
    script = 'ring r=0,x,dp; "ring s=0,y,dp;"; ring s=(0,a),y,dp; minpoly = a2+1; setring r; proc f(ring q) {}\n'
    parts = instrument(script).split(_MARK)
    assert [p.rsplit(";", 2)[-2].strip() for p in parts[:-1]] == [
        "ring r=0,x,dp", "ring s=(0,a),y,dp", "minpoly = a2+1", "setring r"]
    assert "".join(parts) == script


def test_read_reference_decodes_uuencoded_gzip(tmp_path):
    text = "i[1]=x\n   ? error occurred in or before foo.tst line 3: `f();`\n" * 5
    data = gzip.compress(text.encode())
    lines = ["begin 644 foo.res.gz"] + [binascii.b2a_uu(data[k:k + 45]).decode().rstrip("\n")
                                        for k in range(0, len(data), 45)] + ["`", "end"]
    path = tmp_path / "foo.res.gz.uu"
    path.write_text("\n".join(lines) + "\n")
    assert read_reference(path) == text
    assert read_reference(tmp_path / "absent.res.gz.uu") is None


# ---------------------------------------------------------------- parsing outputs
OUTPUT = f"""{MARKER}{RING[0]}@@0@@0
i[1]=x2
i[2]=y
[1]:
   [1]:
      _[1]=y
   [2]:
      2,3
[2]:
   text line
m[1,1]=x
m[1,2]=1
   ? `f` is not defined
   ? error occurred in or before case.sing line 5: `f();`
after
"""


def test_parse_items_and_rings():
    text, err = split_error(OUTPUT)
    assert [it.kind for it in parse("[1]:\n   1\n[2]:\n   2\n[1]:\n   3\n")] == ["list", "list"]
    assert err == "`f` is not defined" and "after" not in text
    items = parse(text)
    assert [it.kind for it in items] == ["ideal", "list", "matrix"]
    assert items[0].gens == ["x2", "y"] and items[0].ring == RING
    inner = items[1].elems[0][0]
    assert inner.kind == "list" and inner.elems[0][0].gens == ["y"] and inner.elems[1][0].text == "2,3"
    assert items[1].elems[1][0].text == "text line" and items[2].gens == ["1,1=x", "1,2=1"]
    assert normalize("a  \n\n// ** note\nb\n") == "a\nb"


# ---------------------------------------------------------------- comparing as values
class FakeOracle(Oracle):
    """Answers from a table; records what it was asked."""

    def __init__(self, truth):
        super().__init__(lambda qs: {q: truth(q) for q in qs})
        self.asked = []

    def settle(self):
        self.asked += list(self.pending)
        return super().settle()


def _eq_as_sets(q):
    return q[0] == "eq" and sorted(q[2]) == sorted(q[3])


def _ring(text):
    return f"{MARKER}{RING[0]}@@0@@0\n{text}"


def test_text_must_match_and_ideals_compare_as_ideals():
    o = FakeOracle(_eq_as_sets)
    S = parse(_ring("5\n_[1]=x\n_[2]=y\n"))
    assert compare(S, parse("5\n_[1]=y\n_[2]=x\n"), o) is None and o.asked
    assert "Singular `6`" in compare(parse(_ring("6\n")), parse("7\n"), FakeOracle(_eq_as_sets))
    why = compare(S, parse("5\n_[1]=y\n_[2]=x2\n"), FakeOracle(_eq_as_sets))
    assert why and "output line 3" in why
    assert compare(S, parse("5\n"), FakeOracle(_eq_as_sets)).endswith("mech nothing more")
    assert "(printed name)" in compare(parse(_ring("i[1]=x\n")), parse("_[1]=x\n"), FakeOracle(_eq_as_sets))


def test_lists_of_ideals_compare_as_sets_other_lists_in_order():
    S = parse(_ring("[1]:\n   _[1]=x\n[2]:\n   _[1]=y\n"))
    assert compare(S, parse("[1]:\n   _[1]=y\n[2]:\n   _[1]=x\n"), FakeOracle(_eq_as_sets)) is None
    assert compare(S, parse("[1]:\n   _[1]=y\n[2]:\n   _[1]=y\n"), FakeOracle(_eq_as_sets))
    ints = parse(_ring("[1]:\n   1\n[2]:\n   2\n"))
    assert compare(ints, parse("[1]:\n   2\n[2]:\n   1\n"), FakeOracle(_eq_as_sets))


def test_primary_decompositions_may_differ_in_embedded_components():
    # Singular: (x) and embedded (x2,y) at (x,y); mech: another embedded component (x2,xy,y2)
    s = "[1]:\n   [1]:\n      _[1]=x\n   [2]:\n      _[1]=x\n[2]:\n   [1]:\n      _[1]=x2\n      _[2]=y\n" \
        "   [2]:\n      _[1]=x\n      _[2]=y\n"
    m = s.replace("_[1]=x2\n      _[2]=y\n", "_[1]=x2\n      _[2]=xy\n      _[3]=y2\n", 1)

    def truth(q):
        if q[0] == "sub":
            return set(q[2]) >= set(q[3]) or q[2] == ("x",)
        return q[0] in ("inter_eq", "primary") or _eq_as_sets(q)
    o = FakeOracle(truth)
    assert compare(parse(_ring(s)), parse(m), o) is None
    assert {q[0] for q in o.asked} >= {"inter_eq", "primary"}
    assert "intersection" in compare(parse(_ring(s)), parse(m), FakeOracle(lambda q: truth(q) and q[0] != "inter_eq"))


def test_factorizations_up_to_order_and_units():
    s = "[1]:\n   _[1]=1\n   _[2]=x-y\n   _[3]=x+y\n[2]:\n   1,1,2\n"
    m = "[1]:\n   _[1]=-1\n   _[2]=x+y\n   _[3]=-x+y\n[2]:\n   1,2,1\n"
    up_to_sign = {"x-y": "x-y", "-x+y": "x-y", "x+y": "x+y"}

    def truth(q):
        return q[0] == "poly_eq" or q[0] == "eq" and up_to_sign.get(q[2][0]) == up_to_sign.get(q[3][0]) is not None
    assert compare(parse(_ring(s)), parse(m), FakeOracle(truth)) is None
    assert compare(parse(_ring(s)), parse(m), FakeOracle(lambda q: truth(q) and q[0] != "poly_eq"))


# ---------------------------------------------------------------- classifying mech's runs
def _answer(questions):
    return {q: _eq_as_sets(q) for q in questions}


def _judge(s_text, s_error, out, err="", status=0):
    return judge("Short/t.tst", s_text, s_error, {"out": out, "err": err, "status": status}, _answer)


@pytest.mark.parametrize("err, status, category, key", [
    ("f.tst:3:1: error: unknown command 'res'\nres(i,0);\n^\n", 1, "unsupported", "command res"),
    ("f.tst:3:1: error: unknown command 'sat' (it is in elim.lib: load it with LIB \"elim.lib\";)\n", 1,
     "unsupported", "command sat (mech has it in elim.lib; not loaded)"),
    ("f.tst:3:1: error: type 'qring' is not supported yet\nqring q;\n^\n", 1, "unsupported", "type qring"),
    ("f.tst:3:9: error: unexpected '[', expected an expression\nv=[x];\n", 1, "unsupported",
     "syntax: unexpected '[', expected an expression"),
    ("f.tst:3:1: error: wrong arguments for std: got (ideal, poly), expected std(ideal)\n", 1, "unsupported",
     "arguments std(ideal, poly)"),
    ("f.tst:3:1: error: factorize is not available over the coefficient field GF(7)(a,b)\n", 1, "unsupported",
     "factorize over coefficient field GF(7)(...)"),
    ("f.tst:3:1: error: division by 0\n1/0;\n^\n", 1, "error", "division by 0"),
    ("f.tst:3:1: error: internal error: KeyError: 3\nstd(i);\n^\n", 1, "crash", "internal error: KeyError: 3"),
    ("f.tst:3:1: error: time limit of 30 s exceeded\nstd(i);\n^\n", 1, "timeout", "time limit of 30 s exceeded"),
    ("", None, "timeout", "process time limit"),
    ("", -11, "crash", "exit status -11"),
])
def test_mech_failures_are_classified_by_their_message(err, status, category, key):
    r = _judge(_ring("1\n"), None, "1\n", err, status)
    assert (r.category, r.key) == (category, key)


def test_judgement_of_outputs():
    assert _judge(_ring("1\n"), None, "1\n").key == "text"
    assert _judge(_ring("_[1]=x\n_[2]=y\n"), None, "_[1]=y\n_[2]=x\n").key == "values"
    # a wrong value printed before mech stops counts as a difference
    r = _judge(_ring("1\n2\n"), None, "3\n", "f:2:1: error: unknown command 'f'\n", 1)
    assert (r.category, r.key) == ("differ", "value")
    # Singular's error at the same place as mech's: agreement; mech going on: a difference of its own kind
    assert _judge(_ring("1\n"), "`f` is not defined", "1\n", "f:2:1: error: oops\n", 1).category == "agree"
    assert _judge(_ring("1\n"), "`f` is not defined", "1\n", "f:2:1: error: unknown identifier 'f'\n",
                  1).category == "agree"
    # ... unless mech's error is a feature it lacks
    err = "f:2:1: error: unknown command 'preimage'\n"
    r = _judge(_ring("1\n"), "2nd/3rd arguments must have names", "1\n", err, 1)
    assert (r.category, r.key) == ("unsupported", "command preimage")
    assert (_judge(_ring("1\n"), "`f` is not defined", "1\n2\n").category,
            _judge(_ring("1\n"), "`f` is not defined", "1\n2\n").key) == ("differ", "accepts")
    assert _judge(_ring("1\n"), "`f` is not defined", "1\n2\n", "f:3:1: error: unknown command 'g'\n",
                  1).key == "accepts"
    assert _judge(_ring("1\n"), "`f` is not defined", "5\n2\n").key == "value"


class CannedSingular:
    def __init__(self, out):
        self.out = out

    def output(self, script):
        return self.out


def test_singular_errors_are_intended_only_when_the_recorded_result_has_them():
    out = "1\n   ? `f` is not defined\n   ? error occurred in or before case.sing line 2: `f();`\n"
    ref = "STDIN 2> f();\n   ? `f` is not defined\n   ? error occurred in or before STDIN line 2: `f();`\n"
    aside, text, err = singular_side(Case("Short/t.tst", "1;\nf();\n", ref), CannedSingular(out))
    assert aside is None and text == "1" and err == "`f` is not defined"
    aside, _, _ = singular_side(Case("Short/t.tst", "1;\nf();\n", "1\n"), CannedSingular(out))
    assert aside.category == "set aside" and aside.key == "fails in the installed Singular"
    aside, _, _ = singular_side(Case("LIB/x.lib:f", "1;\n"), CannedSingular(None))
    assert aside.key == "Singular runs out of time"


def test_ranking_counts_first_blocking_constructs():
    rs = [Result(f"Short/{k}.tst", "unsupported", key) for k, key in enumerate(["type qring"] * 3 + ["command res"])]
    lines = _ranking(rs + [Result("Short/x.tst", "agree", "text"), Result("Short/y.tst", "error", "division by 0"),
                           Result("Short/z.tst", "error", "division by 0")])
    assert "6 cases" in lines[1]
    assert lines[5].startswith("| 1 | type qring | unsupported | 3 |")
    assert lines[6].startswith("| 2 | division by 0 | error | 2 |") and lines[7].startswith("| 3 | command res |")


def test_identifiers_are_named_with_the_call_they_are_an_argument_of():
    err = "f.tst:2:9: error: unknown identifier 'all'\nlistvar(all);\n        ^\n"
    assert _judge(_ring(""), None, "", err, 1).key == "identifier all in listvar(...)"
    err = "f.tst:2:8: error: unknown identifier 'minpoly'\nstring(minpoly);\n       ^\n"
    assert _judge(_ring(""), None, "", err, 1).key == "identifier minpoly"
    err = "f.tst:1:16: error: type 'bigint' is not supported yet\nbigint j = i + bigint(n)^50;\n"
    assert _judge(_ring(""), None, "", err, 1).key == "conversion bigint(...)"


def test_long_form_for_reading_polynomials_back():
    names = {"a", "d", "e", "f", "x"}
    assert long_form("1/2x2+(a+1)*def-3def2+16000x^2", names) == "1/2*x^2+(a+1)*d*e*f-3*d*e*f^2+16000*x^2"
    assert long_form("x(1)^2+x(2)", {"x(1)", "x(2)"}) == "x(1)^2+x(2)"


# ---------------------------------------------------------------- the questions, asked of real Singular
@pytest.mark.singular
def test_check_script_in_singular():
    import subprocess
    local = ("(ZZ/32003),(x,y),(ds(2),C)", "0", "0")
    ext = ("(0,a),(x,y),(dp(2),C)", "(a2+1)", "0")
    quotient = ("(QQ),(x,y),(dp(2),C)", "0", "x2")
    qs = [("eq", RING, ("x2", "y"), ("y+x2", "x2")), ("eq", RING, ("x2", "y"), ("x", "y")),
          ("eq", local, ("x+x2", "y"), ("x", "y+y3")), ("eq", ext, ("(a)*x+1",), ("x-a",)),
          ("eq", quotient, ("x2+y",), ("y",)), ("sub", RING, ("x2",), ("x",)), ("sub", RING, ("x",), ("x2",)),
          ("inter_eq", RING, (("x",), ("y",)), (("xy",),)), ("primary", RING, ("x2", "y"), ("x", "y")),
          ("primary", RING, ("x2", "xy"), ("x",)), ("poly_eq", RING, "(x+y)^2", "x2+2xy+y2"),
          ("eq", RING, ("x+",), ("x",)),
          ("eq", ("(ZZ/32003),(d,e,f),(ds(3),C)", "0", "0"), ("def+d2f",), ("def+d2f+def2+d2f2",))]
    out = subprocess.run([SINGULAR, "-q", "--no-rc", "--no-warn"], input=check_script(qs), text=True,
                         capture_output=True, timeout=120).stdout
    got = read_answers(qs, out)
    assert [got.get(q) for q in qs] == [True, False, True, True, True, True, False, True, True, False, True, None,
                                     True]


# ---------------------------------------------------------------- values judged by a check (tst_checks)
def test_value_lines_are_printed_split_and_edited_in():
    from tst_checks import Check, edit, split_values, value
    assert value("f", "reduce(f,G)") == '"@@VALUE " + string(f) + " @@ " + string(reduce(f,G));'
    out = f"{MARKER}{RING[0]}@@0@@0\nS[1]=x\n@@VALUE x2 @@ y\n1\n"
    rest, values = split_values(out)
    assert values == [(RING, ["x2", "y"])] and "@@VALUE" not in rest and "S[1]=x" in rest
    check = Check("why", (("print(T);", value("T")),), "ok = 1;")
    assert edit("matrix T; print(T);", check) == 'matrix T; "@@VALUE " + string(T);'
    assert edit("matrix T;", check) is None  # the text the check edits is missing


def test_a_case_agrees_only_when_every_differing_value_passes(monkeypatch):
    from tst_checks import Check, judge_checked
    check = Check("a remainder is not unique", (), "ok = ({m1}) == ({s1});")
    marker = f"{MARKER}{RING[0]}@@0@@0\n"
    singular = marker + "1\n@@VALUE x @@ y\n@@VALUE z @@ y\n"
    scripts = []

    def run_singular(script, answers):
        scripts.append(script)
        return "".join(f"@@OK {k} {a}\n" for k, a in enumerate(answers))

    def judge_text(s, m):
        return judge("c", s, None, {"out": m, "err": "", "status": 0}, lambda qs: {})
    mech = "1\n@@VALUE x @@ y\n@@VALUE w @@ y\n"  # the first value as Singular's: not asked
    r = judge_checked(check, singular, mech, lambda s: run_singular(s, ["1"]), judge_text)
    assert (r.category, r.key, r.detail) == ("agree", "checked", "a remainder is not unique")
    assert "check@0" in scripts[-1] and "w" in scripts[-1] and "check@1" not in scripts[-1]
    r = judge_checked(check, singular, mech, lambda s: run_singular(s, ["0"]), judge_text)
    assert r.category == "differ" and "value 2" in r.detail
    r = judge_checked(check, singular, "2\n@@VALUE x @@ y\n@@VALUE w @@ y\n", lambda s: run_singular(s, ["1"]),
                      judge_text)
    assert r.category == "differ"  # the rest of the output differs: no check can make it agree
    r = judge_checked(check, singular, "1\n@@VALUE x @@ y\n", lambda s: run_singular(s, ["1"]), judge_text)
    assert r.category == "differ" and "Singular prints 2, mech 1" in r.detail


@pytest.mark.singular
def test_checks_prove_right_values_and_refuse_wrong_ones():
    import subprocess
    from tst_checks import CHECKS, check_script
    remainder = CHECKS["Buch/Example_1_6_13.tst"]  # f - r in <G>, no term of r divisible by lead(G)
    ring = ("(QQ),(x,y,z),(dp(3),C)", "0", "0")
    f, G = "x2yz+xy2z+y2z+z3+xy", "xy+y2-1,xy"
    singular = [(ring, [f, G, "y2z+z3"])] * 3
    mech = [(ring, [f, G, "y2z+z3-y2+xz+1"]), (ring, [f, G, "y2z+z3+1"]), (ring, [f, G, "xy+y2z+z3-y2+xz+1"])]
    out = subprocess.run([SINGULAR, "-q", "--no-rc", "--no-warn"], input=check_script(remainder, singular, mech),
                         text=True, capture_output=True, timeout=120).stdout
    assert [ln for ln in out.splitlines() if ln.startswith("@@OK")] == ["@@OK 0 1", "@@OK 1 0", "@@OK 2 0"]
    modules = CHECKS["LIB/elim.lib:elim"]  # the same module as Singular's
    local = ("(QQ),(x,y),(c,ds(2))", "0", "0")
    singular = [(local, ["[x,y],[0,y2]"])] * 2
    mech = [(local, ["[x+x2,y+xy],[0,y2+y3]"]), (local, ["[x,y],[0,y3]"])]
    out = subprocess.run([SINGULAR, "-q", "--no-rc", "--no-warn"], input=check_script(modules, singular, mech),
                         text=True, capture_output=True, timeout=120).stdout
    assert [ln for ln in out.splitlines() if ln.startswith("@@OK")] == ["@@OK 0 1", "@@OK 1 0"]
