"""The joint model's registry (statements, syntax help, variables) and the checks that catch likely
mistakes in a description: one test per message, each naming the statement."""
from __future__ import annotations

import pytest

from mech import Session
from mech.dsl.errors import MechError
from mech.dsl.printing import poly_str
from mech.stdlib.analysis import analyze
from mech.stdlib.joints import all_forms, classes, keywords, syntax
from mech.stdlib.mechanism import MechanismError, parse_mechanism
from mech.stdlib.reports import report_data, report_text
from tests.util import error


# ---------------------------------------------------------------- the registry
def test_keywords_and_help_come_from_the_registry():
    assert keywords()[:6] == ("ground", "fix", "bar", "prismatic", "body", "slider")
    assert {"revolute", "cylindrical", "universal"} <= set(keywords())
    help_text = syntax()
    for word, form in all_forms():
        assert f"{word} {form.args}" in help_text and form.meaning in help_text
    assert [c.__name__ for c in classes("slider")] == ["Slider", "LineSlider"]


@pytest.mark.parametrize("text", [
    "fix O 0 0; bar O A l1; bar A B l2; slider B",
    "fix O 0 0; fix A 1 0; bar O B l1; bar B C l2; bar C A l3",
    "fix O 0 0; fix A 1 0; fix G 2 0; bar O B 1; bar B C 1; body A C 1 0 E 0 1; bar E F 1; bar F G 1",
    "fix O 0 0; bar O A 1; prismatic A B; slider B 1 1 0",
    "fix O 0 1; fix Q 0 1/2; bar O A 1; bar Q B 2; bar B C 3; slider A Q B; slider C",
    "fix O 0 0 0; fix P 1 0 0; bar O A 1; body A B 1 0 0 C 0 1 0; bar P B 1; bar O C 2",
    "revolute A a 1 twist 0 1; revolute B d 1/2 a 4/5 twist 3/5 4/5; prismatic C theta 0 1 a 1; "
    "cylindrical D a 2 twist 0 -1; universal E",
])
def test_canonical_text_reads_back_the_same(text):
    m = parse_mechanism(text)
    assert str(m) == text and str(parse_mechanism(str(m))) == text


@pytest.mark.parametrize("text, variables", [
    ("fix O; bar O A 1; prismatic A B; slider B", ["c1", "s1", "c2", "s2", "d2"]),
    ("slider A; bar A B 2; slider B 1 0 0", ["c1", "s1", "x_A", "y_A"]),
    ("fix O 0 0 0; bar O A 1; body A B 1 0 0 C 0 1 0",
     ["r11_2", "r21_2", "r31_2", "r12_2", "r22_2", "r32_2", "x_A", "y_A", "z_A"]),
    ("revolute A a 1 twist 0 1; prismatic B a 1 twist 0 1; cylindrical C a 1 twist 0 1; universal D a 1",
     ["c_A", "s_A", "d_B", "c_C", "s_C", "d_C", "c_D", "s_D", "c2_D", "s2_D"]),
    ("revolute A a 1 twist 0 1; revolute B a 1 twist 0 1; revolute C a 1 twist 0 1; revolute D a 1 twist 0 1",
     ["c_A", "s_A", "c_D", "s_D"]),   # the cut link's two joints are left out
])
def test_variable_names_follow_the_table(text, variables):
    assert parse_mechanism(text).variables() == variables


def test_the_old_syntax_gives_the_old_ideal():
    R, gens = parse_mechanism("fix O; bar O A l1; bar A B l2; slider B 0 1 e").constraints()
    assert R.names == ("c1", "s1", "c2", "s2", "l1", "l2", "e")
    assert [poly_str(g) for g in gens] == ["s1*l1+s2*l2-e", "c1^2+s1^2-1", "c2^2+s2^2-1"]


def test_block_form_accepts_the_new_statements():
    out = Session().execute('LIB "mechanism.lib";\nmechanism m {\n  revolute A twist 0 1; revolute B twist 3/5 4/5;\n'
                            '  revolute C twist 0 1; revolute D twist 5/13 12/13;\n}\nmobility(m);\n')
    assert out == "1\n"


