"""Rational function fields QQ(a,b,...) and Z/p(a,...): arithmetic, Singular's normal form and
printing, and Gröbner bases over them, against Singular 4.3.1."""
import random
import re
from fractions import Fraction

import flint
import pytest
from tests.util import SINGULAR, ideal_blocks, run_singular

from mech.kernel import Block, MonomialOrder, Poly, PolyRing
from mech.kernel.errors import DomainError
from mech.kernel.groebner import groebner
from mech.kernel.ratfunc import RatFunc, RationalFunctionField, format_coeff

singular = pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")


def parse(R, text):
    """A polynomial of ``R`` (a ring with parameters) from Singular's long form."""
    F = R.field
    scope = {n: g for n, g in zip(R.names, R.gens())}
    scope.update({p: F.gen(i) for i, p in enumerate(F.params)})
    scope["_N"] = lambda s: F(int(s))
    value = eval(re.sub(r"(?<![\w^])(\d+)", r"_N(\1)", text).replace("^", "**"),  # noqa: S307
                 {"__builtins__": {}}, scope)
    return value if isinstance(value, Poly) else R.const(value)


QAB = RationalFunctionField(0, "ab")


# (expression in a, b; Singular's short and long printing), from Singular 4.3.1 runs
PRINTED = [
    ("a", "(a)", "(a)"),
    ("2*a+1", "(2a+1)", "(2*a+1)"),
    ("-a/b", "(-a)/(b)", "(-a)/(b)"),
    ("(a**2-1)/(a+b)", "(a2-1)/(a+b)", "(a^2-1)/(a+b)"),
    ("a/2+b/3", "(3a+2b)/6", "(3*a+2*b)/6"),
    ("(a+1)**2", "(a2+2a+1)", "(a^2+2*a+1)"),
    ("a/2", "(a)/2", "(a)/2"),
    ("1/(2*a)", "1/(2a)", "1/(2*a)"),
    ("2/a", "2/(a)", "2/(a)"),
    ("-a", "(-a)", "(-a)"),
    ("(a+1)/(a-1)", "(a+1)/(a-1)", "(a+1)/(a-1)"),
    ("-1/(a+b)", "-1/(a+b)", "-1/(a+b)"),
    ("(a**2+b)/3", "(a2+b)/3", "(a^2+b)/3"),
    ("-(a**2+b)/3", "(-a2-b)/3", "(-a^2-b)/3"),
    ("2/(3*a)", "2/(3a)", "2/(3*a)"),
    ("QAB(3)/4", "3/4", "3/4"),
    ("-QAB(3)/4", "-3/4", "-3/4"),
    ("1/(1-a)", "-1/(a-1)", "-1/(a-1)"),
    ("1/(b-a)", "-1/(a-b)", "-1/(a-b)"),
    ("(2*a+4)/(6*b-2)", "(a+2)/(3b-1)", "(a+2)/(3*b-1)"),
    ("(a-1)/(1-a)", "-1", "-1"),
    ("(4*a**2-1)/(2*a+1)", "(2a-1)", "(2*a-1)"),
    ("(2*a)/(4*b)", "(a)/(2b)", "(a)/(2*b)"),
    ("(QAB(3)/2*a)/(b/4)", "(6a)/(b)", "(6*a)/(b)"),
    ("(a+1)/(-2)", "(-a-1)/2", "(-a-1)/2"),
    ("a+b**2", "(a+b2)", "(a+b^2)"),
    ("a**2*b+a*b**2+a+b+1", "(a2b+ab2+a+b+1)", "(a^2*b+a*b^2+a+b+1)"),
]


@pytest.mark.parametrize("expr,short,long", PRINTED)
def test_normal_form_and_printing(expr, short, long):
    a, b = QAB.gens()
    c = eval(expr, {"a": a, "b": b, "QAB": QAB})  # noqa: S307
    assert format_coeff(c) == short
    assert format_coeff(c, short=False) == long
    assert str(c) == short


def test_prime_characteristic_printing():
    F7 = RationalFunctionField(7, "a")
    (a,) = F7.gens()
    assert format_coeff(3 * a + 5) == "(3a-2)"       # symmetric coefficients
    assert format_coeff(a / 3) == "(-2a)"
    assert format_coeff((a + 4) / (2 * a - 1)) == "(-3a+2)/(a+3)"  # monic denominator
    F5 = RationalFunctionField(5, "ab")
    a, b = F5.gens()
    assert format_coeff((2 * a + b) / (3 * b + a)) == "2"
    assert format_coeff((2 * a + b) / (3 * b + 2)) == "(-a+2b)/(b-1)"
    F32003 = RationalFunctionField(32003, "ab")
    a, b = F32003.gens()
    assert format_coeff(16000 * a + b) == "(16000a+b)"


def test_long_names_print_long():
    T = RationalFunctionField(0, ["t1", "t2"])
    t1, t2 = T.gens()
    assert format_coeff(t1**2 * t2 + 3 * t2) == "(t1^2*t2+3*t2)"
    assert format_coeff(t1 / (2 * t2)) == "(t1)/(2*t2)"


