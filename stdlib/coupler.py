"""Coupler curves: the path a named point of a mechanism traces, as an implicit equation and as a
picture (``LIB "mechanism.lib";``).

The point's coordinates ``(X, Y)`` are polynomials in the configuration variables
(:meth:`Mechanism.positions`); its path is the projection of the configuration space, so its
Zariski closure is ``V(E)`` with ``E = (J + <x - X, y - Y>) ∩ Q[x, y]`` (elimination of the
configuration variables). For a one-degree-of-freedom mechanism ``E`` is principal: for a four-bar's
coupler point a sextic, tricircular (its top-degree part is a multiple of ``(x^2 + y^2)^3``;
Roberts 1875; Hunt, *Kinematic geometry of mechanisms*, ch. 7). The picture samples each real motion
mode numerically (:func:`mech.stdlib.plots.sample_mode`) and draws the point's positions over the
mechanism in one configuration.
"""
from __future__ import annotations

from typing import Any

from mech.dsl.errors import MechRuntimeError
from mech.dsl.registry import command
from mech.kernel import QQ, Block, MonomialOrder, Poly, PolyRing
from mech.kernel.ideals import eliminate
from mech.stdlib.mechanism import Mechanism, MechanismError
from mech.stdlib.standard import normalize

#: The names of the plane's coordinates in the curve's ring.
XY = ("x", "y")


def _tracer(m: Mechanism, point: str, cmd: str) -> None:
    if m.symbols():
        raise MechRuntimeError(f"{cmd} needs numeric lengths (setLengths(m, ...) for {','.join(m.symbols())})")
    if point not in m.points():
        raise MechRuntimeError(f"{cmd}: the mechanism has no point {point} (its points: {', '.join(m.points())})")
    if point in m.fixed:
        raise MechRuntimeError(f"{cmd}: {point} is fixed: it traces no curve")


def coupler_curve(m: Mechanism, point: str) -> list[Poly]:
    """The elimination ideal ``(J + <x - X, y - Y>) ∩ Q[x, y]`` of the path of ``point`` (in the ring
    ``QQ[x, y]``, dp), generators with coprime integer coefficients: one polynomial for a
    one-degree-of-freedom mechanism, ``[]`` when the point sweeps a region."""
    _tracer(m, point, "couplerCurve")
    try:
        R0, J = m.constraints()
    except MechanismError as e:
        raise MechRuntimeError(str(e)) from None
    n = R0.nvars
    clash = [v for v in XY if v in R0.names]
    if clash:
        raise MechRuntimeError(f"couplerCurve: the mechanism already has a variable {clash[0]}")
    R = PolyRing(QQ, list(R0.names) + list(XY), MonomialOrder([Block("dp", n), Block("dp", 2)]))
    lift = lambda p: Poly(R, {e + (0, 0): c for e, c in p.terms.items()})  # noqa: E731
    pos, _ = m.positions(R0)
    X, Y = (lift(c) for c in pos[point])
    x, y = R.gens()[n:]
    E = eliminate([lift(g) for g in J] + [x - X, y - Y], list(range(n)), R)
    plane = PolyRing(QQ, list(XY), MonomialOrder([Block("dp", 2)]))
    return [normalize(Poly(plane, {e[n:]: c for e, c in g.terms.items()})) for g in E if not g.is_zero()]


def coupler_path(m: Mechanism, point: str, count: int = 3000) -> Any:
    """Points ``(x, y)`` (a numpy array) of the path of ``point``, sampled on every real motion mode;
    also the configurations they come from."""
    from mech.stdlib.analysis import require_complete, run_analysis
    from mech.stdlib.plots import _compile, _numpy, sample_mode
    np = _numpy()
    a = run_analysis(m, local=False)
    require_complete(a, "plotCouplerCurve")  # a time limit's partial analysis may lack modes
    pos, _ = m.positions(a.ring)
    where = _compile(list(pos[point]), a.ring.nvars)
    found = [sample_mode(md.prime, len(m.links), count, seed=i) for i, md in enumerate(a.modes, 1) if md.real]
    configs = np.concatenate(found) if found else np.zeros((0, a.ring.nvars))
    return where(configs), configs


# ---------------------------------------------------------------- commands
@command("couplerCurve", lib="mechanism.lib")
def coupler_curve_command(ctx: Any, m: Mechanism, point: str) -> Poly:
    """couplerCurve(m, "F"): the implicit equation of the path of the point F, in the variables x, y
    of the basering: the configuration variables eliminated from J + <x - F_x, y - F_y> (a sextic
    for a coupler point of a four-bar).

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A 1; bar A B 2; slider B";
      ring r = 0,(x,y),dp;
      couplerCurve(m, "A");
      → x2+y2-1
      couplerCurve(m, "B");
      → y
    """
    ring = ctx.basering().poly
    missing = [v for v in XY if v not in ring.names]
    if missing:
        raise MechRuntimeError("couplerCurve: the basering needs the variables x and y (ring r = 0,(x,y),dp;)")
    E = coupler_curve(m, point)
    if len(E) != 1:
        what = "it sweeps a region" if not E else f"its ideal has {len(E)} generators"
        raise MechRuntimeError(f"couplerCurve: the path of {point} is not a plane curve ({what})")
    from mech.kernel.maps import imap
    return imap(E, E[0].ring, ring)[0]


@command("plotCouplerCurve", lib="mechanism.lib")
def plot_coupler_curve(ctx: Any, m: Mechanism, point: str, path: str, count: int = 3000) -> None:
    """plotCouplerCurve(m, "F", "file.svg"[, samples]): the path of the point F (sampled on each
    real motion mode from `samples` random starting configurations, default 3000) over the mechanism
    in one of its configurations. The file is SVG or PNG by its name's ending.

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O; bar O A 1; bar A B 2; slider B";
      plotCouplerCurve(m, "O", "path.svg");
      → <stdin>:3:1: error: plotCouplerCurve: O is fixed: it traces no curve
      → plotCouplerCurve(m, "O", "path.svg");
      → ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
    """
    from mech.stdlib.plots import MAX_SAMPLES, _check_path, _compile, _write, mechanism_scene
    _tracer(m, point, "plotCouplerCurve")
    _check_path(path)
    if not 0 < count <= MAX_SAMPLES:
        raise MechRuntimeError(f"plotCouplerCurve: the number of samples must be in 1..{MAX_SAMPLES}, not {count}")
    xy, configs = coupler_path(m, point, count)
    if not len(configs):
        raise MechRuntimeError("plotCouplerCurve: no real configuration found")
    R, _ = m.constraints()
    pos, _ = m.positions(R)
    names = list(pos)
    at = _compile([c for p in names for c in pos[p]], R.nvars)(configs[:1])[0]
    joints = {p: (float(at[2 * i]), float(at[2 * i + 1])) for i, p in enumerate(names)}
    title = f"path of {point}"
    _write(ctx, mechanism_scene(m, joints, title, xy.tolist()), path, f"{title}: {m}")
