"""The Macaulay2 dialect's rings, operators and functions: scripts with the output real Macaulay2
1.21 prints for them (``M2 --script``); the ``macaulay2`` tests check these outputs against the
installed Macaulay2."""
from __future__ import annotations


import pytest

from mech import Session
from tests.util import m2_case_tests

#: (name, script, what Macaulay2 prints)
CASES = [
    ("degree_and_unit_ideal", """R = QQ[x,y];
print toString degree(x^2*y)
print (saturate(ideal(x^2), ideal(x)) == R)
print (ideal(x) == R)
print (ideal(x, 1) == 1)
""", "{3}\ntrue\nfalse\ntrue\n"),
    ("quotient_rings", """R = QQ[x,y];
S = R/ideal(x^2-y);
print toString (x^3+y)
print dim S
I = ideal(x*y);
print toString gens gb I
print dim I
print ((x^2) == y)
print toString ideal(x^3, y)
print toString gens gb ideal(x^3, y^2)
print (ideal(x) == ideal(y))
print (ideal(x^2) == ideal(y))
""", "x*y+y\n1\nmatrix {{y^2, x*y}}\n0\ntrue\nideal(x*y,y)\nmatrix {{y^2, x*y}}\nfalse\ntrue\n"),
    ("towers", """T = QQ[t][u];
print toString ((t+1)*u^2 - t + (t*u)^2)
""", "(t^2+t+1)*u^2-t\n"),
    ("tower_terms_and_degrees", """R = QQ[a..d]; S = R[x,y];
f = a*x+b*x+c*x*y+c*x^3+1+a+a^2*x^3;
print toString terms f
print toString leadTerm f
print toString leadMonomial f
print toString leadCoefficient f
print toString degree f
print toString degree (x+a^5)
print toString degree (a^5+a)
print toString degrees S
print toString isHomogeneous(x+a)
print toString support f
U = QQ[a][b][z];
print toString degree (z*b+a^3)
""", "{(a^2+c)*x^3, c*x*y, (a+b)*x, a+1}\n(a^2+c)*x^3\nx^3\na^2+c\n{3, 2}\n{1, 5}\n{5}\n"
     "{{1, 0}, {1, 0}}\nfalse\n{x, y, a, b, c}\n{1, 1, 3}\n"),
    ("free_modules_and_maps", """R = ZZ/101[x,y,z];
p = map(R^2,R^{-2,-2,0},{{x^2,0,3},{0,y^2,5}});
print toString p
print toString isHomogeneous p
print toString map(R^2,R^3,{(0,0) => x+y, (1,1) => x^2, (0,2) => x-1, (0,0) => x-y})
q = map(R^2,3,{{x^2,0,3},{0,y^2,5}});
print toString degrees source q
print toString (R^{-2,3})
print toString id_(R^2)
m = matrix {{x^2, y, 0}, {1, x^3, 0}};
print toString degrees source m
print toString isHomogeneous m
print toString degree map(R^1, R^1, {{x^4}}, Degree => 4)
print toString m_{1,0}
print toString m^{1}
print toString degrees transpose m
print toString degree(R^1/ideal(x^2,y^3,z))
""", "matrix {{x^2, 0, 3}, {0, y^2, 5}}\ntrue\nmatrix {{x-y, 0, x-1}, {0, x^2, 0}}\n{{2}, {2}, {0}}\nR^2\n"
     "matrix {{1, 0}, {0, 1}}\n{{2}, {3}, {0}}\nfalse\n{4}\nmatrix {{y, x^2}, {x^3, 1}}\nmatrix {{1, x^3, 0}}\n"
     "{{{-2}, {-3}, {0}}, {{0}, {0}}}\n6\n"),
    ("local_rings", """needsPackage "LocalRings";
R = ZZ/32003[a,b,c];
RP = localRing(R, ideal(a,b));
I = ideal(a/(a+1)-b/(b+1), a/(a+1)+b/(b+1));
print toString (ideal(a,b) == I)
print toString (ideal(a^2-a) == ideal(a))
print toString isSubset(ideal((a-b)*(b^2+1)*c), I)
print toString isSubset(I, ideal((a-b)*(b^2+1)*c))
print toString (a/(a+1)+b)
print toString (I : ideal(c) == ideal(a-b,b^2+b))
print toString isWellDefined RP
S = QQ[x,y];
SP = S_(ideal(x,y));
print toString length(SP^1/promote(ideal(y-x^3, y-x^2), SP))
""", "true\ntrue\ntrue\nfalse\n(a*b+a+b)/(a+1)\ntrue\ntrue\n2\n"),
    ("rings_over_ZZ", """R = ZZ[x,y];
I = ideal(6*x^3, 9*x*y, 8*y^2);
print toString (intersect(I:ideal(-3,x^2), I:ideal(4*y)) == ideal(8*y^2, 3*x*y, x*y^2, 6*x^3))
print toString (I : ideal(-3, x^2, 4*y) == ideal(8*y^2, 3*x*y, 6*x^3))
print toString isSubset(ideal(x), ideal(2*x))
print toString (eliminate(ideal(x - 2*y, y^2 - 3), y) == ideal(x^2-12))
print toString det matrix {{x, 2}, {3, y}}
print toString resultant(x^2 + 3*y, x - y, x)
print toString monomialIdeal(2*x, 3*y)
print toString sort {"a11","a1","a2","A11","A1","A2","B2"}
""", "true\ntrue\nfalse\ntrue\nx*y-6\ny^2+3*y\nmonomialIdeal(x,y)\n{A1, a1, A2, a2, A11, a11, B2}\n"),
    ("operators", """R = QQ[x,y];
print ({1,2} | {3})
print toString (0..<3)
print (x === x)
print (ideal(x) === ideal(x))
print (try error "a" else 5)
print (7 // 2)
print toString ([1,2])
print toString (3:x)
print toString w
print toString (symbol w)
print toString (ideal(x,y))_*
print toString ((x^3+x*y+1) // x)
A = QQ[z_(1,1)..z_(2,2)];
print toString (z_(1,2)*z_(2,1))
print toString gens A
""", "{1, 2, 3}\n(0,1,2)\ntrue\ntrue\n5\n3\n[1, 2]\n(x,x,x)\nw\nw\n{x, y}\nx^2+y\n"
     "z_(1,2)*z_(2,1)\n{z_(1,1), z_(1,2), z_(2,1), z_(2,2)}\n"),
]


