"""Eliminating one variable from two polynomials over ZZ, one monic in it (kernel/zz_elimination.py):
the principal generator agrees with a strong Gröbner basis (the same ideal given by three generators,
which takes the Gröbner basis route) and with values Macaulay2 1.21 prints."""
from __future__ import annotations

import random

import pytest

from mech.kernel import Block, MonomialOrder, PolyRing
from mech.kernel.coeffs import QQ
from mech.kernel.zz_elimination import eliminate_pair
from mech.kernel.zz_groebner import eliminate, strong_basis

RING = PolyRing(QQ, ["x", "a", "b"], MonomialOrder([Block("dp", 3)], 3))
X, A, B = RING.gen(0), RING.gen(1), RING.gen(2)


def same_ideal(F, G) -> bool:
    from mech.kernel.zz_groebner import contains
    bf, bg = strong_basis(F, RING), strong_basis(G, RING)
    return all(contains(bg, f) for f in F) and all(contains(bf, g) for g in G)


@pytest.mark.parametrize("f, g, expected", [
    (X**2 + A, 2 * X + B, B**2 + 4 * A),                                  # Macaulay2: ideal(b^2+4*a)
    (X**3 + A * X + B, 6 * X**2 + 4 * A, 4 * A**3 + 54 * B**2),           # Macaulay2: ideal(4*a^3+54*b^2)
    (-X**2 + 3, 2 * X - 2, RING.one() * 4),                               # Macaulay2: ideal 4
    (X**2 + A**2, X * A + B * X + A * B, A**4 + 2 * A**3 * B + 2 * A**2 * B**2)])
def test_values_of_macaulay2(f, g, expected) -> None:
    assert eliminate_pair(f, g, 0, RING) == [expected]


def test_agrees_with_strong_bases() -> None:
    rng = random.Random(7)
    for _ in range(6):
        def poly(deg: int):
            p = RING.zero()
            for _ in range(3):
                p = p + rng.randint(-3, 3) * X**rng.randint(0, deg - 1) * A**rng.randint(0, 1) * B**rng.randint(0, 1)
            return p
        f = X**rng.randint(2, 3) + poly(2)
        g = rng.randint(1, 3) * X**rng.randint(1, 2) + poly(2)
        fast = eliminate_pair(f, g, 0, RING)
        if fast is None:
            continue
        slow = eliminate([f, g, f + g], [0], RING)  # three generators: the Gröbner basis route
        assert same_ideal(fast, slow)


def test_not_monic_or_zero_resultant_is_left_to_groebner_bases() -> None:
    assert eliminate_pair(2 * X**2 + A, 3 * X + B, 0, RING) is None
    assert eliminate_pair(X**2 + A, X**2 + A, 0, RING) is None
