"""Hilbert series, degree, mult, vdim, kbase and homogenization against Singular 4.3.1
(hard-coded truths from real runs; live differential runs when Singular is installed)."""
import random

import pytest
from tests.util import SINGULAR, run_singular

from mech.kernel import QQ, Block, MonomialOrder, PolyRing
from mech.kernel.errors import DomainError
from mech.kernel.groebner import groebner
from mech.kernel import hilbert as H
from mech.kernel.hilbert import (DegreeInfo, colon_numerator, degree, first_numerator, hilb_lines,
                                 hilbert_numerators, kbase, minimal_monomials, mult, vdim)
from mech.kernel.homog import homogenize, is_homogeneous, variable_weights

singular = pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")


def lms_of(gens):
    return [g.lm() for g in groebner(gens)]


def ring(names):
    return PolyRing(QQ, list(names), MonomialOrder([Block("dp", len(names))]))


def mono(ring_names, text):
    """Exponent tuple of a short monomial such as ``x2yz``."""
    import re
    e = [0] * len(ring_names)
    for name, power in re.findall(r"([a-z])(\d*)", text):
        e[ring_names.index(name)] += int(power or 1)
    return tuple(e)


def test_twisted_cubic_affine():
    R = ring("xyz")
    x, y, z = R.gens()
    L = lms_of([x**2 - y, x**3 - z])  # leading ideal (x2, xy, y2)
    assert hilbert_numerators(L, 3) == ([1, 0, -3, 2], [1, 2], 1)
    assert degree(L, 3) == DegreeInfo("proj.", 0, 3)
    assert mult(L, 3) == 3 and vdim(L, 3) == -1 and kbase(L, 3) == []
    assert hilb_lines(L, 3) == [
        "//         1 t^0", "//        -3 t^2", "//         2 t^3", "",
        "//         1 t^0", "//         2 t^1",
        "// dimension (proj.)  = 0", "// degree (proj.)   = 3"]


def test_twisted_cubic_projective():
    R = ring("xyzw")
    x, y, z, w = R.gens()
    L = lms_of([x * z - y**2, y * w - z**2, x * w - y * z])
    assert hilbert_numerators(L, 4) == ([1, 0, -3, 2], [1, 2], 2)
    assert degree(L, 4).lines() == ["// dimension (proj.)  = 1", "// degree (proj.)   = 3"]


def test_zero_dimensional():
    R = ring("xyz")
    x, y, z = R.gens()
    L = lms_of([x**2 + y**2 + z**2 - 1, x - y, z**2 - x])  # x, z2, y2
    assert hilbert_numerators(L, 3) == ([1, -1, -2, 2, 1, -1], [1, 2, 1], 0)
    assert degree(L, 3).lines() == ["// dimension (affine) = 0", "// degree (affine)  = 4"]
    assert vdim(L, 3) == 4 and mult(L, 3) == 4
    assert kbase(L, 3) == [mono("xyz", m) for m in ["yz", "z", "y", ""]]


@pytest.mark.parametrize("gens,basis", [
    ("x2 y2 z2", "xyz yz xz z xy y x 1"),
    ("x3 y2 z2 xyz", "yz x2z xz z x2y xy y x2 x 1"),
])
def test_kbase_order(gens, basis):
    L = [mono("xyz", g) for g in gens.split()]
    assert kbase(L, 3) == [mono("xyz", "" if b == "1" else b) for b in basis.split()]
    assert vdim(L, 3) == len(basis.split())


def test_kbase_two_variables_and_degrees():
    L = [mono("xy", g) for g in ["x3", "y4", "x2y2"]]
    assert kbase(L, 2) == [mono("xy", "" if b == "1" else b) for b in "xy3 y3 xy2 y2 x2y xy y x2 x 1".split()]
    A = [mono("xyz", g) for g in ["x2", "y3", "z2"]]
    assert kbase(A, 3, 2) == [mono("xyz", b) for b in ["yz", "xz", "y2", "xy"]]
    assert kbase(A, 3, 0) == [(0, 0, 0)] and kbase(A, 3, 7) == []
    B = [mono("xyz", g) for g in ["x2", "xy"]]  # positive dimension: kbase(B, d) still works
    assert kbase(B, 3, 2) == [mono("xyz", b) for b in ["z2", "yz", "xz", "y2"]]
    assert kbase(B, 3, 3) == [mono("xyz", b) for b in ["z3", "yz2", "xz2", "y2z", "y3"]]
    assert kbase(B, 3) == []


