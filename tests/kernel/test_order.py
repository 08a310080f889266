"""Monomial orderings against Singular 4.3.1's own term order (hard-coded truths from real runs)."""
import re

import pytest

from mech.kernel.errors import OrderingError
from mech.kernel.order import Block, MonomialOrder

# Singular printed f = x2y2+x2+xy2+xz3+x+y3z+y+z4+z+1 in each ring; terms appear largest first.
SINGULAR = {
    "lp": "x2y2+x2+xy2+xz3+x+y3z+y+z4+z+1",
    "dp": "x2y2+y3z+xz3+z4+xy2+x2+x+y+z+1",
    "Dp": "x2y2+xz3+y3z+z4+xy2+x2+x+y+z+1",
    "wp(1,2,3)": "z4+xz3+y3z+x2y2+xy2+z+x2+y+x+1",
    "Wp(1,2,3)": "z4+xz3+y3z+x2y2+xy2+z+x2+y+x+1",
    "ls": "1+z+z4+y+y3z+x+xz3+xy2+x2+x2y2",
    "ds": "1+x+y+z+x2+xy2+x2y2+y3z+xz3+z4",
    "Ds": "1+x+y+z+x2+xy2+x2y2+xz3+y3z+z4",
    "ws(1,2,3)": "1+x+x2+y+z+xy2+x2y2+y3z+xz3+z4",
    "(dp(1),dp(2))": "x2y2+x2+xz3+xy2+x+y3z+z4+y+z+1",
    "(lp(1),dp(2))": "x2y2+x2+xz3+xy2+x+y3z+z4+y+z+1",
    "(a(1,0,1),dp)": "xz3+z4+x2y2+x2+y3z+xy2+x+z+y+1",
    "(dp(2),ds(1))": "x2y2+xy2+y3z+x2+x+xz3+y+1+z+z4",
    "(ds(1),dp(2))": "y3z+z4+y+z+1+xz3+xy2+x+x2y2+x2",
    "Ws(1,2,3)": "1+x+x2+y+z+xy2+x2y2+y3z+xz3+z4",
    "M(1,1,1,0,0,-1,0,-1,0)": "x2y2+y3z+xz3+z4+xy2+x2+x+y+z+1",
}

ORDERS = {
    "lp": [Block("lp", 3)], "dp": [Block("dp", 3)], "Dp": [Block("Dp", 3)],
    "wp(1,2,3)": [Block("wp", 3, (1, 2, 3))], "Wp(1,2,3)": [Block("Wp", 3, (1, 2, 3))],
    "ls": [Block("ls", 3)], "ds": [Block("ds", 3)], "Ds": [Block("Ds", 3)],
    "ws(1,2,3)": [Block("ws", 3, (1, 2, 3))],
    "(dp(1),dp(2))": [Block("dp", 1), Block("dp", 2)],
    "(lp(1),dp(2))": [Block("lp", 1), Block("dp", 2)],
    "(a(1,0,1),dp)": [Block("a", 0, (1, 0, 1)), Block("dp", 3)],
    "(dp(2),ds(1))": [Block("dp", 2), Block("ds", 1)],
    "(ds(1),dp(2))": [Block("ds", 1), Block("dp", 2)],
    "Ws(1,2,3)": [Block("Ws", 3, (1, 2, 3))],
    "M(1,1,1,0,0,-1,0,-1,0)": [Block("M", 3, (1, 1, 1, 0, 0, -1, 0, -1, 0))],
}


def exponents(term: str) -> tuple[int, ...]:
    e = [0, 0, 0]
    for name, k in re.findall(r"([xyz])(\d*)", term):
        e["xyz".index(name)] = int(k or 1)
    return tuple(e)


@pytest.mark.parametrize("name", sorted(SINGULAR))
def test_term_order_matches_singular(name):
    order = MonomialOrder(ORDERS[name], 3)
    terms = [exponents(t) for t in SINGULAR[name].split("+")]
    assert sorted(terms, key=order.key, reverse=True) == terms


@pytest.mark.parametrize("name", sorted(SINGULAR))
def test_order_is_multiplicative_and_total(name):
    order = MonomialOrder(ORDERS[name], 3)
    terms = [exponents(t) for t in SINGULAR[name].split("+")]
    for a in terms:
        for b in terms:
            assert (order.compare(a, b) == 0) == (a == b)
            for c in terms:
                shifted = (tuple(x + z for x, z in zip(a, c)), tuple(y + z for y, z in zip(b, c)))
                assert order.compare(*shifted) == order.compare(a, b)


def test_global_local_mixed():
    assert MonomialOrder.simple("dp", 3).is_global
    assert MonomialOrder.simple("ds", 3).is_local
    mixed = MonomialOrder([Block("dp", 2), Block("ds", 1)])
    assert not mixed.is_global and not mixed.is_local


def test_degenerate_and_mismatched_orderings_are_rejected():
    with pytest.raises(OrderingError):
        MonomialOrder([Block("M", 2, (1, 1, 2, 2))])
    with pytest.raises(OrderingError):
        MonomialOrder([Block("dp", 2)], 3)


def test_elimination_property():
    assert MonomialOrder([Block("dp", 4), Block("dp", 2)]).is_elimination_for(range(4))
    assert not MonomialOrder.simple("dp", 6).is_elimination_for(range(4))
    assert MonomialOrder.simple("lp", 3).is_elimination_for([0])
