"""The grammar on every construct of Singular's statement language, and syntax errors."""
import pytest

from mech.dsl import ast as A
from mech.dsl.errors import MechSyntaxError
from mech.dsl.parser import parse
from mech.dsl.split import split_complete


def one(src):
    prog = parse(src)
    assert len(prog.body) == 1
    return prog.body[0]


def expr(src):
    s = one(src + ";")
    assert isinstance(s, A.ExprStmt)
    assert len(s.exprs) == 1
    return s.exprs[0]


def show(e):
    """A compact prefix form of an expression tree."""
    if isinstance(e, A.Name):
        return e.id
    if isinstance(e, A.IntLit):
        return str(e.value)
    if isinstance(e, A.RatLit):
        return f"{e.num}/{e.den}"
    if isinstance(e, A.MonomLit):
        return f"<{e.num}/{e.den}:{e.monomial}>"
    if isinstance(e, A.StrLit):
        return repr(e.value)
    if isinstance(e, A.BinOp):
        return f"({e.op} {show(e.left)} {show(e.right)})"
    if isinstance(e, A.UnOp):
        return f"({e.op} {show(e.operand)})"
    if isinstance(e, A.Range):
        return f"(.. {show(e.lo)} {show(e.hi)})"
    if isinstance(e, A.Index):
        return f"{show(e.base)}[{', '.join(show(i) for i in e.indices)}]"
    if isinstance(e, A.Call):
        return f"{show(e.func)}({', '.join(show(a) for a in e.args)})"
    if isinstance(e, A.TypeCall):
        return f"{e.type}!({', '.join(show(a) for a in e.args)})"
    if isinstance(e, A.Tuple):
        return f"[{', '.join(show(a) for a in e.items)}]"
    raise AssertionError(e)


@pytest.mark.parametrize("src, tree", [
    ("1 + 2 * 3", "(+ 1 (* 2 3))"),
    ("1 - 2 - 3", "(- (- 1 2) 3)"),
    ("-2^2", "(- (^ 2 2))"),
    ("2^3^2", "(^ (^ 2 3) 2)"),
    ("2**3", "(^ 2 3)"),
    ("a^-1", "(^ a (- 1))"),
    ("a div b mod c % d", "(mod (mod (div a b) c) d)"),
    ("a / b", "(/ a b)"),
    ("7/2", "7/2"),
    ("x^2/3", "(^ x 2/3)"),
    ("3x2y + 1/2x - 7", "(- (+ <3/1:x2y> <1/2:x>) 7)"),
    ("x2y", "x2y"),
    ("1 or 0 and 0", "(&& (|| 1 0) 0)"),
    ("a || b && c", "(&& (|| a b) c)"),
    ("!a == b", "(== (! a) b)"),
    ("not a", "(! a)"),
    ("a == b != c", "(!= (== a b) c)"),
    ("a <> b", "(!= a b)"),
    ("a < b + 1", "(< a (+ b 1))"),
    ("a <= b", "(<= a b)"),
    ("a >= b", "(>= a b)"),
    ("a > b", "(> a b)"),
    ("1..n+1", "(.. 1 (+ n 1))"),
    ("0:3", "(: 0 3)"),
    ("L[2][1]", "L[2][1]"),
    ("M[i,j]", "M[i, j]"),
    ("I[1..2]", "I[(.. 1 2)]"),
    ("std(I)", "std(I)"),
    ("f()", "f()"),
    ("c1*s1*c2", "(* (* c1 s1) c2)"),
    ("ideal(x, y)", "ideal!(x, y)"),
    ("list()", "list!()"),
    ("string(1)", "string!(1)"),
    ("(1, 2)", "[1, 2]"),
    ("((a))", "a"),
    ("x(1..n)", "x((.. 1 n))"),
    ('"a // not a comment"', "'a // not a comment'"),
    ("size(#)", "size(#)"),
    ("-x", "(- x)"),
    ("+x", "(+ x)"),
])
def test_expressions(src, tree):
    assert show(expr(src)) == tree


