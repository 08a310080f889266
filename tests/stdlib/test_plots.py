"""plotConfigurations and drawMechanism: SVG written directly (checked as XML, its coordinates mapped
back through the axis ticks), PNG through matplotlib, the numerical sampling, the choice of angles."""
from __future__ import annotations

import math
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from fractions import Fraction

import numpy as np
import pytest

from mech import Session
from mech.dsl.errors import MechError
from mech.stdlib.analysis import run_analysis
from mech.stdlib.mechanism import parse_mechanism
from mech.stdlib.plots import COLOURS, TOLERANCE, sample_mode

NS = "{http://www.w3.org/2000/svg}"
SLIDER2 = "fix O; bar O A 1; bar A B 1; slider B"
DIAGONAL = "fix O; bar O A 1; bar A B 1; slider B 1 -1 0"  # singular points with coordinates +-sqrt(2)/2
FOURBAR = "ground O A 1; bar O B 1; bar B C 1; bar C A 1"
PENDULUM = FOURBAR + "; bar C D 1"  # four links: a free bar hangs at C


def run(tmp_path, monkeypatch, script: str) -> Session:
    monkeypatch.chdir(tmp_path)
    s = Session()
    s.execute('LIB "mechanism.lib";\n' + script)
    return s


def svg(path) -> ET.Element:
    root = ET.parse(path).getroot()  # well-formed XML
    assert root.tag == NS + "svg"
    return root


def by_class(root: ET.Element, cls: str) -> list[ET.Element]:
    return [e for e in root.iter() if e.get("class") == cls]


def numbers(d: str) -> list[float]:
    return [float(v) for v in re.findall(r"-?[0-9.]+", d)]


def tick_value(label: str) -> float:
    label = label.replace("−", "-")
    if "π" in label:
        num, _, den = label.partition("/")
        k = {"π": 1.0, "-π": -1.0}.get(num, 0.0)
        return k * math.pi / (float(den) if den else 1.0)
    return float(label)


def axis_map(root: ET.Element, cls: str, coord: str):
    """Data value -> pixel coordinate along an axis, from its tick labels."""
    ticks = [(tick_value(e.text), float(e.get(coord))) for e in by_class(root, cls)]
    (v0, p0), (v1, p1) = ticks[0], ticks[-1]
    return lambda v: p0 + (v - v0) * (p1 - p0) / (v1 - v0)


def plane_map(root: ET.Element):
    """(x, y) data -> pixel for a plane picture (a y tick label's baseline is 0.35 em below its tick)."""
    fx = axis_map(root, "xtick", "x")
    ticks = [(tick_value(e.text), float(e.get("y")) - 0.35 * float(e.get("font-size")))
             for e in by_class(root, "ytick")]
    (v0, p0), (v1, p1) = ticks[0], ticks[-1]
    return lambda x, y: (fx(x), p0 + (y - v0) * (p1 - p0) / (v1 - v0))


def cross_centres(root: ET.Element) -> list[tuple[float, float]]:
    (path,) = by_class(root, "singular")
    v = numbers(path.get("d"))
    return [((v[i] + v[i + 2]) / 2, (v[i + 1] + v[i + 3]) / 2) for i in range(0, len(v), 8)]


def dots(root: ET.Element, cls: str) -> np.ndarray:
    (path,) = by_class(root, cls)
    return np.array(numbers(path.get("d").replace("h0", " "))).reshape(-1, 2)


def angles(point) -> tuple[float, ...]:
    vals = [float(Fraction(int(c.p), int(c.q))) if hasattr(c, "p") else float(c) for c in point]
    return tuple(math.atan2(vals[i + 1], vals[i]) for i in range(0, len(vals), 2))


def matches(got, want, tol: float) -> bool:
    return len(got) == len(want) and all(min(math.dist(g, w) for w in want) < tol for g in got) \
        and all(min(math.dist(g, w) for g in got) < tol for w in want)


# ---------------------------------------------------------------- configuration plots
def test_plane_plot_of_the_slider_crank(tmp_path, monkeypatch):
    run(tmp_path, monkeypatch, f'mechanism m = "{SLIDER2}"; plotConfigurations(m, "s.svg");')
    root = svg(tmp_path / "s.svg")
    a = run_analysis(parse_mechanism(SLIDER2))
    assert len(a.modes) == 2
    for i in (1, 2):  # one series per real mode, in its colour, with its legend entry
        (path,) = by_class(root, f"mode{i}")
        assert path.get("stroke") == COLOURS[i - 1]
    legend = [e.text for e in by_class(root, "legend") if e.tag == NS + "text"]
    assert legend == ["mode 1 (dim 1)", "mode 2 (dim 1)", "singular configurations"]
    assert [e.text for e in by_class(root, "xlabel") + by_class(root, "ylabel")] == ["θ₁", "θ₂"]
    to_px = plane_map(root)
    want = [to_px(*angles(s.point)) for s in a.singular]
    assert matches(cross_centres(root), want, 0.15)
    assert matches([angles(s.point) for s in a.singular], [(math.pi / 2, -math.pi / 2), (-math.pi / 2, math.pi / 2)],
                   1e-12)


