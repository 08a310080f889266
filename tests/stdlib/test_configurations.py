"""Sampled configurations (stdlib/configurations.py): every exported row satisfies the constraint
equations, modes and circuits are the right ones (checked by hand), CSV and JSON files follow the
file policy."""
from __future__ import annotations

import csv
import json
import math
from fractions import Fraction

import pytest

from mech.stdlib.configurations import sample_configurations
from mech.stdlib.mechanism import parse_mechanism
from tests.util import error, run

CRANK_ROCKER = "ground O A 5; bar O B 2; bar B C 5; bar C A 4"
KITE = "ground O A 1; bar O B 1; bar B C 2; bar C A 2"


def _residual(text, row):
    """The largest |g(row)| over the generators g of J, evaluated exactly at the row's floats."""
    R, J = parse_mechanism(text).constraints()
    point = [Fraction(float(row[n])) for n in R.names]
    return max(abs(float(g.evaluate(point))) for g in J)


def _file(tmp_path, monkeypatch, text, name, n):
    monkeypatch.chdir(tmp_path)
    run(f'LIB "mechanism.lib"; mechanism m = "{text}"; exportConfigurations(m, "{name}", {n});')
    return tmp_path / name


def test_csv_rows_satisfy_the_constraints(tmp_path, monkeypatch):
    """Every row read back from the CSV is a configuration to 1e-9; a crank-rocker's two circuits
    are its two assembly modes (by hand: the transmission angle at C stays in [36.87, 101.54], never
    0 or 180, so the sign of sin mu = c2*s3 - s2*c3 is constant on a circuit, and the mirror image
    in the ground line, the other circuit, has the other sign)."""
    path = _file(tmp_path, monkeypatch, CRANK_ROCKER, "c.csv", 30)
    rows = list(csv.DictReader(path.open()))
    assert rows and all(_residual(CRANK_ROCKER, r) < 1e-9 for r in rows)
    assert {r["mode"] for r in rows} == {"1"} and {r["circuit"] for r in rows} == {"1", "2"}
    signs = {}
    for r in rows:
        sin_mu = float(r["c2"]) * float(r["s3"]) - float(r["s2"]) * float(r["c3"])
        signs.setdefault(r["circuit"], set()).add(sin_mu > 0)
    assert sorted(map(len, signs.values())) == [1, 1] and signs["1"] != signs["2"]
    for r in rows:  # the points and angles agree with the variables
        assert abs(float(r["B_x"]) - 2 * float(r["c1"])) < 1e-12
        assert abs(float(r["C_x"]) - 5 - 4 * -float(r["c3"])) < 1e-9


def test_json_kite_modes(tmp_path, monkeypatch):
    """Kite: both modes have one circuit; on the folded mode B = A (c1 = 1, s1 = 0, the crank's
    angle 0); on the general mode the kite O B C A is symmetric about the line OC (|OB| = |OA|,
    |BC| = |CA|), so C lies on the line through O at half the crank's angle."""
    path = _file(tmp_path, monkeypatch, KITE, "k.json", 12)
    d = json.loads(path.read_text())
    assert [(m["mode"], m["circuits"], m["circuits_assigned"]) for m in d["modes"]] == [(1, 1, True), (2, 1, True)]
    assert d["modes"][0]["name"] == "folded mode: B = A; link 1 frozen at 0°"
    rows = d["rows"]
    assert all(_residual(KITE, r) < 1e-9 for r in rows) and {r["mode"] for r in rows} == {1, 2}
    for r in rows:
        if r["mode"] == 1:
            assert abs(r["B_x"] - 1) < 1e-9 and abs(r["B_y"]) < 1e-9 and abs(r["theta1"]) < 1e-6
        else:  # C on the line through O at half the crank's angle
            half = math.radians(r["theta1"] / 2)
            assert abs(r["C_x"] * math.sin(half) - r["C_y"] * math.cos(half)) < 1e-9


def test_rigid_mode_rows_are_exact():
    """A triangle of bars (mobility 0, |OC| = 3, |CA| = 5, |OA| = 4): C = (0, 3) or (0, -3), each a
    rigid mode over Q, given exactly, one circuit each."""
    s = sample_configurations(parse_mechanism("ground O A 4; bar O C 3; bar C A 5"), 5)
    got = sorted((r["mode"], r["circuit"], round(r["C_x"], 12) + 0.0, round(r["C_y"], 12)) for r in s.rows)
    assert [g[:2] for g in got] == [(1, 1), (2, 1)] and sorted(g[2:] for g in got) == [(0.0, -3.0), (0.0, 3.0)]
    assert [m["name"] for m in s.modes] == ["rigid mode (an isolated configuration: no link moves)"] * 2


def test_sample_command_rows():
    out = run(f'LIB "mechanism.lib"; mechanism m = "{CRANK_ROCKER}"; list L = sampleConfigurations(m, 6);'
              ' size(L[1][3]); jointAngles(m, L[1][3]);')
    assert out.startswith("6\nO ")


@pytest.mark.parametrize("code, message", [
    ('exportConfigurations(m, "../c.csv");', "'..' is not allowed"),
    ('exportConfigurations(m, "c.txt");', "ending in .csv or .json"),
    ('exportConfigurations(m, "c.csv", 0);', "must be in 1.."),
    ('mechanism s = "ground O A 1; bar O B l1; bar B C 2; bar C A 2"; sampleConfigurations(s);', "numeric lengths"),
])
def test_errors(code, message, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    e = error(f'LIB "mechanism.lib"; mechanism m = "{CRANK_ROCKER}";\n{code}')
    assert message in str(e)