def test_declarations():
    d = one("int i = 3;")
    assert isinstance(d, A.Decl) and d.type == "int" and d.items[0].name == "i" and show(d.value[0]) == "3"
    d = one("ideal I, J;")
    assert [x.name for x in d.items] == ["I", "J"] and d.value is None
    d = one("matrix D[5][6];")
    assert d.type == "matrix" and [show(x) for x in d.items[0].dims] == ["5", "6"]
    d = one("matrix M[3][4] = 1, 2, x;")
    assert len(d.value) == 3
    d = one("list v = c1, s1, c2;")
    assert [show(v) for v in d.value] == ["c1", "s1", "c2"]
    d = one("map phi = r, x+1, y;")
    assert d.type == "map" and len(d.value) == 3
    for t in ["number", "poly", "string", "intvec", "def", "bigint", "intmat", "module", "vector", "qring"]:
        assert one(f"{t} a;").type == t


@pytest.mark.parametrize("src, parts", [
    ("ring r = 0, (x,y,z), dp;", ["0", "[x, y, z]", "dp"]),
    ("ring r = 32003, (x(1..5)), (dp(4),dp(2));", ["32003", "x((.. 1 5))", "[dp(4), dp(2)]"]),
    ("ring r = (0,a,b), (x,y), dp;", ["[0, a, b]", "[x, y]", "dp"]),
    ("ring r = 0, (x,y,z,w), (a(1,2,3), dp(2), lp(1), C);",
     ["0", "[x, y, z, w]", "[a(1, 2, 3), dp(2), lp(1), C]"]),
    ("ring r = 0, x, wp(1,2);", ["0", "x", "wp(1, 2)"]),
    ("ring r = 0, (x,y), M(1,1,0,-1);", ["0", "[x, y]", "M(1, 1, 0, (- 1))"]),
    ("ring r = 0, (x,y), (c, ls);", ["0", "[x, y]", "[c, ls]"]),
])
def test_ring_declarations(src, parts):
    d = one(src)
    assert d.type == "ring" and [show(v) for v in d.value] == parts


def test_orderings_parse():
    for o in ["lp", "dp", "Dp", "wp(1,2)", "Wp(1,2)", "ls", "ds", "Ds", "ws(1,2)", "Ws(1,2)", "(a(1,1),dp)",
              "M(1,1,0,-1)", "(c,dp)", "(dp,C)"]:
        assert one(f"ring r = 0, (x,y), {o};").type == "ring"


def test_assignments():
    a = one("I[2] = x;")
    assert isinstance(a, A.Assign) and show(a.targets[0]) == "I[2]"
    assert show(one("D[i,j] = diff(J[i], v[j]);").targets[0]) == "D[i, j]"
    assert show(one("L[3][1] = 5;").targets[0]) == "L[3][1]"
    a = one("a, b = 1, 2;")
    assert len(a.targets) == 2 and len(a.values) == 2
    assert isinstance(one("i++;"), A.IncDec) and one("i--;").delta == -1
    with pytest.raises(MechSyntaxError, match="cannot assign"):
        parse("1 = 2;")
    with pytest.raises(MechSyntaxError, match="cannot assign"):
        parse("f(x)[1] + 1 = 2;")
    assert isinstance(one("len(2) = 2;"), A.Assign)  # a variable declared as `int len(2)`


def test_control_flow():
    s = one("if (a) { 1; } else { 2; }")
    assert isinstance(s, A.If) and len(s.then) == 1 and len(s.orelse) == 1
    s = one("if (a) { 1; } else if (b) { 2; } else { 3; }")
    assert isinstance(s.orelse[0], A.If)
    assert one("if (a) { 1; }").orelse is None
    s = one("for (i = 1; i <= n; i++) { s = s + i; }")
    assert isinstance(s, A.For) and isinstance(s.init, A.Assign) and isinstance(s.step, A.IncDec)
    s = one("for (int i = 1; i <= n; i = i + 1) { }")
    assert isinstance(s.init, A.Decl) and s.body == []
    s = one("while (i < 10) { i++; if (i == 5) { break; } continue; }")
    assert isinstance(s, A.While) and isinstance(s.body[1].then[0], A.Break)
    assert isinstance(s.body[2], A.Continue)
    assert isinstance(one("{ 1; 2; }"), A.Block)


