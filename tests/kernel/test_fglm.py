"""FGLM (kernel/fglm.py) and the conversions ``auto`` makes with it: lexicographic and block
orderings of zero-dimensional ideals, against other engines and real Singular."""
from __future__ import annotations

import flint
import pytest
from tests.util import cyclic, ideal_blocks, katsura, parse_poly, ring, run_singular

from mech.kernel import GF, QQ, Block, MonomialOrder, PolyRing
from mech.kernel.engines import standard_basis
from mech.kernel.errors import EngineError
from mech.kernel.fglm import NotZeroDimensional, fglm_modp, staircase

LEX = [Block("lp", 5)]
BLOCKS = [Block("dp", 2), Block("dp", 3)]


@pytest.mark.parametrize("blocks", [LEX, BLOCKS], ids=["lp", "(dp(2),dp(3))"])
def test_fglm_agrees_with_f4_over_zp(blocks):
    R = ring("abcde", blocks, GF(32003))
    gens = katsura(R, 4)
    assert standard_basis(gens, R, "fglm") == standard_basis(gens, R, "f4")


@pytest.mark.parametrize("blocks", [[Block("lp", 4)], [Block("dp", 2), Block("dp", 2)]],
                         ids=["lp", "(dp(2),dp(2))"])
def test_fglm_agrees_with_modular_f4_over_qq(blocks):
    R = ring("abcd", blocks, QQ)
    gens = katsura(R, 3)
    ours = standard_basis(gens, R, "fglm")
    assert ours == standard_basis(gens, R, "modular") == standard_basis(gens, R, "buchberger")


def test_the_conversion_is_reduced_and_sorted():
    R = ring("abcde", LEX, QQ)
    basis = standard_basis(cyclic(R), R, "fglm")
    key = R.order.key
    lms = [p.lm() for p in basis]
    assert lms == sorted(lms, key=key)
    assert all(p.lc() == 1 for p in basis)
    for p in basis:  # no term of a tail is divisible by a leading monomial
        assert not any(all(a <= b for a, b in zip(lm, e)) for e in p.terms if e != p.lm() for lm in lms)
    assert len(staircase(lms, 5)) == 70  # cyclic-5 has 70 solutions with multiplicity


def test_positive_dimensional_ideals_are_refused():
    R = ring("xyz", [Block("lp", 3)], QQ)
    x, y, z = R.gens()
    with pytest.raises(EngineError, match="zero-dimensional"):
        standard_basis([x * y - z, x ** 2 - y], R, "fglm")
    with pytest.raises(NotZeroDimensional):
        staircase([(1, 0, 0)], 3)
    # auto falls back to another engine
    assert standard_basis([x * y - z, x ** 2 - y], R) == standard_basis([x * y - z, x ** 2 - y], R, "buchberger")


def test_unit_ideal_and_a_point():
    R = ring("xy", [Block("lp", 2)], QQ)
    x, y = R.gens()
    assert standard_basis([x * y - 1, x, y - 2], R, "fglm") == [R.one()]
    assert standard_basis([x + y - 3, x - y - 1], R, "fglm") == [y - 1, x - 2]


def test_fglm_modp_reports_how_each_monomial_was_reached():
    R = ring("xy", [Block("dp", 2)], GF(101))
    x, y = R.gens()
    dp = standard_basis([x ** 2 - y, y ** 2 - 1], R)
    conv = fglm_modp([{e: int(c) for e, c in g.terms.items()} for g in dp], R.order,
                     MonomialOrder([Block("lp", 2)]), 101)
    assert conv.stairs[0] == (0, 0) and conv.stair_from[0] == (-1, -1)
    for t, (i, k) in zip(conv.stairs[1:] + conv.lms, conv.stair_from[1:] + conv.lm_from):
        parent = list(conv.stairs[k])
        parent[i] += 1
        assert tuple(parent) == t
    assert conv.lms == [(0, 2), (2, 0)]  # y^2 - 1 and x^2 - y: already a lex basis


SINGULAR_CASES = [("katsura-5, lp", "lp", lambda R: katsura(R, 5), 6),
                  ("cyclic-5, lp", "lp", cyclic, 5),
                  ("katsura-5, (dp(3),dp(3))", "(dp(3),dp(3))", lambda R: katsura(R, 5), 6)]


