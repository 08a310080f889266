"""Motion modes are the minimal primes of J (mech.stdlib.modes): embedded components of a
non-radical J reported apart, the strategy chain on a six-bar, partial reports on a time limit."""
from __future__ import annotations

import dataclasses
import functools
import re
import subprocess
import sys
import time

import pytest

from mech.kernel import Block
from mech.kernel.ideals import ideals_equal
from mech.kernel.primdec import min_ass_gtz
from mech.stdlib.analysis import analyze
from mech.stdlib.mechanism import parse_mechanism
from mech.stdlib.reports import report_data, report_text
from tests.util import SINGULAR, ideal_blocks, parse_poly, ring, run_singular

DOUBLE_PARALLELOGRAM = "ground O A 3; fix E 6 0; bar O B 1; body B C 3 0 F 6 0; bar C A 1; bar F E 1"
WATT_I = "ground O A 4; body O B 3 0 E 2 2; body B C 4 0 F 2 2; bar C A 2; bar E H 3; bar H F 3"
# J of the double parallelogram written by hand: B = (c1,s1), C = B + 3(c2,s2), F = B + 6(c2,s2),
# C + (c3,s3) = A = (3,0), F + (c4,s4) = E = (6,0)
HAND = ("ring r = 0, (c1,s1,c2,s2,c3,s3,c4,s4), dp;\n"
        "ideal J = c1+3*c2+c3-3, s1+3*s2+s3, c1+6*c2+c4-6, s1+6*s2+s4,"
        " c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1, c4^2+s4^2-1;\n")


def _primes(R, blocks):
    return [[parse_poly(R, t) for t in b] for b in blocks]


def _same_sets(ours, theirs, R):
    return len(ours) == len(theirs) and all(any(ideals_equal(p, q, R) for q in theirs) for p in ours)


def test_double_parallelogram_one_mode_two_constraint_singularities():
    a = analyze(parse_mechanism(DOUBLE_PARALLELOGRAM))
    assert not a.radical and [(m.dim, m.real) for m in a.modes] == [(1, True)]
    assert sorted(e.point for e in a.embedded) == [(-1, 0, 1, 0, 1, 0, 1, 0), (1, 0, 1, 0, -1, 0, -1, 0)]
    assert all(e.modes == [1] and e.dim == 0 and e.singular is False for e in a.embedded)
    assert a.singular == []  # the one mode is a smooth curve: the points are not singular configurations
    text = report_text(a)
    assert "motion modes (minimal primes of J): 1\n" in text and "embedded components of J: 2" in text
    assert "constraint singularities" in text and "regular" not in text
    data = report_data(a)
    assert len(data["motion_modes"]) == 1 and len(data["embedded_components"]) == 2


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular not installed")
def test_double_parallelogram_against_singular():
    """minAssGTZ (the modes) and primdecGTZ (the embedded primes) of a hand-written J."""
    a = analyze(parse_mechanism(DOUBLE_PARALLELOGRAM))
    R = a.ring
    out = run_singular('LIB "primdec.lib";\n' + HAND + 'list L = minAssGTZ(J);\n'
                       'int i; for (i = 1; i <= size(L); i++) { print("---"); L[i]; }')
    assert _same_sets([m.prime for m in a.modes], _primes(R, ideal_blocks(out)), R)
    out = run_singular('LIB "primdec.lib";\n' + HAND + 'list L = primdecGTZ(J);\n'
                       'int i; for (i = 1; i <= size(L); i++) { print("---"); L[i][2]; }')
    assoc = _primes(R, ideal_blocks(out))
    assert len(assoc) == 3
    embedded = [p for p in assoc if not any(ideals_equal(p, m.prime, R) for m in a.modes)]
    assert _same_sets([e.prime for e in a.embedded], embedded, R)


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular not installed")
def test_watt_i_finishes_with_one_mode():
    """The issue's Watt I six-bar: one mode, proved; the singular configurations are Singular's
    minimal primes of J + I_9(dJ)."""
    start = time.process_time()
    a = analyze(parse_mechanism(WATT_I))
    assert time.process_time() - start < 60  # about 2 s of CPU on a quiet machine
    R = a.ring
    assert a.radical and len(a.modes) == 1 and ideals_equal(a.modes[0].prime, a.ideal, R) and a.modes[0].real
    from mech.dsl.printing import poly_str
    out = run_singular('LIB "primdec.lib";\nring r = 0, (' + ",".join(R.names) + "), dp;\nideal J0 = "
                       + ", ".join(poly_str(g) for g in a.ideal) + ";\nideal J = J0 + minor(jacob(J0), 9);\n"
                       'list L = minAssGTZ(J); size(L);\n'
                       'int i; for (i = 1; i <= size(L); i++) { print("---"); L[i]; }', timeout=300)
    theirs = [b for b in ideal_blocks(out) if b != ["1"]]  # minAssGTZ(<1>) is <1>: no singular configuration
    assert _same_sets([s.prime for s in a.singular], _primes(R, theirs), R)
    assert a.singular == [] and not a.unfinished


