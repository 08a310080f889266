"""Core Singular commands added for issue 21 in session 8, checked against Singular."""
from __future__ import annotations

import pytest

from tests.util import error, run, run_singular

QHWEIGHT_SRC = """
ring r=0,(x,y,z),dp;
qhweight(ideal(x2y+y3,z2)); qhweight(ideal(x2+y3+xy)); qhweight(ideal(y2+z3)); qhweight(ideal(xy+z));
qhweight(ideal(x7+y3z2+z4y)); qhweight(ideal(x9+y2z11)); qhweight(ideal(x5+yz7)); qhweight(ideal(x13+y5z7+y2));
qhweight(ideal(xy)); qhweight(ideal(0)); qhweight(x33+x11y12z13);
ring r4=0,(t,x,y,z),dp; qhweight(ideal(x4+y3+z2)); qhweight(ideal(x4+z2)); qhweight(ideal(x4+y3+z2+t5+xy));
ring s=0,(x,y,z),ds; qhweight(ideal(z+xy));
"""


@pytest.mark.singular
def test_qhweight_as_singular() -> None:
    assert run(QHWEIGHT_SRC).split() == run_singular(QHWEIGHT_SRC).split()


def test_qhweight_makes_quasihomogeneous() -> None:
    assert run("ring r=0,(t,x,y,z),dp; qhweight(ideal(x4+y3+z2));").split() == ["0,3,4,6"]


PREIMAGE_LOCAL_SRC = """
ring r=0,(x,y,z),ds;
map m=r,x+y+z+y2+x3,x-y-z,z;
ideal id=2y+2z+x^3+y^2,x-y-z,y2+2z3;
ideal pid=preimage(basering,m,id);
ideal imid=m(pid);
size(reduce(id,std(imid))); size(reduce(imid,std(id)));
ring s = 0,(a,b,c),ds;
ring t = 0,(x,y,z,u,v,w),dp;
map phi = s,x-w,u2w+1,yz-v;
ideal Z;
setring s;
preimage(t,phi,Z);
"""


@pytest.mark.singular
def test_preimage_local_source_as_singular() -> None:
    assert run(PREIMAGE_LOCAL_SRC).split() == run_singular(PREIMAGE_LOCAL_SRC).split()
    std_src = "ring r=0,(x,y,z),ds; map m=r,x+y+z+y2+x3,x-y-z,z; ideal id=2y+2z+x^3+y^2,x-y-z,y2+2z3; " \
              "std(preimage(basering,m,id));"
    assert run(std_src).split() == run_singular(std_src).split()


INDEXED_NAMES_SRC = """
ring R = (0,p_(1..2)),(c(1..2)(1..2),d(1,2),a_(3,2,3)),dp; R;
d(1,2)+c(1)(2); int i=2; d(1,i); a_(3,2,3)^2*p_(2); subst(a_(3,2,3)+d(1,2), a_(3,2,3), p_(1)*d(1,2));
"""


@pytest.mark.singular
def test_names_with_several_indices_as_singular() -> None:
    assert run(INDEXED_NAMES_SRC).split() == run_singular(INDEXED_NAMES_SRC).split()


INDEXED_DECL_SRC = """
ring R; int n=3; ideal j(3); ideal j(n); ideal j(2)=x; j(2..3); int foo(1)=42; foo(1)+1;
poly rp(2..3); rp(3); listvar();
for (n=1; n<4; n=n+1) { poly q(n) = x^n; } q(3); kill q(2); listvar();
"""


@pytest.mark.singular
def test_indexed_declarations_as_singular() -> None:
    def plain(text: str) -> list[str]:  # without the warnings of redefinitions
        return " ".join(line for line in text.splitlines() if not line.startswith("// **")).split()
    assert plain(run(INDEXED_DECL_SRC)) == plain(run_singular(INDEXED_DECL_SRC))


ALIAS_SRC = """
proc probe3(alias int i) { i; listvar(); };
int j = 2; probe3(j); probe3(1+2);
proc adummy4(alias int a, alias int b) { return("works"); };
int a, b; adummy4(a, b);
proc p1(alias list j) { def br = basering; listvar(); ring s = 0, x, ds; list k = fetch(br, j); setring(br); }
ring rr = 0, x, dp; list l = list(ideal(x)); p1(l);
proc p2(alias ideal i) { def br = basering; ring s = 0, x, ds; ideal i = imap(br, i); setring(br); return(i); }
ideal i = x; p2(i);
ring r=32003,(x,y,z),dp; poly f = x; def s=basering; setring s; listvar(); listvar(r);
"""


@pytest.mark.singular
def test_alias_parameters_and_ring_names_as_singular() -> None:
    assert run(ALIAS_SRC).split() == run_singular(ALIAS_SRC).split()


COMPARE_SRC = """
ring rc = (0,c),(x,y),dp;
c/2 > c/3; c2/3 < c; -c < c; 0 < c; 0 > -c; (c+1)/(c-1) > 1; (c+1)/(c-1) >= 1; 2c/(3c+1) > 1/2;
-c/(2c+1) < 0; c >= 2c; 1 < c; x2/3 < x2/2; x2/3 <x;
ring rab = (0,a,b),x,dp; a+b > a2; a > b; b > a; a2b > ab2; a/b > b/a; -a < b;
ring rp = (7,c),x,dp; c > 2c; 3c > 2c; c2 > c; 0 < c; 0 > c; c/3 > c/2;
ring r = 0,x,dp; poly p = -1; p < 0; p > 0; poly q=0; q > p;
ring r7=7,x,dp; poly p=6; p > 0; p > 1; poly z=0; z > p; 6x > x;
"""