# ---------------------------------------------------------------- errors: one per message
@pytest.mark.parametrize("text, message", [
    ("fix O; fix O 1 0; bar O A 1",
     "statement 2 'fix O 1 0': O is already fixed at (0, 0) by statement 1 'fix O' (a point is fixed once)"),
    ("fix O; bar O A 0", "statement 2 'bar O A 0': the length of a bar is positive, not 0"),
    ("fix O; bar O A -2", "statement 2 'bar O A -2': the length of a bar is positive, not -2"),
    ("ground O A 0; bar O B 1", "statement 1 'ground O A 0': the ground length is 0: O and A would be one point"),
    ("fix O; bar O O 1", "statement 2 'bar O O 1': a bar joins two different points, not O to itself"),
    ("fix O; bar O A 1; bar A B 1; slider C",
     "statement 4 'slider C': C is not a point of any link or fixed point (an undefined point: a misspelt name?)"),
    ("fix O; bar O A 1; slider A 0 0 1", "statement 3 'slider A 0 0 1': a*x + b*y = c is no line when a = b = 0"),
    ("fix O; body O A 0 0", "statement 2 'body O A 0 0': point A is at the body's origin O (local coordinates 0)"),
    ("fix O; body O A 1 0 A 0 1", "statement 2 'body O A 1 0 A 0 1': point A is listed twice in the body"),
    ("fix O; body O A 1", "statement 2 'body O A 1': 'body' takes A B u v [C u v ...] (a point and 2 local "
                          "coordinates for each point after the first), not 3 arguments"),
    ("fix O; bar O C 1; slider C B", "statement 3 'slider C B': 'slider' takes 1, 3 or 4 arguments (slider P | "
                                     "slider P a b c | slider P A B), not 2"),
    ("fix O; bar O A", "statement 2 'bar O A': 'bar' takes 3 arguments (bar A B l), not 2"),
    ("fix O; rod O A 1", "statement 2 'rod O A 1': unknown statement 'rod' (expected ground, fix, bar, prismatic, "
                         "body, slider, revolute, cylindrical, universal, helical or gear)"),
    ("fix O 0 0 0; fix P 1 0", "statement 1 'fix O 0 0 0' is spatial but statement 2 'fix P 1 0' is planar: "
                               "a mechanism is either planar or spatial"),
    ("revolute A; revolute A; revolute B",
     "statement 2 'revolute A': the joint name A is used by statement 1 'revolute A' already (name each joint once)"),
    ("revolute A; revolute B", "statement 2 'revolute B': a loop needs at least three joints, not 2"),
    ("revolute A; revolute B; revolute C; fix O", "statement 4 'fix O': a loop of joints (revolute, prismatic, "
     "cylindrical, universal, helical) is described by its joints alone: points, bars and bodies cannot be added to it"),
    ("fix O; fix Q 2 0; bar O A 1; bar Q B 1; gear O Q 1/2", "statement 5 'gear O Q 1/2': the gear ratio is a "
     "non-zero integer (the number of turns of the gear at Q per turn of the one at O), not 1/2"),
    ("fix O; fix Q 2 0; bar O A 1; bar Q B 1; gear O Q 0", "statement 5 'gear O Q 0': the gear ratio is a non-zero "
     "integer (the number of turns of the gear at Q per turn of the one at O), not 0"),
    ("fix O; fix Q 2 0; bar O A 1; bar Q B 1; gear O Q -1", "statement 5 'gear O Q -1': an internal gear pair of "
     "ratio -1 would have two gears of one size, one inside the other"),
    ("fix O; bar O A 1; gear O X 2", "statement 3 'gear O X 2': X is not a point of any link or fixed point "
                                     "(an undefined point: a misspelt name?)"),
    ("helical A a 1; revolute B; revolute C", "statement 1 'helical A a 1': a helical joint needs its pitch "
                                               "(helical J pitch P: the slide per radian of turn)"),
    ("helical A pitch 0; revolute B; revolute C",
     "statement 1 'helical A pitch 0': a helical joint of pitch 0 does not slide: write revolute A"),
    ("helical A pitch p; revolute B; revolute C",
     "statement 1 'helical A pitch p': the pitch of a helical joint is a number, not the name 'p'"),
    ("revolute A a -1; revolute B; revolute C",
     "statement 1 'revolute A a -1': a is the distance between the joint axes (a length >= 0), not -1"),
    ("revolute A twist 1 1; revolute B; revolute C", "statement 1 'revolute A twist 1 1': twist 1 1: cos^2 + sin^2 "
     "= 2, not 1 (give a rational point of the unit circle such as 3/5 4/5, or 0 1 for 90 degrees)"),
    ("revolute A b 1; revolute B; revolute C", "statement 1 'revolute A b 1': 'b' is not a parameter of a "
                                               "revolute joint (its parameters: d, a, twist)"),
    ("revolute A twist 0; revolute B; revolute C",
     "statement 1 'revolute A twist 0': 'twist' needs its cosine and sine (such as 3/5 4/5)"),
    ("bar A B 1; bar B C 1", "mechanism: nothing is fixed (fix a point, or put one on a fixed line with slider)"),
])
def test_mistakes_are_errors_naming_the_statement(text, message):
    with pytest.raises(MechanismError) as e:
        parse_mechanism(text).constraints()
    assert e.value.message == message


