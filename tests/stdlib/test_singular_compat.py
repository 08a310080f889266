"""Singular's commands and language pieces that mech took over for compatibility (issue 21): each
snippet's output is compared with the installed Singular's, line by line."""
from __future__ import annotations

import pytest

from tests.util import output_lines, run, run_singular

pytestmark = pytest.mark.singular

SNIPPETS = {
    "indexing": """
ring r=0,(x,y,z),dp;
poly f = x2+y3+2z;
f[2..3]; f[-1]; f[5];
string s = "hello world";
s[2,3]; s[1,1];
defined(42);
""",
    "execute": """
int a = 1;
execute("a = a + 41; a;");
ring r = 0,(x,y),dp;
execute("poly g = x+y;"); g;
proc p() { execute("int b = 5;"); return(b); }
p();
""",
    "polyops": """
LIB "general.lib"; LIB "polylib.lib";
ring r=0,(x,y,z),dp;
gcd(2x2-2, 4x-4); gcd(12,18); gcd(-12,18);
lcm(2x2-2, 4x-4); lcm(x2,xy,y3); lcm(4,6);
resultant(x2+y, x3-y2+1, x); resultant(x2+y, x3-y2+1, y); resultant(2x2+y, 3x-y, x);
gcd(2x2*y, 4xy3); gcd(2/3*x, 4x);
cyclic(3);
poly f = 3x2y+2xz-z;
coef(f, x); coef(f, xz); coeffs(f, x); coeffs(ideal(f, x2+1), x);
prime(100); prime(2);
find("abcabc","c"); find("abcabc","c",4); find("abc","z");
ring s = 7,(a,b),dp;
gcd(a2-b2, 3a+3b); resultant(a3+b, a2*b-1, a);
""",
    "idealops": """
ring r=0,(x,y,z),dp;
ideal i = 2x2+4y, 3x2+y, 6xy, x3+y2, 0;
interred(i);
option(redSB); interred(i); option(noredSB);
interred(ideal(x2+xy+y2, xy+z, z2+x));
ideal j = std(ideal(x2-y, xy-z));
std(j, z3-x); std(j, ideal(z3-x, y3));
reduce(x3+y3+z, j, 1);
indepSet(std(ideal(xy, xz))); indepSet(std(ideal(xy, xz)), 1); indepSet(std(ideal(xy, xz)), 0);
simplify(ideal(0,2x,x,0,3x2+y),1); simplify(ideal(0,2x,x,0,3x2+y),2); simplify(ideal(0,2x,x,0,3x2+y),4);
simplify(ideal(0,2x,x,0,3x2+y),8); simplify(ideal(0,2x,x,0,3x2+y),7);
simplify(ideal(x2,xy,x2+y,x3),32); simplify(ideal(x2,xy,x2+y,x3),16);
minbase(ideal(x2, xy, x2+xy, x3, y2));
ring s=0,(x,y),ds;
reduce(x+y3, std(ideal(x-x2)), 1);
ring R=0,(a,b,c),dp;
ring S=0,(x,y),dp;
map phi = R, x2, xy, y2;
ideal zero;
setring R;
preimage(S, phi, zero);
setring S; ideal J = x-y; setring R;
preimage(S, phi, J);
""",
    "listvar": """
int a = 3;
intvec v = 1,2;
string s = "ab";
list L = 1,2;
ring r=0,(x,y,z),dp;
poly f = x;
ideal i = x,y;
matrix m[2][3];
number n = 3;
map phi = r, x,y,z;
ring r2 = 7,(a,b),lp;
poly g = a;
listvar();
listvar(all);
listvar(r);
setring r;
listvar();
proc t() { int k = 2; poly u = x; listvar(); listvar(all); }
t();
""",
    "sysvars": """
int debug=0;
intvec i=1,2,3;
dbprint(debug,i);
debug=1;
dbprint(debug,i, "abc");
proc p() { dbprint(i); "in p"; dbprint(printlevel-voice+3, "lev"); }
p();
printlevel = 1;
p();
ring r = 0,(x,y),dp;
short;
poly f = 3x2y+1;
f;
short = 0;
f;
ideal j = f, x;
j;
matrix m[1][2] = f,x;
print(m);
short;
short = 1; f;
ring s = 0,(x(1..2)),dp;
short;
x(1)^2;
degBound; noether;
""",
    "attrib": """
ring r=0,(x,y,z),dp;
ideal I=std(maxideal(2));
attrib(I);
attrib(I,"isSB");
ideal J = x2, y;
attrib(J);
attrib(J,"isSB");
attrib(J, "isSB", 1);
attrib(J);
attrib(J, "isSB");
reduce(x3+y, J);
J = x2, x2+y;
attrib(J, "isSB");
int i = 3;
attrib(i);
attrib(r, "lll", "str1");
intmat m[1][1] = -4;
attrib(r, "ll", m);
attrib(r);
attrib(r, "ll"); attrib(r, "global"); attrib(r, "isLetterplaceRing");
ring s = 0,(x,y),ds;
attrib(s); attrib(s, "global");
""",
    "intmat": """
intmat m[2][3] = 1,-2,3,40,5;
m;
print(m);
typeof(m);
m[2,1];
m[1,2] = 7; m;
intmat n[2][3] = 1,1,1,1,1,1;
m+n; m-n; 3*m;
m*transpose(n);
transpose(m);
nrows(m); ncols(m);
intmat k = m;
k;
intmat q[2][2] = 1,2,3,4;
det(q);
q*q;
size(m);
m == m;
intmat e[2][2];
e;
intmat u = intmat(intvec(1,2,3,4),2,2);
u;
q * intvec(1,1);
-q;
q[1,1..2];
q + 1; 1 + q; q - 1; q div 2;
intmat wm[1][6] = -5,-1,5,1,-4,4;
wm div 2; wm div -2; wm / 2; wm % 2; wm % -2;
intvec vv = -5,-1,5,1,-4,4;
vv div 2; vv div -2; vv / 2; vv % 2; vv mod -2;
intmat b[2][2]; b = 1,2,3; b;
intmat big[2][2] = 1,-2,123456789,4;
print(big);
intvec w = 1,2; intmat y = w; y; print(y);
listvar();
ring r = 0,x,dp;
matrix M = q; M;
""",
    "qring": """
ring R = 32003,(x,y,z),dp;
ideal I = x2+y2-z5, z-x-y2;
qring Q = groebner(I);
Q;
typeof(Q);
poly f = z2 + y2;
poly g = z2+2x-2z-3z5+3x2+6y2;
f*g;
reduce(f-g,std(0));
std(0);
ideal q = quotient(0,f);
q;
q = reduce(q,std(0));
size(q);
std(ideal(x));
dim(std(ideal(x)));
basering;
ideal(basering);
setring R;
ring S = 0,(x,y),dp;
qring T = std(ideal(x2, y3));
poly h = x3+xy;
h;
h*x;
h^2;
ideal zz = h, y;
zz;
std(zz);
vdim(std(0));
kbase(std(0));
""",
    "qring_coordinate_ring": """
ring A = 0,(x,y,z),dp;
ideal I = x2+y2+z2-1, x-y;
qring KV = std(I);
KV;
poly f = x3+y;
reduce(f, std(0));
NF(x2, std(0));
dim(std(0));
dim(std(ideal(z)));
std(ideal(x*z));
vdim(std(ideal(z)));
kbase(std(ideal(z)));
setring A;
ring L = 0,(x,y),ds;
qring LQ = std(ideal(y2-x3));
dim(std(0));
reduce(y3, std(0));
std(ideal(y));
vdim(std(ideal(y)));
ideal(basering);
""",
    "more_commands": """
ring r=0,(x,y,z),dp;
"a"+newline+"b";
leadexp(3x2y+z5);
rvar(y); rvar("z"); rvar(x2); rvar("w");
jet(x2+y3+z+1, 2);
jet(ideal(x2+y3, z4+x), 2);
cleardenom(1/2x2+1/3y);
cleardenom(-2x2+4y);
chinrem(intvec(2,3), intvec(5,7));
chinrem(list(2,3), list(5,7));
ideal I = x2-1, y2-x, z-y;
finduni(std(I));
ring s = 0,(x,y,z),lp;
setring r;
ideal J = std(ideal(x2-y, y2-1, z3-x));
setring s;
fglm(r, J);
""",
    "algebra_lib": """
LIB "algebra.lib";
ring r = 0,(a,b,c),dp;
ring s = 0,(x,y,z,u,v,w),dp;
ideal I = x-w,u2w+1,yz-v;
map phi = r,I;
alg_kernel(phi,r);
is_injective(phi,r);
is_surjective(phi,r);
is_bijective(phi,r);
ring A = 0,(x,y),dp;
ring B = 0,(s,t),dp;
map psi = A, s2, s3;
is_injective(psi, A);
is_surjective(psi, A);
alg_kernel(psi, A);
is_bijective(psi, A);
ring B2 = 0,(p,q),dp;
map sw = A, q, p+q2;
is_bijective(sw, A);
ring C = 0,(e),dp;
map pp = A, e, e2;
is_bijective(pp, A);
""",
    "matrix_ranges": """
ring r=0,(x,y),dp;
matrix m[3][3] = 1,2,3,4,5,6,7,8,x;
m[1..2,1];
matrix B[2][2] = m[2..3, 2..3];
print(B);
m[3,1..3];
list l1 = 1,2,3;
insert(l1,"-",3);
""",
    "algebra_lib_maps": """


ring S = 0,(a,b,c),lp;
ring R = 0,(x,y,z),dp;
ideal i = x, y, x2-y3;
map phi = S,i;
LIB "algebra.lib";

is_injective(phi,S);

ideal j = x, x+y, z-x2+y3;
map psi = S,j;
is_injective(psi,S);

alg_kernel(phi,S);

alg_kernel(psi,S);

is_surjective(psi,S);

is_bijective(psi,S);

""",
}


@pytest.mark.parametrize("name", sorted(SNIPPETS))
def test_as_singular(name: str) -> None:
    src = SNIPPETS[name]
    assert output_lines(run(src)) == output_lines(run_singular(src))
