"""Minimal associated primes, primary decompositions, radicals and equidimensional parts: the
paper's decompositions (reference runs of Singular 4.3.1), embedded and non-reduced components,
components of different dimensions, parameters, Z/p, and live comparisons with Singular."""
import itertools
import re
from fractions import Fraction

import pytest
from tests.util import SINGULAR, run_singular

from mech.kernel import GF, QQ, Block, MonomialOrder, PolyRing
from mech.kernel.groebner import groebner
from mech.kernel.ideals import dimension, intersect
from mech.kernel.primdec import (equi_radical, equidim, equidim_max, is_primary, is_prime,
                                 min_ass_char, min_ass_gtz, primdec_gtz, primdec_sy, radical)


# --- helpers shared with test_primdec_random.py --------------------------------------------

def det(rows):
    """Determinant by Laplace expansion along the first row."""
    if len(rows) == 1:
        return rows[0][0]
    total = rows[0][0].ring.zero()
    for j, a in enumerate(rows[0]):
        if not a.is_zero():
            term = a * det([r[:j] + r[j + 1:] for r in rows[1:]])
            total = total + term if j % 2 == 0 else total - term
    return total


def fitting_ideal(gens, variables):
    """The ideal of the maximal minors of the Jacobian matrix w.r.t. the variables (indices)."""
    jac = [[g.diff(v) for v in variables] for g in gens]
    k = len(gens)
    minors = [det([[row[c] for c in cols] for row in jac]) for cols in itertools.combinations(range(len(variables)), k)]
    return [m for m in minors if not m.is_zero()]


def as_set(ideals, R):
    return {tuple(groebner(i, R)) for i in ideals}


def check_decomposition(I, comps, R):
    """The primaries intersect to I, the primes are distinct radicals of the primaries."""
    assert intersect(*[q for q, _ in comps], ring=R) == groebner(I, R)
    primes = [tuple(p) for _, p in comps]
    assert len(set(primes)) == len(primes)
    for q, p in comps:
        assert radical(q, R) == p


def sections(output):
    return [s.strip() for s in output.split("@\n")[1:]]


def parse(R, text):
    """A polynomial from Singular's long form, rational coefficients included."""
    expr = re.sub(r"(\d+)/(\d+)", r"_q(\1,\2)", text.replace("^", "**"))
    scope = dict(zip(R.names, R.gens()), _q=lambda a, b: R.const(Fraction(a, b)))
    value = eval(expr, {"__builtins__": {}}, scope)  # noqa: S307 - test data only
    return value if not isinstance(value, int) else R.const(value)


def parse_ideal(R, text):
    polys = [parse(R, m) for m in re.findall(r"^\s*_\[\d+\]=(.*)$", text, re.M)]
    return [p for p in polys if not p.is_zero()]


def singular_ring(R, ordering):
    char = R.field.characteristic
    return f'LIB "primdec.lib"; ring r = {char},({",".join(R.names)}),{ordering}; short = 0; int k;\n'


def singular_decompositions(R, ordering, I):
    """Singular's minAssGTZ(I) and primdecGTZ(I): (primes, [(primary, prime)])."""
    gens = ",".join(p.to_str() for p in I)
    script = singular_ring(R, ordering) + (
        f"ideal I = {gens}; list L = minAssGTZ(I); list P = primdecGTZ(I);\n"
        '"@"; size(L); for (k = 1; k <= size(L); k++) { "@"; L[k]; }\n'
        '"@"; size(P); for (k = 1; k <= size(P); k++) { "@"; P[k][1]; "@"; P[k][2]; }\n')
    out = sections(run_singular(script))
    n = int(out[0])
    primes = [parse_ideal(R, t) for t in out[1:1 + n]]
    m = int(out[1 + n])
    rest = out[2 + n:]
    comps = [(parse_ideal(R, rest[2 * i]), parse_ideal(R, rest[2 * i + 1])) for i in range(m)]
    return primes, comps


