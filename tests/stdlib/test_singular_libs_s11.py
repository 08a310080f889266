"""Commands of Singular's libraries added in session 11: elim.lib's select/select1/nselect of modules,
elim, elim1, elim2 (ideals, modules, matrices) and eliminate of modules; polylib.lib's content; matrix.lib's
compress; weighted jets and jet(f, u, d); inout.lib's lprint of modules; sing.lib's is_regs, is_active and
is_reg of modules; print and show of a zero vector; modules over qrings; normalize, number of a non-constant polynomial, concat of
modules/vectors/ideals, qslimgb; general.lib's sort of modules and lists, primdec.lib's Ann;
coef and coeffs of vectors; matrix.lib's linear_relations (no generator with a constant entry:
Singular's procedure goes wrong there), pmat of modules;
standard.lib's par2varRing; an int n as an ordering block's size in ring lists;
koszul(d, ...) with d out of range; chinrem with bigint moduli; mult and degree of modules, multiplicity; standard.lib's quot; highcorner of modules.  Each snippet's output is compared with the installed
Singular's line by line."""
from __future__ import annotations

import pytest

from tests.util import output_lines, run, run_singular

pytestmark = pytest.mark.singular

SNIPPETS = {
    "coeffs_in_a_basis": """
ring r = 32003,(x,y,z),dp;
module M = [y3+x2z, xy], [-xy, y2+x2z];
module K = [x2, xy], [y3, xy], [xy, x];
print(coeffs(M, K, xy));
module M2 = [x2z+y, 3xz], [y, x];
module K2 = [x,0],[0,x],[y,0],[0,y],[1,0],[0,1];
print(coeffs(M2, K2, xy)); print(coeffs(M2, K2, x));
""",
    "select_modules": """
LIB "elim.lib";
ring r = 0,(x,y,t,s,z),dp;
module m = [x-y,x-y],[-z2+y,-z2+y],[-t3+z,-t3+z],[y3-x+s,y3-x+s],0;
nselect(m, 3..4); select(m, 1..2); select1(m, 3..4); select(m, 3); select(m, 5);
""",
    "elim": """
LIB "elim.lib";
ring r = 0,(x,y,u,v,w),dp;
ideal i = x-u, y-u2, w-u3, v-x+y3;
elim(i, 3..4); elim(i, uv); elim1(i, uv); elim2(i, 3..4);
int p = printlevel; printlevel = 1;
elim(i, uv, "withWeights", "slimgb");
printlevel = p;
module m = i*gen(1)+i*gen(2);
show(elim(m, 3..4)); show(elim1(m, uv)); show(elim2(m, 3..4));
eliminate(m, uv);
matrix M = m;
print(elim(M, uv));
ring s = 0,(x,y,t),ds;
ideal j = x-t, y-t2;
elim1(j, t); elim2(j, 3);
""",
    "content_compress_jet": """
LIB "polylib.lib"; LIB "matrix.lib";
ring r = 0,(x,y,z),(c,lp);
content(3x2+18xy-27xyz); content(-3x2+6y); content(1/2x+1/3y); content(0);
vector v = [-3x2+6y,9y]; content(v);
ring r2 = (0,a),(x,y),dp; content(2a*x+4a2*y);
ring r3 = 7,(x,y),dp; content(3x+2y);
ring r4 = 0,(x,y,z),ds;
matrix A[3][4] = 1,0,3,0,x,0,z,0,x2,0,z2,0;
print(compress(A)); module m = module(A); show(m); show(compress(m));
compress(ideal(0,x,0,y));
intmat B[3][4] = 1,0,3,0,4,0,5,0,6,0,7,0; compress(B);
intvec C = 0,0,1,2,0,3; compress(C);
vector w = 0; print(w);
ring r5 = 32003,(x,y,z),(c,dp);
poly f = 1+x+x2+xz+y2+x3+y3+x2y2+z4;
jet(f, 3, intvec(2,1,1)); jet(ideal(f, x2+y), 2, intvec(1,2,3));
ring r6 = 0,x,ds;
jet(1, 1+x, 5); jet(x, 1+x, 3); jet(1, 2-x, 3);
""",
    "lprint_module": """
LIB "inout.lib";
ring r = 0,(x,y,z),ds;
poly f = (x+y)*(x-y)*(x+z)*(y+z)^2;
module m = [f*(x-y)],[0,f*(x-y)];
string s = lprint(m); s;
lprint(m, 30);
""",
    "regular": """
LIB "sing.lib";
int p = printlevel; printlevel = 1;
ring r1 = 32003,(x,y,z),ds;
ideal i = x8,y8,(x+y)^4;
is_regs(i);
module m = [x,0,y];
i = x8,(x+z)^4;
is_regs(i,m);
printlevel = p;
is_regs(ideal(x,y));
is_active(x, ideal(yx3+y,yz3+y3z));
is_active(y, ideal(y2));
is_active(x, module([x,y],[y,z]));
is_reg(x, module([y,0],[0,y]));
is_reg(y, module([y,0],[0,x*y]));
ring r2 = 0,(x,y),dp;
is_reg(x, module([x,y]));
is_reg(y, module([y,0],[0,x*y]));
is_regs(ideal(x, x+y, y));
LIB "polylib.lib";
is_zero(ideal(1)); is_zero(ideal(x),1); is_zero(module([1,0],[0,1])); is_zero(module([1,0],[0,x]),"a");
qring q = std(ideal(x2+y3)); is_zero(ideal(x2+y3-37));
""",
    "qring_modules": """
ring R = 0,(x,y,z),(c,dp);
qring S = std(ideal(x2-y, yz));
module M = [x2,xy+z],[y,z2],[xz,x3];
option(redSB);  // Singular's std over a qring leaves tails unreduced otherwise (the same module)
std(M); syz(M); dim(std(M));
module N = [x,y],[y2,0];
quotient(module([0]), N); quotient(M, N); std(quotient(M, x));
reduce([x3,y2z], std(M));
modulo(M, N); modulo(ideal(x, y), ideal(z2));
ring L = 32003,(x,y,z),ds;
qring Q = std(x4y5);
module m = [yx3+x,yx3+y3x];
std(m); dim(std(m)); dim(std(m+x*freemodule(2)));
""",
    "normalize_number_qslimgb_concat": """
LIB "polylib.lib"; LIB "matrix.lib";
ring r = 0,(x,y,z),ls;
normalize(2x5+3y2+4z3); normalize(ideal(3x+1, 0, 2y));
module m = [9xy,0,3z3],[4z,6y,2x];
normalize(m);
ring s = 0,(x,y,z),(c,ls);
module m = [9xy,0,3z3],[4z,6y,2x];
normalize(m); normalize([0,2x,4]);
number(3x); number(3x+2); number(poly(5));
print(concat(freemodule(2), ideal(x,y))); print(concat(m, [x,y]));
ring R = (0,v),(x,y,z,u),dp;
qring Q = std(x2-y3);
module M = [x+y2,1,0], [1,1,x2+y2+xyz];
print(qslimgb(M));
ideal j = qslimgb(ideal(x+y2, u*v-1)); j;
""",
    "sort_ann": """
LIB "general.lib"; LIB "primdec.lib";
sort(list(3,1,2)); sort(intvec(5,-1,3)); intvec v = 1,2; sort(list(v,-v,intvec(0,3)));
ring r = 0,(x,y),(c,dp);
module M = [x,y],[y],[0,x2],0;
sort(M); sort(M,"dp,C"); sort(M,"c,dp",1); sort(M, intvec(3,1));
ideal i = x3,0,y2,xy;
sort(i); sort(i,"lp"); sort(i,"ls",1);
ring s = 0,(x,y,z),lp;
Ann(module(x2-y2,z3)); Ann(module([1,x2],[y,x]));
qring Q = std(xy-1);
Ann(module([1,x2],[y,x]));
""",
    "coef_coeffs_vectors": """
ring r = 32003,(x,y,z),dp;
poly f = x20+xyz+xy+x2y+z3;
vector v = [f, zy+77+xy];
matrix mc; matrix mm;
coef(v, y, mc, mm); print(mc); print(mm);
coef([x2, 0, y3+x], xy, mc, mm); print(mc); print(mm);
print(coeffs([(x+y)^3, xyz+z10y4], y)); print(coeffs([x, 0, 1], z));
""",
    "linear_relations": """
LIB "matrix.lib"; LIB "inout.lib";
ring r = (3,w), (a,b,c,d),dp;
minpoly = w2-w-1;
module M = [a2,b2],[wab,w2c2+2b2],[(w-2)*a2+wab,wb2+w2c2];
module REL = linear_relations(M);
pmat(REL); pmat(matrix(M)*REL);
ring s = 0,(x,y),dp;
print(linear_relations(module([x,y],[2x,2y],[y,x])));
linear_relations(module([x,y],[y,x]));
print(linear_relations(module([x2,y],[y,x],[x2+y,x+y])));
""",
    "par2varRing": """
ring R = (0,a),(x,y),dp;
def P = par2varRing(ideal(a*x+1, y-a2))[1]; setring P; Id[1]; P;
ring S = (7,a,b),(x,y),(c,lp);
def Q = par2varRing(ideal(a*x+b2*y+1), module([a,b]))[1]; setring Q; Id; Q;
ring R2 = (0,w),(y,z),lp; minpoly = w2+1;
module m = w3*[1,1], (wyz-1)*[1,0];
def Q2 = par2varRing(m)[1]; setring Q2; print(Id[1]);
ring T = 0,x,dp;
def U = par2varRing(ideal(x))[1]; setring U; Id;
""",
    "ring_list_int_blocks": """
LIB "ring.lib";
ring r = 0,(x,y,u,v),(dp(2),ds);
def R = changeord(list(list("wp",intvec(2,3)),list("dp",1:2))); R;
def R2 = changeord(list(list("lp",nvars(r)))); R2;
def S = ring(list(0, list("x","y","u","v"), list(list("lp",2),list("dp",2)), ideal(0))); S;
def S2 = ring(list(0, list("x","y","u","v"), list(list("wp",2),list("ds",2)), ideal(0))); S2;
""",
    "koszul_chinrem": """
ring r = 0,(x,y,z),dp;
koszul(0,3); koszul(0,maxideal(1)); koszul(4,3); print(koszul(2,3));
ideal i1 = 5x+2y,x2+3y2+xy;
ideal i2 = 2x-3y,2x2+4y2+5xy;
chinrem(list(i1,i2),list(bigint(7),bigint(11)));
chinrem(list(2,-3),list(bigint(7),11)); chinrem(intvec(2,-3),intvec(7,11));
""",
    "mult_modules": """
ring r1 = 32003,(x,y,z),(c,ds);
ideal i = 3x2+yz,7y6+2x2y+5xz;
multiplicity(i); mult(std(i));
module m = [x2,y2],[xy,xz],[x4,z8];
multiplicity(m); mult(std(m)); dim(std(m));
module m2 = [x2,0],[0,y3],[x,y]; mult(std(m2)); dim(std(m2));
ring s = 0,(x,y),dp;
module m3 = [x2,0],[0,y3]; mult(std(m3));
module m4 = [x2,0],[0,y]; mult(std(m4));
qring q = std(x3); mult(std(module([y,0])));
ring r2 = 32003,(x,y,z,w),dp;
module m0 = [x2y+yz2,0],[yzw+w3,0],[xyzw-1,0],[0,x3+yzw],[0,y3+xzw],[0,w2+z2];
module m5 = std(m0);
dim(m5); mult(m5); degree(m5); hilb(m5);
ring r3 = 32003,x,ds;
module m6 = std(module(gen(1), gen(5), x2*gen(2), x3*gen(3), x*gen(4)));
mult(m6); degree(m6); vdim(m6);
""",
    "quot": """
ring r = 0,(x,y),dp;
quot(ideal(x2, xy), ideal(x), 2); quot(module([x,y],[y,x2]), module([x2,0],[0,y]));
quot(module([x,y],[y,x2]), ideal(x)); quot(ideal(x2,xy), module([x]));
""",
    "highcorner_modules": """
ring r=32003,(x,y),ds;
ideal i=x2,xy,y3;
highcorner(std(i));
module m=i*gen(1),i*gen(2);
highcorner(std(m));
m=m,[0,y2];
highcorner(std(m));
module m2=maxideal(2)*gen(1), maxideal(3)*gen(2);
highcorner(std(m2));
module m3=maxideal(3)*gen(1), maxideal(2)*gen(2);
highcorner(std(m3));
module m4=maxideal(3)*gen(1),[0,x];
highcorner(std(m4));
ring s=32003,(x,y),(c,ds);
module m3=maxideal(3)*gen(1), maxideal(2)*gen(2);
highcorner(std(m3));module m5=maxideal(2)*gen(1), maxideal(3)*gen(2);
highcorner(std(m5));ring s2=32003,(x,y),(c,ds);
ideal i=x2,xy,y3;
module m=i*gen(1),i*gen(2);
highcorner(std(m));
ring t=32003,(x,y),(C,ds);
ideal i=x2,xy,y3;
module m=i*gen(1),i*gen(2);
highcorner(std(m));
""",
}


@pytest.mark.parametrize("name", sorted(SNIPPETS))
def test_as_singular(name: str) -> None:
    src = SNIPPETS[name]
    assert output_lines(run(src)) == output_lines(run_singular(src))
