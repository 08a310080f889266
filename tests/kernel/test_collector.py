"""kernel/collector: the garbage collector paused or thinned out, restored on exit and on errors."""
import gc

import pytest

from mech.kernel.collector import paused, relaxed


def test_paused_restores_the_collector():
    assert gc.isenabled()
    with paused():
        assert not gc.isenabled()
    assert gc.isenabled()
    with pytest.raises(ValueError), paused():
        raise ValueError
    assert gc.isenabled()


def test_relaxed_sets_and_restores_the_threshold():
    before = gc.get_threshold()
    with relaxed(before[0] + 1000):
        assert gc.get_threshold() == (before[0] + 1000, *before[1:])
        with relaxed(before[0] + 10):  # already rarer: unchanged
            assert gc.get_threshold()[0] == before[0] + 1000
    assert gc.get_threshold() == before
    with pytest.raises(ValueError), relaxed(before[0] + 1000):
        raise ValueError
    assert gc.get_threshold() == before
