"""The Macaulay2 dialect's monomial orders ``ProductOrder`` and ``GLex`` with degrees, ``trim`` and
``mingens`` over ZZ, ``sort`` of matrices, ``options``, ``RevLex`` and the invertible variables of
``GroupLex`` / ``GroupRevLex`` (session 11), integers in ideals and matrices as ZZ's whatever ring is
in use, promoted beside another ring's values (session 12): each script's output is what
Macaulay2 1.21 prints for it (``M2 --script``); the ``macaulay2`` test checks these outputs against
the installed Macaulay2."""
from __future__ import annotations


import pytest

from mech import Session
from tests.util import m2_case_tests
from mech.dsl.errors import MechError

#: (name, script, what Macaulay2 prints)
CASES = [
    ("product_order", """R = QQ[a..e, MonomialOrder => ProductOrder {3,2}];
print toString (a*d^3+b^2*e+c^3+a^2*b+e^5)
R = QQ[a..e, Degrees => {1,2,3,1,1}, MonomialOrder => ProductOrder {3,2}];
print toString (a^3+b^2+c+c*d^3+d^6)
""", "a^2*b+c^3+b^2*e+a*d^3+e^5\nb^2+a^3+c*d^3+c+d^6\n"),
    ("glex_ignores_degrees", """R = QQ[a,b, Degrees => {1,3}, MonomialOrder => GLex];
print toString (a^2+b)
R = QQ[a,b,c, Degrees => {1,3,1}, MonomialOrder => {Lex => 1, GLex}];
print toString (a^2+b+c^5)
R = QQ[a,b,c, Degrees => {1,3,1}, MonomialOrder => {Weights => {1,2,3}, GLex}];
print toString (a^2+b+c^5)
""", "a^2+b\na^2+c^5+b\nc^5+a^2+b\n"),
    ("trim_over_zz", """R = ZZ[w,x,y,z];
I = ideal(z*w-2*x*y, 3*w^3-z^3, w*x^2-4*y*z^2, x);
print toString mingens I
print toString trim I
R = ZZ[x,y];
print toString trim ideal(2*x, 3*x)
print toString trim ideal(6, 4*x, x^2)
print toString mingens ideal(x^2+1, 3)
""", "matrix {{x, w*z, 4*y*z^2, 3*w^3-z^3}}\nideal(x,w*z,4*y*z^2,3*w^3-z^3)\nideal x\nideal(6,2*x,x^2)\n"
     "matrix {{3, x^2+1}}\n"),
    ("sort_matrix_and_options", """R = ZZ/32003[a..d, MonomialOrder => Lex];
m = matrix{{a*d, b^2, b^100, b^50*d^50, c^2*d}};
print toString sort m
print toString sort(m, DegreeOrder => null, MonomialOrder => Descending)
print toString sort(m, DegreeOrder => Descending)
print toString sort(m, DegreeOrder => Ascending, MonomialOrder => Descending)
print toString ((options sort).MonomialOrder)
""", "matrix {{c^2*d, b^2, b^50*d^50, b^100, a*d}}\nmatrix {{a*d, b^100, b^50*d^50, b^2, c^2*d}}\n"
     "matrix {{b^50*d^50, b^100, c^2*d, b^2, a*d}}\nmatrix {{a*d, b^2, c^2*d, b^100, b^50*d^50}}\nAscending\n"),
    ("ring_options", """R = QQ[a..d, Degrees => {1,2,1,3}, MonomialOrder => {Position => Down, 2}];
print toString (options R).MonomialOrder
R = QQ[a..d, Degrees => {1,2,1,3}, MonomialOrder => GLex];
print toString (options R).MonomialOrder
R = QQ[a..d, Degrees => {1,2,1,3}, MonomialOrder => Eliminate 2];
print toString (options R).MonomialOrder
R = QQ[a..d, Degrees => {1,2,1,3}, MonomialOrder => ProductOrder {1,3}];
print toString (options R).MonomialOrder
R = QQ[a..d, MonomialOrder => {Weights => {1,2}, Lex}];
print toString (options R).MonomialOrder
R = QQ[a,b, MonomialOrder => RevLex, Global => false];
print toString (options R).MonomialOrder
print toString (options R).Global
print toString (options R).Variables
print toString (options R).Degrees
""", "VerticalList{MonomialSize => 32, Position => Down, GRevLex => {1, 2}, GRevLex => {1, 3}}\n"
     "VerticalList{MonomialSize => 32, Weights => {1, 1, 1, 1}, Lex => 4, Position => Up}\n"
     "VerticalList{MonomialSize => 32, Weights => {1, 1}, GRevLex => {1, 2, 1, 3}, Position => Up}\n"
     "VerticalList{MonomialSize => 32, GRevLex => {1}, GRevLex => {2, 1, 3}, Position => Up}\n"
     "VerticalList{MonomialSize => 32, Weights => {1, 2}, Lex => 4, Position => Up}\n"
     "VerticalList{MonomialSize => 32, RevLex => 2, Position => Up}\nfalse\n{a, b}\n{{1}, {1}}\n"),
    ("revlex_and_group_orders", """S = QQ[a,b,c, MonomialOrder => RevLex, Global => false];
print toString (a+b+c)
print toString (a*b+c^2+a^2)
R = QQ[a..d, MonomialOrder => GroupRevLex => 2, Global => false];
print toString (a^-1*b^-2+c^2+a)
print toString (a^-1+b^-1)
print toString (a^2*b^-1+1+a*b^-2)
print toString (options R).MonomialOrder
R = ZZ[a..f, MonomialOrder => GroupLex => 3];
print toString (a^-2*(c+d) + b*(c^100+d^100)*(c + e + f))
R = QQ[a..d, MonomialOrder => GroupLex => 2];
print toString (b^-1*d^3+a^2*d+a^-1*c^2+c)
print toString ((a^-1+b)^2)
print toString (a^-1*a)
print (try c^(-1) else "failed")
""", "c+b+a\nc^2+a*b+a^2\na^(-1)*b^(-2)+c^2+a\na^(-1)+b^(-1)\n1+a*b^(-2)+a^2*b^(-1)\n"
     "VerticalList{MonomialSize => 32, GroupRevLex => 2, GRevLex => {1, 1}, Position => Up}\n"
     "b*c^101+b*c^100*e+b*c^100*f+b*c*d^100+b*d^100*e+b*d^100*f+a^(-2)*c+a^(-2)*d\n"
     "a^2*d+c+b^(-1)*d^3+a^(-1)*c^2\nb^2+2*a^(-1)*b+a^(-2)\n1\nfailed\n"),
    ("integers_are_zz_in_any_ring", """R = QQ[x,y];
print toString(ideal(x^2, 2*x) : ideal(2))
print toString(ideal(2) == ideal(1))
print toString(ideal(x) + ideal(2))
print toString(trim(ideal(x) + ideal(2)))
print toString(generator ideal(4,6))
print toString(matrix{{1,2}} * transpose matrix{{x,y}})
print toString(2 * matrix{{x,y}})
print toString(matrix{{1,2}} + matrix{{x,y}})
print toString(matrix{{1,2}} == matrix{{1,2}})
print toString(ring ideal(7))
S = ZZ/7[z];
print toString(matrix{{8,2}})
print toString(ring matrix{{8,2}})
print toString(z * matrix{{8,2}})
""", 'ideal x\nfalse\nideal(x,2)\nideal 1\n2\nmatrix {{x+2*y}}\nmatrix {{2*x, 2*y}}\nmatrix {{x+1, y+2}}\ntrue\nZZ\nmatrix {{8, 2}}\nZZ\nmatrix {{z, 2*z}}\n'),
]


