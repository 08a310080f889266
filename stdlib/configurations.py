"""Sampled real configurations of a mechanism, mode by mode and circuit by circuit, as rows (for
Python), as a list (for scripts) or written to a CSV or JSON file (``LIB "mechanism.lib";``).

Each row is one configuration: its motion mode, its circuit, the configuration variables, each
link's angle ``theta_i`` and the joint angles a person reads (degrees, docs/mechanisms.md), and
the moving points' coordinates.  The points come from :func:`mech.stdlib.plots.sample_mode`
(random angles moved onto the mode by Gauss–Newton steps); a row is kept only when every
generator of the mode's prime and of ``J`` is below :data:`TOLERANCE` there.  Rigid (dimension 0)
modes give their real points exactly (:func:`mech.kernel.real_solve.real_solutions`), one circuit
each.

Circuits of a one-dimensional mode: their number is exact (:func:`mech.kernel.real_curve.curve_topology`);
the sampled points are split by the single-linkage tree of their distances, cut at its
``k - 1`` longest edges for ``k`` circuits.  Circuits are disjoint compact sets (or far apart
unbounded ones), so with dense samples the cut edges are far longer than the others; the split is
used only when each cut edge is at least :data:`GAP` times the longest edge kept, else the rows of
that mode have no circuit (0 in scripts, empty in CSV, null in JSON).
"""
from __future__ import annotations

import csv
import json
import math
from dataclasses import dataclass, field
from typing import Any, Optional

from mech.dsl.errors import MechRuntimeError
from mech.dsl.files import output_file
from mech.dsl.registry import command
from mech.dsl.values import List
from mech.stdlib.mechanism import Mechanism

TOLERANCE = 1e-9
#: How much longer than any kept edge the cut edges of the single-linkage tree must be.
GAP = 4.0
#: Starting points per mode for the circuit split (at least).
DENSE = 2000
#: Seconds of CPU time the exact circuit count of one mode may take.
CIRCUIT_BUDGET = 20.0
MAX_ROWS = 100_000


@dataclass
class Sampled:
    """The rows (dicts with :attr:`columns`), and per mode: ``number``, ``name``, ``dimension``,
    ``circuits`` (exact count, None if not known) and whether the rows' circuits are assigned."""

    mechanism: str
    columns: list[str]
    rows: list[dict[str, Any]] = field(default_factory=list)
    modes: list[dict[str, Any]] = field(default_factory=list)

    def data(self) -> dict[str, Any]:
        return {"mechanism": self.mechanism, "columns": self.columns, "modes": self.modes, "rows": self.rows}


def _columns(m: Mechanism, names: list[str], moving: list[str], joints: list[str]) -> list[str]:
    thetas = [f"theta{i}" for i in range(1, len(m.links) + 1) if f"c{i}" in names] if m.model.__name__.endswith(
        "planar") else []
    return (["mode", "circuit"] + names + thetas + [f"joint_{j}" for j in joints]
            + [f"{p}_{x}" for p in moving for x in "xyz"[:m.dim]])


def _tree_split(x: Any, k: int) -> Optional[list[int]]:
    """Labels 1..k of the points ``x`` (rows) from their single-linkage tree cut at its ``k - 1``
    longest edges, or None when the cut edges are not :data:`GAP` times longer than the rest."""
    import numpy as np
    n = len(x)
    if k == 1:
        return [1] * n
    if n < k:
        return None
    parent = np.full(n, -1)
    best = np.full(n, np.inf)
    inside = np.zeros(n, bool)
    inside[0] = True
    best[:] = np.linalg.norm(x - x[0], axis=1)
    parent[:] = 0
    edges = []
    for _ in range(n - 1):  # Prim's algorithm
        cand = np.where(inside, np.inf, best)
        j = int(np.argmin(cand))
        edges.append((float(cand[j]), int(parent[j]), j))
        inside[j] = True
        d = np.linalg.norm(x - x[j], axis=1)
        closer = d < best
        best[closer], parent[closer] = d[closer], j
    edges.sort()
    kept, cut = edges[:n - k], edges[n - k:]
    if kept and cut[0][0] < GAP * kept[-1][0]:
        return None
    root = list(range(n))

    def find(i: int) -> int:
        while root[i] != i:
            root[i] = root[root[i]]
            i = root[i]
        return i
    for _, a, b in kept:
        root[find(a)] = find(b)
    order: dict[int, int] = {}
    return [order.setdefault(find(i), len(order) + 1) for i in range(n)]


