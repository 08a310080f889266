"""The Macaulay2 dialect's lists, strings, matrices, monoids, integer matrices, quotient rings and
multigraded rings (session 9): each script's output is what Macaulay2 1.21 prints for it
(``M2 --script``); the ``macaulay2`` test checks these outputs against the installed Macaulay2."""
from __future__ import annotations


import pytest

from mech import Session
from tests.util import m2_case_tests
from mech.dsl.errors import MechError

#: (name, script, what Macaulay2 prints)
CASES = [
    ("lists_and_strings", """print toString {3:a, 2:b}
print toString splice {2:a, 1:b}
print toString identity()
print toString toList join(iterator {1, 2}, {3})
R = QQ[a..d];
print toString flatten matrix {{a, b}, {c, d}}
print toString select("([a-z]+);", "\\\\U$1", "dog; cat, deer;")
print toString select("^.*$", "AB\\nCD\\r\\nEF")
print toString select("[[:digit:]]+", "a12b345")
""",
     '{(a,a,a), (b,b)}\n{a, a, b}\n()\n{1, 2, 3}\nmatrix {{a, c, b, d}}\n{DOG, DEER}\n{AB, CD, EF}\n{12, 345}\n'),
    ("matrices_monoids_frobenius", """R = QQ[a..f];
f = matrix {{a, b, c}, {d, e, f}};
print toString submatrix(f, {1, 0}, {0..1})
print toString submatrix(f, , {2})
print toString submatrix'(f, {0}, {1, 7})
print toString (matrix {{a, b}} ** matrix {{c}, {d}})
print toString matrix {{f, f}, {f, 0}}
I = ideal(a^2*b, c^3);
print toString I^[2]
print toString I^[1,2,1,1,1,1]
print toString baseName a
print (R/ideal(a, a - 1) == 0)
print (R/ideal(a^2) == 0)
M = monoid[x, y, z];
print numgens M
print toString vars M
print toString gens monoid R
""",
     'matrix {{d, e}, {a, b}}\nmatrix {{c}, {f}}\nmatrix {{d, f}}\nmatrix {{a*c, b*c}, {a*d, b*d}}\nmatrix {{a, b, c, a, b, c}, {d, e, f, d, e, f}, {a, b, c, 0, 0, 0}, {d, e, f, 0, 0, 0}}\nideal(a^4*b^2,c^6)\nideal(a^2*b^2,c^3)\na\ntrue\nfalse\n3\n{x, y, z}\n{a, b, c, d, e, f}\n'),
    ("integers_quotients_gradings", """print toString matrix {{1, 2}, {3, 4}}
print toString ((matrix {{1, 2}, {3, 4}})^2)
print toString ideal 6
print toString matrix 7
R = ZZ/5[x, y];
print toString ((matrix {{1, 2}, {3, 4}})^2)
print toString promote(ideal(2, 3), R)
print (id_(R^{1, 2}) == id_(R^2))
print (id_(R^2) == id_(R^2))
S = QQ[x, y, z]/(y^2 - x^3);
print toString jacobian S
print degree S
print toString annihilator (y^2)
T = QQ[a..c, Degrees => {{1, 0}, {0, 1}, {1, 1}}];
print toString heft T
print toString degree (a*c^2 + b)
print isHomogeneous (a*b - c)
print isHomogeneous (a - c)
print toString degrees T
U = QQ[a..c, Degrees => {{0, 1}, {1, 0}, {-1, 1}}];
print toString heft U
print toString (a + b + c)^2
""",
     'matrix {{1, 2}, {3, 4}}\nmatrix {{7, 10}, {15, 22}}\nideal 6\nmatrix {{7}}\nmatrix {{7, 10}, {15, 22}}\nideal(2,-2)\nfalse\ntrue\nmatrix {{-3*x^2}, {2*y}, {0}}\n3\nideal()\n{1, 1}\n{3, 2}\ntrue\nfalse\n{{1, 0}, {0, 1}, {1, 1}}\n{1, 2}\na^2+2*a*b+2*a*c+b^2+2*b*c+c^2\n'),
    # a strong Gröbner basis over ZZ (kernel/zz_groebner.py: the normal strategy and criteria)
    ("eliminate_over_ZZ", """R = ZZ[x,a,b,c,d];
f = x^4+3*x^2+a*x+b;
g = x^3+x^2+c*x+d;
print toString eliminate(ideal(f,g),x)
print (eliminate(ideal(f,g),x) == ideal resultant(f,g,x))
""",
     'ideal(b*c^4-a*c^3*d+a^2*b*c+3*a*b*c^2+2*b^2*c^2-6*b*c^3-a^3*d-3*a^2*c*d-5*a*b*c*d+6*a*c^2*d-4*b*c^2*d+3*a^2*d^2+3*a*c*d^2+4*b*c*d^2+3*c^2*d^2-3*a*d^3+d^4-a*b^2+b^3-4*a*b*c-10*b^2*c+12*b*c^2+4*a^2*d+10*a*b*d+4*b^2*d-12*a*c*d+12*b*c*d+3*a*d^2-7*b*d^2-18*c*d^2-6*d^3+4*b^2-24*b*d+36*d^2)\ntrue\n'),
]


def run(code: str) -> str:
    return Session(dialect="m2").execute(code)


test_cases, test_cases_are_macaulay2s = m2_case_tests(CASES)


@pytest.mark.parametrize("code, message", [
    ("R = QQ[a,b, Degrees => {{1,0},{0,1}}]; isHomogeneous matrix {{a, b}}", "over a multigraded ring"),
    ("R = QQ[a]; f = matrix {{a}}; submatrix(f, {3}, {0})", "rows are numbers from 0 to 0"),
    ("R = QQ[a]; I = ideal(a); I^[1,2]", "one exponent >= 0 or one per variable (1)"),
    ("R = QQ[a]; matrix {{matrix {{a}}, matrix {{a}, {a}}}}", "need as many"),
    ("R = QQ[x]/(x^2); degree ideal(x)", "degree on elements of a quotient ring R/I is not supported"),
    ("R = QQ[x]; jacobian R", "jacobian R takes a quotient ring"),
])
def test_named_refusals(code: str, message: str) -> None:
    """What mech lacks stops with a message naming it (never a wrong value or a traceback)."""
    with pytest.raises(MechError) as e:
        run(code)
    assert message in e.value.format()
