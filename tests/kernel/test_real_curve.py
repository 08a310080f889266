"""Real topology of curves: circuits, isolated points and unbounded branches of plane and space
curves with known answers, and four-bar linkages in mech's mechanism variables checked against a
dense numerical sampling of the input angle (an independent witness)."""
from __future__ import annotations

import math

import pytest
from flint import fmpq

from mech.kernel import QQ, MonomialOrder, PolyRing
from mech.kernel.groebner import groebner
from mech.kernel.ideals import intersect
from mech.kernel.primdec import min_ass_gtz
from mech.kernel.real_curve import curve_topology
from mech.kernel.real_roots import RealSolvingError
from mech.kernel.real_solve import real_solutions

R2 = PolyRing(QQ, ["x", "y"], MonomialOrder.simple("dp", 2))
x, y = R2.gens()
R3 = PolyRing(QQ, ["x", "y", "z"], MonomialOrder.simple("dp", 3))
X, Y, Z = R3.gens()
R6 = PolyRing(QQ, ["c1", "s1", "c2", "s2", "c3", "s3"], MonomialOrder.simple("dp", 6))
c1, s1, c2, s2, c3, s3 = R6.gens()

# (curve, circuits, isolated points, unbounded circuits)
PLANE = [
    (x ** 2 + y ** 2 - 1, 1, 0, 0),
    (x ** 2 + y ** 2 + 1, 0, 0, 0),
    (x ** 2 + y ** 2, 0, 1, 0),                                   # one real point
    (x ** 2 - y ** 2, 1, 0, 1),                                   # two crossing lines
    (y ** 2 - x ** 3, 1, 0, 1),                                   # cusp
    (y ** 2 - x ** 2 - x ** 3, 1, 0, 1),                          # nodal cubic
    (y ** 2 + x ** 2 - x ** 3, 1, 1, 1),                          # cubic with an isolated point
    ((x ** 2 + y ** 2 - 1) * (x ** 2 + y ** 2 - 4), 2, 0, 0),     # nested circles
    ((x ** 2 + y ** 2 - 1) * ((x - 3) ** 2 + y ** 2 - 1), 2, 0, 0),
    ((x ** 2 + y ** 2 - 1) * (x ** 2 + (y - 1) ** 2 - 1), 1, 0, 0),   # two circles meeting
    (x * y - 1, 2, 0, 2),                                         # hyperbola
    (y ** 2 - (x ** 2 - 1) * (x ** 2 - 4) * (x ** 2 - 9), 4, 0, 2),
    ((x ** 2 + y ** 2) ** 2 - (x ** 2 - y ** 2), 1, 0, 0),        # lemniscate
    (x ** 4 + y ** 4 - 1, 1, 0, 0),
    ((x ** 2 + y ** 2 - 1) * (x ** 2 + y ** 2 - 2) * ((x - 5) ** 2 + y ** 2), 2, 1, 0),
]


@pytest.mark.parametrize("f,circuits,isolated,unbounded", PLANE)
def test_plane_curves(f, circuits, isolated, unbounded):
    topo = curve_topology([f], R2, None)
    assert (topo.count, len(topo.isolated)) == (circuits, isolated)
    assert sum(not c.bounded for c in topo.circuits) == unbounded


def test_sample_points_and_bounding_boxes():
    """Sample points lie on the curve; a bounded circuit's box is its bounding box: the two ovals of
    y^2 = (x^2-1)(x^2-4)(x^2-9) span 1 <= |x| <= 2 exactly, the unbounded branches have no certified box."""
    f = y ** 2 - (x ** 2 - 1) * (x ** 2 - 4) * (x ** 2 - 9)
    topo = curve_topology([f], R2, 8)
    for c in topo.circuits:
        for box in c.samples:
            assert all(hi - lo <= fmpq(1, 10 ** 8) for lo, hi in box)
            assert abs(float(f.evaluate([(lo + hi) / 2 for lo, hi in box]))) < 1e-5
        assert all(c.box[i][0] <= b[i][0] and b[i][1] <= c.box[i][1] for b in c.samples for i in range(2))
    ovals = sorted((c.box for c in topo.circuits if c.bounded), key=lambda b: b[0][0])
    assert all(c.certified == c.bounded for c in topo.circuits)
    top = max(math.sqrt((t * t - 1) * (t * t - 4) * (t * t - 9)) for t in (1 + k / 10000 for k in range(10001)))
    for box, (a, b) in zip(ovals, [(-2, -1), (1, 2)]):
        assert abs(float(box[0][0]) - a) < 1e-8 and abs(float(box[0][1]) - b) < 1e-8
        assert abs(float(box[1][1]) - top) < 1e-6 and abs(float(box[1][0]) + top) < 1e-6


SPACE = [
    ("Hopf link", intersect([X ** 2 + Y ** 2 - 1, Z], [(X - 1) ** 2 + Z ** 2 - 1, Y], ring=R3), 2, 0),
    ("separate circles", intersect([X ** 2 + Y ** 2 - 1, Z], [(X - 3) ** 2 + Z ** 2 - 1, Y], ring=R3), 2, 0),
    ("touching circles", intersect([X ** 2 + Y ** 2 - 1, Z], [(X - 2) ** 2 + Z ** 2 - 1, Y], ring=R3), 1, 0),
    ("Viviani", [X ** 2 + Y ** 2 + Z ** 2 - 4, (X - 1) ** 2 + Y ** 2 - 1], 1, 0),
    ("twisted cubic", [Y - X ** 2, Z - X ** 3], 1, 0),
    ("circle and point", intersect([X ** 2 + Y ** 2 - 1, Z], [X - 3, Y, Z - 1], ring=R3), 1, 1),
    ("no real point", [X ** 2 + Y ** 2 + Z ** 2 + 1, X - Y], 0, 0),
]