def test_dots_lie_on_the_configuration_space(tmp_path, monkeypatch):
    run(tmp_path, monkeypatch, f'mechanism m = "{SLIDER2}"; plotConfigurations(m, "s.svg", 500);')
    root = svg(tmp_path / "s.svg")
    to_px = plane_map(root)
    (x0, y0), (x1, y1) = to_px(0, 0), to_px(1, 1)
    for i in (1, 2):
        px = dots(root, f"mode{i}")
        assert len(px) > 100
        th1, th2 = (px[:, 0] - x0) / (x1 - x0), (px[:, 1] - y0) / (y1 - y0)
        assert np.abs(np.sin(th1) + np.sin(th2)).max() < 0.2 / (x1 - x0)  # the slider: s1 + s2 = 0


def test_algebraic_singular_points_are_drawn(tmp_path, monkeypatch):
    run(tmp_path, monkeypatch, f'mechanism m = "{DIAGONAL}"; plotConfigurations(m, "d.svg");')
    root = svg(tmp_path / "d.svg")
    (s,) = run_analysis(parse_mechanism(DIAGONAL)).singular
    assert s.point is None and s.dim == 0 and s.real
    to_px = plane_map(root)
    q = math.pi / 4
    assert matches(cross_centres(root), [to_px(-q, 3 * q), to_px(3 * q, -q)], 0.15)


def test_three_d_plot_of_the_four_bar(tmp_path, monkeypatch):
    run(tmp_path, monkeypatch, f'mechanism m = "{FOURBAR}"; plotConfigurations(m, "f.svg");')
    root = svg(tmp_path / "f.svg")
    a = run_analysis(parse_mechanism(FOURBAR))
    labels = [by_class(root, f"label{k}")[0].text for k in (1, 2, 3)]
    assert labels == ["θ₁", "θ₂", "θ₃"] and all(len(by_class(root, f"tick{k}")) == 5 for k in (1, 2, 3))
    crosses = cross_centres(root)
    assert len(crosses) == 3
    series = {i: dots(root, f"mode{i}") for i in (1, 2, 3)}
    for s in a.singular:  # each cross is where the two modes through it meet
        assert len(s.modes) == 2
        near = [c for c in crosses if all(np.hypot(*(series[i] - c).T).min() < 3 for i in s.modes)]
        assert len(near) == 1


def test_choice_of_angles(tmp_path, monkeypatch):
    run(tmp_path, monkeypatch, f'mechanism m = "{PENDULUM}";\n'
        'plotConfigurations(m, "p134.svg", list(1, 3, 4), 300);\n'
        'plotConfigurations(m, "p41.svg", intvec(4, 1), 300);\n'
        f'mechanism f = "{FOURBAR}"; plotConfigurations(f, "f31.svg", list(3, 1));')
    root = svg(tmp_path / "p134.svg")
    assert [by_class(root, f"label{k}")[0].text for k in (1, 2, 3)] == ["θ₁", "θ₃", "θ₄"]
    assert all(by_class(root, f"mode{i}") for i in (1, 2, 3))
    assert by_class(root, "singular-dim1")  # the four-bar's singular points times the pendulum's circle
    root = svg(tmp_path / "p41.svg")
    assert [e.text for e in by_class(root, "xlabel") + by_class(root, "ylabel")] == ["θ₄", "θ₁"]
    root = svg(tmp_path / "f31.svg")
    to_px = plane_map(root)
    want = [to_px(t[2], t[0]) for t in (angles(s.point) for s in run_analysis(parse_mechanism(FOURBAR)).singular)]
    assert matches(cross_centres(root), want, 0.15)


@pytest.mark.parametrize("args, message", [
    ('list(1)', "give 2 or 3 link numbers, not 1"),
    ('list(1, 2, 3, 4)', "give 2 or 3 link numbers, not 4"),
    ('list(1, 5)', "there is no link 5 (the links are 1..3)"),
    ('list(0, 1)', "there is no link 0"),
    ('list(2, 2)', "a link is repeated in 2, 2"),
    ('list("a", 2)', "the links are given by their numbers (int), not 'a'"),
    ('0', "the number of samples must be in 1..100000, not 0"),
    ('list(1, 2), -5', "the number of samples must be in 1..100000, not -5"),
])
def test_angle_choice_errors(tmp_path, monkeypatch, args, message):
    with pytest.raises(MechError) as e:
        run(tmp_path, monkeypatch, f'mechanism m = "{FOURBAR}"; plotConfigurations(m, "x.svg", {args});')
    assert message in str(e.value)
    assert not list(tmp_path.iterdir())


