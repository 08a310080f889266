"""The reduced basis over QQ by python-flint's compiled reduction on embedded monomials
(kernel/flint_reduce.py) against Buchberger's reduction in Python, in several orderings."""
import pytest

from mech.kernel import QQ, Block, MonomialOrder, PolyRing
from mech.kernel.buchberger import buchberger, reduce_basis
from mech.kernel.flint_reduce import reduce_basis_qq
from mech.kernel.hilbert_driven import hilbert_driven
from mech.kernel import engines as E
from tests.util import katsura, parse_poly

BLOCK = ["x^2+y*u-1", "y^2-x*v", "z^3-u^2*v", "x*y*z-u-v"]
SMALL = ["x^2+y*u-1", "y^2-x*v", "z*u-2*v^2+x/3"]  # lex bases of BLOCK take Buchberger minutes
ORDERS = [
    ([Block("dp", 3), Block("dp", 2)], BLOCK),
    ([Block("lp", 5)], SMALL),
    ([Block("wp", 5, (3, 1, 2, 1, 4))], BLOCK),
    ([Block("a", 5, (0, 0, 1, 1, 0)), Block("dp", 5)], BLOCK),
    ([Block("dp", 2), Block("lp", 3)], SMALL),
]


@pytest.mark.parametrize("blocks, texts", ORDERS)
def test_same_reduced_basis_as_buchberger(blocks, texts):
    R = PolyRing(QQ, list("xyzuv"), MonomialOrder(blocks))
    gens = [parse_poly(R, t) for t in texts]
    G = buchberger(gens, R)  # not reduced, with non-minimal elements
    ours = reduce_basis_qq(G, R)
    assert ours == reduce_basis(G, R)
    key = R.order.key
    assert all(next(iter(b)) == max(b, key=key) for b in ours)  # leading exponent first
    assert all(type(a) is int for b in ours for e in b for a in e)
    assert [key(next(iter(b))) for b in ours] == sorted(key(next(iter(b))) for b in ours)


def test_hilbert_driven_basis_with_denominators():
    R = PolyRing(QQ, [f"x{i}" for i in range(5)], MonomialOrder([Block("dp", 2), Block("dp", 3)]))
    gens = katsura(R, 4)[:4] + [R.gens()[0] * 3 - R.gens()[4] * 7 - 2]  # rational coefficients after monic
    G = hilbert_driven(gens, R, E._dp_auto)
    assert reduce_basis_qq(G, R) == reduce_basis(G, R)


def test_unit_and_empty():
    R = PolyRing(QQ, list("xy"), MonomialOrder([Block("lp", 2)]))
    one = parse_poly(R, "1")
    assert reduce_basis_qq([one.terms, parse_poly(R, "x^2-y").terms], R) == [one.terms]
    assert reduce_basis_qq([], R) == []
