"""Further commands of Singular's libraries and built-ins (session 9): primdec.lib's zerodec,
zero_decomp, newZero_decomp, newMaxIndependSetDp/Lp; sqrfree, facstd, mstd, janet, fglmquot; tjurina of a
complete intersection; matrix.lib's gauss_col/gauss_row; ring.lib's preimageLoc; algebra.lib's
noetherNormal and module_containment; elim.lib's blowup0; hilb(I, 1, w); minor(M, k, I, n); milnor's and
nf_icis's comments; indepSet's order; ringlist, ring(list), ring_list, create_ring, quotientList, changechar,
changeord, extendring, optionIsSet, show; factmodd; general.lib's sort; orderings as strings (ring.lib's defring, create_ring: read as ring(L) reads them, not
merged as a ring declaration's); the widths of a ring's weights and its minimal polynomial in long form.  Each snippet's output is compared with the installed Singular's,
line by line; where Singular's answer is random or not unique, the snippet prints what is determined."""
from __future__ import annotations

import pytest

from tests.util import output_lines, run, run_singular

pytestmark = pytest.mark.singular

SNIPPETS = {
    "ring_list_coefficients": """
ring r = 0,(x,y),dp;
list L = ring_list(r);
typeof(L[1]);
L[1];
ring s = 7,(x),dp;
ring_list(s)[1];
typeof(ring_list(s)[1]);
ring t = (0,a),(x),dp;
ring_list(t)[1];
typeof(ring_list(t)[1]);
ring u = (7,a),(x),dp;
minpoly = a2+1;
ring_list(u)[1];
typeof(ring_list(u)[1]);
ringlist(r)[1];
""",
    "ordering_strings": """
ring r = 0,(x,y,z),(dp(1),lp(2)); r;
ring r2 = 0,(x,y,z),(wp(1,1),lp(1)); r2;
ring r3 = 0,(x,y,z),(a(1,2,3,4),dp); r3;
LIB "ring.lib";
def s1 = defring("0", 3, "x", "(dp(1),lp(2))"); s1;
def s2 = defring("0", 3, "x", "(wp(1,1),lp(1))"); s2;
def s3 = defring("0", 3, "x", "(a(1,2,3,4),dp)"); s3;
def s4 = defring("(7,a)", 4, "u", "(ds(2),M(1,2,0,1))"); s4;
ring s = 0,(x,y,z),dp;
ring_list(create_ring(0, "(x,y,z)", "(wp(1,1),lp(1))"))[3];
""",
    "primdec_zero": """
LIB "primdec.lib";
ring r = 0,(x,y),lp;
ideal i = std(ideal(x2-1, y3-y));
list z = zerodec(i); size(z);
list d = zero_decomp(i, ideal(0), 0); size(d);
int k; for (k = 1; k <= size(d); k++) { vdim(std(d[k])); }
d = newZero_decomp(i, ideal(0), 1); size(d);
zero_decomp(std(ideal(x)), ideal(0), 0);
ring s = 0,(a,b,c,d,e),dp;
ideal j = std(ideal(ab, cd, ae));
newMaxIndependSetDp(j); newMaxIndependSetDp(j, 0); newMaxIndependSetLp(j);
indepSet(j, 0); indepSet(j, 1); indepSet(std(ideal(abc, de)), 1);
""",
    "sqrfree": """
ring r = 0,(x,y,z),dp;
poly f = 4*(x-y)^3*(x+z)^3*(y-z)^2*(x2+1);
sqrfree(f, 1); sqrfree(f, 3);
ring s = 7,(x,y),dp;
sqrfree((x-y)^7*(x+1)^2, 1);
""",
    "bases": """
ring r = 32003,(x,y,z),(c,dp);
ideal I = xyz, x2z;
list L = facstd(I); size(L); facstd(I, x);
size(facstd(ideal(x2-1, xy-y))); facstd(ideal(x2-1, xy-y), x+1);
ring t = 0,(x,y,z,w),dp;
poly f = x3+y4+z6+xyz;
ideal j = jacob(f), f;
j = homog(j, w);
mstd(j)[2];
ring c3 = 0,(x,y,z),dp;
janet(ideal(x*y*z-1, x+y+z, x*y+x*z+y*z));
janet(ideal(x2+yz, y3-z, xz));
ring l = 0,(x,y,z),lp;
option(redSB);
ideal i = std(ideal(y3+x2, x2y+x2, x3-x2, z4-x2-y));
fglmquot(i, reduce(x+yz2+z10, i)); fglmquot(i, 1); fglmquot(i, 0);
""",
    "tjurina": """
LIB "sing.lib";
ring r = 32003,(x,y,z),(c,ds);
tjurina(ideal(x2+y2+z2, x2+2y2+3z2));
ring s = 0,(x,y,z),ds;
tjurina(ideal(xy, x2+y3+z2)); tjurina(ideal(x2+y3+z5, y2-x*z)); tjurina(ideal(xy, xz));
ring g = 0,(c1,s1,c2,s2),dp; tjurina(ideal(s1+s2, c1^2+s1^2-1, c2^2+s2^2-1)); tjurina(ideal(c1*s1-1, c2));
ring s = 0,(x,y,z),ds;
int p = printlevel; printlevel = 1;
milnor(ideal(xy, xz)); milnor(ideal(x5+y6+z6, x2+2y2+3z2, xyz+yx));
proc m(ideal i) { return(milnor(i)); }
m(ideal(x2+y2+z3, xy+z2));
nf_icis(ideal(x3+y4, xy, yz));
printlevel = p;
size(nf_icis(ideal(x3+y4, z4+yx)));
""",
    "gauss": """
LIB "matrix.lib";
ring r = (0,a,b),(A,B,C),dp;
matrix m[3][4] = 0,2,a,A, b,1,0,B, 2b,4,2a,C;
print(gauss_row(m)); print(gauss_col(m));
ring S = 0,x,(c,dp);
matrix M[3][4] = 1,2,3,4,2,4,6,8,1,0,1,x;
list L = gauss_col(M, 1); print(L[1]); print(L[2]);
L = gauss_row(M, 1); print(L[1]); print(L[2]);
""",
    "maps": """
LIB "ring.lib"; LIB "algebra.lib";
ring S = 0,(x,y,z),dp;
ring R0 = 0,(x,y,z),ds;
qring R = std(ideal(x+x2, yz));
map psi = S,x,y,z;
ideal nu = z;
setring S;
preimageLoc("R","psi","nu");
noetherNormal(ideal(xy, xz))[2];
noetherNormal(ideal(x2-y3, z2-x))[2];
noetherNormal(ideal(0)); noetherNormal(ideal(x-1, y, z));
ring P = 0,(x,y,z),dp;
int p = printlevel; printlevel = 1;
module_containment(x2+y2, ideal(x2+y2, z2, x4+y4), ideal(1, xyz));
list l = module_containment(x, ideal(x2+y2, z2, x4+y4), ideal(1, xyz), 1);
l[1]; def T = l[2]; setring T; check;
printlevel = p;
""",
    "blowup": """
LIB "elim.lib";
option(redSB);
ring r = 0,(x,y),dp;
def B = blowup0(x2+y3, ideal(x, y));
setring B;
B; std(bR); std(aS); std(tT); std(sT); std(eD); bM; C; J; W;
ring q = 0,(x,y,z),dp;
def B2 = blowup0(x2-yz, ideal(x2, y), ideal(z-y));
setring B2;
B2; std(bR); std(aS); std(sT); std(eD);
""",
    "overloads": """
ring R = 32003,(x,y,z),dp;
ideal s = std(ideal(x2, y2, z2));
hilb(s, 1, intvec(2,2,2)); hilb(s, 1, intvec(1,2,3)); hilb(std(ideal(xy, z3)), 1, intvec(3,1,2));
ring r = 0,(a,b,c,d,e,f,g,h,s,t,u,v),ds;
matrix m[3][4] = a,b,c,d,e,f,g,h,s,t,u,v;
ideal i = std(ideal(a, c));
minor(m, 2, i, 4); minor(m, 2, i, -4, "Laplace"); minor(m, 3, i, 2);
""",
    "ringlists": """
LIB "ring.lib";
ring r = (0,a),(x,y),(dp,C); minpoly = a2+1;
ringlist(r);
ring s = (7,a,b),(x,y,z),(c,wp(1,2),ls(1));
ringlist(s);
ring t = 32003,(x,y,z),(a(1,2),M(1,0,0,0,1,0,0,0,1));
qring q = std(x2);
list l = ringlist(q); l;
def u = ring(l); setring u; u;
ring v = 0,(x(1..3)),dp;
list m = ringlist(v);
m[1] = list(0,list("a"),list(list("lp",1)),ideal(0));
m[2][size(m[2])+1] = "y";
m[3][3] = m[3][2]; m[3][1] = list("dp",intvec(1,1)); m[3][2] = list("wp",intvec(3,4));
def ra = ring(m); ra; setring ra;
list lra = ringlist(ra); lra[1][4] = ideal(a2+1);
def Ra = ring(lra); setring Ra; Ra;
ring w = (0,a),x,lp; minpoly = a2+1;
qring Q = ideal(x3-2);
list LQ = ring_list(Q); LQ;
ring S = create_ring(LQ[1], "(x,y,t)", "dp", "no_minpoly"); S;
ring S2 = create_ring(0, "(x,y)", "(lp(1),dp(1))"); S2;
ring P = 0,(y,z,u,v),lp;
qring Q2 = std(ideal(y+u2+uv3, z+uv3));
list L2 = ringlist(Q2); L2[3][1][1] = "dp";
option(redSB);
quotientList(L2)[4];
ring rr = 2,A,dp;
ring r4 = 0,(x,y,u,v),(dp(2),ds);
def R5 = changechar(ringlist(rr)); R5;
def R6 = changechar(32003, r4); R6;
def R7 = changeord(list(list("wp",intvec(2,3)),list("dp",1:2))); R7;
ring n = 0,(xxx,y,zz),(wp(3,4,5)); n;
""",
    "factmodd": """
ring s = 7,(x,y),dp; poly h = (y2+3+x*y)*(y+x2)+x3*y+2x4; poly f0 = y2+3; poly g0 = y;
factmodd(h, 5, f0, g0);
ring s2 = 0,(x,y),dp; poly h = (y2+3+x*y)*(y+x2)+x3*y+2x4; poly f0 = y2+3; poly g0 = y;
factmodd(h, 5, f0, g0); factmodd(h, 5, g0, f0);
ring s3 = 0,(y,x),dp; poly h = (y2+3+x*y)*(y+x2)+x3*y+2x4; poly f0 = y2+3; poly g0 = y;
factmodd(h, 5, f0, g0, 2, 1);
""",
    "sort": """
LIB "general.lib";
ring r0 = 0,(x,y,z,t),lp;
ideal i = x3,z3,xyz;
sort(i); sort(i,3..1); sort(i,"ls")[1];
intvec v = 1,10..5,2..4;
sort(v); sort(i,"Dp",1); sort(ideal(x,0,y,x)); sort(list(3,1,2)); sort(ideal(x,x));
""",
    "show_extendring": """
LIB "ring.lib";
ring r = (0,a),(x,y),(dp,C); minpoly = a2+1;
ideal i = x2,a*y; poly f = x+y; int k = 3; intvec v = 1,2; string s = "hi"; number n = a;
matrix m[2][2] = 1,x,y,2; list L = 1,i;
show(r); show(i); show(f); show(k); show(v); show(s); show(n); show(m); show(L);
ring t = 7,(x,y,z),(c,lp); qring q = std(x2); show(q);
setring r;
def R1 = extendring(3, "u", "dp"); show(R1);
def R2 = extendring(2, "T(", "c,ls", 1); show(R2);
intvec w = 2,1,2,1;
def R3 = extendring(5, "A", "ws,dp", w, 0, t); show(R3);
def R4 = extendring(3, "b", "dp(1)", 0, t); show(R4);
optionIsSet("redSB"); option("redSB"); optionIsSet("redSB"); option(noredSB); optionIsSet("redSB");
""",
}


@pytest.mark.parametrize("name", sorted(SNIPPETS))
def test_as_singular(name: str) -> None:
    src = SNIPPETS[name]
    assert output_lines(run(src)) == output_lines(run_singular(src))
