"""Ideal operations: elimination (the paper's eliminants), intersections, quotients, saturations,
sums, products, powers, containment and radicals, against Singular 4.3.1 (hard-coded truths and
live differential runs)."""
import random
import re

import pytest
from tests.util import SINGULAR, parse_poly, run_singular

from mech.kernel import GF, QQ, Block, MonomialOrder, PolyRing
from mech.kernel.groebner import groebner
from mech.kernel.ideals import (dimension, eliminate, ideal_power, ideal_product, ideal_sum,
                                ideals_equal, intersect, is_subset, quotient, saturate)
from mech.kernel.primdec import radical

XYZ = PolyRing(QQ, "xyz", MonomialOrder.simple("dp", 3))


def ideal(R, *texts):
    return [parse_poly(R, t) for t in texts]


def same(a, b, R):
    return groebner(a, R) == groebner(b, R)


# --- elimination ------------------------------------------------------------------------

def test_twisted_cubic():
    R = PolyRing(QQ, "txyz", MonomialOrder.simple("dp", 4))
    t, x, y, z = R.gens()
    E = eliminate([x - t, y - t ** 2, z - t ** 3], [0])
    assert E == groebner([x ** 2 - y, x * y - z, y ** 2 - x * z], R)
    # lex ring: the ordering is already an elimination ordering for t
    L = PolyRing(QQ, "txyz", MonomialOrder.simple("lp", 4))
    t, x, y, z = L.gens()
    assert eliminate([x - t, y - t ** 2, z - t ** 3], [0]) == groebner([y - x ** 2, z - x ** 3], L)
    # eliminating the last variables of a dp ring (not an elimination ordering there)
    R2 = PolyRing(QQ, "xyzt", MonomialOrder.simple("dp", 4))
    x, y, z, t = R2.gens()
    assert eliminate([x - t, y - t ** 2, z - t ** 3], [3]) == groebner([x ** 2 - y, x * y - z, y ** 2 - x * z], R2)
    assert eliminate([x - t, y - t ** 2, z - t ** 3], [0, 3]) == groebner([y ** 3 - z ** 2], R2)


def paper_ring(n):
    names = [f"{v}{i}" for i in range(1, n + 1) for v in "cs"] + [f"l{i}" for i in range(1, n + 1)]
    return PolyRing(QQ, names, MonomialOrder([Block("dp", 2 * n), Block("dp", n)]))


def test_slider2_eliminant():
    R = PolyRing(QQ, "c1 s1 c2 s2 l1 l2".split(), MonomialOrder([Block("dp", 4), Block("dp", 2)]))
    c1, s1, c2, s2, l1, l2 = R.gens()
    S = [l1 * s1 + l2 * s2, c1 ** 2 + s1 ** 2 - 1, c2 ** 2 + s2 ** 2 - 1, c1, c2]
    assert eliminate(S, range(4)) == [l1 ** 2 - l2 ** 2]


def test_slider3_eliminant():
    R = paper_ring(3)
    c1, s1, c2, s2, c3, s3, l1, l2, l3 = R.gens()
    S = [l1 * s1 + l2 * s2 + l3 * s3, c1 ** 2 + s1 ** 2 - 1, c2 ** 2 + s2 ** 2 - 1,
         c3 ** 2 + s3 ** 2 - 1, c1, c2, c3]
    E = eliminate(S, range(6))
    assert E == ideal(R, "l1^4-2*l1^2*l2^2+l2^4-2*l1^2*l3^2-2*l2^2*l3^2+l3^4")


def test_fourbar_eliminant():
    R = paper_ring(3)
    c1, s1, c2, s2, c3, s3, l1, l2, l3 = R.gens()
    S = [l1 * c1 + l2 * c2 + l3 * c3 - 1, l1 * s1 + l2 * s2 + l3 * s3, c1 ** 2 + s1 ** 2 - 1,
         c2 ** 2 + s2 ** 2 - 1, c3 ** 2 + s3 ** 2 - 1,
         -s2 * c3 + c2 * s3, -s1 * c3 + c1 * s3, -s1 * c2 + c1 * s2]
    E = eliminate(S, range(6))
    assert len(E) == 1
    expected = 1
    for a in (1, -1):
        for b in (1, -1):
            for c in (1, -1):
                expected = expected * (l1 + a * l2 + b * l3 + c)
    assert E == [expected]
    assert E[0].total_degree() == 8


