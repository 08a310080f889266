"""The F4 engines (kernel/f4.py, f4_vectors.py, f4_trace.py, f4_rows.py, modular.py, monomials.py)
against Buchberger's reduced bases: ``f4`` over Z/p, ``modular`` over QQ; every test runs with the
compiled row kernel and with the pure-Python linear algebra."""
import itertools
import random

import flint
import pytest

from mech.kernel import GF, QQ, Block, MonomialOrder, f4_rows, modular
from mech.kernel.engines import clear_cache
from mech.kernel.groebner import groebner
from mech.kernel import f4 as f4_module
from mech.kernel.f4 import F4, pack_polys
from mech.kernel.f4_trace import TraceMismatch, replay
from mech.kernel.modular import (ExactReducer, Reconstructor, _modular, _pack, _replayed_basis_agrees, _top_reduces_packed,
                                 primes, primitive, ratrec, verify_basis)
from mech.kernel.monomials import Packing
from tests.util import cyclic, katsura, ring

P32003 = GF(32003)
pytestmark = pytest.mark.usefixtures("row_kernel")


def f4(R):
    """The F4 engine for the ring's field."""
    return "modular" if R.field == QQ else "f4"


def same(gens, R=None):
    """F4's reduced basis equals Buchberger's (as lists of polynomials, leading terms too)."""
    R = R or gens[0].ring
    G = groebner(gens, R, engine=f4(R))
    B = groebner(gens, R, engine="buchberger")
    assert G == B
    assert [g.lm() for g in G] == [max(g.terms, key=R.order.key) for g in G]
    return G


@pytest.mark.parametrize("field", [QQ, P32003], ids=["QQ", "Z/32003"])
def test_katsura4_cyclic4_cyclic5(field):
    R = ring([f"x{i}" for i in range(5)], [Block("dp", 5)], field)
    assert len(same(katsura(R, 4))) == 13
    assert len(same(cyclic(ring("abcd", [Block("dp", 4)], field)))) == 7
    assert len(same(cyclic(ring("abcde", [Block("dp", 5)], field)))) == 20


@pytest.mark.parametrize("field", [QQ, P32003], ids=["QQ", "Z/32003"])
def test_small_classics(field):
    R = ring("xyz", [Block("dp", 3)], field)
    x, y, z = R.gens()
    assert [g.lm() for g in same([x**2 - y, x**3 - z])] == [(0, 2, 0), (1, 1, 0), (2, 0, 0)]
    R = ring("xyz", [Block("lp", 3)], field)
    x, y, z = R.gens()
    same([x**2 + y**2 + z**2 - 1, x - y**2, y * z - x])
    R = ring("xyzuv", [Block("dp", 3), Block("dp", 2)], field)
    x, y, z, u, v = R.gens()
    same([x**2 + y * u - 1, y**2 - x * v, z**3 - u**2 * v, x * y * z - u - v])


def test_block_and_weighted_orderings():
    R = ring("abcdxy", [Block("dp", 4), Block("dp", 2)])
    a, b, c, d, x, y = R.gens()
    same([x - a * b, y - c * d, a**2 + b**2 - 1, c**2 + d**2 - 1])  # an elimination
    R = ring("xyzuv", [Block("lp", 2), Block("dp", 3)])
    x, y, z, u, v = R.gens()
    same([x * y - z, x**2 - u * v + 1, y**2 - z * u, z * v - x])
    R = ring("xyz", [Block("wp", 3, (3, 1, 2))], P32003)
    x, y, z = R.gens()
    same([x**2 - y * z, y**3 + x - z, x * z - y**2 + 1])
    R = ring("xyz", [Block("a", 3, (0, 1, 1)), Block("lp", 3)])
    x, y, z = R.gens()
    same([x**2 - y * z, y**3 + x - z, x * z - y**2 + 1])


def test_big_rational_coefficients():
    R = ring("xyz", [Block("dp", 3)])
    x, y, z = R.gens()
    big = flint.fmpq(3**80 + 7, 2**70 - 1)
    same([big * x**2 - y * z + flint.fmpq(1, 10**30), x * y - big * z**2, y**2 - x + big * big])


def test_unit_zero_constant():
    for field in (QQ, P32003):
        R = ring("xy", [Block("dp", 2)], field)
        x, y = R.gens()
        assert groebner([x, x - 1], engine=f4(R)) == [R.one()]
        assert groebner([x**2 * y - 1, x * y**2 - x, x**3 - y**2 - 2], engine=f4(R)) == same(
            [x**2 * y - 1, x * y**2 - x, x**3 - y**2 - 2])
        assert groebner([R.zero()], engine=f4(R)) == []
        assert groebner([R.const(5), x], engine=f4(R)) == [R.one()]
        assert groebner([x**3 - 1, x * y + 3, 0 * x], engine=f4(R)) == same([x**3 - 1, x * y + 3])


