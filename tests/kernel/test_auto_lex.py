"""``auto`` on positive-dimensional ideals in a lex ordering over Z/p: F4 on the lex ordering
within its budget (kernel/engines.py F4_BUDGET), else the Hilbert-driven algorithm; F4's
budget (kernel/f4.py) on both of its paths."""
import pytest

from mech.kernel import GF, Block, MonomialOrder, PolyRing, f4_rows
from mech.kernel import engines as E
from mech.kernel.buchberger import TooLong, buchberger, reduce_basis
from mech.kernel.engines import clear_cache, standard_basis
from mech.kernel.f4 import f4_modp

P = 32003


def rcyclic(n, order="lp"):
    """Singular's rcyclic-n (positive-dimensional: n - 1 generators in n variables)."""
    R = PolyRing(GF(P), [f"x{i}" for i in range(1, n + 1)], MonomialOrder([Block(order, n)]))
    X = R.gens()
    def prod(idx):
        t = R.one()
        for k in idx:
            t = t * X[k]
        return t
    gens = [X[0] + X[1] + X[2]]
    for d in range(2, n - 1):
        gens.append(prod(range(d)) + prod(range(1, d + 1)) + prod(range(2, d + 2)))
    gens.append(prod(range(n - 1)) + prod([0] + list(range(2, n))) + prod(range(1, n)))
    return R, gens


def reference(gens, R):
    return reduce_basis(buchberger(gens, R), R)


def no_attempt(gens, ring):
    raise TooLong


@pytest.fixture
def calls(monkeypatch):
    """Buchberger's first try skipped, and the engines ``auto`` reaches recorded."""
    seen = []
    f4, hd = E.f4_modp, E._hilbert_reduced

    def spy_f4(gens, ring, budget=float("inf")):
        seen.append(("f4", budget))
        return f4(gens, ring, budget)

    def spy_hd(gens, ring):
        seen.append(("hilbert", None))
        return hd(gens, ring)
    monkeypatch.setattr(E, "_attempt", no_attempt)
    monkeypatch.setattr(E, "f4_modp", spy_f4)
    monkeypatch.setattr(E, "_hilbert_reduced", spy_hd)
    clear_cache()
    yield seen
    clear_cache()


def test_auto_takes_f4_on_lex_for_positive_dimensional_ideals(calls):
    R, gens = rcyclic(7)
    G = standard_basis(gens, R)
    assert [g.terms for g in G] == reference(gens, R)
    assert ("f4", E.F4_BUDGET) in calls and ("hilbert", None) not in calls


def test_auto_leaves_f4_for_the_hilbert_driven_algorithm_past_the_budget(calls, monkeypatch):
    monkeypatch.setattr(E, "F4_BUDGET", 10)
    R, gens = rcyclic(6)
    G = standard_basis(gens, R)
    assert [g.terms for g in G] == reference(gens, R)
    assert calls[-2:] == [("f4", 10), ("hilbert", None)]


def test_block_orderings_stay_with_the_hilbert_driven_algorithm(calls):
    n = 6
    R = PolyRing(GF(P), [f"x{i}" for i in range(1, n + 1)], MonomialOrder([Block("dp", 3), Block("dp", 3)]))
    _, lex_gens = rcyclic(n)
    gens = [type(g)(R, g.terms) for g in lex_gens]
    G = standard_basis(gens, R)
    assert [g.terms for g in G] == reference(gens, R)
    assert ("f4", E.F4_BUDGET) not in calls and ("hilbert", None) in calls  # (F4 without budget: the dp basis)


@pytest.mark.parametrize("compiled", [True, False], ids=["compiled", "python"])
def test_f4_budget_raises_too_long(compiled, monkeypatch):
    if not compiled:
        monkeypatch.setattr(f4_rows, "KERNEL", None)
    elif f4_rows.KERNEL is None:
        pytest.skip("the compiled kernel is not built")
    R, gens = rcyclic(6)
    with pytest.raises(TooLong):
        f4_modp(gens, R, budget=50)
    assert f4_modp(gens, R, budget=10 ** 9) == reference(gens, R)
