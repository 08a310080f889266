"""Helpers of the pictures (:mod:`mech.stdlib.plots`, :mod:`mech.stdlib.plots_spatial`): the numerical
sampling of a variety, the colours, a title, reading a number."""
from __future__ import annotations

import math
import os
from fractions import Fraction
from typing import TYPE_CHECKING, Any, Callable, Sequence

from mech.dsl.convert import parse_decimal
from mech.dsl.errors import MechRuntimeError
from mech.kernel import Poly

if TYPE_CHECKING:
    from mech.stdlib._scene import Scene

# matplotlib's tab10 colours
COLOURS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
           "#bcbd22", "#17becf"]
MAX_SAMPLES = 100_000
TOLERANCE = 1e-9  # largest residual of a drawn point

# ---------------------------------------------------------------- sampling
def _rational(c: Any) -> float:
    return float(Fraction(int(c.p), int(c.q)))


def _numpy() -> Any:
    """numpy, with one BLAS thread unless the environment says otherwise (set before numpy's first
    import): the plots' many small batched solves gain nothing from threads, and starting and
    spinning them cost 0.3 s of a 0.6 s script here."""
    for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ.setdefault(var, "1")
    import numpy
    return numpy


def _compile(polys: Sequence[Poly], nvars: int) -> Callable[[Any], Any]:
    """The polynomials as one numpy function: an (N, nvars) array of points to the (N, len(polys))
    array of their values."""
    def term(e: tuple, c: Any) -> str:
        factors = [repr(_rational(c))] + [f"x{i}" if k == 1 else f"x{i}**{k}" for i, k in enumerate(e) if k]
        return "*".join(factors)
    exprs = ["zero + " + (" + ".join(term(e, c) for e, c in p.terms.items()) or "0.0") for p in polys]
    source = ("def f(x):\n    zero = np.zeros(len(x))\n"
              + "".join(f"    x{i} = x[:, {i}]\n" for i in range(nvars))
              + f"    return np.stack([{', '.join(exprs)}], axis=1)\n")
    np = _numpy()
    scope: dict[str, Any] = {"np": np}
    exec(compile(source, "<polynomials>", "exec"), scope)
    return scope["f"]


def sample_mode(prime: Sequence[Poly], nlinks: int, count: int = 3000, seed: int = 0,
                iterations: int = 40) -> Any:
    """Points of ``V(prime)`` of a planar mechanism whose first ``2 nlinks`` variables are the
    links' (cos, sin) pairs: :func:`sample` with those pairs."""
    return sample(prime, [(2 * i, 2 * i + 1) for i in range(nlinks)], count, seed, iterations)


def sample(prime: Sequence[Poly], pairs: Sequence[tuple[int, int]], count: int = 3000, seed: int = 0,
           iterations: int = 40) -> Any:
    """Points (rows of configuration-variable values) of ``V(prime)``: random angles for the
    (cos, sin) pairs of variables ``pairs`` (and values in [-2, 2] for the other variables) moved by
    minimum-norm Gauss–Newton steps in those parameters until the residual of every generator is
    below 1e-12 or ``iterations`` steps are done; only the points whose residual is below
    :data:`TOLERANCE` are returned."""
    np = _numpy()
    n = prime[0].ring.nvars
    k = len(pairs)
    cs, ss = [c for c, _ in pairs], [s for _, s in pairs]
    plain = [i for i in range(n) if i not in cs and i not in ss]
    gens = _compile(prime, n)
    jac = _compile([g.diff(j) for g in prime for j in range(n)], n)
    rng = np.random.default_rng(seed)
    params = np.column_stack([rng.uniform(-math.pi, math.pi, (count, k)),
                              rng.uniform(-2, 2, (count, n - 2 * k))])

    def point(p: Any) -> Any:
        x = np.empty((len(p), n))
        x[:, cs], x[:, ss] = np.cos(p[:, :k]), np.sin(p[:, :k])
        x[:, plain] = p[:, k:]
        return x

    active = np.arange(count)
    with np.errstate(all="ignore"):  # diverging points overflow
        for _ in range(iterations):
            x = point(params[active])
            res = gens(x)
            worst = np.abs(res).max(axis=1)
            moving = np.isfinite(worst) & (worst >= 1e-12)  # diverged points stop too
            active, x, res = active[moving], x[moving], res[moving]
            if not len(active):
                break
            dx = jac(x).reshape(len(x), len(prime), n)
            # chain rule: d/dtheta_i = -s_i d/dc_i + c_i d/ds_i
            jp = np.concatenate([dx[:, :, ss] * x[:, None, cs] - dx[:, :, cs] * x[:, None, ss],
                                 dx[:, :, plain]], axis=2)
            # (J^T J + eps I) step = J^T res: the minimum-norm step as eps -> 0
            jt = jp.transpose(0, 2, 1)
            normal = jt @ jp
            eps = 1e-12 * (1 + np.trace(normal, axis1=1, axis2=2))
            normal += eps[:, None, None] * np.eye(normal.shape[1])
            step = np.linalg.solve(normal, jt @ res[:, :, None])[:, :, 0]
            params[active] -= step
        x = point(params)
        return x[np.abs(gens(x)).max(axis=1) < TOLERANCE]


def _angles(x: Any, nlinks: int) -> Any:
    np = _numpy()
    return np.arctan2(x[:, 1:2 * nlinks:2], x[:, 0:2 * nlinks:2])


def _title(scene: Scene, text: str, centre: float) -> None:
    from mech.stdlib._scene import FONT, Text
    size = min(FONT, 2 * min(centre, scene.width - centre) / (0.62 * max(len(text), 1)))
    scene.add(Text(centre, 22, text, size, cls="title"))


def _thin(xy: Any) -> list:
    """The pixel positions ``xy`` (an (N, 2) array) keeping one per half pixel."""
    np = _numpy()
    _, first = np.unique(np.round(xy * 2), axis=0, return_index=True)
    return xy[np.sort(first)].tolist()


def _value(v: Any) -> float:
    if isinstance(v, int):
        return float(v)
    if isinstance(v, str):
        try:
            return float(parse_decimal(v))
        except (ValueError, OverflowError):
            pass
    raise MechRuntimeError(f"drawMechanism: '{v}' is not a number (integers or strings such as \"1/2\", \"0.25\")")


