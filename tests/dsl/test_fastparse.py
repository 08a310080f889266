"""The fast path of the parser (mech.dsl.fastparse) builds exactly Lark's trees, positions included:
on every script of the corpus, the examples and the libraries, and on random statements; it gives up
(Lark then reports the error) on whatever it does not take."""
import dataclasses
import random

import pytest

from mech.dsl import ast as A
from mech.dsl.errors import MechSyntaxError, Source
from mech.dsl.fastparse import parse_fast
from mech.dsl.parser import _parse_lark, _parser, grammar_words, parse
from mech.dsl.types import type_names

from tests.util import ROOT


def same(a, b) -> bool:
    """Structural equality of syntax trees (their nodes compare by identity)."""
    if type(a) is not type(b):
        return False
    if isinstance(a, A.Node):
        return all(same(getattr(a, f.name), getattr(b, f.name)) for f in dataclasses.fields(a))
    if isinstance(a, list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    return a == b


def fast(text: str, at=(1, 1)):
    source = Source("<t>", text)
    words, types = grammar_words()
    return parse_fast(text, at, words, types + type_names(), lambda piece, where: _parse_lark(piece, source, where))


def test_grammar_words_are_the_parsers():
    """The keywords and type names read from the grammar's text (no Lark at start-up) are the
    parser's: its string terminals that are names, its rule type_name."""
    parser = _parser()
    keywords = {t.pattern.value for t in parser.terminals
                if t.pattern.type == "str" and t.pattern.value.replace("_", "a").isalnum()}
    values = {t.name: t.pattern.value for t in parser.terminals}
    types = [values[r.expansion[0].name] for r in parser.rules if r.origin.name == "type_name"]
    words, builtin = grammar_words()
    assert set(words) | set(type_names()) == keywords and set(builtin) | set(type_names()) == set(types)


def check(text: str, at=(1, 1)) -> bool:
    """The fast parse equals Lark's (or gives up where Lark fails); whether it parsed."""
    try:
        want = _parse_lark(text, Source("<t>", text), at)
    except MechSyntaxError:
        assert fast(text, at) is None, text
        return False
    got = fast(text, at)
    assert got is not None and same(got, want), text
    return True


SCRIPTS = sorted([*ROOT.glob("tests/corpus/*.sing"), *ROOT.glob("examples/*.mech"), *ROOT.glob("stdlib/*.lib"),
                  *ROOT.glob("tests/data/*.sing")])


@pytest.mark.parametrize("path", SCRIPTS, ids=lambda p: p.name)
def test_scripts_parse_alike(path):
    assert check(path.read_text())


def test_pieces_at_other_positions():
    assert check("x = 1;\n  y[2][3] = 4, 5;", (7, 9)) and check('s = "a\nb"; t;', (3, 4))


ATOMS = ["x", "y2", "#", "7", "12/5", "3x2y", "2/3ab", '"s"', '"a\nb"', "f(x)", "f()", "I[2]", "L[1][2]", "M[1,2]",
         "poly(x)", "ideal()", "(x)", "(x, y)", "( x )"]
BINARY = ["+", "-", "*", "/", "%", "mod", "div", "^", "**", "^-", "**-", "==", "!=", "<>", "<", "<=", ">", ">=",
          "&&", "||", "and", "or", ":", ".."]
UNARY = ["-", "+", "!", "not ", ""]


def random_expr(rng: random.Random, depth: int) -> str:
    if depth == 0 or rng.random() < 0.3:
        return rng.choice(ATOMS)
    k = rng.random()
    if k < 0.6:
        return f"{random_expr(rng, depth - 1)}{rng.choice(['', ' ', '  '])}{rng.choice(BINARY)} {random_expr(rng, depth - 1)}"
    if k < 0.75:
        return rng.choice(UNARY) + random_expr(rng, depth - 1)
    if k < 0.9:
        return f"({random_expr(rng, depth - 1)})"
    return f"g({random_expr(rng, depth - 1)}, {random_expr(rng, depth - 1)})[{random_expr(rng, depth - 1)}]"


def random_statement(rng: random.Random) -> str:
    e = lambda: random_expr(rng, 3)  # noqa: E731
    return rng.choice([
        lambda: f"{e()};", lambda: f"{e()}, {e()};", lambda: f"x = {e()};", lambda: f"I[2], y = {e()}, {e()};",
        lambda: f"poly f = {e()};", lambda: "int i, j;", lambda: f"matrix m[2][3] = {e()};",
        lambda: f"list L = {e()}, {e()};", lambda: "k++;", lambda: "L[2]--;", lambda: f"{e()} = 1;",
        lambda: f"if ({e()}) {{ x = 1; }}", lambda: "LIB \"primdec.lib\";", lambda: f"// c\n{e()}; /* d */",
        lambda: f"{e()}", lambda: f"{e()};;", lambda: f"mechanism m = {e()};", lambda: f"return({e()});",
        lambda: f"if ({e()}) {{ x = 1; ; }} else {{ {e()}; }}", lambda: f"if (1) {{}} else if ({e()}) {{ k++; }} else {{}}",
        lambda: f"while ({e()}) {{ break; continue; {{ x; }} }}", lambda: f"for (int i = 1; i <= {e()}; i++) {{ x; }}",
        lambda: "for (; ; ) { }", lambda: f"if ({e()}) x = 1;", lambda: f"{{ {e()}; }}", lambda: "else { x; }",
        lambda: f"for (i = 1, j = 2; {e()}; ) {{ }}", lambda: f"while (1) {{ {e()} }}",
    ])()


def test_random_statements_parse_alike():
    rng = random.Random(23)
    parsed = 0
    for _ in range(3000):
        text = "\n".join(random_statement(rng) for _ in range(rng.randint(1, 4)))
        parsed += check(text)
    assert parsed > 1000


def test_the_parser_uses_the_fast_path_and_reports_errors_as_before():
    program = parse("ring r = 0,(x,y),dp; poly f = x2+y; if (f == 0) { f = 1; } f;")
    assert [type(s).__name__ for s in program.body] == ["Decl", "Decl", "If", "ExprStmt"]
    with pytest.raises(MechSyntaxError) as e:
        parse("x = 1;\ny = 2 +* 3;")
    assert (e.value.line, e.value.column, e.value.message) == (2, 8, "unexpected '*', expected an expression")


def run_script(text: str) -> str:
    """Output, warnings and the error (if any) of running ``text`` as a script."""
    import io
    from mech.dsl.errors import MechError
    from mech.dsl.interpreter import Interpreter
    out = io.StringIO()
    try:
        Interpreter(out=out).execute(text, "s.mech")
    except MechError as e:
        out.write(e.format())
    return out.getvalue()


SHARED = [  # repeated one-line statements: errors, warnings and notes at the line that runs
    "int k = 1; int j;\nj = 10 div k; if (1) { int a = 2; }\nif (1) { int a = 2; }\n"
    "j = 10 div k; if (1) { int a = 2; }\nk = 0; if (k) { j = 1; }\nj = 10 div k; if (1) { int a = 2; }\n",
    "int k = 1; int j;\nj = 10 div k;\nk = 0;\n  j = 10 div k;\n",
    "proc p(int v) { return (10 div v); }\nint k = 1; int j;\nj = p(k);\nk = 0;\nj = p(k);\n",
    "int k = 0; if (k) { break; }\nk = 1;\nint m = 1; if (k) { break; }\n",
    "int k = 0; int i; for (i = 1; i <= 2; i++) { if (k) { i++; continue; } }\nk = 1;\n"
    "int m = 1; for (i = 1; i <= 2; i++) { if (k) { i++; continue; } }\nif (k) { continue; }\n",
    "ring r = 0,(x,y),dp; poly f = x;\nring r = 0,(x,y),dp; poly f = x;\nf = f / 0;\nf = f / 0;\n",
    'int i = 1; execute("int q = 1/0;");\nint j = 1; execute("int q = 1/0;");\n',
]


@pytest.mark.parametrize("text", SHARED)
def test_shared_trees_keep_positions(text, monkeypatch):
    """A statement whose tree is shared with the same text on an earlier line (fastparse's table)
    reports errors and warnings exactly as when each line is parsed on its own."""
    import mech.dsl.fastparse as fp
    shared = run_script(text)
    monkeypatch.setattr(fp, "MAX_SHARED", 0)
    assert shared == run_script(text)
    assert "error" in shared or "//" in shared


def test_shared_trees_are_reused():
    """The table takes repeated one-line statements: the second copy is the first's tree, moved."""
    program = parse("int k;\nk = k + k;\nk = k + k;\n", shared=True)
    a, b = program.body[1], program.body[2]
    assert isinstance(b, A.Moved) and b.stmt is a and b.dline == 1 and b.pos.line == 3


def test_shared_table_when_full_keeps_the_newer_half(monkeypatch):
    import mech.dsl.fastparse as fp
    monkeypatch.setattr(fp, "MAX_SHARED", 4)
    fp._SHARED.clear()
    text = "int k;\n" + "".join(f"k = k + {i % 7};\nk;\n" for i in range(30))
    small = run_script(text)
    assert all(len(table) <= 4 for table in fp._SHARED.values())
    monkeypatch.setattr(fp, "MAX_SHARED", 0)
    assert small == run_script(text) and small.count("\n") == 30
