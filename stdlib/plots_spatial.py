"""Pictures of spatial mechanisms and loops of joints: a mechanism in a chosen view, and the
configuration space in the coordinates a person reads (the joints' angles and slides).

A view is an orthographic projection from azimuth ``azim`` and elevation ``elev`` (degrees, as in
matplotlib: azimuth about the z-axis from the x-axis, elevation above the x-y plane), or a named
view (:data:`VIEWS`).  Spatial points, bars and bodies are drawn as in the plane; a loop of joints
(Denavit–Hartenberg) is drawn link by link (along its joint's axis by the offset ``d``, then
along the common normal by the length ``a``) with every joint's axis as a dash-dotted line through
it (a universal joint's second axis too) and a marker by kind.  A small triad shows the directions
of x, y and z in the view.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Optional, Sequence

from mech.dsl.errors import MechRuntimeError
from mech.dsl.values import List
from mech.stdlib.joints import Helical, Universal
from mech.stdlib.mechanism import Mechanism

if TYPE_CHECKING:
    from mech.stdlib._scene import Scene

# azimuth, elevation (degrees)
VIEWS: dict[str, tuple[float, float]] = {
    "front": (-90.0, 0.0),   # x to the right, z up (seen from -y)
    "side": (0.0, 0.0),      # y to the right, z up (seen from +x)
    "top": (-90.0, 90.0),    # x to the right, y up (seen from +z)
    "iso": (-45.0, math.degrees(math.atan(1 / math.sqrt(2)))),  # the isometric view: the axes at 120 degrees
}
JOINT_MARKERS = {"revolute": "circle", "prismatic": "square", "cylindrical": "square", "universal": "circle",
                 "helical": "triangle"}
Vec = Sequence[float]


def parse_view(view: Any, command: str) -> tuple[float, float]:
    """``(azim, elev)`` from a view's name or a list ``(azimuth, elevation)`` in degrees."""
    if isinstance(view, str):
        if view not in VIEWS:
            raise MechRuntimeError(f"{command}: unknown view '{view}' (the views: {', '.join(VIEWS)}, or "
                                   "list(azimuth, elevation) in degrees)")
        return VIEWS[view]
    items = view.items if isinstance(view, List) else None
    if items is None or len(items) != 2 or not all(isinstance(v, (int, str)) for v in items):
        raise MechRuntimeError(f"{command}: a view is a name ({', '.join(VIEWS)}) or list(azimuth, elevation) "
                               "in degrees")
    from mech.stdlib.plot_sampling import _value
    azim, elev = (_value(v) for v in items)
    if not -90 <= elev <= 90:
        raise MechRuntimeError(f"{command}: the elevation is in -90..90 degrees, not {elev:g}")
    return azim, elev


class View:
    """The orthographic projection from ``(azim, elev)``: a point in space to its screen
    coordinates (right, up)."""

    def __init__(self, azim: float, elev: float) -> None:
        a, e = math.radians(azim), math.radians(elev)
        self.right = (-math.sin(a), math.cos(a), 0.0)
        self.up = (-math.sin(e) * math.cos(a), -math.sin(e) * math.sin(a), math.cos(e))

    def __call__(self, p: Vec) -> tuple[float, float]:
        return (sum(a * b for a, b in zip(self.right, p)), sum(a * b for a, b in zip(self.up, p)))


def _add(p: Vec, q: Vec, k: float = 1.0) -> list[float]:
    return [a + k * b for a, b in zip(p, q)]


@dataclass
class JointPicture:
    """A joint of a loop as drawn: its place, its axis as a segment, a universal joint's second axis."""

    name: str
    kind: str
    point: list[float]
    axis: list[list[float]]
    second: Optional[list[list[float]]] = None
    thread: Optional[list[list[float]]] = None  # a helical joint's last turn of thread