def test_errors_in_scripts_name_the_line():
    e = error('LIB "mechanism.lib";\nmechanism m = "fix O; fix O 1 0";\n')
    assert e.line == 2 and e.message.startswith("mechanism: statement 2 'fix O 1 0': O is already fixed")


def test_setlengths_refuses_a_zero_length():
    m = parse_mechanism("fix O; bar O A l1; bar A B l2; slider B")
    with pytest.raises(MechanismError, match=r"statement 3 'bar A B l2': the length of a bar is positive, not 0"):
        m.with_values({"l1": 1, "l2": 0})


# ---------------------------------------------------------------- warnings: one per message
@pytest.mark.parametrize("text, message", [
    ("fix O; bar O A 1; bar A B 1; bar B Cx 1; slider B",
     "statement 4 'bar B Cx 1': Cx appears in no other statement: the link dangles (a misspelt point name?)"),
    ("fix O; fix Q 1 0; bar O A 1; slider A", "statement 2 'fix Q 1 0': Q is fixed but no link or slider uses it"),
    ("fix O; fix O; bar O A 1; slider A", "statement 2 'fix O': O is fixed twice (as in statement 1 'fix O')"),
    ("fix O; fix P 0 0; bar O A 1; bar P A 1",
     "statement 2 'fix P 0 0': P is fixed at (0, 0), where O is fixed (statement 1 'fix O'): two names for one point?"),
    ("fix O; bar O A 1; bar O A 1; slider A",
     "statement 3 'bar O A 1': O and A are joined by statement 2 'bar O A 1' already: a redundant constraint"),
    ("ground O A 1; bar O A 1", "statement 2 'bar O A 1': both ends are fixed: the bar moves nothing (a redundant "
                                "constraint, or no configuration when the lengths differ)"),
    ("fix O; bar O A 1; slider A; slider A", "statement 4 'slider A': repeats statement 3 'slider A': a redundant "
                                             "constraint"),
    ("fix O; bar O A 1; slider O; slider A",
     "statement 3 'slider O': O is fixed: the slider moves nothing (a redundant constraint)"),
])
def test_likely_mistakes_are_warnings_naming_the_statement(text, message):
    said: list[str] = []
    parse_mechanism(text, warn=said.append)
    assert said == ["mechanism: " + message]


def test_warnings_reach_the_script():
    out = Session().execute('LIB "mechanism.lib";\nmechanism m = "fix O; bar O A 1; bar A B 1; bar B C 1";\n')
    assert out == ("// ** mechanism: statement 4 'bar B C 1': C appears in no other statement: the link dangles "
                   "(a misspelt point name?)\n")


def test_a_correct_description_has_no_warning():
    said: list[str] = []
    parse_mechanism("ground O A 1; fix G 2 0; bar O B 1; bar B C 1; body A C 1 0 E 0 1; bar E F 1; bar F G 1",
                    warn=said.append)
    assert said == []


# ---------------------------------------------------------------- Grübler–Kutzbach beside the mobility
@pytest.mark.parametrize("text, count", [
    ("ground O A 1; bar O B 1; bar B C 2; bar C A 2", 1),                       # four-bar
    ("fix O; bar O A 1; bar A B 1; slider B", 1),                               # slider-crank
    ("slider A; bar A B 2; slider B 1 0 0", 1),                                 # trammel
    ("fix O 0 1; fix Q 0 1/2; bar O A 1; bar Q B 2; slider A Q B; bar B C 3; slider C", 1),  # Whitworth
    ("ground O A 2; fix P 1 0; bar O B 1; bar A C 1; body B C 2 0 D 1 0; bar P D 1", 0),     # double parallelogram
    ("revolute A a 1 twist 0 1; revolute B a 4/5 twist 3/5 4/5; revolute C a 1 twist 0 1; "
     "revolute D a 4/5 twist 3/5 4/5", -2),                                     # Bennett
    ("revolute A twist 0 1; revolute B twist 3/5 4/5; revolute C twist 0 1; revolute D twist 5/13 12/13", 1),
])
def test_gruebler_kutzbach_counts(text, count):
    assert parse_mechanism(text).gruebler_kutzbach() == count


