"""Pictures of configuration spaces and mechanisms (matplotlib, Agg backend, PNG/SVG files).

Configuration spaces are drawn in angle coordinates ``theta_i = atan2(s_i, c_i)`` like the
paper's Figures 2 and 4: a plane picture for two links, a 3-d picture of the first three angles
otherwise.  Points of each motion mode are found numerically: random angles are projected onto
the mode's variety by Gauss–Newton steps (minimum-norm, on the prime's generators with
``c_i = cos theta_i``, ``s_i = sin theta_i``); only points whose residual is below 1e-9 are drawn.
Each mode has its own colour; the singular configurations are marked."""
from __future__ import annotations

import math
import os
from fractions import Fraction
from typing import Any, Callable, Sequence

from mech.dsl.errors import MechRuntimeError
from mech.dsl.values import List
from mech.kernel import Poly
from mech.stdlib.analysis import require_numeric, run_analysis
from mech.stdlib.mechanism import Mechanism
from mech.stdlib.registry import command

COLOURS = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink"]


def _pyplot() -> Any:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def _numeric_poly(p: Poly) -> Callable[[Any], Any]:
    """``p`` as a function of an array of points (one row per point)."""
    terms = [(float(c.p) / float(c.q), e) for e, c in p.terms.items()]

    def f(x: Any) -> Any:
        import numpy as np
        out = np.zeros(x.shape[0])
        for c, e in terms:
            t = np.full(x.shape[0], c)
            for i, k in enumerate(e):
                if k:
                    t = t * x[:, i] ** k
            out = out + t
        return out
    return f


def sample_mode(prime: Sequence[Poly], nlinks: int, count: int = 3000, seed: int = 0) -> Any:
    """Points (rows of configuration-variable values) of ``V(prime)``: random angles projected by
    Gauss–Newton steps; only converged points are kept."""
    import numpy as np
    ring = prime[0].ring
    n = ring.nvars
    gens = [_numeric_poly(g) for g in prime]
    jac = [[_numeric_poly(g.diff(j)) for j in range(n)] for g in prime]
    rng = np.random.default_rng(seed)
    # parameters: one angle per link, then the other (prismatic) variables
    theta = rng.uniform(-math.pi, math.pi, (count, nlinks))
    rest = rng.uniform(-2, 2, (count, n - 2 * nlinks))

    def point(th: Any, r: Any) -> Any:
        cols = []
        for i in range(nlinks):
            cols += [np.cos(th[:, i]), np.sin(th[:, i])]
        return np.column_stack(cols + [r[:, j] for j in range(r.shape[1])])

    for _ in range(40):
        x = point(theta, rest)
        res = np.column_stack([g(x) for g in gens])
        dx = np.stack([np.column_stack([d(x) for d in row]) for row in jac], axis=1)  # (N, m, n)
        # chain rule to the parameters
        cols = []
        for i in range(nlinks):
            cols.append(-dx[:, :, 2 * i] * x[:, None, 2 * i + 1] + dx[:, :, 2 * i + 1] * x[:, None, 2 * i])
        cols += [dx[:, :, 2 * nlinks + j] for j in range(n - 2 * nlinks)]
        jp = np.stack(cols, axis=2)
        step = np.einsum("nij,nj->ni", np.linalg.pinv(jp, rcond=1e-10), res)
        theta = theta - step[:, :nlinks]
        rest = rest - step[:, nlinks:]
    x = point(theta, rest)
    res = np.abs(np.column_stack([g(x) for g in gens])).max(axis=1)
    return x[res < 1e-9]


def _angles(x: Any, nlinks: int) -> Any:
    import numpy as np
    return np.column_stack([np.arctan2(x[:, 2 * i + 1], x[:, 2 * i]) for i in range(nlinks)])


def _check_path(path: str) -> str:
    if not path.lower().endswith((".png", ".svg")):
        raise MechRuntimeError(f"'{path}': give a file name ending in .png or .svg")
    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):
        raise MechRuntimeError(f"'{path}': the folder {folder} does not exist")
    return path


