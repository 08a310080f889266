"""The real answers of a mechanism's report (docs/mechanisms.md, "Real answers"): what a
kinematician reads, computed exactly with :mod:`mech.kernel.real_solve`, ``real_curve`` and
``real_branches`` (docs/real.md).

* ``assembly_modes`` (mobility 0): the numbers of distinct complex and real configurations and
  the real poses (joint points and configuration, certified decimals);
* ``real_circuits``: for each one-dimensional motion mode the number of circuits (connected
  pieces of its real points: the linkage moves through one circuit without disassembly);
* ``grashof``: the Grashof class of a four-bar (:mod:`mech.stdlib.grashof`);
* ``real_branches``: at each singular configuration that is a point, the real branches through it,
  their tangent directions and the type (node: branches cross and the linkage can switch; cusp;
  isolated real configuration; ...);
* ``input_output`` for a four-bar: crank to rocker mode by mode (and circuit by circuit), the
  rocker's range and limit positions, the crank's dead centres, the transmission angle, a link
  frozen on a mode said so (:mod:`mech.stdlib.input_output`).

The steps share a time budget (:data:`BUDGET` seconds of CPU time for all of them, so that a busy
machine does not change the report, and never beyond the statement's own time limit); a step over
budget is reported as such instead of holding up the report. The report
formats (:mod:`mech.stdlib.reports`) call :func:`real_sections` once per analysis.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any, Callable

from mech.dsl.limits import REPORT_KEEP, cut, remaining
from mech.dsl.limits import within as limited
from mech.kernel import Poly
from mech.kernel.real_roots import RealSolvingError
from mech.stdlib.analysis import Analysis, mode_generators, relaxed_gc
from mech.stdlib.grashof import four_bar

#: Seconds of CPU time the real steps of one report may take together (besides the statement's time
#: limit, which is wall-clock time).
BUDGET = 30.0
#: Digits after the point of the decimals in the report.
DIGITS = 4

_TYPES = {
    "node": "{n} real branches cross: the linkage can switch from one to another here",
    "tacnode": "{n} real branches touch (a common tangent): the linkage can switch from one to another here",
    "cusp": "a cusp: one real branch that turns back (the motion reverses here)",
    "isolated": "an isolated real configuration: the linkage is rigid here and cannot move",
    "regular": "one real branch through a smooth point",
    "singular": "one real branch through a singular point",
}


@dataclass
class RealSections:
    """The real answers of one analysis: ``data`` under the JSON report's keys, ``lines`` for the
    text report."""

    data: dict[str, Any] = field(default_factory=dict)
    lines: list[str] = field(default_factory=list)
    deadline: float = field(default_factory=lambda: time.thread_time() + BUDGET, repr=False)  # CPU clock
    cut: bool = field(default=False, repr=False)  # a step stopped by the statement's time limit


def within(seconds: float, fn: Callable[..., Any], *args: Any) -> tuple[bool, Any]:
    """``(True, fn(*args))``, or ``(False, None)`` when it takes more than ``seconds`` of CPU time
    (this thread's: :func:`mech.dsl.limits.within` with ``cpu``) or longer than the statement's
    time limit allows (keeping ``REPORT_KEEP`` seconds for the rest of the report,
    also when one long call outlasts both: :func:`mech.dsl.limits.within`)."""
    seconds = cut(seconds, REPORT_KEEP)
    if seconds <= 0:
        return False, None
    return limited(seconds, fn, *args, cpu=True, reserve=REPORT_KEEP)


def _step(sec: RealSections, what: str, fn: Callable[..., Any], *args: Any) -> Any:
    """Run one step under the budget; None (and a note in the report) when it is over budget or
    the exact methods refuse the input."""
    try:
        ok, value = within(sec.deadline - time.thread_time(), fn, *args)
    except RealSolvingError as e:
        sec.lines.append(f"  {what}: not computed ({e})")
        sec.data.setdefault("real_notes", []).append(f"{what}: {e}")
        return None
    if not ok:
        sec.cut = remaining() is not None
        budget = "the statement's time limit" if sec.cut else f"the real answers' budget of {BUDGET:g} s of CPU time"
        sec.lines.append(f"  {what}: too expensive, not computed (over {budget})")
        sec.data.setdefault("real_notes", []).append(f"{what}: over budget")
        return None
    return value


# ---------------------------------------------------------------- the steps
def _rounded_boxes(rep: Any, roots: list, polys: list[Poly], digits: int) -> list[list[str]]:
    """``polys`` at the real solutions ``roots`` of ``rep``, correctly rounded to ``digits``."""
    from mech.kernel.real_solve import decimal, shape_representation, solution_boxes
    from flint import fmpq
    image = shape_representation(rep.poly, [rep.value(p) for p in polys])
    for extra in (2, 8, 24):
        boxes = [b for _, b in solution_boxes(image, roots, fmpq(1, 10 ** (digits + extra)))]
        if all(decimal(lo, digits) == decimal(hi, digits) for box in boxes for lo, hi in box):
            break
    return [[decimal((lo + hi) / 2, digits) for lo, hi in box] for box in boxes]


def assembly_modes(a: Analysis, digits: int = DIGITS) -> dict[str, Any]:
    """Mobility 0: ``complex`` and ``real`` counts of the distinct configurations, and ``poses``:
    for each real one the moving joint points and the configuration, as decimals."""
    from mech.kernel.real_solve import real_solutions
    finite = getattr(a, "finite", None)  # the zero-dimensional analysis computed them already
    sols = finite.solutions if finite is not None and digits == finite.digits else real_solutions(a.ideal, a.ring, digits)
    rep = sols.representation
    roots = [s.root for s in sols.real]
    moving: list[str] = []
    pos: dict[str, tuple[Poly, ...]] = {}
    if hasattr(a.mechanism.model, "positions"):       # points (planar or spatial); loops of joints have none
        pos, _ = a.mechanism.positions(a.ring)
        moving = [p for p in a.mechanism.points() if p not in a.mechanism.fixed and p in pos]
    coords = [c for p in moving for c in pos[p]]
    starts = [sum(len(pos[q]) for q in moving[:i]) for i in range(len(moving))]
    values = _rounded_boxes(rep, roots, coords, digits) if roots and coords else [[] for _ in roots]
    config = _rounded_boxes(rep, roots, list(a.ring.gens()[:a.nvars]), digits) if roots else []
    poses = [{"points": {p: v[k:k + len(pos[p])] for p, k in zip(moving, starts)},
              "configuration": c} for v, c in zip(values, config)]
    return {"complex": sols.complex_count, "real": sols.real_count, "with_multiplicity": sols.total,
            "poses": poses}


def _circuits(gens: list[Poly], a: Analysis, is_prime: bool) -> int:
    from mech.stdlib.circuit_counts import circuit_count
    return circuit_count(gens, a.ring, is_prime)


def _branches(a: Analysis, s: Any) -> list[dict[str, Any]]:
    from mech.kernel.real_branches import real_branches
    from mech.kernel.real_solve import decimal
    point = [c for c in s.point] if s.point is not None else s.prime
    out = []
    for b in real_branches(a.ideal, a.ring, point):
        out.append({"point": [decimal((lo + hi) / 2, DIGITS) for lo, hi in b.point],
                    "count": b.branches, "half_branches": b.half_branches, "type": b.kind,
                    "tangents": [_direction(t) for t in b.tangents]})
    return out


def _direction(box: list) -> list[str]:
    """A tangent direction (a box) scaled so that its largest coordinate is 1."""
    from mech.kernel.real_solve import decimal
    v = [(lo + hi) / 2 for lo, hi in box]
    big = max(v, key=abs)
    return [decimal(x / big, DIGITS) for x in v]


def _branch_words(b: dict[str, Any]) -> str:
    n = b["count"]
    words = {2: "two", 3: "three", 4: "four"}.get(n, str(n))
    return _TYPES.get(b["type"], b["type"]).format(n=words)


# ---------------------------------------------------------------- the sections
def _compute(a: Analysis) -> RealSections:
    sec = RealSections()
    if a.params:
        return sec
    sec.lines.append("real answers (exact real solving):")
    fb = four_bar(a.mechanism)
    if fb is not None:
        g = fb.classify()
        sec.data["grashof"] = {"kind": g.kind, "grashof": g.grashof, "inequality": g.inequality,
                               "shortest": g.shortest, "description": g.description,
                               "lengths": {"ground": str(fb.ground), "crank": str(fb.crank),
                                           "coupler": str(fb.coupler), "rocker": str(fb.rocker)},
                               "joints": list(fb.joints)}
        sec.lines.append(f"  Grashof: {g.kind}: {g.inequality}; {g.description}")
    if a.mobility == 0:
        am = _step(sec, "assembly modes", assembly_modes, a)
        if am is not None:
            sec.data["assembly_modes"] = am
            sec.lines.append(f"  assembly modes: {am['complex']} complex, {am['real']} real")
            for i, pose in enumerate(am["poses"], 1):
                pts = ", ".join(f"{p} = ({', '.join(xs)})" for p, xs in pose["points"].items()) \
                    or "configuration (" + ", ".join(pose["configuration"]) + ")"
                sec.lines.append(f"    [{i}] {pts}")
    elif a.mobility == 1:
        _circuit_section(sec, a)
        _branch_section(sec, a)
        if fb is not None:
            from mech.stdlib.input_output import four_bar_io
            io = _step(sec, "input and output", four_bar_io, a.mechanism, a)
            if io is not None:
                sec.data["input_output"] = io.data()
                sec.lines += ["  " + line for line in io.lines()]
    else:
        sec.lines.append(f"  real circuits and branches: only for one degree of freedom (mobility {a.mobility})")
    return sec


def _circuit_section(sec: RealSections, a: Analysis) -> None:
    if a.modes:
        parts = [(i, mode_generators(a, i)) for i, md in enumerate(a.modes, 1) if md.dim == 1 and md.real]
    else:  # a quick analysis: the configuration space as a whole
        parts = [(None, a.ideal)]
    if len(parts) > 1:  # modes meet at real points: the configuration space's circuits are not the modes'
        parts.insert(0, (None, a.ideal))
    out = []
    for i, prime in parts:
        what = f"real circuits of mode {i}" if i else "real circuits"
        n = _step(sec, what, _circuits, prime, a, i is not None)
        if n is None:
            continue
        out.append({"mode": i, "circuits": n})
        where = f"mode {i}" if i else "the configuration space"
        piece = "circuit" if n == 1 else "circuits"
        apart = (" (the linkage cannot pass from one to another without disassembly)"
                 if n > 1 and (i is None or len(parts) == 1) else "")
        sec.lines.append(f"  real circuits: {where} has {n} {piece}{apart}")
    sec.data["real_circuits"] = out


def _branch_section(sec: RealSections, a: Analysis) -> None:
    out = []
    for i, s in enumerate(a.singular, 1):
        if s.dim != 0 or not s.real:
            continue
        found = _step(sec, f"real branches at q{i}", _branches, a, s)
        if found is None:
            continue
        for b in found:
            out.append({"configuration": f"q{i}", **b})
            where = f"q{i}" if s.point is not None else f"q{i} at ({','.join(b['point'])})"
            tangents = "; ".join("(" + ",".join(t) + ")" for t in b["tangents"])
            local = (f" (one local component over C, {b['count']} real branches)"
                     if len(s.local_components) == 1 and b["count"] > 1 else "")
            sec.lines.append(f"  real branches at {where}: {b['count']} ({b['type']}): {_branch_words(b)}{local}" +
                             (f"; tangent directions {tangents}" if tangents else ""))
    sec.data["real_branches"] = out


_CACHE: dict[int, tuple[Analysis, RealSections]] = {}


def real_sections(a: Analysis) -> RealSections:
    """The real answers of ``a`` (computed once per analysis, again when a statement's time limit
    cut them short)."""
    hit = _CACHE.get(id(a))
    if hit is None or hit[0] is not a:
        with relaxed_gc():
            hit = (a, _compute(a))
        if not hit[1].cut:
            _CACHE[id(a)] = hit
    return hit[1]
