"""Circuit counts shared by the report and the exported configurations: computed once per mode, the
exact methods' refusal remembered, a budget's stop remembered with the time it ran."""
from __future__ import annotations

import pytest

import mech.kernel.real_curve as real_curve
from mech.kernel import QQ, MonomialOrder, PolyRing
from mech.kernel.real_roots import RealSolvingError
from mech.stdlib import circuit_counts, configurations
from mech.stdlib.circuit_counts import circuit_count, time_tried

R = PolyRing(QQ, ["x", "y"], MonomialOrder.simple("dp", 2))
x, y = R.gens()


def _counting(monkeypatch, behaviour=None) -> list:
    calls: list = []
    real = real_curve.curve_topology

    def counted(*args, **kwargs):
        calls.append(args)
        if behaviour is not None:
            behaviour()
        return real(*args, **kwargs)
    monkeypatch.setattr(real_curve, "curve_topology", counted)
    monkeypatch.setattr(circuit_counts, "_COUNTS", {})
    monkeypatch.setattr(circuit_counts, "_TRIED", {})
    return calls


def test_counted_once(monkeypatch):
    calls = _counting(monkeypatch)
    two = (x ** 2 + y ** 2 - 1) * ((x - 3) ** 2 + y ** 2 - 1)   # two disjoint circles
    assert circuit_count([two], R) == 2
    assert circuit_count([x ** 2 + y ** 2 - 1], R) == 1
    assert circuit_count([two], R) == 2                          # remembered
    assert len(calls) == 2
    assert configurations._circuit_count([two], R) == 2          # the export asks the same table
    assert len(calls) == 2


def test_refusal_remembered(monkeypatch):
    def refuse():
        raise RealSolvingError("not a curve")
    calls = _counting(monkeypatch, refuse)
    for _ in range(2):
        with pytest.raises(RealSolvingError):
            circuit_count([x + y], R)
    assert len(calls) == 1
    assert configurations._circuit_count([x + y], R) is None


class _Stop(BaseException):
    """As a budget's watchdog raises."""


def test_budget_stop_remembered(monkeypatch):
    def stop():
        raise _Stop()
    calls = _counting(monkeypatch, stop)
    with pytest.raises(_Stop):
        circuit_count([x * y - 1], R)
    assert time_tried([x * y - 1], R) > 0
    monkeypatch.setattr(configurations, "CIRCUIT_BUDGET", time_tried([x * y - 1], R))
    assert configurations._circuit_count([x * y - 1], R) is None  # not started again: no more time than before
    assert len(calls) == 1