def loop_geometry(m: Mechanism, config: dict[str, float]) -> tuple[list[list[list[float]]], list[JointPicture]]:
    """The polylines of the links of a loop of joints and its joints at a configuration (the ring
    variables' values): each link from its joint along the axis by ``d``, then along the common
    normal by ``a``; the axes reach beyond the links by 0.3 of the loop's size."""
    from mech.stdlib import loops
    vals = loops.joint_values(m, config)
    frames = loops.frames(m, config)

    def param(v: Any) -> float:
        return config[v] if isinstance(v, str) else float(v)
    links, axes = [], []
    for i, (j, v) in enumerate(zip(m.joints, vals)):
        start, end = frames[i], frames[i + 1]
        mid = _add(end.trans, end.column(0), -param(j.a))  # the foot of the common normal on the joint's axis
        links.append([list(start.trans), mid, list(end.trans)])
        second = None
        if isinstance(j, Universal):
            c, s = v["theta"]
            second = [c * p + s * q for p, q in zip(start.column(0), start.column(1))]
        thread = None
        if isinstance(j, Helical):  # one turn up to the present angle: p + r (cos phi, sin phi) + pitch phi z
            theta, pitch = math.atan2(v["theta"][1], v["theta"][0]), float(j.pitch)
            x, y, z = start.column(0), start.column(1), start.column(2)
            base = _add(start.trans, z, v["d"] - pitch * theta)
            r = 0.25 * max(abs(pitch) * 2 * math.pi, 1.0)
            thread = [_add(base, [r * math.cos(f) * p + r * math.sin(f) * q + pitch * f * w for p, q, w in zip(x, y, z)])
                      for f in (theta - 2 * math.pi * k / 48 for k in range(48, -1, -1))]
        axes.append((j, list(start.trans), start.column(2), mid, second, thread))
    corners = [p for line in links for p in line] + [p for a in axes if a[5] for p in a[5]]
    size = max((math.dist(p, q) for p in corners for q in corners), default=0.0)
    if size < 1e-9:
        return _spherical(axes)
    h = 0.3 * size
    out = []
    for j, origin, z, mid, second, thread in axes:
        offset = sum((p - q) * w for p, q, w in zip(mid, origin, z))
        out.append(JointPicture(j.name, j.keyword, origin, [_add(origin, z, min(offset, 0) - h),
                                                            _add(origin, z, max(offset, 0) + h)],
                                [_add(origin, second, -h / 2), _add(origin, second, h / 2)] if second else None,
                                thread))
    return links, out


def _spherical(axes: list[tuple]) -> tuple[list[list[list[float]]], list[JointPicture]]:
    """A spherical loop (every axis through one point, the centre): each joint drawn where its axis
    meets the unit sphere about the centre, the links as great-circle arcs between them (a universal
    joint's two axes joined by an arc too), the axes from the centre."""
    centre = axes[0][1]
    stations, out = [], []
    for j, _, z, _, second, _ in axes:
        stations.append(_add(centre, z))
        if second:
            stations.append(_add(centre, second))
        out.append(JointPicture(j.name, j.keyword, _add(centre, z), [list(centre), _add(centre, z, 1.4)],
                                [list(centre), _add(centre, second, 1.4)] if second else None))
    arcs = [_arc(centre, p, q) for p, q in zip(stations, stations[1:] + stations[:1])]
    return arcs, out


def _arc(centre: Vec, p: Vec, q: Vec, steps: int = 16) -> list[list[float]]:
    """The great-circle arc from ``p`` to ``q`` on the unit sphere about ``centre``."""
    u, v = _add(p, centre, -1), _add(q, centre, -1)
    angle = math.acos(max(-1.0, min(1.0, sum(a * b for a, b in zip(u, v)))))
    if angle < 1e-9:
        return [list(p), list(q)]
    out = []
    for k in range(steps + 1):
        t = angle * k / steps
        a, b = math.sin(angle - t) / math.sin(angle), math.sin(t) / math.sin(angle)
        out.append(_add(centre, [a * x + b * y for x, y in zip(u, v)]))
    return out


def check_helical(m: Mechanism, config: dict[str, float], command: str) -> None:
    """A configuration of a loop with helical joints: each one's slide is its pitch times its angle
    (in radians, up to whole turns), which the ideal does not say (it is not polynomial)."""
    from mech.stdlib import loops
    for j, v in zip(m.joints, loops.joint_values(m, config)):
        if isinstance(j, Helical):
            pitch, theta = float(j.pitch), math.atan2(v["theta"][1], v["theta"][0])
            turns = (v["d"] / pitch - theta) / (2 * math.pi)
            if abs(turns - round(turns)) * 2 * math.pi * abs(pitch) > 1e-6:
                raise MechRuntimeError(f"{command}: not a configuration of the helical joint {j.name}: d_{j.name} = "
                                       f"{v['d']:.6g} is not {j.pitch} times its angle {theta:.6g} (radians) plus "
                                       "whole turns")


