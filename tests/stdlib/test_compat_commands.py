"""Singular commands added for issue 21: type, and primdec.lib's algorithm options (they choose an
algorithm, not the result)."""
from __future__ import annotations

import pytest

from tests.util import error, run, run_singular

TYPE_SRC = ('int i=3; type i; ring r; poly f=x2+1; type f; ideal I=x,y; type I; list L=1,2; type L; '
            'string s="ab"; type s; number n=3; type n; matrix m[2][2]=1,x,y,2; type m; intvec v=1,2; type v; '
            'type(f); def d=3; type d; type r; map phi=r,x,y,z; type phi; intmat im[2][2]=1,2,3,4; type im;')


@pytest.mark.singular
def test_type_as_singular() -> None:
    assert run(TYPE_SRC).split() == run_singular(TYPE_SRC).split()


def test_type_header() -> None:
    assert run("int i = 3; type i;").strip() == "// i int 3"


def test_primdec_options_same_result() -> None:
    base = 'LIB "primdec.lib"; ring r=0,(x,y,z),dp; ideal i = xy, xz, (x-1)^2*y; '
    assert run(base + "primdecSY(i, 1);") == run(base + "primdecSY(i);")
    assert run(base + 'minAssGTZ(i, "noFacstd");') == run(base + "minAssGTZ(i);")
    assert run(base + "minAssChar(i, 2);") == run(base + "minAssChar(i);")
    assert "unknown option" in str(error(base + 'minAssGTZ(i, "foo");'))


ORDER_SRC = """
ring s=0,(a,b,c),wp(-1,1,2); poly g=a+1+b+a2+ab+c+a2c+bc+b2+ac2+a3b2+abc; g;
ring t=0,(a,b,c),ws(-1,1,2); imap(s,g);
ring w=0,(a,b,c),wp(0,1,2); imap(s,g);
ring t3=0,(x,y),wp(-2,1); x+y2+1+x2y4+xy2;
ring u2=0,(x,y,z),(dp(1),Wp(-1,2)); x+y+z+y2+yz+1+y3z;
ring r=0,(x,y,z),dp; coef(xy+x2+y2+x+y+1, xy);
ring l=0,(x,y,z),lp; coef(xy+x2+y2+x+y+1, xy);
ring d=0,(x,y,z),ds; coef(xy+x2+y2+x+y+1, xy);
ring m=0,(e,x),ws(-6,1); coef(3e+1,e);
"""


@pytest.mark.singular
def test_weight_orderings_and_coef_as_singular() -> None:
    assert run(ORDER_SRC).split() == run_singular(ORDER_SRC).split()


MISC_SRC = """
list l=1,2,3; insert(l,"x",4);
ring r=(0,a,b),x,dp; pardeg(a2b+1); pardeg(number(3)); pardeg((a+1)/(b3)); pardeg(number(0));
matrix m[2][2]=1,x,3,x2; trace(m); matrix n[2][3]=1,2,3,4,5,6; trace(n);
intvec v=1,2,3; transpose(v); typeof(transpose(v));
ring t=(0,a),x,dp; minpoly=a2+1; pardeg(a+1);
LIB "primdec.lib"; ring s=0,(x,y),dp; idealsEqual(ideal(x, x+y), ideal(x, y)); idealsEqual(ideal(x2), ideal(x));
"""


@pytest.mark.singular
def test_misc_as_singular() -> None:
    assert run(MISC_SRC).split() == run_singular(MISC_SRC).split()
