"""The local components at singular configurations (stdlib/analysis_points.py's "local components" stage) against
Singular's minimal primes in the local ring (``minAssGTZ`` in a ``ds`` ring, over ``Q(t)`` at conjugate
points), and the kernel's certificates behind them (kernel/local.py: a mode stays prime over ``Q(t)``)."""
from __future__ import annotations

import pytest
from flint import fmpq_poly

from mech.dsl.printing import poly_str
from mech.kernel import QQ, Block, MonomialOrder, PolyRing
from mech.kernel.groebner import groebner
from mech.kernel.local import (SmoothSlices, _field_product, _moved, moved_basis, primitive_element, stays_prime,
                               vanishes_at)
from mech.stdlib.analysis import analyze
from mech.stdlib.mechanism import parse_mechanism
from mech.stdlib.standard import normalize
from tests.util import SINGULAR, run_singular

KITE = "ground O A 1; bar O B 1; bar B C 2; bar C A 2"
WATT = "ground O A 1; fix G 2 0; bar O B 1; bar B C 1; body A C 1 0 E 0 1; bar E F 1; bar F G 1"
TILTED = "fix O; bar O A 1; bar A B 1; slider B 1 1 0"  # two modes meeting at conjugate points (t^2 = 1/2)
BODIES2 = "ground O A 1; body O B 1 2; bar B C 1; body C A 2 1"


def ring(names):
    return PolyRing(QQ, names, MonomialOrder([Block("dp", len(names))]))


def singular_matches(a) -> list[tuple[int, int]]:
    """For each singular configuration that is a point: Singular's number of local components
    (minAssGTZ of each mode through it moved there, in ``ds``, over Q(t) at conjugate points) and how
    many of mech's components equal one of them (both inclusions, in a dp ring over the same field)."""
    names = ",".join(a.ring.names[:a.nvars])
    lines = ['LIB "primdec.lib";', f"ring R = 0, ({names}), dp;"] + \
        [f"ideal M{i} = {', '.join(poly_str(g) for g in md.prime)};" for i, md in enumerate(a.modes)] + \
        ["int i; int j; int c; int ok;"]
    for k, s in enumerate(a.singular):
        if s.algebraic is not None:
            pt = s.algebraic
            field = f"(0,{pt.ring.names[-1]})"
            minpoly = f"minpoly = {poly_str(normalize(pt.minpoly))};"
            shift = [f"{x}+({poly_str(c)})" for x, c in zip(a.ring.names, pt.coords)]
            n = pt.ring.nvars - 1
            ours = [[g for g in c if any(any(e[:n]) for e in g.terms)] for c in s.local_components]
        else:
            field, minpoly = "0", ""
            shift = [f"{x}+({c})" for x, c in zip(a.ring.names, s.point)]
            ours = s.local_components
        lines += [f"ring L{k} = {field}, ({names}), ds; {minpoly}", f"map sh{k} = R, {', '.join(shift)};",
                  f"list C{k};"] + [f"C{k} = C{k} + minAssGTZ(sh{k}(M{i - 1}));" for i in s.modes]
        lines += [f"ring D{k} = {field}, ({names}), dp; {minpoly}", f"list C = imap(L{k}, C{k}); list O;"]
        lines += [f"O = insert(O, std(ideal({', '.join(poly_str(g) for g in c)})));" for c in ours]
        lines += ["c = 0; for (i = 1; i <= size(O); i++) { for (j = 1; j <= size(C); j++) {",
                  "  ok = size(reduce(C[j], O[i])) == 0 and size(reduce(O[i], std(C[j]))) == 0; c = c + ok; } }",
                  f'"point {k} " + string(size(C)) + " " + string(c);', "setring R;"]
    out = run_singular("\n".join(lines))
    return [tuple(map(int, line.split()[2:4])) for line in out.splitlines() if line.startswith("point ")]


@pytest.mark.skipif(not SINGULAR, reason="Singular not installed")
@pytest.mark.parametrize("mechanism", [KITE, WATT, TILTED, BODIES2])
def test_local_components_are_singulars_minimal_primes_in_the_local_ring(mechanism):
    a = analyze(parse_mechanism(mechanism))
    points = [s for s in a.singular if s.point is not None or s.algebraic is not None]
    assert points and any(len(s.local_components) > 1 for s in points)
    got = singular_matches(a)
    assert got == [(len(s.local_components), len(s.local_components)) for s in points]


def test_field_product():
    """Q(sqrt2) (x) Q(sqrt3) and Q(cbrt2) (x) Q(i) are fields; Q(sqrt2) (x) Q(sqrt2) and Q(2^(1/4)) (x) Q(sqrt2)
    are not (t^2 - 2 has a root there)."""
    sq2, sq3, cb2, i, qr2 = (fmpq_poly(c) for c in ([-2, 0, 1], [-3, 0, 1], [-2, 0, 0, 1], [1, 0, 1], [-2, 0, 0, 0, 1]))
    assert _field_product(sq2, sq3) and _field_product(i, cb2)
    assert not _field_product(sq2, sq2) and not _field_product(sq2, qr2)


def test_a_slice_through_the_cusp_has_no_smooth_orbit():
    """y^2 = x^3 cut through the cusp (x = 0 or y = 0, whichever variable is free) meets it with
    multiplicity 2 or 3 (the quotient algebra is not reduced there): no orbit of smooth points, so no
    certificate; a random slice gives one orbit of all its (smooth) points."""
    R = ring(["x", "y"])
    x, y = R.gens()

    class AtZero:
        def randint(self, lo, hi):
            return max(lo, 0) if lo <= 0 else 1
    at_cusp = SmoothSlices([y ** 2 - x ** 3], tries=2)
    at_cusp._rnd = AtZero()
    assert list(at_cusp) == []
    orbits = list(SmoothSlices([y ** 2 - x ** 3], tries=1))
    assert len(orbits) == 1 and orbits[0].degree() in (2, 3)


def test_stays_prime_and_the_moved_basis():
    """At (+-sqrt2, 0): the circle x^2 + y^2 = 2 passes there and stays prime over Q(sqrt2); x^2 - 2y^2
    does not pass there, and through (+-sqrt2, 1) it splits into two lines over Q(sqrt2); the moved basis
    is the reduced Gröbner basis that Buchberger gives."""
    R = ring(["x", "y"])
    x, y = R.gens()
    pt = primitive_element([x ** 2 - 2, y], R)
    pt1 = primitive_element([x ** 2 - 2, y - 1], R)
    circle, lines = [x ** 2 + y ** 2 - 2], [x ** 2 - 2 * y ** 2]
    assert vanishes_at(circle, pt) and not vanishes_at(lines, pt) and vanishes_at(lines, pt1)
    assert stays_prime(circle, pt) and not stays_prime(lines, pt1)
    lemniscate = [(x ** 2 + y ** 2) ** 2 - 2 * (x ** 2 - y ** 2)]
    for P, p in ((circle, pt), (lemniscate, pt), (lines, pt1), (circle, pt1)):
        assert moved_basis(P, p) == groebner(_moved(P, p), p.ring)