@pytest.mark.singular
@pytest.mark.parametrize("char", [0, 32003])
def test_conversions_match_singular(char):
    script = "option(redSB);\n"
    rings = []
    for name, order, make, n in SINGULAR_CASES:
        names = [f"x{i}" for i in range(n)]
        blocks = [Block("lp", n)] if order == "lp" else [Block("dp", 3), Block("dp", 3)]
        R = PolyRing(QQ if char == 0 else GF(char), names, MonomialOrder(blocks))
        gens = make(R)
        rings.append((R, gens))
        script += (f"ring r = {char}, ({','.join(names)}), {order}; short = 0; "
                   f"ideal i = {', '.join(g.to_str() for g in gens)}; groebner(i); kill r;\n")
    blocks = ideal_blocks(run_singular(script, timeout=300))
    assert len(blocks) == len(rings)
    for (R, gens), block in zip(rings, blocks):
        theirs = sorted((parse_poly(R, t).monic() for t in block), key=lambda p: R.order.key(p.lm()))
        assert standard_basis(gens, R) == theirs
        assert standard_basis(gens, R, "fglm") == theirs


# --- the Hilbert-driven engine and auto's choice for positive-dimensional ideals ----------------

FIVEBAR = ["c1+c2+c3+c4-2", "s1+s2+s3+s4", "c1^2+s1^2-1", "c2^2+s2^2-1", "c3^2+s3^2-1", "c4^2+s4^2-1",
           "y1-c1-s1", "y2-c2-s2", "y3-c3-s3"]


def _fivebar(field):
    R = ring(["c1", "s1", "c2", "s2", "c3", "s3", "c4", "s4", "y1", "y2", "y3"],
             [Block("dp", 8), Block("dp", 3)], field)
    return R, [parse_poly(R, t) for t in FIVEBAR]


def test_hilbert_driven_agrees_with_buchberger_over_zp():
    R, gens = _fivebar(GF(32003))
    ours = standard_basis(gens, R, "hilbert")
    assert ours == standard_basis(gens, R, "buchberger")
    assert len(ours) == 35 and [p for p in ours if max(p.lm()[:8]) == 0][0].total_degree() == 14


def test_hilbert_driven_on_a_homogeneous_ideal_needs_no_new_variable():
    R = ring("xyzw", [Block("lp", 4)], QQ)
    x, y, z, w = R.gens()
    gens = [x * z - y ** 2, x * w - y * z, y * w - z ** 2]  # the twisted cubic, homogeneous
    assert standard_basis(gens, R, "hilbert") == standard_basis(gens, R, "buchberger")


@pytest.mark.singular
def test_the_fivebar_elimination_matches_singular():
    R, gens = _fivebar(QQ)
    out = run_singular("option(redSB); ring r = 0, (" + ",".join(R.names) + "), (dp(8),dp(3)); short = 0; "
                       f"ideal i = {', '.join(FIVEBAR)}; groebner(i);", timeout=300)
    theirs = sorted((parse_poly(R, t).monic() for t in ideal_blocks(out)[0]), key=lambda p: R.order.key(p.lm()))
    assert standard_basis(gens, R) == theirs


@pytest.mark.parametrize("p", [32003, 268435399], ids=["small p", "p near 2^28"])
def test_compiled_and_packed_linear_algebra_give_the_same_conversion(monkeypatch, p):
    """kernel/_fglm.c's steps against the packed Python integers, on a lex and a block target
    (both paths also see a staircase of one monomial)."""
    from mech.kernel import f4_rows
    from mech.kernel import fglm as F
    if f4_rows.KERNEL is None:
        pytest.skip("the compiled kernel is not built")
    runs = []
    for path in ("compiled", "packed"):
        if path == "packed":
            monkeypatch.setattr(F, "COMPILED_ENTRIES", 0)
        out = []
        for names, gens, target in [("abcde", cyclic, LEX), ("abcdef", lambda R: katsura(R, 5), BLOCKS + [Block("dp", 1)]),
                                    ("xy", lambda R: [R.gens()[0] - 3, R.gens()[1] ** 2 - R.gens()[0]], [Block("lp", 2)])]:
            R = ring(names, [Block("dp", len(names))], GF(p))
            dp = standard_basis(gens(R), R)
            conv = fglm_modp([{e: int(c) for e, c in g.terms.items()} for g in dp], R.order,
                             MonomialOrder(target), p)
            out.append((conv.lms, conv.tails, conv.stairs, conv.stair_from, conv.lm_from))
        runs.append(out)
    assert runs[0] == runs[1]
    assert len(runs[0][0][2]) == 70 and len(runs[0][1][2]) == 32


