"""Singular builtins added in session 13 for the conformance run: division (global and local orderings,
vectors), a matrix declared from a vector ([rows][cols] filled row by row), matrix * ideal, gcd over a
parameter field in several variables, reduce(f, u, I, d), ring.lib's isSubModule, and the lines imap prints
under option(Imap); attributes: homog marks isHomog (the components' weights), an assignment drops a
variable's attributes, modules of at most one generator are standard bases.  Each snippet's output is compared with the installed Singular's line by line; the
expected values of a few are also checked without Singular."""
from __future__ import annotations

import pytest

from tests.util import output_lines, run, run_singular

SNIPPETS = {
    "division_global_and_local": """
ring A = 0,(x,y),dp; division(x2y+y2, ideal(x2, y)); division(ideal(x3+y, xy2+1), ideal(x2, y2-1));
ring R = 0,(x,y,z),ds; poly f = yx2+yx; ideal I = x-x2,y+x;
list L = division(f, I); L; matrix(I)*L[1]-matrix(f)*L[2]-matrix(L[3]);
ring S = 0,(x,y),ds; poly f = x5+x2y2+y5; division(f, jacob(f));
""",
    "division_of_vectors": """
ring r = 0,(x),ds;
matrix M[2][2] = [1,0,0,0]; matrix NN[2][1] = [1,0]; module N = std(NN);
list l = division(M, N); matrix T = l[1]; matrix R = l[2]; matrix U = l[3];
matrix(M)*U; matrix(N)*T+matrix(R);
""",
    "matrix_from_a_vector_and_times_an_ideal": """
ring r = 0,(x,y),dp;
matrix M[2][2] = [1,2,3,4]; print(M); matrix C[2][3] = [1,2]; print(C);
module m = [1,2],[3,4]; matrix D[3][3] = m; print(D);
matrix A[2][1] = x,y; ideal I = x,y; print(A*I);
""",
    "gcd_over_parameters_in_several_variables": """
ring r = (32003,a,c),(x,y),dp;
poly f = (x+a*y)*(c*x-y2)*(x+1); poly g = (x+a*y)*(x-c)*(c*x-y2)/(a+c);
gcd(f, g); gcd(f*(x-1)/a, g*(y+a));
ring s = (0,a,b),(x,y,z),dp;
gcd((a*x+y/b)^2*(z-a), (a*x+y/b)*(z+x)); gcd(x+y, x-y);
""",
    "reduce_up_to_a_degree": """
ring rs = 0,x,ds; reduce(poly(1), 1+x, ideal(x3), 5); reduce(x2+1, 1-x, ideal(x4), 6);
ring r = 0,(x,y),ds; reduce(x+y, 1+x+y, ideal(x2,y2), 3);
reduce(1+y, 1-x-y2, std(ideal(x2-y3, xy)), 4);
""",
    "isSubModule": """
LIB "primdec.lib";
ring r = 0,x,dp; isSubModule(ideal(x3), ideal(x2)); isSubModule(ideal(x2), ideal(x3));
ring s = 0,(x,y),ds; isSubModule(ideal(x), ideal(x+x2,y));
module m = [x,y],[y,x]; isSubModule([x2-y2,0], m); isSubModule([x2-y2,1], m);
""",
    "imap_under_option_Imap": """
option(Imap);
ring r = (0,a),(x,y,z),dp; poly f = x+a*y+z;
ring s = (0,x),(z,w,a),dp; imap(r, f);
ring t = 0,(y),dp; imap(r, f);
""",
}


def test_division_identity_and_unit():
    out = run("ring R = 0,(x,y,z),ds; poly f = yx2+yx; ideal I = x-x2,y+x; list L = division(f, I);\n"
              "matrix(f)*L[3] - matrix(I)*L[1] - matrix(L[2]); L[3];")
    assert output_lines(out) == ["_[1,1]=0", "_[1,1]=1+y"]


def test_gcd_over_parameters_without_singular():
    out = run("ring r = (0,a),(x,y),dp; gcd((x+a*y)*(x-y)^2, (x+a*y)*(x-y)*(x+y));")
    assert output_lines(out) == ["x2+(a-1)*xy+(-a)*y2"]


ATTRIBUTE_SNIPPETS = {
    "homog_marks_isHomog": """
ring r = 0,(x,y),dp; module M = [x,y3],[0,y]; homog(M); attrib(M, "isHomog");
module N = [0,x2,y],[x,0,0]; homog(N); attrib(N, "isHomog");
module K = [x,y2]; homog(K); attrib(K);
ideal I = x2,y2; homog(I); attrib(I); attrib(I, "isHomog"); poly f = x2; homog(f); attrib(f);
ring B = 0,(x,y,z),wp(1,2,3); module M = [y3-z2,x3-z],[x3,1]; homog(M); attrib(M, "isHomog");
intvec v = 4,7; attrib(M, "isHomog", v); attrib(M, "isHomog");
""",
    "assignment_drops_attributes": """
ring r = 0,(x,y),dp; ideal i = x; attrib(i, "huhu", 1); attrib(i); i = x,y; attrib(i);
attrib(i, "huhu", 1); i[2] = x+1; attrib(i);
ideal j = x2,y; attrib(j, "huhu", 2); attrib(j, "isSB", 1); attrib(j); killattrib(j, "isSB"); attrib(j);
module Z; attrib(Z); module L = [x,y],[y,x]; attrib(L); attrib(std(L), "isSB");
""",
}