def run(code: str) -> str:
    return Session(dialect="m2").execute(code)


test_cases, test_cases_are_macaulay2s = m2_case_tests(CASES)


@pytest.mark.parametrize("code, message", [
    ("R = QQ[a,b, MonomialOrder => {GLex => 2}]", "Macaulay2 takes GLex only without a size"),
    ("R = QQ[a,b, MonomialOrder => ProductOrder {2,3}]", "ProductOrder {n1, n2, ...} takes positive sizes"),
    ("R = QQ[a][b]; options R", "options R of a quotient ring, tower, local or multigraded ring is not supported"),
    ("options gb", "options of gb is not supported by mech"),
    ("R = QQ[a,b, MonomialOrder => GroupLex => 1]; (a+b)^-1", "negative power of an element that is not a unit"),
    ("R = QQ[a,b, MonomialOrder => GroupLex => 1]; gb ideal(a^-1*b)", "ideal on elements of a ring with invertible"),
    ("R = QQ[a,b, MonomialOrder => GroupLex => 1]; a^-1 / b", "operator / in a ring with invertible variables"),
    ("R = QQ[a,b, MonomialOrder => {Lex => 1, GroupLex => 1}]", "GroupLex => k takes the first"),
    ("R = QQ[a,b]; sort matrix {{a, 0}}", "sort of a matrix with zero entries is not supported"),
    ("R = QQ[a,b]; sort matrix {{a}, {b}}", "sort of a matrix with several rows is not supported"),
    ("R = QQ[a,b]; sort(matrix {{a+b^2}}, DegreeOrder => Ascending)", "inhomogeneous entries is not supported"),
    ("R = QQ[x]; ideal(1_R) == ideal 1", "== of ideals of two rings"),
    ("R = QQ[x]; intersect(ideal 2, ideal x)", "intersect: expected ideals of one ring"),
])
def test_named_refusals(code: str, message: str) -> None:
    """What Macaulay2 refuses or mech lacks stops with a message naming it."""
    with pytest.raises(MechError) as e:
        run(code)
    assert message in e.value.format()
