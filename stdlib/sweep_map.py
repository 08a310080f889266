"""The picture of a two-parameter sweep: a map of the design plane coloured by one answer, with
the exact length conditions (where the singular configurations appear, so where counts may
change) drawn on top as curves (PNG or SVG, matplotlib's Agg canvas, no pyplot)."""
from __future__ import annotations

from fractions import Fraction
from typing import Any, Sequence

from mech.dsl.errors import MechRuntimeError

# matplotlib's tab10 colours; errors grey
COLOURS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#bcbd22",
           "#17becf", "#7f7f7f"]
ERROR = "#d9d9d9"

Terms = dict[tuple[int, ...], Fraction]


def _float(v: Any) -> float:
    return float(Fraction(str(v)))


def _key(v: Any) -> tuple:
    return (0, v, "") if isinstance(v, (int, float)) else (1, 0, str(v))


def draw_map(rows: Sequence[dict[str, Any]], x: str, y: str, answer: str, path: str,
             curves: Sequence[tuple[str, Terms]] = (), title: str = "") -> None:
    """Write the map of ``answer`` over the designs' ``x`` and ``y`` to ``path`` (.png or .svg);
    ``curves``: (label, polynomial in (x, y)) pairs drawn where they vanish."""
    if not rows:
        raise MechRuntimeError("sweepMap: the table has no rows")
    for c in (x, y, answer):
        if c not in rows[0]:
            raise MechRuntimeError(f"sweepMap: the table has no column '{c}' (it has {', '.join(rows[0])})")
    import numpy as np
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from matplotlib.patches import Patch
    values = [r[answer] if r[answer] != "" else "error" for r in rows]
    kinds = sorted({v for v in values if v != "error"}, key=_key) + (["error"] if "error" in values else [])
    from mech.stdlib.grashof import KINDS  # Grashof types keep their colours from map to map
    slot = {k: KINDS.index(k) if answer == "grashof" and k in KINDS else i for i, k in enumerate(kinds)}
    colour = {k: (ERROR if k == "error" else COLOURS[slot[k] % len(COLOURS)]) for k in kinds}
    xs = np.array([_float(r[x]) for r in rows])
    ys = np.array([_float(r[y]) for r in rows])
    fig = Figure(figsize=(6.4, 5.2))
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    ux, uy = np.unique(xs), np.unique(ys)
    if len(ux) * len(uy) == len(rows) and len(ux) > 1 and len(uy) > 1:  # a grid: one cell a design
        from matplotlib.colors import ListedColormap
        index = {k: i for i, k in enumerate(kinds)}
        grid = np.zeros((len(uy), len(ux)))
        for xv, yv, v in zip(xs, ys, values):
            grid[np.searchsorted(uy, yv), np.searchsorted(ux, xv)] = index[v]
        ax.pcolormesh(_edges(ux), _edges(uy), grid, cmap=ListedColormap([colour[k] for k in kinds]),
                      vmin=-0.5, vmax=len(kinds) - 0.5, shading="flat")
    else:
        ax.scatter(xs, ys, c=[colour[v] for v in values], s=12, marker="s", linewidths=0)
    _curves(ax, curves, (xs.min(), xs.max()), (ys.min(), ys.max()))
    ax.set_xlim(*_span(xs)), ax.set_ylim(*_span(ys))
    ax.set_xlabel(x), ax.set_ylabel(y)
    ax.set_title(title or f"{answer} over ({x}, {y})")
    ax.legend(handles=[Patch(color=colour[k], label=str(k)) for k in kinds], loc="upper left",
              bbox_to_anchor=(1.01, 1), fontsize="small", title=answer)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def _edges(u: Any) -> Any:
    import numpy as np
    mid = (u[1:] + u[:-1]) / 2
    return np.concatenate([[u[0] - (mid[0] - u[0])], mid, [u[-1] + (u[-1] - mid[-1])]])


def _span(v: Any) -> tuple[float, float]:
    lo, hi = float(v.min()), float(v.max())
    pad = (hi - lo) / 50 or 0.5
    return lo - pad, hi + pad


def _curves(ax: Any, curves: Sequence[tuple[str, Terms]], xr: tuple, yr: tuple) -> None:
    """The zero sets of the conditions, as contours of their values on a fine mesh."""
    import numpy as np
    if not curves:
        return
    gx, gy = np.meshgrid(np.linspace(*_span(np.array(xr)), 400), np.linspace(*_span(np.array(yr)), 400))
    for label, terms in curves:
        z = sum(float(c) * gx ** e[0] * gy ** e[1] for e, c in terms.items())
        if isinstance(z, np.ndarray) and z.min() < 0 < z.max():
            ax.contour(gx, gy, z, levels=[0], colors="black", linewidths=0.8)