def test_timeout_gives_a_partial_report_and_a_nonzero_status(tmp_path):
    """A six-bar whose analysis takes several seconds: --timeout stops it with what was finished.

    Where it stops depends on the machine, so the test checks the partial report's shape, whatever the stage."""
    script = tmp_path / "six.mech"
    script.write_text('LIB "mechanism.lib";\nmechanism m = "ground O A 4; body O B 3 0 E 1 2; '
                      'body B C 4 0 F 1 2; bar C A 3; bar E H 2; bar H F 3";\nanalyze(m);\n')
    start = time.monotonic()
    r = subprocess.run([sys.executable, "-m", "mech", "--timeout", "1", str(script)], cwd=tmp_path,
                       text=True, capture_output=True, timeout=300)
    assert r.returncode != 0 and time.monotonic() - start < 120
    assert "Traceback" not in r.stderr
    assert "time limit exceeded in analyze (the report above is partial)" in r.stderr
    stopped = re.search(r"the analysis did not finish \((.+?): interrupted by the time limit", r.stderr)
    stage = stopped.group(1) if stopped else None
    if stage and r.stdout:
        assert r.stdout.startswith("mechanism: fix O 0 0; fix A 4 0;")
        assert r.stdout.endswith(f"not finished: {stage}: interrupted by the time limit, and the steps after it\n")
    if stage == "decomposition":
        assert 'analyze(m, "text", "quick") gives the singular configurations' in r.stdout


def test_stage_benchmark_measures_the_stages():
    """benchmarks/analysis_stages.py: mech's stages from the progress events, Singular's script."""
    import importlib.util
    from tests.util import ROOT
    spec = importlib.util.spec_from_file_location("analysis_stages", ROOT / "benchmarks" / "analysis_stages.py")
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    spent, total, a = bench.mech_stages(bench.CASES[0])  # the kite
    assert {"dimension", "decomposition", "singular configurations"} <= set(spent) and total > 0
    assert {"points", "local components", "tangent cones"} <= set(spent)
    scripts = bench.singular_script(a, "full")
    assert len(scripts) == 3  # the decomposition and the local components in processes of their own
    assert "minAssGTZ(J);" in scripts[2] and "minor(D, 5)" in scripts[0] and "tangentcone(" in scripts[0]
    assert "int t;" not in "".join(scripts)  # an int t would stand for the parameter t of Q(t)
    if SINGULAR:
        got = bench.singular_stages(scripts, 120)
        assert set(got) == {"dimension", "decomposition", "singular configurations", "points", "local components",
                            "tangent cones"}
        assert all(v is not None for v in got.values())



WATT_I_B = "ground O A 4; body O B 3 0 E 1 2; body B C 4 0 F 1 2; bar C A 3; bar E H 2; bar H F 3"
STEPHENSON = "ground O A 1; fix G 2 0; bar O B 1; body B C 1 0 E 0 1; bar C A 1; bar E F 1; bar F G 1"
# their J written by hand, in (c1,s1,...,c5,s5).  Watt I: B = 3(c1,s1), C = B + 4(c2,s2) = A - 3(c3,s3),
# E = R1(1,2), F = B + R2(1,2), H = E + 2(c4,s4) = F - 3(c5,s5).  Stephenson: C = (c1,s1) + (c2,s2) =
# A - (c3,s3), E = (c1,s1) + R2(0,1), F = E + (c4,s4) = G - (c5,s5).
HAND_J = {
    WATT_I_B: "3*c1+4*c2+3*c3-4, 3*s1+4*s2+3*s3, c1-2*s1+2*c4+3*c5-(3*c1+c2-2*s2), s1+2*c1+2*s4+3*s5-(3*s1+s2+2*c2)",
    STEPHENSON: "c1+c2+c3-1, s1+s2+s3, c1-s2+c4+c5-2, s1+c2+s4+s5",
}
CIRCLES = ", c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1, c4^2+s4^2-1, c5^2+s5^2-1"
SLICE = "3*c1-7*s1+2*c2+5*s2-4*c3+9*s3-3*c4+8*s4+5*c5-6*s5-2"  # a random affine hyperplane, not one of mech's
DEGREES = {WATT_I_B: [6, 10], STEPHENSON: [2, 2, 2, 6, 6]}


def _image(mechanism: str):
    from mech.kernel.slices import curve_image
    from mech.stdlib.analysis import constraint_ideal
    R, J, _ = constraint_ideal(parse_mechanism(mechanism))
    return curve_image(J, R)


