"""Commands of Singular's kernel and libraries added in session 10: char_series (Wang's irreducible
characteristic series, factory's ordering rules), weight (the bounded integer search of Singular's
ecart-weight heuristic), elim.lib's select/select1/nselect, general.lib's timeStd/factorH/timeFactorize,
monomial, print(x, format), sprintf, printf, sba; the basering after a procedure that exports a ring; keepring's ring seen by the
caller; QQ as the characteristic of a ring; factorize over Z/p[a]/(m) (univariate or homogeneous);
rootofUnity in characteristic p.  Each snippet's output is compared with the installed Singular's line by
line."""
from __future__ import annotations

import pytest

from tests.util import error, output_lines, run, run_singular

pytestmark = pytest.mark.singular

SNIPPETS = {
    "char_series": """
ring r = 32003,(x,y,z),dp;
print(char_series(ideal(xyz, xz, y)));
print(char_series(ideal(x2-y, xy-z)));
ring s = 0,(x,y,z,u),dp;
ideal i = -3zu+y2-2x+2, -3x2u-4yz-6xz+2y2+3xy, -3z2u-xu+y2z+y;
char_series(i);
print(char_series(ideal(x2-1, (y-x)*(y+2), z*y-1)));
print(char_series(ideal(0)));
print(char_series(ideal(1)));
ring t = 2,(x,y,z),dp;
print(char_series(ideal(x*z^2+y^2+y, x*y+y^2*z^2)));
""",
    "char_series_split": """
ring R = 3,(x,y),lp;
print(char_series(ideal(y4-x3-x, x9-x, y9-y)));
ring R2 = 5,(x,y),dp;
print(char_series(ideal(x2-2, y2-2)));
print(char_series(ideal(x2-2, (y2-3)*(y-x))));
ring R7 = 7,(x,y,z),dp;
print(char_series(ideal(x3-2, y3-x, z-y)));
""",
    "elim_select": """
LIB "elim.lib";
ring r = 0,(x,y,z),dp;
ideal i = x2, xy, z, y3+1, 0, xz;
select(i, 1); select(i, 1..2); select1(i, 1..2); nselect(i, 1); nselect(i, 1..3);
matrix m[2][3] = x,y,z,1,x2,y;
print(nselect(m, 3)); print(select(m, 1)); print(select1(m, 2..3));
""",
    "general_time": """
LIB "general.lib";
ring r = 32003,(x,y,z),dp;
timeStd(ideal(x2-y, xy-z), 60);
timeStd(ideal(x2-y, xy-z));
factorH(x2z-z3+y*(x-z));
factorH((x2y-z3)*(y2-xz));
timeFactorize(x2-y2);
""",
    "monomial": """
ring r = 0,(x,y,z),dp;
monomial(intvec(2,3)); monomial(intvec(1,2,3,4,5)); monomial(intvec(0,0,0,0)); leadexp(monomial(intvec(0,4)));
monomial(intvec(2,3,0,1)); leadexp(monomial(intvec(2,3,0,1))); monomial(intvec(1,0,0,3));
""",
    "sprintf_sba": """
ring r = 0,(x,y,z),dp;
ideal i = x2,y;
print(i, "%s"); print(3, "%2s"); print("", "%2s"); print(i, "%p");
sprintf("s:%s,%n p:%p", 1, ideal(x, y));
sprintf("abc"); sprintf("%"); sprintf("a%sb%n", 1); sprintf("a%sb%sc", 1);
printf("%s and %s", 1, 2);
list l = 1, x2;
sprintf("%s|%s", l);
sba(ideal(x2-y, xy-z, z3-x)); size(sba(ideal(x2-y, xy-z), 1, 0));
""",
    "proc_ring": """
proc mk(int n) { ring R = 32003,(x(0..n)),dp; ideal i = x(0)^2, x(1)-x(0); export(R); export(i); return("a"); }
string s = mk(2);
nameof(basering); std(i);
ring A = 0,(a),dp;
ring B = 0,(b),dp;
proc sw() { setring A; return(1); }
int k = sw(); nameof(basering);
proc mk3() { ring D = 0,(d),dp; export(D); return(3); }
k = mk3(); nameof(basering);
""",
    "qq_keepring": """
ring r = QQ,(x,y),dp; r;
ring s = (QQ,a),(x),dp; charstr(s);
proc mk(ideal J) { def R = basering; string ri = "ring Rhelp=(" + charstr(R) + "),(" + varstr(R) + ",Y),dp;";
  execute(ri); ideal I = imap(R, J), Y-var(1); keepring(Rhelp); return(std(I)); }
setring r;
mk(ideal(x2-y));
nameof(basering); setring r; kill Rhelp;
""",
    "factorize_fq": """
ring C = (32003,i),x,dp;
minpoly = i2+1;
factorize(x2+1); factorize(x2+1, 1); factorize(x2+1, 2); factorize((x3-2)*(x+i)^2);
ring R3 = (2,a),(x,y),lp;
minpoly = a2+a+1;
factorize(x2+xy+y2);
ring R5 = (5,b),(x,y,z),dp;
minpoly = b2+2;
factorize(x4+y4); factorize(x2-2z2);
""",
    "root_of_unity_p": """
LIB "ring.lib";
ring r = (5,a),x,dp;
minpoly = a2-2;
rootofUnity(6);
ring s = (7,b),x,dp;
rootofUnity(6); rootofUnity(8); rootofUnity(1); rootofUnity(2); rootofUnity(12); rootofUnity(16);
""",
    "weight": """
ring r = 32003,(x,y,z),dp;
weight(ideal(x5+y3, z2+xy));
weight(ideal(x3+xyz+z3, y4+y2z2+z4, x5+x2y2z+y5));
weight(ideal(x33+x11y12z13+z39, y48+y24z26+z52));
weight(ideal(0)); weight(ideal(x, y2));
ring s = 0,(t,x,y,z,u),ds;
weight(ideal(9x8+y7t3z4+5x4y2t2+2xy2z3t2, 9y8+7xy6t+2x5y4t2, 9z8+3x2y3z2t4, u3-xyz));
""",
}


@pytest.mark.parametrize("name", sorted(SNIPPETS))
def test_as_singular(name: str) -> None:
    src = SNIPPETS[name]
    assert output_lines(run(src)) == output_lines(run_singular(src))


def test_time_factorize_with_a_limit() -> None:
    """With a limit the factorization that finishes is returned (the installed Singular's fork link never
    reports it ready and answers "irreducible"; general.lib documents the factorization)."""
    out = run('LIB "general.lib"; ring r = 0,(x,y),dp; timeFactorize(x2-y2, 60);')
    assert output_lines(out) == ["[1]:", "   _[1]=-1", "   _[2]=-x+y", "   _[3]=x+y", "[2]:", "   1,1,1"]


def test_char_series_reducible_over_the_extension_is_refused() -> None:
    """y2-2 splits over Q(x) with x2 = 2: the series would need factoring over the extension (not built)."""
    e = error("ring r = 0,(x,y),dp; char_series(ideal(x2-2, y2-2));")
    assert "not supported" in str(e)


def test_root_of_unity_odd_with_several_candidates_is_an_error() -> None:
    """Over Z/7 t^9-1 has several factors of the largest degree: ring.lib assumes an even n there (an error)."""
    e = error('LIB "ring.lib"; ring s = (7,b),x,dp; rootofUnity(9);')
    assert "ASSUME failed" in str(e)