def singular_checks(R, ordering, comps):
    """For each (Q, P): Singular's number of primary components of Q and std(radical(Q))."""
    script = singular_ring(R, ordering)
    for q, _ in comps:
        script += f'ideal Q = {",".join(p.to_str() for p in q)};\n"@"; size(primdecGTZ(Q)); "@"; std(radical(Q));\n'
    out = sections(run_singular(script))
    return [(int(out[2 * i]), parse_ideal(R, out[2 * i + 1])) for i in range(len(comps))]


def compare_with_singular(R, ordering, I):
    """Our minimal primes and primary decompositions (GTZ and SY) against Singular's: equal sets of
    primes, equal isolated components, Singular certifies every primary and its radical."""
    primes, comps = singular_decompositions(R, ordering, I)
    assert as_set(min_ass_gtz(I, R), R) == as_set(primes, R)
    assert as_set(min_ass_char(I, R), R) == as_set(primes, R)
    isolated = {tuple(groebner(p, R)): tuple(groebner(q, R)) for q, p in comps
                if not any(set(groebner(o, R)) < set(groebner(p, R)) for o in primes)}
    minimal = as_set(primes, R)
    for method in (primdec_gtz, primdec_sy):
        ours = method(I, R)
        assert intersect(*[q for q, _ in ours], ring=R) == groebner(I, R)
        assert as_set([p for _, p in ours], R) == as_set([p for _, p in comps], R)
        for q, p in ours:
            if tuple(p) in minimal:
                assert tuple(q) == isolated[tuple(p)]
        for (q, p), (count, rad) in zip(ours, singular_checks(R, ordering, ours)):
            assert count == 1 and groebner(rad, R) == p


def ring(names, field=QQ, blocks=None):
    names = names.split() if " " in names else list(names)
    return PolyRing(field, names, MonomialOrder(blocks or [Block("dp", len(names))]))


def ideals(R, *groups):
    return [[parse(R, t) for t in g] for g in groups]


# --- the paper --------------------------------------------------------------------------

SLIDER2 = ring("c1 s1 c2 s2 l1 l2", blocks=[Block("dp", 4), Block("dp", 2)])
PAPER9 = ring("c1 s1 c2 s2 c3 s3 l1 l2 l3", blocks=[Block("dp", 6), Block("dp", 3)])
ANGLES2 = ring("c1 s1 c2 s2")
ANGLES3 = ring("c1 s1 c2 s2 c3 s3")


def slider2_fitting():
    c1, s1, c2, s2, l1, l2 = SLIDER2.gens()
    J = [l1 * s1 + l2 * s2, c1 ** 2 + s1 ** 2 - 1, c2 ** 2 + s2 ** 2 - 1]
    return fitting_ideal(J, range(4))


def slider3_fitting():
    c1, s1, c2, s2, c3, s3, l1, l2, l3 = PAPER9.gens()
    J = [l1 * s1 + l2 * s2 + l3 * s3, c1 ** 2 + s1 ** 2 - 1, c2 ** 2 + s2 ** 2 - 1, c3 ** 2 + s3 ** 2 - 1]
    return fitting_ideal(J, range(6))


def fourbar_fitting():
    c1, s1, c2, s2, c3, s3, l1, l2, l3 = PAPER9.gens()
    J = [l1 * c1 + l2 * c2 + l3 * c3 - 1, l1 * s1 + l2 * s2 + l3 * s3, c1 ** 2 + s1 ** 2 - 1,
         c2 ** 2 + s2 ** 2 - 1, c3 ** 2 + s3 ** 2 - 1]
    return fitting_ideal(J, range(6))


def fourbar_l1():
    c1, s1, c2, s2, c3, s3 = ANGLES3.gens()
    return [c1 + c2 + c3 - 1, s1 + s2 + s3, c1 ** 2 + s1 ** 2 - 1, c2 ** 2 + s2 ** 2 - 1, c3 ** 2 + s3 ** 2 - 1]