@pytest.mark.parametrize("mechanism", [WATT_I_B, STEPHENSON])
def test_six_bars_mode_count_by_projection(mechanism):
    """The projection interpolated from slices proves the number of modes and their degrees."""
    image = _image(mechanism)
    assert image.degree == sum(DEGREES[mechanism])
    assert sorted(g.total_degree() for g in image.factors) == DEGREES[mechanism]


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular not installed")
@pytest.mark.parametrize("mechanism", [WATT_I_B, STEPHENSON])
def test_six_bars_mode_count_against_singular(mechanism):
    """Degree bookkeeping in Singular on a hand-written J: dimension 1, deg V (vdim of a random
    linear slice), and the slice's minimal primes (its Galois orbits: for a generic slice one per
    mode, of the mode's degree) against the degrees of mech's modes."""
    out = run_singular('LIB "primdec.lib";\nring r = 0, (c1,s1,c2,s2,c3,s3,c4,s4,c5,s5), dp;\nideal J = '
                       + HAND_J[mechanism] + CIRCLES + f";\ndim(std(J)); ideal S = std(J + ({SLICE})); vdim(S);\n"
                       'list L = minAssGTZ(S); int i; for (i = 1; i <= size(L); i++) { vdim(std(L[i])); }',
                       timeout=300)
    nums = [int(x) for x in out.split()]
    image = _image(mechanism)
    assert nums[:2] == [1, image.degree]
    assert sorted(nums[2:]) == sorted(g.total_degree() for g in image.factors) == DEGREES[mechanism]


def test_proved_mode_count_is_reported_when_the_ideals_run_out(monkeypatch):
    """With budgets too short for minAssGTZ and for the saturations, the report still gives the
    number of modes and their degrees that the projection proved, and the singular configurations."""
    import dataclasses
    from mech.stdlib import modes
    monkeypatch.setattr(modes, "SPLIT_BUDGET", 0.2)
    monkeypatch.setattr(modes, "IDEALS_BUDGET", 0.2)
    monkeypatch.setattr(modes, "STRATEGIES", [dataclasses.replace(s, budget=0.2) if s.name == "minimal primes" else s
                                              for s in modes.STRATEGIES])
    a = analyze(parse_mechanism(WATT_I_B))
    assert a.mode_degrees == [6, 10] and not a.modes_found and len(a.singular) == 2
    text = report_text(a)
    assert "motion modes: 2, curves of degrees 6, 10 (proved by a projection" in text
    assert "local components not computed: the motion modes were not found" in text
    assert report_data(a)["motion_mode_degrees"] == [6, 10]


@pytest.mark.parametrize("mechanism", [WATT_I_B, STEPHENSON])
def test_six_bars_get_their_mode_ideals(mechanism):
    """The projection's modes get their prime ideals (mech.kernel.curve_ideals), and with them the
    local components at every singular configuration."""
    a = _analysis(mechanism)
    assert a.modes_found and a.mode_degrees == DEGREES[mechanism]
    assert sorted(len(m.prime) and _curve_degree(m.prime, a.ring) for m in a.modes) == DEGREES[mechanism]
    assert all(m.dim == 1 for m in a.modes) and a.singular
    assert all(sp.local_components for sp in a.singular)
    text = report_text(a)
    assert "certified by a projection interpolated from slices" in text and "not computed" not in text.split("real answers")[0]


@functools.lru_cache(maxsize=None)
def _analysis(mechanism: str):
    return analyze(parse_mechanism(mechanism))


def _curve_degree(prime, R):
    from mech.kernel.ideals import std
    from mech.kernel.projection import variety_degree
    return variety_degree(std(prime, R), R)


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular not installed")
@pytest.mark.parametrize("mechanism", [WATT_I_B, STEPHENSON])
def test_six_bar_mode_ideals_against_singular(mechanism):
    """In Singular, on the hand-written J: each mode's ideal contains J, has dimension 1 and the
    proved degree, and the modes intersect in J (minAssGTZ of J itself does not finish in 300 s)."""
    from mech.dsl.printing import poly_str
    a = _analysis(mechanism)
    script = ('LIB "primdec.lib";\nring r = 0, (c1,s1,c2,s2,c3,s3,c4,s4,c5,s5), dp;\nideal J = std(ideal('
              + HAND_J[mechanism] + CIRCLES + "));\n")
    for k, m in enumerate(a.modes):
        script += f"ideal P{k} = std(ideal(" + ", ".join(poly_str(g) for g in m.prime) + "));\n"
        script += f"size(reduce(J, P{k}, 1)); dim(P{k}); mult(P{k});\n"
    script += "ideal I = intersect(" + ", ".join(f"P{k}" for k in range(len(a.modes))) + ");\n"
    script += "size(reduce(I, J, 1)) + size(reduce(J, std(I), 1));\n"
    nums = [int(x) for x in run_singular(script, timeout=300).split()]
    per = [nums[3 * k:3 * k + 3] for k in range(len(a.modes))]
    assert all(z == 0 and d == 1 for z, d, _ in per)
    assert sorted(deg for _, _, deg in per) == DEGREES[mechanism]
    assert nums[-1] == 0 and len(nums) == 3 * len(a.modes) + 1