def space_scene(m: Mechanism, config: dict[str, float], title: str, azim: float, elev: float,
                points: Optional[dict[str, Vec]] = None) -> "Scene":
    """The spatial mechanism ``m`` seen from ``(azim, elev)``: its joint points at ``points``
    (points, bars, bodies) or, for a loop of joints, its links and joint axes at ``config``."""
    from mech.stdlib._scene import Axes2D, Lines, Markers, Scene, Text
    from mech.stdlib.plot_sampling import _title
    view = View(azim, elev)
    scene = Scene(520, 440)
    _title(scene, title, 260)
    if points is None:
        links, joints = loop_geometry(m, config)
        named = {j.name: j.point for j in joints}
    else:
        links = [[list(points[p]) for p in link.points] for link in m.links]
        links = [pts + pts[:1] if len(pts) > 2 else pts for pts in links]
        joints, named = [], dict(points)
    flat = [view(p) for line in links for p in line] + [view(p) for p in named.values()] \
        + [view(p) for j in joints for p in j.axis + (j.second or []) + (j.thread or [])]
    size = max(max(u for u, _ in flat) - min(u for u, _ in flat), max(v for _, v in flat) - min(v for _, v in flat),
               1.0)
    pad = (0.1 if joints else 0.3) * size
    axes = Axes2D((30, 40, 490, 420), (min(u for u, _ in flat) - pad, max(u for u, _ in flat) + pad),
                  (min(v for _, v in flat) - pad, max(v for _, v in flat) + pad), equal=True)

    def px(p: Vec) -> tuple[float, float]:
        return axes.map(*view(p))
    if joints:
        scene.add(Lines([[px(p) for p in j.axis] for j in joints], "#888888", 1, dash=True, cls="joint-axes"))
        seconds = [[px(p) for p in j.second] for j in joints if j.second]
        if seconds:
            scene.add(Lines(seconds, "#888888", 1, dash=True, cls="second-axes"))
    if points is not None and m.sliders:  # a slider's line through two points of a link (or fixed)
        scene.add(Lines([[px(_add(points[s.a], _add(points[s.b], points[s.a], -1), t)) for t in (-1.0, 2.0)]
                         for s in m.sliders], "grey", dash=True, cls="slider-line"))
    threads = [[px(p) for p in j.thread] for j in joints if j.thread]
    if threads:
        scene.add(Lines(threads, "#2ca02c", 1.5, cls="threads"))
    scene.add(Lines([[px(p) for p in line] for line in links], "#1f77b4", 4, round=True, cls="links"))
    if points is not None and m.sliders:
        scene.add(Markers([px(points[s.point]) for s in m.sliders], "square", 16, "#d62728", width=1.5,
                          cls="sliders"))
    if joints:
        for kind in JOINT_MARKERS:
            at = [px(j.point) for j in joints if j.kind == kind]
            if at:
                scene.add(Markers(at, JOINT_MARKERS[kind], 11, "black", "white", 1.5, cls=f"{kind}-joints"))
    else:
        scene.add(Markers([px(p) for n, p in named.items() if n not in m.fixed], "circle", 9, "black", "white",
                          cls="joints"))
        scene.add(Markers([px(p) for n, p in named.items() if n in m.fixed], "triangle", 14, "black", "black",
                          cls="fixed"))
    for n, p in named.items():
        u, v = px(p)
        scene.add(Text(u + 8, v - 8, n, anchor="start", cls="point"))
    _triad(scene, view, azim, elev)
    return scene


def _triad(scene: "Scene", view: View, azim: float, elev: float) -> None:
    """The directions of x, y, z in the view (an axis seen end-on has no arrow) and the view's angles."""
    from mech.stdlib._scene import FONT, Lines, Text
    cx, cy, r = 60.0, 380.0, 28.0
    arrows = []
    for k, name in enumerate("xyz"):
        e = [0.0, 0.0, 0.0]
        e[k] = 1.0
        u, v = view(e)
        if math.hypot(u, v) < 1e-6:
            continue
        arrows.append([(cx, cy), (cx + r * u, cy - r * v)])
        scene.add(Text(cx + (r + 9) * u, cy - (r + 9) * v + FONT * 0.35, name, cls="triad-label"))
    scene.add(Lines(arrows, "black", 1.2, cls="triad"))
    scene.add(Text(cx - 30, cy + 52, f"azimuth {azim:g}°, elevation {elev:g}°", FONT * 0.9, anchor="start",
                   cls="view"))


# ---------------------------------------------------------------- configuration spaces
def coordinates(m: Mechanism) -> list[str]:
    """The names of the coordinates a configuration space of a loop of joints or a spatial
    mechanism is drawn in: the joints' angles and slides (as ``jointAngles`` reads them), or the
    configuration variables of spatial points and bodies."""
    if not m.joints:
        return m.variables()
    out = []
    for j in m.joints:
        if "theta" in j.joint_variables:
            out.append(f"θ_{j.name}")
        if "theta2" in j.joint_variables:
            out.append(f"θ2_{j.name}")
        if "d" in j.joint_variables:
            out.append(f"d_{j.name}")
    return out


def values_of(m: Mechanism, x: Any) -> Any:
    """The coordinates (:func:`coordinates`, angles in radians) of the configurations ``x`` (rows
    of the ring variables' values)."""
    np = __import__("numpy")
    if not m.joints:
        return np.asarray(x)
    from mech.stdlib.mechanism_display import joint_readings
    names = m.variables()
    rows = []
    for row in x:
        readings = joint_readings(m, dict(zip(names, map(float, row))))
        rows.append([math.radians(v) if angle else v for _, v, angle in readings])
    return np.array(rows).reshape(len(rows), len(coordinates(m)))


