"""The compiled Hilbert-driven Buchberger algorithm (kernel/hilbert_compiled.py, kernel/_bba.c,
engine ``hilbert-compiled``): modulo p and over QQ by a lift from primes, against Buchberger's
reduced basis, the Python Hilbert-driven algorithm and Singular."""
import random
from array import array

import flint
import pytest

from mech.kernel import GF, QQ, Block, MonomialOrder, PolyRing
from mech.kernel import engines as E
from mech.kernel import hilbert_compiled as HC
from mech.kernel.buchberger import TooLong, buchberger, reduce_basis
from mech.kernel.engines import clear_cache, standard_basis
from mech.kernel.modular import ModularFailure, primitive
from mech.kernel.poly import Poly
from tests.util import ideal_blocks, parse_poly, run_singular

needs_compiled = pytest.mark.skipif(HC._bba is None, reason="the C extension _bba is not built")

FIVE_BAR = ["c1+c2+c3+c4-2", "s1+s2+s3+s4", "c1^2+s1^2-1", "c2^2+s2^2-1", "c3^2+s3^2-1", "c4^2+s4^2-1",
            "y1-c1-s1", "y2-c2-s2", "y3-c3-s3"]  # benchmarks/cases.py's five-bar projection


def ring_of(field, names, blocks):
    return PolyRing(field, list(names), MonomialOrder([Block(k, n) for k, n in blocks]))


def random_ideal(R, rng, count, degree=3, terms=4):
    n = R.nvars
    gens = []
    for _ in range(count):
        t = {}
        for _ in range(terms):
            e = [0] * n
            for _ in range(rng.randint(1, degree)):
                e[rng.randrange(n)] += 1
            t[tuple(e)] = R.field(rng.randint(-9, 9) or 1)
        gens.append(Poly(R, t))
    return gens


def reference(gens, R):
    return reduce_basis(buchberger(gens, R), R)


BLOCKS = [(("dp", 2), ("dp", 2)), (("lp", 4),), (("dp", 1), ("lp", 3)), (("dp", 3), ("dp", 1))]


@needs_compiled
@pytest.mark.parametrize("field", [QQ, GF(32003), GF(2147483629)])
@pytest.mark.parametrize("blocks", BLOCKS)
def test_random_ideals_match_buchberger(field, blocks):
    rng = random.Random(f"{field}{blocks}")
    R = ring_of(field, "abcd", blocks)
    for _ in range(4):
        gens = random_ideal(R, rng, rng.randint(2, 3))
        clear_cache()
        assert [g.terms for g in standard_basis(gens, R, "hilbert-compiled")] == reference(gens, R)


@needs_compiled
@pytest.mark.parametrize("field", [QQ, GF(32003)])
def test_each_basis_element_leads_with_its_leading_monomial(field):
    """``returns_reduced``: every dict starts with its leading term, as the entry point expects."""
    R = ring_of(field, "xyzuv", (("dp", 3), ("dp", 2)))
    gens = [parse_poly(R, t) for t in ["x^2+y*u-1", "y^2-x*v", "z^3-u^2*v", "x*y*z-u-v"]]
    basis = E._hilbert_reduced(gens, R)
    assert all(next(iter(b)) == max(b, key=R.order.key) for b in basis)
    assert [R.order.key(next(iter(b))) for b in basis] == sorted(R.order.key(next(iter(b))) for b in basis)


@needs_compiled
def test_five_bar_projection_matches_the_python_hilbert_driven_algorithm():
    R = ring_of(QQ, ["c1", "s1", "c2", "s2", "c3", "s3", "c4", "s4", "y1", "y2", "y3"], (("dp", 8), ("dp", 3)))
    gens = [parse_poly(R, t) for t in FIVE_BAR]
    clear_cache()
    ours = standard_basis(gens, R, "hilbert-compiled")
    clear_cache()
    assert ours == standard_basis(gens, R, "hilbert")
    assert len(ours) == 35 and sum(len(g.terms) for g in ours) == 8018


