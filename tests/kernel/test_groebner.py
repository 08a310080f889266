"""Reduced Gröbner bases against Singular 4.3.1 (hard-coded truths in tests/data, live runs when
Singular is installed)."""
import pytest
from tests.util import ROOT, SINGULAR, cyclic, ideal_blocks, katsura, parse_poly, ring, run_singular

from mech.kernel import GF, Block, contains, normal_form
from mech.kernel.dimension import krull_dim
from mech.kernel.groebner import groebner

DATA = ROOT / "tests" / "data"


def cases():
    """(name, ring, generators) in the order of tests/data/groebner_truths.sing."""
    R = ring("xyz", [Block("dp", 3)])
    x, y, z = R.gens()
    yield "twisted cubic", R, [x**2 - y, x**3 - z]
    R = ring([f"x{i}" for i in range(5)], [Block("dp", 5)])
    yield "katsura-4", R, katsura(R, 4)
    R = ring("abcde", [Block("dp", 5)])
    yield "cyclic-5", R, cyclic(R)
    R = ring("xyzuv", [Block("dp", 3), Block("dp", 2)])
    x, y, z, u, v = R.gens()
    yield "block (dp(3),dp(2))", R, [x**2 + y * u - 1, y**2 - x * v, z**3 - u**2 * v, x * y * z - u - v]
    R = ring("xyz", [Block("dp", 3)], GF(32003))
    x, y, z = R.gens()
    yield "Z/32003", R, [2 * x**2 + 3 * y**2 - 5 * z, x**3 * y - 7 * z**2 + 1, 17 * x * y * z - y**3]


def truths():
    blocks = ideal_blocks((DATA / "groebner_truths.out").read_text())
    # the katsura block prints the input ideal I first
    return [blocks[0]] + blocks[2:]


@pytest.mark.parametrize("index", range(5))
def test_reduced_basis_matches_singular(index):
    name, R, gens = list(cases())[index]
    expected = [parse_poly(R, t).monic() for t in truths()[index]]
    assert groebner(gens) == expected, name


def test_basis_properties_cyclic5():
    _, R, gens = list(cases())[2]
    G = groebner(gens)
    assert len(G) == 20
    assert all(contains(G, g) for g in gens)
    assert krull_dim([g.lm() for g in G], R.nvars) == 0


def test_unit_zero_and_constant_ideals():
    R = ring("xy", [Block("dp", 2)])
    x, y = R.gens()
    assert groebner([x, x - 1]) == [R.one()]
    assert groebner([R.zero()]) == []
    assert groebner([R.const(3)]) == [R.one()]


def test_normal_form_and_dimension():
    R = ring("xyz", [Block("dp", 3)])
    x, y, z = R.gens()
    G = groebner([x**2 - y, x * y - z])
    assert normal_form(x**2, G) == y
    assert normal_form(x**3, G) == z
    assert krull_dim([g.lm() for g in G], 3) == 1
    assert krull_dim([g.lm() for g in groebner([x - 1, y, z**2])], 3) == 0
    assert krull_dim([], 3) == 3
    assert krull_dim([g.lm() for g in groebner([x, x + 1])], 3) == -1


def test_lex_basis_is_triangular():
    R = ring("xyz", [Block("lp", 3)])
    x, y, z = R.gens()
    G = groebner([x**2 + y**2 + z**2 - 1, x - y, y - z])
    assert [g.lm() for g in G] == [(0, 0, 2), (0, 1, 0), (1, 0, 0)]


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
def test_live_singular_agrees():
    script = (DATA / "groebner_truths.sing").read_text()
    blocks = ideal_blocks(run_singular(script))
    assert [blocks[0]] + blocks[2:] == truths()


def test_batched_normal_forms_and_membership():
    """normal_forms and contains_all pack the basis once and agree with normal_form one by one;
    the packing of an ordering and degree is shared."""
    from mech.kernel.groebner import contains_all, normal_forms
    from mech.kernel.monomials import packing
    R = ring("xyzuv", [Block("dp", 3), Block("dp", 2)])
    B = groebner([parse_poly(R, p) for p in ("x^2+y^2-u", "x*y-v", "z^3-x*u")], R)
    fs = [parse_poly(R, p) for p in ("x^3*y+z^4", "x^2*y^2-v^2", "u*z-1", "x^5")]
    assert normal_forms(fs, B) == [normal_form(f, B) for f in fs]
    inside = [B[0] * fs[0], B[1] * parse_poly(R, "z-u") + B[2]]
    assert contains_all(B, inside) and contains_all(B, []) and not contains_all(B, inside + [fs[2]])
    assert packing(R.order, 8) is packing(R.order, 8)