@pytest.mark.singular
def test_comparisons_with_parameters_and_constants_as_singular() -> None:
    assert run(COMPARE_SRC).split() == run_singular(COMPARE_SRC).split()


SUBST_PARAM_SRC = """
ring r = (0,a), x, dp; minpoly = a2+1; poly p = x; subst(p,a,x); subst(p,x,a); p = x+a; subst(p,a,x);
subst(p,x,a); subst(minpoly,a,x);
ring r2=(0,a,b),(x,y),dp; poly f = a*b*x + (a2+b)*y + a; subst(f,a,x+1); subst(f,b,y); subst(f,a,b);
ring s=(0,a),x,dp; minpoly=a2+a+1; poly f=(a+1)*x2+a; subst(f,a,x); subst(f,a,2);
ring t=(7,a),x,dp; subst((a2+3)*x+a,a,x2);
"""


@pytest.mark.singular
def test_subst_parameter_as_singular() -> None:
    assert run(SUBST_PARAM_SRC).split() == run_singular(SUBST_PARAM_SRC).split()


def test_radical_algorithm_options_same_result() -> None:
    base = 'LIB "primdec.lib"; ring r=0,(x,y,z),dp; ideal i = x2y, (z-1)^3*x, y3; '
    assert run(base + 'radical(i, "KL");') == run(base + "radical(i);") == run(base + 'radical(i, "SL", 0);')
    assert "unknown option" in str(error(base + 'radical(i, "foo");'))
    assert "not supported" in str(error(base + "radical(i, 1);"))


DIFF_SRC = """
ring r=0,(x,y),dp; print(diff(ideal(x, y2), ideal(x2, xy2))); print(diff(ideal(x+2y2, 3), ideal(x2y2, xy3+1)));
ring r2=2,(x,y),dp; print(diff(ideal(x,y),ideal(x2,y2))); print(diff(ideal(x),ideal(x2+x,x4+x)));
"""


@pytest.mark.singular
def test_diff_by_operators_as_singular() -> None:
    assert run(DIFF_SRC).split() == run_singular(DIFF_SRC).split()


COEFFS_SRC = """
ring r=0,(x,y,z),dp; poly f = x4+2x2+x3y4+y5+z7; matrix T; matrix M = coeffs(f,y,T); T; T*M == f;
ideal I = x3y4+z7+y5+x4+2x2,x2y+y3; matrix TT; matrix NN = coeffs(I,y,TT); TT*NN; print(coeffs(I,y));
matrix m[1][1]=x; m==x; m!=x; x==m; m==2;
"""


@pytest.mark.singular
def test_coeffs_with_powers_as_singular() -> None:
    assert run(COEFFS_SRC).split() == run_singular(COEFFS_SRC).split()


MATRIX_ARGS_SRC = """
LIB "primdec.lib"; ring r = (2,t),(x),dp; matrix m[1][1] = x+t; primdecSY(m);
ring s = 0,(x,y,z),dp; matrix n[1][3] = x2-y, xy-z, y2; print(std(n)); size(minAssGTZ(std(n))); dim(std(minAssGTZ(n)[1]));
"""


@pytest.mark.singular
def test_matrix_arguments_as_singular() -> None:
    assert run(MATRIX_ARGS_SRC).split() == run_singular(MATRIX_ARGS_SRC).split()


INDEXED_ASSIGN_SRC = """
int c; for (c=1; c<=3; c=c+1) { int len(c); len(c) = c*c; } len(2); len(3) = len(3) + 1; len(3); pagewidth;
ring r=0,(x,y,z),dp; maxideal(1); ring s=0,(x,y,z),ds; maxideal(1); maxideal(2);
"""


@pytest.mark.singular
def test_assign_to_indexed_names_as_singular() -> None:
    assert run(INDEXED_ASSIGN_SRC).split() == run_singular(INDEXED_ASSIGN_SRC).split()


IDEAL_PLUS_ROW_SRC = """
ring A=0,(x,y,z),dp; ideal I=zy2-zx3-x6; ideal sing=I+jacob(I); sing; matrix m[1][2]=x,y; ideal s2 = m+I; s2;
"""


@pytest.mark.singular
def test_ideal_plus_one_row_matrix_as_singular() -> None:
    assert run(IDEAL_PLUS_ROW_SRC).split() == run_singular(IDEAL_PLUS_ROW_SRC).split()


REDUCE_BAD_ECART_SRC = ("ring r = 32003,(x,y),ds; ideal j = std(ideal(y2+x10y, x22)); poly p = y2+y3+x2y2;\n"
                        "reduce(p, j, 2); reduce(p, j, 1); reduce(p, j); reduce(p - reduce(p, j, 2), j);\n")


@pytest.mark.singular
def test_reduce_with_bad_ecart_in_local_ordering_matches_singular() -> None:
    assert run(REDUCE_BAD_ECART_SRC).split() == run_singular(REDUCE_BAD_ECART_SRC).split()