# --- quotients, intersections, saturations (truths from Singular 4.3.1) ----------------

def test_monomial_quotient_intersection_saturation():
    R = XYZ
    I = ideal(R, "x^2*y", "x*y^3", "z^3")
    J = ideal(R, "x*y", "z")
    assert quotient(I, J) == groebner(ideal(R, "z^3", "x*z^2", "x^2*y", "y^2*z^2", "x*y^3"), R)
    assert intersect(I, J) == groebner(ideal(R, "z^3", "x^2*y", "x*y^3"), R)
    assert saturate(I, J) == ([R.one()], 4)
    x, y, z = R.gens()
    assert saturate([x ** 2 * y, x * y ** 3], [x]) == ([y], 2)
    assert saturate([x ** 2 * y, x * y ** 3], [y]) == ([x], 3)
    assert saturate([x ** 2 * y, x * y ** 3], [x, y]) == ([x * y], 2)
    assert saturate([x * y], [z]) == ([x * y], 0)
    assert saturate([x ** 2, x * y], [x, y]) == ([x], 1)
    assert saturate([x ** 2, x * y], [R.one()]) == (groebner([x ** 2, x * y]), 0)
    assert saturate([x ** 2, x * y], [x]) == ([R.one()], 2)
    assert saturate([x ** 3 * y ** 2, y ** 5], [y]) == ([R.one()], 5)
    assert intersect([x], [y], [z]) == [x * y * z]
    big = intersect([z], [x, y], [x ** 2, z ** 2], [x ** 5, y ** 5, z ** 5])
    assert big == groebner([y * z ** 5, x * z ** 5, x ** 5 * z, y ** 5 * z ** 2, x ** 2 * y ** 5 * z], R)


def test_nonmonomial_quotient_intersection_saturation():
    R = XYZ
    I2 = ideal(R, "x^2-y*z", "x*y-z^2", "y^3-x*z^2")
    J2 = ideal(R, "x-y", "z-1")
    assert quotient(I2, J2) == groebner(ideal(
        R, "x*y-z^2", "x^2-y*z", "y^2*z-x*z^2", "y^3-x*z^2", "y*z^3-z^4", "x*z^3-z^4"), R)
    assert intersect(I2, J2) == groebner(ideal(
        R, "y^2*z-x*z^2-x^2+y*z", "x*y*z-z^3-x*y+z^2", "x^2*z-y*z^2-x^2+y*z",
        "x*y^2-y^3+x*z^2-y*z^2", "x^2*y-y^3", "x^3-y^3+x*z^2-z^3+x^2-x*y-y*z+z^2",
        "y*z^3-z^4+x^2-x*y-y*z+z^2", "x*z^3-z^4+x^2-x*y-y*z+z^2"), R)
    assert saturate(I2, ideal(R, "x")) == (groebner(ideal(R, "y-z", "x-z"), R), 3)
    I3 = ideal(R, "(x^2+y^2-1)*(x-z)", "(x^2+y^2-1)*(y+z)", "x^3*y-z")
    f = ideal(R, "x^2+y^2-1")
    truth = groebner(ideal(R, "y+z", "x-z", "z^4+z"), R)
    assert quotient(I3, f) == truth
    assert saturate(I3, f) == (truth, 1)
    assert intersect(ideal(R, "x^2-y"), ideal(R, "y^2-z"), ideal(R, "x*z-1")) == groebner(ideal(
        R, "x^3*y^2*z-x*y^3*z-x^3*z^2-x^2*y^2+x*y*z^2+y^3+x^2*z-y*z"), R)
    assert saturate(ideal(R, "x^3*y^2*z", "x*y^4-z^3", "x^5"), ideal(R, "x", "y")) == (groebner(ideal(
        R, "x^3*z", "x^4", "x*y^4-z^3", "x^2*z^4", "x*z^7", "z^10"), R), 6)


def test_edge_cases():
    R = XYZ
    x, y, z = R.gens()
    assert quotient([x], [R.zero()], ring=R) == [R.one()]
    assert quotient([], [x], ring=R) == []
    assert intersect([], [x], ring=R) == []
    assert intersect([R.one()], [x, y]) == [y, x]
    assert saturate([x * y], [R.zero()]) == ([R.one()], 1)
    assert eliminate([], [0], ring=R) == []
    assert ideal_sum([x], [], ring=R) == [x]


