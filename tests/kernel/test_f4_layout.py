"""F4's compiled symbolic preprocessing (kernel/_f4sym.c through f4_rows.Packed) against the
Python one (F4._layout) feeding the same compiled row reduction: the same reduced bases, traces
that replay, packing overflows found, on packings of one to three words."""
import random

import flint
import pytest

from mech.kernel import GF, Block, MonomialOrder, f4_rows
from mech.kernel.f4 import F4, PackingOverflow, is_groebner, pack_polys
from mech.kernel.f4_rows import Packed
from mech.kernel.f4_trace import replay
from mech.kernel.monomials import Packing
from tests.util import cyclic, katsura, ring

pytestmark = pytest.mark.skipif(f4_rows.LAYOUT is None, reason="the compiled kernel is not built")

P = 32003


def engines(gens, R, maxdeg, record=False):
    """An F4 run with the compiled layout and one with the Python layout (same packing)."""
    Pk = Packing(R.order, maxdeg)
    rows = [r for r in pack_polys(gens, Pk, lambda c: int(c)) if r[0]]
    fast = F4(rows, Pk, P, record)
    slow = F4(rows, Pk, P, record)
    slow.packed = None
    assert isinstance(fast.packed, Packed)
    return fast, slow, Pk, rows


@pytest.mark.parametrize("maxdeg", [7, 31, 1023, 100000])  # one to four words per monomial
def test_same_bases_as_the_python_layout(maxdeg):
    """(The reducers chosen may differ: the compiled layout takes the shortest divisor each time.)"""
    R = ring([f"x{i}" for i in range(5)], [Block("dp", 5)], GF(P))
    for gens in (katsura(R, 4), cyclic(R)):
        fast, slow, Pk, _ = engines(gens, R, maxdeg)
        assert fast.packed.nw == -(-Pk.bits // 64)
        assert outcome(fast) == outcome(slow)


def outcome(eng):
    """The basis, or "overflow" (a packing too narrow for the run)."""
    try:
        return eng.run()
    except PackingOverflow:
        return "overflow"


@pytest.mark.parametrize("blocks", [[Block("lp", 4)], [Block("dp", 2), Block("dp", 2)], [Block("Dp", 4)]],
                         ids=["lp", "block", "Dp"])
def test_random_systems_on_other_orderings(blocks):
    rng = random.Random(20)
    for _ in range(6):
        R = ring("abcd", blocks, GF(P))
        a, b, c, d = R.gens()
        mons = [a, b, c, d, a * b, c * d, a * c, b * d, a * a, d * d, a * b * c, b * c * d, R.one()]
        gens = [sum((R.field(rng.randrange(1, P)) * m for m in rng.sample(mons, 4)), R.zero()) for _ in range(3)]
        fast, slow, _, rows = engines(gens, R, 63)
        basis = fast.run()
        assert basis == slow.run()
        Pk = fast.P
        assert is_groebner(basis, Pk, P)


def test_trace_recorded_with_the_compiled_layout_replays():
    R = ring([f"x{i}" for i in range(5)], [Block("dp", 5)], GF(P))
    fast, slow, Pk, rows = engines(katsura(R, 4), R, 63, record=True)
    assert fast.run() == slow.run()
    q = 1000003
    lifted = [[int(c) % q for c in cs] for _, cs in rows]
    want = F4([(ms, cs) for (ms, _), cs in zip(rows, lifted)], Pk, q).run()
    assert replay(fast.trace, lifted, q) == [cs for _, cs in want]
    assert replay(slow.trace, lifted, q) == [cs for _, cs in want]


def test_overflow_of_the_packing_is_found():
    """Degree 7 generators in a packing for degree 7: the S-pairs' rows exceed it."""
    R = ring("xyz", [Block("dp", 3)], GF(P))
    x, y, z = R.gens()
    gens = [x**7 - y**3 * z**4, y**7 - x * z**6, z**7 - x**2 * y**5]
    for eng in engines(gens, R, 7)[:2]:
        assert outcome(eng) == "overflow"


def test_bad_arguments_are_errors():
    with pytest.raises(ValueError):
        f4_rows.LAYOUT(1, b"\0" * 8, 0, 8, 63, [b"\0" * 8], [0], [b""], [False], [], {})  # terms and coefficients disagree
    with pytest.raises(ValueError):
        f4_rows.LAYOUT(1, b"\0" * 8, 0, 8, 63, [b"\0" * 8], [0], [b"\1" + b"\0" * 7], [False], [(5, b"\0" * 8)], {})


def test_replays_through_plans_agree_with_rows_added_one_by_one(monkeypatch):
    """A recorded run's matrices replayed with their rows laid out once (f4_rows.Plan, the
    coefficients gathered in C), and again row by row: the same basis, the full replay too."""
    from mech.kernel.f4_trace import replay_full
    R = ring([f"x{i}" for i in range(5)], [Block("dp", 5)], GF(P))
    fast = engines(cyclic(R), R, 63, record=True)[0]
    fast.run()
    assert all("full" in st.plans for st in fast.trace.steps)
    q = 1000003
    coefs = [[(7 * c + 1) % q for c in cs] for cs in fast.coefs[:fast.trace.npolys]]
    with_plans = replay(fast.trace, coefs, q), replay_full(fast.trace, coefs, q)
    for st in fast.trace.steps + [fast.trace.final]:
        assert st.plans  # laid out by the replays
        st.plans.clear()
    monkeypatch.setattr(f4_rows, "GATHER", None)
    assert (replay(fast.trace, coefs, q), replay_full(fast.trace, coefs, q)) == with_plans
    assert all(not st.plans for st in fast.trace.steps)


def test_gather_checks_the_rows():
    from array import array
    rk, start, off = array("i", [0, 1]), array("i", [1, 0]), array("q", [0, 2, 3])
    assert array("Q", f4_rows.GATHER([[5, 6, 7], [8]], rk, start, off)).tolist() == [6, 7, 8]
    with pytest.raises(ValueError):
        f4_rows.GATHER([[5, 6], [8]], rk, start, off)  # row 0 is one term short
    with pytest.raises(TypeError):
        f4_rows.GATHER([[5, 6, 7], ["x"]], rk, start, off)


def test_a_trace_too_large_to_keep_lets_its_full_layouts_go(monkeypatch):
    from mech.kernel import f4 as f4_module
    monkeypatch.setattr(f4_module, "FULL_TRACE_WORK", 2000)
    R = ring([f"x{i}" for i in range(5)], [Block("dp", 5)], GF(P))
    fast = engines(cyclic(R), R, 63, record=True)[0]
    fast.run()
    assert not fast.trace.full
    assert all(st.full is None and "full" not in st.plans for st in fast.trace.steps)


@pytest.mark.parametrize("nvars, maxdeg", [(3, 63), (6, 63), (7, 255), (2, 100000), (10, 63)])
@pytest.mark.parametrize("kind", ["dp", "lp"])
def test_exponents_unpacked_in_c_as_in_python(nvars, maxdeg, kind):
    """Packing.unpack_all: the compiled unpacking (exponent fields within 64 bits; ten variables
    of 7 bits exceed them and stay in Python) gives every monomial's exponents as Python does,
    Packing.term_dicts the same dicts (in the rows' order); Packing.pack_all packs as pack (in C
    within 128 bits, beyond them in Python)."""
    rng = random.Random(nvars * maxdeg)
    Pk = Packing(MonomialOrder.simple(kind, nvars), maxdeg)
    exps = [tuple(rng.randrange(maxdeg // nvars + 1) for _ in range(nvars)) for _ in range(200)]
    mons = [Pk.pack(e) for e in exps] * 2
    assert max(mons).bit_length() > 64 or nvars < 6
    assert Pk.pack_all(exps) == mons[:200] == [Pk.pack(e) for e in exps]  # packed in C up to 128 bits
    got = Pk.unpack_all(iter(mons))
    rows = [(mons[i:i + 7], list(range(i, i + 7))) for i in range(0, 200, 7)]
    dicts = Pk.term_dicts(rows), Pk.term_dicts(rows, flint.nmod(1, 7))
    assert Pk._compiled_unpack == (nvars * Pk.ebits <= 64)
    Pk._compiled_unpack = False
    assert got == Pk.unpack_all(iter(mons)) == {Pk.pack(e): e for e in exps}
    assert dicts == (Pk.term_dicts(rows), Pk.term_dicts(rows, flint.nmod(1, 7)))
    assert [list(d.items()) for d in dicts[1]] == [[(Pk.unpack(m), flint.nmod(c, 7)) for m, c in zip(*r)] for r in rows]
