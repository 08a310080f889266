"""Pictures of spatial mechanisms and loops of joints: drawMechanism in a chosen view (joint points and
axes checked against an independent Denavit–Hartenberg product), plotConfigurations in the joints'
coordinates (dots checked against the mechanism's equations)."""
from __future__ import annotations

import math
import re
import subprocess
import sys

import numpy as np
import pytest

from mech import Session
from mech.dsl.errors import MechError
from tests.util import ROOT
from tests.stdlib.test_plots import NS, by_class, dots, numbers, plane_map, run, svg

BENNETT = "revolute A a 1 twist 0 1; revolute B a 4/5 twist 3/5 4/5; revolute C a 1 twist 0 1; " \
          "revolute D a 4/5 twist 3/5 4/5"
#  a configuration of the Bennett linkage (c_A, s_A, c_D, s_D), from its sampled motion mode
ON_BENNETT = ["-0.9024903925", "0.4307099854", "0.3686602839", "0.9295641963"]
TRIPOD = "fix O 0 0 0; fix P 2 0 0; bar O A 2; bar P A 2"  # A on the circle x = 1, y^2 + z^2 = 3


def dh(theta: float, d: float, a: float, twist: float) -> np.ndarray:
    """The 4x4 matrix Rz(theta) Tz(d) Tx(a) Rx(twist), written out."""
    ct, st, ca, sa = math.cos(theta), math.sin(theta), math.cos(twist), math.sin(twist)
    return np.array([[ct, -st * ca, st * sa, a * ct], [st, ct * ca, -ct * sa, a * st], [0, sa, ca, d], [0, 0, 0, 1]])


def bennett_joints() -> list[np.ndarray]:
    """The joints' points of the Bennett loop: the angles of B and C solved numerically from the
    closure T_A T_B T_C T_D = I (independently of mech's cut-link equations)."""
    ta = math.atan2(float(ON_BENNETT[1]), float(ON_BENNETT[0]))
    td = math.atan2(float(ON_BENNETT[3]), float(ON_BENNETT[2]))
    tw = [math.pi / 2, math.acos(3 / 5), math.pi / 2, math.acos(3 / 5)]
    lengths = [1, 0.8, 1, 0.8]

    def closure(tb: float, tc: float) -> float:
        t = dh(ta, 0, lengths[0], tw[0]) @ dh(tb, 0, lengths[1], tw[1]) @ dh(tc, 0, lengths[2], tw[2]) \
            @ dh(td, 0, lengths[3], tw[3])
        return float(np.abs(t - np.eye(4)).max())
    grid = np.linspace(-math.pi, math.pi, 721)
    _, tb, tc = min((closure(b, c), b, c) for b in grid[::4] for c in grid[::4])
    for step in (1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7):  # refine by a pattern search
        _, tb, tc = min((closure(tb + i * step, tc + j * step), tb + i * step, tc + j * step)
                        for i in range(-8, 9) for j in range(-8, 9))
    assert closure(tb, tc) < 1e-5
    frames, t = [], np.eye(4)
    for theta, a, twist in zip([ta, tb, tc, td], lengths, tw):
        frames.append(t[:3, 3].copy())
        t = t @ dh(theta, 0, a, twist)
    return frames


def test_a_loop_of_joints_seen_from_the_top(tmp_path, monkeypatch):
    values = ", ".join(f'"{v}"' for v in ON_BENNETT)
    run(tmp_path, monkeypatch, f'mechanism m = "{BENNETT}"; drawMechanism(m, list({values}), "b.svg", "top");')
    root = svg(tmp_path / "b.svg")
    labels = {e.text: (float(e.get("x")) - 8, float(e.get("y")) + 8) for e in by_class(root, "point")}
    assert list(labels) == ["A", "B", "C", "D"]
    want = bennett_joints()  # seen from the top: x to the right, y up
    a, b = np.array(labels["A"]), np.array(labels["C"])
    scale = np.linalg.norm(b - a) / np.linalg.norm(want[2][:2] - want[0][:2])
    for name, p in zip("ABCD", want):
        px = a + scale * np.array([p[0] - want[0][0], -(p[1] - want[0][1])])
        assert np.abs(px - np.array(labels[name])).max() < 0.3, name
    (markers,) = by_class(root, "revolute-joints")
    assert markers.get("d").count("M") == 4
    (axes,) = by_class(root, "joint-axes")
    assert axes.get("d").count("M") == 4 and axes.get("stroke-dasharray")
    (links,) = by_class(root, "links")
    ends = [numbers(part) for part in links.get("d").split("M")[1:]]
    assert len(ends) == 4 and all(math.dist(e[-2:], f[:2]) < 0.15 for e, f in zip(ends, ends[1:] + ends[:1]))
    assert [e.text for e in by_class(root, "triad-label")] == ["x", "y"]  # z is seen end-on


