"""Choosing the Gröbner engine from the language (``engine("NAME")``), from Python
(``Session(engine=...)``) and from the command line (``mech --engine NAME``): a newly registered
engine is reached by ``std`` and the commands built on it; bad names are clear errors."""
from __future__ import annotations

import subprocess
import sys

import pytest

from mech import MechError, Session
from mech.kernel import engines
from mech.kernel.buchberger import buchberger

SCRIPT = "ring r = 0,(x,y,z),dp; ideal I = x2-y, xy-z; std(I); eliminate(I, y);"


@pytest.fixture
def toy():
    """A registered engine "toy" (Buchberger, counting its calls), removed afterwards."""
    calls: list[int] = []

    def run(gens, ring):
        calls.append(len(gens))
        return buchberger(gens, ring)
    engines.register("toy", run, "Buchberger, counted")
    engines.clear_cache()
    yield calls
    del engines.ENGINES["toy"]
    engines.clear_cache()


def test_std_reaches_a_registered_engine_from_the_language(toy):
    assert Session().execute(SCRIPT) and toy == []  # auto: the toy is not used
    engines.clear_cache()
    out = Session().execute('engine("toy"); engine();' + SCRIPT)
    assert out == "toy\n" + Session().execute(SCRIPT)
    assert len(toy) >= 2  # std and the elimination's basis


def test_session_engine_keyword(toy):
    s = Session(engine="toy")
    assert s.execute("engine();") == "toy\n"
    s.execute(SCRIPT)
    assert toy
    with pytest.raises(ValueError, match="unknown engine 'nope' \\(known: auto, buchberger"):
        Session(engine="nope")


def test_every_engine_gives_the_same_output():
    expected = Session().execute(SCRIPT)
    for name, _ in engines.list_engines():
        engines.clear_cache()
        assert Session(engine=name).execute(SCRIPT) == expected, name


def test_bad_engine_names():
    with pytest.raises(MechError, match="unknown engine 'nope' \\(known: auto, buchberger"):
        Session().execute('engine("nope");')


def test_cli_engine_option():
    run = [sys.executable, "-m", "mech", "--engine", "buchberger", "-c", 'engine();' + SCRIPT]
    r = subprocess.run(run, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and r.stdout == "buchberger\n" + Session().execute(SCRIPT)
    r = subprocess.run([sys.executable, "-m", "mech", "--engine", "nope", "-c", "1;"],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 2 and "invalid choice: 'nope'" in r.stderr
