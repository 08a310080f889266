"""The report formats (stdlib/reports.py): one table, FORMATS, drives analyze(m, FORMAT), its default
(the interpreter's settings["report_format"]) and mech --format."""
from __future__ import annotations

import json

import pytest

from mech import Session
from mech.cli import _parser
from mech.dsl.errors import MechError
from mech.stdlib.analysis import run_analysis
from mech.stdlib.mechanism import parse_mechanism
from mech.stdlib.reports import FORMATS, report_data, report_latex, report_text

SLIDER = "fix O; bar O A 1; slider A"
SETUP = f'LIB "mechanism.lib"; mechanism m = "{SLIDER}";'


def test_the_table():
    assert list(FORMATS) == ["text", "json", "latex"]
    a = run_analysis(parse_mechanism(SLIDER))
    assert FORMATS["text"](a) == report_text(a)
    assert json.loads(FORMATS["json"](a)) == report_data(a)
    assert FORMATS["latex"](a) == report_latex(a)


@pytest.mark.parametrize("name", list(FORMATS))
def test_analyze_prints_the_renderer_output(name):
    s = Session()
    s.execute(SETUP)
    assert s.execute(f'analyze(m, "{name}");') == FORMATS[name](run_analysis(parse_mechanism(SLIDER)))


def test_a_new_format_reaches_analyze_and_the_cli(monkeypatch):
    monkeypatch.setitem(FORMATS, "modes", lambda a: f"{len(a.modes)} modes\n")
    s = Session()
    s.execute(SETUP)
    assert s.execute('analyze(m, "modes");') == "2 modes\n"
    assert _parser().parse_args(["--format", "modes"]).format == "modes"
    with pytest.raises(MechError) as e:
        s.execute('analyze(m, "xml");')
    assert "analyze: unknown format 'xml' (text, json, latex or modes)" in str(e.value)


def test_default_format_from_settings():
    s = Session()
    s.execute(SETUP)
    assert s.execute("analyze(m);") == s.execute('analyze(m, "text");')
    s.interpreter.settings["report_format"] = "json"
    assert s.execute("analyze(m);") == s.execute('analyze(m, "json");')
    assert s.execute('analyze(m, "latex");').startswith("\\begin{align*}")  # an explicit format wins


@pytest.mark.parametrize("where", ["argument", "setting"])
def test_unknown_format_lists_the_known_ones(where):
    s = Session()
    s.execute(SETUP)
    if where == "setting":
        s.interpreter.settings["report_format"] = "xml"
    with pytest.raises(MechError) as e:
        s.execute('analyze(m, "xml");' if where == "argument" else "analyze(m);")
    assert "analyze: unknown format 'xml' (text, json or latex)" in str(e.value)
