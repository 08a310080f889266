"""The compiled F4 row kernel (kernel/_f4rows.c through kernel/f4_rows.py) against the
pure-Python linear algebra of kernel/f4_vectors.py on random matrices."""
import random
from array import array

import flint
import pytest

from mech.kernel import Block, f4_rows, f4_trace
from mech.kernel.f4 import F4
from mech.kernel.f4_rows import CodedRow, Flat
from mech.kernel.f4_trace import replay
from mech.kernel.f4_vectors import RowSpec, Vectors, echelon, support
from mech.kernel.modular import primitive
from mech.kernel.monomials import Packing
from tests.util import katsura, ring

pytestmark = pytest.mark.skipif(f4_rows.KERNEL is None, reason="the compiled row kernel is not built")


def random_matrix(rng, p, K, m, npair):
    """Reducers (pivot j refers to pivots below j and to slots) and pair rows, as
    (coefficients, pivot entries, slot entries)."""
    rows = []
    for j in range(K + npair):
        top = j if j < K else K
        piv = rng.sample(range(top), min(top, rng.randrange(0, 6)))
        slots = rng.sample(range(m), rng.randrange(0, min(m, 5) + 1))
        coefs = [rng.randrange(p) for _ in piv + slots]
        rows.append((coefs, piv, slots))
    return rows


def by_python(p, K, m, rows):
    vec = Vectors(p)
    comb = vec.combiner(m)
    T, D = [0] * K, []
    for j, (cs, piv, slots) in enumerate(rows):
        n = len(piv)
        spec = RowSpec(0, list(range(n)), piv, list(range(n, n + len(slots))), slots)
        v = comb(spec, cs, [p - c for c in cs], T)
        if j < K:
            T[j] = v
        else:
            D.append(v)
    E, used = echelon(vec, D, m)
    return used, [(s0, *support(vec, E[s0], m)) for s0 in sorted(E)], [support(vec, t, m) for t in T]


MODES = {"chosen": -1, "dense tails": 0, "pivot by pivot": 1}  # the kernel's two reductions, or its choice


def by_kernel(p, K, m, rows, stop=False, mode=-1):
    flat = Flat()
    flat.ids.extend(range(K))
    for cs, piv, slots in rows:
        flat.add(piv + [~s for s in slots], cs)
    if mode < 0:
        return flat.reduce(p, m, K, list(range(K)), stop)
    return f4_rows.KERNEL(p, m, K, len(flat.ids), flat.ids, flat.off, flat.col, flat.val,
                          array("i", range(K)), stop, mode)


@pytest.mark.parametrize("mode", MODES.values(), ids=MODES.keys())
@pytest.mark.parametrize("p", [2, 3, 32003, (1 << 28) - 57, (1 << 31) - 1])
def test_random_matrices(p, mode):
    rng = random.Random(p)
    for trial in range(40):
        K, m, npair = rng.randrange(0, 40), rng.randrange(1, 30), rng.randrange(0, 12)
        rows = random_matrix(rng, p, K, m, npair)
        used, E, W = by_kernel(p, K, m, rows, mode=mode)
        assert (used, E, W) == by_python(p, K, m, rows)
        first, _, _ = by_kernel(p, K, m, rows, stop=True, mode=mode)
        assert first == used[:1]


@pytest.mark.parametrize("mode", MODES.values(), ids=MODES.keys())
def test_dense_rows_need_intermediate_reduction(mode):
    """More products per slot than fit 64 bits at once: the kernel reduces on the way."""
    p, K, m = (1 << 31) - 1, 30, 8
    rows = [([p - 1] * (j + m), list(range(j)), list(range(m))) for j in range(K)]
    rows.append(([p - 2] * (K + m), list(range(K)), list(range(m))))
    assert by_kernel(p, K, m, rows, mode=mode) == by_python(p, K, m, rows)


def test_the_kernel_chooses_each_reduction_somewhere():
    """Many sparse reducers and few pair rows go pivot by pivot, dense reducers with many pair
    rows by dense tails (the choice only changes the cost: the results are equal above)."""
    p, rng = 32003, random.Random(5)
    few = random_matrix(rng, p, 400, 300, 2)
    many = [([1] * (j + 40), list(range(j)), list(range(40))) for j in range(40)]
    many += [([2] * 80, list(range(40)), list(range(40)))] * 40
    for rows, K, m in [(few, 400, 300), (many, 40, 40)]:
        assert by_kernel(p, K, m, rows) == by_kernel(p, K, m, rows, mode=0) == by_kernel(p, K, m, rows, mode=1)


@pytest.mark.parametrize("mode", MODES.values(), ids=MODES.keys())
def test_bad_arguments_are_errors(mode):
    flat = Flat()
    flat.ids.append(0)
    flat.add([1], [1])  # refers to a pivot not yet filled
    with pytest.raises(ValueError):
        f4_rows.KERNEL(32003, 2, 2, 1, flat.ids, flat.off, flat.col, flat.val, array("i"), False, mode)
    flat = Flat()
    flat.ids.extend([0, 1])
    flat.add([1], [1])  # reducer 0 refers to pivot 1 above it
    flat.add([], [])
    flat.add([0, ~0], [1, 1])
    with pytest.raises(ValueError):
        f4_rows.KERNEL(32003, 2, 2, 2, flat.ids, flat.off, flat.col, flat.val, array("i"), False, mode)
    with pytest.raises(ValueError):
        Flat().reduce(1 << 31, 2, 0)
    assert not f4_rows.compiled(1 << 31)


