"""Multivariate factorization, squarefree parts and gcds over QQ and Z/32003 (truths from the
paper's reference runs and Singular 4.3.1; live differential test when Singular is installed)."""
import random

import pytest
from tests.util import SINGULAR, ideal_blocks, parse_poly, run_singular

from mech.kernel import GF, QQ, Block, MonomialOrder, PolyRing
from mech.kernel.errors import DivisionError
from mech.kernel.factor import divide_exact, factorize, gcd, normalize, squarefree_part

PAPER = PolyRing(QQ, "c1 s1 c2 s2 c3 s3 l1 l2 l3".split(), MonomialOrder([Block("dp", 6), Block("dp", 3)]))

# E[1] of slider3.out and fourbar.out (the eliminants of Sections 4.1.2 and 4.2)
SLIDER3_E = "l1^4-2*l1^2*l2^2+l2^4-2*l1^2*l3^2-2*l2^2*l3^2+l3^4"
FOURBAR_E = ("l1^8-4*l1^6*l2^2+6*l1^4*l2^4-4*l1^2*l2^6+l2^8-4*l1^6*l3^2+4*l1^4*l2^2*l3^2"
             "+4*l1^2*l2^4*l3^2-4*l2^6*l3^2+6*l1^4*l3^4+4*l1^2*l2^2*l3^4+6*l2^4*l3^4-4*l1^2*l3^6"
             "-4*l2^2*l3^6+l3^8-4*l1^6+4*l1^4*l2^2+4*l1^2*l2^4-4*l2^6+4*l1^4*l3^2-40*l1^2*l2^2*l3^2"
             "+4*l2^4*l3^2+4*l1^2*l3^4+4*l2^2*l3^4-4*l3^6+6*l1^4+4*l1^2*l2^2+6*l2^4+4*l1^2*l3^2"
             "+4*l2^2*l3^2+6*l3^4-4*l1^2-4*l2^2-4*l3^2+1")
# the factors Singular prints (factorize(E[1])[1], unit 1 first)
SLIDER3_FACTORS = ["-l1+l2-l3", "l1+l2-l3", "-l1+l2+l3", "l1+l2+l3"]
FOURBAR_FACTORS = ["-l1-l2+l3-1", "-l1-l2+l3+1", "l1-l2+l3-1", "l1-l2+l3+1",
                   "-l1+l2+l3-1", "-l1+l2+l3+1", "l1+l2+l3-1", "l1+l2+l3+1"]


def product(unit, factors):
    ring = factors[0][0].ring
    p = ring.const(unit)
    for g, m in factors:
        p = p * g ** m
    return p


@pytest.mark.parametrize("text, expected", [(SLIDER3_E, SLIDER3_FACTORS), (FOURBAR_E, FOURBAR_FACTORS)])
def test_paper_eliminants_factor_as_singular(text, expected):
    f = parse_poly(PAPER, text)
    unit, factors = factorize(f)
    assert product(unit, factors) == f
    assert all(m == 1 for _, m in factors)
    # the same factors as Singular up to sign; ours have a positive leading coefficient
    assert {g for g, _ in factors} == {normalize(parse_poly(PAPER, t)) for t in expected}
    assert all(g.lc() > 0 for g, _ in factors)
    assert unit == 1


def test_rational_unit_multiplicities_and_order():
    R = PolyRing(QQ, "xyz", MonomialOrder.simple("dp", 3))
    x, y, z = R.gens()
    f = (x - 1) ** 2 * (y + 1) ** 3 * (z - x * y) * QQ(-3) / 4
    unit, factors = factorize(f)
    assert factors == [(x * y - z, 1), (x - 1, 2), (y + 1, 3)]
    assert unit == QQ(3) / 4
    assert product(unit, factors) == f
    unit, factors = factorize(x / 2 - y / 3)
    assert factors == [(3 * x - 2 * y, 1)] and unit == QQ(1) / 6
    assert factorize(R.const(-5)) == (QQ(-5), [])
    assert factorize(R.zero())[1] == []


