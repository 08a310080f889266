"""Mechanisms from the kinematics literature that mech's examples did not have (issue 17: the quoted
cases are samples): four-bars with coupler points, six-bars of other inversions, an inverted
slider-crank, the Scotch yoke, a two-freedom five-bar, spatial RSSR and RRSS four-bars, the Sarrus
linkage, 6-3 Stewart–Gough platforms (one with a self-motion).  Each is compared with an ideal
written here in point coordinates (joint points, axes as points and unit directions), never in mech's
variables, decided by real Singular: its dimension (the mobility), its minimal primes (the motion
modes) or, where Singular's decomposition is slow, a certified projection (an eliminant whose
irreducible factors' degrees add up to the degree of the variety), or, for a rigid structure, the
factors over Q of a separating polynomial (the Galois orbits of the assembly modes)."""
from __future__ import annotations

import json
import subprocess
import sys
from fractions import Fraction as F

import pytest

from mech.stdlib.mechanism import parse_mechanism
from tests.util import ROOT, run_singular

EXAMPLES = ROOT / "examples"


# ---------------------------------------------------------------- mech's side
def report(desc: str | None = None, example: str | None = None, cwd=None) -> dict:
    """The JSON report of ``analyze`` on a description (or an example file ending in analyze(m, "json"))."""
    if example is not None:
        args = [str(EXAMPLES / f"{example}.mech")]
    else:
        args = ["-c", f'LIB "mechanism.lib"; mechanism m = "{desc}"; analyze(m, "json");']
    r = subprocess.run([sys.executable, "-m", "mech", *args], cwd=cwd, capture_output=True, text=True, timeout=600)
    assert r.returncode == 0 and "Traceback" not in r.stderr, r.stderr
    return json.loads(r.stdout.splitlines()[-1])


def modes(d: dict) -> list[int]:
    return sorted(m["dimension"] for m in d["motion_modes"])


# ---------------------------------------------------------------- independent ideals
def d2(p, q, length) -> str:
    """``|p - q|^2 - length^2`` for points given as coordinate strings."""
    return "+".join(f"(({a})-({b}))^2" for a, b in zip(p, q)) + f"-({length})^2"


def pt(name: str, dim: int = 2) -> tuple[str, ...]:
    return tuple(f"{name}{x}" for x in "xyz"[:dim])


def rigid(o, e, v, e_local, v_local) -> list[str]:
    """A third point ``v`` of a planar rigid body with points ``o`` (its origin) and ``e``: linear in
    the points, ``v - o = alpha (e - o) + beta J (e - o)`` (J the quarter turn) from the local
    coordinates (no mirror image, unlike three distances)."""
    (u1, v1), (u2, v2) = e_local, v_local
    n = F(u1) ** 2 + F(v1) ** 2
    al, be = (F(u1) * u2 + F(v1) * v2) / n, (F(u1) * v2 - F(v1) * u2) / n
    ex, ey = f"(({e[0]})-({o[0]}))", f"(({e[1]})-({o[1]}))"
    return [f"({v[0]})-({o[0]})-({al})*{ex}+({be})*{ey}", f"({v[1]})-({o[1]})-({al})*{ey}-({be})*{ex}"]


def _cross(a, b) -> list[str]:
    return [f"(({a[1]})*({b[2]})-({a[2]})*({b[1]}))", f"(({a[2]})*({b[0]})-({a[0]})*({b[2]}))",
            f"(({a[0]})*({b[1]})-({a[1]})*({b[0]}))"]