# --- arithmetic and comparison ---------------------------------------------------------

def test_sum_product_power_subset_equal():
    R = XYZ
    x, y, z = R.gens()
    assert ideal_sum([x * y], [x - z]) == groebner([x * y, x - z])
    assert ideal_product([x, y], [x, z]) == groebner([x * x, x * z, x * y, y * z])
    assert ideal_power([x, y], 3) == groebner([x ** 3, x ** 2 * y, x * y ** 2, y ** 3])
    assert ideal_power([x, y], 0) == [R.one()]
    assert is_subset([x * y, x ** 2], [x])
    assert not is_subset([x, y], [x * y])
    assert ideals_equal([x + y, x - y], [x, y])
    assert not ideals_equal([x], [x, y])
    assert dimension([x * y, x * z]) == 2
    assert dimension([R.one()]) == -1


def test_radical():
    R = XYZ
    x, y, z = R.gens()
    assert radical([x ** 2 * y, x * y ** 3]) == [x * y]
    assert radical([(x ** 2 - 2) ** 2, y ** 3]) == groebner([x ** 2 - 2, y])
    assert radical([x ** 3 - y ** 2, z ** 2]) == groebner([x ** 3 - y ** 2, z])
    assert radical([x ** 2, x * y]) == [x]
    assert radical([R.one()]) == [R.one()]
    F = PolyRing(GF(32003), "xy", MonomialOrder.simple("dp", 2))
    u, v = F.gens()
    assert radical([u ** 3 - v ** 3, (u - v) ** 2]) == groebner([u - v])


# --- live differential tests -------------------------------------------------------------

def random_ideal(R, rng, gens=2, terms=3, deg=3):
    out = []
    for _ in range(gens):
        p = R.zero()
        for _ in range(terms):
            e = [rng.randint(0, deg) for _ in range(R.nvars)]
            while sum(e) > deg:
                e[rng.randrange(R.nvars)] = 0
            p = p + R.monomial(tuple(e), rng.randint(-3, 3) or 1)
        out.append(p)
    return [p for p in out if not p.is_zero()]


def sections(output):
    """Singular output split at the lines ``@`` printed between results."""
    return [s.strip() for s in output.split("@\n")[1:]]


def parse_ideal(R, text):
    polys = [parse_poly(R, m) for m in re.findall(r"^\s*_\[\d+\]=(.*)$", text, re.M)]
    return [p for p in polys if not p.is_zero()]


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
@pytest.mark.parametrize("char", [0, 32003])
def test_live_singular_ideal_operations(char):
    rng = random.Random(11 + char)
    R = PolyRing(QQ if char == 0 else GF(char), "xyz", MonomialOrder.simple("dp", 3))
    cases = [(random_ideal(R, rng), random_ideal(R, rng, gens=1, terms=2, deg=2)) for _ in range(4)]
    script = f'LIB "elim.lib"; LIB "primdec.lib"; ring r = {char},(x,y,z),dp; short = 0; list s;\n'
    for I, J in cases:
        i = ",".join(p.to_str() for p in I)
        j = ",".join(p.to_str() for p in J)
        script += (f'ideal I = {i}; ideal J = {j};\n"@"; std(intersect(I, J));\n"@"; std(quotient(I, J));\n'
                   f'"@"; s = sat(I, J); std(s[1]);\n"@"; s[2];\n"@"; std(eliminate(I, x));\n'
                   f'"@"; std(radical(I));\n')
    out = sections(run_singular(script))
    assert len(out) == 6 * len(cases)
    for k, (I, J) in enumerate(cases):
        got = out[6 * k:6 * k + 6]
        assert intersect(I, J) == groebner(parse_ideal(R, got[0]), R)
        assert quotient(I, J) == groebner(parse_ideal(R, got[1]), R)
        sat, exp = saturate(I, J)
        assert sat == groebner(parse_ideal(R, got[2]), R)
        assert exp == int(got[3])
        assert eliminate(I, [0]) == groebner(parse_ideal(R, got[4]), R)
        assert radical(I) == groebner(parse_ideal(R, got[5]), R)
