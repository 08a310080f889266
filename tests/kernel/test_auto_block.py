"""``auto`` on positive-dimensional ideals in block orderings (kernel/engines.py): Buchberger's
budgeted attempt, which also counts S-polynomials (kernel/buchberger.py PAIR_WORK), then the
dimension read off the homogenized generators' ``dp`` basis (kernel/hilbert_driven.py
degree_leads) and the Hilbert-driven algorithm, without the ideal's own ``dp`` basis."""
import pytest

from mech.kernel import GF, QQ, Block, MonomialOrder, PolyRing
from mech.kernel import engines as E
from mech.kernel.buchberger import TooLong, buchberger, reduce_basis
from mech.kernel.engines import clear_cache, standard_basis
from mech.kernel.hilbert import minimal_monomials
from mech.kernel.hilbert_driven import _homogenized_basis, degree_leads
from mech.kernel.poly import Poly
from tests.util import ideal_blocks, parse_poly, run_singular

BLOCK = ["x^2+y*u-1", "y^2-x*v", "z^3-u^2*v", "x*y*z-u-v"]  # benchmarks/cases.py's block (dp(3),dp(2))


def block_ring(field=QQ, blocks=(("dp", 3), ("dp", 2))):
    return PolyRing(field, list("xyzuv"), MonomialOrder([Block(k, n) for k, n in blocks]))


def gens_of(R, texts):
    return [parse_poly(R, t) for t in texts]


def no_attempt(gens, ring):
    raise TooLong


@pytest.fixture
def degree_bases(monkeypatch):
    """The rings in which ``auto`` computes the ideal's own dp basis (no Buchberger attempt)."""
    seen = []
    original = E._degree_basis

    def spy(gens, ring):
        seen.append(ring)
        return original(gens, ring)
    monkeypatch.setattr(E, "_degree_basis", spy)
    monkeypatch.setattr(E, "_attempt", no_attempt)
    clear_cache()
    yield seen
    clear_cache()


def test_a_budget_counts_s_polynomials():
    """The block system's S-polynomials, most of them reducing to zero, exhaust the budget of auto
    (163 reductions to the old budget of 5000 when only reducer terms counted); the four-bar's small
    elimination still finishes."""
    R = block_ring()
    gens = gens_of(R, BLOCK)
    with pytest.raises(TooLong):
        buchberger(gens, R, E.SMALL_BUCHBERGER)
    four_bar = PolyRing(QQ, ["c1", "s1", "c2", "s2", "c3", "s3", "x", "y"],
                        MonomialOrder([Block("dp", 6), Block("dp", 2)]))
    fb = gens_of(four_bar, ["4+3*c3-2*c1-4*c2", "3*s3-2*s1-4*s2", "x-2*c1-2*c2+s2", "y-2*s1-2*s2-c2",
                            "c1^2+s1^2-1", "c2^2+s2^2-1", "c3^2+s3^2-1"])
    assert reduce_basis(buchberger(fb, four_bar, E.SMALL_BUCHBERGER), four_bar) == \
        reduce_basis(buchberger(fb, four_bar), four_bar)


@pytest.mark.parametrize("field", [QQ, GF(32003)])
def test_degree_leads_generate_the_leading_ideal_for_dp(field):
    R = block_ring(field)
    gens = gens_of(R, BLOCK + ["x*u-z^2"])
    dp = PolyRing(field, R.names, MonomialOrder([Block("dp", 5)]))
    ref = reduce_basis(buchberger([parse_poly(dp, t) for t in BLOCK + ["x*u-z^2"]], dp), dp)
    leads = degree_leads(gens, R, E._dp_auto)
    assert sorted(minimal_monomials(leads)) == sorted(max(b, key=dp.order.key) for b in ref)


@pytest.mark.parametrize("field", [QQ, GF(32003)])
def test_positive_dimensional_block_basis_without_the_ideals_dp_basis(degree_bases, field):
    R = block_ring(field)
    gens = gens_of(R, BLOCK)
    G = standard_basis(gens, R)
    assert [g.terms for g in G] == reduce_basis(buchberger(gens, R), R)
    dp_of_ideal = PolyRing(field, R.names, MonomialOrder([Block("dp", 5)]))
    assert dp_of_ideal not in degree_bases


def test_unit_ideal_found_from_the_homogenized_basis(degree_bases):
    """Fewer generators than variables: only the unit ideal has a finite quotient; auto then
    computes the dp basis ([1]) as before."""
    R = block_ring()
    G = standard_basis(gens_of(R, ["x*y-1", "x*z^2+u*v", "z^2-u-1", "x*u+x+u*v+1"]), R)
    assert G == [R.one()]
    assert degree_bases


@pytest.mark.singular
def test_block_eliminations_match_singular():
    orders = [(("dp", 3), ("dp", 2)), (("dp", 2), ("dp", 3)), (("lp", 3), ("dp", 2))]
    script = "option(redSB);\n" + "".join(
        f"ring r = {p}, (x,y,z,u,v), ({','.join(f'{k}({n})' for k, n in o)}); short = 0; "
        f"ideal i = {', '.join(BLOCK)}; std(i); kill r;\n" for o in orders for p in (0, 32003))
    blocks = ideal_blocks(run_singular(script))
    assert len(blocks) == 2 * len(orders)
    k = 0
    for o in orders:
        for field in (QQ, GF(32003)):
            R = block_ring(field, o)
            clear_cache()
            ours = standard_basis(gens_of(R, BLOCK), R)
            theirs = sorted((p.monic() for p in (parse_poly(R, t) for t in blocks[k]) if not p.is_zero()),
                            key=lambda p: R.order.key(p.lm()))
            assert ours == theirs, (o, field)
            k += 1


@pytest.mark.parametrize("field", [QQ, GF(32003)])
def test_the_homogenized_dp_basis_past_its_budget_goes_to_auto(field, monkeypatch):
    """The Hilbert series' dp basis: by the compiled Buchberger within HOMOGENEOUS_BUDGET, past it
    by ``auto`` (modular F4 over QQ): the same basis either way, kept as ``auto``'s."""
    R = block_ring(field)
    gens = gens_of(R, BLOCK)
    clear_cache()
    within = _homogenized_basis(gens, R, E._dp_homogeneous)[2]
    dp = within[0].ring
    hgens = [Poly(dp, g.terms) for g in _homogenized_basis(gens, R, E._dp_homogeneous)[1]]
    assert E.cached_standard_basis(hgens, dp, E.AUTO) == within
    monkeypatch.setattr(E, "HOMOGENEOUS_BUDGET", 1)
    clear_cache()
    assert _homogenized_basis(gens, R, E._dp_homogeneous)[2] == within
    clear_cache()
    assert [g.terms for g in standard_basis(gens, R)] == reduce_basis(buchberger(gens, R), R)
