"""The Hilbert-driven F4 (kernel/hilbert_driven.py ``hilbert_f4``, engine ``hilbert-f4``) on
both paths of the row kernel, and where ``auto`` uses it (kernel/engines.py FGLM_STAIRS)."""
from __future__ import annotations

import pytest
from tests.util import cyclic, katsura, ring

from mech.kernel import GF, QQ, Block, f4_rows
from mech.kernel import engines as E
from mech.kernel.engines import clear_cache, standard_basis
from mech.kernel.hilbert_driven import Counter

BLOCKS = [Block("dp", 3), Block("dp", 2)]


def _elim(field):
    R = ring("xyzuv", BLOCKS, field)
    x, y, z, u, v = R.gens()
    return R, [x * x + y * u - 1, y * y - x * v, z ** 3 - u * u * v, x * y * z - u - v]


@pytest.fixture(params=["compiled", "python"])
def path(request, monkeypatch):
    if request.param == "python":
        monkeypatch.setattr(f4_rows, "KERNEL", None)
    elif f4_rows.KERNEL is None:
        pytest.skip("the compiled kernel is not built")
    clear_cache()
    yield request.param
    clear_cache()


@pytest.mark.parametrize("field", [QQ, GF(32003)], ids=["QQ", "Z/p"])
def test_positive_dimensional_elimination_agrees_with_hilbert_driven_buchberger(path, field):
    if path == "python" and field == QQ:
        pytest.skip("20 s on the pure-Python path; its modular F4 is tested on the zero-dimensional cases")
    R, gens = _elim(field)
    G = standard_basis(gens, R, "hilbert-f4")
    assert G == standard_basis(gens, R, "hilbert") and len(G) == 40


@pytest.mark.parametrize("field", [QQ, GF(32003)], ids=["QQ", "Z/p"])
def test_zero_dimensional_block_and_lex_agree_with_fglm(path, field):
    R = ring("abcde", [Block("dp", 2), Block("dp", 3)], field)
    assert standard_basis(cyclic(R), R, "hilbert-f4") == standard_basis(cyclic(R), R, "fglm")
    R = ring("abcd", [Block("lp", 4)], field)
    gens = katsura(R, 3)
    assert standard_basis(gens, R, "hilbert-f4") == standard_basis(gens, R, "fglm")


def test_the_counter_stops_f4_early(path):
    """With the Hilbert series the run ends before the pairs do: fewer matrices than without."""
    from mech.kernel.f4 import F4, initial_degree, pack_polys
    from mech.kernel.hilbert import hilbert_numerators
    from mech.kernel.hilbert_driven import homogenize, homogenized_ring
    from mech.kernel.monomials import Packing
    R, gens = _elim(GF(32003))
    H = homogenized_ring(R)
    hgens = [homogenize(g, H) for g in gens]
    dp = ring("xyzuvh", [Block("dp", 6)], GF(32003))
    target = hilbert_numerators([b.lm() for b in standard_basis([type(g)(dp, g.terms) for g in hgens], dp)], 6)[0]
    P = Packing(H.order, initial_degree(hgens))
    rows = pack_polys(hgens, P, int)
    plain, driven = F4(rows, P, 32003, record=True), F4(rows, P, 32003, record=True, counter=Counter(target, 6))
    assert plain.run() == driven.run()
    assert len(driven.trace.steps) < len(plain.trace.steps)


def test_auto_sends_large_zero_dimensional_block_ideals_over_qq_to_hilbert_f4(monkeypatch):
    seen = []
    hf4 = E.hilbert_f4
    monkeypatch.setattr(E, "hilbert_f4", lambda *a: seen.append(1) or hf4(*a))
    monkeypatch.setattr(E, "FGLM_STAIRS", 20)  # cyclic-5 has 70 standard monomials
    clear_cache()
    R = ring("abcde", [Block("dp", 2), Block("dp", 3)], QQ)
    assert standard_basis(cyclic(R), R) == standard_basis(cyclic(R), R, "fglm") and seen
    seen.clear()
    clear_cache()
    R = ring("abcde", [Block("lp", 5)], QQ)  # lex stays with FGLM
    assert standard_basis(cyclic(R), R) == standard_basis(cyclic(R), R, "fglm") and not seen
    clear_cache()


def attempts(monkeypatch):
    """The rings in which ``auto`` makes Buchberger's budgeted attempt."""
    seen = []
    attempt = E._attempt
    monkeypatch.setattr(E, "_attempt", lambda gens, ring: seen.append(ring) or attempt(gens, ring))
    return seen


def test_auto_skips_buchbergers_attempt_on_zero_dimensional_lex_ideals(monkeypatch):
    seen = attempts(monkeypatch)
    clear_cache()
    R = ring("abcde", [Block("lp", 5)], GF(32003))
    G = standard_basis(katsura(R, 4), R)
    assert G == standard_basis(katsura(R, 4), R, "fglm") and not seen
    clear_cache()


def test_auto_tries_buchberger_first_only_with_fewer_generators_than_variables(monkeypatch):
    """Block orderings over QQ: katsura-3 (4 generators, 4 variables) goes to FGLM from its dp basis
    without Buchberger's budgeted attempt; the block system above (4 generators, 5 variables: a
    positive-dimensional ideal by Krull's theorem) gets the attempt first; over Z/p the dp basis
    always comes first."""
    seen = attempts(monkeypatch)
    clear_cache()
    R = ring("abcd", [Block("dp", 2), Block("dp", 2)], QQ)
    assert standard_basis(katsura(R, 3), R) == standard_basis(katsura(R, 3), R, "fglm")
    assert not seen
    clear_cache()
    R, gens = _elim(QQ)
    assert standard_basis(gens, R) == standard_basis(gens, R, "hilbert")
    assert seen == [R]
    seen.clear()
    clear_cache()
    R = ring("abcd", [Block("dp", 2), Block("dp", 2)], GF(32003))
    standard_basis(katsura(R, 3), R)
    assert not seen
    clear_cache()
