"""Singular's syntax and assignment corners (issue 21): ``return(x)`` and a string closing a block without ``;``, quotes in names, backquotes,
an ``else`` without ``if`` (skipped), several values into a list entry or a def, ``LIB("x.lib")``."""
from __future__ import annotations

from tests.util import error, run


def test_return_without_semicolon() -> None:
    assert run("proc f(){ if(1) { return(1) } return(0) }\nf();\nproc g(){ return(2) }\ng();").split() == ["1", "2"]


def test_string_without_semicolon_closes_a_block() -> None:
    """As Singular (Manual/lusolve.tst): a string literal may close a block without its ``;``."""
    assert run('if (1) { "x"; "y" }\nif (0) { 1; } else { "z" }\nproc p() { 2; "in p" }\np();') == "x\ny\nz\n2\nin p\n"
    assert "unexpected '}'" in str(error("int i; if (1) { i }"))


def test_names_with_quotes_and_backquoted_names() -> None:
    """As Singular (Manual/Names_3.tst, ring.lib's changevar): quotes in names, `s` the variable named s."""
    assert run("int a'b = 1; int c'' = 2; a'b + c'';") == "3\n"
    script = 'int foo(1) = 42; string bar = "foo"; `bar+"(1)"` + 1;\nring r = 0,(x,y),dp; `"y"`;'
    assert run(script) == "43\ny\n"
    assert "`foo` is undefined" in str(error('string bar = "foo"; `bar`;'))
    assert "needs a string" in str(error("`5`;"))


def test_assigning_an_increment_is_ignored() -> None:
    """As Singular (Manual/int_operations.tst): ``j = i++;`` changes i, warns and leaves j."""
    out = run("int i = 1; int j;\nj = i++;\nj; i;\nj = i--; i;")
    assert out.splitlines() == ["// ** right side is not a datum, assignment ignored in line >>j = i++;<<", "0", "2",
                                "// ** right side is not a datum, assignment ignored in line >>j = i--; i;<<", "1"]


def test_a_character_out_of_range_is_empty() -> None:
    """As Singular (Old/string.tst): s[0] and s[9] of an 8-character string read as ""; writing there is an error."""
    assert run('string s = "abcdefgh"; s[0]; s[9]; s[-1]; s[2];') == "\n\n\nb\n"
    assert "out of range" in str(error('string s = "ab"; s[0] = ".";'))


def test_dangling_else_is_skipped() -> None:
    assert run('if (0) {1;}\nint i;\nelse\n{ 5; }\n"done";').split() == ["done"]


def test_several_values_into_a_list_entry() -> None:
    out = run("ring r; list L = ideal(x); L[1] = L[1], L[1]; L;")
    assert out.split() == ["[1]:", "_[1]=x", "_[2]=x"]
    assert "several values" in str(error("list L = 1, 2; L[1] = 3, 4;"))
    assert "several values" in str(error("list L; L[1] = 1, 2;"))
    assert "one value" in str(error("def d = 1, 2;"))


def test_matrix_resize_needs_positive_sizes() -> None:
    assert "positive" in str(error("ring r; matrix A[1][1] = 8; matrix(A, 1, 0);"))


def test_map_assignment_and_entries() -> None:
    src = "ring R=0,(x,y),dp; ring S=0,(a,b),dp; map phi=R,a,b; phi=R,a2,3; phi(x+y); phi[2]=b2; phi(x+y);"
    assert run(src).split() == ["a2+3", "a2+b2"]


def test_lib_with_parentheses() -> None:
    """``LIB("x.lib");`` is Singular's other spelling of ``LIB "x.lib";``."""
    assert run('LIB("poly.lib"); ring r = 0,(x,y),dp; ideal i = x2, y3; vdim(std(i));').split() == ["6"]
    assert "unknown library 'nosuch.lib'" in str(error('LIB("nosuch.lib");'))
