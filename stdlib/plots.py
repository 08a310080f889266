"""Pictures of configuration spaces and mechanisms, as SVG (written directly) or PNG (matplotlib).

Configuration spaces are drawn in angle coordinates ``theta_i = atan2(s_i, c_i)`` like the
paper's Figures 2 and 4: a plane picture of two angles, a 3-d picture of three (the first ones,
or the links chosen).  Points of each motion mode are found numerically: random angles are
projected onto the mode's variety by Gauss–Newton steps (minimum-norm, on the prime's
generators with ``c_i = cos theta_i``, ``s_i = sin theta_i``); only points whose residual is below
1e-9 are drawn.  Each mode has its own colour; the singular configurations are black crosses
(exact for rational ones; algebraic ones are sampled like the modes).

Each picture is built once as a :class:`~mech.stdlib._scene.Scene`; ``_svg.py`` and ``_png.py``
render it (the three are imported when a picture is drawn, not when the commands are loaded)."""
from __future__ import annotations

import math
from fractions import Fraction
from typing import TYPE_CHECKING, Any, Sequence

from mech.dsl.errors import MechRuntimeError
from mech.dsl.files import output_file
from mech.dsl.values import IntVec, List
from mech.kernel import Poly
from mech.stdlib.analysis import Analysis, require_complete, require_numeric, run_analysis
from mech.stdlib.joints import LineSlider
from mech.stdlib.mechanism import Mechanism
from mech.dsl.registry import command
from mech.stdlib.plot_sampling import (COLOURS, MAX_SAMPLES, TOLERANCE, _angles, _compile, _numpy,  # noqa: F401
                                       _rational, _thin, _title, _value, sample_mode)  # (coupler.py, tests use them)

if TYPE_CHECKING:
    from mech.stdlib._scene import Scene

_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


# ---------------------------------------------------------------- pictures
def configuration_scene(m: Mechanism, a: Analysis, links: Sequence[int], count: int) -> Scene:
    """The configuration space of ``m`` (analysed in ``a``) in the angles of ``links`` (0-based)."""
    from mech.stdlib._scene import Axes2D, Axes3D, Markers, Scene, legend, pi_ticks
    np = _numpy()
    nlinks = len(m.links)
    scene = Scene(800, 540)
    _title(scene, str(m), 305)
    labels = ["θ" + str(k + 1).translate(_SUB) for k in links]
    cube = [(-math.pi, math.pi)] * len(links)
    if len(links) == 2:
        axes = Axes2D((80, 45, 530, 480), cube[0], cube[1])
        axes.frame(scene, pi_ticks(), pi_ticks(), labels[0], labels[1])

        def place(th: Any) -> Any:
            return np.column_stack(axes.map(th[:, 0], th[:, 1]))
    else:
        box = Axes3D(cube, (310, 285), 230)
        box.frame(scene, [pi_ticks()] * 3, labels)

        def place(th: Any) -> Any:
            return np.column_stack(box.project((th[:, 0], th[:, 1], th[:, 2])))
    entries = []
    for i, mode in enumerate(a.modes, 1):
        if not mode.real:
            continue
        th = _angles(sample_mode(mode.prime, nlinks, count, seed=i), nlinks)[:, links]
        dots = scene.add(Markers(_thin(place(th)), "dot", 2.2, COLOURS[(i - 1) % len(COLOURS)], cls=f"mode{i}"))
        entries.append((dots, f"mode {i} (dim {mode.dim})"))
    points, sets = [], {}
    for s in a.singular:
        if s.point is not None:
            points.append([_rational(c) for c in s.point])
        elif s.real and s.dim == 0:
            points += np.unique(np.round(sample_mode(s.prime, nlinks, 200, seed=1), 6), axis=0).tolist()
        elif s.real:
            sets.setdefault(s.dim, []).append(sample_mode(s.prime, nlinks, count, seed=1))
    for d, found in sorted(sets.items()):
        th = _angles(np.concatenate(found), nlinks)[:, links]
        dots = scene.add(Markers(_thin(place(th)), "dot", 3, "black", cls=f"singular-dim{d}"))
        entries.append((dots, f"singular configurations (dim {d})"))
    if points:
        th = _angles(np.array(points), nlinks)[:, links]
        crosses = scene.add(Markers(place(th).tolist(), "x", 10, "black", width=2, cls="singular"))
        entries.append((crosses, "singular configurations"))
    if entries:
        legend(scene, 600, 50, entries)
    return scene


