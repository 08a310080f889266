"""Long single python-flint calls of exact linear algebra and univariate polynomials
(``mech.kernel.offload_exact``): FGLM's linear solve over Q (when its multimodular solve gives up),
characteristic polynomials and the squarefree decompositions and factorizations of real-root isolation go to a child when their
estimate is long, with the same results, and Ctrl-C stops them there."""
import _thread
import os
import random
import threading
import time

import flint
import pytest

from mech.kernel import QQ, Block, fglm, fglm_solve, offload, offload_exact
from mech.kernel.engines import standard_basis
from mech.kernel.real_roots import isolate_real_roots

from tests.util import katsura, ring

pytestmark = pytest.mark.skipif(not hasattr(os, "fork"), reason="needs os.fork")


@pytest.fixture
def forking(monkeypatch):
    """Every call goes to a child, as a long one in the shell does."""
    monkeypatch.setattr(offload, "INTERRUPTIBLE", True)
    monkeypatch.setattr(offload, "THRESHOLD", 0.0)


def dense(D, bits, seed=1):
    rnd = random.Random(seed)
    return flint.fmpq_mat(D, D, [flint.fmpq(rnd.getrandbits(bits) - (1 << (bits - 1)), rnd.getrandbits(8) + 1)
                                 for _ in range(D * D)])


def test_results_through_a_child_equal_the_process(forking):
    V, N = dense(6, 16), dense(6, 16, seed=2)
    assert offload_exact.solve(V, N) == V.solve(N)
    assert offload_exact.charpoly(V) == V.charpoly()
    x = flint.fmpz_poly([0, 1])
    p = (x ** 3 - 2) ** 2 * (3 * x + 1) * (x ** 2 + 5)
    assert offload_exact.factor_squarefree(p) == p.factor_squarefree()
    assert offload_exact.factor(p) == p.factor()
    with pytest.raises(ZeroDivisionError):  # a singular system: the child's error comes back
        offload_exact.solve(flint.fmpq_mat(2, 2, [1, 2, 2, 4]), flint.fmpq_mat(2, 1, [1, 1]))


def test_fglm_and_real_roots_use_them(forking, monkeypatch):
    """FGLM's exact solve runs in the process (kernel/fglm_solve.py) and comes here only when
    its multimodular loop gives up (forced: no primes)."""
    monkeypatch.setattr(fglm_solve, "DIRECT", 0.0)
    monkeypatch.setattr(fglm_solve, "MAX_PRIMES", 0)
    monkeypatch.setattr(fglm, "LIFT_HEIGHT", -1)  # the exact conversion (katsura-3 would lift from primes)
    calls = []
    for name in ("solve", "factor_squarefree"):
        real = getattr(offload_exact, name)
        monkeypatch.setattr(offload_exact, name, lambda *a, real=real, name=name: calls.append(name) or real(*a))
    R = ring("abcd", [Block("lp", 4)], QQ)
    gens = katsura(R, 3)
    assert standard_basis(gens, R, "fglm") == standard_basis(gens, R, "buchberger")
    x = flint.fmpz_poly([0, 1])
    assert [r.multiplicity for r in isolate_real_roots((x ** 2 - 2) ** 2 * (x - 1))] == [2, 1, 2]
    assert {"solve", "factor_squarefree"} <= set(calls)


def test_estimates_tell_milliseconds_from_minutes():
    assert offload_exact.solve_seconds(dense(10, 16), dense(10, 16)) < 0.01
    assert offload_exact.solve_seconds(dense(100, 16), dense(100, 16)) > 10     # minutes in flint
    assert offload_exact.charpoly_seconds(dense(10, 16)) < 0.01
    assert offload_exact.charpoly_seconds(dense(120, 16)) > 5                   # 7 s measured


def test_ctrl_c_stops_a_long_exact_solve(monkeypatch):
    monkeypatch.setattr(offload, "INTERRUPTIBLE", True)  # the shell's setting; the estimate decides
    V, N = dense(100, 24), dense(100, 24, seed=2)                  # over a minute in the process
    threading.Timer(1.0, _thread.interrupt_main).start()
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        offload_exact.solve(V, N)
    assert time.monotonic() - started < 30