def test_procedures():
    p = one("proc f(int n, ideal I) { return(n); }")
    assert isinstance(p, A.ProcDef) and [(x.type, x.name) for x in p.params] == [("int", "n"), ("ideal", "I")]
    assert isinstance(p.body[0], A.Return) and show(p.body[0].values[0]) == "n"
    p = one('proc g(a, b)\n"USAGE: g(a, b)"\n{\n  return(a, b);\n}')
    assert [x.type for x in p.params] == [None, None] and p.doc == "USAGE: g(a, b)" and len(p.body[0].values) == 2
    p = one("proc h(list #) { return(); }")
    assert p.params[0].name == "#" and p.body[0].values == []
    assert one("static proc k() { }").static
    assert one("proc m { 1; }").params is None


def test_other_statements():
    assert isinstance(one("kill x, y;"), A.Kill)
    assert isinstance(one("export(I);"), A.Export)
    assert isinstance(one("export I;"), A.Export)
    assert isinstance(one("keepring r;"), A.Keepring)
    assert one('LIB "primdec.lib";').name == "primdec.lib"
    assert isinstance(one("setring r;"), A.Setring)
    assert isinstance(one("quit;"), A.Quit) and isinstance(one("exit;"), A.Quit)
    assert one("help std;").topic == "std" and one("help;").topic is None
    assert isinstance(one("option(redSB);"), A.ExprStmt)
    assert isinstance(one('system("--ticks-per-sec", 1000);'), A.ExprStmt)
    assert isinstance(one(";"), A.Empty)
    assert len(parse("int i; int j; timer; rtimer; print(M); basering;").body) == 6


def test_comments_and_strings():
    prog = parse('// line\nint i = 1; /* block\n comment */ string s = "x /* y */";  // end')
    assert len(prog.body) == 2 and prog.body[1].value[0].value == "x /* y */"
    assert parse('string t = "two\nlines";').body[0].value[0].value == "two\nlines"


def test_positions():
    s = one("ideal I = std(J);")
    call = s.value[0]
    assert (call.pos.line, call.pos.col, call.pos.end_col) == (1, 11, 17)
    prog = parse("int i;\n  poly p = x;")
    assert prog.body[1].pos.line == 2 and prog.body[1].pos.col == 3


@pytest.mark.parametrize("src, line, col, msg", [
    ("ring r = 0, (x,y), dp; ideal I = x2 +* y;", 1, 38, "unexpected '*', expected an expression"),
    ("int i = 1\nint j = 2;", 1, 10, "expected ';'"),
    ("int i = (1;", 1, 11, "unexpected ';', expected ')'"),
    ("if (1) { 2;", 1, 12, "missing '}'"),
    ('string s = "abc', 1, 12, "unterminated string"),
    ("int i = 1 $ 2;", 1, 11, "unexpected character '$'"),
    ("f(1,,2);", 1, 5, "unexpected ','"),
    ("x +", 1, 4, "incomplete statement"),
    ("ideals I = x;", 1, 8, "'ideals' is not a type"),
])
def test_syntax_errors(src, line, col, msg):
    with pytest.raises(MechSyntaxError) as info:
        parse(src)
    assert (info.value.line, info.value.column) == (line, col)
    assert msg in info.value.message


def test_split_complete():
    assert split_complete("int i; if (1) {2;}") == (18, False)
    assert split_complete("int i; if (1) {2;} else") == (6, True)
    assert split_complete("int i; if (1) {") == (6, True)
    assert split_complete("int i; x") == (6, True)
    assert split_complete("int i; /* ") == (6, True)
    assert split_complete('int i; "abc') == (6, True)
    assert split_complete("proc f() {1;} 2;") == (16, False)
    assert split_complete("for (i=1; i<3; i++) { }") == (23, False)
    assert split_complete("// only a comment\n") == (0, False)
