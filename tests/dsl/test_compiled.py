"""Statements compiled to closures (dsl/compiled.py) behave as the evaluator by node types: the same
output and the same errors (message and file:line:col) on scripts exercising each inline path."""
from __future__ import annotations

import pytest

from mech import MechError, Session

SCRIPTS = [
    # ints: operators, comparisons, logic, div/mod, loops, x++
    "int i, k, s; for (i = 1; i <= 20; i++) { k = k + i*i - 3; if (k mod 3 == 0 && k > 10 || i == 4) { s = s + 1; } }\n"
    "k; s; -k; !s; k div 7; k mod -5; (-k) div 4; 2^10; i--; i; 7 / 2;",
    "int i; while (1) { i++; if (i < 5) { continue; } if (i > 8) { break; } } i;",
    "int k = 5;\nint j;\nfor (j = 3; j >= 0; j--) {\n  k = k div j;\n}",
    "int k = 5;\nk = k mod 0;",
    # polys, numbers and ints mixed; ring variables; monomials
    "ring r = 0, (x,y), dp; poly p = x+y; int i; number n = 3/4;\n"
    "for (i = 1; i <= 5; i++) { p = p*x + 1; p = p - x*p + y; p = i - p; p = p + n; p = 2*p; }\n"
    "p; p == p; p + 1 == p; x2y + 3x; n*p; p*n; -p; p - 1;",
    "ring r = 0, (x,y), dp; poly p = x;\np = p + z;",
    "ring r = 0, (x,y), dp; poly p = x;\nring s = 0, (x,y), lp; poly q = x;\nsetring r;\npoly t = p;\nt = t + 1;\nint k = p;",
    # entries of lists and ideals
    "ring r = 0, (x,y), dp; ideal I = x, y, x+y; list L = 1, \"a\", I;\n"
    "I[2] = I[1]*I[3]; L[1] = L[1] + 5; I; L[1]; L[2]; L[3][2]; I[1..2]; L[5] = 3; size(L);",
    "list L = 1, 2;\nL[3];",
    "ring r = 0, x, dp; ideal I = x;\nI[0];",
    # procedures
    "proc f(int a, int b) { return(a + b, a - b); }\nproc g(string s) { return(s + \"!\"); }\n"
    "int u, v; u, v = f(7, 2); u; v; g(\"hi\"); list l = f(1, 2); l; f(3, 4);",
    "proc f(int a) { int b = a + c; return(b); }\nint k = 1;\nk = f(2);",
    "proc f(int a) { return(a); }\nf(\"x\");",
    # strings
    "string s = \"a\"; int i; for (i = 1; i <= 3; i++) { s = s + string(i) + \",\"; } s; s[2]; s + s;",
    "string s = \"a\";\ns = s + 1;",
    # assignments of several values, unknown names, errors in shared lines
    "int a = 1; int b = 2; a, b = b, a; a; b; int c;\nc = a, b;",
    "int k;\nk = k + 1;\nk = k + 1;\nk = q + 1;",
    "int k = 1;\nk = k + 1;\nk = k div 0;\nk = k div 0;",
    # entries set in loops: intvec, ideal and matrix inline (padding, other rings, bounds), the rest as the evaluator
    "ring r = 0, (x,y), dp; ideal I; intvec v; matrix M[2][3]; def d = I; int i; list L;\n"
    "for (i = 1; i <= 6; i++) { v[i + 2] = i*i; I[i mod 4 + 2] = x^i + y; M[i mod 2 + 1, i mod 3 + 1] = x*i; "
    "d[i] = y^i; L[size(L) + 1] = i; }\n"
    "v; I; M; d; typeof(d); L[6]; I[2] = 3; I; v[1] = 2, 3; v; M[1,1] = 5; M;",
    "ring r = 0, (x,y), dp; matrix M[2][2]; int i;\nfor (i = 1; i <= 3; i++) {\n  M[i, 1] = x;\n}",
    "ring r = 0, (x,y), dp; ideal I = x; ring s = 0, (x,y), lp; poly p = x; int i;\nsetring r;\n"
    "for (i = 1; i <= 2; i++) {\n  I[i] = p;\n}",
    "ring r = 0, (x,y), dp; list L = 1, 2; int i;\nfor (i = 3; i <= 5; i++) { L[i] = i; } L[7] = x;\n"
    "ring s = 0, (a), dp; listvar(); setring r; L[7]; size(L);",
    "intvec v = 1, 2; int i;\nfor (i = 1; i <= 2; i++) {\n  v[i - 1] = 3;\n}",
    # commands called in loops: argument names (warnings), coercions, errors at the call
    "ring r = 0, (x,y), dp; ideal I = x2 - y, y3; poly f = x5 + y; int i, k; list L = 1, 2;\n"
    "for (i = 1; i <= 2; i++) { k = k + size(L) + deg(f) + size(string(i)); reduce(f, I); } k; deg(3);",
    "ring r = 0, (x,y), dp; int i, k;\nfor (i = 1; i <= 2; i++) {\n  k = k + deg(\"a\");\n}",
    "int i, k;\nfor (i = 1; i <= 2; i++) {\n  k = k + nosuchcommand(i);\n}",
]