def _circuit_count(prime: list, ring: Any) -> Optional[int]:
    """The mode's exact circuit count (shared with the report), None when not known in the budget."""
    from mech.kernel.real_roots import RealSolvingError
    from mech.dsl.limits import within
    from mech.stdlib.circuit_counts import circuit_count, time_tried
    if time_tried(prime, ring) >= CIRCUIT_BUDGET:  # the report already ran out of this much time on it
        return None
    try:
        ok, n = within(CIRCUIT_BUDGET, circuit_count, prime, ring, True, cpu=True)
    except RealSolvingError:
        return None
    return n if ok else None


def circuit_split(prime: list, ring: Any, nlinks: int, count: int = DENSE, seed: int = 0
                  ) -> tuple[Any, Optional[list[int]], Optional[int]]:
    """Sampled points of the one-dimensional mode ``V(prime)`` (from ``count`` starts), their
    circuits 1..k (None when the split is not clear) and the exact number ``k`` of circuits (None
    when not computed)."""
    from mech.stdlib.plots import sample_mode
    x = sample_mode(prime, nlinks, count, seed=seed)
    k = _circuit_count(prime, ring)
    return x, _tree_split(x, k) if k else None, k


def _mode_points(md: Any, ring: Any, nlinks: int, count: int, seed: int) -> tuple[Any, list[int] | None, Optional[int]]:
    """Points of one mode, their circuits (None: not assigned) and the exact circuit count."""
    import numpy as np
    from mech.kernel.real_solve import real_solutions
    from mech.stdlib.plots import sample_mode
    if md.dim == 0:
        sols = real_solutions(md.prime, ring, 15).real
        x = np.array([[float(v.p) / float(v.q) for v in s.midpoint()] for s in sols]).reshape(len(sols), ring.nvars)
        return x, list(range(1, len(sols) + 1)), len(sols)
    if md.dim != 1:
        return _spread(sample_mode(md.prime, nlinks, max(DENSE, 4 * count), seed=seed), count), None, None
    x, labels, k = circuit_split(md.prime, ring, nlinks, max(DENSE, 4 * count), seed)
    if labels is None:
        return _spread(x, count), None, k
    parts, circuits = [], []
    for c in range(1, k + 1):  # the rows spread over the circuits, in proportion to their points
        mine = x[[i for i, lab in enumerate(labels) if lab == c]]
        parts.append(_spread(mine, max(1, round(count * len(mine) / len(x)))))
        circuits += [c] * len(parts[-1])
    return np.concatenate(parts), circuits, k


def _even(n: int, k: int) -> list[int]:
    return sorted({round(i * (n - 1) / max(k - 1, 1)) for i in range(min(k, n))}) if n else []


def _spread(x: Any, count: int) -> Any:
    """``count`` of the points ``x``, evenly spaced in the order of the first link's angle."""
    import numpy as np
    x = x[np.argsort(np.arctan2(x[:, 1], x[:, 0]) if x.shape[1] > 1 else x[:, 0])]
    return x[_even(len(x), count)]


