"""Motion modes by parts (stdlib/analysis_parts.py) and Peaucellier's inversor, whose minimal primes
minAssGTZ did not find in minutes (in Singular neither)."""
import shutil
import subprocess

import pytest

from mech.kernel.ideals import dimension, dp_ring, is_subset, move, std
from mech.kernel.primdec import min_ass_gtz
from mech.kernel.projection import variety_degree
from mech.stdlib.analysis import run_analysis
from mech.stdlib.analysis_parts import loop_groups, min_ass_reduced, modes_by_parts
from mech.stdlib.mechanism import parse_mechanism

PEAUCELLIER = "fix O; fix Q 1 0; bar Q C 1; bar O B 3; bar O D 3; bar C B 1; bar C D 1; bar B P 1; bar D P 1"


def _same_primes(a, b, R):
    return len(a) == len(b) and all(any(is_subset(p, q, R) and is_subset(q, p, R) for q in b) for p in a)


def test_loop_groups_are_the_loops_with_their_circles():
    R, J = parse_mechanism(PEAUCELLIER).constraints()
    groups = loop_groups(J)
    # three loops (O-Q-C-B, O-Q-C-D, O-B-P-D): two closure equations each, with the circles of their bars
    assert sorted(len(g) for g in groups) == [5, 5, 6]
    assert all(any(p is g for G in groups for p in G) for g in J)
    assert loop_groups(parse_mechanism("ground O A 2; bar O B 1; bar B C 2; bar C A 1").constraints()[1]) is None


def test_min_ass_reduced_agrees_with_min_ass_gtz():
    """The kite (two modes) and the double parallelogram's J (not radical): linear variables removed first."""
    for text in ("ground O A 1; bar O B 1; bar B C 2; bar C A 2",
                 "ground O A 3; fix E 6 0; bar O B 1; body B C 3 0 F 6 0; bar C A 1; bar F E 1"):
        R, J = parse_mechanism(text).constraints()
        assert _same_primes(min_ass_reduced(J, R), min_ass_gtz(J, R), R)


def test_modes_by_parts_of_a_watt_six_bar_agree_with_min_ass_gtz():
    R, J = parse_mechanism("ground O A 1; fix G 2 0; bar O B 1; bar B C 1; body A C 1 0 E 0 1; bar E F 1; "
                           "bar F G 1").constraints()
    assert _same_primes(modes_by_parts(J, R), min_ass_gtz(J, R), R)


def _peaucellier():
    m = parse_mechanism(PEAUCELLIER)
    return m, run_analysis(m)


def test_peaucellier_modes():
    """B = D: a 2-dimensional degenerate mode (C and B on a degenerate four-bar, P on a circle about B);
    B != D: P = C (1-dimensional) and the inversor's motion, where P moves on the line x = 4 (C on the
    circle through O of diameter 2, O C . O P = O B^2 - B C^2 = 8)."""
    m, a = _peaucellier()
    R = a.ring
    assert a.radical and a.radical_decided and not a.equidimensional
    assert sorted(md.dim for md in a.modes) == [1, 1, 2]
    pos, _ = m.positions(R)
    (bx, by), (dx, dy), (cx, cy), (px, py) = pos["B"], pos["D"], pos["C"], pos["P"]
    line = [md for md in a.modes if is_subset([px - R.const(4)], md.prime, R)]
    assert len(line) == 1 and line[0].dim == 1 and line[0].real
    assert not is_subset([bx - dx], line[0].prime, R) and not is_subset([px - cx], line[0].prime, R)
    (flat,) = [md for md in a.modes if md.dim == 2]
    assert is_subset([bx - dx, by - dy], flat.prime, R)
    (fold,) = [md for md in a.modes if md.dim == 1 and md is not line[0]]
    assert is_subset([px - cx, py - cy], fold.prime, R)
    assert a.modes_by == "minimal primes of J, from the minimal primes of its loops"
    assert a.singular_done and not a.unfinished


SINGULAR = """LIB "primdec.lib";
ring r = 0, (c1,c2,b1,b2,d1,d2,p1,p2), dp;
ideal J = (c1-1)^2+c2^2-1, b1^2+b2^2-9, d1^2+d2^2-9, (b1-c1)^2+(b2-c2)^2-1, (d1-c1)^2+(d2-c2)^2-1,
          (p1-b1)^2+(p2-b2)^2-1, (p1-d1)^2+(p2-d2)^2-1;
// the rhombus C-B-P-D of unit sides: B = D, or P = C, or P = B + D - C (minAssGTZ does not finish in
// minutes on J, nor on J + (B - D): minAssChar does at once)
list L = minAssChar(J + ideal(b1-d1, b2-d2)) + minAssGTZ(J + ideal(p1-c1, p2-c2))
       + minAssGTZ(J + ideal(p1-b1-d1+c1, p2-b2-d2+c2));
int i; int j; int keep;
for (i = 1; i <= size(L); i++) {
  keep = 1;
  for (j = 1; j <= size(L); j++) {
    if (j != i) { if (size(reduce(L[j], std(L[i]))) == 0) { if (size(reduce(L[i], std(L[j]))) != 0 || j < i) { keep = 0; } } }
  }
  if (keep) { ideal S = std(L[i]); print("COMP " + string(dim(S)) + " " + string(mult(S)) + " " + string(reduce(p1-4, S) == 0)); kill S; }
}
quit;
"""


@pytest.mark.singular
def test_peaucellier_modes_against_singular():
    """Singular on point coordinates: the same modes (dimension, degree), the line x = 4 on the 1-dimensional one."""
    out = subprocess.run([shutil.which("Singular"), "-q", "--no-warn"], input=SINGULAR, text=True,
                         capture_output=True, timeout=120).stdout
    theirs = sorted(tuple(line.split()[1:]) for line in out.splitlines() if line.startswith("COMP"))
    _, a = _peaucellier()
    R = a.ring
    dp = dp_ring(R)
    ours = []
    for md in a.modes:
        x = a.mechanism.positions(R)[0]["P"][0]
        degree = variety_degree(std(move(md.prime, dp), dp), dp)
        ours.append((str(md.dim), str(degree), "1" if is_subset([x - R.const(4)], md.prime, R) else "0"))
    assert theirs == sorted(ours) == [("1", "6", "0"), ("1", "6", "1"), ("2", "12", "0")]
    assert all(dimension(md.prime, R) == md.dim for md in a.modes)