def loop_axes(links: list[tuple]) -> tuple[list[str], list[str]]:
    """A loop of revolute joints, link ``i`` = ``(a, (cos, sin) of the twist, d)``: axis ``i`` is the
    point ``O_i`` where the normal from axis ``i-1`` arrives and a unit direction ``u_i``; the normal to
    axis ``i+1`` leaves at ``O_i + d u_i``, so with ``D = O_{i+1} - O_i - d u_i``: ``a u_i x u_{i+1} = sin D``
    and ``u_i.u_{i+1} = cos`` (twisted), or ``u_{i+1} = cos u_i``, ``D.u_i = 0``, ``|D| = a`` (parallel
    axes).  The last link is the ground: axis 1 the z-axis through 0, axis n along ``(0, sin, cos)``."""
    n = len(links)
    an, (cn, sn), dn = links[-1]
    U = {1: ("0", "0", "1"), n: ("0", str(sn), str(cn))}
    P = {1: ("0", "0", "0"), n: (str(-an), str(-dn * sn), str(-dn * cn))}
    names: list[str] = []
    for i in range(2, n):
        P[i], U[i] = pt(f"p{i}", 3), pt(f"u{i}", 3)
        names += [*P[i], *U[i]]
    eqs = []
    for i in range(1, n):
        a, (c, s), d = links[i - 1]
        dlt = [f"(({P[i + 1][k]})-({P[i][k]})-({d})*({U[i][k]}))" for k in range(3)]
        if s:
            x = _cross(U[i], U[i + 1])
            eqs += [f"({a})*{x[k]}-({s})*{dlt[k]}" for k in range(3)]
            eqs.append("+".join(f"({U[i][k]})*({U[i + 1][k]})" for k in range(3)) + f"-({c})")
        else:
            eqs += [f"({U[i + 1][k]})-({c})*({U[i][k]})" for k in range(3)]
            eqs.append("+".join(f"{dlt[k]}*({U[i][k]})" for k in range(3)))
            eqs.append("+".join(f"{dlt[k]}^2" for k in range(3)) + f"-({a})^2")
    eqs += ["+".join(f"({u})^2" for u in U[i]) + "-1" for i in range(2, n)]
    return names, eqs


def singular_primes(names: list[str], eqs: list[str], char: int = 0) -> list[int]:
    """The dimensions of the minimal primes (``minAssGTZ``).  Over Z/32003 a prime over Q may split, so
    there the count is an upper bound for the count over Q (equal when mech finds as many over Q)."""
    script = (f'LIB "primdec.lib"; ring r = {char}, ({",".join(names)}), dp; ideal J = {", ".join(eqs)};\n'
              'list L = minAssGTZ(J); int i; for (i = 1; i <= size(L); i++) { print(dim(std(L[i]))); }\n')
    return sorted(int(w) for w in run_singular(script, timeout=300).split())


def singular_radical(names: list[str], eqs: list[str]) -> bool:
    script = (f'LIB "primdec.lib"; ring r = 0, ({",".join(names)}), dp; ideal J = {", ".join(eqs)};\n'
              'print(size(reduce(radical(J), std(J))) == 0);\n')
    return run_singular(script, timeout=300).split() == ["1"]


def singular_projection(names: list[str], eqs: list[str], coefficients: list[list[int]]) -> tuple[int, list[int]]:
    """``deg V(J)`` and the degrees of the distinct irreducible factors of the eliminant of ``J`` under the
    linear projection by the given forms (dim J + 1 of them), over Z/32003.  When the degrees add up to
    ``deg V(J)`` each factor is the image of exactly one component of top dimension (a projection never
    raises degrees), and a factor irreducible modulo p is irreducible over Q."""
    ts = [f"t{k}" for k in range(len(coefficients))]
    forms = ["+".join(f"({c})*{v}" for c, v in zip(row, names)) for row in coefficients]
    script = (f'LIB "primdec.lib"; ring r = 32003, ({",".join(names + ts)}), dp; ideal J = {", ".join(eqs)};\n'
              'print(mult(std(J)));\n' + "".join(f"J = J + ({t} - ({f}));\n" for t, f in zip(ts, forms)) +
              f'ideal E = eliminate(J, {"*".join(names)}); list Fa = factorize(E[1]); int i;\n'
              'for (i = 2; i <= size(Fa[1]); i++) { print(deg(Fa[1][i])); }\n')
    words = [int(w) for w in run_singular(script, timeout=300).split()]
    return words[0], sorted(words[1:])


