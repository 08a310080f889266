"""Partial results under a statement's time limit: the analysis' report of what it finished even
when one C call outlasts the analysis' budget and the statement's limit together."""
import pytest

from mech import Session
from mech.dsl.limits import MechLimitError
from mech.stdlib import analysis

from tests.util import LongCCall

FOUR_BAR = 'LIB "mechanism.lib"; mechanism m = "ground O A 4; bar O B 2; bar B C 3; bar C A 3";'


def test_analyze_reports_when_one_c_call_outlasts_its_budget_and_the_limit(monkeypatch):
    call = LongCCall(monkeypatch)
    monkeypatch.setattr(analysis, "motion_modes", lambda a: call())  # the decomposition: one long C call
    s = Session(timeout=2)
    s.execute(FOUR_BAR)
    with pytest.raises(MechLimitError) as info:
        s.execute("analyze(m);")
    assert call.overlap.is_set()
    out = info.value.output
    assert "mobility 1" in out and "motion modes: not determined" in out
    assert "not finished: decomposition: interrupted by the time limit" in out
    assert "time limit exceeded in analyze (the report above is partial)" in info.value.message
    assert s.execute("m;") == "fix O 0 0; fix A 4 0; bar O B 2; bar B C 3; bar C A 3\n"  # the session goes on


@pytest.mark.parametrize("command, name", [
    ("inputOutput(m);", "inputOutput"),
    ("list L = sampleConfigurations(m, 5);", "sampleConfigurations"),
    ('plotCouplerCurve(m, "C", "path.svg");', "plotCouplerCurve"),
    ('plotConfigurations(m, "modes.svg");', "plotConfigurations"),
])
def test_commands_needing_the_whole_analysis_say_it_did_not_finish(command, name, monkeypatch, tmp_path):
    """No answer from a partial analysis (it may lack motion modes): the limit's error, saying so."""
    monkeypatch.chdir(tmp_path)
    call = LongCCall(monkeypatch)
    monkeypatch.setattr(analysis, "motion_modes", lambda a: call())
    s = Session(timeout=1)
    s.execute(FOUR_BAR)
    with pytest.raises(MechLimitError) as info:
        s.execute(command)
    assert info.value.message == (f"time limit exceeded in {name}: the analysis did not finish "
                                  "(decomposition: interrupted by the time limit, and the steps after it)")
    assert not list(tmp_path.iterdir())
