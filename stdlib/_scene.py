"""A neutral description of a picture (lines, marker groups, texts in pixel coordinates, y down) and
the chart layouts the plots build from it: plane axes, a 3-d axis box under a fixed oblique
orthographic projection, a legend.  ``_svg.py`` and ``_png.py`` render a :class:`Scene`."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Sequence, Union

Point = tuple[float, float]

FONT = 11.0  # px: tick labels, legend; titles and axis labels scale from it


@dataclass
class Lines:
    """Polylines sharing one style (``fill``: closed, filled polygons)."""

    lines: list[list[Point]]
    colour: str = "black"
    width: float = 1.0
    fill: str | None = None
    dash: bool = False
    round: bool = False  # round caps and joins
    cls: str = ""


@dataclass
class Markers:
    """One marker shape at many points: ``dot`` (filled disc), ``x``, ``circle``, ``triangle``, ``square``;
    ``size`` is the width and height (px)."""

    points: list[Point]
    shape: str
    size: float
    colour: str = "black"
    fill: str | None = None
    width: float = 1.0
    cls: str = ""


@dataclass
class Text:
    """``anchor``: start, middle or end of the text at ``(x, y)`` (the baseline); ``rotate``: 90 reads
    upwards."""

    x: float
    y: float
    text: str
    size: float = FONT
    anchor: str = "middle"
    rotate: int = 0
    cls: str = ""


Item = Union[Lines, Markers, Text]


@dataclass
class Scene:
    width: int
    height: int
    items: list[Item] = field(default_factory=list)

    def add(self, item: Item) -> Item:
        self.items.append(item)
        return item


# ---------------------------------------------------------------- ticks
def pi_ticks() -> list[tuple[float, str]]:
    """Ticks of an angle axis [-pi, pi]."""
    return [(k * math.pi / 2, label) for k, label in zip(range(-2, 3), ["−π", "−π/2", "0", "π/2", "π"])]


def nice_ticks(lo: float, hi: float, count: int = 6) -> list[tuple[float, str]]:
    """About ``count`` round values (1, 2 or 5 times a power of ten apart) in ``[lo, hi]``."""
    raw = (hi - lo) / max(count - 1, 1) or 1.0
    power = 10.0 ** math.floor(math.log10(raw))
    step = next(k * power for k in (1, 2, 5, 10) if k * power >= raw)
    digits = max(0, -math.floor(math.log10(step) + 1e-9))
    first = math.ceil(lo / step - 1e-9)
    out = []
    for k in range(first, math.floor(hi / step + 1e-9) + 1):
        label = f"{k * step:.{digits}f}".replace("-", "−")
        out.append((k * step, "0" if label.strip("−0.") == "" else label))
    return out


# ---------------------------------------------------------------- plane axes
@dataclass
class Axes2D:
    """Plane axes: data ``xrange`` x ``yrange`` onto the pixel box ``(left, top, right, bottom)``;
    ``equal`` widens one range so that both axes have the same scale."""

    box: tuple[float, float, float, float]
    xrange: tuple[float, float]
    yrange: tuple[float, float]
    equal: bool = False

    def __post_init__(self) -> None:
        left, top, right, bottom = self.box
        if self.equal:
            (x0, x1), (y0, y1) = self.xrange, self.yrange
            scale = max((x1 - x0) / (right - left), (y1 - y0) / (bottom - top))
            cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
            self.xrange = (cx - scale * (right - left) / 2, cx + scale * (right - left) / 2)
            self.yrange = (cy - scale * (bottom - top) / 2, cy + scale * (bottom - top) / 2)

    def map(self, x: float, y: float) -> Point:
        left, top, right, bottom = self.box
        (x0, x1), (y0, y1) = self.xrange, self.yrange
        return (left + (x - x0) / (x1 - x0) * (right - left), bottom - (y - y0) / (y1 - y0) * (bottom - top))

    def frame(self, scene: Scene, xticks: Sequence[tuple[float, str]], yticks: Sequence[tuple[float, str]],
              xlabel: str = "", ylabel: str = "") -> None:
        """The axes' frame, ticks with their labels (classes ``xtick``, ``ytick``) and axis labels."""
        left, top, right, bottom = self.box
        scene.add(Lines([[(left, top), (right, top), (right, bottom), (left, bottom), (left, top)]], cls="frame"))
        marks = []
        for v, label in xticks:
            x, _ = self.map(v, self.yrange[0])
            marks.append([(x, bottom), (x, bottom + 4)])
            scene.add(Text(x, bottom + 6 + FONT, label, cls="xtick"))
        for v, label in yticks:
            _, y = self.map(self.xrange[0], v)
            marks.append([(left - 4, y), (left, y)])
            scene.add(Text(left - 6, y + FONT * 0.35, label, anchor="end", cls="ytick"))
        scene.add(Lines(marks, cls="ticks"))
        if xlabel:
            scene.add(Text((left + right) / 2, bottom + 12 + 2.3 * FONT, xlabel, FONT * 1.2, cls="xlabel"))
        if ylabel:
            width = max((len(label) for _, label in yticks), default=1)
            scene.add(Text(left - 20 - 0.62 * FONT * width, (top + bottom) / 2, ylabel, FONT * 1.2, rotate=90,
                           cls="ylabel"))