RELATIVE_SNIPPETS = {
    "liftstd_relative_to_a_module": """
LIB "matrix.lib";
ring R = 0,(x,y,z),(c,dp);
matrix A[1][1] = x; matrix B[1][2] = x+y-z,x-y-z;
matrix C[nrows(A)][ncols(A) + ncols(B)] = concat(A,B);
matrix G1 = std(C); matrix T;
module G2 = liftstd(module(A), T, "std", module(B));
print(reduce(G1,G2)); print(reduce(A*T-matrix(G2),std(B)));
ring S = 0,(x,y,z),lp; matrix M[2][3] = x,x,y,y,z,z; module A1 = module(M); module A2 = A1[3]; A1 = A1[1..2];
matrix T; module U; module G = liftstd(A1, T, U, A2);
print(reduce(matrix(G) - matrix(A1)*T, std(A2))); print(reduce(matrix(A1)*matrix(U), std(A2)));
size(reduce(std(A2+A1), std(G))); size(reduce(modulo(A1, A2), std(U))); size(reduce(U, std(modulo(A1, A2))));
""",
    "division_up_to_a_degree_identity": """
ring S = 0,(x,y),ds; poly f = x5+x2y2+y5; list D = division(ideal(f^2), jacob(f), 10);
print(jet(matrix(ideal(f^2)) - matrix(jacob(f))*D[1] - matrix(D[2]), 10));
""",
}


ALL_SNIPPETS = {**SNIPPETS, **ATTRIBUTE_SNIPPETS, **RELATIVE_SNIPPETS}


@pytest.mark.singular
@pytest.mark.parametrize("name", sorted(ALL_SNIPPETS))
def test_as_singular(name: str) -> None:
    src = ALL_SNIPPETS[name]
    assert output_lines(run(src)) == output_lines(run_singular(src))


LISTVAR = """
ring r1 = 32003,(x,y,z),dp; poly s2 = 12x2+3y2; int i = 34;
ring r2 = 0,(x,y,z),ds; poly s1 = x4+y2; ideal i1 = x2,y2,z2;
listvar(r2); listvar(ring); listvar(poly); listvar(i1); listvar(int); listvar(all);
"""


@pytest.mark.singular
def test_listvar_of_a_type_as_singular() -> None:
    assert output_lines(run(LISTVAR)) == output_lines(run_singular(LISTVAR))


WEIGHTED_HILB = """
ring r4 = 32003,(x(1..6)),ds;
ideal i0 = x(1)+x(2)+x(3)+x(4), x(1)^2*x(2)^2+x(2)*x(3)*x(5)*x(6), x(1)*x(2)^2*x(3)+x(2)*x(3)*x(6)^2;
option(returnSB); module m = syz(i0);
hilb(m); hilb(m, 1);
ring r = 0,(x,y,z),dp; module s = syz(ideal(x, y2, z3)); hilb(std(s)); hilb(s, 1); hilb(syz(ideal(x+1, y)), 1);
"""


@pytest.mark.singular
def test_hilb_of_syzygies_with_their_weights_as_singular() -> None:
    assert output_lines(run(WEIGHTED_HILB)) == output_lines(run_singular(WEIGHTED_HILB))


OUTPUT_ARGUMENTS = """
ring r = 0, (x1), (dp(1), c);
module a1 = 2*x1*(gen(6)), gen(6)*(2-8*(x1)), gen(1)*(x1-2*(x1^2))+gen(6)*(-2+8*(x1));
module a2 = gen(6), gen(1)*(-(x1)+2*(x1^2));
matrix T; module result = lift(a1, a2, T, "slimgb"); print(T); print(matrix(a1)*matrix(result) - matrix(a2));
ring R = 0,(x,y,z),lp;
matrix A[2][3] = x,x,y,y,z,z; module A1 = module(A); module A2 = A1[3]; A1 = A1[1..2];
matrix T; module S = modulo(A1,A2,T,"std"); print(S);
matrix T1; module S2; matrix G = liftstd(A1,T1,S2,"std",A2); print(T-T1); reduce(G-A1*T,A2);
module m = [x,y],[y,x]; matrix U[2][1] = 1,x; print(m*U);
"""


@pytest.mark.singular
def test_output_arguments_of_lift_and_modulo_as_singular() -> None:
    assert output_lines(run(OUTPUT_ARGUMENTS)) == output_lines(run_singular(OUTPUT_ARGUMENTS))