def test_slider2_fitting_ideal_primes():
    F = slider2_fitting()
    assert len(F) == 4
    expected = ideals(SLIDER2, ["l2", "l1"], ["l2", "c1"], ["l1", "c2"], ["s2", "c2"], ["c2", "c1"], ["s1", "c1"])
    L = min_ass_gtz(F)
    assert len(L) == 6 and as_set(L, SLIDER2) == as_set(expected, SLIDER2)
    assert as_set(min_ass_char(F), SLIDER2) == as_set(expected, SLIDER2)


def test_slider3_fitting_ideal_primes():
    expected = ideals(PAPER9, ["l3", "l2", "l1"], ["l3", "l2", "c1"], ["l3", "l1", "c2"], ["l3", "c2", "c1"],
                      ["l2", "l1", "c3"], ["l2", "c3", "c1"], ["s3", "c3"], ["l1", "c3", "c2"],
                      ["c3", "c2", "c1"], ["s2", "c2"], ["s1", "c1"])
    L = min_ass_gtz(slider3_fitting())
    assert len(L) == 11 and as_set(L, PAPER9) == as_set(expected, PAPER9)


def test_fourbar_fitting_ideal_primes():
    expected = ideals(PAPER9, ["l3", "l2"], ["l3", "l1"], ["-s1*c2+c1*s2", "l3"], ["l2", "l1"],
                      ["-s1*c3+c1*s3", "l2"], ["-s2*c3+c2*s3", "l1"], ["s3", "c3"],
                      ["-s2*c3+c2*s3", "-s1*c3+c1*s3", "-s1*c2+c1*s2"], ["s2", "c2"], ["s1", "c1"])
    F = fourbar_fitting()
    L = min_ass_gtz(F)
    assert len(L) == 10 and as_set(L, PAPER9) == as_set(expected, PAPER9)
    assert radical(F) == intersect(*expected, ring=PAPER9)


def test_slider2_motion_modes_and_singular_points():
    c1, s1, c2, s2 = ANGLES2.gens()
    J = [s1 + s2, c1 ** 2 + s1 ** 2 - 1, c2 ** 2 + s2 ** 2 - 1]
    modes = ideals(ANGLES2, ["c2^2+s2^2-1", "c1-c2", "s1+s2"], ["c2^2+s2^2-1", "c1+c2", "s1+s2"])
    comps = primdec_gtz(J)
    assert as_set([q for q, _ in comps], ANGLES2) == as_set(modes, ANGLES2)
    assert all(q == p for q, p in comps)  # J is radical
    assert as_set([q for q, _ in primdec_sy(J)], ANGLES2) == as_set(modes, ANGLES2)
    points = ideals(ANGLES2, ["s2-1", "c2", "s1+s2", "c1"], ["s2+1", "c2", "s1+s2", "c1"])
    assert as_set(min_ass_gtz(J + [c1, c2]), ANGLES2) == as_set(points, ANGLES2)


def test_slider3_singular_points():
    c1, s1, c2, s2, c3, s3 = ANGLES3.gens()
    J = [2 * s1 + s2 + s3, c1 ** 2 + s1 ** 2 - 1, c2 ** 2 + s2 ** 2 - 1, c3 ** 2 + s3 ** 2 - 1]
    assert dimension(J) == 2
    assert is_prime(J)
    points = ideals(ANGLES3, ["s3-1", "c3", "s2-1", "c2", "s1+1/2*s2+1/2*s3", "c1"],
                    ["s3+1", "c3", "s2+1", "c2", "s1+1/2*s2+1/2*s3", "c1"])
    assert as_set(min_ass_gtz(J + [c1, c2, c3]), ANGLES3) == as_set(points, ANGLES3)