class _Deferring(HC._Series):
    """A series whose deferral hint is replaced by ``hint(zeros known, number of pairs)``."""

    def __init__(self, target, nvars, hint):
        super().__init__(target, nvars)
        self.hint = hint
        self.sizes = {}

    def deferred(self, node, d):
        known = super().deferred(node, d)
        return self.hint(known, self.sizes.get((node, d), len(known)))

    def reduced_to_zero(self, node, d, zeros):
        self.sizes[(node, d)] = len(zeros)
        super().reduced_to_zero(node, d, zeros)


@needs_compiled
@pytest.mark.parametrize("hint", [
    lambda known, n: known,  # the first prime's zero reductions last (what the lift does)
    lambda known, n: bytes(1 - b for b in known),  # the pairs that gave new elements last
    lambda known, n: b"\x01" * n,  # every pair marked: the order is unchanged
    lambda known, n: b"\x01" * (n + 1),  # a hint of the wrong length is ignored
])
def test_deferring_pairs_keeps_the_basis_modulo_p(hint):
    """A degree is complete once it has its new leading monomials, whichever pairs gave them: the
    five-bar's reduced basis modulo p is the same whatever pairs are deferred, and every later
    prime sees the first prime's zero reductions."""
    R = ring_of(QQ, ["c1", "s1", "c2", "s2", "c3", "s3", "c4", "s4", "y1", "y2", "y3"], (("dp", 8), ("dp", 3)))
    gens = [parse_poly(R, t) for t in FIVE_BAR]
    hring, hgens, target = HC._homogenized(gens, R, E._dp_homogeneous)
    ints = [primitive(g.terms) for g in hgens]
    p = 2147483629
    plain = HC._reduced_modp(ints, hring, R, HC._Series(target, hring.nvars), p)[1]
    series = _Deferring(target, hring.nvars, hint)
    first = HC._reduced_modp(ints, hring, R, series, p)[1]
    assert any(0 < sum(z) for z in series.zeros.values())  # some pairs reduced to zero
    assert HC._reduced_modp(ints, hring, R, series, p)[1] == first == plain


@needs_compiled
def test_a_prime_dividing_a_leading_coefficient_is_skipped():
    """The first prime of the lift divides the leading coefficient: the lift goes on without it."""
    p = next(HC.lift_primes())
    R = ring_of(QQ, "xyz", (("dp", 1), ("dp", 2)))
    gens = [parse_poly(R, f"{p}*x^2-y*z+1"), parse_poly(R, "x*y-z^2"), parse_poly(R, "y^3-x-3")]
    clear_cache()
    assert [g.terms for g in standard_basis(gens, R, "hilbert-compiled")] == reference(gens, R)


def test_without_the_extension_the_python_algorithm_answers(monkeypatch):
    R = ring_of(QQ, "xyzuv", (("dp", 3), ("dp", 2)))
    gens = [parse_poly(R, t) for t in ["x^2+y*u-1", "y^2-x*v", "z^3-u^2*v", "x*y*z-u-v"]]
    monkeypatch.setattr(HC, "_bba", None)
    assert not HC.usable(R)
    clear_cache()
    G = standard_basis(gens, R, "hilbert-compiled")
    assert [g.terms for g in G] == reference(gens, R)
    assert all(g._lm == max(g.terms, key=R.order.key) for g in G)


@needs_compiled
@pytest.mark.singular
def test_block_and_lex_eliminations_match_singular():
    gens = ["x^2+y*u-1", "y^2-x*v", "z^3-u^2*v", "x*y*z-u-v"]
    orders = [(("dp", 3), ("dp", 2)), (("dp", 1), ("dp", 4)), (("lp", 5),)]
    script = "option(redSB);\n" + "".join(
        f"ring r = {p}, (x,y,z,u,v), ({','.join(f'{k}({n})' for k, n in o)}); short = 0; "
        f"ideal i = {', '.join(gens)}; std(i); kill r;\n" for o in orders for p in (0, 32003))
    blocks = ideal_blocks(run_singular(script))
    assert len(blocks) == 2 * len(orders)
    k = 0
    for o in orders:
        for field in (QQ, GF(32003)):
            R = ring_of(field, "xyzuv", o)
            clear_cache()
            ours = standard_basis([parse_poly(R, t) for t in gens], R, "hilbert-compiled")
            theirs = sorted((p.monic() for p in (parse_poly(R, t) for t in blocks[k]) if not p.is_zero()),
                            key=lambda p: R.order.key(p.lm()))
            assert ours == theirs, (o, field)
            k += 1