@pytest.mark.parametrize("name,ideal,circuits,isolated", SPACE, ids=[s[0] for s in SPACE])
def test_space_curves(name, ideal, circuits, isolated):
    topo = curve_topology(ideal, R3, None)
    assert (topo.count, len(topo.isolated)) == (circuits, isolated)


def fourbar(ground, a, b, c):
    """mech's constraint ideal of ``ground O A g; bar O B a; bar B C b; bar C A c``."""
    return [a * c1 + b * c2 + c * c3 - ground, a * s1 + b * s2 + c * s3,
            c1 ** 2 + s1 ** 2 - 1, c2 ** 2 + s2 ** 2 - 1, c3 ** 2 + s3 ** 2 - 1]


def sampled_circuits(ground, a, b, c, steps=20000):
    """An independent count of the circuits of a four-bar from its input angle, and the range of
    c1 = cos(t) over its configurations: B = a(cos t, sin t) and C on the circles of radius b about B
    and c about A = (g, 0).  Assemblies exist where (b - c)^2 <= |AB|^2 <= (b + c)^2; on each arc of
    such angles the two assemblies (elbow up and down) join where the inequality is tight, so an arc is
    one circuit; if every angle is an interior one, the two assemblies never meet: two circuits (a
    full-turn input)."""
    margins, cosines = [], []
    for k in range(steps):
        t = 2 * math.pi * k / steps
        d2 = ground ** 2 + a ** 2 - 2 * a * ground * math.cos(t)
        margins.append(min(d2 - (b - c) ** 2, (b + c) ** 2 - d2))
    tol = 1e-9
    feasible = [m >= -tol for m in margins]
    cosines = [math.cos(2 * math.pi * k / steps) for k in range(steps) if feasible[k]]
    if all(feasible):
        return (2 if min(margins) > tol else 1), (min(cosines), max(cosines))
    start = feasible.index(False)
    arcs, inside = 0, False
    for k in range(steps):
        f = feasible[(start + k) % steps]
        arcs += f and not inside
        inside = f
    return arcs, (min(cosines), max(cosines))


FOURBARS = [("crank-rocker", (5, 2, 5, 4), 2), ("double crank", (2, 4, 5, 4), 2),
            ("rocker-crank", (5, 4, 5, 2), 2), ("triple rocker (non-Grashof)", (7, 4, 3, 5), 1),
            ("change point", (5, 2, 4, 3), 1)]


@pytest.mark.parametrize("name,lengths,circuits", FOURBARS, ids=[f[0] for f in FOURBARS])
def test_fourbar_circuits(name, lengths, circuits):
    count, (lo, hi) = sampled_circuits(*lengths)
    assert count == circuits
    assert curve_topology(fourbar(*lengths), R6, None).count == circuits
    topo = curve_topology(fourbar(*lengths), R6, 6)
    assert topo.count == circuits and not topo.isolated and topo.bounded
    for circuit in topo.circuits:
        assert circuit.certified
        for box in circuit.samples:
            p = [(lo_ + hi_) / 2 for lo_, hi_ in box]
            assert all(abs(float(g.evaluate(p))) < 1e-5 for g in fourbar(*lengths))
        c1_lo, c1_hi = map(float, circuit.box[0])  # the input link's cosine: contains the sampled range
        assert c1_lo <= lo + 1e-12 and hi <= c1_hi + 1e-12 and lo - c1_lo < 1e-3 and c1_hi - hi < 1e-3


@pytest.mark.parametrize("lengths", [(1, 1, 1, 1), (2, 1, 2, 1), (2, 2, 1, 1)])
def test_reducible_fourbars(lengths):
    """Parallelogram and kite linkages: several motion modes, each one circuit here, meeting at
    real points; the union's connected components are those of the graph of modes joined where
    they meet (an independent witness)."""
    I = fourbar(*lengths)
    modes = min_ass_gtz(I, R6)
    assert len(modes) > 1 and all(curve_topology(P, R6, None).count == 1 for P in modes)
    parent = list(range(len(modes)))

    def find(i):
        while parent[i] != i:
            i = parent[i]
        return i
    for i in range(len(modes)):
        for j in range(i + 1, len(modes)):
            meet = groebner(modes[i] + modes[j], R6)
            if not any(g.is_constant() for g in meet) and real_solutions(meet, R6, 3).real_count:
                parent[find(i)] = find(j)
    assert curve_topology(I, R6, None).count == len({find(i) for i in range(len(modes))})


def test_not_a_curve():
    with pytest.raises(RealSolvingError):
        curve_topology([X ** 2 + Y ** 2 + Z ** 2 - 1], R3)
    topo = curve_topology([x ** 2 - 2, y - 1], R2)  # a 0-dimensional ideal: isolated points only
    assert topo.count == 0 and len(topo.isolated) == 2


def test_prime_curve_skips_its_minimal_primes(monkeypatch):
    """A curve known to be prime (a motion mode) is not decomposed again: the space curve
    x^2 + y^2 = 1, z = x y, given with the redundant x z - x^2 y (three generators: not the
    complete-intersection case) has one circuit with and without ``prime``."""
    import mech.kernel.primdec as primdec
    x, y, z = R3.gens()
    gens = [x * x + y * y - 1, z - x * y, x * z - x * x * y]
    assert curve_topology(gens, R3, None).count == 1

    def refuse(*args, **kwargs):
        raise AssertionError("decomposed a prime curve")
    monkeypatch.setattr(primdec, "min_ass_gtz", refuse)
    assert curve_topology(gens, R3, None, prime=True).count == 1
