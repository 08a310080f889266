"""Real roots of univariate polynomials: isolation (VCA) against Sturm counts and flint's certified
complex roots, refinement, exact rational roots, multiplicities and signs at roots."""
from __future__ import annotations

import random

import pytest
from flint import fmpq, fmpq_poly, fmpz_poly

from mech.kernel.real_solve import decimal
from mech.kernel.real_roots import (RealSolvingError, count_real_roots, isolate_real_roots, sign_at,
                                    squarefree_decomposition, sturm_count, sturm_sequence)


def _poly(*roots_and_factors):
    out = fmpz_poly([1])
    for f in roots_and_factors:
        out *= fmpz_poly(f)
    return out


def test_isolation_on_a_known_polynomial():
    # (x^2 - 2) (x^2 + 1) (x - 3)^2 (2x + 1) x
    f = _poly([-2, 0, 1], [1, 0, 1], [-3, 1], [-3, 1], [1, 2], [0, 1])
    roots = isolate_real_roots(f)
    assert [r.multiplicity for r in roots] == [1, 1, 1, 1, 2]
    assert [r.exact for r in roots] == [None, fmpq(-1, 2), fmpq(0), None, fmpq(3)]
    assert [round(float(r), 12) for r in roots] == [-1.414213562373, -0.5, 0.0, 1.414213562373, 3.0]
    for r in roots:  # isolating: the squarefree polynomial changes sign across the interval
        assert r.lo < r.hi and r.poly(r.lo) * r.poly(r.hi) < 0
    assert count_real_roots(f) == sturm_count(f) == 5
    assert count_real_roots(f, fmpq(0), fmpq(2)) == sturm_count(f, fmpq(0), fmpq(2)) == 1


def test_refinement_to_many_digits():
    r = isolate_real_roots([-2, 0, 1])[1]
    q = r.approx(62)
    assert abs(q * q - 2) < fmpq(1, 10 ** 61)
    assert decimal(q, 60) == "1.414213562373095048801688724209698078569671875376948073176680"
    narrow = r.refined(fmpq(1, 10 ** 30))
    assert narrow.hi - narrow.lo <= fmpq(1, 10 ** 30) and narrow.lo < q < narrow.hi


@pytest.mark.parametrize("seed", range(6))
def test_random_polynomials_against_flint_and_sturm(seed):
    rnd = random.Random(seed)
    for _ in range(40):
        f = fmpz_poly([rnd.randint(-9, 9) for _ in range(rnd.randint(2, 14))])
        if f.degree() < 1:
            continue
        f *= fmpz_poly([rnd.randint(-3, 3), rnd.randint(1, 3)]) ** rnd.randint(1, 3)
        roots = isolate_real_roots(f)
        flint_real = sorted((c for c, _ in f.complex_roots() if c.imag.is_zero()), key=lambda c: float(c.real.mid()))
        assert len(roots) == len(flint_real) == sturm_count(f)
        for r, c in zip(roots, flint_real):
            assert r.ball(256).overlaps(c.real)
        assert all(a.hi <= b.lo for a, b in zip(roots, roots[1:]))


def test_signs_at_roots_are_exact():
    roots = isolate_real_roots(_poly([-2, 0, 1], [-3, 0, 1]))  # -sqrt3, -sqrt2, sqrt2, sqrt3
    x2_minus_2 = fmpq_poly([-2, 0, 1])
    assert [sign_at(x2_minus_2, r) for r in roots] == [1, 0, 0, 1]
    # x - 1.4142 is positive at sqrt2, x - 1.4143 negative: refinement decides
    assert sign_at([fmpq(-14142, 10000), 1], roots[2]) == 1
    assert sign_at([fmpq(-14143, 10000), 1], roots[2]) == -1
    assert sign_at([0, 1], roots[0]) == -1


def test_squarefree_decomposition_and_sturm_sequence():
    f = _poly([-1, 1], [-1, 1], [-1, 1], [2, 1])
    assert squarefree_decomposition(f) == [(fmpz_poly([2, 1]), 1), (fmpz_poly([-1, 1]), 3)]
    seq = sturm_sequence([0, -1, 0, 1])  # x^3 - x
    assert seq == [fmpq_poly([0, -1, 0, 1]), fmpq_poly([-1, 0, 3]), fmpq_poly([0, fmpq(2, 3)]), fmpq_poly([1])]


def test_zero_polynomial_is_refused():
    with pytest.raises(RealSolvingError):
        isolate_real_roots([0])