GEARED_FIVEBAR = "ground O Q 2; bar O A 1; bar Q B 1; bar A C 2; bar B C 2; gear O Q 2"


def test_mode_generators_of_a_prime_J_are_Js_own():
    """A radical J with one mode is that mode's prime: the real answers take J's 8 generators of
    degree <= 2 (the prime's reduced basis has 17, up to degree 4: the algebra of the critical points
    of its real circuits took 20 s, from J 0.2 s); a non-radical J's mode keeps its prime."""
    from mech.kernel.ideals import dp_ring, move
    from mech.kernel.real_curve import _critical_algebra
    from mech.stdlib.analysis import mode_generators
    from flint import fmpq
    a = analyze(parse_mechanism(GEARED_FIVEBAR))
    gens = mode_generators(a, 1)
    assert gens == list(a.ideal) and len(a.modes[0].prime) == 17
    assert ideals_equal(gens, a.modes[0].prime, a.ring)
    R = dp_ring(a.ring)
    algebra = _critical_algebra(move(gens, R), R, [fmpq(k) for k in (1, 2, -1, 3, 1, -2, 2, 1)])
    assert algebra is not None and len(algebra.monomials) == 40
    b = analyze(parse_mechanism(DOUBLE_PARALLELOGRAM))
    assert mode_generators(b, 1) == b.modes[0].prime


WATT = "ground O A 1; fix G 2 0; bar O B 1; bar B C 1; body A C 1 0 E 0 1; bar E F 1; bar F G 1"


@pytest.mark.parametrize("mechanism, orbits, short_try", [
    (STEPHENSON, [2, 2, 2, 6, 6], False),  # modes of degree 6: the interpolated projection first
    (WATT, [2] * 8, True),                 # eight conics: minAssGTZ at once
])
def test_slice_orbits_order_the_strategies(monkeypatch, mechanism, orbits, short_try):
    """A slice's Galois orbit of many points lies on a mode of high degree: the short minAssGTZ try is
    skipped for the projection; the modes are the same either way (the other tests check them)."""
    from mech.stdlib import modes
    budgets = []
    real = modes._by_min_ass
    monkeypatch.setattr(modes, "STRATEGIES", [dataclasses.replace(s, run=lambda a, b=s.budget: (budgets.append(b), real(a))[1])
                                              if s.name == "minimal primes" else s for s in modes.STRATEGIES])
    a = analyze(parse_mechanism(mechanism))
    assert a.slice_orbits == orbits and a.modes_found and len(a.modes) == len(orbits)
    assert (budgets == [2]) if short_try else (budgets == [])
    assert a.modes_by == ("minimal primes of J" if short_try
                          else "minimal primes of J, certified by a projection interpolated from slices")


def test_small_rings_try_the_reduction_and_min_ass_first():
    """A kite (6 variables): the reduction to dimension zero runs before the slice and finds its two modes,
    the minimal primes of J (as minAssGTZ gives them); the short minAssGTZ try also comes before the slice."""
    from mech.stdlib import modes
    a = analyze(parse_mechanism("ground O A 1; bar O B 1; bar B C 2; bar C A 2"))
    assert a.ring.nvars <= modes.SMALL and a.slice_orbits is None and len(a.modes) == 2
    assert a.modes_by == "minimal primes of J"
    found = modes._by_reduction(a)
    assert sorted(map(str, found)) == sorted(map(str, min_ass_gtz(a.ideal, a.ring)))
    assert [s.name for s in modes._chain(a)][:3] == ["reduction", "minimal primes", "slice"]


def test_the_reduction_declines_when_a_mode_lies_where_h_vanishes():
    """x*y over K(u) for one variable u misses the line u = 0: the degrees (1 against 2) say so, and the
    chain goes on to minAssGTZ."""
    import types
    from mech.stdlib import modes
    R = ring(["x", "y"], [Block("dp", 2)])
    x, y = R.gens()
    assert modes._by_reduction(types.SimpleNamespace(ring=R, ideal=[x * y])) is None
    two = modes._by_reduction(types.SimpleNamespace(ring=R, ideal=[x * y - 1, x - y]))  # two points
    assert two is not None and sorted(map(str, two)) == sorted(map(str, min_ass_gtz([x * y - 1, x - y], R)))