def _katsura4_rows() -> tuple[Packing, list[tuple[list[int], list[int]]]]:
    """katsura-4's generators over QQ as F4's packed rows: monomials from the largest, integer coefficients."""
    R = ring([f"x{i}" for i in range(5)], [Block("dp", 5)])
    P = Packing(R.order, 31)
    rows = []
    for t in (primitive(g.terms) for g in katsura(R, 4)):
        items = sorted(((P.pack(e), c) for e, c in t.items()), reverse=True)
        rows.append(([m for m, _ in items], [c for _, c in items]))
    return P, rows


@pytest.mark.parametrize("record_compiled", [True, False], ids=["recorded-compiled", "recorded-python"])
def test_trace_recorded_by_one_path_replays_on_the_other(record_compiled, monkeypatch):
    """A trace recorded with the kernel (rows as CodedRow) replays in pure Python and the
    reverse (rows as RowSpec), giving the basis a fresh F4 run gives."""
    P, rows = _katsura4_rows()
    kernel = f4_rows.KERNEL
    p0, p = 32003, 1000003
    monkeypatch.setattr(f4_rows, "KERNEL", kernel if record_compiled else None)
    eng = F4([(ms, [c % p0 for c in cs]) for ms, cs in rows], P, p0, record=True)
    eng.run()
    assert isinstance(eng.trace.steps[0].rows[0][0], CodedRow) == record_compiled
    monkeypatch.setattr(f4_rows, "KERNEL", None if record_compiled else kernel)
    got = replay(eng.trace, [[c % p for c in cs] for _, cs in rows], p)
    assert got == [cs for _, cs in F4([(ms, [c % p for c in cs]) for ms, cs in rows], P, p).run()]


def test_replays_cut_from_the_whole_matrix_plan(monkeypatch):
    """A replay takes the rows it needs from the plan of each whole matrix (in C): the same
    reducers and rows as laid out from the recorded rows, and the same basis."""
    P, rows = _katsura4_rows()
    eng = F4([(ms, [c % 32003 for c in cs]) for ms, cs in rows], P, 32003, record=True)
    eng.run()
    for st in eng.trace.steps + [eng.trace.final]:
        cut = st.plans["full"].sub(st.K, [r for r, _ in st.used], st.roots)
        laid = f4_rows.Plan([j for j, _ in st.reducers], [r for _, r in st.reducers] + [r for r, _ in st.rows])
        assert (cut.ids, cut.off, cut.col, cut.rk, cut.rstart) == (laid.ids, laid.off, laid.col, laid.rk, laid.rstart)
    p = 1000003
    polys = [[c % p for c in cs] for _, cs in rows]
    got = replay(eng.trace, polys, p)
    monkeypatch.setattr(f4_trace, "SUBPLAN", None)
    for st in eng.trace.steps + [eng.trace.final]:
        st.plans.pop("rows", None)
    assert got == replay(eng.trace, polys, p)
    assert got == [cs for _, cs in F4([(ms, [c % p for c in cs]) for ms, cs in rows], P, p).run()]
    with pytest.raises(ValueError):
        f4_rows.SUBPLAN(array("q", [0, 1]), array("i", [0]), array("i", [0]), array("i", [0]), 1,
                        array("i", [5]), array("i"))  # no pair row 5


@pytest.mark.skipif(f4_rows.WORDS is None, reason="the compiled word packing is not built")
def test_words_are_the_monomials_little_endian():
    rng = random.Random(5)
    for nw in (1, 2, 3):
        ms = [0, 1, (1 << 64 * nw) - 1] + [rng.getrandbits(64 * nw) for _ in range(20)]
        assert f4_rows.WORDS(ms, nw) == b"".join(m.to_bytes(8 * nw, "little") for m in ms)
    with pytest.raises(OverflowError):
        f4_rows.WORDS([1 << 64], 1)
    with pytest.raises(OverflowError):
        f4_rows.WORDS([-1], 1)
    # packed monomials of rings over parameter fields may be flint integers (minAssGTZ over Z/7(a) stopped here)
    assert f4_rows.WORDS([flint.fmpz(5), 3], 1) == (5).to_bytes(8, "little") + (3).to_bytes(8, "little")
    with pytest.raises(TypeError):
        f4_rows.WORDS(["5"], 1)


def test_packed_basis_elements_are_the_same_without_the_compiled_words(monkeypatch):
    P = Packing(ring("abcd", [Block("dp", 4)]).order, 9)
    mons = [[P.pack((2, 1, 0, 3)), P.pack((0, 0, 1, 0))], [P.pack((1, 1, 1, 1))]]
    coefs = [[3, 5], [7]]
    compiled = f4_rows.Packed(P)
    compiled._sync(mons, coefs)
    monkeypatch.setattr(f4_rows, "WORDS", None)
    python = f4_rows.Packed(P)
    python._sync(mons, coefs)
    assert compiled.mons == python.mons and compiled.coefs == python.coefs