def test_random_systems_match_buchberger():
    rng = random.Random(7)
    orders = [[Block("dp", 3)], [Block("lp", 3)], [Block("Dp", 3)], [Block("dp", 1), Block("dp", 2)],
              [Block("wp", 3, (1, 2, 3))]]
    for trial in range(40):
        R = ring("xyz", rng.choice(orders), rng.choice([QQ, P32003, GF(7)]))
        gens = []
        for _ in range(rng.randint(1, 4)):
            terms = {tuple(rng.randint(0, 3) for _ in range(3)): rng.randint(-9, 9) for _ in range(rng.randint(1, 4))}
            gens.append(R.from_dict(terms))
        gens = [g for g in gens if not g.is_zero()] or [R.gens()[0]]
        same(gens, R)


def test_auto_engine_is_f4_for_larger_systems():
    R = ring([f"x{i}" for i in range(5)], [Block("dp", 5)])
    assert groebner(katsura(R, 4)) == groebner(katsura(R, 4), engine="buchberger")


def test_packing_matches_the_ordering():
    rng = random.Random(3)
    for blocks in ([Block("dp", 4)], [Block("lp", 4)], [Block("Dp", 4)], [Block("wp", 4, (3, 1, 2, 5))],
                   [Block("dp", 2), Block("lp", 2)], [Block("a", 4, (1, 0, 2, 0)), Block("dp", 4)],
                   [Block("M", 4, (1, 1, 1, 1, 0, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0))]):
        order = MonomialOrder(blocks)
        P = Packing(order, 31)
        for _ in range(300):
            a, b = (tuple(rng.randrange(8) for _ in range(4)) for _ in range(2))
            pa, pb = P.pack(a), P.pack(b)
            assert (pa < pb) == (order.key(a) < order.key(b))
            assert P.unpack(pa) == a and P.degree(pa) == sum(a)
            assert P.divides(pa, pb) == all(x <= y for x, y in zip(a, b))
            assert P.lcm(pa, pb) == P.pack(tuple(max(x, y) for x, y in zip(a, b)))
            assert P.pack(tuple(x + y for x, y in zip(a, b))) == pa + pb


