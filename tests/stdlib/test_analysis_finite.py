"""The zero-dimensional path of ``analyze`` (stdlib/analysis_finite.py) agrees with the general path
(minimal primes by minAssGTZ, primdecGTZ's primary components, Theorem 1's Fitting ideal) on small rigid
mechanisms, radical or not, and says what it checked."""
from __future__ import annotations

import pytest

from mech.kernel.ideals import dimension, ideals_equal, std
from mech.kernel.primdec import min_ass_gtz
from mech.stdlib import analysis
from mech.stdlib.analysis import analyze, fitting_ideal
from mech.stdlib.mechanism import parse_mechanism
from mech.stdlib.reports import report_data, report_text

TRIANGLE = "fix O 0 0; fix Q 4 0; bar O A 5; bar Q A 3"          # A = (4, +-3): two rational points
IRRATIONAL = "fix O 0 0; fix Q 3 0; bar O A 2; bar Q A 2"        # A = (3/2, +-sqrt(7)/2): one orbit of 2
TANGENT = "fix O 0 0; fix Q 8 0; bar O A 5; bar Q A 3"           # A = (5, 0), a double point: J not radical
# the 3-RPR of docs/mechanisms.md (legs 5, 7, 4): 6 complex assembly modes, one Galois orbit, all real
RPR = "fix A1; fix A2 6 0; fix A3 0 5; bar A1 B1 5; bar A2 B2 7; bar A3 B3 4; body B1 B2 5 0 B3 4 3"
KEYS = ("dimension", "mobility", "radical", "motion_modes", "embedded_components", "singular", "complex_configurations",
        "assembly_modes", "equidimensional")


def _both(spec: str, monkeypatch) -> tuple[dict, dict]:
    new = report_data(analyze(parse_mechanism(spec)))
    with monkeypatch.context() as mp:
        mp.setattr(analysis, "finite_analysis", lambda a, mode: False)  # the general path
        old = report_data(analyze(parse_mechanism(spec)))
    return new, old


@pytest.mark.parametrize("spec", [TRIANGLE, IRRATIONAL, TANGENT, RPR])
def test_same_answers_as_the_general_path(spec, monkeypatch):
    new, old = _both(spec, monkeypatch)
    assert "assembly_orbits" in new and "assembly_orbits" not in old
    assert {k: new.get(k) for k in KEYS} == {k: old.get(k) for k in KEYS}


@pytest.mark.parametrize("spec, orbits", [
    (TRIANGLE, [(1, 1, 1, 4), (1, 1, 1, 4)]), (IRRATIONAL, [(2, 2, 1, 4)]), (TANGENT, [(1, 1, 2, 3)]),
    (RPR, [(6, 6, 1, 8)])])
def test_orbits(spec, orbits):
    """(configurations, real, multiplicity, Jacobian rank) per assembly mode; the rank is full exactly
    where the configuration is a simple solution (the Jacobian criterion)."""
    d = report_data(analyze(parse_mechanism(spec)))
    assert [(o["configurations"], o["real"], o["multiplicity"], o["jacobian_rank"])
            for o in d["assembly_orbits"]] == orbits
    assert d["radical"] == all(o[2] == 1 for o in orbits)
    assert all((o[3] == len(d["variables"])) == (o[2] == 1) for o in orbits)


def test_modes_are_the_minimal_primes_and_no_singular_configuration():
    """Independently of the report: the modes are minAssGTZ's primes of J, and V(J + I_n(dJ)) is empty for
    a radical J (the Fitting ideal the zero-dimensional path does not compute)."""
    a = analyze(parse_mechanism(RPR))
    R, J = a.ring, a.ideal
    primes = min_ass_gtz(J, R)
    assert len(primes) == len(a.modes) == 1 and ideals_equal(primes[0], a.modes[0].prime, R)
    assert dimension(J + fitting_ideal(J, a.nvars, a.nvars), R) == -1
    assert a.singular == [] and a.singular_done


def test_text_report():
    text = report_text(analyze(parse_mechanism(TRIANGLE)))
    assert ("mobility 0; J is radical\nassembly modes (Galois orbits of configurations over Q: the irreducible "
            "factors of the separating polynomial of t = s2): 2, of 1 and 1 configurations (1 and 1 real); "
            "2 complex configurations, 2 real\n") in text
    assert "the Jacobian of J has full rank 4 at all 2 configurations (checked exactly on each orbit)" in text
    text = report_text(analyze(parse_mechanism(TANGENT)))
    assert "1 complex configuration (2 with multiplicity), 1 real" in text
    assert "mode 1: the Jacobian of J has rank 3 < 4 at its configuration, of multiplicity 2" in text


def test_prime_basis_is_reduced():
    """The linear-algebra bases of the modes are the reduced Gröbner bases std computes."""
    a = analyze(parse_mechanism(IRRATIONAL))
    for md in a.modes:
        assert md.prime == std(md.prime, a.ring)