def test_fourbar_motion_modes_and_singular_points():
    J = fourbar_l1()
    c1, s1, c2, s2, c3, s3 = ANGLES3.gens()
    modes = ideals(ANGLES3, ["s3", "c3-1", "c2^2+s2^2-1", "s1+s2+s3", "c1+c2+c3-1"],
                   ["c3^2+s3^2-1", "s2+s3", "c2+c3", "s1+s2+s3", "c1+c2+c3-1"],
                   ["c3^2+s3^2-1", "s2", "c2-1", "s1+s2+s3", "c1+c2+c3-1"])
    for method in (primdec_gtz, primdec_sy):
        comps = method(J)
        assert as_set([q for q, _ in comps], ANGLES3) == as_set(modes, ANGLES3)
        assert all(q == p for q, p in comps)
    S = J + [-s2 * c3 + c2 * s3, -s1 * c3 + c1 * s3, -s1 * c2 + c1 * s2]
    points = ideals(ANGLES3, ["s3", "c3-1", "s2", "c2-1", "s1+s2+s3", "c1+c2+c3-1"],
                    ["s3", "c3-1", "s2", "c2+1", "s1+s2+s3", "c1+c2+c3-1"],
                    ["s3", "c3+1", "s2", "c2-1", "s1+s2+s3", "c1+c2+c3-1"])
    assert as_set(min_ass_gtz(S), ANGLES3) == as_set(points, ANGLES3)
    assert radical(J) == groebner(J)


# --- embedded, non-reduced, mixed dimensions ------------------------------------------------

XYZ = ring("xyz")


def test_embedded_component():
    x, y, z = XYZ.gens()
    I = [x ** 2, x * y]
    assert min_ass_gtz(I) == [[x]]
    comps = primdec_gtz(I)
    assert comps == [([x], [x]), (groebner([x ** 2, y]), [y, x])]  # Singular's answer too
    assert primdec_sy(I) == comps
    check_decomposition(I, comps, XYZ)
    assert not is_primary(I) and not is_prime(I)


def test_embedded_monomial_components():
    x, y, z = XYZ.gens()
    I = [x ** 2 * y, x * y ** 3]
    comps = primdec_gtz(I)
    assert as_set([p for _, p in comps], XYZ) == as_set([[x], [y], [x, y]], XYZ)
    iso = {tuple(p): q for q, p in comps}
    assert iso[(x,)] == [x] and iso[(y,)] == [y]
    check_decomposition(I, comps, XYZ)
    check_decomposition(I, primdec_sy(I), XYZ)


def test_nonreduced_primaries():
    x, y, z = XYZ.gens()
    Q = [(x ** 2 - 2) ** 2, y - x]
    assert is_primary(Q) and not is_prime(Q)
    assert primdec_gtz(Q) == [(groebner(Q), groebner([x ** 2 - 2, y - x]))]
    I = intersect([(x - 1) ** 3, y], [x, (y - z) ** 2])
    comps = primdec_gtz(I)
    assert as_set([q for q, _ in comps], XYZ) == as_set([[(x - 1) ** 3, y], [x, (y - z) ** 2]], XYZ)
    assert as_set([q for q, _ in primdec_sy(I)], XYZ) == as_set([[(x - 1) ** 3, y], [x, (y - z) ** 2]], XYZ)


def test_mixed_dimensions_and_equidim():
    x, y, z = XYZ.gens()
    I = intersect([z], [x, y], [x ** 2, z ** 2], [x ** 5, y ** 5, z ** 5])
    comps = primdec_gtz(I)
    check_decomposition(I, comps, XYZ)
    assert [dimension(p) for _, p in comps] == [2, 1, 1, 0]
    assert as_set([p for _, p in comps], XYZ) == as_set([[z], [x, y], [x, z], [x, y, z]], XYZ)
    check_decomposition(I, primdec_sy(I), XYZ)
    parts = equidim(I)
    assert len(parts) == 3 and parts[-1] == [z] == equidim_max(I)
    assert intersect(*parts) == I
    assert [dimension(p) for p in parts] == [0, 1, 2]
    assert radical(parts[1]) == intersect([x, y], [x, z])
    assert equi_radical(I) == [z]
    assert equi_radical([x * z, y * z]) == [z]
    assert equidim([XYZ.one()]) == [[XYZ.one()]]