@needs_compiled
@pytest.mark.parametrize("field", [QQ, GF(32003)])
def test_compiled_buchberger_on_homogeneous_ideals_matches_buchberger(field):
    """The engine buchberger-compiled (all pairs, no Hilbert series): the dp bases the
    Hilbert-driven algorithms start from."""
    rng = random.Random(f"homogeneous {field}")
    R = ring_of(field, "abcde", (("dp", 5),))
    for _ in range(4):
        gens = []
        for _ in range(rng.randint(2, 4)):
            d = rng.randint(2, 3)
            t = {}
            for _ in range(4):
                e = [0] * 5
                for _ in range(d):
                    e[rng.randrange(5)] += 1
                t[tuple(e)] = R.field(rng.randint(1, 9))
            gens.append(Poly(R, t))
        clear_cache()
        assert [g.terms for g in standard_basis(gens, R, "buchberger-compiled")] == reference(gens, R)


@needs_compiled
@pytest.mark.parametrize("blocks", BLOCKS)
def test_the_compiled_arithmetic_modulo_primes_of_50_bits(blocks):
    """The lift's primes lie below 2^50 (products by a double-precision quotient): the basis
    modulo the largest prime below 2^50 is Buchberger's over that field, with coefficients
    spread over the whole range."""
    p = (1 << 50) - 27
    assert flint.fmpz(p).is_prime() and p < HC.PRIMES[1]
    rng = random.Random(f"p50 {blocks}")
    R = ring_of(GF(p), "abcd", blocks)
    for _ in range(4):
        gens = [Poly(R, {e: R.field(rng.randrange(1, p)) for e, _ in g.terms.items()})
                for g in random_ideal(R, rng, rng.randint(2, 3))]
        got = HC.buchberger_modp(gens, R)
        assert [{e: int(c) for e, c in b.items()} for b in got] == \
            [{e: int(c) for e, c in b.items()} for b in reference(gens, R)]


@needs_compiled
def test_the_compiled_reconstruction_refuses_a_wrong_check_and_too_many_bits():
    """``ratlift`` returns None when the lift disagrees with the check residues (a wrong candidate),
    and refuses primes whose product passes 124 bits or a prime of 50 bits or more."""
    from array import array
    p1, p2, q = (1 << 50) - 27, (1 << 50) - 35, (1 << 49) - 81
    values = [flint.fmpq(-3, 7), flint.fmpq(123456789, 1000003), flint.fmpq(5)]

    def residues(m):
        return array("Q", [int(v.p) * pow(int(v.q), -1, m) % m for v in values]).tobytes()

    nums, dens = HC._bba.ratlift([residues(p1), residues(p2)], [p1, p2], residues(q), q)
    assert list(map(flint.fmpq, nums, dens)) == values
    wrong = bytearray(residues(q))
    wrong[0] ^= 1
    assert HC._bba.ratlift([residues(p1), residues(p2)], [p1, p2], bytes(wrong), q) is None
    with pytest.raises(ValueError):
        HC._bba.ratlift([residues(p1)] * 3, [p1, p2, q], residues(q), q)  # 149 bits
    with pytest.raises(ValueError):
        HC._bba.ratlift([residues(p1)], [1 << 50], residues(q), q)


@needs_compiled
def test_coefficients_past_two_primes_are_lifted_in_python():
    """Coefficients of ~150 bits need more primes than the compiled lift (two below 2^50) takes."""
    R = ring_of(QQ, "xyz", (("dp", 1), ("dp", 2)))
    big = 3 ** 95
    gens = [parse_poly(R, f"x^2-{big}*y*z+1"), parse_poly(R, f"x*y-{big + 2}*z^2"), parse_poly(R, "y^3-x-3")]
    clear_cache()
    assert [g.terms for g in standard_basis(gens, R, "hilbert-compiled")] == reference(gens, R)


@needs_compiled
def test_the_exact_check_refuses_a_basis_missing_an_element():
    R = ring_of(QQ, "xyzuv", (("dp", 3), ("dp", 2)))
    gens = [parse_poly(R, t) for t in ["x^2+y*u-1", "y^2-x*v", "z^3-u^2*v", "x*y*z-u-v"]]
    basis = E._hilbert_reduced(gens, R)
    polys = [g.terms for g in gens]
    assert HC.reduce_to_zero(basis, polys, R.order)
    assert not HC.reduce_to_zero(basis[:-1], polys, R.order)


