"""kernel/f4.py ``reduce_modp`` (the reduced basis over Z/p by one F4 back substitution) against
Buchberger's reduction (kernel/buchberger.py ``reduce_basis``), on the compiled row kernel and
on the pure-Python path."""
from __future__ import annotations

import flint
import pytest
from tests.util import cyclic, katsura, ring

from mech.kernel import GF, Block
from mech.kernel.buchberger import buchberger, reduce_basis
from mech.kernel.f4 import reduce_modp

F = GF(32003)
pytestmark = pytest.mark.usefixtures("row_kernel")


def _systems():
    R = ring("xyzuv", [Block("dp", 3), Block("dp", 2)], F)
    x, y, z, u, v = R.gens()
    yield R, [x * x + y * u - 1, y * y - x * v, z ** 3 - u * u * v, x * y * z - u - v]
    R = ring("abcde", [Block("lp", 5)], F)
    yield R, cyclic(R)
    R = ring("abcd", [Block("dp", 2), Block("dp", 2)], F)
    yield R, katsura(R, 3)


@pytest.mark.parametrize("k", range(3))
def test_reduce_modp_is_buchbergers_reduced_basis(k):
    R, gens = list(_systems())[k]
    basis = buchberger(gens, R)
    expected = reduce_basis(basis, R)
    assert reduce_modp(basis, R) == expected
    assert len(expected) < len(basis) or any(len(a) < len(b) for a, b in zip(expected, basis))  # work was done
    # not monic, not minimal (a multiple of an element, an element twice): the same reduced basis
    x = R.gens()[0].terms
    (one,) = x.values()
    messy = [{e: c * flint.nmod(7 + i, 32003) for e, c in b.items()} for i, b in enumerate(basis)]
    shifted = {tuple(a + b for a, b in zip(e, next(iter(x)))): c * one for e, c in basis[0].items()}
    messy += [shifted, dict(basis[-1])]
    assert reduce_modp(messy, R) == expected