@command("plotConfigurations", lib="mechanism.lib")
def plot_configurations(m: Mechanism, path: str, count: int = 3000) -> None:
    """plotConfigurations(m, "file.png"[, samples]): the configuration space in angle coordinates,
    one colour per motion mode, singular configurations marked.

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A 1; bar A B 1; slider B";
      plotConfigurations(m, "modes.pdf");
      → <stdin>:3:1: error: 'modes.pdf': give a file name ending in .png or .svg
      → plotConfigurations(m, "modes.pdf");
      → ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
    """
    import numpy as np
    _check_path(path)
    a = run_analysis(m)
    require_numeric(a, "plotConfigurations")
    nlinks = len(m.links)
    if nlinks < 2:
        raise MechRuntimeError("plotConfigurations needs at least two links")
    plt = _pyplot()
    fig = plt.figure(figsize=(6, 5))
    ax = fig.add_subplot(111, projection="3d" if nlinks >= 3 else None)
    dims = min(nlinks, 3)
    for i, mode in enumerate(a.modes, 1):
        if not mode.real:
            continue
        th = _angles(sample_mode(mode.prime, nlinks, count, seed=i), nlinks)
        ax.scatter(*(th[:, k] for k in range(dims)), s=2, color=COLOURS[(i - 1) % len(COLOURS)],
                   label=f"mode {i} (dim {mode.dim})")
    sing = [s.point for s in a.singular if s.point is not None]
    if sing:
        pts = np.array([[float(Fraction(int(c.p), int(c.q))) for c in p] for p in sing])
        th = _angles(pts, nlinks)
        ax.scatter(*(th[:, k] for k in range(dims)), s=60, color="black", marker="x",
                   label="singular configurations", depthshade=False) if dims == 3 else \
            ax.scatter(th[:, 0], th[:, 1], s=60, color="black", marker="x", label="singular configurations")
    ax.set_xlabel(r"$\theta_1$")
    ax.set_ylabel(r"$\theta_2$")
    if dims == 3:
        ax.set_zlabel(r"$\theta_3$")
    ax.legend(loc="upper left", fontsize=7)
    ax.set_title(str(m), fontsize=7)
    fig.savefig(path)
    plt.close(fig)


def _value(v: Any) -> float:
    if isinstance(v, int):
        return float(v)
    if isinstance(v, str):
        try:
            return float(Fraction(v))
        except ValueError:
            pass
    raise MechRuntimeError(f"drawMechanism: '{v}' is not a number (integers or strings such as \"1/2\", \"0.25\")")


@command("drawMechanism", lib="mechanism.lib")
def draw_mechanism(m: Mechanism, config: List, path: str) -> None:
    """drawMechanism(m, list(c1,s1,c2,s2,...), "file.svg"): the mechanism in that configuration.

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A 1; bar A B 1; slider B";
      drawMechanism(m, list(0, 1), "m.svg");
      → <stdin>:3:1: error: drawMechanism: 4 values expected (c1,s1,c2,s2), 2 given
      → drawMechanism(m, list(0, 1), "m.svg");
      → ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
    """
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
    bad = max(abs(float(_evaluate(g, values))) for g in gens)
    if bad > 1e-6:
        raise MechRuntimeError(f"drawMechanism: the values are not a configuration (a constraint is {bad:.3g})")
    pos, _ = m.positions(R)
    xy = {p: (float(_evaluate(x, values)), float(_evaluate(y, values))) for p, (x, y) in pos.items()}
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(5, 4))
    for link in m.links:
        pts = [xy[p] for p in link.points]
        if len(pts) > 2:
            pts = pts + pts[:1]
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "-", lw=3, color="tab:blue", solid_capstyle="round")
    for s in m.sliders:
        a, b, c = (float(Fraction(t)) if not isinstance(t, str) else 0.0 for t in s.line)
        px, py = xy[s.point]
        dx, dy = (b, -a) if (a, b) != (0, 0) else (1, 0)
        span = max(1.0, max(abs(u) + abs(v) for u, v in xy.values()))
        ax.plot([px - span * dx, px + span * dx], [py - span * dy, py + span * dy], "--", color="grey", lw=1)
        ax.plot([px], [py], "s", ms=12, mfc="none", color="tab:red")
    for p, (x, y) in xy.items():
        fixed = p in m.fixed
        ax.plot([x], [y], "^" if fixed else "o", ms=10 if fixed else 6,
                color="black" if fixed else "white", mec="black")
        ax.annotate(p, (x, y), textcoords="offset points", xytext=(5, 5))
    ax.set_aspect("equal")
    ax.margins(0.2)
    ax.set_title(", ".join(f"{n}={v:.3g}" for n, v in zip(names, values)), fontsize=7)
    fig.savefig(path)
    plt.close(fig)


def _evaluate(p: Poly, values: Sequence[float]) -> float:
    return sum(float(Fraction(int(c.p), int(c.q))) * math.prod(v ** k for v, k in zip(values, e))
               for e, c in p.terms.items())