def circle_pairs(m: Mechanism) -> list[tuple[int, int]]:
    """The indices of the (cos, sin) pairs among the ring variables (sampled as angles)."""
    names = m.variables()
    return [(i, i + 1) for i, n in enumerate(names[:-1])
            if n.startswith("c") and names[i + 1] == "s" + n[1:]]


def relaxation_note(m: Mechanism) -> str:
    """What a plot of a loop with helical joints shows: the cylindrical relaxation (its ideal lets each
    helical joint slide freely; the coupling d = pitch * theta is not polynomial); "" without them."""
    names = [j.name for j in m.joints if isinstance(j, Helical)]
    if not names:
        return ""
    many = len(names) > 1
    return (f"cylindrical relaxation: helical joint{'s' if many else ''} {', '.join(names)} "
            f"slide{'' if many else 's'} freely here (d = pitch·θ is not imposed)")


def space_configuration_scene(m: Mechanism, a: Any, chosen: Sequence[int], count: int) -> "Scene":
    """The configuration space of a loop of joints or a spatial mechanism (analysed in ``a``) in
    the coordinates numbered ``chosen`` (0-based in :func:`coordinates`): angles on [-pi, pi],
    slides and point coordinates on the range of the samples."""
    from mech.stdlib._scene import Axes2D, Axes3D, Markers, Scene, Text, legend, nice_ticks, pi_ticks
    from mech.stdlib.plot_sampling import COLOURS, _numpy, _rational, _thin, _title, sample
    np = _numpy()
    names = coordinates(m)
    pairs = circle_pairs(m)
    angle = [n.startswith("θ") for n in names] if m.joints else [False] * len(names)
    modes, singular, crosses = [], [], []
    for i, mode in enumerate(a.modes, 1):
        if mode.real:
            modes.append((i, mode, values_of(m, sample(mode.prime, pairs, count, seed=i))[:, chosen]))
    for s in a.singular:
        if s.point is not None:
            crosses.append([_rational(c) for c in s.point])
        elif s.real:
            singular.append(sample(s.prime, pairs, 200 if s.dim == 0 else count, seed=1))
    crosses_v = values_of(m, np.array(crosses))[:, chosen] if crosses else np.empty((0, len(chosen)))
    singular_v = values_of(m, np.concatenate(singular))[:, chosen] if singular else np.empty((0, len(chosen)))
    every = np.concatenate([v for _, _, v in modes] + [crosses_v, singular_v])
    ranges, ticks = [], []
    for col, k in enumerate(chosen):
        if angle[k]:
            ranges.append((-math.pi, math.pi))
            ticks.append(pi_ticks())
        else:
            lo, hi = (float(every[:, col].min()), float(every[:, col].max())) if len(every) else (-1.0, 1.0)
            pad = 0.1 * max(hi - lo, 1.0)  # a constant coordinate: a range of 0.2
            ranges.append((lo - pad, hi + pad))
            ticks.append(nice_ticks(lo - pad, hi + pad))
    labels = [names[k] for k in chosen]
    scene = Scene(800, 540)
    _title(scene, str(m), 305)
    note = relaxation_note(m)
    if note:
        scene.add(Text(305, 40, note, 11, cls="note"))
    if len(chosen) == 2:
        axes = Axes2D((80, 45, 530, 480), ranges[0], ranges[1])
        axes.frame(scene, ticks[0], ticks[1], labels[0], labels[1])

        def place(v: Any) -> Any:
            return np.column_stack(axes.map(v[:, 0], v[:, 1]))
    else:
        box = Axes3D(ranges, (310, 285), 230)
        box.frame(scene, ticks, labels)

        def place(v: Any) -> Any:
            return np.column_stack(box.project((v[:, 0], v[:, 1], v[:, 2])))
    entries = []
    for i, mode, v in modes:
        dots = scene.add(Markers(_thin(place(v)) if len(v) else [], "dot", 2.2, COLOURS[(i - 1) % len(COLOURS)],
                                 cls=f"mode{i}"))
        entries.append((dots, f"mode {i} (dim {mode.dim})"))
    if len(singular_v):
        entries.append((scene.add(Markers(_thin(place(singular_v)), "dot", 3, "black", cls="singular-set")),
                        "singular configurations (sampled)"))
    if len(crosses_v):
        entries.append((scene.add(Markers(place(crosses_v).tolist(), "x", 10, "black", width=2, cls="singular")),
                        "singular configurations"))
    if entries:
        legend(scene, 600, 50, entries)
    return scene