def test_trace_replay_and_mismatch():
    R = ring([f"x{i}" for i in range(5)], [Block("dp", 5)])
    gens = [primitive(g.terms) for g in katsura(R, 4)]
    P = Packing(R.order, 31)

    class Int:  # primitive integer polynomials with the Poly interface pack_polys needs
        def __init__(self, t):
            self.terms = t
    rows = pack_polys([Int(t) for t in gens], P, lambda c: c)
    engines = {}
    for p in (1000003, 998244353 // 32 | 1, 32003):
        if not flint.fmpz(p).is_prime():
            continue
        engines[p] = F4([(ms, [c % p for c in cs]) for ms, cs in rows], P, p, record=True)
        engines[p].run()
    p0, e0 = next(iter(engines.items()))
    for p, e in engines.items():
        got = replay(e0.trace, [[c % p for c in cs] for _, cs in rows], p)
        assert got == [cs for _, cs in F4([(ms, [c % p for c in cs]) for ms, cs in rows], P, p).run()]
    # a generator changed so that the recorded path no longer applies
    bad = [[c % 101 for c in cs] for _, cs in rows]
    bad[0] = [0] * len(bad[0])
    bad[0][0] = 1
    with pytest.raises(TraceMismatch):
        replay(e0.trace, bad, 101)


def test_rational_reconstruction_and_lift():
    m = 1000003 * 998244353
    for n, d in [(3, 7), (-12345, 679), (0, 1), (1, 1), (-1, 99991)]:
        a = n * pow(d, -1, m) % m
        assert ratrec(a, m, 10**7) == (n, d)
    rec = Reconstructor([2, 1])
    values = [[5 * pow(3, -1, m) % m, 7 * pow(3, -1, m) % m], [-2 * pow(9, -1, m) % m]]
    assert rec.attempt(values, m) == [[flint.fmpq(5, 3), flint.fmpq(7, 3)], [flint.fmpq(-2, 9)]]
    big = flint.fmpq(3**20, 7**10)
    M = m * 1000033 * 1000037
    a = int(big.p) * pow(int(big.q), -1, M) % M
    assert Reconstructor([1]).attempt([[a % m]], m) != [[big]]  # too few primes: another fraction
    assert Reconstructor([1]).attempt([[a]], M) == [[big]]


def test_verification_rejects_a_wrong_basis():
    R = ring("xyz", [Block("dp", 3)])
    x, y, z = R.gens()
    gens = [x**2 - y, x**3 - z]
    G = groebner(gens, engine="modular")
    basis = [dict(g.terms) for g in G]
    ints = [primitive(g.terms) for g in gens]
    assert verify_basis(basis, ints, R, primes(), exact=True)
    assert verify_basis(basis, ints, R, primes())
    wrong = [dict(b) for b in basis]
    e = next(iter(wrong[0]))
    wrong[0][(0, 0, 1)] = wrong[0].get((0, 0, 1), 0) + flint.fmpq(1, 3)  # y^2 - x z + z/3
    assert not verify_basis(wrong, ints, R, primes(), exact=True)
    assert not verify_basis(wrong, ints, R, primes())
    assert e == (0, 2, 0)
    assert ExactReducer(basis, R.order).reduces_to_zero(primitive((x**5 - z * y).terms))


def test_full_replay_certifies_the_lift_modulo_a_fresh_prime():
    """The fast check modulo q by a full replay of the trace: the true lift agrees, a changed
    coefficient disagrees (and fails verification), a trace without all rows cannot tell."""
    R = ring([f"x{i}" for i in range(5)], [Block("dp", 5)])
    ints = [primitive(g.terms) for g in katsura(R, 4)]
    P = Packing(R.order, 31)
    shapes, coefs = _pack(ints, P)
    shape, G, trace, _ = _modular(shapes, coefs, P, primes(), 100)
    q = 1000003
    compiled = f4_rows.compiled(q)
    assert _replayed_basis_agrees(trace, coefs, G, q) is (True if compiled else None)
    wrong = [list(cs) for cs in G]
    wrong[-1][-1] += flint.fmpq(1, 7)
    assert _replayed_basis_agrees(trace, coefs, wrong, q) is (False if compiled else None)
    basis = [{P.unpack(m): c for m, c in zip(ms, cs)} for ms, cs in zip(shape, wrong)]
    assert not verify_basis(basis, ints, R, primes(), replayed=lambda p: _replayed_basis_agrees(trace, coefs, wrong, p))
    trace.full = False
    assert _replayed_basis_agrees(trace, coefs, G, q) is None


def test_top_reduction_on_packed_monomials():
    """The exact inclusion check on F4's packed rows (modular._top_reduces_packed) decides as
    flint's top reduction (ExactReducer) on katsura-4's generators and on non-members, and
    gives up (None) where a product leaves the packing."""
    R = ring([f"x{i}" for i in range(5)], [Block("dp", 5)])
    gens = katsura(R, 4)
    ints = [primitive(g.terms) for g in gens]
    P = Packing(R.order, 31)
    shapes, coefs = _pack(ints, P)
    shape, G, _, _ = _modular(shapes, coefs, P, primes(), 100)
    elements = list(zip(shape, G))
    leads = [ms[0] for ms in shape]
    basis = [{P.unpack(m): c for m, c in zip(ms, cs)} for ms, cs in elements]
    flint_red = ExactReducer(basis, R.order)
    x = R.gens()
    others = [primitive(t.terms) for t in (gens[0] * x[1] + gens[2] * x[3], gens[1] + x[4], x[0] ** 3 - 2)]
    for f in ints + others:
        fs, fc = _pack([f], P)
        assert _top_reduces_packed((fs[0], fc[0]), elements, leads, P.guard) == flint_red.reduces_to_zero(f)
    assert [_top_reduces_packed(r, elements, leads, P.guard) for r in zip(*_pack(others, P))] == [True, False, False]
    # lp in x, y: x^3 by x - y^3 passes x^2 y^3 of degree 5, past a packing for degree 3
    for maxdeg, want in [(3, None), (63, False)]:  # (63: it ends in y^9, which x does not divide)
        Q = Packing(MonomialOrder.simple("lp", 2), maxdeg)
        g = ([Q.pack((1, 0)), Q.pack((0, 3))], [1, -1])
        assert _top_reduces_packed(([Q.pack((3, 0))], [1]), [g], [g[0][0]], Q.guard) is want


def test_a_large_run_keeps_no_full_trace(monkeypatch):
    """Past FULL_TRACE_WORK matrix entries the trace lets every row go (memory); the check
    modulo a fresh prime then falls back to the direct one."""
    monkeypatch.setattr(f4_module, "FULL_TRACE_WORK", 200)
    R = ring([f"x{i}" for i in range(5)], [Block("dp", 5)])
    ints = [primitive(g.terms) for g in katsura(R, 4)]
    P = Packing(R.order, 31)
    shapes, coefs = _pack(ints, P)
    shape, G, trace, _ = _modular(shapes, coefs, P, primes(), 100)
    assert not trace.full and all(st.full is None for st in trace.steps)
    assert _replayed_basis_agrees(trace, coefs, G, 1000003) is None


def _stream_from(first, monkeypatch):
    """f4_qq's primes: ``first`` (adversarial choices), then the usual sequence."""
    usual = modular.primes
    monkeypatch.setattr(modular, "primes", lambda seed=20031: itertools.chain(first, usual(seed)))


def test_a_lift_from_the_first_prime_is_confirmed_by_a_full_replay(monkeypatch):
    """Small coefficients: the lift from p0 alone is confirmed by the next prime's full replay,
    which is the check modulo a fresh prime (no direct S-pair check is made)."""
    R = ring([f"x{i}" for i in range(5)], [Block("dp", 5)])
    gens = cyclic(R)
    ints = [primitive(g.terms) for g in gens]
    P = Packing(R.order, 63)
    shapes, coefs = _pack(ints, P)
    stream = primes()
    shape, G, trace, certified = _modular(shapes, coefs, P, stream, 100)
    assert next(stream) == list(itertools.islice(primes(), 3))[2]  # p0 and one confirming prime used
    if f4_rows.KERNEL is None:  # no full replays in pure Python: the check is made apart
        assert not certified
        return
    assert certified and trace.full
    monkeypatch.setattr(modular, "_is_groebner_mod", lambda *a: pytest.fail("direct check made"))
    clear_cache()
    assert groebner(gens, engine="modular") == groebner(gens, engine="buchberger")


def test_an_unlucky_first_prime(monkeypatch):
    """x^2 + q y, x y - 1 is the unit ideal modulo q (x = x^2 y - x (x y - 1)), not over QQ: with
    q as the first prime, the trace does not hold for the next primes and another prime learns."""
    q = 134217757  # a prime of PRIME_RANGE
    assert flint.fmpz(q).is_prime() and modular.PRIME_RANGE[0] < q < modular.PRIME_RANGE[1]
    R = ring("xy", [Block("dp", 2)])
    x, y = R.gens()
    gens = [x**2 + q * y, x * y - 1]
    _stream_from([q], monkeypatch)
    clear_cache()
    G = groebner(gens, engine="modular")
    assert G == groebner(gens, engine="buchberger") and G != [R.one()]


def test_a_confirming_prime_off_the_full_trace_still_serves_the_lift(monkeypatch):
    """A prime whose full replay leaves the trace gives its plain replay to the lift; the check
    modulo a fresh prime is then made apart (and can fail for a changed basis)."""
    R = ring([f"x{i}" for i in range(5)], [Block("dp", 5)])
    gens = katsura(R, 4)
    full = modular.replay_full
    calls = []

    def refuse_first(trace, polys, p):  # the first full replay leaves the trace
        calls.append(p)
        if len(calls) == 1:
            raise TraceMismatch("adversarial")
        return full(trace, polys, p)
    monkeypatch.setattr(modular, "replay_full", refuse_first)
    clear_cache()
    assert groebner(gens, engine="modular") == groebner(gens, engine="buchberger")
    # the refused prime, then the separate check (without the kernel: only the check's attempt)
    assert len(calls) >= (2 if f4_rows.KERNEL is not None else 1)


def test_a_wrong_lift_from_few_primes_is_rejected(monkeypatch):
    """Basis coefficients of about 64 bits: lifts from one or two primes (below 2^56) fail or are
    wrong (fractions that agree with the primes used, not with the next one), and the confirming
    prime says so."""
    R = ring("xyz", [Block("dp", 3)])
    x, y, z = R.gens()
    big = flint.fmpq(3**40 + 1, 7**20)
    gens = [x**2 - big * y * z, y**2 - x + big, z**2 - y]
    lifts = []
    attempt = modular.Reconstructor.attempt

    def spy(self, values, m):
        out = attempt(self, values, m)
        lifts.append(out)
        return out
    monkeypatch.setattr(modular.Reconstructor, "attempt", spy)
    clear_cache()
    G = groebner(gens, engine="modular")
    assert G == groebner(gens, engine="buchberger")
    final = [c for cs in lifts[-1] for c in cs]
    assert max(c.height_bits() for c in final) > 56  # beyond what one or two primes can lift
    assert len(lifts) >= 4 and all(out is None or out != lifts[-1] for out in lifts[:2])
