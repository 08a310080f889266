"""Values that interoperate with Python: sympy (``_sympy_``), numbers as int/float/Fraction,
assignment from Fractions, floats and sympy numbers, ideals compared as ideals, indexing from 0,
LaTeX for notebooks, a Session as a context manager, short errors."""
import math
import operator
import traceback
from fractions import Fraction

import pytest
import sympy

from mech import MechError, MechSyntaxError, MechTypeError, Session

x, y, z = sympy.symbols("x y z")


@pytest.fixture
def s():
    ses = Session()
    ses.execute("ring r = 0,(x,y,z),dp; ideal I = x2-y, xy-z; poly f = 1/2x2y-3z+1; number n = 7/2;"
                "number m = -6; matrix M[2][2] = x,y,z,1;")
    return ses


def test_sympy_sees_polynomials_ideals_matrices_and_numbers(s):
    f = s["f"]
    assert sympy.sympify(f) == x**2 * y / 2 - 3 * z + 1
    assert sympy.Symbol("x") + f == x**2 * y / 2 - 3 * z + 1 + x      # sympy on the left calls _sympy_
    w = sympy.Symbol("w")                                               # on the right: Poly defers to sympy
    assert f + w == x**2 * y / 2 - 3 * z + 1 + w and f - w == x**2 * y / 2 - 3 * z + 1 - w
    assert w - f == w - (x**2 * y / 2 - 3 * z + 1)
    assert sympy.expand(f * sympy.Integer(2)) == x**2 * y - 6 * z + 2
    assert sympy.sympify(s["I"]) == sympy.Tuple(x**2 - y, x*y - z)
    assert s["I"].to_sympy_polys()[1] == sympy.Poly(x*y - z, x, y, z)
    assert sympy.sympify(s["M"]) == sympy.ImmutableMatrix([[x, y], [z, 1]])
    assert s["M"].to_sympy() == sympy.Matrix([[x, y], [z, 1]])
    assert sympy.sympify(s["n"]) == sympy.Rational(7, 2)


def test_numbers_as_python_numbers(s):
    n, m = s["n"], s["m"]
    assert (int(m), operator.index(m), float(n), Fraction(n)) == (-6, -6, 3.5, Fraction(7, 2))
    assert "abcdefg"[m] == "b" and math.isclose(math.sqrt(n), 3.5 ** 0.5)
    assert n.as_integer_ratio() == (7, 2) and n == Fraction(7, 2) and m == -6 and bool(m)
    with pytest.raises(MechTypeError, match="cannot convert the number 7/2 to an int"):
        int(n)
    p = Session()
    p.execute("ring r = 32003,(x),dp; number a = 32000;")
    assert int(p["a"]) == -3                                  # Singular's int(number): symmetric
    with pytest.raises(MechTypeError, match="Z/32003 to a float"):
        float(p["a"])
    q = Session()
    q.execute("ring r = (0,t),(x),dp; number a = t+1; number b = 3/4;")
    assert Fraction(q["b"]) == Fraction(3, 4)
    with pytest.raises(MechTypeError, match="depends on the parameters"):
        float(q["a"])


def test_assignment_from_fractions_floats_and_sympy_numbers(s):
    s["a"] = Fraction(1, 3)
    s["b"] = 0.1                                  # the float's exact binary value
    s["c"] = sympy.Rational(2, 7)
    s["d"] = sympy.Float(0.5)
    s["L"] = [Fraction(1, 2), y]
    assert s.execute("a; b; c; d; typeof(b); L;") == \
        "1/3\n3602879701896397/36028797018963968\n2/7\n1/2\nnumber\nL[1]=1/2\nL[2]=y\n"
    assert Fraction(s["b"]) == Fraction(0.1)
    s["n"] = 0.25                                 # an existing number variable
    assert s.execute("n;") == "1/4\n"
    for bad, why in [(float("nan"), "not finite"), (float("inf"), "not finite"), (1j, "complex")]:
        with pytest.raises(MechTypeError) as e:
            s["bad"] = bad
        assert why in str(e.value) or "cannot convert" in str(e.value)


