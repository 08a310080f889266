"""The highest corner's top degree (kernel/mora_corner.py), the corner over the variables that
occur, and Mora's packed working polynomial for ds (kernel/mora_packed.py)."""
import random

import pytest
from tests.util import parse_poly

from mech.kernel import GF, QQ, Block, MonomialOrder, PolyRing
from mech.kernel.engines import standard_basis
from mech.kernel.hilbert import hilbert_numerators
from mech.kernel.mora import Elem, Front, _leading_rank, _mora
from mech.kernel.mora_corner import Corner, top_degree
from mech.kernel.mora_packed import PackedFront, Packing
from mech.kernel.poly import divides


def ring(names, field=GF(32003), kind="ds"):
    return PolyRing(field, list(names), MonomialOrder([Block(kind, len(names))]))


def test_top_degree_by_hand():
    assert top_degree([(2, 0), (0, 3)])[0] == 3  # x*y^2
    assert top_degree([(2, 0), (1, 1), (0, 2)])[0] == 1  # x or y
    assert top_degree([(2, 0), (1, 1)]) is None  # y^k outside for every k
    assert top_degree([(0, 0)])[0] == -1  # the unit ideal


def test_top_degree_agrees_with_the_hilbert_series():
    rng = random.Random(7)
    for _ in range(200):
        n = rng.randint(1, 4)
        gens = [tuple(rng.randint(0, 5) for _ in range(n)) for _ in range(rng.randint(1, 6))]
        for i in range(n):
            if rng.random() < 0.85:
                gens.append(tuple(rng.randint(1, 7) if j == i else 0 for j in range(n)))
        _, p, d = hilbert_numerators(gens, n)
        expected = -1 if d < 0 else (len(p) - 1 if d == 0 else None)
        got = top_degree(gens)
        assert (None if got is None else got[0]) == expected
        if got is not None and got[0] >= 0:  # the witness: of that degree, outside the ideal
            assert sum(got[1]) == got[0] and not any(divides(g, got[1]) for g in gens)


def test_corner_over_the_used_variables_only():
    R = ring("wxy")
    c = Corner(R, used=(1, 2))
    assert not c.update((0, 2, 0), lambda: [(0, 2, 0)])
    assert c.update((0, 0, 3), lambda: [(0, 2, 0), (0, 0, 3)]) and c.cut == 3
    # a new leading monomial that does not divide the witness leaves the cut alone
    assert not c.update((0, 2, 1), lambda: [(0, 2, 0), (0, 0, 3), (0, 2, 1)])
    assert c.update((0, 1, 2), lambda: [(0, 2, 0), (0, 0, 3), (0, 1, 2)]) and c.cut == 2


def test_a_variable_that_does_not_occur_keeps_the_corner():
    """Singular's mora_6 situation: w occurs in no generator; the basis is the one of the
    ring without w, and the corner is found."""
    R, S = ring("wxyz"), ring("xyz")
    f = "x*y*z*(x+y+z)^2+(x+y+z)^3+x^7+y^7+z^7"
    gens = [parse_poly(R, f).diff(i) for i in range(1, 4)] + [parse_poly(R, f)]
    basis, corner = _mora(gens, R)
    assert corner.found
    small = [parse_poly(S, f).diff(i) for i in range(3)] + [parse_poly(S, f)]
    assert sorted((0,) + g.lm() for g in standard_basis(small, S)) == \
        sorted(max(b, key=R.order.key) for b in basis)


@pytest.mark.parametrize("field", [GF(32003), QQ])
def test_packed_front_reduces_as_the_plain_one(field):
    R = ring("xyz", field)
    key = R.order.key
    f = parse_poly(R, "3*x*y+x^2*z-5*y^3*z+x^4+2*y^2*z^3")
    g = Elem(dict(parse_poly(R, "x*y+z^3-x^2*y^2").terms), key)
    pk = Packing(3)
    for cut in (None, 5, 4):
        plain, packed = Front(dict(f.terms), _leading_rank(R), cut), PackedFront(dict(f.terms), pk, cut)
        assert plain.lm() == packed.lm() == (1, 1, 0)
        plain.reduce(plain.lm(), g)
        packed.reduce(packed.lm(), g)
        assert plain.p == packed.terms() and plain.lm() == packed.lm()
    u = PackedFront(dict(parse_poly(R, "x*y+x^2*y-3*x*y*z^2").terms), pk)
    assert u.unit_cancelled(u.lm()) and u.terms() == {(1, 1, 0): field.one}
    v = PackedFront(dict(parse_poly(R, "x*y+x^2").terms), pk)
    assert not v.unit_cancelled(v.lm())


def test_top_degree_adds_up_over_disjoint_variables():
    # generators in the variable groups {0,1}, {2}, {3,4}: the top degrees add, checked
    # against the Hilbert series of the whole ideal
    rng = random.Random(11)
    for _ in range(50):
        gens = [(rng.randint(1, 4), 0, 0, 0, 0), (0, rng.randint(1, 4), 0, 0, 0),
                (rng.randint(1, 3), rng.randint(1, 3), 0, 0, 0), (0, 0, rng.randint(1, 5), 0, 0),
                (0, 0, 0, rng.randint(1, 4), 0), (0, 0, 0, 0, rng.randint(1, 4)),
                (0, 0, 0, rng.randint(1, 3), rng.randint(1, 3))]
        _, p, d = hilbert_numerators(gens, 5)
        got = top_degree(gens)
        assert d == 0 and got[0] == len(p) - 1
        assert sum(got[1]) == got[0] and not any(divides(g, got[1]) for g in gens)
    assert top_degree([(2, 0, 0), (0, 3, 0)]) is None  # the last variable is free
