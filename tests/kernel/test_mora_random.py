"""Random local standard bases (``ds`` over Z/32003): the compiled Mora loop against the
pure-Python one (the same bases term by term, the same reduction steps, with and without the
trial cuts that make the reductions run in ``K[x]/m^(cut+1)``), and the ``auto`` policy and
Mora against Lazard's method (homogenize, F4, dehomogenize: an independent route) by their
leading ideals.  One sum of curves in separate variables coupled by their sum (the shape of
``tjurina`` in Singular's vdim_overflow test) is checked against Singular itself."""
import random

import pytest
from tests.util import SINGULAR, ideal_blocks, parse_poly, run_singular

from mech.kernel import GF, Block, MonomialOrder, PolyRing
from mech.kernel import mora_compiled
from mech.kernel.engines import clear_cache, standard_basis
from mech.kernel.hilbert import minimal_monomials
from mech.kernel.mora import Budget, BudgetExceeded, mora, positive_dimensional
from mech.kernel.poly import Poly

P = 32003


def _ring(n: int) -> PolyRing:
    return PolyRing(GF(P), [f"x{i}" for i in range(n)], MonomialOrder([Block("ds", n)]))


def _random_ideal(seed: int) -> tuple[PolyRing, list[Poly]]:
    """2-4 variables, as many generators as variables give or take one, each with a term of
    degree 1-3 and up to three of degree 2-7."""
    rnd = random.Random(seed)
    n = rnd.choice([2, 3, 3, 4])
    R = _ring(n)
    gens = []
    for _ in range(max(1, n + rnd.choice([-1, 0, 0, 1]))):
        terms = {}
        for low, high in [(1, 3)] + [(2, 7)] * rnd.randint(1, 3):
            d = rnd.randint(low, high)
            e = [0] * n
            for _ in range(d):
                e[rnd.randrange(n)] += 1
            terms[tuple(e)] = R.field(rnd.randrange(1, P))
        gens.append(Poly(R, terms))
    return R, gens


def _leading_ideal(basis, R) -> list:
    key = R.order.key
    return sorted(minimal_monomials([max(b, key=key) if isinstance(b, dict) else b.lm() for b in basis]))


SEEDS = range(40)


def _mora_within(gens, R, steps, trials=True):
    """Mora's basis and the steps left, or None and -1 when it runs out of ``steps`` (some
    ideals drive Mora's normal form into high degrees: the policy then turns to Lazard)."""
    budget = Budget(steps)
    try:
        return mora(gens, R, budget, shared=True, trials=trials), budget.steps
    except BudgetExceeded:
        return None, -1


@pytest.mark.skipif(mora_compiled.C is None, reason="the C extension _mora is not built")
@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("trials", [True, False])
def test_compiled_loop_is_the_python_loop(seed, trials, monkeypatch):
    R, gens = _random_ideal(seed)
    compiled = _mora_within(gens, R, 5000, trials)
    monkeypatch.setattr(mora_compiled, "C", None)
    assert _mora_within(gens, R, 5000, trials) == compiled


@pytest.mark.parametrize("seed", SEEDS)
def test_auto_and_mora_have_the_leading_ideal_of_lazard(seed):
    R, gens = _random_ideal(seed)
    clear_cache()
    lazard = _leading_ideal(standard_basis(gens, R, "lazard"), R)
    assert _leading_ideal(standard_basis(gens, R), R) == lazard
    basis, _ = _mora_within(gens, R, 10**5)
    if basis is not None:
        assert _leading_ideal(basis, R) == lazard
    if positive_dimensional(gens):  # Krull: no pure power of some variable leads
        assert any(not any(m[i] == sum(m) for m in lazard) for i in range(R.nvars))


@pytest.mark.parametrize("compiled", [True, False])
def test_each_element_comes_with_its_leading_monomial_first(compiled, monkeypatch):
    """:func:`.mora.finished` reads the leading monomial as the first key of each dict."""
    if not compiled:
        monkeypatch.setattr(mora_compiled, "C", None)
    for seed in range(10):
        R, gens = _random_ideal(seed)
        basis, _ = _mora_within(gens, R, 5000)
        for b in basis or []:
            assert next(iter(b)) == max(b, key=R.order.key)


def test_most_random_ideals_finish_in_mora():
    finished = [_mora_within(*reversed(_random_ideal(seed)), 5000)[0] is not None for seed in SEEDS]
    assert sum(finished) >= 30


@pytest.mark.parametrize("compiled", [True, False])
def test_a_sugar_bound_stops_a_runaway_early(compiled, monkeypatch):
    """Seed 12 drives Mora's normal form from degree 7 to degree 85 (the policy then turns to
    Lazard); with ``Budget(degree=4)`` it stops on the sugar, steps to spare."""
    if not compiled:
        monkeypatch.setattr(mora_compiled, "C", None)
    R, gens = _random_ideal(12)
    budget = Budget(20_000, degree=4)
    with pytest.raises(BudgetExceeded):
        mora(gens, R, budget, shared=True, trials=False)
    assert budget.steps > 0
    R, gens = _random_ideal(0)
    assert mora(gens, R, Budget(20_000, degree=6), shared=True) == mora(gens, R, Budget(20_000), shared=True)


CURVES = 3
SUM = "+".join(f"y{k}^7-x{k}^9+x{k}^4*y{k}^4" for k in range(1, CURVES + 1))


@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
def test_sum_of_curves_matches_singular():
    names = [f"x{k}" for k in range(1, CURVES + 1)] + [f"y{k}" for k in range(1, CURVES + 1)]
    R = PolyRing(GF(P), names, MonomialOrder([Block("ds", len(names))]))
    script = f"ring r = {P}, ({','.join(names)}), ds;\npoly g = {SUM};\nideal I = jacob(g), g;\nlead(std(I));\n"
    singular = sorted(parse_poly(R, m).lm() for m in ideal_blocks(run_singular(script))[0])
    g = parse_poly(R, SUM)
    gens = [g.diff(i) for i in range(len(names))] + [g]
    assert len(singular) == 19
    assert sorted(b.lm() for b in standard_basis(gens, R)) == singular