def singular_orbits(names: list[str], eqs: list[str], form: list[int]) -> tuple[int, list[int]]:
    """A zero-dimensional ideal over Q: ``vdim`` and the degrees of the irreducible factors (each to the
    first power when the form separates the points) of the form's minimal polynomial (FGLM to lex)."""
    lin = "+".join(f"({c})*{v}" for c, v in zip(form, names))
    script = (f'option(redSB); ring r = 0, ({",".join(names)}, t), dp; ideal J = {", ".join(eqs)}, t - ({lin});\n'
              'ideal G = std(J); print(vdim(G));\n'
              f'ring s = 0, ({",".join(names)}, t), lp; ideal H = fglm(r, G); list Fa = factorize(H[1]); int i;\n'
              'for (i = 2; i <= size(Fa[1]); i++) { print(string(deg(Fa[1][i])) + "^" + string(Fa[2][i])); }\n')
    words = run_singular(script, timeout=300).split()
    assert all(w.endswith("^1") for w in words[1:])  # squarefree: the form separates the points
    return int(words[0]), sorted(int(w[:-2]) for w in words[1:])


O = ("0", "0")
B, C, D, E, FF, H = pt("b"), pt("c"), pt("d"), pt("e"), pt("f"), pt("h")
R90, R35, R45, R513, R1213 = (0, 1), (F(3, 5), F(4, 5)), (F(4, 5), F(3, 5)), (F(5, 13), F(12, 13)), (F(12, 13), F(5, 13))

CHEBYSHEV = "ground O A 2; bar O B 1; body B C 5/2 0 P 5/4 0; bar C A 5/2"   # P: the coupler's midpoint
HOECKENS = "ground O A 2; bar O B 1; body B C 5/2 0 P 5 0; bar C A 5/2"      # P: the coupler extended
STEPHENSON3 = "fix O; fix A 4 0; body O C 2 0 D 1 1; bar C E 3; bar D F 3; body E F 1 0 H 2 1; bar A H 2"
INVERTED = "fix O; fix A 2 0; bar O B 1; bar A C 3; slider B A C"
YOKE = "fix O; bar O B 1; body Y Z 2 0 S 0 1; slider Y; slider Z; slider B Y S"
FIVEBAR = "ground O A 3; bar O B 1; bar B C 2; bar C D 2; bar D A 1"
RRSS = ("fix O1 0 0 0; fix O2 0 0 1; body O1 O2 1 0 0 B1 0 1 0 B2 0 1 1; body B1 B2 1 0 0 C 0 2 0; "
        "fix D 1 0 2; bar C D 2")
STEWART63 = ("fix B1 -3 0 0; fix B2 0 -3 0; fix B3 6 0 0; fix B4 5 -4 0; fix B5 0 4 1; fix B6 2 8 8; "
             "body P1 P2 3 0 0 P3 0 4 0; bar B1 P1 5; bar B2 P1 5; bar B3 P2 5; bar B4 P2 6; bar B5 P3 3; bar B6 P3 6")
FOURBAR_POINTS = ([*B, *C], [d2(B, O, 1), d2(C, B, "5/2"), d2(C, ("2", "0"), "5/2")])


