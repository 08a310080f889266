"""Macaulay2 package functions of the dialect (PrimaryDecomposition's primaryComponent, EHV and Monomial
strategies; quotient rings' presentation, ambient and describe; iterators and list functions; LocalRings'
hilbertSamuelFunction): scripts with what Macaulay2 1.21 prints for them (``M2 --script``, checked by hand
and by the ``macaulay2`` tests against the installed Macaulay2)."""
from __future__ import annotations


import pytest

from mech import Session
from tests.util import m2_case_tests

#: (name, script, what Macaulay2 prints)
CASES = [
    ("primary_component", """R = ZZ/101[x,y];
I = ideal(x^2, x*y);
print toString primaryComponent(I, ideal(x))
print toString primaryComponent(I, ideal(x,y))
R = ZZ/31991[x,y,z];
J = ideal(x*y^2, x*z^2);
print toString primaryComponent(J, ideal(y,z))
print toString primaryDecomposition(J, Strategy => EisenbudHunekeVasconcelos)
R = ZZ/101[x,y,z];
S = R/ideal(x^2, x*y);
print toString primaryDecomposition(ideal(0_S), Strategy => EisenbudHunekeVasconcelos)
""",
     'ideal x\nideal(y^2,x*y,x^2)\nideal(z^2,y^2)\n{ideal x, ideal(z^2,y^2)}\n{ideal x, ideal y^2}\n'),
    ("monomial_decomposition", """R = QQ[a..g];
I = ideal(a*b*c^3, a^3*d*f^2, a*b*c*d*e, b*c^4*d^3, e*f^5);
C = primaryDecomposition I;
print toString C
print toString associatedPrimes I
print toString primaryDecomposition ideal(a^2*b, a*b^3)
""",
     '{ideal(b,f^2), ideal(c,f^2), ideal(e,b,a^3), ideal(b,a^3,f^5), ideal(e,a^3,c^4,a*c^3), ideal(a*c,a^3,c^4,f^5), ideal(e,a,d^3), ideal(a,d^3,f^5), ideal(e,d,b), ideal(d,b,f^5), ideal(e,d,c^3), ideal(d,c^3,f^5), ideal(e,f^2,c^3)}\n{ideal(f,b), ideal(f,c), ideal(e,b,a), ideal(f,b,a), ideal(e,c,a), ideal(f,c,a), ideal(e,d,a), ideal(f,d,a), ideal(e,d,b), ideal(f,d,b), ideal(e,d,c), ideal(f,d,c), ideal(f,e,c)}\n{ideal a, ideal b, ideal(a^2,b^3)}\n'),
    ("quotient_ring_data", """R = ZZ/101[a..d];
S = R/(a*b-c^2);
T = S/(a^3, b^3);
print toString presentation T
print toString ring presentation T
print toString ambient T
print toString describe R
print toString describe S
U = QQ[t][u,v];
print toString describe U
""",
     'matrix {{a^3, b^3, a*b-c^2}}\nR\nS\n(ZZ/101)[a..d, Degrees => {4:1}, Heft => {1}]\nR/(a*b-c^2)\n(QQ[t])[u..v, Degrees => {2:1}, Heft => {1}]\n'),
    ("iterators", """it = iterator {1,2,3};
print toString next it
print toString toSequence it
print toString next it
s = select("foo", i -> i == "o");
print toString toList s
a = apply(iterator "foo", toUpper);
print toString next a
print toString join({1}, iterator {4, 5})
print toString apply("foo", "bar", concatenate)
print toString select(10, odd)
print toString position({10,20,43,105,6,93}, odd, Reverse => true)
print toString position((10,20,43),(18,82,12), (a,b) -> a>b)
""",
     '1\n(2,3)\nStopIteration\n{o, o}\nF\n{1, 4, 5}\n(fb,oa,or)\n{1, 3, 5, 7, 9}\n5\n2\n'),
    ("symmetric_power_and_radical_containment", """R = ZZ/32003[a..f];
print toString symmetricPower(2, matrix{{a,b,c}})
print toString symmetricPower(3, matrix{{c,a}})
F = map(R, R, symmetricPower(2, matrix{{a,b,c}}));
I = ker F;
print toString radicalContainment(I_0, I^2)
print toString radicalContainment(I_0 - a^2, I^2)
print toString radicalContainment(ideal(b, I_0), I^2)
""",
     'matrix {{a^2, a*b, a*c, b^2, b*c, c^2}}\nmatrix {{c^3, a*c^2, a^2*c, a^3}}\ntrue\nfalse\n0\n'),
    ("matrices_flatten_by_columns", """R = ZZ/101[a..f];
print toString ideal matrix{{a,b},{c,d},{e,f}}
print toString diff(matrix{{a,b},{c,a}}, matrix{{a^2*b, b*c},{a*c^2, a^3*b^2*c}})
S = R/(a^3, b^3);
print toString topComponents ideal(a^2*c, a*d)
print toString removeLowestDimension ideal(a^2*c, a*d)
""",
     'ideal(a,c,e,b,d,f)\nmatrix {{2*a*b, 0, a^2, c}, {c^2, 3*a^2*b^2*c, 0, 2*a^3*b*c}, {0, b, 2*a*b, 0}, '
     '{2*a*c, a^3*b^2, c^2, 3*a^2*b^2*c}}\nideal a\nideal(a*d,a^2)\n'),
    ("quotients_in_quotient_rings", """R = ZZ/101[vars(0..3)]/(a*d);
I2 = ideal(a^3);
print toString quotient(I2, ideal(a^3, b*d))
print toString (I2 : ideal(a))
print toString quotient(I2, d)
print toString saturate(ideal(b*d^2), a)
""",
     'ideal a\nideal(d,a^2)\nideal a\nideal d\n'),
    ("factor_over_zz", """R = ZZ[x,y,z];
d = factor((x - 2^32*y) * (x + 2^33*z - 77*y));
print toString d
print(#d)
print toString factor(6*x^2-6)
print(#factor(6*x^2-6))
S = QQ[t];
print toString factor(t/2+1)
print toString value factor(t/2+1)
""",
     '(x-4294967296*y)*(x-77*y+8589934592*z)\n2\n(x-1)*(x+1)*(6)\n3\n(t+2)*(1/2)\n(1/2)*t+1\n'),
    ("minors_and_vars", """R = ZZ[a..f];
M = matrix{{a,b,c},{d,e,f}};
print toString minors(2, M, Limit => 1)
print toString minors(0, M)
print toString vars(-3..-1)
print toString vars(3 .. 5, 51 .. 53)
""",
     'ideal(-b*d+a*e)\nideal 1\n(X3,X2,X1)\n(d,e,f,Z,x0,x1)\n'),
    ("ring_maps", """R = QQ[a,b,c]; S = QQ[s,t];
F = map(S,R,{s^3-t^2, s^3-t, s-t});
print toString F.matrix
print toString preimage(F, ideal(s-3))
G = map(R,R,{a=>b*c,b=>a*c,c=>a*b});
print toString(G*G)
print isInjective G
print toString coimage G
print toString coimage map(S,R,{s,s,t})
""",
     'matrix {{s^3-t^2, s^3-t, s-t}}\nideal(b-c-24,c^2+a-6*c-18)\nmap(R,R,{a^2*b*c, a*b^2*c, a*b*c^2})\ntrue\nR\n'
     'R/(a-b)\n'),
    ("ring_map_from_a_matrix_and_identity", """R = QQ[a..d];
S = QQ[s,t];
F = map(R, matrix{{s^4,s^3*t,s*t^3,t^4}});
print toString F
print toString kernel F
print(map(S,S) === id_S)
print(map(S,S,{t,s}) === id_S)
""",
     'map(S,R,{s^4, s^3*t, s*t^3, t^4})\nideal(b*c-a*d,c^3-b*d^2,a*c^2-b^2*d,b^3-a^2*c)\ntrue\nfalse\n'),
    ("lift_substitute_singular_locus", """R = ZZ/101[a..d];
S = R/(a*b-c^2);
T = S/(a^3, b^3);
J1 = lift(ideal c, R);
print toString J1
J1 = J1 + ideal(R_3^5);
print toString trim substitute(J1, T)
print toString lift(c^2+a*b, R)
U = QQ[x,y]/(x^2-y^3);
print toString singularLocus U
""",
     'ideal(c,a^3,b^3,a*b-c^2)\nideal(c,d^5)\n2*c^2\nQQ[x..y]/(-y^3+x^2,2*x,-3*y^2)\n'),
    ("hilbert_samuel", """R = QQ[x,y,z];
RP = localRing(R, ideal gens R);
M = RP^1/ideal(x^5+y^3+z^3,x^3+y^5+z^3,x^3+y^3+z^5);
print toString hilbertSamuelFunction(M, 0, 6)
print toString (hilbertSamuelFunction(max ring M, M, 0, 6) // sum)
R = ZZ/32003[x,y];
RP = localRing(R, ideal gens R);
print toString hilbertSamuelFunction(ideal(x^2,y^3), RP^1, 0, 3)
print toString hilbertSamuelFunction(RP^1, 4)
""",
     '{1, 3, 6, 7, 6, 3, 1}\n27\n{6, 12, 18, 24}\n5\n'),
]


def run(code: str) -> str:
    return Session(dialect="m2").execute(code)


test_cases, test_cases_are_macaulay2s = m2_case_tests(CASES, prelude='needsPackage "LocalRings"\n')


def test_unnamed_iterator_and_errors() -> None:
    """An iterator prints by the name it was given; what mech lacks is refused by name."""
    from mech.dsl.errors import MechError
    assert run("it = iterator {1}\nit\niterator {2}") == "o1 = it\no2 = it\no3 = -*Function*-\n"
    assert run("toList join(iterator {1}, {2})") == "o1 = {1, 2}\n"  # an iterator first: an iterator
    for code, message in [("R = QQ[a,b,MonomialOrder=>Lex]; describe R", "describe is supported for"),
                          ("R = QQ[x]; ambient R", "not a quotient ring")]:
        with pytest.raises(MechError) as e:
            run(code)
        assert message in e.value.format()
