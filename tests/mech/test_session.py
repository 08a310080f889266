"""The Python API: Session.execute / eval / item access, values to and from sympy, errors."""
import os
import signal
import threading
import time

import pytest
import sympy

from mech import MechError, MechNameError, MechSyntaxError, Session
from mech.dsl.limits import MechLimitError
from mech.dsl.values import Ideal, IntVec, List


@pytest.fixture
def s():
    ses = Session()
    ses.execute("ring r = 0,(x,y,z),dp; ideal I = x2-y, xy-z;")
    return ses


def test_execute_returns_printed_text(s):
    assert s.execute("std(I);") == "_[1]=y2-xz\n_[2]=xy-z\n_[3]=x2-y\n"
    assert s.execute("int k = 1;") == ""


def test_eval_returns_values(s):
    G = s.eval("std(I)")
    assert isinstance(G, Ideal) and len(G.gens) == 3
    x, y, z = sympy.symbols("x y z")
    assert G.to_sympy() == [y**2 - x*z, x*y - z, x**2 - y]
    assert s.eval("dim(std(I))") == 1
    assert s.eval("1, 2") == (1, 2)
    assert s.eval('"abc"') == "abc"
    assert s.eval("print(1)") is None


def test_items(s):
    x, y, z = sympy.symbols("x y z")
    s["f"] = x**3 + sympy.Rational(1, 2) * y
    assert s.execute("f; reduce(f, std(I));") == "x3+1/2y\n1/2y+z\n"
    s["I"] = "x2-y, xy-z, z"
    assert s.execute("I;") == "I[1]=x2-y\nI[2]=xy-z\nI[3]=z\n"
    s["n"] = 5
    s["name"] = "hello"
    s["J"] = [x, y**2]
    s["v"] = [1, 2, 3]
    assert s.execute("n; name; J; v; typeof(J); typeof(v);") == "5\nhello\nJ[1]=x\nJ[2]=y2\n1,2,3\nideal\nintvec\n"
    assert s["n"] == 5 and s["name"] == "hello" and isinstance(s["v"], IntVec)
    assert "I" in s and "nothing" not in s
    with pytest.raises(MechNameError):
        s["nothing"]
    s["n"] = 7
    assert s.eval("n + 1") == 8
    s["L"] = [1, "a"]
    assert isinstance(s["L"], List)


def test_errors_carry_position(s):
    with pytest.raises(MechNameError) as info:
        s.execute("int k = 1;\nk = k + q;")
    e = info.value
    assert (e.line, e.column) == (2, 9) and isinstance(e, MechError)
    with pytest.raises(MechSyntaxError):
        s.eval("1 +")
    with pytest.raises(MechError):
        s["f"] = sympy.Symbol("w")  # not a ring variable


def test_sessions_are_independent():
    a, b = Session(), Session()
    a.execute("int i = 1;")
    with pytest.raises(MechNameError):
        b.execute("i;")


def test_package_docstring_example():
    """The example in mech/__init__.py's docstring runs and gives the values its comments show."""
    import mech
    env: dict = {}
    for line in mech.__doc__.split("::\n", 1)[1].splitlines():
        code, _, comment = line.strip().partition("  # ")
        if not code:
            continue
        shown = comment.rsplit(": ", 1)[-1].strip()
        if shown.startswith(("'", "[")):
            assert repr(eval(code, env)) == shown, code
        else:
            exec(code, env)


def test_sympy_both_ways_with_parameters_matrices_and_numbers():
    from mech import to_sympy
    a, x, y = sympy.symbols("a x y")
    s = Session()
    s.execute("ring q = (0,a),(x,y),dp; poly g = a*x + 1/a*y + (a+1)/(a-1); matrix M[2][2] = x, a, 1, y;")
    g = to_sympy(s["g"])
    assert sympy.simplify(g - (a*x + y/a + (a + 1)/(a - 1))) == 0
    assert to_sympy(s["M"]) == sympy.Matrix([[x, a], [1, y]])
    s["h"] = g * x                                   # and back: coefficients rational in the parameter
    assert s.execute("h - g*x; typeof(h);") == "0\npoly\n"
    s["N"] = sympy.Matrix([[x, 1], [a, y**2]])
    assert s.execute("print(N); typeof(N);") == "x,  1,\n(a),y2\nmatrix\n"
    s["c"] = sympy.Rational(3, 4)
    assert s.execute("c; typeof(c);") == "3/4\nnumber\n"
    s.execute("ring p = 32003,(x,y),dp; poly f = 16002x + 3;")
    assert to_sympy(s["f"]) == 3 - 16001*x          # Z/p: Singular's symmetric representatives
    with pytest.raises(MechError, match="not a variable"):
        s["e"] = a * x                              # no parameter a in this ring


# ---------------------------------------------------------------- one long python-flint call
LONG = "poly f = (x+y+z+1)^1500;"   # one call into python-flint of several minutes and gigabytes


def started(**limits):
    s = Session(**limits)
    s.execute("ring r = 0,(x,y,z),dp; int k = 7;")
    return s, time.monotonic()


def still_usable(s):
    assert s.execute("k; defined(f); (x+y)^2;") == "7\n0\nx2+2xy+y2\n"


def test_a_time_limit_stops_one_long_flint_call():
    s, t = started(timeout=2)
    with pytest.raises(MechLimitError) as info:
        s.execute(LONG)
    assert time.monotonic() - t < 30            # 2 s, a few on a busy machine
    assert info.value.format().startswith("<string>:1:1: error: time limit of 2 s exceeded\n")
    still_usable(s)


def test_a_memory_limit_stops_one_long_flint_call():
    s, t = started(max_memory=200)
    with pytest.raises(MechLimitError) as info:
        s.execute(LONG)
    assert info.value.format().startswith("<string>:1:10: error: memory limit of 200 MB exceeded\n")
    still_usable(s)


def test_ctrl_c_stops_one_long_flint_call():
    s, t = started()
    threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT)).start()
    with pytest.raises(KeyboardInterrupt):
        s.execute(LONG)
    assert time.monotonic() - t < 30
    still_usable(s)


def test_a_time_limit_stops_a_long_factorization():
    s, _ = started()
    s.execute("poly g = (x+y+z+1)^60*(x-2y+3z+5)^60+1;")   # flint needs over 35 s to factor it (idle machine)
    t = time.monotonic()
    with pytest.raises(MechLimitError) as info:
        s.execute('limits("timeout", 2); list L = factorize(g);')
    assert time.monotonic() - t < 30
    assert info.value.message == "time limit of 2 s exceeded in factorize"
    assert s.execute("k; defined(L);") == "7\n0\n"


def test_a_time_limit_stops_a_long_real_root_isolation():
    """The squarefree decomposition of real-root isolation: one flint call (minutes here)."""
    s, _ = started()
    s.execute("ring r1 = 0,x,dp; poly p = (x^6000+7^6000*x+1)^2*(x^5999-3x+5);")
    t = time.monotonic()
    with pytest.raises(MechLimitError) as info:
        s.execute('limits("timeout", 2); list L = realRoots(p);')
    assert time.monotonic() - t < 30
    assert info.value.message == "time limit of 2 s exceeded in realRoots"
    assert s.execute("k; defined(L); deg(p);") == "7\n0\n17999\n"
