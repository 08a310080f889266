"""Singular's everyday commands added in round 7 (issue 21): chinrem/farey on lists, ideals and
matrices, lift, print of wide matrices, ring sums, primdec.lib's equidimMax/prepareAss/testPrimary, library procedures as values, redeclarations reading the new variable, padded substrings, ASSUME, ERROR, option(warn), echo — outputs compared with the installed Singular's."""
from __future__ import annotations

import pytest

from tests.util import error, run, run_singular

SNIPPETS = {
    "chinrem_farey": """
ring r=0,x,dp;
chinrem(intvec(4,3), intvec(5,7)); chinrem(list(4,3), list(5,7)); chinrem(list(1,2), list(5,7));
ideal i1 = 2x+3x2+5x4; ideal i2 = x+51x4; ideal i3 = x+6x2+7x4;
chinrem(list(i1,i2,i3), intvec(181,32003,31991));
chinrem(list(ideal(x), ideal(x,x2)), list(2,3));
matrix m1[2][2] = 3,4,5,x; matrix m2[2][2] = 8,2,667,64;
matrix t = chinrem(list(m1,m2), intvec(3,7)); print(t);
print(farey(t, 21));
farey(-38,273); farey(235,273); farey(78,273); farey(300,273); farey(12,273); farey(7x+3,10);
bigint b = bigint(7); b^30;
""",
    "lift": """
ring A = 0,(x,y),dp;
ideal I = x10+x9y2,y8-x2y7;
matrix M = lift(I, xy13+y12); M;
matrix T = lift(I, std(I)); print(T);
print(lift(ideal(xy+y2, x2, y3), x2y)); print(lift(ideal(x2, xy, y3), x2y));
print(lift(ideal(xy+y2, x2+y2), x2y)); print(lift(ideal(x2+y, xy), x3y));
ideal K = std(ideal(x2, xy+y2)); print(lift(K, x2y));
print(lift(std(ideal(x2,y2)), ideal(x3+x2y+y, x2)));
ring r1 = 32003,(x,y,z),(c,dp);
ideal i2 = std(jacob(y7+x3+xyz+z2));
print(lift(i2, ideal(3x2+yz,7y6+2x2y+5xz)));
matrix n[2][2] = (x+y+z)^3, (x+y)^7, 1, 2; print(n);
matrix m[1][3] = x, (x+y+z)^3, y; print(m);
""",
    "ring_sum": """
ring r1=0,x,(c,dp); ring r2=0,y,(c,dp);
def r=r1+r2; r; setring r; (x+y)^2;
ring r3=0,(x,y,z),ws(1,2,3); ring s=0,(a,b),dp; r3+s; s+r3;
ring t=(0,p),(u,v),lp; r3+t; ring q=32003,(w),ds; q+s; r3+r3;
""",
    "primdec_parts": """
LIB "primdec.lib";
ring r=0,(x,y,z),dp;
equidimMax(ideal(1)); equidimMax(ideal(0)); prepareAss(ideal(1)); prepareAss(ideal(0));
radicalEHV(ideal(0)); radicalEHV(ideal(x2,y2)); equidimMaxEHV(intersect(ideal(z), ideal(x,y), ideal(x2,z2)));
list pr = primdecGTZ(ideal(x2,xy)); testPrimary(pr, ideal(x2,xy)); testPrimary(pr, ideal(x2));
prepareAss(intersect(ideal(z),ideal(x,y),ideal(x2,z2),ideal(x5,y5,z5)));
proc apply1(method, I) { def res = method(I); return(size(res)); }
apply1(minAssGTZ, ideal(xy)); typeof(minAssGTZ);
""",
    "redeclaration_substring": """
int i = 3; i = i+1; int i = i+1; i;
ring r=0,(x,y),dp; ideal I = x; ideal I = I, y; I; poly f = x; poly f = f+1; f;
string s = "a"; string s = s+"b"; s; intvec v = 1,2; intvec v = v,3; v;
proc p() { int k = 2; int k = k+1; return(k); } p();
string t = "abcde"; ">>"+t[1,10]+"<<"; ">>"+t[3,5]+"<<"; ">>"+t[5,1]+"<<";
""",
    "char_trace_intvec": """
intmat m[2][2]=1,2,3,4; trace(m);
ring r3 = 10,(x),dp; r3; ring r4 = 32004,x,dp; charstr(r4);
intvec w = 1,0,3; ideal(w); size(ideal(w));
""",
    "weighted_deg": """
ring r = 0,(x,y,z),wp(1,2,3); deg(x+y2+z3); deg(ideal(x,y2));
ring s = 0,(x,y,z),(wp(1,2),dp(1)); deg(x+y2+z3); ring t = 0,(x,y,z),ws(1,2,3); deg(x+y2+z3);
ring u=0,(x,y,z),(a(1,2,3),dp); deg(x+y2+z3); ring v=0,(x,y,z),ls; deg(x+y2+z3);
ring w=0,(x,y,z),(dp(1),wp(2,3)); deg(x+y2+z3); deg(x+y2+z3, intvec(1,1,1));
""",
    "assume_option": """
ring r = 0,x,dp;
ASSUME(0, 2+2 == 4); ASSUME(1, 0); "ok";
option(warn); option(); option(nowarn); option();
""",
}


def _lines(text: str) -> list[str]:
    return [ln.rstrip() for ln in text.splitlines() if ln.strip() and not ln.startswith("// **")]


@pytest.mark.singular
@pytest.mark.parametrize("name", sorted(SNIPPETS))
def test_as_singular(name: str) -> None:
    assert _lines(run(SNIPPETS[name])) == _lines(run_singular(SNIPPETS[name]))


def test_assume_and_error_stop_with_the_message() -> None:
    assert "ASSUME failed:ASSUME(0, 1 == 2);" in error("int k = 1;\nASSUME(0, 1 == 2);").message
    assert error('proc p() { ERROR("bad input"); }\np();').message.startswith("bad input")


def test_an_invalid_characteristic_becomes_32003_with_a_warning() -> None:
    out = run("ring r = 4,(x),dp; charstr(r);")
    assert out.splitlines() == ["// ** 4 is invalid as characteristic of the ground field. 32003 is used.", "ZZ/32003"]


def test_echo_prints_each_line_before_it_runs() -> None:
    out = run("echo = 1;\nint i = 3;\n\ni;\necho = 0;\ni;")
    assert out.splitlines() == ["<string>   2> int i = 3;", "<string>   3> ", "<string>   4> i;", "3",
                                "<string>   5> echo = 0;", "3"]