def test_complete_intersections():
    x2y2z2 = [mono("xyz", g) for g in ["x2", "y2", "z2"]]
    assert hilbert_numerators(x2y2z2, 3) == ([1, 0, -3, 0, 3, 0, -1], [1, 3, 3, 1], 0)
    assert degree(x2y2z2, 3) == DegreeInfo("affine", 0, 8)
    # the leading ideal of the non-complete-intersection x2y, y3+z, xz
    R = ring("xyz")
    x, y, z = R.gens()
    L = lms_of([x**2 * y, y**3 + z, x * z])
    assert hilbert_numerators(L, 3) == ([1, 0, -1, -2, 1, 2, -1], [1, 2, 2, 0, -1], 1)
    assert degree(L, 3) == DegreeInfo("proj.", 0, 4)
    assert hilbert_numerators([mono("xy", "x2"), mono("xy", "y")], 2)[:2] == ([1, -1, -1, 1], [1, 1])
    assert hilbert_numerators([mono("xy", "x")], 2) == ([1, -1], [1], 1)


def test_unit_and_zero_ideals():
    assert hilbert_numerators([(0, 0)], 2) == ([0], [0], -1)
    assert degree([(0, 0)], 2).lines() == ["// dimension (affine) = 0", "// degree (affine)  = 0"]
    assert degree([(0, 0)], 2, local=True).lines() == ["// dimension (local)   = -1", "// multiplicity = 0"]
    assert mult([(0, 0)], 2) == 0 and vdim([(0, 0)], 2) == 0 and kbase([(0, 0)], 2) == []
    assert hilb_lines([(0, 0)], 2) == ["", "// dimension (affine) = 0", "// degree (affine)  = 0"]
    assert hilbert_numerators([], 2) == ([1], [1], 2)
    assert degree([], 2) == DegreeInfo("proj.", 1, 1)
    assert mult([], 2) == 1 and vdim([], 2) == -1


def test_local_orderings_use_leading_monomials():
    # ds standard bases from Singular: {y-x2, z-x3}, {y2-x3}, {x+y2, y3+z5}, {x2+x3, y2, z2}
    xyz = "xyz"
    assert hilbert_numerators([mono(xyz, "y"), mono(xyz, "z")], 3) == ([1, -2, 1], [1], 1)
    assert degree([mono(xyz, "y"), mono(xyz, "z")], 3, local=True).lines() == [
        "// dimension (local)   = 1", "// multiplicity = 1"]
    assert degree([mono(xyz, "y2")], 3, local=True) == DegreeInfo("local", 2, 2)
    L2 = [mono(xyz, "x"), mono(xyz, "y3")]
    assert hilbert_numerators(L2, 3) == ([1, -1, 0, -1, 1], [1, 1, 1], 1)
    assert degree(L2, 3, local=True) == DegreeInfo("local", 1, 3) and vdim(L2, 3) == -1
    F = [mono(xyz, "x2"), mono(xyz, "y2"), mono(xyz, "z2")]
    assert degree(F, 3, local=True) == DegreeInfo("local", 0, 8) and vdim(F, 3) == 8


def test_minimal_monomials():
    assert sorted(minimal_monomials([(2, 0), (1, 1), (2, 1), (1, 1), (0, 3)])) == [(0, 3), (1, 1), (2, 0)]
    with pytest.raises(DomainError):
        hilbert_numerators([(1, 0)], 3)


@pytest.mark.parametrize("compiled", [True, False])
def test_colon_numerator_is_the_numerator_of_the_colon_ideal(compiled, monkeypatch):
    """Q(t) of K[x]/(L : m) (the Hilbert-driven algorithms' update), in C with a divisor and in
    Python, against the colon's generators lcm(l, m) / m written out; m in L gives the unit ideal."""
    if not compiled:
        monkeypatch.setattr(H, "_compiled_numerator", None)
    rng = random.Random(7)
    for _ in range(30):
        n = rng.randint(1, 5)
        lms = [tuple(rng.randint(0, 3) for _ in range(n)) for _ in range(rng.randint(1, 6))]
        m = tuple(rng.randint(0, 3) for _ in range(n))
        colon = [tuple(max(a - b, 0) for a, b in zip(g, m)) for g in lms]
        assert colon_numerator(lms, m, n) == first_numerator(colon, n)
    assert colon_numerator([(1, 0)], (2, 1), 2) == [0]
    assert colon_numerator([], (2, 1), 2) == [1]


