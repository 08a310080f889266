"""Long python-flint calls in a forked child (``mech.kernel.offload``): results and errors come
back, Ctrl-C and a dying child are handled, small calls and other threads stay in the process."""
import _thread
import os
import signal
import threading
import time

import pytest

from mech.kernel import GF, QQ, MonomialOrder, PolyRing, flint_bridge, offload

pytestmark = pytest.mark.skipif(not hasattr(os, "fork"), reason="needs os.fork")


@pytest.fixture
def forking(monkeypatch):
    """Every estimated call goes to a child, as in the shell."""
    monkeypatch.setattr(offload, "INTERRUPTIBLE", True)
    monkeypatch.setattr(offload, "THRESHOLD", 0.0)


def always(*_):
    return 1.0


def gone(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return True
    return False


def test_the_call_runs_in_a_child_and_its_result_comes_back(forking):
    assert offload.call(always, os.getpid) != os.getpid()
    big = {(i, i + 1): i * 10**40 for i in range(3 * offload.CHUNK + 5)}  # sent in pieces
    assert offload.call(always, lambda: big) == big
    assert offload.call(always, lambda: list(big)) == list(big)


def test_small_calls_and_other_threads_stay_in_the_process(forking, monkeypatch):
    monkeypatch.setattr(offload, "THRESHOLD", 1.0)
    assert offload.call(lambda: 0.5, os.getpid) == os.getpid()
    monkeypatch.setattr(offload, "THRESHOLD", 0.0)
    seen = []
    worker = threading.Thread(target=lambda: seen.append(offload.call(always, os.getpid)))
    worker.start()
    worker.join()
    assert seen == [os.getpid()]          # no limit there, and Ctrl-C reaches only the main thread
    monkeypatch.setattr(offload, "INTERRUPTIBLE", False)
    assert offload.call(always, os.getpid) == os.getpid()   # scripts without limits


def test_errors_come_back(forking):
    with pytest.raises(ZeroDivisionError):
        offload.call(always, lambda: 1 // 0)

    class Odd(Exception):
        def __reduce__(self):
            raise TypeError("no pickling")
    with pytest.raises(offload.ChildError, match="Odd"):
        offload.call(always, lambda: (_ for _ in ()).throw(Odd("x")))


def test_a_child_that_dies_is_out_of_memory(forking):
    with pytest.raises(MemoryError):  # GMP aborts when an allocation fails
        offload.call(always, lambda: os.kill(os.getpid(), signal.SIGABRT))


def test_ctrl_c_kills_the_child_at_once(forking, tmp_path):
    where = tmp_path / "pid"

    def long():
        where.write_text(str(os.getpid()))
        time.sleep(300)
    threading.Timer(1.0, _thread.interrupt_main).start()
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        offload.call(always, long)
    assert time.monotonic() - started < 60      # 1 s, on a busy machine a few
    assert gone(int(where.read_text()))          # killed and reaped
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


@pytest.mark.parametrize("field", [QQ, GF(32003)])
def test_polynomial_results_match_the_process(field, monkeypatch):
    ring = PolyRing(field, "xyz", MonomialOrder.simple("dp", 3))
    x, y, z = ring.gens()
    f = x + 2 * y - 3 * z + 1
    inside = flint_bridge.power(field, 3, f.terms, 9)
    monkeypatch.setattr(offload, "INTERRUPTIBLE", True)
    monkeypatch.setattr(offload, "THRESHOLD", 0.0)
    assert offload.possible() and flint_bridge.power(field, 3, f.terms, 9) == inside
    assert flint_bridge.product(field, 3, f.terms, (f ** 3).terms) == (f ** 4).terms


def test_estimates_tell_milliseconds_from_minutes():
    ring = PolyRing(QQ, "xyz", MonomialOrder.simple("dp", 3))
    x, y, z = ring.gens()
    f = x + y + z + 1
    assert flint_bridge.power_seconds(ring.field, f.terms, 1500) > 1000
    assert flint_bridge.power_seconds(ring.field, f.terms, 20) < 0.01
    g = f ** 10
    assert flint_bridge.product_seconds(ring.field, g.terms, g.terms) < 0.1