def test_ideals_compare_as_ideals(s):
    I, G = s["I"], s.eval("std(I)")
    assert I == G and not I.same_generators(G)                  # other generators, the same ideal
    assert I != s.eval("ideal(x2-y)") and I != s.eval("ideal(x2-y, xy-z, z)")
    assert s.eval("ideal(0)") == s.eval("ideal(0, 0)")
    # the language's == stays Singular's: generator by generator, in lists too
    assert s.execute("ideal G = std(I); I == G; I == I; list(I) == list(G);") == "0\n1\n0\n"
    other = Session()
    other.execute("ring r = 0,(x,y,z),lp; ideal I = x2-y, xy-z;")
    assert I != other["I"]                                      # ideals of other rings differ


def test_len_iteration_and_indexing_from_zero(s):
    I, M = s["I"], s["M"]
    assert len(I) == 2 and [sympy.sympify(g) for g in I] == [x**2 - y, x*y - z]
    assert sympy.sympify(I[0]) == x**2 - y and sympy.sympify(I[-1]) == x*y - z   # I[1] in the language
    assert s.execute("I[1];") == "x2-y\n"
    assert M.shape == (2, 2) and sympy.sympify(M[1, 0]) == z and sympy.sympify(M[-1, -1]) == 1
    with pytest.raises(IndexError):
        M[2, 0]


def test_latex_of_values(s):
    assert s["f"]._repr_latex_() == r"$\frac{1}{2} x^{2} y - 3 z + 1$"
    assert s["I"]._repr_latex_() == r"$\left\langle x^{2} - y,\; x y - z \right\rangle$"
    assert s["M"]._repr_latex_() == r"$\begin{pmatrix} x & y \\ z & 1 \end{pmatrix}$"
    assert s["n"]._repr_latex_() == r"$\frac{7}{2}$" and s["m"]._repr_latex_() == "$- 6$"
    p = Session()
    p.execute("ring r = (0,a),(x(1..2)),dp; poly g = (a2-1)/3*x(1)^2 - a*x(2);")
    assert p["g"]._repr_latex_() == r"$\left(\frac{a^{2}}{3} - \frac{1}{3}\right) x_{1}^{2} - a x_{2}$"


def test_session_is_a_context_manager_with_settings():
    with Session(report_format="json") as s:
        assert s.settings["report_format"] == "json" and s.settings["engine"] == "auto"
        s.execute("int k = 3;")
        assert "k" in s
    assert "k" not in s                              # closed: a fresh session
    assert Session(engine="modular").settings["engine"] == "modular"   # read by the interpreter's engine switch


def test_errors_are_short():
    s = Session()
    with pytest.raises(MechSyntaxError) as e:
        s.execute("ring r = 0,(x),dp;\nideal I = x +* 1;")
    err = e.value
    assert len(traceback.extract_tb(err.__traceback__)) == 2 and err.__context__ is None  # the test, execute
    assert err._render_traceback_() == ["<string>:2:14: error: unexpected '*', expected an expression",
                                        "ideal I = x +* 1;", "             ^"]
    for bad in (lambda: s.eval("x +* 1"), lambda: s.eval("nothing"), lambda: s.__setitem__("f", sympy.Symbol("q"))):
        with pytest.raises(MechError) as e:
            bad()
        assert [f.name for f in traceback.extract_tb(e.value.__traceback__)][2:] in (["eval"], ["__setitem__"])


def test_echo_prints_as_it_runs(capsys):
    s = Session(echo=True)
    assert s.execute("1+1; 2+2;") == "2\n4\n"
    assert capsys.readouterr().out == "2\n4\n"


def test_display_gets_rich_bundles():
    shown = []
    s = Session(display=shown.append)
    assert s.execute('ring r = 0,(x,y),dp; ideal I = x2, y; I; 1+1; "text";') == "2\ntext\n"
    assert shown == [{"text/plain": "I[1]=x2\nI[2]=y\n", "text/latex": r"$\left\langle x^{2},\; y \right\rangle$"}]