# ---------------------------------------------------------------- the 3-d box
@dataclass
class Axes3D:
    """A 3-d axis box: ``ranges`` onto the cube [-1, 1]^3, seen from azimuth ``azim`` and elevation
    ``elev`` (degrees) by an orthographic projection, centred at ``centre`` with ``radius`` px for
    the cube's half side."""

    ranges: Sequence[tuple[float, float]]
    centre: Point
    radius: float
    azim: float = -55.0
    elev: float = 22.0

    def _unit(self, p: Sequence[float]) -> list[float]:
        return [2 * (v - lo) / (hi - lo) - 1 for v, (lo, hi) in zip(p, self.ranges)]

    def _view(self) -> tuple[tuple[float, ...], tuple[float, ...], tuple[float, ...]]:
        a, e = math.radians(self.azim), math.radians(self.elev)
        right = (-math.sin(a), math.cos(a), 0.0)
        up = (-math.sin(e) * math.cos(a), -math.sin(e) * math.sin(a), math.cos(e))
        towards = (math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e))
        return right, up, towards

    def project(self, p: Sequence[float]) -> Point:
        """The pixel position of the data point ``p`` (coordinates may be numpy arrays: columns of points)."""
        u = self._unit(p)
        right, up, _ = self._view()
        # the cube's diagonal is sqrt(3): scale so that the whole box fits in the radius
        k = self.radius / math.sqrt(3)
        return (self.centre[0] + k * sum(a * b for a, b in zip(right, u)),
                self.centre[1] - k * sum(a * b for a, b in zip(up, u)))

    def _corner(self, signs: Sequence[int]) -> list[float]:
        return [lo if s < 0 else hi for s, (lo, hi) in zip(signs, self.ranges)]

    def frame(self, scene: Scene, ticks: Sequence[Sequence[tuple[float, str]]], labels: Sequence[str]) -> None:
        """Grid lines on the three back faces, the box's edges, and for each axis ticks, tick labels
        (classes ``tick1``.. ``tick3``) and its label on a front edge."""
        towards = self._view()[2]
        back = [-1 if t > 0 else 1 for t in towards]  # the far value of each coordinate
        grid = []
        for k in range(3):  # the back face where coordinate k is at its far end
            for j in range(3):
                if j == k:
                    continue
                free = 3 - j - k
                for v, _ in ticks[j]:
                    a, b = [0.0] * 3, [0.0] * 3
                    a[k] = b[k] = self._corner(back)[k]
                    a[j] = b[j] = v
                    a[free], b[free] = self.ranges[free]
                    grid.append([self.project(a), self.project(b)])
        scene.add(Lines(grid, colour="#dddddd", width=0.8, cls="grid"))
        edges = []
        for k in range(3):
            for s1 in (-1, 1):
                for s2 in (-1, 1):
                    signs = [s1, s2]
                    signs.insert(k, -1)
                    a = self._corner(signs)
                    signs[k] = 1
                    edges.append([self.project(a), self.project(self._corner(signs))])
        scene.add(Lines(edges, colour="#888888", width=0.8, cls="box"))
        marks = []
        for k in range(3):
            edge = self._axis_edge(k, back)
            for v, label in ticks[k]:
                p = list(edge)
                p[k] = v
                x, y = self.project(p)
                dx, dy = self._outwards(edge, k)
                marks.append([(x, y), (x + 5 * dx, y + 5 * dy)])
                anchor = "end" if dx < -0.2 else "start" if dx > 0.2 else "middle"
                scene.add(Text(x + 9 * dx, y + 9 * dy + FONT * (0.35 + 0.5 * dy), label, anchor=anchor,
                               cls=f"tick{k + 1}"))
            mid = list(edge)
            mid[k] = sum(self.ranges[k]) / 2
            x, y = self.project(mid)
            dx, dy = self._outwards(edge, k)
            scene.add(Text(x + 36 * dx, y + 36 * dy + FONT * 0.4, labels[k], FONT * 1.2, cls=f"label{k + 1}"))
        scene.add(Lines(marks, cls="ticks"))

    def _axis_edge(self, k: int, back: Sequence[int]) -> list[float]:
        """A point on the edge parallel to axis ``k`` that carries its ticks: for the horizontal
        axes the lowest bottom edge in front, for the vertical axis the left-most edge."""
        signs = [0, 0, 0]
        if k < 2:
            signs[2] = -1
            signs[1 - k] = -back[1 - k]
        else:
            options = [(s0, s1) for s0 in (-1, 1) for s1 in (-1, 1) if (s0, s1) != (back[0], back[1])]
            signs[0], signs[1] = min(options, key=lambda s: self.project(self._corner([s[0], s[1], 0]))[0])
        return self._corner(signs)

    def _outwards(self, edge: Sequence[float], k: int) -> Point:
        """The unit screen direction from the box's centre line to ``edge``, across the axis."""
        a, b = list(edge), list(edge)
        a[k], b[k] = self.ranges[k]
        (x0, y0), (x1, y1) = self.project(a), self.project(b)
        ex, ey = x1 - x0, y1 - y0
        norm = math.hypot(ex, ey) or 1.0
        nx, ny = -ey / norm, ex / norm
        mx, my = (x0 + x1) / 2 - self.centre[0], (y0 + y1) / 2 - self.centre[1]
        return (nx, ny) if nx * mx + ny * my >= 0 else (-nx, -ny)


# ---------------------------------------------------------------- legend
def legend(scene: Scene, x: float, y: float, entries: Sequence[tuple[Markers, str]]) -> None:
    """A framed legend with its top left corner at ``(x, y)``: each entry's marker style and label."""
    row = FONT * 1.5
    width = 30 + 0.6 * FONT * max((len(label) for _, label in entries), default=0)
    height = row * len(entries) + 6
    scene.add(Lines([[(x, y), (x + width, y), (x + width, y + height), (x, y + height)]], colour="#cccccc",
                    fill="white", cls="legend"))
    for i, (style, label) in enumerate(entries):
        cy = y + 3 + row * (i + 0.5)
        size = max(style.size, 6.0) if style.shape == "dot" else style.size
        scene.add(Markers([(x + 12, cy)], style.shape, size, style.colour, style.fill, style.width, "legend"))
        scene.add(Text(x + 24, cy + FONT * 0.35, label, anchor="start", cls="legend"))