def sample_configurations(m: Mechanism, count: int = 100, seed: int = 0) -> Sampled:
    """About ``count`` real configurations of each motion mode with real points of ``m`` (numeric
    lengths), with mode, circuit, variables, angles and points (see the module)."""
    import numpy as np
    from mech.stdlib.analysis import require_complete, require_numeric, run_analysis
    from mech.stdlib.mechanism_display import joint_readings
    from mech.stdlib.mode_names import mode_names
    from mech.stdlib.plots import _compile
    if not 0 < count <= MAX_ROWS:
        raise MechRuntimeError(f"the number of configurations per mode must be in 1..{MAX_ROWS}, not {count}")
    a = run_analysis(m, local=False)
    require_complete(a, "sampleConfigurations")
    require_numeric(a, "sampleConfigurations")
    if not a.modes:
        raise MechRuntimeError("sampleConfigurations: the motion modes are not known (the analysis did not finish)")
    R, n = a.ring, a.nvars
    names = list(R.names[:n])
    pos: dict[str, tuple] = {}
    if hasattr(m.model, "positions"):
        pos, _ = m.positions(R)
    moving = [p for p in m.points() if p in pos and p not in m.fixed]
    where = _compile([c for p in moving for c in pos[p]], n) if moving else None
    residual = _compile(list(a.ideal), n)
    labels = mode_names(a)
    out = Sampled(str(m), [])
    joints: list[str] = []
    for k, md in enumerate(a.modes, 1):
        entry = {"mode": k, "name": labels[k - 1].name if k <= len(labels) and labels[k - 1] else None,
                 "dimension": md.dim, "real_points": md.real, "circuits": None, "circuits_assigned": False}
        out.modes.append(entry)
        if md.real is False:
            continue
        x, circuits, total = _mode_points(md, R, len(m.links), count, seed=k)
        entry["circuits"], entry["circuits_assigned"] = total, circuits is not None
        if not len(x):
            continue
        good = np.abs(residual(x)).max(axis=1) < TOLERANCE
        xy = where(x) if where else np.zeros((len(x), 0))
        for i in np.flatnonzero(good):
            values = {v: float(t) for v, t in zip(names, x[i])}
            row: dict[str, Any] = {"mode": k, "circuit": circuits[i] if circuits else None, **values}
            if m.model.__name__.endswith("planar"):
                row.update({f"theta{j}": math.degrees(math.atan2(values[f"s{j}"], values[f"c{j}"]))
                            for j in range(1, len(m.links) + 1)})
            for name, value, angle in joint_readings(m, values):
                if angle:
                    row[f"joint_{name}"] = value
                    if name not in joints:
                        joints.append(name)
            row.update({f"{p}_{c}": float(xy[i][d * m.dim + j]) for d, p in enumerate(moving)
                        for j, c in enumerate("xyz"[:m.dim])})
            out.rows.append(row)
    out.columns = _columns(m, names, moving, joints)
    out.rows.sort(key=lambda r: (r["mode"], r["circuit"] or 0, r.get("theta1", r[names[0]])))
    return out


def write_configurations(s: Sampled, path: str) -> None:
    """``s`` as CSV (a header, one line per row, empty cells for no circuit) or JSON (by the
    name's ending), numbers with all their digits."""
    try:
        with open(path, "w", newline="") as f:
            if path.lower().endswith(".json"):
                json.dump(s.data(), f, indent=1)
                f.write("\n")
            else:
                w = csv.DictWriter(f, s.columns)
                w.writeheader()
                for r in s.rows:
                    w.writerow({c: "" if r.get(c) is None else repr(r[c]) if isinstance(r[c], float) else r[c]
                                for c in s.columns})
    except OSError as e:
        raise MechRuntimeError(f"'{path}': cannot write the file ({e.strerror or e})") from None


# ---------------------------------------------------------------- commands
@command("sampleConfigurations", lib="mechanism.lib")
def sample_configurations_command(m: Mechanism, count: int = 100) -> List:
    """sampleConfigurations(m[, n]): about n real configurations of each motion mode (default 100),
    each as list(mode, circuit, list of the variables' values as decimal strings); circuit 0 when
    the sampled points could not be split into the mode's circuits. A configuration can be given
    to drawMechanism and jointAngles.

    Example:
      LIB "mechanism.lib";
      mechanism m = "ground O A 5; bar O B 2; bar B C 5; bar C A 4";
      list L = sampleConfigurations(m, 10);
      size(L) >= 8;
      → 1
      L[1][1];
      → 1
      L[1][2];
      → 1
    """
    s = sample_configurations(m, count)
    names = m.variables()
    return List(List([r["mode"], r["circuit"] or 0, List([f"{r[v]:.15g}" for v in names])]) for r in s.rows)


@command("exportConfigurations", lib="mechanism.lib")
def export_configurations_command(m: Mechanism, path: str, count: int = 100) -> None:
    """exportConfigurations(m, "file.csv"[, n]): write about n real configurations of each motion
    mode (default 100) to a CSV or JSON file (by its ending): mode, circuit, the variables, the
    link angles theta_i and joint angles (degrees), the moving points' coordinates; where files may
    be written: docs/reliability.md, "Files".

    Example:
      LIB "mechanism.lib";
      mechanism m = "ground O A 5; bar O B 2; bar B C 5; bar C A 4";
      exportConfigurations(m, "/tmp/c.csv");
      → <stdin>:3:1: error: '/tmp/c.csv': give a path relative to the working directory (scripts write only inside it)
      → exportConfigurations(m, "/tmp/c.csv");
      → ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
    """
    output_file(path, (".csv", ".json"))
    write_configurations(sample_configurations(m, count), path)
