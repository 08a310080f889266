"""Grashof classification of four-bars, checked on the textbook cases and, for every four-bar with
lengths 1..6, against a sampled test of which links turn fully."""
from __future__ import annotations

import itertools
import math
from fractions import Fraction

import pytest

from mech.stdlib.grashof import KINDS, FourBar, four_bar, grashof
from mech.stdlib.mechanism import parse_mechanism


@pytest.mark.parametrize("lengths, kind, rel", [
    ((5, 2, 5, 4), "crank-rocker", "<"),       # ground 5; crank 2, coupler 5, rocker 4
    ((2, 5, 4, 6), "double-crank", "<"),       # the ground is the shortest: drag link
    ((5, 4, 2, 6), "double-rocker", "<"),      # the coupler is the shortest
    ((5, 2, 4, 3), "change point", "="),       # 2 + 5 = 4 + 3
    ((7, 4, 3, 5), "non-Grashof", ">"),        # triple rocker: 3 + 7 > 4 + 5
])
def test_textbook_cases(lengths, kind, rel):
    g = grashof(*(Fraction(x) for x in lengths))
    assert g.kind == kind
    assert g.grashof == (rel != ">")
    assert f"s + l {rel} p + q" in g.inequality


def test_inequality_text():
    g = grashof(Fraction(5), Fraction(2), Fraction(5), Fraction(4))
    assert g.inequality == "s + l < p + q: 2 + 5 < 4 + 5 (shortest crank 2, longest ground 5)"
    assert g.shortest == "crank" and "crank turns fully" in g.description
    assert grashof(Fraction(5), Fraction(4), Fraction(5), Fraction(2)).description.startswith("rocker-crank")
    h = grashof(Fraction(1, 2), Fraction(3, 2), Fraction(1), Fraction(7, 4))
    assert "1/2 + 7/4" in h.inequality and h.kind == "double-crank"


def test_degenerate_lengths():
    assert "cannot be assembled" in grashof(Fraction(10), Fraction(1), Fraction(2), Fraction(3)).description
    assert "single" in grashof(Fraction(6), Fraction(1), Fraction(2), Fraction(3)).description
    with pytest.raises(ValueError):
        grashof(Fraction(0), Fraction(1), Fraction(1), Fraction(1))


def _turns_fully(ground: int, a: int, b: int, c: int, samples: int = 720) -> bool:
    """Whether the link of length ``a`` pivoted at the origin can take every angle: the distance d
    from its tip to the other pivot (ground, 0) must lie in [|b - c|, b + c]."""
    for k in range(samples):
        t = 2 * math.pi * (k + 0.5) / samples
        d = math.hypot(a * math.cos(t) - ground, a * math.sin(t))
        if not abs(b - c) - 1e-12 <= d <= b + c + 1e-12:
            return False
    return True


def test_against_sampled_rotation():
    checked = 0
    for g, a, b, c in itertools.product(range(1, 7), repeat=4):
        if max(g, a, b, c) >= g + a + b + c - max(g, a, b, c):
            continue  # cannot be assembled (or only stretched)
        t = grashof(Fraction(g), Fraction(a), Fraction(b), Fraction(c))
        if t.kind == "change point":
            continue
        crank, rocker = _turns_fully(g, a, b, c), _turns_fully(g, c, b, a)
        expected = {"crank": (True, False), "ground": (True, True), "rocker": (False, True),
                    "coupler": (False, False)}[t.shortest] if t.grashof else (False, False)
        assert (crank, rocker) == expected, (g, a, b, c, t)
        assert t.kind in KINDS
        checked += 1
    assert checked > 500


def test_recognise_four_bar():
    fb = four_bar(parse_mechanism("ground O A 5; bar O B 2; bar B C 5; bar C A 4"))
    assert fb == FourBar(5, 2, 5, 4, ("O", "B", "C", "A"), (1, 2, 3))
    assert fb.classify().kind == "crank-rocker"
    # links written in another direction and order, a coupler body with a tracer point F
    fb = four_bar(parse_mechanism("fix O; fix A 3 4; bar A C 4; body B C 5 0 F 2 3; bar O B 2"))
    assert (fb.ground, fb.crank, fb.coupler, fb.rocker) == (5, 2, 5, 4)
    assert fb.joints == ("O", "B", "C", "A") and fb.links == (3, 2, 1)
    # symbolic lengths with values
    m = parse_mechanism("ground O A 1; bar O B l1; bar B C l2; bar C A l3")
    assert four_bar(m) is None
    assert four_bar(m, {"l1": 1, "l2": 1, "l3": 1}).classify().kind == "change point"


@pytest.mark.parametrize("text", [
    "fix O; bar O A 1; bar A B 2; slider B",                              # slider-crank
    "ground O A 2; bar O B 1; bar B C 1; bar C D 1; bar D A 1",            # five-bar
    "fix O; fix A 1 1; bar O B 1; bar B C 1; bar C A 1",                   # ground of irrational length
    "ground O A 1; bar O B 1; bar B C 1; bar O C 1",                       # not a chain from O to A
])
def test_not_a_four_bar(text):
    assert four_bar(parse_mechanism(text)) is None
