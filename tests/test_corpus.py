"""The corpus: scripts in tests/corpus/*.sing with Singular 4.3.1's output in *.out must print exactly
that under mech.  The live check (marker singular) confirms the recorded outputs against Singular."""

import pytest
from tests.util import ROOT, SINGULAR

from mech import Session

CORPUS = ROOT / "tests" / "corpus"
SCRIPTS = sorted(CORPUS.glob("*.sing"))


@pytest.mark.parametrize("script", SCRIPTS, ids=[s.stem for s in SCRIPTS])
def test_corpus_matches_singular_output(script, monkeypatch):
    monkeypatch.chdir(CORPUS)
    out = Session().execute(script.read_text(), script.name)
    assert out == script.with_suffix(".out").read_text()


@pytest.mark.singular
@pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")
@pytest.mark.parametrize("script", SCRIPTS, ids=[s.stem for s in SCRIPTS])
def test_recorded_outputs_are_singulars(script):
    import sys
    sys.path.insert(0, str(CORPUS))
    from regen import singular_output
    assert singular_output(script) == script.with_suffix(".out").read_text()
