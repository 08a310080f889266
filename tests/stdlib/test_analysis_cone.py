"""Local analysis at a singular configuration (stdlib/analysis_points.py): the kind, the local components and the
transition come first, from the motion modes; the tangent cone of J (a local standard basis, which does not
finish on Bricard's 6R loop) has its own budget, and when it runs out the report gives the cone as a set (the
union of the local components' cones) and says so."""
from __future__ import annotations

import pytest

from mech.kernel.ideals import dp_ring, ideals_equal, move
from mech.kernel.primdec import radical
from mech.stdlib import analysis_points
from mech.stdlib.analysis import analyze
from mech.stdlib.mechanism import parse_mechanism
from mech.stdlib.reports import report_data, report_text

PARALLELOGRAM = "ground O A 4; bar O B 2; bar B C 4; bar C A 2"  # two modes that meet


def _spin(*args):
    while True:
        pass


def test_cone_out_of_budget_keeps_the_classification(monkeypatch):
    full = analyze(parse_mechanism(PARALLELOGRAM))
    assert "components meet" in [s.kind for s in full.singular]
    assert full.singular and all(not s.cone_note for s in full.singular)
    monkeypatch.setattr(analysis_points, "CONE_BUDGET", 0.3)
    monkeypatch.setattr(analysis_points, "cone_at_point", _spin)
    part = analyze(parse_mechanism(PARALLELOGRAM))
    assert [(s.kind, s.transition, s.modes) for s in part.singular] == \
        [(s.kind, s.transition, s.modes) for s in full.singular]
    for p, f in zip(part.singular, full.singular):
        assert len(p.local_components) == len(f.local_components)
        ring = dp_ring(f.tangent_cone[0].ring)      # the same set: the radicals of the two cones agree
        assert ideals_equal(radical(move(p.tangent_cone, ring), ring), radical(move(f.tangent_cone, ring), ring), ring)
        assert p.cone_note.startswith("as a set: the union of the local components' cones")
    text = report_text(part)
    assert "tangent cone (coordinates centred at q1; as a set: the union of the local components' cones (the ideal " \
           "of lowest forms ran out of its 0.3 s budget)): <" in text
    assert report_data(part)["singular"][0]["tangent_cone_note"] == part.singular[0].cone_note
    assert "tangent_cone_note" not in report_data(full)["singular"][0]


def test_relaxed_gc_restores_the_threshold():
    """The analysis raises the young generation's threshold while it runs and restores it after,
    also when it fails."""
    import gc

    from mech.stdlib.analysis import YOUNG_THRESHOLD, relaxed_gc
    old = gc.get_threshold()
    try:
        gc.set_threshold(700, *old[1:])
        with relaxed_gc():
            assert gc.get_threshold()[0] == YOUNG_THRESHOLD
        assert gc.get_threshold()[0] == 700
        with pytest.raises(ValueError), relaxed_gc():
            raise ValueError
        assert gc.get_threshold()[0] == 700
    finally:
        gc.set_threshold(*old)
