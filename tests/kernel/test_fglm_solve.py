"""FGLM's linear solve over QQ (kernel/fglm_solve.py): flint's solve for small systems, the
multimodular loop for the others; both against fmpq_mat.solve."""
import random

import flint
import pytest

from mech.kernel import fglm_solve
from mech.kernel.fglm_solve import solve_qq


def random_system(rng, D, L, bits):
    def q():
        return flint.fmpq(rng.randrange(-2 ** bits, 2 ** bits), rng.randrange(1, 2 ** (bits // 2 + 1)))
    return flint.fmpq_mat(D, D, [q() for _ in range(D * D)]), flint.fmpq_mat(D, L, [q() for _ in range(D * L)])


@pytest.mark.parametrize("direct", [True, False], ids=["direct", "multimodular"])
def test_solutions_agree_with_flint(direct, monkeypatch):
    monkeypatch.setattr(fglm_solve, "DIRECT", 1e9 if direct else 0)
    rng = random.Random(7)
    for D, L, bits in [(1, 1, 4), (5, 3, 8), (12, 4, 30), (16, 3, 12)]:
        V, N = random_system(rng, D, L, bits)
        assert solve_qq(V, N) == V.solve(N)


def test_multimodular_solve_of_a_sparse_system_with_large_answers(monkeypatch):
    """A bidiagonal system whose solution entries grow to thousands of bits."""
    monkeypatch.setattr(fglm_solve, "DIRECT", 0)
    D = 30
    V = flint.fmpq_mat(D, D, [(flint.fmpq(3, 7) if i == j else (-977 if j == i - 1 else 0))
                              for i in range(D) for j in range(D)])
    N = flint.fmpq_mat(D, 2, [flint.fmpq(i + 1, 5) for i in range(2 * D)])
    X = solve_qq(V, N)
    assert V * X == N
    assert max(int(x.p).bit_length() for x in X.entries()) > 300


@pytest.mark.parametrize("direct", [True, False], ids=["direct", "multimodular"])
def test_singular_systems_raise(direct, monkeypatch):
    monkeypatch.setattr(fglm_solve, "DIRECT", 1e9 if direct else 0)
    V = flint.fmpq_mat(3, 3, [1, 2, 3, 2, 4, 6, 0, 1, flint.fmpq(1, 2)])
    with pytest.raises(ZeroDivisionError):
        solve_qq(V, flint.fmpq_mat(3, 1, [1, 1, 1]))
