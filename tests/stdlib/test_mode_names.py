"""Mode names (mech.stdlib.mode_names) against hand derivations on four-bars and the double
parallelogram, and their place in the text and json reports."""
from __future__ import annotations

import json

from mech.stdlib.analysis import analyze
from mech.stdlib.mechanism import parse_mechanism
from mech.stdlib.mode_names import mode_names
from mech.stdlib.reports import report_data, report_json, report_text

KITE = "ground O A 1; bar O B 1; bar B C 2; bar C A 2"
PARALLELOGRAM = "ground O A 2; bar O B 1; bar B C 2; bar C A 1"
RHOMBUS = "ground O A 1; bar O B 1; bar B C 1; bar C A 1"
DOUBLE_PARALLELOGRAM = "ground O A 3; fix E 6 0; bar O B 1; body B C 3 0 F 6 0; bar C A 1; bar F E 1"
CRANK_ROCKER = "ground O A 5; bar O B 2; bar B C 5; bar C A 4"


def _by_kind(a):
    return sorted(mode_names(a), key=lambda n: n.name)


def test_kite_folded_mode():
    """Kite O=(0,0), A=(1,0), |OB|=1, |BC|=|CA|=2.  By hand: B = A (c1 = 1, s1 = 0) leaves C on the
    circle of radius 2 about A, a one-parameter motion with the crank at rest (angle 0) and the
    coupler and rocker folded onto each other (opposite directions); the other mode is the kite's
    general motion, where no link is at rest and no two points meet."""
    a = analyze(parse_mechanism(KITE))
    folded, general = _by_kind(a)
    assert folded.name == "folded mode: B = A; link 1 frozen at 0°"
    assert folded.coincident == [("B", "A")] and folded.frozen == [(1, 0.0)]
    assert folded.parallel_links == [(2, 3, "opposite")]
    assert general.name == "general mode" and not (general.frozen or general.coincident or general.parallel_links)


def test_parallelogram_and_anti_parallelogram_modes():
    """Opposite sides equal (|OA| = |BC| = 2, |OB| = |CA| = 1).  By hand: either B - O = C - A (the
    parallelogram: the coupler translates, parallel to the ground, angle 0; crank and rocker, written
    O->B and C->A, point opposite ways) or the crossed anti-parallelogram, whose loop diagonals OC and
    BA are parallel (the four points form an isosceles trapezoid) while no link stays at rest."""
    a = analyze(parse_mechanism(PARALLELOGRAM))
    anti, para = _by_kind(a)
    assert para.name == "parallelogram mode: O B C A; link 2 frozen at 0°"
    assert para.parallelograms == [("O", "B", "C", "A")] and para.parallel_links == [(1, 3, "opposite")]
    assert anti.name == "anti-parallelogram mode (crossed): O B C A"
    assert anti.anti_parallelograms == [("O", "B", "C", "A")] and not anti.frozen and not anti.parallelograms


def test_rhombus_three_modes():
    """All sides 1: the parallelogram mode and two folded modes (B = A with the crank at rest, C = O
    with the rocker at rest); a folded loop is not called an anti-parallelogram."""
    a = analyze(parse_mechanism(RHOMBUS))
    names = sorted(n.name for n in mode_names(a))
    assert names == ["folded mode: B = A; link 1 frozen at 0°", "folded mode: C = O; link 3 frozen at 0°",
                     "parallelogram mode: O B C A; link 2 frozen at 0°"]


def test_double_parallelogram():
    """One mode: the body B C F translates (link 2 at angle 0) and the three cranks stay parallel:
    the loops O B C A, O B F E and A C F E are parallelograms."""
    a = analyze(parse_mechanism(DOUBLE_PARALLELOGRAM))
    (n,) = mode_names(a)
    assert sorted(n.parallelograms) == [("A", "C", "F", "E"), ("O", "B", "C", "A"), ("O", "B", "F", "E")]
    assert n.frozen == [(2, 0.0)]
    assert n.parallel_links == [(1, 3, "opposite"), (1, 4, "opposite"), (3, 4, "same")]


def test_generic_four_bar_is_general():
    """A crank-rocker (5; 2, 5, 4) is prime and no membership holds: the general mode."""
    a = analyze(parse_mechanism(CRANK_ROCKER))
    assert [n.name for n in mode_names(a)] == ["general mode"]


def test_frozen_at_other_angles():
    """A bar O A (O = (0,0)) held by a bar A P to P = (0,2), both of length 1: A = (0,1), so both
    links point up (90 degrees) and only the bar A B turns.  With P = (3/2, 0) instead, A = (3/4,
    +-sqrt(7)/4): one mode over Q whose links 1 and 2 are at rest at an algebraic angle."""
    a = analyze(parse_mechanism("fix O; fix P 0 2; bar O A 1; bar A P 1; bar A B 1"))
    (n,) = mode_names(a)
    assert n.frozen == [(1, 90.0), (2, 90.0)] and n.name == "link 1 frozen at 90°, link 2 frozen at 90°"
    a = analyze(parse_mechanism("fix O; fix P 3/2 0; bar O A 1; bar A P 1; bar A B 1"))
    (n,) = mode_names(a)
    assert n.frozen == [(1, None), (2, None)] and "link 1 frozen (at an algebraic angle)" in n.name


def test_names_in_reports():
    a = analyze(parse_mechanism(KITE))
    text = report_text(a)
    assert "\n      folded mode: B = A; link 1 frozen at 0°\n" in text and "\n      general mode\n" in text
    modes = json.loads(report_json(a))["motion_modes"]
    assert sorted(m["name"] for m in modes) == ["folded mode: B = A; link 1 frozen at 0°", "general mode"]
    folded = next(m for m in modes if m["name"].startswith("folded"))
    assert folded["shape"]["coincident_points"] == [["B", "A"]]
    assert folded["shape"]["frozen_links"] == [{"link": 1, "angle": 0.0}]
    assert report_data(a)["motion_modes"][0].keys() >= {"name", "shape", "prime"}


def test_coinciding_points_grouped():
    """Pairs B = A, F = A, B = F are one class, written once with the fixed point last."""
    from mech.stdlib.mode_names import _classes
    assert _classes([("B", "A"), ("F", "A"), ("B", "F")]) == [["B", "F", "A"]]
    assert _classes([("C", "O"), ("F", "A")]) == [["C", "O"], ["F", "A"]]


def test_rigid_orbit():
    """The 3-RPR of docs/mechanisms.md (legs 5, 7, 4): one rigid mode over Q holding its 6 complex
    assembly modes (a Galois orbit), named with that count."""
    a = analyze(parse_mechanism("fix A1; fix A2 6 0; fix A3 0 5; bar A1 B1 5; bar A2 B2 7; bar A3 B3 4; "
                                "body B1 B2 5 0 B3 4 3"))
    assert [n.name for n in mode_names(a)] == ["rigid mode (6 conjugate isolated configurations over C: no link moves)"]
