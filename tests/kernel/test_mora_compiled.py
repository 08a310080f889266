"""Mora's loop compiled (kernel/_mora.c through kernel/mora_compiled.py) against the pure-Python
loop of kernel/mora.py: the same bases term by term and the same number of reduction steps."""
import pytest
from tests.util import parse_poly

from mech.kernel import GF, Block, MonomialOrder, PolyRing
from mech.kernel import mora_compiled
from mech.kernel.mora import Budget, mora

pytestmark = pytest.mark.skipif(mora_compiled.C is None, reason="the C extension _mora is not built")

F5 = "x*y*z*(x+y+z)^2+(x+y+z)^3+x^7+y^7+z^7"
SYSTEMS = [
    ("x,y,z", ["x^2*y+z^3+x^5", "y^3+x*z^2+y^6", "z^4+x*y*z+x^7"]),
    ("x,y,z", ["x^2+y^2+z^2", "x*y*z", "x^3+y^3"]),
    ("x,y,z", [F5, "2*x*y*z*(x+y+z)+x^2*y+3*(x+y+z)^2+7*x^6+y*(x+y+z)^2*z"]),
    ("a,b,c,d", ["a^2+b*c*d+a^5", "b^3-c^2+a*d^4", "c*d+a^3*b", "d^4+a*b*c"]),
    ("x,y", ["x^3+y^2+x^4*y", "x*y^3+y^5"]),
]


def _run(names, polys, compiled, monkeypatch):
    if not compiled:
        monkeypatch.setattr(mora_compiled, "C", None)
    R = PolyRing(GF(32003), names.split(","), MonomialOrder([Block("ds", len(names.split(",")))]))
    assert mora_compiled.CompiledMora.usable(R) == compiled
    budget = Budget(10**6)
    basis = mora([parse_poly(R, p) for p in polys], R, budget, shared=True)
    return basis, budget.steps


@pytest.mark.parametrize("names,polys", SYSTEMS)
def test_compiled_loop_is_the_python_loop(names, polys, monkeypatch):
    with monkeypatch.context() as m:
        python = _run(names, polys, False, m)
    compiled = _run(names, polys, True, monkeypatch)
    assert compiled == python
    assert python[1] < 10**6  # some reduction happened


def test_pack_round_trip():
    terms = [((3, 0, 2), 5), ((0, 1, 0), 7), ((1, 1, 1), 32002)]
    b = mora_compiled.C.pack(3, terms)
    out = mora_compiled.C.unpack(3, b)
    assert sorted(out) == sorted(terms)
    assert out[0][0] == (0, 1, 0)  # ds: the lowest degree leads