def _run(script: str, compiled: bool) -> tuple[str, str]:
    s = Session()
    s.interpreter.compiled = compiled
    try:
        return s.execute(script, "t.sing"), ""
    except MechError as e:
        return getattr(e, "output", ""), str(e)


@pytest.mark.parametrize("script", SCRIPTS)
def test_same_as_the_evaluator(script):
    first = _run(script, True)  # statements of one line compile when their shared trees run again
    again = _run(script, True)
    slow = _run(script, False)
    assert first == again == slow
    assert slow[0] or slow[1]


def test_errors_name_the_line():
    out, err = _run("int k = 5;\nint j;\nfor (j = 3; j >= 0; j--) {\n  k = k div j;\n}", True)
    assert err.startswith("t.sing:4:") and "division by 0" in err


def test_a_list_follows_its_entries_ring_as_in_singular():
    # Singular 4.3.1 prints the same: L holds x after the loop of ints (it belongs to r), M holds
    # only ints after its x is replaced (it is seen from s)
    out, err = _run("ring r = 0,(x,y),dp; list L = 1,2; int i; for (i=3;i<=6;i++) { L[i] = i; } L[8] = x;\n"
                    "ring s = 0,(a),dp; listvar(); setring r; L[8]; list M = 1, x; M[2] = 3; setring s;\n"
                    "listvar(); size(M);", True)
    assert err == ""
    assert out == ("// s                              [0]  *ring\n// i                              [0]  int 7\n"
                   "// r                              [0]  ring\nx\n"
                   "// M                              [0]  list, size: 2\n// s                              [0]  *ring\n"
                   "// i                              [0]  int 7\n// r                              [0]  ring\n2\n")


def test_long_appends_keep_entries_and_ring():
    s = Session()
    out = s.execute("list L; int i; for (i = 1; i <= 3000; i++) { L[size(L) + 1] = i; } size(L); L[2999];\n"
                    "ring r = 0, (x), dp; L[3001] = x; L[3001]; ring t = 0, (y), dp; defined(L);")
    assert out == "3000\n2999\nx\n0\n"


def test_a_time_limit_stops_a_loop_of_inline_commands_and_entries():
    from mech.dsl.limits import MechLimitError
    s = Session(timeout=0.5)
    with pytest.raises(MechLimitError) as info:
        s.execute("ring r = 0, (x,y), dp; ideal I; intvec v; int i;\n"
                  "while (1) { i++; I[i mod 5 + 1] = x^(i mod 3); v[i mod 4 + 1] = i; i = i + size(string(i)) - 1; }")
    assert info.value.line == 2 and info.value.message.startswith("time limit of 0.5 s exceeded")
    assert s.execute("size(I); size(v);") == "5\n4\n"


def test_lists_pickle_and_copy_without_their_ring():
    import copy
    import pickle

    from mech.dsl.m2_values import Array
    from mech.dsl.values import List, ring_of
    s = Session()
    s.execute("ring r = 0, (x), dp; list L = 1, x; list M = 1, 2;")
    L, M = s.interpreter.lookup("L").value, s.interpreter.lookup("M").value
    assert ring_of(L) is s.interpreter.ring.poly and ring_of(M) is None
    assert ring_of(pickle.loads(pickle.dumps(M))) is None  # (polynomial rings do not pickle)
    for f in (copy.copy, copy.deepcopy):
        assert ring_of(f(M)) is None and ring_of(f(L)) is not None and len(f(L)) == 2
    assert type(copy.copy(Array([1, 2]))) is Array and ring_of(List([Array([1])])) is None