def test_the_lifted_conversion_over_qq_is_the_exact_one(monkeypatch):
    """cyclic-5 in lp: the conversion lifted from primes and proved (its source has 8-bit
    coefficients) against the exact conversion (the lift switched off)."""
    from mech.kernel import fglm as F
    dp = ring("abcde", [Block("dp", 5)], QQ)
    source = [g.terms for g in standard_basis(cyclic(dp), dp)]
    target = MonomialOrder(LEX)
    proofs = []
    proved = F._proved
    monkeypatch.setattr(F, "_proved", lambda *a: proofs.append(proved(*a)) or proofs[-1])
    lifted = F.fglm_qq(source, dp.order, target)
    assert proofs == [True]
    monkeypatch.setattr(F, "LIFT_HEIGHT", -1)
    assert F.fglm_qq(source, dp.order, target) == lifted


def test_the_proof_of_a_lifted_conversion_refuses_wrong_bases():
    from mech.kernel import fglm as F
    dp = ring("abcde", [Block("dp", 5)], QQ)
    source = [{max(g.terms, key=dp.order.key): g.lc(), **g.terms} for g in standard_basis(cyclic(dp), dp)]
    lex = ring("abcde", LEX, QQ)
    target = [dict(g.terms) for g in standard_basis(cyclic(lex), lex)]
    B = staircase([next(iter(g)) for g in source], 5)
    assert F._proved(target, source, dp.order, lex.order, B)
    wrong = [dict(g) for g in target]
    e = next(e for e in wrong[-1] if e != next(iter(wrong[-1])))
    wrong[-1][e] += 1  # a tail coefficient off: no longer in the ideal
    assert not F._proved(wrong, source, dp.order, lex.order, B)
    assert not F._proved(target[:-1], source, dp.order, lex.order, B)  # too many standard monomials


# --- the compiled conversion (kernel/_fglm.c) and the exact check (kernel/_fglm_proof.c) --------

def _compiled_fglm():
    from mech.kernel import fglm as F
    if F.STEP is None:
        pytest.skip("the compiled FGLM module is not built")
    return F


def _modp_basis(R):
    return [{e: int(c) for e, c in g.terms.items()} for g in standard_basis(cyclic(R), R)]


def test_the_walk_in_c_takes_the_steps_of_the_python_walk(monkeypatch):
    """fglm_walk against the Python walk over the same compiled steps, on cyclic-5 to lex and to a
    block ordering: the same conversion, visit by visit."""
    F = _compiled_fglm()
    R = ring("abcde", [Block("dp", 5)], GF(32003))
    basis = _modp_basis(R)
    runs = []
    for walk in (F.WALK, None):
        monkeypatch.setattr(F, "WALK", walk)
        out = []
        for target in (LEX, BLOCKS):
            conv = F.fglm_modp(basis, R.order, MonomialOrder(target), 32003)
            out.append((conv.lms, conv.tails, conv.stairs, conv.stair_from, conv.lm_from, conv.steps.tolist()))
        runs.append(out)
    assert runs[0] == runs[1]
    assert len(runs[0][0][2]) == 70 and len(runs[0][0][0]) == 11


def test_a_basis_that_is_not_reduced_has_no_border_plan_but_converts_the_same():
    F = _compiled_fglm()
    R = ring("abcde", [Block("dp", 5)], GF(32003))
    basis = _modp_basis(R)
    key = R.order.key
    B = sorted(staircase([max(g, key=key) for g in basis], 5), key=key)
    assert F.Border.of(basis, R.order, B) is not None
    g, h = basis[0], basis[-1]  # h + g: the same leading monomial, a tail outside the staircase
    unreduced = basis[:-1] + [{e: (h.get(e, 0) + g.get(e, 0)) % 32003 for e in set(g) | set(h)}]
    assert max(unreduced[-1], key=key) == max(h, key=key)
    assert F.Border.of(unreduced, R.order, B) is None
    lex = MonomialOrder(LEX)
    ours, theirs = F.fglm_modp(unreduced, R.order, lex, 32003), F.fglm_modp(basis, R.order, lex, 32003)
    assert (ours.lms, ours.tails, ours.stairs) == (theirs.lms, theirs.tails, theirs.stairs)


def _points_basis(points, p):
    """The reduced dp basis (x > y) of three points in general position modulo ``p``: for each
    quadratic monomial m, m + a x + b y + c vanishing at the points (Cramer's rule)."""
    from fractions import Fraction
    rows = [(Fraction(x), Fraction(y), Fraction(1)) for x, y in points]

    def det(m):
        return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    d = det(rows)
    basis = []
    for lm in [(2, 0), (1, 1), (0, 2)]:
        rhs = [-(x ** lm[0]) * (y ** lm[1]) for x, y in points]
        g = {lm: 1}
        for col, e in enumerate([(1, 0), (0, 1), (0, 0)]):
            m = [list(r) for r in rows]
            for i in range(3):
                m[i][col] = rhs[i]
            v = det(m) / d
            if v:
                g[e] = v.numerator * pow(v.denominator, -1, p) % p
        basis.append(g)
    return basis


