"""Algebraic extensions ``minpoly = ...`` (issue 21): arithmetic, printing, std, reduce, gcd and
factorize over QQ[a]/(m) and Z/p[a]/(m), compared line by line with the installed Singular."""
from __future__ import annotations

import pytest

from tests.util import error, run, run_singular

SNIPPETS = {
    "arithmetic": """
ring r=(0,a),(x,y),dp;
minpoly=a2+1;
a2; a3+a; 1/(a+1); (a+1)^-1; -a; (a+1)*x-a*y+1/2*a; minpoly; typeof(minpoly);
poly g=(a+1)*x2-a*y; g*g;
number n = 2a/3; n; n*n; n/(a-1);
basering;
""",
    "charp": """
ring s=(7,b),(x,y),dp; minpoly=b2+b+3;
1/b; b5; b^7; par(1); charstr(s); minpoly;
poly f = (2b+1)*x-y; f^3;
s;
""",
    "long_form": """
ring t=(0,c),(x),lp; minpoly=c3-2;
number m=c2/(c+1); m; 3/5*c;
short=0; m; (c+1)*x^2;
""",
    "kills_objects": """
ring r0=(0,a),x,dp; minpoly; poly f=x; minpoly=a3-2; defined(f); r0;
""",
    "std_reduce": """
ring R=(0,a),(x,y),dp;
minpoly=a2+1;
ideal i=(2a+1)*x+1/3, a*y2+3;
std(i);
reduce(x2, std(i));
ring r7=(7,a),(x,y),dp; minpoly=a2+1;
std(ideal((2a+1)*x+3, a*y2+3));
""",
    "factorize_gcd": """
ring R=(0,a),(x,y),dp;
minpoly=a2+1;
factorize(2x2+2);
factorize((a+1)*x2+2a*xy+y2);
gcd(x2+1, x2+a*x);
gcd(2*x2-2a*x, (4a+2)*x3*y);
ring S=(0,a),(y),dp;
minpoly=a3+a+1;
factorize(y3+y+1, 1);
""",
    "ordering": """
ring R=(0,a),x,dp; minpoly=2*a^2-1;
number n=7; n>0; n<0; a>0; -a>0; a>1; a>2a; (a+1)>(a-5); (2a+1)>(a+7); 0>a; 0>-a; 1/2<1/3; -3<2;
(a+1)>=(a-5); (a+1)<=(a-5); (a+1)<(a-5); a>=a;
ring T=(0,a),x,dp; 1/3<1/2; number(0)<number(0);
ring r=0,(x,y),dp; poly(0)>x; x>0; 0>-x; -x>0; -x>-2x; x2+y>x2+2y; x>=x; x+1>=x+2; x+1<=x+2;
poly(2)>poly(1); 2x>x; x+2>x+1; x+y>x; x2>y; y>x2;
ring s=7,(x),lp; number(6)>number(1); -x>x; 6x>x; x>6x; 5x>3x; 3x>5x; 6x>5x; 4x>x;
""",
}


@pytest.mark.singular
@pytest.mark.parametrize("name", sorted(SNIPPETS))
def test_as_singular(name: str) -> None:
    src = SNIPPETS[name]
    assert run(src).split() == run_singular(src).split()


def test_inverse_by_hand() -> None:
    # (a+1)(-a/2+1/2) = -a2/2 + 1/2 = 1 when a2 = -1
    assert run("ring r=(0,a),x,dp; minpoly=a2+1; 1/(a+1);").strip() == "(-1/2a+1/2)"


def test_refusals() -> None:
    assert "one parameter" in str(error("ring r=(0,a,b),x,dp; minpoly=a2+1;"))
    assert "already" in str(error("ring r=(0,a),x,dp; minpoly=a2+1; minpoly=a3-2;"))
    assert "reducible" in str(error("ring r=(0,a),x,dp; minpoly=a2-1; 1/(a-1);"))

