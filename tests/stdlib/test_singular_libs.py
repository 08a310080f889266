"""Commands of Singular's libraries (matrix, general, ring, inout, polylib, sing, algebra, standard,
primdec, elim) and the built-ins ord, contract, ludecomp, lusolve, luinverse, rank, primefactors,
numerator, denominator, variables, univariate, sortvec, tensor, wedge, jacob(matrix), intvec(intmat),
vandermonde, highcorner, interpolation, kernel, frwalk, koszul: each
snippet runs the library's kind of example and further cases; its output is compared with the
installed Singular's, line by line (the help examples are compared in test_help_examples)."""
from __future__ import annotations

import pytest

from tests.util import output_lines, run, run_singular

pytestmark = pytest.mark.singular

SNIPPETS = {
    "matrix_build": """
LIB "matrix.lib";
ring r = 0,(x,y,z),ds;
matrix A[3][3] = 1,2,3,x,y,z,x2,y2,z2;
matrix B[2][2] = 1,0,2,0; matrix C[1][4] = 4,5,x,y;
print(concat(A,B,C)); print(concat(B,C));
print(diag(xy,3)); print(diag(B));
print(dsum(A,B)); print(dsum(C,B,C));
print(outer(B,C)); print(outer(C,B));
print(headStand(A));
print(submat(A,intvec(3,1),2..3)); flatten(B);
print(power(A,2)); print(power(B,0));
intmat M[2][2] = 1,2,3,4; print(power(M,5));
""",
    "matrix_ops": """
LIB "matrix.lib";
ring r = 32003,(x,y,z),lp;
matrix A[3][3] = 1,2,3,4,5,6,7,8,9;
print(addcol(A,1,xy,2)); print(addrow(A,1,xy,3)); print(addrow(A,3,-z,1));
print(multcol(A,2,xy)); print(multrow(A,3,x+1));
print(permcol(A,2,3)); print(permrow(A,2,1)); print(permrow(A,3,3));
""",
    "matrix_gauss": """
LIB "matrix.lib";
ring r = (0,a,b),(A,B,C),dp;
matrix m[3][4] = 0,2,a,A, b,1,0,B, 2b,4,2a,C;
print(rowred(m)); list L = rowred(m,1); print(L[1]); print(L[2]);
print(colred(transpose(m))); L = colred(transpose(m),1); print(L[1]); print(L[2]);
ring s = 0,(x,y),dp;
matrix u[3][4] = 1,0,x,2,0,1,y,3,0,0,1,x;
print(rm_unitcol(u)); print(rm_unitrow(transpose(u)));
def S = symmetricBasis(3, 2, "t"); setring S; S; symBasis;
""",
    "general": """
LIB "general.lib";
A_Z("c",5); A_Z("Z",-5); A_Z("x",6); A_Z_L("b",3);
ASCII(); ASCII(42); ASCII(32,126); ASCII(97,99);
absValue(-2002); absValue(17);
factorial(37); factorial(0); fibonacci(42); fibonacci(1);
primes(50,100); primes(37,1); primes(2,2);
list l = 1,2,3,4,5; deleteSublist(intvec(1,3,4),l); deleteSublist(intvec(5),l);
number_e(30); primecoeffs(intvec(7*8*121,7*8));
primefactors(7^4*11*37^2); primefactors(1001, 7); primefactors(-12);
ring r = 0,(x,y,z),dp;
poly f = -4; absValue(f); absValue(-1/3);
number e = number_e(12); e;
ideal m = maxideal(1); product(m); product(m[2..3]);
matrix M[2][3] = 1,x,2,y,3,z; product(M); product(M,intvec(2,4,6));
intvec iv = 1,2,3,4,5,6,7,8,9; product(iv,1..5); product(iv,12);
intmat T[2][3] = 1,1,1,2,2,2; product(T,3..5); product(list(x,y,3));
sum(m); sum(M,intvec(2,4,6)); sum(iv,2..4); sum(intvec(1..100)); sum(M,9); sum(T);
primecoeffs(ideal(-13x6y3z+4x5y4z,-10x4y2z-5x4yz2));
lcm(ideal(x2-y2, x+y), x-y); lcm(2..6); lcm(2,3,6);
""",
    "ring": """
LIB "ring.lib";
def r = defring("0",5,"u","ls"); r; setring r;
def R = defring("(2,A)",10,"x(","(dp(3),ws(1,2,3),ds)"); R;
def S5 = defrings(5,0); S5; def S3 = defringp(3); S3;
ring t = 0,(x,y,u,v),(dp(2),ds);
ideal i = x^2,y^2-u^3,v;
qring Q = std(i);
setring t;
def T = changevar("A()"); T;
def Q2 = changevar("a,b,c,d",Q); setring Q2; isQuotientRing(Q2); reduce(a2+b2+c3, std(0));
ring R1 = 0,(x,y),dp; ring S1 = 0,(u,v),ls;
ord_test(R1); ord_test(S1); ord_test(R1+S1);
ring w = 0,x(1..5),(ds(3),wp(2,3)); ringweights(w); ringweights(R1);
isQuotientRing(w); isQuotientRing(Q); hasCommutativeVars(w);
ring q = (0,q),(x,y,z),dp;
rootofUnity(6); rootofUnity(7); rootofUnity(12); rootofUnity(1);
minpoly = rootofUnity(8); q;
ring a1 = 32003,(x,y,u,v),dp; ring a2 = 0,(a,b,c),wp(1,2,3); ring a3 = 0,x(1..3),(c,ls);
def RT = ringtensor(a1,a2,a3); RT;
""",
    "inout": """
LIB "inout.lib";
ring r = 0,(x,y,z),ls;
ideal i = x,z+3y,x+y,z;
matrix m[3][3] = i^2;
pmat(m); pmat(m,5); pmat(m,3);
for (int n = 0; n <= 3; n++) { tab(3-n)+"*"+tab(n)+"+"; }
ring s = 0,(x,y,z),ds;
poly f = (x+y+z)^4;
split(string(f),50); split(lprint(f)); lprint(f,30);
poly g = (x+y)*(x-y)*(x+z)*(y+z)^2;
lprint(g,40); lprint(ideal(g,x),40);
string s1 = "x[0]3-101/74x[0]2x[1]+7371x[0]x[1]2-13/83x[1]3-x[0]2x[2]-4/71x[0]x[1]x[2]";
rMacaulay(s1);
string s2 = "
0  0  0
a3 0  0
0  b3 1 ";
rMacaulay(s2);
rMacaulay("first line
x[1]2-x[2]", 1);
ring t = 2,(a,b,c,d,x,y),ds;
poly f = y+ax2+bx3+cx2y2+dxy3;
showrecursive(f,x); showrecursive(f,xy,"lp"); showrecursive(f,abcd);
allprint("not shown");
int ALLprint = 0;
allprint("M =", f);
""",
    "polylib": """
LIB "polylib.lib";
ring r = 0,(x,y,z),ls;
poly f = x5+y2+z3;
ord(f); mindeg(f); mindeg1(f,intvec(1,-3,2)); maxdeg(f); maxdeg1(f,intvec(2,1,1));
matrix m[2][2] = x10,1,0,f^2;
mindeg(m); maxdeg(m); mindeg1(m,1..3); maxdeg1(m,1..3);
ring w = 0,(x,y,z),wp(1,2,3);
ord(x+y2+z3); ord(0); maxdeg(x+y2+z3);
ring d = 0,(x,y,z),ds;
poly g = 345x2-1234567890y+7/4z;
maxcoef(g); maxcoef(ideal(g,10/1234567890));
ring q = 0,(b,c,t),dp;
ideal I = -bc+4b2c2t,bc2t-5b2c;
substitute(I,c,b+c,t,0,b,b-1);
substitute(I,ideal(c,t,b),ideal(b+c,0,b-1));
ring e = 0,(u,v,w,x,y,z),lp;
elemSymmPoly(3,2,5); elemSymmPoly(6,1,6); elemSymmId(3);
newtonDiag(x2y+3xz-5y+3);
ring h = 0,(b,c,t,h),dp;
ideal H = bct-t2h+2th2+h3, bt3-ct3-t4+b2th+c2th-2bt2h+2ct2h+2t3h-bch2-2bth2+2cth2+2th3;
hilbPoly(H); hilbPoly(ideal(b2,c));
ring k = 0,(x,y,z),dp;
katsura(); katsura(2); katsura(4); basering;
setring k;
rad_con(x4+y4, ideal(x2+y2,z2)); rad_con(z, ideal(x2+y2,z2)); rad_con(x+y, ideal((x+y)^3));
""",
    "builtins": """
ring r = 0,(a,b,c,d),dp;
ideal I = a2,a2+bc,abc;
ideal J = a2-bc,abcd;
print(contract(I,J)); print(contract(ideal(a,b),ideal(a2b+b3,cd)));
ring s = 0,x,dp;
matrix A[3][4] = 1,2,3,4,1,1,1,1,2,2,1,1;
list plu = ludecomp(A);
print(plu[1]); print(plu[2]); print(plu[3]); print(plu[1]*A-plu[2]*plu[3]);
matrix C[2][2] = 1/3,1,2,1; plu = ludecomp(C); print(plu[1]); print(plu[3]);
matrix B[4][4] = 1,1,1,0,1,2,3,1,1,3,5,2,1,4,7,3;
matrix v[4][1] = 2,5,8,11;
list L = ludecomp(B);
list Q = lusolve(L[1],L[2],L[3],v);
Q[1]; print(Q[2]); print(Q[3]);
matrix E[3][3] = 1,2,3,1,1,1,2,2,1;
list N = luinverse(E); N[1]; print(N[2]);
matrix F[2][2] = 1,2,2,4; luinverse(F); rank(F); rank(E); rank(A);
ring t = 0,(x,y,z),dp;
number n = -6/4; numerator(n); denominator(n); numerator(5); denominator(5);
variables(2); variables(x+y2); variables(ideal(z, x3y)); univariate(x2+1); univariate(1); univariate(z+z2);
sortvec(ideal(y,z,x,x3,xz)); sortvec(ideal(x,0,1));
matrix P[2][2] = x,y,0,z; matrix Q[1][2] = 1,2; print(tensor(Q,P)); print(tensor(P,Q));
print(jacob(P)); intmat im[2][3] = 1,2,3,4,5,6; intvec(im);
ring v2 = 0,(x,y),dp;
poly ip = vandermonde(ideal(2,3),ideal(1,2,3,4,5,6,7,8,9),2); ip;
subst(subst(ip,x,2^8),y,3^8); vandermonde(ideal(2,3),ideal(1,2,3,4),1);
highcorner(std(ideal(x2,y3))); highcorner(std(ideal(x)));
ideal J = interpolation(list(ideal(x,y),ideal(x-1,y)),intvec(2,1));
size(reduce(J,std(ideal(y2,xy,x3-x2)))); size(reduce(ideal(y2,xy,x3-x2),std(J)));
setring t;
print(koszul(1,2)); print(koszul(2,3)); print(koszul(3,3));
ideal KI = xy,y2,x2+y; print(koszul(2,KI)); print(koszul(2,KI)*koszul(3,KI));
ring k1 = 0,(a,b,c,d),dp;
ring k2 = 0,(x,y),dp;
map kf = k1,x,y,x+y,xy;
setring k1; kernel(k2,kf);
ring fw = 0,(x,y,z),dp;
ideal fi = std(ideal(y3+x2,x2y+x2,x3-x2,z4-x2-y));
ring fw2 = 0,(x,y,z),lp;
frwalk(fw,fi);
ring hc = 0,(x,y),ds;
highcorner(std(ideal(x3,x2y,y3))); highcorner(std(ideal(1))); highcorner(std(ideal(x2)));
setring t;
matrix W[3][3] = x,y,z,y,z,x,1,2,x+y; print(wedge(W,1)); print(wedge(W,2)); print(wedge(W,3));
""",
    "sing": """
LIB "sing.lib";
ring r = 0,(x,y),dp;
ideal j = y6,x4; ideal m = x,y;
attrib(m,"isSB",1); attrib(j,"isSB",1);
codim(m,j); codim(j,m);
ring s = 32003,(x,y,z),ds;
dim_slocus(ideal(x5+y6+z6,x2+2y2+3z2)); dim_slocus(ideal(xy));
int p = printlevel; printlevel = 1;
is_ci(ideal(x4+y5+z6,xyz,yx2+xz2+zy7)); is_ci(ideal(xy,yz));
is_is(ideal(x2y,x4+y5+z6,yx2+xz2+zy7)); is_is(ideal(xy+yz));
printlevel = p;
ring t = 32003,(x,y),ds;
ideal i = intersect(ideal(x8,y8),ideal((x+y)^4));
is_reg(xy,i); is_reg(x-1,i);
ring u = 0,(x,y,z),ds;
ideal i5 = xyz+z5,2x2+y3+z7,3z5+y5;
ring q = 32003,(x,y,z),dp;
qhspectrum(x3+y5+z2,intvec(10,6,15)); qhspectrum(xy+z2,intvec(1,1,1)); qhspectrum(x2y+z3,intvec(1,1,1));
setring u;
ideal L5 = locstd(i5); size(reduce(L5,std(i5))); size(reduce(std(i5),L5)); locstd(ideal(x2+y3,xy));
""",
    "algebra": """
LIB "algebra.lib";
int p = printlevel; printlevel = 1;
ring R = 0,(x,y,z),dp;
ideal A = x2+y2,z2,x4+y4,1,x2z-1y2z,xyz,x3y-1xy3;
algebra_containment(z,A);
algebra_containment(x10z3-x8y2z3+2x6y4z3-2x4y6z3+x2y8z3-y10z3+x6z4+3x4y2z4+3x2y4z4+y6z4,A);
list L = algebra_containment(x4-y4,ideal(x2+y2,x2-y2),1);
L[1]; def S = L[2]; setring S; check;
setring R;
inSubring(x4-y4,ideal(x2+y2,x2-y2)); inSubring(x,ideal(x2,y));
list l = algDependent(ideal(x2,y2,xy,z));
l[1]; def T = l[2]; setring T; ker;
setring R;
nonZeroEntry(intvec(0,3,0,5)); nonZeroEntry(list(37,0,x,intvec(0)));
printlevel = p;
ring s = 0,(x,y,z,a,b,c),(lp(3),dp);
finitenessTest(std(ideal(a-(xy)^3+x2-z, b-y2-1, c-z3)),1..3);
finitenessTest(std(ideal(a-(xy)^3+x2-z, b-y2-1, c-z3, xy)),1..3);
ring r3 = 0,(a,b,c),dp;
ring s3 = 0,(x,y,z),dp;
map phi = r3,(xy)^3+x2+z,y2-1,z3;
mapIsFinite(phi,r3,ideal(xy)); mapIsFinite(phi,r3);
""",
    "algebra_maps": """
LIB "algebra.lib";
int p = printlevel; printlevel = 1;
ring r = 0,(a,b,c),ds;
ring s = 0,(x,y,z,u,v,w),dp;
map phi = r,x-w,u2w+1,yz-v;
alg_kernel(phi,r); is_injective(phi,r);
ring S = 0,(a,b,c),ds;
ring R = 0,(x,y,z),dp;
qring Q = std(x-y);
map psi = S,x,y,x2-y3;
alg_kernel(psi,S,"ker",3);
setring S; ker;
setring R;
map chi = R,x,y,x2-y3;
is_surjective(chi); is_bijective(chi,R);
list l = is_injective(chi,R,""); l[1]; def K = l[2]; setring K; ker;
setring R;
qring Q2 = std(z-x2+y3);
is_bijective(ideal(x,y,x2-y3),Q2);
ring T = 0,(a,b,c,d),dp;
map om = R,a,a+b,c-a2+b3,0;
is_bijective(om,R);
printlevel = p;
""",
    "standard": """
LIB "standard.lib";
max(2,3); max(1,4,3); max(intvec(1,2),intvec(0,1),intvec(1,1));
min(2,3); min(1,4,3); min(intvec(1,2),intvec(0,1),intvec(1,1));
ring r = 0,x,dp;
max(x+1,x2+x); min(x+1,x2+x);
ring R = 0,(x,y),wp(1,2);
weightKB(ideal(0),3,intvec(1,2)); weightKB(std(ideal(x2)),5,intvec(1,2));
ring l = 0,(x,y,z),lp;
ideal i = y3+x2,x2y+x2,x3-x2,z4-x2-y;
stdfglm(i,"std"); stdfglm(i,"(a(2,3,4),dp)");
""",
    "elim": """
LIB "elim.lib";
ring R = 0,(x,y,z,u,v),(c,lp);
def P = elimRing(yu); P;
intvec w = 1,1,3,4,5;
elimRing(yu,w); elimRing(xz,w,"b"); elimRing(v,"b");
ring S = 0,(x,y,z),ds;
elimRing(y);
ring T = (0,a),(x,y,z,u,v),ws(1,2,3,4,5);
minpoly = a2+1;
def E = elimRing(yv)[1]; setring E; E;
""",
    "primdec": """
LIB "primdec.lib";
ring r = 0,(x,y,z),dp;
ideal i = (z2+1)*(z3+2)^2,y-z2;
size(minAss(i)); size(minAssE(i)); minAss(ideal(xy)); minAssE(ideal(1)); minAssGTZE(ideal(1)); minAssCharE(ideal(5));
primdecGTZE(ideal(1)); primdecSYE(ideal(xy));
""",
}


@pytest.mark.parametrize("name", sorted(SNIPPETS))
def test_as_singular(name: str) -> None:
    src = SNIPPETS[name]
    assert output_lines(run(src)) == output_lines(run_singular(src))