def platform(base, legs, sides) -> tuple[list[str], list[str]]:
    """A 6-3 platform in its three points' world coordinates: the sides, the legs (pairs on each point)."""
    P = [pt("p1", 3), pt("p2", 3), pt("p3", 3)]
    eqs = [d2(P[0], P[1], sides[0]), d2(P[0], P[2], sides[1]), d2(P[1], P[2], sides[2])]
    eqs += [d2(P[k // 2], tuple(map(str, base[k])), legs[k]) for k in range(6)]
    return [x for p in P for x in p], eqs


# ---------------------------------------------------------------- the examples
@pytest.mark.singular
def test_sarrus_example(tmp_path):
    """The Sarrus linkage: Grübler–Kutzbach count 0, mobility 1, two motion modes (dimension 1 each,
    degree 4 in the axes' ideal) over Z/32003 for the axes' ideal and over Q for mech."""
    d = report(example="sarrus", cwd=tmp_path)
    assert (d["mobility"], modes(d), d["gruebler_kutzbach"], d["overconstrained"]) == (1, [1, 1], 0, True)
    links = [(2, (1, 0), -2), (1, (1, 0), 0), (0, R90, 2), (1, (1, 0), 0), (2, (1, 0), 0), (0, R90, 0)]
    assert singular_primes(*loop_axes(links), char=32003) == [1, 1]
    # the singular configurations: the two modes are smooth and meet in 4 points
    names, eqs = loop_axes(links)
    script = (f'LIB "primdec.lib"; ring r = 32003, ({",".join(names)}), dp; ideal J = {", ".join(eqs)};\n'
              'list L = minAssGTZ(J); list M = minAssGTZ(L[1] + L[2]); print(size(M)); int k;\n'
              f'for (k = 1; k <= 2; k++) {{ print(dim(std(L[k] + minor(jacob(L[k]), {len(names) - 1})))); }}\n')
    assert run_singular(script, timeout=300).split() == ["4", "-1", "-1"]
    assert len(d["singular"]) == 4


@pytest.mark.singular
def test_sarrus_with_equal_limb_links_folds_flat():
    """Limb links of equal length and no offsets: both limbs can fold with the plate on the ground, each
    middle hinge then free: a mode of dimension 2 besides the two straight-line modes (mobility 2)."""
    desc = ("revolute A a 1; revolute B a 1; revolute C twist 0 1; revolute D a 1; revolute E a 1; "
            "revolute F twist 0 1")
    d = report(desc)
    assert (d["mobility"], modes(d)) == (2, [1, 1, 2])
    links = [(1, (1, 0), 0), (1, (1, 0), 0), (0, R90, 0), (1, (1, 0), 0), (1, (1, 0), 0), (0, R90, 0)]
    assert singular_primes(*loop_axes(links), char=32003) == [1, 1, 2]


@pytest.mark.singular
def test_rssr_example(tmp_path):
    """The RSSR four-bar: mobility 1, one motion mode, no singular configuration; its count equals the
    mobility (two points shared with the ground are a revolute joint), so the report has none."""
    d = report(example="rssr", cwd=tmp_path)
    assert (d["mobility"], modes(d), d["singular"], d["radical"]) == (1, [1], [], True)
    assert "gruebler_kutzbach" not in d
    names, eqs = ["bx", "by", "cx", "cz"], ["bx^2+by^2-1", "(cx-3)^2+cz^2-4", "(cx-bx)^2+by^2+cz^2-9"]
    assert singular_primes(names, eqs) == [1] and singular_radical(names, eqs)


@pytest.mark.singular
def test_selfmotion_example(tmp_path):
    """The 6-3 platform with a self-motion: over Q, a curve (the translation on a circle) and six rigid
    assembly modes (isolated points), J not radical — in mech's report and in Singular."""
    d = report(example="selfmotion", cwd=tmp_path)
    assert (d["mobility"], modes(d), d["radical"], d["overconstrained"]) == (1, [0] * 6 + [1], False, True)
    names, eqs = platform([(-3, 0, 0), (3, 0, 0), (-3, 4, 0), (3, 4, 0), (-3, 0, 3), (3, 0, 3)], [5] * 6, (4, 3, 5))
    assert singular_primes(names, eqs) == [0] * 6 + [1]
    assert not singular_radical(names, eqs)


# ---------------------------------------------------------------- planar
@pytest.mark.singular
@pytest.mark.parametrize("desc", [CHEBYSHEV, HOECKENS])
def test_four_bars_with_coupler_points(desc):
    """Chebyshev's and Hoeckens' straight-line linkages: a coupler point adds no freedom; one mode."""
    d = report(desc)
    assert (d["mobility"], modes(d), d["radical"], d["singular"]) == (1, [1], True, [])
    assert singular_primes(*FOURBAR_POINTS) == [1] and singular_radical(*FOURBAR_POINTS)


@pytest.mark.singular
def test_inverted_slider_crank():
    """The crank's pin B slides on the rocker A-C (a slider on a moving link): one mode."""
    d = report(INVERTED)
    assert (d["mobility"], modes(d), d["singular"]) == (1, [1], [])
    names, eqs = [*B, *C], [d2(B, O, 1), d2(C, ("2", "0"), 3), "(cx-2)*by-cy*(bx-2)"]
    assert singular_primes(names, eqs) == [1]


@pytest.mark.singular
def test_scotch_yoke():
    """A yoke sliding on the x-axis (Y, Z on it) with a vertical slot Y-S the crank pin slides in: two
    motion modes, the yoke the right way round or turned over (Z right or left of Y)."""
    d = report(YOKE)
    assert (d["mobility"], modes(d)) == (1, [1, 1])
    names, eqs = ["bx", "by", "yx", "zx"], [d2(B, O, 1), "(zx-yx)^2-4", "(zx-yx)*(bx-yx)"]
    assert singular_primes(names, eqs) == [1, 1]


@pytest.mark.singular
def test_stephenson_iii():
    """A Stephenson six-bar on a binary ground link (ternary links O C D and E F H): one mode; Singular's
    eliminant is irreducible of degree 18 = deg V(J)."""
    d = report(STEPHENSON3)
    assert (d["mobility"], modes(d)) == (1, [1])
    names = [*C, *D, *E, *FF, *H]
    eqs = [d2(C, O, 2), *rigid(O, C, D, (2, 0), (1, 1)), d2(E, C, 3), d2(FF, D, 3), d2(FF, E, 1),
           *rigid(E, FF, H, (1, 0), (2, 1)), d2(H, ("4", "0"), 2)]
    rows = [[3, -1, 4, 1, -5, 9, 2, -6, 5, 3], [2, 7, -1, 8, 2, -8, 1, 8, -2, 8]]
    assert singular_projection(names, eqs, rows) == (18, [18])


@pytest.mark.singular
def test_five_bar_with_two_freedoms():
    """The five-bar with both cranks free: mobility 2, one mode (an irreducible eliminant of degree 14 =
    deg V(J) in three linear forms of the points)."""
    d = report(FIVEBAR)
    assert (d["mobility"], modes(d)) == (2, [2])
    names, eqs = [*B, *C, *D], [d2(B, O, 1), d2(C, B, 2), d2(C, D, 2), d2(D, ("3", "0"), 1)]
    rows = [[3, -1, 4, 1, -5, 9], [2, 7, -1, 8, 2, -8], [1, -4, 2, 3, 7, -2]]
    assert singular_projection(names, eqs, rows) == (14, [14])


# ---------------------------------------------------------------- spatial
@pytest.mark.singular
def test_rrss():
    """An RRSS loop: a crank about z, a body hinged to it along a tangent axis (B1 B2), its point C on a
    bar to a fixed point: mobility 1, one mode."""
    d = report(RRSS)
    assert (d["mobility"], modes(d)) == (1, [1])
    assert "gruebler_kutzbach" not in d
    names = ["bx", "by", "wx", "wy", "wz"]   # B1 on the unit circle, C = B1 + 2 w with w square to the hinge
    eqs = ["bx^2+by^2-1", "-wx*by+wy*bx", "wx^2+wy^2+wz^2-1", "(bx+2*wx-1)^2+(by+2*wy)^2+(2*wz-2)^2-4"]
    assert singular_primes(names, eqs) == [1]


@pytest.mark.singular
def test_stewart_6_3_non_planar_base():
    """A 6-3 platform whose base is not planar: 16 distinct assembly modes in two Galois orbits (the home
    pose and 15 conjugates)."""
    d = report(STEWART63)
    assert (d["mobility"], d["complex_configurations"], modes(d)) == (0, 16, [0, 0])
    assert sorted(o["configurations"] for o in d["assembly_orbits"]) == [1, 15]
    names, eqs = platform([(-3, 0, 0), (0, -3, 0), (6, 0, 0), (5, -4, 0), (0, 4, 1), (2, 8, 8)],
                          [5, 5, 5, 6, 3, 6], (3, 4, 5))
    assert singular_orbits(names, eqs, [3, -2, 5, 7, -1, 4, 2, -3, 1]) == (16, [1, 15])


@pytest.mark.singular
def test_closed_6r_arm_example(tmp_path):
    """A general 6R arm closed into a loop (its inverse kinematics): 16 complex assembly modes, one orbit
    over Q (Singular agrees over Q with a separating form's minimal polynomial, irreducible of degree 16,
    but takes minutes; here its count modulo 32003 on the axes' ideal: dimension 0, vdim 16)."""
    d = report(example="arm6r", cwd=tmp_path)
    assert (d["mobility"], d["complex_configurations"], [o["configurations"] for o in d["assembly_orbits"]]) == \
        (0, 16, [16])
    names, eqs = loop_axes([(1, R90, 0), (2, R35, 0), (1, R513, 0), (F(3, 2), R90, 0), (1, R45, 0), (2, R1213, 0)])
    script = (f'ring r = 32003, ({",".join(names)}), dp; ideal J = {", ".join(eqs)}; ideal G = std(J);\n'
              'print(dim(G)); print(vdim(G));\n')
    assert run_singular(script, timeout=300).split() == ["0", "16"]


# ---------------------------------------------------------------- counts and mistakes
@pytest.mark.parametrize("desc, count", [
    ("fix O1 0 0 0; fix O2 0 0 1; body O1 O2 1 0 0 B 0 1 0; fix G1 3 0 0; fix G2 3 1 0; "
     "body G1 G2 1 0 0 C 0 2 0; bar B C 3", 1),                       # RSSR: 6*3 - 5 - 5 - 3 - 3 - 1 spin
    (RRSS, 1),
    ("fix O 0 0 0; fix P 0 0 1; fix Q 0 0 2; body O P 1 0 0 Q 2 0 0", 0),   # three shared points weld
    ("fix O; fix A 1 0; body O A 1 0 B 0 1; bar B C 1; fix D 0 3; bar C D 1", 0),  # a body on two fixed points
    (STEWART63, 0),
])
def test_gruebler_kutzbach_counts_hinges(desc, count):
    assert parse_mechanism(desc).gruebler_kutzbach() == count


@pytest.mark.parametrize("desc, message", [
    (STEWART63.replace("bar B6 P3 6", "bar B6 p3 6"), "statement 13 'bar B6 p3 6': p3 appears in no other statement"),
    (YOKE.replace("slider Z", "slider z"), "statement 5 'slider z': z is not a point of any link"),
    (INVERTED.replace("slider B A C", "slider b A C"), "statement 5 'slider b A C': b is not a point"),
    (STEWART63.replace("fix B2 0 -3 0", "fix B1 0 -3 0"), "statement 2 'fix B1 0 -3 0': B1 is already fixed"),
    (STEWART63.replace("bar B5 P3 3", "bar B5 P3 0"), "statement 12 'bar B5 P3 0': the length of a bar is positive"),
    ("fix O 0 0 0; fix P 3 0 0; bar O P 2; bar O A 1; bar P A 3",
     "statement 3 'bar O P 2': both ends are fixed, 3 apart: a bar of length 2 does not fit"),
    (CHEBYSHEV + "; bar B C 5/2", "statement 5 'bar B C 5/2': B and C are points of one body (statement 3"),
])
def test_mistakes_on_unseen_mechanisms(desc, message):
    warnings: list[str] = []
    try:
        parse_mechanism(desc, warn=warnings.append)
    except Exception as e:  # an error: the message names the statement
        warnings.append(str(e))
    assert any(message in w for w in warnings), warnings


def test_a_bar_between_fixed_points_set_to_a_wrong_length():
    m = parse_mechanism("fix O; fix P 2 3; bar O P l; bar O A 1; bar P A 3")
    with pytest.raises(Exception, match=r"statement 3 'bar O P l': both ends are fixed, sqrt\(13\) apart"):
        m.with_values({"l": 2})


def test_radicality_not_decided_is_not_reported_as_not_radical():
    """An analysis stopped before deciding radicality (the Peaucellier inversor's decomposition over a time
    limit left J's radicality open, and the report said "not radical": Singular finds J radical) says so."""
    from mech.stdlib.analysis import Analysis
    from mech.stdlib.reports import report_data, report_text
    m = parse_mechanism("fix O; fix Q 1 0; bar Q C 1; bar O B 3; bar O D 3; bar C B 1; bar C D 1; bar B P 1; bar D P 1")
    R, gens = m.constraints()
    a = Analysis(m, R, gens, R.nvars, [], dim=2, mobility=2)
    a.modes_found, a.unfinished = False, ["decomposition: interrupted by the time limit, and the steps after it"]
    assert "J is not known to be radical (the analysis stopped before deciding)" in report_text(a)
    assert "embedded components" not in report_text(a)
    assert report_data(a)["radical"] is None