def test_png_is_the_same_scene(tmp_path, monkeypatch):
    run(tmp_path, monkeypatch, f'mechanism m = "{SLIDER2}"; plotConfigurations(m, "s.png", 300);'
        'drawMechanism(m, list(1, 0, 1, 0), "d.png");')
    from matplotlib.image import imread
    image = imread(tmp_path / "s.png")
    assert image.shape[:2] == (540, 800)
    assert imread(tmp_path / "d.png").shape[:2] == (440, 520)
    blue = np.all(np.abs(image[:, :, :3] - np.array([0x1f, 0x77, 0xb4]) / 255) < 0.05, axis=2)
    assert blue.sum() > 200  # the first mode's dots


def test_svg_does_not_load_matplotlib(tmp_path):
    code = ('import sys\nfrom mech import Session\n'
            f'Session().execute(\'LIB "mechanism.lib"; mechanism m = "{SLIDER2}"; plotConfigurations(m, "s.svg", 200);'
            'drawMechanism(m, list(1, 0, 1, 0), "d.svg");\')\n'
            'print("matplotlib" in sys.modules)\n')
    r = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, text=True, capture_output=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "False" and (tmp_path / "s.svg").exists() and (tmp_path / "d.svg").exists()


# ---------------------------------------------------------------- sampling
@pytest.mark.parametrize("desc", [SLIDER2, FOURBAR, "fix O; bar O A 2; bar A B 1; bar B C 1; slider C",
                                  "fix O; fix A 2 0; bar O B 1; prismatic A B"])
def test_sampled_points_satisfy_the_constraints(desc):
    m = parse_mechanism(desc)
    a = run_analysis(m)
    R, gens = m.constraints()
    for i, mode in enumerate(a.modes, 1):
        x = sample_mode(mode.prime, len(m.links), 400, seed=i)
        assert len(x) > 360
        for g in list(mode.prime) + gens:
            value = sum(float(Fraction(int(c.p), int(c.q))) * np.prod([x[:, j] ** k for j, k in enumerate(e)], axis=0)
                        for e, c in g.terms.items())
            assert np.abs(value).max() < TOLERANCE
        assert np.ptp(x, axis=0).max() > 0.5  # spread over the mode, not one point


# ---------------------------------------------------------------- drawMechanism
def test_draw_mechanism_at_the_joint_coordinates(tmp_path, monkeypatch):
    run(tmp_path, monkeypatch, f'mechanism m = "{SLIDER2}"; drawMechanism(m, list("3/5", "4/5", "3/5", "-4/5"), '
        '"d.svg");')
    root = svg(tmp_path / "d.svg")
    to_px = plane_map(root)
    joints = {"O": (0, 0), "A": (0.6, 0.8), "B": (1.2, 0)}
    (links,) = by_class(root, "links")
    segments = [numbers(part) for part in links.get("d").split("M")[1:]]
    want = [[*to_px(*joints["O"]), *to_px(*joints["A"])], [*to_px(*joints["A"]), *to_px(*joints["B"])]]
    assert len(segments) == 2 and np.abs(np.array(segments) - np.array(want)).max() < 0.15
    labels = {e.text: (float(e.get("x")) - 8, float(e.get("y")) + 8) for e in by_class(root, "point")}
    assert labels.keys() == joints.keys()
    assert all(math.dist(labels[p], to_px(*xy)) < 0.15 for p, xy in joints.items())
    (square,) = by_class(root, "sliders")
    v = numbers(square.get("d"))
    assert math.dist((v[0] + 8, v[1] + 8), to_px(*joints["B"])) < 0.15
    assert by_class(root, "slider-line")[0].get("stroke-dasharray")
    assert by_class(root, "title")[0].text == "c1=0.6, s1=0.8, c2=0.6, s2=-0.8"


def test_draw_a_rigid_body(tmp_path, monkeypatch):
    run(tmp_path, monkeypatch, 'mechanism m = "fix O; body O A 2 0 B 0 1"; drawMechanism(m, list(0, 1), "b.svg");')
    root = svg(tmp_path / "b.svg")
    to_px = plane_map(root)
    (links,) = by_class(root, "links")
    corners = np.array(numbers(links.get("d"))).reshape(-1, 2)
    want = [to_px(0, 0), to_px(0, 2), to_px(-1, 0), to_px(0, 0)]  # turned by 90 degrees, closed
    assert np.abs(corners - np.array(want)).max() < 0.15


def test_a_folder_in_the_way_is_an_error(tmp_path, monkeypatch):
    (tmp_path / "d.svg").mkdir()
    with pytest.raises(MechError) as e:
        run(tmp_path, monkeypatch, f'mechanism m = "{SLIDER2}"; drawMechanism(m, list(1, 0, 1, 0), "d.svg");')
    assert "'d.svg': exists and is not a regular file" in str(e.value)
