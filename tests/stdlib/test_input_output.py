"""Input–output analysis (stdlib/input_output.py) against hand-derived values of a crank-rocker, and
the other Grashof types, the change point and a slider-crank."""
from __future__ import annotations

import math

import pytest

from mech.stdlib.analysis import analyze
from mech.stdlib.input_output import input_output
from mech.stdlib.mechanism import parse_mechanism
from mech.stdlib.reports import report_data
from tests.util import error, run

CRANK_ROCKER = "ground O A 5; bar O B 2; bar B C 5; bar C A 4"


def _io(text, inp=1, out=3, trans=("C", 2, 3)):
    m = parse_mechanism(text)
    R, J = m.constraints()
    return input_output(m, J, inp, out, trans)


def test_crank_rocker_hand_derived():
    """Ground g = 5, crank a = 2, coupler b = 5, rocker c = 4.  The rocker's limit positions have the
    crank and coupler aligned, |OC| = b + a = 7 or b - a = 3, so the angle OAC is
    arccos((g^2 + c^2 - |OC|^2) / (2 g c)); the link C A points from C to A, at -OAC for C above the
    ground.  The transmission angle at C has cos = (b^2 + c^2 - |BA|^2) / (2 b c), |BA| in [g-a, g+a]."""
    g, a, b, c = 5, 2, 5, 4
    io = _io(CRANK_ROCKER)
    outs, ins = [], []
    for oc, folded in ((b + a, False), (b - a, True)):
        oac = math.degrees(math.acos((g * g + c * c - oc * oc) / (2 * g * c)))
        cx, cy = g + c * math.cos(math.radians(180 - oac)), c * math.sin(math.radians(180 - oac))
        crank = math.degrees(math.atan2(cy, cx)) + (-180 if folded else 0)
        for sign in (1, -1):  # C above and below the ground
            outs.append(-sign * oac)
            ins.append(sign * crank)
    expected = sorted(zip(ins, outs))
    assert len(io.limit_positions) == 4
    for (i1, o1), (i2, o2) in zip(io.limit_positions, expected):
        assert abs(i1 - i2) < 0.01 and abs(o1 - o2) < 0.01
    swing = sorted(abs(o) for o in outs)
    lo, hi = round(swing[0], 2), round(swing[3], 2)
    assert io.output_range == [(-hi, -lo), (lo, hi)] == [(-101.54, -36.87), (36.87, 101.54)]
    assert io.input_range == [(-180.0, 180.0)] and io.dead_centres == [] and io.singular == []
    mu = [math.degrees(math.acos((b * b + c * c - d * d) / (2 * b * c))) for d in (g - a, g + a)]
    assert io.transmission == (round(mu[0], 2), round(mu[1], 2)) == (36.87, 101.54)


def test_driven_from_the_rocker():
    """The rocker as input: its extremes are dead centres (coupler and crank aligned: the
    transmission angle at B reaches 0 and 180)."""
    io = _io(CRANK_ROCKER, 3, 1, ("B", 2, 1))
    assert io.output_range == [(-180.0, 180.0)] and len(io.dead_centres) == 4
    assert io.transmission == (0.0, 180.0)


@pytest.mark.parametrize("text, output_full, input_full", [
    ("ground O A 2; bar O B 5; bar B C 4; bar C A 6", True, True),      # double-crank
    ("ground O A 5; bar O B 4; bar B C 2; bar C A 6", False, False),    # double-rocker
    ("ground O A 7; bar O B 4; bar B C 3; bar C A 5", False, False),    # non-Grashof
    ("ground O A 5; bar O B 2; bar B C 4; bar C A 3", False, True),     # change point
])
def test_grashof_types(text, output_full, input_full):
    io = _io(text)
    assert (io.output_range == [(-180.0, 180.0)]) == output_full
    assert (io.input_range == [(-180.0, 180.0)]) == input_full


def test_change_point_singular():
    io = _io("ground O A 5; bar O B 2; bar B C 4; bar C A 3")
    assert io.singular == [(180.0, 0.0)]          # the folded configuration: crank back, all aligned
    assert io.output_range == [(-93.82, 93.82)]   # through 0, the output at the change point