def _clip(p: tuple[float, float], d: tuple[float, float], box: tuple[tuple[float, float], ...]
          ) -> list[tuple[float, float]]:
    """The segment of the line ``p + t d`` inside the rectangle ``box`` = (x range, y range)."""
    lo, hi = -math.inf, math.inf
    for v, dv, (a, b) in zip(p, d, box):
        if dv:
            t1, t2 = (a - v) / dv, (b - v) / dv
            lo, hi = max(lo, min(t1, t2)), min(hi, max(t1, t2))
    return [(p[0] + t * d[0], p[1] + t * d[1]) for t in (lo, hi)]


def mechanism_scene(m: Mechanism, xy: dict[str, tuple[float, float]], title: str,
                    path: Sequence[tuple[float, float]] = ()) -> Scene:
    """The mechanism ``m`` with its joint points at ``xy`` (over the points ``path`` of a traced
    path, if given)."""
    from mech.stdlib._scene import Axes2D, Lines, Markers, Scene, Text, nice_ticks
    scene = Scene(520, 440)
    _title(scene, title, 285)
    xs = [x for x, _ in xy.values()] + [x for x, _ in path]
    ys = [y for _, y in xy.values()] + [y for _, y in path]
    circles = [c for g in m.gears for c in _pitch_circles(xy[g.a], xy[g.b], g.ratio)]
    for (cx, cy), r in circles:
        xs += [cx - r, cx + r]
        ys += [cy - r, cy + r]
    pad = 0.25 * max(max(xs) - min(xs), max(ys) - min(ys), 1.0)
    axes = Axes2D((70, 40, 500, 390), (min(xs) - pad, max(xs) + pad), (min(ys) - pad, max(ys) + pad), equal=True)
    axes.frame(scene, nice_ticks(*axes.xrange), nice_ticks(*axes.yrange), "x", "y")
    if len(path):
        np = _numpy()
        scene.add(Markers(_thin(np.column_stack(axes.map(*np.asarray(path).T))), "dot", 2, COLOURS[1],
                          cls="path"))
    for s in m.sliders:
        if isinstance(s, LineSlider):  # the line through two points (of a link, or fixed)
            (ax, ay), (bx, by) = xy[s.a], xy[s.b]
            line = _clip(xy[s.a], (bx - ax, by - ay), (axes.xrange, axes.yrange))
        else:
            a, b, _ = (float(Fraction(t)) for t in s.line)
            line = _clip(xy[s.point], (b, -a) if (a, b) != (0, 0) else (1.0, 0.0), (axes.xrange, axes.yrange))
        scene.add(Lines([[axes.map(*p) for p in line]], "grey", dash=True, cls="slider-line"))
    if circles:
        scene.add(Lines([_circle(axes, c, r) for c, r in circles], "#2ca02c", 1.5, cls="gears"))
    links = []
    for link in m.links:
        pts = [axes.map(*xy[p]) for p in link.points]
        links.append(pts + pts[:1] if len(pts) > 2 else pts)
    scene.add(Lines(links, "#1f77b4", 4, round=True, cls="links"))
    scene.add(Markers([axes.map(*xy[s.point]) for s in m.sliders], "square", 16, "#d62728", width=1.5,
                      cls="sliders"))
    scene.add(Markers([axes.map(*xy[p]) for p in xy if p not in m.fixed], "circle", 9, "black", "white",
                      cls="joints"))
    scene.add(Markers([axes.map(*xy[p]) for p in xy if p in m.fixed], "triangle", 14, "black", "black",
                      cls="fixed"))
    for p, (x, y) in xy.items():
        u, v = axes.map(x, y)
        scene.add(Text(u + 8, v - 8, p, anchor="start", cls="point"))
    return scene


