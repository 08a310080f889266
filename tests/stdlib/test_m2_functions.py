"""Macaulay2 functions of the dialect added for issue 22 (table, ultimate, isPrimary(Q, P),
leadTerm(n, ...) and of vectors, monomialIdeal over ZZ, monomialSubideal, permanents, substitute into
ZZ, ZZ^n, vectors, lengths over R_P at a non-maximal prime): scripts with what Macaulay2 1.21 prints
for them (``M2 --script``; the ``macaulay2`` tests check it against the installed Macaulay2)."""
from __future__ import annotations


import pytest

from mech import Session
from tests.util import m2_case_tests

#: (name, script, what Macaulay2 prints)
CASES = [
    ("table", """R = ZZ[a..c];
print toString table(2, {a, b}, (i, j) -> j^(i+1))
print toString table({1,2}, 3, (i, j) -> i*j)
print toString ultimate(coefficientRing, ZZ/101[a][b])
print toString isPrimary(ideal(a^2, b), ideal(a, b))
print toString isPrimary(ideal(a*b, b^2), ideal(b))
""",
     '{{a, b}, {a^2, b^2}}\n{{0, 1, 2}, {0, 2, 4}}\nZZ/101\ntrue\nfalse\n'),
    ("leadterm", """R = QQ[a..d, MonomialOrder => {Weights => {1,2,3,4}, Weights => {2,4,2,1}}];
f = a^6 + b^3 + c^2;
print toString apply(4, n -> leadTerm(n, f))
print toString leadTerm(1, ideal(a^6 + b^3 + c^2, d))
R = QQ[x,y,z, MonomialOrder => {GRevLex => 2, Lex => 1}];
print toString leadTerm(1, x^3+x*y^2+y^3+x^2*z+z^4)
R = QQ[x,y,z,w, MonomialOrder => GLex];
print toString leadTerm(1, x^2*z+y^3+z*w^2+w^3)
R = QQ[a..d, MonomialOrder => {GRevLex => 2, Position => Down, GRevLex => 2}];
F = R^3;
print toString leadTerm(b*F_0 + c^4*F_1)
print toString leadTerm(c*F_0 + d^2*F_1)
R = QQ[a..d]; F = R^3;
print toString leadTerm(a*F_0 + a*F_1)
""",
     '{a^6+b^3+c^2, a^6+b^3+c^2, a^6+b^3, a^6}\nmatrix {{d, a^6+b^3+c^2}}\nx^3\nx^2*z+y^3+z*w^2+w^3\nvector {b, 0, 0}\nvector {c, 0, 0}\nvector {0, a, 0}\n'),
    ("monomial", """R = ZZ[x,y];
print toString monomialIdeal ideal(2*x, 3*y)
print toString monomialIdeal ideal(6*x^2, 4*y^2+x)
R = ZZ/101[a,b,c];
print toString monomialSubideal ideal(a^3, b^3, c^3, a^2-b^2)
print toString monomialSubideal ideal(a^2-b^2, a*b)
print toString monomialSubideal ideal(a+b, a*c-1)
print toString permanents(2, matrix {{a, b}, {c, a}})
print toString substitute(51*a^2*b+3, matrix {{2, -3, 0}})
print toString (map ZZ^3 === id_(ZZ^3))
""",
     'monomialIdeal(x,y)\nmonomialIdeal(x^2,y^2)\nmonomialIdeal(a^3,a^2*b,a*b^2,b^3,c^3)\nmonomialIdeal(a^3,a*b,b^3)\nmonomialIdeal()\nideal(a^2+b*c)\n603\ntrue\n'),
    ("vectors", """R = ZZ/101[x,y,z];
F = R^3;
v = x*F_0 + y*F_1 + z*F_2;
print toString v
print toString (-v + F_0)
print toString (v == v)
print toString entries v
print toString matrix v
print toString matrix {F_2, F_1, v}
print toString vector {1, 2, 3}
print toString entries vector {x, 0, y^2}
""",
     'vector {x, y, z}\nvector {-x+1, -y, -z}\ntrue\n{x, y, z}\nmatrix {{x}, {y}, {z}}\nmatrix {{0, 0, x}, {0, 1, y}, {1, 0, z}}\nvector {1, 2, 3}\n{x, 0, y^2}\n'),
    ("length", """R = QQ[x,y,z,w];
P = ideal(x*z-y^2, y*w-z^2, x*w-y*z);
RP = localRing(R, P);
print length(RP^1/promote(P^2, RP))
print length(RP^1/promote(P^3, RP))
use R;
I = ideal(x*z-y^2, z*(y*w-z^2)-w*(x*w-y*z));
print length(RP^1/promote(I, RP))
""",
     '3\n6\n2\n'),
    ("exterior_dual", """R = QQ[a..f];
print toString exteriorPower(2, matrix {{a, b, c}, {d, e, f}})
print toString exteriorPower(0, matrix {{a, b}, {c, d}})
QQ[x,y];
f = matrix {{x^2, x*y}, {0, y^2}};
print toString dual f
print toString target dual f
S = QQ[u,v]/(u^2-v^2);
print toString minors(2, matrix {{u, v}, {v, u}})
""",
     'matrix {{-b*d+a*e, -c*d+a*f, -c*e+b*f}}\nmatrix {{1}}\nmatrix {{x^2, 0}, {x*y, y^2}}\n(QQ[x..y])^2\nideal()\n'),
    ("module_quotients", """R = QQ[a..d];
M = image matrix {{a, b}, {c, d}};
print toString quotient(M, R^2)
print toString (M : image matrix {{a}, {0}})
print toString quotient(image matrix {{a*b, 0}, {0, b}}, image matrix {{a}, {b}})
print toString ann(R^2/M)
""",
     'ideal(b*c-a*d)\nideal(b*c-a*d)\nideal b\nideal(b*c-a*d)\n'),
    ("eliminate_over_ZZ", """R = ZZ[x,a,b];
print toString eliminate(ideal(x^3+a*x+b, 6*x^2+4*a), x)
print toString eliminate(ideal(-x^2+3, 2*x-2), x)
print toString eliminate(ideal(x^2-a*x+1, b*x^2+2), x)
""",
     'ideal(4*a^3+54*b^2)\nideal 4\nideal(2*a^2*b+b^2-4*b+4)\n'),
]


test_cases, test_cases_are_macaulay2s = m2_case_tests(CASES, prelude='needsPackage "LocalRings"\n')


def test_refusals() -> None:
    """Parts of orders and lengths mech does not know are refused, not guessed."""
    from mech.dsl.errors import MechError
    for code, message in [
            ("R = QQ[x,y,z,w,MonomialOrder=>{Weights=>{1,1,1,1}, Lex}]; leadTerm(2, x+y)", "are not known to mech"),
            ("R = QQ[x,y]; RP = localRing(R, ideal(x*y)); length(RP^1/promote(ideal(x^2*y^2), RP))", "prime"),
            ("R = QQ[x,y,z]; RP = localRing(R, ideal(x,y)); length(RP^1/promote(ideal(x), RP))", "infinite length")]:
        with pytest.raises(MechError) as e:
            Session(dialect="m2").execute(code)
        assert message in e.value.format()