def _intvec(text):
    return [int(v) for v in text.split(",")]


@singular
def test_random_monomial_ideals_match_singular():
    rng = random.Random(11)
    names = "xyzuv"
    cases = []
    for _ in range(25):
        n = rng.randint(2, 5)
        gens = [tuple(rng.randint(0, 3) for _ in range(n)) for _ in range(rng.randint(1, 6))]
        gens = [g for g in gens if any(g)] or [(1,) + (0,) * (n - 1)]
        if rng.random() < 0.3:  # make some zero-dimensional
            gens += [tuple(rng.randint(1, 3) if j == i else 0 for j in range(n)) for i in range(n)]
        cases.append((n, gens))
    script = []
    for n, gens in cases:
        ideal = ",".join("*".join(f"{names[i]}^{e}" for i, e in enumerate(g) if e) for g in gens)
        script.append(f"ring r=0,({','.join(names[:n])}),dp; ideal I=std(ideal({ideal}));"
                      f"string(hilb(I,1)); string(hilb(I,2)); vdim(I); mult(I); degree(I);"
                      f"string(kbase(I)); string(kbase(I,2)); \"end\";")
    out = run_singular("\n".join(script)).split("end\n")
    for (n, gens), chunk in zip(cases, out):
        lines = chunk.strip().splitlines()
        q, p, _ = hilbert_numerators(gens, n)
        assert _intvec(lines[0]) == q + [0] and _intvec(lines[1]) == p + [0]
        assert int(lines[2]) == vdim(gens, n) and int(lines[3]) == mult(gens, n)
        assert lines[4:6] == degree(gens, n).lines()
        for got, mine in ((lines[6], kbase(gens, n)), (lines[7], kbase(gens, n, 2))):
            text = got.split(",")
            exps = [] if text == ["0"] else [mono(names[:n], "" if t == "1" else t) for t in text]
            assert exps == mine


def test_homog():
    R = ring("xyz")
    x, y, z = R.gens()
    # Singular: homog(ideal(x2-y+1, x3-z, 0, 5), z) = x2-yz+z2, x3-z3, 0, 5
    assert homogenize([x**2 - y + 1, x**3 - z, R.zero(), R.const(5)], 2) == [
        x**2 - y * z + z**2, x**3 - z**3, R.zero(), R.const(5)]
    assert homogenize(x**2 + y**2, 2) == x**2 + y**2
    assert homogenize(x * z + x, 2) == 2 * x * z
    assert not is_homogeneous([x**2 - y + 1]) and is_homogeneous([x**2 - y * z, x * y])
    assert is_homogeneous([R.zero(), R.const(5)])
    with pytest.raises(DomainError):
        homogenize(x, 3)


def test_weighted_homog():
    W = PolyRing(QQ, list("xyz"), MonomialOrder([Block("wp", 3, (2, 3, 1))]))
    x, y, z = W.gens()
    f = x**3 - y**2 + x
    assert variable_weights(W) == (2, 3, 1)
    assert not is_homogeneous(f) and is_homogeneous(x**3 - y**2)
    assert homogenize(f, 2) == x**3 - y**2 + x * z**4     # Singular: x3-y2+xz4
    with pytest.raises(DomainError, match="weight 1"):
        homogenize(f, 0)
    A = PolyRing(QQ, list("xyz"), MonomialOrder([Block("a", 3, (1, 2, 3)), Block("dp", 3)]))
    x, y, z = A.gens()
    assert variable_weights(A) == (1, 2, 3) and not is_homogeneous(x**3 - y)
    with pytest.raises(DomainError, match="weight 1"):
        homogenize(x**2 - y + 1, 2)
    L = PolyRing(QQ, list("xyz"), MonomialOrder([Block("ds", 3)]))
    x, y, z = L.gens()
    assert homogenize(x**2 - y + 1, 2) == x**2 - y * z + z**2