def _pitch_circles(a: tuple[float, float], b: tuple[float, float], ratio: int) -> list[tuple[tuple[float, float], float]]:
    """The pitch circles (centre, radius) of a gear pair centred at ``a`` and ``b``: radii in the
    ratio's proportion, touching (external) or one inside the other (internal), ``|ab|`` apart."""
    gap = math.dist(a, b)
    rb = gap / (ratio + 1) if ratio > 0 else gap / (-ratio - 1)
    return [(a, abs(ratio) * rb), (b, rb)]


def _circle(axes: Any, centre: tuple[float, float], r: float) -> list:
    cx, cy = centre
    return [axes.map(cx + r * math.cos(t * math.pi / 36), cy + r * math.sin(t * math.pi / 36)) for t in range(73)]


def _check_path(path: str) -> None:
    output_file(path, (".png", ".svg"))  # the file policy: mech.dsl.files


def _write(ctx: Any, scene: Scene, path: str, title: str) -> None:
    """Write the picture where the (checked) ``path`` says; in a notebook also show it inline."""
    try:
        if path.lower().endswith(".svg"):
            from mech.stdlib._svg import write_svg
            write_svg(scene, path, title)
        else:
            from mech.stdlib._png import write_png
            write_png(scene, path)
    except OSError as e:
        raise MechRuntimeError(f"'{path}': cannot write the file ({e.strerror or e})") from None
    if "display" in ctx.settings:
        from mech.stdlib._svg import to_svg
        ctx.display({"image/svg+xml": to_svg(scene, title), "text/plain": f"<picture: {title}>\n"})


# ---------------------------------------------------------------- commands
def _plot(ctx: Any, m: Mechanism, path: str, links: Sequence[Any] | None, count: int) -> None:
    _check_path(path)
    if not 0 < count <= MAX_SAMPLES:
        raise MechRuntimeError(f"plotConfigurations: the number of samples must be in 1..{MAX_SAMPLES}, not {count}")
    planar = m.dim == 2 and not m.joints
    if planar:
        what, names = "link", [f"θ{k}" for k in range(1, len(m.links) + 1)]
    else:
        from mech.stdlib.plots_spatial import coordinates
        what, names = "coordinate", coordinates(m)
    if links is None:
        if len(names) < 2:
            raise MechRuntimeError(f"plotConfigurations needs at least two {what}s")
        links = list(range(1, min(len(names), 3) + 1))
    if len(links) not in (2, 3):
        raise MechRuntimeError(f"plotConfigurations: give 2 or 3 {what} numbers, not {len(links)}")
    for k in links:
        if type(k) is not int:
            raise MechRuntimeError(f"plotConfigurations: the {what}s are given by their numbers (int), not '{k}'")
        if not 1 <= k <= len(names):
            known = "" if planar else f": {', '.join(names)}"
            raise MechRuntimeError(f"plotConfigurations: there is no {what} {k} (the {what}s are "
                                   f"1..{len(names)}{known})")
    if len(set(links)) < len(links):
        raise MechRuntimeError(f"plotConfigurations: a {what} is repeated in {', '.join(map(str, links))}")
    a = run_analysis(m)
    require_complete(a, "plotConfigurations")
    require_numeric(a, "plotConfigurations")
    if planar:
        scene = configuration_scene(m, a, [k - 1 for k in links], count)
    else:
        from mech.stdlib.plots_spatial import relaxation_note, space_configuration_scene
        scene = space_configuration_scene(m, a, [k - 1 for k in links], count)
        if relaxation_note(m):
            ctx.warn(f"plotConfigurations: {relaxation_note(m)}")
    _write(ctx, scene, path, f"configuration space of {m}")


@command("plotConfigurations", lib="mechanism.lib")
def plot_configurations(ctx, m: Mechanism, path: str, count: int = 3000) -> None:
    """plotConfigurations(m, "file.svg"[, links][, samples]): the configuration space in angle
    coordinates theta_i, one colour per motion mode, singular configurations as black crosses.

    The picture is plane for two links and 3-d for three or more: the angles of the first three
    links, or of the 2 or 3 links numbered in the list (or intvec) `links`.  Each mode is sampled
    at `samples` (default 3000) random starting points moved onto it numerically.  The file is
    SVG or PNG by its name's ending.

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A 1; bar A B 1; slider B";
      plotConfigurations(m, "modes.svg", list(1, 3));
      → <stdin>:3:1: error: plotConfigurations: there is no link 3 (the links are 1..2)
      → plotConfigurations(m, "modes.svg", list(1, 3));
      → ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
      plotConfigurations(m, "modes.pdf");
      → <stdin>:1:1: error: 'modes.pdf': give a file name ending in .png or .svg
      → plotConfigurations(m, "modes.pdf");
      → ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
    """
    _plot(ctx, m, path, None, count)