def test_overconstrained_is_said_beside_the_mobility():
    a = analyze(parse_mechanism("ground O A 2; fix P 1 0; bar O B 1; bar A C 1; body B C 2 0 D 1 0; bar P D 1"))
    assert a.mobility == 1
    assert ("mobility 1 (Grübler–Kutzbach count 0: overconstrained, a special geometry gives more freedom)"
            in report_text(a))
    d = report_data(a)
    assert (d["gruebler_kutzbach"], d["overconstrained"]) == (0, True)
    plain = report_data(analyze(parse_mechanism("fix O; bar O A 1; bar A B 1; slider B")))
    assert "gruebler_kutzbach" not in plain  # the reports of mechanisms whose count is right are unchanged


# ---------------------------------------------------------------- commands
def test_syntax_help_and_joint_angles_commands():
    s = Session()
    assert s.execute('LIB "mechanism.lib";\nmechanismSyntax();\n') == syntax() + "\n"
    s.execute('mechanism b = "revolute A a 1 twist 0 1; revolute B a 4/5 twist 3/5 4/5; revolute C a 1 twist 0 1; '
              'revolute D a 4/5 twist 3/5 4/5";')
    assert s.execute("jointAngles(b, list(-1, 0, 1, 0));") == "A 180°, B 0°, C 180°, D 0°\n"
    e = error('LIB "mechanism.lib";\nmechanism b = "fix O; bar O A 1; slider A";\njointAngles(b, list(0, 1));\n')
    assert e.message == "jointAngles: the values are not a configuration (a constraint is 1)"


def test_draw_moving_slots_and_spatial_points(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    s = Session()
    s.execute('LIB "mechanism.lib";\n'
              'mechanism q = "fix O 0 1; fix Q 0 1/2; bar O A 1; bar Q B 2; slider A Q B; bar B C 3; slider C";\n'
              'drawMechanism(q, list(1, 0, "0.8944271909999159", "0.4472135954999579", "0.8854109409383547", '
              '"-0.4648090636666386"), "q.svg");\n'
              'mechanism t = "fix O 0 0 0; fix P 2 0 0; fix Q 0 2 0; bar O A 2; bar P A 2; bar Q A 2";\n'
              'drawMechanism(t, list(1, 1, "1.4142135623730951"), "t.svg");\n')
    assert "slider-line" in (tmp_path / "q.svg").read_text() and "links" in (tmp_path / "t.svg").read_text()
    s.execute('mechanism b = "revolute A a 1 twist 0 1; revolute B a 4/5 twist 3/5 4/5; '
              'revolute C a 1 twist 0 1; revolute D a 4/5 twist 3/5 4/5";\ndrawMechanism(b, list(-1, 0, 1, 0), "b.svg");\n')
    assert "joint-axes" in (tmp_path / "b.svg").read_text()  # loops of joints: tests/stdlib/test_plots_spatial.py


def test_gear_pairs():
    """A gear pair of integer ratio n: (c_b + i s_b) conj(z_carrier) = (conj(z_a) z_carrier)^n, written out by
    hand for the ground as carrier (n = 2) and for a carrier link (n = 1); one constraint in the count."""
    m = parse_mechanism("ground O Q 2; bar O A 1; bar Q B 1; bar A C 2; bar B C 2; gear O Q 2")
    _, gens = m.constraints()
    assert {poly_str(g) for g in gens} >= {"-c1^2+s1^2+c2", "2*c1*s1+s2"}
    assert m.gruebler_kutzbach() == 1 and str(m).endswith("; gear O Q 2")
    m = parse_mechanism("fix O; bar O P 2; bar O A 1; bar P B 1; gear O P 1")  # the carrier: link 1 (O P)
    _, gens = m.constraints()
    # z3 conj(z1) = conj(z2) z1: real part c3 c1 + s3 s1 - (c2 c1 + s2 s1), imaginary s3 c1 - c3 s1 - (c2 s1 - s2 c1)
    assert [poly_str(g) for g in gens] == ["-c1*c2-s1*s2+c1*c3+s1*s3", "-s1*c2+c1*s2-s1*c3+c1*s3",
                                           "c1^2+s1^2-1", "c2^2+s2^2-1", "c3^2+s3^2-1"]
    with pytest.raises(MechError) as e:
        Session().execute('LIB "mechanism.lib"; mechanism m = "fix O; bar O A 1; bar A B 1; gear A B 1"; '
                          'constraints(m);')
    assert "statement 4 'gear A B 1': no link turns about B to carry its gear" in str(e.value)
