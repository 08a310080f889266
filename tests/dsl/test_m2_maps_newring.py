"""The Macaulay2 dialect's ring maps by a matrix of numbers (a change of coordinates), maps of
towers given their own variables' images, ``DegreeMap``, ``isHomogeneous`` of a map, maps of free
modules, ``map(f, Degree => d)``, tensor products ``**`` of maps, ring elements and free modules with
their degrees, ``newRing`` and ``entries`` over ZZ (session 11): each script's output is what Macaulay2
1.21 prints for it (``M2 --script``); the ``macaulay2`` test checks these outputs against the
installed Macaulay2."""
from __future__ import annotations


import pytest

from mech import Session
from tests.util import m2_case_tests
from mech.dsl.errors import MechError

#: (name, script, what Macaulay2 prints)
CASES = [
    ("maps", """R = ZZ[x,y];
S = ZZ[a,b,c];
g = map(R,S,matrix {{1,2,3},{4,5,6}});
print toString g
print toString g(a+b)
S = ZZ[a][b,c];
h = map(S,S,matrix {{b,c,2*a}});
print toString h(a^7 + b^3 + c)
k = map(S,S,matrix {{c,b}});
print toString k(a^7 + b^3 + c)
R = QQ[x,y,z];
S = QQ[t,u];
f = map(S,R,{t^2,t*u,u^2},DegreeMap => i -> 2*i);
print isHomogeneous f
print isHomogeneous map(S,R,{t^2,t*u,u^2})
print isHomogeneous map(S,R,{t^2,0,u^2}, DegreeMap => i -> 2*i)
M = R^{1,2};
print toString degrees f M
print toString degrees (f ** M)
print toString (2 * {1, 3})
""", "map(R,S,{x+4*y, 2*x+5*y, 3*x+6*y})\n3*x+9*y\nb^3+c+128*a^7\nc^3+b+a^7\ntrue\nfalse\ntrue\n"
     "{{-2}, {-4}}\n{{-2}, {-4}}\n{2, 6}\n"),
    ("new_ring", """S = QQ[u, v, a, c, Degrees => {2, 3, 1, 2}];
P = ideal(v^3-u^3*a^3, u*v^2-c^2*a^4);
Ps = saturate(P, a);
R = newRing(S, Degrees => entries id_(ZZ^4));
print toString degrees R
print toString (u^2 + v + a^5 + c^3)
Q = saturate(sub(P, R), a);
print (Q == quotient(Q, a))
print (Q == sub(Ps, R))
T = newRing(S, MonomialOrder => Lex);
print toString (u + v^2 + a^3)
print toString entries matrix {{1, 2}, {3, -4}}
""", "{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}\n"
     "c^3+a^5+u^2+v\ntrue\ntrue\nu+v^2+a^3\n"
     "{{1, 2}, {3, -4}}\n"),
    ("matrix_degrees", """R = QQ[a,b];
f = matrix{{a,b},{b^2,a^2}};
g = map(f, Degree => 1);
print toString degrees source g
print toString degree g
print isHomogeneous g
h = f ** matrix{{a},{b}};
print toString h
print toString degrees source h
print toString degree h
k = b^2 ** f;
print toString degrees source k
print toString degree k
print toString degrees (R^{1,2} ** R^{-3,0})
print ((R^{1,2} ** R^{-3,0}) == R^{-2,1,-1,2})
print (map f == f)
""", "{{1}, {1}}\n{1}\nfalse\nmatrix {{a^2, a*b}, {a*b, b^2}, {a*b^2, a^3}, {b^3, a^2*b}}\n{{3}, {3}}\n{0}\n"
     "{{4}, {4}}\n{0}\n{{2}, {-1}, {1}, {-2}}\ntrue\ntrue\n"),
]


def run(code: str) -> str:
    return Session(dialect="m2").execute(code)


test_cases, test_cases_are_macaulay2s = m2_case_tests(CASES)


@pytest.mark.parametrize("code, message", [
    ("R = QQ[x,y]; S = QQ[a,b,c]; map(R, S, matrix {{1,2},{3,4}})", "takes 2 rows and 3 columns"),
    ("R = QQ[x]; S = QQ[a,b]; isHomogeneous map(S, R, {a}, DegreeMap => i -> 2)", "DegreeMap => f: f takes a degree"),
    ("R = QQ[x]/(x^2); newRing(R, Degrees => {2})", "newRing on elements of a quotient ring R/I is not supported"),
])
def test_named_refusals(code: str, message: str) -> None:
    """What mech lacks stops with a message naming it."""
    with pytest.raises(MechError) as e:
        run(code)
    assert message in e.value.format()
