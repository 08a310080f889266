"""Randomized differential tests of standard bases in local orderings: against Singular 4.3.1's
``std`` in ``ds`` and between mech's two engines (Mora, Lazard).

The seed is fixed; set ``MECH_SEED`` to explore others (the failing ideal is in the message).
Ideals are compared as ideals of the local ring: same leading ideal for both bases and for
their union."""
import os
import random
import subprocess

import pytest
from tests.util import SINGULAR, ideal_blocks, parse_poly

from mech.kernel import QQ, Block, MonomialOrder, PolyRing
from mech.kernel.engines import standard_basis

SEED = int(os.environ.get("MECH_SEED", "20261121"))
CASES = 80


def random_ideal(rng: random.Random, order: str) -> list:
    """1 to 3 generators in 2 or 3 variables, 2 to 4 terms of degree 1 to 5 each, small
    integer coefficients, no constant terms (so the origin lies on the variety)."""
    n = rng.choice([2, 3])
    R = PolyRing(QQ, "xyz"[:n], MonomialOrder([Block(order, n)]))
    gens = []
    for _ in range(rng.choice([1, 2, 3])):
        terms = {}
        for _ in range(rng.randint(2, 4)):
            e = [0] * n
            for _ in range(rng.randint(1, 5)):
                e[rng.randrange(n)] += 1
            terms[tuple(e)] = rng.choice([-3, -2, -1, 1, 2, 3])
        gens.append(R.from_dict(terms))
    return gens


def leading(basis):
    return sorted(g.lm() for g in basis)


def singular_std(gens, order: str):
    """Singular's std, or None when Singular takes longer than 5 s (it hangs on a few)."""
    R = gens[0].ring
    script = (f"ring r = 0, ({','.join(R.names)}), {order}; short = 0;\n"
              f"ideal i = {', '.join(g.to_str() for g in gens)};\nstd(i);\nquit;\n")
    try:
        out = subprocess.run([SINGULAR, "-q", "--no-warn"], input=script, text=True, capture_output=True,
                             timeout=5).stdout
    except subprocess.TimeoutExpired:
        return None
    return [parse_poly(R, t) for t in ideal_blocks(out)[0]]


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
def test_random_std_in_ds_against_singular():
    rng = random.Random(SEED)
    compared = 0
    for case in range(CASES):
        gens = random_ideal(rng, "ds")
        theirs = singular_std(gens, "ds")
        if theirs is None:
            continue
        ours = standard_basis(gens)
        label = f"MECH_SEED={SEED} case {case}: {[g.to_str() for g in gens]}"
        assert leading(ours) == leading(theirs), label
        assert leading(standard_basis(ours + theirs)) == leading(theirs), label
        compared += 1
    assert compared >= CASES * 3 // 4


@pytest.mark.parametrize("order", ["ds", "ls"])
def test_random_engines_agree(order):
    rng = random.Random(SEED + 1)
    for case in range(CASES // 2):
        gens = random_ideal(rng, order)
        mora, lazard = standard_basis(gens, engine="auto"), standard_basis(gens, engine="lazard")
        label = f"MECH_SEED={SEED} {order} case {case}: {[g.to_str() for g in gens]}"
        assert leading(mora) == leading(lazard), label
        assert leading(standard_basis(mora + lazard, engine="lazard")) == leading(lazard), label
