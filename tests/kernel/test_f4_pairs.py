"""F4's pair set (kernel/f4_pairs.py): the compiled set (kernel/_f4pairs.c) takes the same steps
as the pure-Python one, and the Gebauer–Möller criteria keep what Buchberger's criterion needs."""
import random

import pytest

from mech.kernel import Block, MonomialOrder, f4_pairs
from mech.kernel.f4_pairs import PairSet, pair_set
from mech.kernel.monomials import Packing

compiled = pytest.mark.skipif(f4_pairs._Compiled is None, reason="the compiled pair set is not built")


def run(pairs, P, leads, sugars, rng):
    """Feed elements one by one (some as input rows), taking pairs now and then; the log of
    everything the set returned."""
    log, active = [], []
    for k, (e, s) in enumerate(zip(leads, sugars)):
        pairs.add(P.pack(e), s)
        active.append(False)
        if rng.random() < 0.2:
            pairs.push(sum(e), k)
            log.append(("push", k))
            continue
        log.append(("update", k, pairs.update(k, active), list(active)))
        if rng.random() < 0.3 and len(pairs):
            if rng.random() < 0.5:
                log.append(("take", pairs.lowest(), pairs.take()))
            else:  # as F4's rows
                log.append(("take_rows", pairs.lowest(), pairs.take_rows()))
    log.append(("rest", len(pairs), pairs.everything(), pairs.minimal(active)))
    return log


@compiled
@pytest.mark.parametrize("maxdeg", [63, 100000], ids=["one word", "wider"])  # packed rows from 64-bit words or ints
@pytest.mark.parametrize("order", ["dp", "lp", "block"])
@pytest.mark.parametrize("seed", range(6))
def test_compiled_and_python_pair_sets_agree(order, seed, maxdeg):
    rng = random.Random(seed)
    n = rng.choice([2, 3, 5, 7])
    if order == "block":
        mo = MonomialOrder([Block("dp", n - 1), Block("dp", 1)]) if n > 1 else MonomialOrder.simple("dp", n)
    else:
        mo = MonomialOrder.simple(order, n)
    P = Packing(mo, maxdeg)
    leads = [tuple(rng.randrange(5) for _ in range(n)) for _ in range(40)]
    leads = [e if any(e) else (1,) + e[1:] for e in leads]
    sugars = [sum(e) + rng.randrange(3) for e in leads]
    by_weight = order != "lp"
    ours = run(pair_set(P, by_weight), P, leads, sugars, random.Random(seed))
    theirs = run(PairSet(P, by_weight), P, leads, sugars, random.Random(seed))
    assert ours == theirs


@pytest.fixture(params=[True, False], ids=["compiled", "python"])
def use_compiled(request, monkeypatch):
    """Each test once with the compiled pair set and once with the pure-Python one."""
    if not request.param:
        monkeypatch.setattr(f4_pairs, "_Compiled", None)
    elif f4_pairs._Compiled is None:
        pytest.skip("the compiled pair set is not built")
    return request.param


def test_overflow_leaves_the_set_unchanged(use_compiled):
    P = Packing(MonomialOrder.simple("dp", 2), 7)
    pairs = pair_set(P, True)
    active = [False, False]
    pairs.add(P.pack((5, 0)), 5)
    assert pairs.update(0, active) and active == [True, False]
    pairs.add(P.pack((0, 5)), 5)
    assert pairs.update(1, active)  # coprime: no pair, its lcm (degree 10) not even formed
    pairs.add(P.pack((3, 3)), 6)
    active.append(False)
    assert not pairs.update(2, active)  # lcms x^5 y^3 and x^3 y^5 of degree 8 > 7
    assert active == [True, True, False] and len(pairs) == 0


def _three_quadrics():
    """The packing, the pair set and the activity flags after adding x^2, xy, y^2 in turn."""
    P = Packing(MonomialOrder.simple("dp", 2), 63)
    pairs = pair_set(P, True)
    active = []
    for k, e in enumerate([(2, 0), (1, 1), (0, 2)]):
        pairs.add(P.pack(e), 2)
        active.append(False)
        assert pairs.update(k, active)
    return P, pairs, active


def test_criteria_on_a_small_example(use_compiled):
    """x^2, xy, y^2: the pairs (x^2, xy) and (xy, y^2) of lcm degree 3 survive, (x^2, y^2) is
    coprime (Buchberger's first criterion drops it)."""
    P, pairs, active = _three_quadrics()
    got = sorted((key, P.unpack(L), i, j) for key, L, i, j in pairs.everything())
    assert got == [(3, (1, 2), 1, 2), (3, (2, 1), 0, 1)]
    assert pairs.lowest() == 3 and len(pairs.take()) == 2 and pairs.lowest() is None


def test_rows_of_pairs(use_compiled):
    """Leading monomials x^2, xy, y^2: the pairs (0, 1) and (1, 2), of lcms x^2 y and x y^2, each
    give the row of their first element as the lcm's reducer and the other as a row to reduce."""
    P, pairs, active = _three_quadrics()
    assert pairs.minimal(active) == [0, 1, 2]
    d, pivots, rows = pairs.take_rows()
    got_pivots = {P.unpack(L): (k, P.unpack(u)) for L, (k, u) in pivots.items()}
    assert d == 3 and len(pairs) == 0
    assert got_pivots == {(2, 1): (0, (0, 1)), (1, 2): (1, (0, 1))}
    assert sorted((k, P.unpack(u)) for k, u in rows) == [(1, (1, 0)), (2, (1, 0))]


def test_minimal_elements(use_compiled):
    """Active x, xy, y^2 and inactive 1: x divides xy (dropped); of two equal leading monomials
    the first stays."""
    P = Packing(MonomialOrder.simple("dp", 2), 63)
    pairs = pair_set(P, True)
    for e in [(1, 0), (1, 1), (0, 2), (0, 0), (0, 2)]:
        pairs.add(P.pack(e), sum(e))
    assert pairs.minimal([True, True, True, False, True]) == [0, 2]
    assert pairs.minimal([False, True, False, False, True]) == [1, 4]
