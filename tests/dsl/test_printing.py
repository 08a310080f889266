"""Printing in Singular 4.3.1's format (expected strings taken from real Singular runs)."""
import pytest
from tests.util import run

from mech.dsl.printing import poly_str


@pytest.mark.parametrize("ring, expr, out", [
    ("0,(x,y,z),dp", "3x2y+1/2y-7", "3x2y+1/2y-7"),
    ("0,(x,y,z),dp", "-x2+x-1", "-x2+x-1"),
    ("0,(x,y,z),dp", "1/2*x", "1/2x"),
    ("0,(x,y,z),dp", "-1/2*z + x10", "x10-1/2z"),
    ("0,(x,y,z),dp", "(x+y)^2", "x2+2xy+y2"),
    ("0,(x,y,z),lp", "z2+y+x", "x+y+z2"),
    ("0,(x,y,z),dp", "z2+y+x", "z2+x+y"),
    ("0,(xa,yb),dp", "3*xa^2*yb - 1/2", "3*xa^2*yb-1/2"),
    ("0,(x,yy),dp", "x2 + x*yy^3", "x*yy^3+x^2"),
    ("0,(x(1..3)),dp", "3*x(1)^2*x(2) - x(3)", "3*x(1)^2*x(2)-x(3)"),
    ("32003,(x,y),dp", "x - 16004*y + 5", "x+15999y+5"),
    ("32003,(a,b),lp", "2a-16002b+3", "2a+16001b+3"),
    ("7,(x,y),dp", "3/2*x", "-2x"),
    ("0,(x,y),ds", "x + x2 + 1", "1+x+x2"),
    ("0,(x,y),dp", "0", "0"),
])
def test_polys(ring, expr, out):
    assert run(f"ring r = {ring}; {expr};") == out + "\n"


def test_numbers():
    assert run("ring r = 0,x,dp; number n = 7/2; n; -n; 2/4; number m = 12345678901234567890; m;") == \
        "7/2\n-7/2\n1/2\n12345678901234567890\n"
    assert run("ring r = 32003,x,dp; number n = 16002; n; number m = 16001; m; 1/2;") == "-16001\n16001\n-16001\n"


def test_ideals_named_and_unnamed():
    src = "ring r = 0,(x,y,z),dp; ideal I = x2-y, xy-z; I; std(I); ideal E; E; ideal(0, x, 0);"
    assert run(src) == ("I[1]=x2-y\nI[2]=xy-z\n_[1]=y2-xz\n_[2]=xy-z\n_[3]=x2-y\nE[1]=0\n"
                        "_[1]=0\n_[2]=x\n_[3]=0\n")


def test_lists():
    src = 'ring r = 0,(x,y),dp; list L = "abc", 1, list("abc", list()), x, ideal(x,y), intvec(1,2,3); L; list E; E;'
    assert run(src) == ("[1]:\n   abc\n[2]:\n   1\n[3]:\n   [1]:\n      abc\n   [2]:\n      empty list\n"
                        "[4]:\n   x\n[5]:\n   _[1]=x\n   _[2]=y\n[6]:\n   1,2,3\nempty list\n")
    assert run("list L = 1; L[3] = 2; L;") == "[1]:\n   1\n[3]:\n   2\n"


def test_intvec_and_print_forms():
    assert run("intvec v = 1,-2,30; v; print(v);") == "1,-2,30\n1,\n-2,\n30 \n"
    assert run("ring r = 0,(x,y,z),dp; matrix M[2][2] = 1,-x,1/2*y+z,0; print(M); M;") == \
        "1,     -x,\n1/2y+z,0  \nM[1,1]=1\nM[1,2]=-x\nM[2,1]=1/2y+z\nM[2,2]=0\n"
    assert run("ring r = 0,(x,y),dp; matrix N[2][3]; print(N);") == "0,0,0,\n0,0,0 \n"
    assert run("ring r = 0,(x,y),dp; print(ideal(x2, y-1)); print(x+1); print(3);") == "x2,\ny-1\nx+1\n3\n"


def test_print_matrix_columns():
    src = ("ring r = 0,(c1,s1,c2,s2,l1,l2),dp; matrix D[2][4] = l1,0,l2,0,2*c1,2*s1,0,2*s2; print(D);")
    assert run(src) == "l1,  0,   l2,0,  \n2*c1,2*s1,0, 2*s2\n"


def test_side_by_side():
    assert run('1,2; "a", 1;') == "1 2\na 1\n"
    assert run("ring r = 0,(x,y),dp; ideal I = x,y; I, x; list L = 1; L, 3;") == \
        "I[1]=x\nI[2]=y x\n[1]:\n   1\n3\n"


def test_ring_printing():
    src = "ring r = 0, (x(1..5), y), (dp(4),dp(2)); r;"
    assert run(src) == ("// coefficients: QQ\n// number of vars : 6\n//        block   1 : ordering dp\n"
                        "//                  : names    x(1) x(2) x(3) x(4)\n//        block   2 : ordering dp\n"
                        "//                  : names    x(5) y\n//        block   3 : ordering C\n")
    src = "ring r = 7,(x,y),ws(2,3); r;"
    assert run(src) == ("// coefficients: ZZ/7\n// number of vars : 2\n//        block   1 : ordering ws\n"
                        "//                  : names    x y\n//                  : weights  2 3\n"
                        "//        block   2 : ordering C\n")


def test_maps_and_procs():
    assert run("ring r = 0,(x,y,z),dp; map phi = r, y, x; phi; phi(x2+z);") == "phi[1]=y\nphi[2]=x\ny2\n"
    assert run("proc f(int n) { return(n+1); } f;") == \
        "// libname  : \n// procname : f\n// type     : singular\n"


def test_poly_str_directly():
    from mech.kernel import QQ, MonomialOrder, PolyRing
    R = PolyRing(QQ, ["x", "y"], MonomialOrder.simple("dp", 2))
    x, y = R.gens()
    assert poly_str(x**2 * y - y / 3) == "x2y-1/3y"


def test_a_polynomial_printed_again_follows_the_short_setting():
    # poly_str keeps the last texts: `short` and the ring's ordering still decide each time
    out = run("ring r=0,(x,y),dp; poly f = 3x2y-1/2; f; short = 0; f; string(f); short = 1; f;\n"
              "ring s = 0,(x,y),ds; poly f = imap(r, f); f; ring t = 0,(x,yy),dp; poly f = 3x2*yy; f; f;")
    assert out.split() == ["3x2y-1/2", "3*x^2*y-1/2", "3*x^2*y-1/2", "3x2y-1/2", "-1/2+3x2y",
                           "3*x^2*yy", "3*x^2*yy"]
