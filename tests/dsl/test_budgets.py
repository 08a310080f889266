"""Budgets inside a statement under a time limit (``mech.dsl.limits.within``): one C call the
watchdog cannot interrupt may outlast a budget and the statement's deadline together; the
budget's exception must still reach its caller (which reports what it finished) and the
statement's limit must still end the statement, within ``overrun`` past its deadline."""
import time
from types import SimpleNamespace

import pytest

from mech.dsl.limits import BudgetExceeded, Limits, MechLimitError, overrun, remaining, within

from tests.util import LongCCall


def interp():
    """What Limits.run saves and restores of an interpreter."""
    return SimpleNamespace(frames=[], ring=None, source=None, stmt=None, argnames=None)


def test_a_budget_pending_across_the_time_limit_reaches_its_caller_with_its_reserve(monkeypatch):
    call = LongCCall(monkeypatch)
    got = {}

    def statement():
        got["ok"], _ = within(0.05, call, reserve=1.0)
        got["left"] = remaining()
        return "partial report"
    assert Limits(timeout=0.5).run(interp(), statement) == "partial report"
    assert call.overlap.is_set()              # the call spanned the budget's end and the statement's limit
    assert got["ok"] is False and got["left"] > 0.5  # the budget's exception, then its reserve (1 s)


def test_the_reserve_never_goes_past_the_bound(monkeypatch):
    call = LongCCall(monkeypatch)
    got = {}

    def statement():
        got["deadline"] = time.monotonic() + remaining()
        got["ok"], _ = within(0.05, call, reserve=100.0)
        got["end"] = time.monotonic() + remaining()
    Limits(timeout=0.2).run(interp(), statement)
    assert got["ok"] is False and got["end"] == pytest.approx(got["deadline"] + overrun(0.2), abs=0.01)


def test_an_inner_budget_does_not_replace_an_outer_ones_exception(monkeypatch):
    call = LongCCall(monkeypatch)
    got = {"inner": "not returned"}

    def inner():  # its budget runs out during the call too, after the outer one's
        got["inner"] = within(0.3, call)
    ok, _ = Limits(timeout=0.5).run(interp(), lambda: within(0.05, inner, reserve=0.5))
    assert ok is False and got["inner"] == "not returned" and call.overlap.is_set()


def test_the_time_limit_waits_for_a_pending_budget_only_so_long():
    def swallowing():  # a caller that (wrongly) swallows its budget's exception
        while True:
            try:
                time.sleep(0.01)
            except BudgetExceeded:
                pass
    start = time.monotonic()
    with pytest.raises(MechLimitError, match="time limit of 0.3 s exceeded"):
        Limits(timeout=0.3).run(interp(), within, 0.05, swallowing)
    assert time.monotonic() - start >= 0.3 + overrun(0.3)


def test_the_watcher_outside_waits_longer_than_a_report_may():
    from mech.watcher import grace
    assert all(grace(t) >= overrun(t) + 1 for t in (0.1, 1, 3, 10, 16, 100))


def test_an_exception_lost_in_a_weakref_callback_is_raised_again(monkeypatch, capsys):
    """Python drops an exception raised in a weakref callback ("Exception ignored in ..."): the
    watchdog's is raised again at its next check, with nothing printed."""
    import sys
    import weakref

    from mech.dsl import limits
    monkeypatch.setattr(sys, "unraisablehook", limits._unraisable)  # pytest puts its own in place
    seen = {"callback": "not run"}

    def callback(_):
        seen["callback"] = "interrupted"
        while True:  # the budget's exception arrives here, where Python cannot raise it
            time.sleep(0.005)

    def body():
        class Thing:
            pass
        thing = Thing()
        ref = weakref.ref(thing, callback)  # noqa: F841
        del thing                           # the callback runs now, until the exception arrives
        seen["after"] = True
        while True:
            time.sleep(0.005)                # ... and here again
    assert within(0.05, body) == (False, None)
    assert seen == {"callback": "interrupted", "after": True}
    assert "Exception ignored" not in capsys.readouterr().err
