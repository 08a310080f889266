"""Singular compatibility found by the conformance run on Tst/Short, Buch and Old (session 9): each
snippet's output is compared with the installed Singular's, line by line."""
from __future__ import annotations

import pytest

from tests.util import output_lines, run, run_singular

pytestmark = pytest.mark.singular

SNIPPETS = {
    "string_escapes": r'''
string s2="how to encode a \" in a string...";
s2; size(s2);
"a\\b"; "a\nb"; "\t|";
''',
    "extgcd": """
extgcd(12,18); extgcd(-4,6); extgcd(18,12); extgcd(0,5); extgcd(7,-3);
ring r=0,(x,y),lp;
extgcd((x2+x3)*(x2-x3),(x2+x5)*(x2+x3)); extgcd(2x+2, 4x2-4); extgcd(3x2+1, 2x+3);
ring s=7,x,dp;
extgcd(3x2+1, 2x+3); extgcd(2x+2, 4x2-4);
""",
    "reserved_and_attributes": """
reservedName("ring"); reservedName("xyz"); reservedName("std"); reservedName("basering");
ring r= 32003,(x,y),lp;
ideal i=maxideal(1);
attrib(i,"isSB",1); attrib(i);
killattrib(i,"isSB"); attrib(i);
attrib(i,"isSB",1); attrib(i,"colour","red"); attrib(i,"size","big"); attrib(i);
killattrib(i,"colour"); attrib(i);
killattrib(i); attrib(i);
""",
    "procedures_without_parameters": """
proc pp
{
  if (size(#) == 0) { "none"; return(); }
  "got", size(#), #[1];
}
pp(); pp(3,5);
proc mk { ring rb(1) = 3,(x,y),lp; export rb(1); }
mk();
rb(1);
""",
    "intmat_plus_intvec": """
intvec v = 1,2;
intmat m[2][1] = 5,6;
m+v; m-v; v+m;
""",
    "factorize_with_parameters": """
ring r=(0,a),b,lp;
factorize((-4a2+8a-4)*b+2a2-2a);
ring R1=(0,x),(z,y),lp;
poly g = (x2+1)*(z2-x*y)*(z+y)^2*(2x-1);
factorize(g); factorize(g,1); factorize(g,2);
ring r7 = (7,a,b),(x,y),dp;
factorize((a2-b2)*(x2-a*y2)*(x+y)^2);
""",
    "attributes": """
ring r;
ideal i;
attrib(i,"a",x); attrib(i); attrib(i,"a");
intmat A[2][2] = 1, 0, 0, 1;
attrib(basering, "mgrad", A);
proc getGrad(def R) { attrib(R, "mgrad"); }
getGrad(basering);
intmat m[3][3] = 3, 0, 1, 0, 1, 0, 0, 0, 1;
ring R = 0, (x,y,z), M(m);
attrib(R,"global");
ring S = 0, (x,y), ds;
attrib(S,"global");
""",
    "gcd_over_algebraic_extension_mod_p": """
ring r=(32003,a),x,dp;
minpoly= a^4+20186*a^3+a^2+23269*a+1;
poly f= (6182*a+7698)*x^19+(7698*a+77)*x^16+102*x^113+91*x^3+a;
poly g= x^21+91*x^13+(127*a+102)*x^10+77*x^6+1;
poly d=a*x^3+(3757*a+20186)*x^2+23268;
gcd(d*f^3,d*g^3); gcd(f, g); gcd(d*(x+a)^2, (x+a)*(x-1));
""",
    "bigint": """
(-5) div 2, (-5) mod 2, 7 div -3, 7 mod -3, (-7) div -3, (-7) mod -3;
bigint(7) div -3, bigint(7) mod -3, bigint(-7) div -3, bigint(-7) mod -3;
bigint b=-5; b div 2; typeof(b div 2); int k = -5; typeof(k div bigint(2)); k div bigint(2); k mod bigint(2);
typeof(bigint(3)+1); bigint(-5)/2; -b; typeof(-b); bigint(2)^70; b < 3; b == -5;
proc check(bigint a, bigint b) { return((a div b)*b+(a mod b)==a && (a mod b)>=0); }
check(7,-3); check(-70000000000,3);
""",
    "empty_results_and_names": """
nameof(basering);
proc p() {  "hello"; return();}
proc q() { int a=1; }
"x"; p(); typeof(_);
"y"; q(); typeof(_);
int i = 9; print(i); typeof(_);
ring r1=32003,(x,y,z,w),lp;
ring r=32003,(x,y,z),dp;
map f=r1,x,y,z;
nameof(preimage(f)); typeof(preimage(f)); nameof(basering); nameof(i+1);
""",
    "mstd": """
ring r=0,(x,y,z,t),dp;
poly f=x3+y4+z6+xyz;
ideal j=jacob(f),f;
j=homog(j,t);
mstd(j);
ring s=0,(x,y),dp;
mstd(ideal(x2, xy, x2+xy, x3));
""",
    "rvar": """
ring r1 = 32003,(x,y,z),dp;
rvar(y); rvar(r); rvar(r1); rvar("z"); rvar("w");
""",
    "facstd": """
ring r=32003,(x,y,z),(c,dp);
ideal I=xyz,x2z;
facstd(I); facstd(I,x);
ring s=0,(x,y,z),dp;
facstd(ideal(x2-y2, z*(x-y))); facstd(ideal(x2+1));
""",
    "procedure_values": """
proc huhu(int i) { print(i); }
proc hihi() { return(huhu); }
hihi()(1);
list ll = huhu;
proc(ll[1])(2);
def ll_1 = ll[1];
ll_1(3);
""",
    "cleardenom_mod_p_with_parameters": """
ring r=(7,a),(x,y),dp;
cleardenom(a*x+a*y); cleardenom(2x+4); cleardenom((a2-1)*x+(a+1)*y);
cleardenom(3/(a+1)*x + 2/(a+1)^2); cleardenom((2a+2)*x+4*y);
ring R=(32003,a,b),(x,y),dp;
cleardenom((a/(1/2*b+1))/((b+5)/(2*(a+b)))*x+1/2*y);
""",
}


@pytest.mark.parametrize("name", sorted(SNIPPETS))
def test_as_singular(name: str) -> None:
    src = SNIPPETS[name]
    assert output_lines(run(src)) == output_lines(run_singular(src))
