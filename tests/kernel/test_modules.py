"""Submodules of free modules (kernel/modules.py): Gröbner bases (lead terms checked against
Macaulay2 1.21's ``gens gb``), syzygies, minimal generators, lifts and minimal free resolutions
(checked by their defining properties and by the Betti numbers of Koszul complexes)."""
from __future__ import annotations

from math import comb

from mech.kernel import Block, GF
from mech.kernel import modules as K
from tests.util import ring


def _setup(n=3, field=None):
    names = ["x", "y", "z", "w"][:n]
    R = ring(names, [Block("dp", n)]) if field is None else ring(names, [Block("dp", n)], field)
    return R, R.gens()


def _cols(rows):
    return [K.vector([r[j] for r in rows]) for j in range(len(rows[0]))]


def _apply(R, cols, rank, coeffs):
    """sum_j coeffs[j] * cols[j] as a list of entries."""
    out = [R.zero()] * rank
    for c, v in zip(coeffs, cols):
        for i, p in enumerate(K.entries(v, R, rank)):
            out[i] = out[i] + c * p
    return out


def test_groebner_basis_of_a_submodule_is_macaulay2s() -> None:
    # Macaulay2 1.21: gens gb matrix {{x^2, x*y}, {y^2, z^2}} is {{x*y, x^2, 0}, {z^2, y^2, y^3-x*z^2}}
    R, (x, y, z) = _setup()
    G = K.groebner_basis(R, 2, _cols([[x**2, x * y], [y**2, z**2]]))
    got = [K.entries(g, R, 2) for g in G]
    assert got == [[x * y, z**2], [x**2, y**2], [R.zero(), y**3 - x * z**2]]


def test_term_over_position_breaks_ties_by_the_larger_component() -> None:
    # Macaulay2: leadTerm matrix {{x}, {x}} is {{0}, {x}}
    R, (x, y, z) = _setup()
    G = K.ModuleGB(R, 2)
    G.add(_cols([[x], [x]]))
    assert G.leads == [((1, 0, 0), 1)]


def test_membership_and_lift() -> None:
    R, (x, y, z) = _setup()
    gens = _cols([[x, y], [y, z]])
    f = K.vector([x * z + y**2, 2 * y * z])          # z * (x, y) + y * (y, z)
    coeffs = K.lift(R, 2, gens, f)
    assert coeffs is not None and _apply(R, gens, 2, coeffs) == K.entries(f, R, 2)
    assert K.lift(R, 2, gens, K.vector([x, R.zero()])) is None


def test_syzygies_annihilate_and_generate() -> None:
    R, (x, y, z) = _setup()
    gens = _cols([[x**2, x * y, y**2]])
    S = K.minimal_generators(R, 3, K.syzygies(R, 1, gens), [2, 2, 2])
    assert len(S) == 2
    for s in S:
        assert _apply(R, gens, 1, K.entries(s, R, 3)) == [R.zero()]
    # the syzygy (y^2, 0, -x^2) of x^2, xy, y^2 is a combination of the two minimal ones
    assert K.lift(R, 3, S, K.vector([y**2, R.zero(), -x**2])) is not None


def test_koszul_resolution_has_binomial_betti_numbers() -> None:
    R, X = _setup(4, GF(101))
    maps = K.resolution(R, 1, [K.vector([v]) for v in X], [0])
    assert [len(cols) for cols, _ in maps] == [comb(4, k) for k in range(1, 5)]
    assert [set(d) for _, d in maps] == [{k} for k in range(1, 5)]
    ranks = [1] + [len(cols) for cols, _ in maps]
    for i in range(len(maps) - 1):   # d_(i+1) d_(i+2) = 0
        for col in maps[i + 1][0]:
            image = _apply(R, maps[i][0], ranks[i], K.entries(col, R, ranks[i + 1]))
            assert all(p.is_zero() for p in image)


def test_twisted_cubic_resolution() -> None:
    # the 2x2 minors of {{a,b,c},{b,c,d}}: Betti numbers 1, 3 (degree 2), 2 (degree 3)
    R, (a, b, c, d) = _setup(4)
    I = [a * c - b**2, a * d - b * c, b * d - c**2]
    maps = K.resolution(R, 1, [K.vector([g]) for g in I], [0])
    assert [d for _, d in maps] == [[2, 2, 2], [3, 3]]


def test_unit_relations_drop_generators() -> None:
    R, (x, y, z) = _setup()
    cols, degrees = K.drop_unit_relations(R, _cols([[R.one(), x], [R.zero(), y]]), [0, 0])
    assert degrees == [0] and [K.entries(c, R, 1) for c in cols] == [[y]]


def test_eagon_northcott_resolution_of_maximal_minors() -> None:
    # the 2x2 minors of a generic 2x4 matrix: Betti numbers 1, 6 (degree 2), 8 (3), 3 (4), as
    # the Eagon-Northcott complex has them (Macaulay2 1.21: the same betti res)
    S = ring([f"v{i}" for i in range(8)], [Block("dp", 8)])
    v = S.gens()
    top, bottom = v[:4], v[4:]
    minors = [top[i] * bottom[j] - top[j] * bottom[i] for i in range(4) for j in range(i + 1, 4)]
    maps = K.resolution(S, 1, [K.vector([g]) for g in minors], [0])
    assert [sorted(d) for _, d in maps] == [[2] * 6, [3] * 8, [4] * 3]