def test_generic_coordinates_needed():
    x, y, z = XYZ.gens()
    assert as_set(min_ass_gtz([x ** 2 - 2, y ** 2 - 2]), XYZ) == as_set([[x - y, y ** 2 - 2], [x + y, y ** 2 - 2]], XYZ)
    assert min_ass_gtz([x ** 2 - 2, y ** 2 - 3]) == [groebner([x ** 2 - 2, y ** 2 - 3])]
    assert is_prime([x ** 2 - 2, y ** 2 - 3, z ** 2 - 5])


def test_parameters_and_block_orderings():
    R = ring("x y a", blocks=[Block("dp", 2), Block("dp", 1)])
    x, y, a = R.gens()
    L = min_ass_gtz([x ** 2 - a, y ** 2 - a])
    assert as_set(L, R) == as_set([[x - y, y ** 2 - a], [x + y, y ** 2 - a]], R)
    assert is_prime([x ** 2 - a * y ** 2])
    comps = primdec_gtz([(x ** 2 - a) * y, y ** 2])
    check_decomposition([(x ** 2 - a) * y, y ** 2], comps, R)
    assert as_set([p for _, p in comps], R) == as_set([[y], [y, x ** 2 - a]], R)


def test_prime_field_decomposition():
    R = ring("xyz", field=GF(32003))
    x, y, z = R.gens()
    I = [x ** 2 + 2 * y ** 2, z ** 3 - z]  # -2 is a square mod 32003
    L = min_ass_gtz(I)
    assert len(L) == 6 and all(dimension(p) == 1 for p in L)
    comps = primdec_gtz([x ** 2 * y, (x - y) ** 2 * z])
    check_decomposition([x ** 2 * y, (x - y) ** 2 * z], comps, R)
    assert as_set(min_ass_gtz([x ** 2 * y, (x - y) ** 2 * z]), R) == as_set([[x, y], [x, z], [y, z]], R)


def test_unit_and_zero_ideal():
    x, y, z = XYZ.gens()
    assert min_ass_gtz([XYZ.one()]) == [] and primdec_gtz([x, x + 1]) == []
    assert min_ass_gtz([], XYZ) == [[]]
    assert primdec_gtz([], XYZ) == [([], [])]
    assert radical([], XYZ) == []


# --- live comparisons with Singular ----------------------------------------------------------

LIVE = [
    ("xyz", "dp", ["x^2", "x*y"]),
    ("xyz", "dp", ["x^2*y", "x*y^3"]),
    ("xyz", "dp", ["x*y*z", "x^2*z^2-y", "y^3"]),
    ("xyz", "dp", ["(x^2-2)*(y-z)^2", "x*(y^2-3)"]),
    ("xyz", "lp", ["x^3-y*z", "y^2-x*z", "z^2-x^2*y"]),
    ("abcd", "dp", ["a+b+c+d", "a*b+b*c+c*d+d*a", "a*b*c+b*c*d+c*d*a+d*a*b", "a*b*c*d-1"]),
]


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
@pytest.mark.parametrize("names, ordering, gens", LIVE)
def test_live_singular_decompositions(names, ordering, gens):
    R = PolyRing(QQ, list(names), MonomialOrder.simple(ordering, len(names)))
    compare_with_singular(R, ordering, [parse(R, g) for g in gens])


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
def test_live_singular_prime_field_with_parameters():
    R = PolyRing(GF(32003), ["x", "y", "a", "b"], MonomialOrder([Block("dp", 2), Block("dp", 2)]))
    I = [parse(R, g) for g in ["(x^2-a)*(y-b)", "x*y^2-a*b*x", "(x-y)^2*a"]]
    compare_with_singular(R, "(dp(2),dp(2))", I)