def test_a_replay_at_another_prime_is_the_conversion_there_and_refuses_another_shape():
    """Three points with distinct y (lex stairs 1, y, y^2) and three with two sharing y (stairs
    1, y, x) have dp bases of the same shape: a replay of the first's conversion on the second
    basis finds the other dependency and refuses."""
    F = _compiled_fglm()
    R = ring("xy", [Block("dp", 2)], QQ)
    lex = MonomialOrder([Block("lp", 2)])
    B = sorted([(0, 0), (0, 1), (1, 0)], key=R.order.key)
    distinct, sharing = [(1, 1), (2, 3), (3, 2)], [(1, 1), (2, 1), (3, 2)]
    p, q = 32003, 65521
    basis = _points_basis(distinct, p)
    structure = F.Border.of(basis, R.order, B)
    first = F.fglm_modp(basis, R.order, lex, p, B, structure)
    assert first.stairs == [(0, 0), (0, 1), (0, 2)]
    at_q = _points_basis(distinct, q)
    again, fresh = F.replay(first, at_q, structure, q), F.fglm_modp(at_q, R.order, lex, q, B)
    assert (again.lms, again.tails, again.stairs) == (fresh.lms, fresh.tails, fresh.stairs)
    other = _points_basis(sharing, p)
    assert all(set(g) <= set(h) for g, h in zip(other, basis))  # the same plan serves
    assert F.fglm_modp(other, R.order, lex, p, B).stairs == [(0, 0), (0, 1), (1, 0)]
    assert F.replay(first, other, structure, p) is None


def test_the_compiled_exact_check_agrees_with_python_and_refuses_wrong_candidates():
    """kernel/_fglm_proof.c against hilbert_compiled.reduce_to_zero: cyclic-5's lex basis lies in
    the ideal, a tail coefficient off or a monomial too many does not; katsura-4's lex basis
    (251-bit coefficients) leaves 64 bits, so Python decides (and the proof still holds)."""
    F = _compiled_fglm()
    from mech.kernel.hilbert_compiled import reduce_to_zero
    for n, make, fits in [(5, cyclic, True), (5, lambda R: katsura(R, 4), False)]:
        names = "abcde"[:n]
        dp = ring(names, [Block("dp", n)], QQ)
        source = [{g.lm(): g.lc(), **g.terms} for g in standard_basis(make(dp), dp)]
        lex = ring(names, LEX, QQ)
        target = [{g.lm(): g.lc(), **g.terms} for g in standard_basis(make(lex), lex)]
        wrong = [dict(g) for g in target]
        e = next(e for e in wrong[-1] if e != next(iter(wrong[-1])))
        wrong[-1][e] += 1
        outside = [dict(g) for g in target]
        outside[0][(0,) * n] = outside[0].get((0,) * n, flint.fmpq(0)) + 1
        for polys, member in [(target, True), (wrong, False), (outside, False)]:
            got = F._reduces_compiled(source, polys, dp.order)
            assert got == member if fits else got in (None, member)
            if not fits and member:
                assert got is None  # Python's integers decided
            assert reduce_to_zero(source, polys, dp.order) == member
        B = staircase([next(iter(g)) for g in source], n)
        assert F._proved(target, source, dp.order, lex.order, B)
        assert not F._proved(wrong, source, dp.order, lex.order, B)


def test_the_conversion_over_qq_without_the_compiled_module_is_the_same(monkeypatch):
    F = _compiled_fglm()
    dp = ring("abcde", [Block("dp", 5)], QQ)
    source = [g.terms for g in standard_basis(cyclic(dp), dp)]
    target = MonomialOrder(LEX)
    compiled = F.fglm_qq(source, dp.order, target)
    for name in ("MATRICES", "REDUCES", "REPLAY", "STEP", "WALK"):
        monkeypatch.setattr(F, name, None)
    assert F.fglm_qq(source, dp.order, target) == compiled


@pytest.mark.parametrize("field", [QQ, GF(32003)], ids=["QQ", "Z/32003"])
def test_conversions_to_weighted_and_mixed_orderings_agree_with_buchberger(field):
    """The C walk takes any global target as its nonnegative weight matrix."""
    for blocks in ([Block("wp", 4, (3, 2, 1, 1))], [Block("lp", 2), Block("wp", 2, (5, 1))], [Block("Dp", 4)]):
        R = ring("abcd", blocks, field)
        gens = katsura(R, 3)
        assert standard_basis(gens, R, "fglm") == standard_basis(gens, R, "buchberger")