def test_named_views_are_azimuth_and_elevation(tmp_path, monkeypatch):
    values = ", ".join(f'"{v}"' for v in ON_BENNETT)
    run(tmp_path, monkeypatch, f'mechanism m = "{BENNETT}"; drawMechanism(m, list({values}), "f.svg", "front"); '
        f'drawMechanism(m, list({values}), "g.svg", list(-90, 0)); drawMechanism(m, list({values}), "i.svg");'
        f'drawMechanism(m, list({values}), "i.png", "iso");')
    assert (tmp_path / "f.svg").read_text() == (tmp_path / "g.svg").read_text()
    assert [e.text for e in by_class(svg(tmp_path / "f.svg"), "triad-label")] == ["x", "z"]
    assert [e.text for e in by_class(svg(tmp_path / "i.svg"), "view")] == ["azimuth -45°, elevation 35.2644°"]
    assert (tmp_path / "i.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_spatial_points_in_a_view(tmp_path, monkeypatch):
    run(tmp_path, monkeypatch, f'mechanism m = "{TRIPOD}"; drawMechanism(m, list(1, 0, "1.7320508075688772"), '
        '"t.svg", "front");')
    root = svg(tmp_path / "t.svg")
    labels = {e.text: np.array([float(e.get("x")) - 8, float(e.get("y")) + 8]) for e in by_class(root, "point")}
    o, p, a = labels["O"], labels["P"], labels["A"]  # front: x to the right, z up; |OP| = 2
    k = (p - o)[0] / 2
    assert abs((p - o)[1]) < 0.15 and np.abs(a - o - k * np.array([1, -math.sqrt(3)])).max() < 0.15
    assert numbers(by_class(root, "fixed")[0].get("d")) and numbers(by_class(root, "joints")[0].get("d"))


@pytest.mark.parametrize("call, message", [
    ('drawMechanism(m, list(1, 0, "1.7320508075688772"), "t.svg", "back")', "unknown view 'back'"),
    ('drawMechanism(m, list(1, 0, "1.7320508075688772"), "t.svg", list(0, 100))', "elevation is in -90..90"),
    ('drawMechanism(m, list(1, 0, "1.7320508075688772"), "t.svg", list(0))', "list(azimuth, elevation)"),
    ('drawMechanism(n, list(1, 0), "t.svg", "top")', "a view is for spatial mechanisms"),
    ('plotConfigurations(m, "t.svg", list(1, 4))', "there is no coordinate 4 (the coordinates are 1..3: x_A, y_A, z_A)"),
])
def test_view_and_coordinate_errors(tmp_path, monkeypatch, call, message):
    with pytest.raises(MechError) as e:
        run(tmp_path, monkeypatch, f'mechanism m = "{TRIPOD}"; mechanism n = "fix O; bar O A 1"; {call};')
    assert message in str(e.value)


def test_a_helical_joint_is_drawn_where_its_slide_fits_its_angle(tmp_path, monkeypatch):
    screw = "revolute A; helical B pitch 1/2; prismatic C"  # theta_B = 60 degrees, d_B = pi/6 (+ a turn: pi)
    run(tmp_path, monkeypatch, f'mechanism m = "{screw}"; drawMechanism(m, list("1/2", "-0.8660254038", "1/2", '
        '"0.8660254038", "3.6651914292", "-3.6651914292"), "s.svg", "front");')
    assert by_class(svg(tmp_path / "s.svg"), "helical-joints")
    with pytest.raises(MechError) as e:
        run(tmp_path, monkeypatch, f'mechanism m = "{screw}"; drawMechanism(m, list("1/2", "-0.8660254038", "1/2", '
            '"0.8660254038", 1, -1), "s.svg");')
    assert "not a configuration of the helical joint B: d_B = 1 is not 1/2 times its angle 1.0472" in str(e.value)


def test_a_helical_loop_is_plotted_as_its_cylindrical_relaxation_and_says_so(tmp_path, monkeypatch):
    """The ideal lets a helical joint slide freely: the plot is of that relaxation (dimension 2 for the screw),
    its picture and a warning say so; a loop without helical joints has no such note."""
    monkeypatch.chdir(tmp_path)
    s = Session()
    out = s.execute('LIB "mechanism.lib"; mechanism m = "revolute A; helical B pitch 1/2; prismatic C"; '
                    'plotConfigurations(m, "s.svg", 300);')
    note = "cylindrical relaxation: helical joint B slides freely here (d = pitch·θ is not imposed)"
    assert f"// ** plotConfigurations: {note}" in out
    assert [t.text for t in by_class(svg(tmp_path / "s.svg"), "note")] == [note]
    run(tmp_path, monkeypatch, f'mechanism m = "{BENNETT}"; plotConfigurations(m, "b.svg", 300);')
    assert by_class(svg(tmp_path / "b.svg"), "note") == []


def test_configuration_space_of_spatial_points(tmp_path, monkeypatch):
    run(tmp_path, monkeypatch, f'mechanism m = "{TRIPOD}"; plotConfigurations(m, "t.svg", list(2, 3), 400);')
    root = svg(tmp_path / "t.svg")
    assert [e.text for e in by_class(root, "xlabel") + by_class(root, "ylabel")] == ["y_A", "z_A"]
    to_px = plane_map(root)
    (x0, y0), (x1, y1) = to_px(0, 0), to_px(1, 1)
    px = dots(root, "mode1")
    y, z = (px[:, 0] - x0) / (x1 - x0), (px[:, 1] - y0) / (y1 - y0)
    assert len(px) > 100 and np.abs(y ** 2 + z ** 2 - 3).max() < 0.05  # the circle of A


def test_configuration_space_of_a_loop_in_its_joint_angles(tmp_path, monkeypatch):
    run(tmp_path, monkeypatch, f'mechanism m = "{BENNETT}"; plotConfigurations(m, "b.svg", list(1, 3), 400);')
    root = svg(tmp_path / "b.svg")
    assert [e.text for e in by_class(root, "xlabel") + by_class(root, "ylabel")] == ["θ_A", "θ_C"]
    legend = [e.text for e in by_class(root, "legend") if e.tag == NS + "text"]
    assert legend == ["mode 1 (dim 1)"]
    to_px = plane_map(root)
    (x0, y0), (x1, y1) = to_px(0, 0), to_px(1, 1)
    px = dots(root, "mode1")
    ta, tc = (px[:, 0] - x0) / (x1 - x0), (px[:, 1] - y0) / (y1 - y0)
    # a Bennett linkage's opposite joints turn by opposite angles (theta_C = -theta_A, mod 2 pi)
    assert len(px) > 100 and np.abs(np.sin((ta + tc) / 2)).max() < 0.02


def test_docs_joint_pictures(tmp_path):
    """examples/joints.mech draws the pictures of docs/img/joints, each shown in docs/mechanisms.md (the
    same elements; the sampled configuration space's dots within a few percent)."""
    r = subprocess.run([sys.executable, "-m", "mech", str(ROOT / "examples" / "joints.mech")],
                       cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert r.returncode == 0 and not r.stderr, r.stderr
    docs = ROOT / "docs" / "img" / "joints"
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == sorted(p.name for p in docs.iterdir()) and len(names) == 16
    text = (ROOT / "docs" / "mechanisms.md").read_text()
    for name in names:
        assert f"img/joints/{name}" in text
        ours, theirs = (tmp_path / name).read_text(), (docs / name).read_text()
        assert re.findall(r'class="([\w-]+)"', ours) == re.findall(r'class="([\w-]+)"', theirs)
        a, b = ours.count("M"), theirs.count("M")
        assert abs(a - b) <= 0.05 * b, name
    kinds = {name: set(re.findall(r'class="([\w-]+)-joints"', (docs / name).read_text())) for name in names}
    assert kinds["revolute.svg"] == {"revolute"} and kinds["cylindrical.svg"] == {"revolute", "cylindrical"}
    assert kinds["loop_prismatic.svg"] == {"revolute", "prismatic"}
    assert kinds["universal.svg"] == {"revolute", "universal"}