def test_slider_crank_coupler_angle():
    """Crank 1, coupler 2, slider on the x-axis: sin(theta2) = -sin(theta1)/2, |theta2| <= 30 or >= 150."""
    io = _io("fix O; bar O A 1; bar A B 2; slider B", 1, 2, None)
    assert io.output_range == [(-30.0, 30.0), (150.0, -150.0)]
    assert io.limit_positions == [(-90.0, 30.0), (-90.0, 150.0), (90.0, -150.0), (90.0, -30.0)]


def test_report_and_command():
    d = report_data(analyze(parse_mechanism(CRANK_ROCKER)))["input_output"]
    assert d["output_range"] == [[-101.54, -36.87], [36.87, 101.54]] and d["input_turns_fully"]
    assert d["transmission_angle"] == [36.87, 101.54]
    out = run(f'LIB "mechanism.lib"; mechanism m = "{CRANK_ROCKER}"; inputOutput(m, 1, 3);')
    assert "  transmission angle: from 36.87 to 101.54 (largest deviation from 90: 53.13)" in out


@pytest.mark.parametrize("code, message", [
    ('mechanism s = "fix O; bar O A 1; bar A B 2; slider B"; inputOutput(s);', "not a four-bar"),
    ('inputOutput(m, 1, 7);', "no link 7"),
    ('inputOutput(m, 1, 1);', "different links"),
    ('inputOutput(m, 1);', "both"),
    ('mechanism s = "fix O; bar O A 1; bar A B 1"; inputOutput(s, 1, 2);', "one degree of freedom"),
])
def test_errors(code, message):
    e = error(f'LIB "mechanism.lib"; mechanism m = "{CRANK_ROCKER}";\n{code}')
    assert message in str(e)


KITE = "ground O A 1; bar O B 1; bar B C 2; bar C A 2"


def _modes(text, inp=1, out=3, trans=("C", 2, 3)):
    from mech.stdlib.input_output import modes_input_output
    a = analyze(parse_mechanism(text))
    return {io.name: io for io in modes_input_output(a.mechanism, a, inp, out, trans).modes}


def test_kite_mode_by_mode():
    """Kite O=(0,0), A=(1,0), |OB|=1, |BC|=|CA|=2 (two modes; J as a whole has a frozen link on one,
    so its Lagrange system is not zero-dimensional).  By hand: on the folded mode B = A the crank
    rests at 0 and C circles about A (the rocker C->A turns fully); the angle at C between CB and CA
    is 0 throughout.  On the general (kite) mode C lies on the bisector of angle AOB, the crank and
    the rocker both turn fully, and the transmission angle at C has cos mu = (4 + 4 - |BA|^2)/8 with
    |BA| in [0, 2]: mu from 0 to 60.  Both modes meet where B = A and C is on the x-axis: the
    rocker at 0 or 180."""
    ios = _modes(KITE)
    folded, general = ios["folded mode: B = A; link 1 frozen at 0°"], ios["general mode"]
    assert folded.frozen == {"input": 0.0} and folded.input_range == [(0.0, 0.0)]
    assert folded.output_range == [(-180.0, 180.0)] and folded.limit_positions == []
    assert folded.transmission == (0.0, 0.0) and folded.singular == [(0.0, 0.0), (0.0, 180.0)]
    assert general.frozen == {} and general.input_range == general.output_range == [(-180.0, 180.0)]
    assert general.dead_centres == general.limit_positions == [] and general.transmission == (0.0, 60.0)
    text = "\n".join(folded.lines())
    assert "input: link 1 is frozen on this mode, at 0.00 (the input does not drive this motion)" in text
    assert "dead-centre" not in text


def test_kite_output_frozen():
    """Driven from the rocker, the folded mode has the output (the crank) frozen at 0 while the
    input turns fully; the angle at B = A between BC and BO = (-1, 0) sweeps 0..180 as C circles."""
    folded = _modes(KITE, 3, 1, ("B", 2, 1))["folded mode: B = A; link 1 frozen at 0°"]
    assert folded.frozen == {"output": 0.0} and folded.input_range == [(-180.0, 180.0)]
    assert "  output: link 1 is frozen on this mode, at 0.00 (the output does not move)" in folded.lines()
    assert folded.transmission == (0.0, 180.0)