def run(code: str) -> str:
    return Session(dialect="m2").execute(code)


test_cases, test_cases_are_macaulay2s = m2_case_tests(CASES)


@pytest.mark.parametrize("code, message", [
    ("R = ZZ[x]; gb ideal(2*x)", "gb on elements of a polynomial ring over ZZ is not supported"),
    ("R = ZZ[x]; x/2", "not in a ring over ZZ"),
    ("R = ZZ[x]; x^2 // 2", "// on elements of a polynomial ring over ZZ is not supported"),
    ("R = QQ[a]; P = ideal(a); S = R_P; gb ideal(a^2)", "gb on elements of a local ring R_P is not supported"),
    ("R = QQ[x,y]; S = R/ideal(x^2); factor(x+y)", "factor on elements of a quotient ring R/I is not supported"),
    ("R = QQ[x]; saturate(ideal(x), DegreeLimit => 2)", "saturate: the option DegreeLimit is not supported"),
    ("R = QQ[x]; y^2", "unknown identifier 'y'"),
    ("R = QQ[a,b, Degrees => {{1,0},{0,1}}]; degrees source matrix {{a, b}}", "degrees of maps and modules over a multigraded ring"),
    ("C = QQ[a, MonomialSize => 8]; a^200", "monomial overflow"),
    ("needsPackage \"NoSuchPackage\"", "the package NoSuchPackage is not available"),
    ("R = QQ[x]; assert(1 == 2)", "assertion failed"),
])
def test_named_refusals(code: str, message: str) -> None:
    """What mech lacks stops with a message naming it (never a wrong value or a traceback)."""
    from mech.dsl.errors import MechError
    with pytest.raises(MechError) as e:
        run(code)
    assert message in e.value.format()


def test_script_and_session_output() -> None:
    """A session prints oN = value for statements without ';' (as M2's REPL); scripts do not."""
    assert run("R = QQ[x]\nx^2 + 1\nprint 3") == "o1 = R\no2 = x^2+1\n3\n"