def test_field_interface():
    a, b = QAB.gens()
    assert QAB.characteristic == 0 and QAB.zero == 0 and QAB.one == 1
    assert QAB("a") == a and QAB(Fraction(1, 2)) == QAB(1) / 2 == flint.fmpq(1, 2)
    assert QAB(a) is a
    assert QAB.to_fraction(QAB(3) / 4) == Fraction(3, 4)
    with pytest.raises(DomainError):
        QAB.to_fraction(a)
    with pytest.raises(DomainError):
        QAB("c")
    with pytest.raises(TypeError):
        QAB(RationalFunctionField(0, "a").gen(0))
    with pytest.raises(ZeroDivisionError):
        a / 0
    with pytest.raises(ZeroDivisionError):
        1 / QAB.zero
    c = (a + 1) / b
    assert c - c == 0 and c * (1 / c) == 1 and c / c == 1 and c**-2 * c**2 == 1
    assert (a + b) ** 2 == a * a + 2 * a * b + b * b
    assert 1 - c == -(c - 1) and 2 * c == c + c
    assert hash(QAB(2)) == hash(2) and {c: 1}[(a + 1) / b] == 1
    assert bool(QAB.zero) is False and bool(a)
    assert repr(QAB) == "QQ(a,b)" and repr(RationalFunctionField(7, "a")) == "GF(7)(a)"
    assert RationalFunctionField(0, "ab") == QAB != RationalFunctionField(0, "ba")
    F7 = RationalFunctionField(7, "a")
    assert F7(Fraction(1, 2)) == 4 and F7.to_fraction(F7(6)) == -1
    with pytest.raises(ZeroDivisionError):
        F7(Fraction(1, 7))
    with pytest.raises(DomainError):
        RationalFunctionField(4, "a")
    assert isinstance(a, RatFunc)


# Gröbner bases over parameter fields; Singular 4.3.1 with option(redSB)
GB_CASES = [
    ((0, "ab"), "xyz", "dp", "a*x^2+b*y-1, x*y-a*z, b*z^2-x",
     "(b)*z^2-x, (b)*y^2+(a^2)*x*z-y, x*y+(-a)*z, (a)*x^2+(b)*y-1"),
    ((0, "t"), "xy", "lp", "x^2+t*y, x*y-t", "y^3+(t), x+y^2"),
    ((7, "a"), "xy", "dp", "a*x^2+y-1, x*y-a", "y^2+(a^2)*x-y, x*y+(-a), (a)*x^2+y-1"),
]


@pytest.mark.parametrize("case", range(len(GB_CASES)))
def test_groebner_over_parameters(case):
    (char, params), names, kind, gens, basis = GB_CASES[case]
    R = PolyRing(RationalFunctionField(char, params), list(names), MonomialOrder([Block(kind, len(names))]))
    G = groebner([parse(R, t) for t in gens.split(",")])
    expected = sorted((parse(R, t).monic() for t in basis.split(",")), key=lambda p: R.order.key(p.lm()))
    assert G == expected


@singular
def test_random_printing_matches_singular():
    rng = random.Random(3)
    a, b = QAB.gens()
    values = []
    for _ in range(30):
        def poly():
            return sum((rng.randint(-4, 4) * a ** rng.randint(0, 2) * b ** rng.randint(0, 2)
                        for _ in range(rng.randint(1, 3))), QAB.zero)
        num, den = poly(), poly()
        values.append(num / den if den != 0 else num)
    script = "ring r=(0,a,b),(x,y),dp;\n" + "\n".join(
        f"number n{i} = {format_coeff(v, short=False)}; n{i}; string(n{i}*x);" for i, v in enumerate(values))
    script += "\nshort=0;\n" + "\n".join(f"n{i};" for i in range(len(values)))
    out = run_singular(script).splitlines()
    k = len(values)
    for i, v in enumerate(values):
        assert out[2 * i] == format_coeff(v)
        term = "x" if v == 1 else "-x" if v == -1 else f"{format_coeff(v)}*x"
        assert out[2 * i + 1] == (term if v != 0 else "0")
        assert out[2 * k + i] == format_coeff(v, short=False)


@singular
@pytest.mark.parametrize("char", [0, 32003])
def test_random_parameter_groebner_matches_singular(char):
    rng = random.Random(char + 1)
    F = RationalFunctionField(char, "ab")
    R = PolyRing(F, ["x", "y", "z"], MonomialOrder([Block("dp", 3)]))
    a, b = F.gens()
    coeffs = [a, b, a + 1, a - b, 2 * a * b, F(3), b**2 - 1, a / (b + 1)]
    for _ in range(3):
        gens = []
        for _ in range(3):
            f = R.zero()
            for _ in range(3):
                e = [rng.randint(0, 2) for _ in range(3)]
                f = f + R.monomial(e, rng.choice(coeffs))
            gens.append(f)
        text = ",".join(f.to_str() for f in gens)
        out = run_singular(f"option(redSB); ring r=({char},a,b),(x,y,z),dp; short=0; "
                           f"ideal I={text}; std(I);")
        expected = sorted((parse(R, t).monic() for t in ideal_blocks(out)[0]),
                          key=lambda p: R.order.key(p.lm()))
        assert groebner(gens) == expected, text

