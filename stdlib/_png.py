"""A :class:`~mech.stdlib._scene.Scene` as a PNG file, drawn by matplotlib (Agg, no pyplot) on axes
covering the whole figure in the scene's pixel coordinates."""
from __future__ import annotations

from mech.stdlib._scene import Lines, Markers, Scene, Text

DPI = 100
PT = 72 / DPI  # points per pixel
_SHAPES = {"dot": "o", "x": "x", "circle": "o", "triangle": "^", "square": "s"}


def write_png(scene: Scene, path: str) -> None:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.collections import LineCollection, PolyCollection
    from matplotlib.figure import Figure

    fig = Figure(figsize=(scene.width / DPI, scene.height / DPI), dpi=DPI)
    FigureCanvasAgg(fig)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, scene.width)
    ax.set_ylim(scene.height, 0)
    ax.set_axis_off()
    for z, item in enumerate(scene.items):
        if isinstance(item, Lines):
            style = dict(edgecolors=item.colour, linewidths=item.width * PT, zorder=z,
                         linestyles=(0, (6, 4)) if item.dash else "solid",
                         capstyle="round" if item.round else "butt", joinstyle="round" if item.round else "miter")
            if item.fill:
                ax.add_collection(PolyCollection(item.lines, facecolors=item.fill, **style))
            else:
                style["colors"] = style.pop("edgecolors")
                ax.add_collection(LineCollection(item.lines, **style))
        elif isinstance(item, Markers):
            if not len(item.points):
                continue
            xs, ys = zip(*item.points)
            dot = item.shape == "dot"
            ax.plot(xs, ys, linestyle="none", marker=_SHAPES[item.shape], ms=item.size * PT, zorder=z,
                    mfc=item.colour if dot else (item.fill or "none"), mec="none" if dot else item.colour,
                    mew=item.width * PT)
        elif isinstance(item, Text):
            ax.text(item.x, item.y, item.text, fontsize=item.size * PT, ha={"start": "left", "middle": "center",
                    "end": "right"}[item.anchor], va="baseline", rotation=item.rotate, rotation_mode="anchor",
                    zorder=z)
    fig.savefig(path, dpi=DPI)