def test_parallelogram_modes_turn_fully():
    """Parallelogram four-bar (2; 1, 2, 1): on both modes the crank and the rocker turn fully (the
    rocker C->A is the crank turned by 180 on the parallelogram mode); the angle at C between CB and
    CA spans 0..180 on both."""
    ios = _modes("ground O A 2; bar O B 1; bar B C 2; bar C A 1")
    assert len(ios) == 2
    for io in ios.values():
        assert io.input_range == io.output_range == [(-180.0, 180.0)] and io.transmission == (0.0, 180.0)


def test_kite_command_and_report():
    out = run(f'LIB "mechanism.lib"; mechanism m = "{KITE}"; inputOutput(m);')
    assert "mode by mode:" in out and "  mode 2 (general mode):" in out
    d = report_data(analyze(parse_mechanism(KITE)))["input_output"]
    assert [(x["mode"], x["input_frozen"], x["input_frozen_at"]) for x in d["modes"]] == [(1, True, 0.0), (2, False, None)]
    assert "output_range" not in d  # two modes: the answers are only per mode
    d = report_data(analyze(parse_mechanism(CRANK_ROCKER)))["input_output"]
    assert d["modes"][0]["output_range"] == d["output_range"] and d["modes"][0]["mode"] == 1


def test_crank_rocker_per_circuit():
    """The crank-rocker's two circuits are mirror images in the ground line (the assembly modes):
    by hand, on the circuit with C below the ground the link C->A points up, so the rocker's angle
    stays in [36.87, 101.54]; its limit positions are the extended one (crank towards C, below:
    (-34.05, 101.54)) and the folded one (crank away from C: (126.87, 36.87)).  The other circuit
    is the mirror image; the transmission angle spans the same range on both."""
    (io,) = _modes(CRANK_ROCKER).values()
    assert [c.circuit for c in io.circuits] == [1, 2]
    by_range = {tuple(c.output_range): c for c in io.circuits}
    below, above = by_range[((36.87, 101.54),)], by_range[((-101.54, -36.87),)]
    assert below.limit_positions == [(-34.05, 101.54), (126.87, 36.87)]
    assert above.limit_positions == [(-126.87, -36.87), (34.05, -101.54)]
    for c in (below, above):
        assert c.input_range == [(-180.0, 180.0)] and c.dead_centres == [] and c.transmission == (36.87, 101.54)
    d = report_data(analyze(parse_mechanism(CRANK_ROCKER)))["input_output"]
    assert [c["circuit"] for c in d["modes"][0]["circuits"]] == [1, 2]


def test_singular_values_by_hand():
    """One-sided Jacobi against hand values: diag(3, 2) padded by a zero column; a rank-one
    3x2 matrix u v^T (singular values |u| |v| and 0); the rotation of (3, 4) by 90 degrees."""
    from mech.stdlib.input_output import singular_values
    assert singular_values([[3.0, 0.0, 0.0], [0.0, 2.0, 0.0]]) == [3.0, 2.0, 0.0]
    sv = singular_values([[1.0 * a * b for b in (3.0, 4.0)] for a in (1.0, 2.0, 2.0)])
    assert abs(sv[0] - 15.0) < 1e-12 and abs(sv[1]) < 1e-12
    sv = singular_values([[0.0, -1.0], [1.0, 0.0]])
    assert all(abs(s - 1.0) < 1e-15 for s in sv)


def test_one_circuit_modes_not_sampled(monkeypatch):
    """A mode with one real circuit (the exact count) is not sampled to split its circuits: the
    four-bar with lengths 1, 1, 1 has three modes of one circuit each."""
    import mech.stdlib.configurations as conf

    def refuse(*args, **kwargs):
        raise AssertionError("sampled a mode with one circuit")
    monkeypatch.setattr(conf, "circuit_split", refuse)
    ios = _modes("ground O A 1; bar O B 1; bar B C 1; bar C A 1")
    assert len(ios) == 3 and all(io.circuits == [] for io in ios.values())