def test_the_exact_check_is_fraction_free_on_rational_coefficients():
    # leading coefficients 3/7 and -5/2, scaled generators: the check is up to nonzero scalars
    R = ring_of(QQ, "xyz", (("dp", 2), ("dp", 1)))
    basis = [parse_poly(R, t).terms for t in ["3/7*y^2-z+1/3", "-5/2*x-4*y+2/9*z"]]
    member = parse_poly(R, "(11/5*x*y-3)*(3/7*y^2-z+1/3)+(2*y^2+1/4)*(-5/2*x-4*y+2/9*z)").terms
    assert HC.reduce_to_zero([dict(sorted(b.items(), key=lambda t: R.order.key(t[0]), reverse=True))
                              for b in basis], [member], R.order)
    assert not HC.reduce_to_zero([dict(sorted(b.items(), key=lambda t: R.order.key(t[0]), reverse=True))
                                  for b in basis], [parse_poly(R, "x*y-z^2").terms], R.order)


def _exact_check_in_c(basis, polys, R):
    """``_bba.in_ideal`` on fmpq basis dicts and integer-scaled polynomials (as the lift calls it)."""
    from mech.kernel.monomials import packing
    pk = packing(R.order, 64)
    width = 8 * ((pk.bits + 64) // 64)
    reducers = []
    for b in basis:
        terms = sorted(((pk.pack(e), flint.fmpq(c)) for e, c in b.items()), key=lambda t: t[0], reverse=True)
        reducers.append((b"".join(m.to_bytes(width, "little") for m, _ in terms),
                         array("q", [int(c.p) for _, c in terms]), array("q", [int(c.q) for _, c in terms])))
    return HC._bba.in_ideal(HC._layout(pk), reducers, [HC._encode(pk, primitive(f)) for f in polys])


@needs_compiled
def test_the_exact_check_in_c_agrees_with_python():
    """The generators' check of a lift on 128-bit integers: a basis, the basis missing an element,
    a perturbed coefficient (a wrong candidate) and rational coefficients, against
    :func:`reduce_to_zero`."""
    R = ring_of(QQ, "xyzuv", (("dp", 3), ("dp", 2)))
    gens = [parse_poly(R, t) for t in ["x^2+y*u-1", "y^2-x*v", "z^3-u^2*v", "x*y*z-u-v"]]
    basis = E._hilbert_reduced(gens, R)
    polys = [g.terms for g in gens]
    wrong = [dict(b) for b in basis]
    e = list(wrong[-1])[-1]
    wrong[-1][e] += 1
    for candidate, expected in [(basis, True), (basis[:-1], False), (wrong, False)]:
        assert HC.reduce_to_zero(candidate, polys, R.order) is expected
        assert _exact_check_in_c(candidate, polys, R) is expected
    S = ring_of(QQ, "xyz", (("dp", 2), ("dp", 1)))
    fractions = [parse_poly(S, t).terms for t in ["3/7*y^2-z+1/3", "-5/2*x-4*y+2/9*z"]]
    member = parse_poly(S, "(11/5*x*y-3)*(3/7*y^2-z+1/3)+(2*y^2+1/4)*(-5/2*x-4*y+2/9*z)").terms
    assert _exact_check_in_c(fractions, [member], S) is True
    assert _exact_check_in_c(fractions, [parse_poly(S, "x*y-z^2").terms], S) is False


@needs_compiled
def test_the_exact_check_leaves_128_bits_to_python():
    """Reducing x^3 by x - c y with c of 62 bits reaches c^3 y^3: the C check answers None and the
    lift's check falls back to Python integers (x^3 lies in (x - c y, y^3), not in (x - c y))."""
    R = ring_of(QQ, "xy", (("dp", 1), ("dp", 1)))
    c = (1 << 61) + 1
    line, cube = {(1, 0): flint.fmpq(1), (0, 1): flint.fmpq(-c)}, {(0, 3): flint.fmpq(1)}
    gens = [Poly(R, {(3, 0): R.field(1)})]
    from mech.kernel.monomials import packing
    pk = packing(R.order, 64)
    width = 8 * ((pk.bits + 64) // 64)

    def shape(basis):
        return [b"".join(pk.pack(e).to_bytes(width, "little") for e in b) for b in basis]

    for basis, fractions, expected in [([line, cube], ([1, -c, 1], [1, 1, 1]), True),
                                       ([line], ([1, -c], [1, 1]), False)]:
        assert _exact_check_in_c(basis, [g.terms for g in gens], R) is None
        assert HC._generators_reduce_to_zero(pk, shape(basis), fractions, basis, gens, R.order) is expected


@needs_compiled
def test_the_compiled_hilbert_numerator_is_the_python_one():
    from mech.kernel import hilbert as H
    rng = random.Random(7)
    for _ in range(200):
        n = rng.randint(1, 6)
        lms = [tuple(rng.randint(0, 4) for _ in range(n)) for _ in range(rng.randint(0, 8))]
        assert H.first_numerator(lms, n) == H._trim(H._numerator(H.minimal_monomials(lms)))


@needs_compiled
@pytest.mark.parametrize("field", [QQ, GF(32003)])
def test_compiled_buchberger_with_sugar_on_inhomogeneous_ideals(field):
    for blocks in BLOCKS:
        rng = random.Random(f"sugar {field} {blocks}")
        R = ring_of(field, "abcd", blocks)
        gens = random_ideal(R, rng, 3)
        clear_cache()
        assert [g.terms for g in standard_basis(gens, R, "buchberger-compiled")] == reference(gens, R)


@needs_compiled
def test_the_compiled_attempt_keeps_to_its_budget():
    """auto's attempt over QQ: the four-bar's elimination finishes within COMPILED_BUDGET, the
    block system's does not (TooLong, then the Hilbert-driven algorithm)."""
    four_bar = ring_of(QQ, ["c1", "s1", "c2", "s2", "c3", "s3", "x", "y"], (("dp", 6), ("dp", 2)))
    fb = [parse_poly(four_bar, t) for t in ["4+3*c3-2*c1-4*c2", "3*s3-2*s1-4*s2", "x-2*c1-2*c2+s2",
                                            "y-2*s1-2*s2-c2", "c1^2+s1^2-1", "c2^2+s2^2-1", "c3^2+s3^2-1"]]
    assert HC.buchberger_qq(fb, four_bar, E.COMPILED_BUDGET) == reference(fb, four_bar)
    R = ring_of(QQ, "xyzuv", (("dp", 3), ("dp", 2)))
    gens = [parse_poly(R, t) for t in ["x^2+y*u-1", "y^2-x*v", "z^3-u^2*v", "x*y*z-u-v"]]
    with pytest.raises(TooLong):
        HC.buchberger_qq(gens, R, E.COMPILED_BUDGET)


@needs_compiled
def test_the_compiled_attempt_gives_up_on_tall_coefficients():
    """A lex basis with coefficients of 1600 bits: the attempt stops after ATTEMPT_PRIMES primes."""
    R = ring_of(QQ, "abcd", (("lp", 4),))
    rng = random.Random("sugar QQ")
    random_ideal(R, rng, 3)  # the dp(2),dp(2) ideal of the test above
    gens = random_ideal(R, rng, 3)
    with pytest.raises(ModularFailure):
        HC.buchberger_qq(gens, R, 0, E.ATTEMPT_PRIMES)


@needs_compiled
@pytest.mark.parametrize("field", [QQ, GF(32003)])
def test_exponents_given_as_flint_integers(field):
    """Exponents may come as fmpz (from flint's polynomials, as in primdecGTZ over parameters)."""
    import flint
    R = ring_of(field, "xyzuv", (("dp", 3), ("dp", 2)))
    gens = [parse_poly(R, t) for t in ["x^2+y*u-1", "y^2-x*v", "z^3-u^2*v", "x*y*z-u-v"]]
    wide = [Poly(R, {tuple(flint.fmpz(a) for a in e): c for e, c in g.terms.items()}) for g in gens]
    clear_cache()
    assert standard_basis(wide, R, "hilbert-compiled") == standard_basis(gens, R, "hilbert")