@command("plotConfigurations", lib="mechanism.lib")
def plot_configurations_of(ctx, m: Mechanism, path: str, links: List | IntVec, count: int = 3000) -> None:
    _plot(ctx, m, path, list(links.items if isinstance(links, List) else links.values), count)


def _evaluate(p: Poly, values: Sequence[float]) -> float:
    return sum(_rational(c) * math.prod(v ** k for v, k in zip(values, e)) for e, c in p.terms.items())


def _view(xyz: Sequence[float]) -> tuple[float, float]:
    """A point in the picture: the plane's own coordinates, or in space the cabinet projection seen from
    the front (x to the right, z up, y receding at 45 degrees, halved)."""
    if len(xyz) == 2:
        return xyz[0], xyz[1]
    x, y, z = xyz
    return x + 0.35 * y, z + 0.35 * y


@command("drawMechanism", lib="mechanism.lib")
def draw_mechanism(ctx, m: Mechanism, config: List, path: str) -> None:
    """drawMechanism(m, list(c1,s1,c2,s2,...), "file.svg"[, view]): the mechanism in that configuration.

    A spatial mechanism is drawn in a cabinet projection (x to the right, z up, y receding), a loop
    of joints in the isometric view, each joint with its axis; `view` chooses another: "front",
    "side", "top", "iso" or list(azimuth, elevation) in degrees.

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A 1; bar A B 1; slider B";
      drawMechanism(m, list(0, 1), "m.svg");
      → <stdin>:3:1: error: drawMechanism: 4 values expected (c1,s1,c2,s2), 2 given
      → drawMechanism(m, list(0, 1), "m.svg");
      → ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
    """
    _draw(ctx, m, config, path, None)


@command("drawMechanism", lib="mechanism.lib")
def draw_mechanism_in_view(ctx, m: Mechanism, config: List, path: str, view: str | List) -> None:
    _draw(ctx, m, config, path, view)


def _draw(ctx: Any, m: Mechanism, config: List, path: str, view: str | List | None) -> None:
    _check_path(path)
    if m.symbols():
        raise MechRuntimeError(f"drawMechanism needs numeric lengths (setLengths(m, ...) for "
                               f"{','.join(m.symbols())})")
    names = m.variables()
    values = [_value(v) for v in config.items]
    if len(values) != len(names):
        raise MechRuntimeError(f"drawMechanism: {len(names)} values expected ({','.join(names)}), "
                               f"{len(values)} given")
    R, gens = m.constraints()
    bad = max(abs(_evaluate(g, values)) for g in gens)
    if bad > 1e-6:
        raise MechRuntimeError(f"drawMechanism: the values are not a configuration (a constraint is {bad:.3g})")
    title = ", ".join(f"{n}={v:.3g}" for n, v in zip(names, values))
    if m.dim == 2 and view is not None:
        raise MechRuntimeError("drawMechanism: a view is for spatial mechanisms (this one is planar)")
    if m.joints or view is not None:
        from mech.stdlib.plots_spatial import check_helical, parse_view, space_scene
        azim, elev = parse_view(view if view is not None else "iso", "drawMechanism")
        config_ = dict(zip(names, values))
        points = None
        if m.joints:
            check_helical(m, config_, "drawMechanism")
        else:
            pos, _ = m.positions(R)
            points = {p: [_evaluate(x, values) for x in xyz] for p, xyz in pos.items()}
        scene = space_scene(m, config_, title, azim, elev, points)
    else:
        pos, _ = m.positions(R)
        xy = {p: _view([_evaluate(x, values) for x in xyz]) for p, xyz in pos.items()}
        scene = mechanism_scene(m, xy, title)
    _write(ctx, scene, path, f"{m} at {title}")