def test_irreducible_and_nontrivial_factors():
    R = PolyRing(QQ, "xyz", MonomialOrder.simple("lp", 3))
    x, y, z = R.gens()
    unit, factors = factorize(x ** 3 - y ** 3)
    assert {g for g, _ in factors} == {x - y, x ** 2 + x * y + y ** 2}
    assert factorize(x ** 2 + y ** 2 + z ** 2 - 1) == (1, [(x ** 2 + y ** 2 + z ** 2 - 1, 1)])
    f = (x ** 4 - 4 * y ** 2) * (x * z + y ** 5)
    assert {g for g, _ in factorize(f)[1]} == {x ** 2 - 2 * y, x ** 2 + 2 * y, x * z + y ** 5}


def test_prime_field():
    F = GF(32003)
    R = PolyRing(F, "xyz", MonomialOrder.simple("dp", 3))
    x, y, z = R.gens()
    f = (2 * x + 3 * y) * (x - 4 * z) * (z - y)
    unit, factors = factorize(f)
    assert product(unit, factors) == f
    assert {g for g, _ in factors} == {(2 * x + 3 * y).monic(), x - 4 * z, y - z}
    assert all(g.lc() == 1 for g, _ in factors)
    # 32003 = 3 mod 8: -1 and 2 are non-squares, -2 is a square
    assert len(factorize(x ** 2 + y ** 2)[1]) == 1
    assert len(factorize(x ** 2 - 2 * y ** 2)[1]) == 1
    assert len(factorize(x ** 2 + 2 * y ** 2)[1]) == 2
    g = (x * y - 1) ** 3 * (x + z) ** 2
    assert factorize(g)[1] == [(x + z, 2), (x * y - 1, 3)]


def test_squarefree_gcd_division():
    R = PolyRing(QQ, "xyz", MonomialOrder.simple("dp", 3))
    x, y, z = R.gens()
    f = (x - 1) ** 2 * (y + 1) ** 3 * (z - x * y) * 6
    assert squarefree_part(f) == normalize((x - 1) * (y + 1) * (z - x * y))
    assert squarefree_part(R.const(7)) == R.one()
    assert gcd(f, (x - 1) * (z - x * y) * 7) == normalize((x - 1) * (x * y - z))
    assert gcd(x + y, x - y) == R.one()
    assert gcd(R.zero(), 2 * x) == x
    assert divide_exact(f, (x - 1) ** 2) == (y + 1) ** 3 * (z - x * y) * 6
    with pytest.raises(DivisionError):
        divide_exact(f, x + 2)
    G = PolyRing(GF(7), "xy", MonomialOrder.simple("dp", 2))
    u, v = G.gens()
    assert squarefree_part(3 * (u + v) ** 2 * u) == u ** 2 + u * v
    assert gcd(u ** 2 - v ** 2, 2 * u + 2 * v) == u + v


def random_poly(R, rng, terms=3, deg=2):
    p = R.zero()
    for _ in range(terms):
        e = tuple(rng.randint(0, deg) for _ in range(R.nvars))
        p = p + R.monomial(e, rng.randint(-5, 5))
    return p


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
@pytest.mark.parametrize("char", [0, 32003])
def test_live_singular_factors(char):
    rng = random.Random(7)
    R = PolyRing(QQ if char == 0 else GF(char), "xyz", MonomialOrder.simple("dp", 3))
    polys = []
    for _ in range(6):
        f = R.one()
        for _ in range(rng.randint(2, 3)):
            g = random_poly(R, rng)
            if not g.is_constant():
                f = f * g ** rng.randint(1, 2)
        polys.append(f)
    script = f"ring r = {char},(x,y,z),dp; short = 0;\n"
    for f in polys:
        script += f"factorize({f.to_str()});\n"
    blocks = ideal_blocks(run_singular(script))
    assert len(blocks) == len(polys)
    for f, block in zip(polys, blocks):
        theirs = {normalize(parse_poly(R, t)) for t in block[1:]}
        ours = {g for g, _ in factorize(f)[1]}
        assert ours == theirs, f.to_str()
