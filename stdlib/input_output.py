"""Input–output analysis of a one-degree-of-freedom mechanism: an input link and an output link
(their angles ``theta_i = atan2(s_i, c_i)`` to the ground's x-axis), the range of the output, its
limit positions, the input's dead-centre positions and, for a four-bar, the transmission angle.

Everything is exact up to the final decimals (:mod:`mech.kernel.real_solve`):

* a function ``f`` on the configuration curve ``V(J)`` (``n`` variables) is critical where
  ``[dJ; grad f]`` has rank below ``n`` (all its ``n``-minors vanish: Lagrange; singular
  configurations are included); for an angle ``theta_j`` the gradient is the rotation field
  ``-s_j d/dc_j + c_j d/ds_j``;
* the **limit positions** of the output are the real critical points of ``theta_out`` (where it
  stops and reverses: a four-bar's crank and coupler are aligned), the **dead-centre positions**
  those of ``theta_in`` (the input cannot drive the output there: coupler and output aligned);
* the **range** of an angle is a union of arcs between consecutive critical values: an arc is
  attained when the fibre over one rational point inside it (``(c, s)`` from a rational
  ``tan(phi/2)``) has a real point (a zero-dimensional count); no critical value and a real fibre:
  the link turns fully;
* the **transmission angle** ``mu`` at the joint of the coupler and the output: ``cos mu`` is the
  dot product of the two links' vectors from that joint over their lengths; its extremes over the
  motion are among the critical values of the dot product.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Callable, Optional

from flint import fmpq

from mech.dsl.errors import MechRuntimeError
from mech.dsl.registry import command
from mech.kernel import Poly, PolyRing
from mech.kernel.matrix import Matrix, minors
from mech.kernel.real_roots import RealSolvingError
from mech.kernel.real_solve import count_solutions, real_solutions
from mech.stdlib.mechanism import Mechanism


@dataclass
class InputOutput:
    """The answers in degrees (two decimals): the output's ``range`` (arcs ``(from, to)``
    counterclockwise; ``[(-180, 180)]`` when it turns fully), the configurations at the output's
    limit positions and at the input's dead centres as ``(input angle, output angle)``, the input's
    range likewise, the transmission angle's ``(min, max)`` (None when not asked), and the singular
    configurations where an angle is critical only because the curve is singular there."""

    input_link: int
    output_link: int
    output_range: list[tuple[float, float]]
    input_range: list[tuple[float, float]]
    limit_positions: list[tuple[float, float]]
    dead_centres: list[tuple[float, float]]
    transmission: Optional[tuple[float, float]] = None
    singular: list[tuple[float, float]] = field(default_factory=list)
    #: On one motion mode: its number and name, and the links frozen on it ("input", "output") with
    #: their angle (None: an algebraic angle).
    mode: Optional[int] = None
    name: Optional[str] = None
    frozen: dict[str, Optional[float]] = field(default_factory=dict)
    #: The answers on each real circuit of the mode (when it has several), ``circuit`` numbering them.
    circuits: list["InputOutput"] = field(default_factory=list)
    circuit: Optional[int] = None

    def lines(self) -> list[str]:
        i, o = self.input_link, self.output_link
        out = [f"input link {i}, output link {o} (angles to the x-axis, degrees):"]
        for role, link, arcs in (("output", o, self.output_range), ("input", i, self.input_range)):
            if role in self.frozen:
                at = self.frozen[role]
                out.append(f"  {role}: link {link} is frozen on this mode" +
                           (f", at {at:.2f}" if at is not None else ", at an algebraic angle") +
                           (" (the input does not drive this motion)" if role == "input" else
                            " (the output does not move)"))
            else:
                out.append(f"  {role} range: {_arcs(arcs)}")
        if "output" not in self.frozen:
            out.append("  limit positions of the output (input, output): " + _pairs(self.limit_positions)
                       if self.limit_positions else "  limit positions of the output: none")
        if "input" not in self.frozen:
            out.append("  dead-centre positions of the input (input, output): " + _pairs(self.dead_centres)
                       if self.dead_centres else
                       "  dead-centre positions of the input: none (the input drives the output everywhere)")
        if self.singular:
            out.append("  singular configurations on the way (input, output): " + _pairs(self.singular))
        if self.transmission is not None:
            lo, hi = self.transmission
            out.append(f"  transmission angle: from {lo:.2f} to {hi:.2f} (largest deviation from 90: "
                       f"{max(abs(90 - lo), abs(90 - hi)):.2f})")
        for c in self.circuits:
            out.append(f"  on circuit {c.circuit} of {len(self.circuits)}:")
            out += ["  " + line for line in c.lines()[1:] if "frozen on this mode" not in line]
        return out

    def data(self) -> dict[str, Any]:
        return {"input_link": self.input_link, "output_link": self.output_link,
                "output_range": [list(a) for a in self.output_range],
                "input_range": [list(a) for a in self.input_range],
                "output_turns_fully": self.output_range == [(-180.0, 180.0)],
                "input_turns_fully": self.input_range == [(-180.0, 180.0)],
                "limit_positions": [list(p) for p in self.limit_positions],
                "dead_centres": [list(p) for p in self.dead_centres],
                "singular": [list(p) for p in self.singular],
                "transmission_angle": list(self.transmission) if self.transmission else None,
                **({} if self.mode is None else {
                    "mode": self.mode, "name": self.name,
                    "input_frozen": "input" in self.frozen, "input_frozen_at": self.frozen.get("input"),
                    "output_frozen": "output" in self.frozen, "output_frozen_at": self.frozen.get("output")}),
                **({"circuit": self.circuit} if self.circuit is not None else
                   {"circuits": [c.data() for c in self.circuits]} if self.mode is not None else {})}


@dataclass
class ModesIO:
    """The input–output answers mode by mode (one-dimensional modes with real points); ``skipped``:
    the other modes and those whose computation failed, with the reason."""

    input_link: int
    output_link: int
    modes: list[InputOutput]
    skipped: list[tuple[int, str]] = field(default_factory=list)

    def lines(self) -> list[str]:
        if len(self.modes) == 1 and not self.skipped:
            return self.modes[0].lines()
        out = [f"input link {self.input_link}, output link {self.output_link} (angles to the x-axis, degrees), "
               f"mode by mode:"]
        for io in self.modes:
            out.append(f"  mode {io.mode}" + (f" ({io.name})" if io.name else "") + ":")
            out += ["  " + line for line in io.lines()[1:]]
        out += [f"  mode {k}: {why}" for k, why in self.skipped]
        return out

    def data(self) -> dict[str, Any]:
        """``input_link``, ``output_link``, ``modes`` (each mode's answers with ``mode``, ``name``,
        ``input_frozen``, ``output_frozen``), ``skipped``; with one mode also its keys at the top."""
        d: dict[str, Any] = {"input_link": self.input_link, "output_link": self.output_link}
        if len(self.modes) == 1 and not self.skipped:
            d.update(self.modes[0].data())
        d["modes"] = [io.data() for io in self.modes]
        d["skipped"] = [{"mode": k, "reason": why} for k, why in self.skipped]
        return d


def _arcs(arcs: list[tuple[float, float]]) -> str:
    if arcs == [(-180.0, 180.0)]:
        return "turns fully"
    if not arcs:
        return "no real motion"
    return ", ".join(f"[{a:.2f}, {b:.2f}]" for a, b in arcs)


def _pairs(ps: list[tuple[float, float]]) -> str:
    return ", ".join(f"({a:.2f}, {b:.2f})" for a, b in ps)


# ---------------------------------------------------------------- exact steps
def _critical_system(J: list[Poly], grad: list[Poly]) -> list[Poly]:
    R = J[0].ring
    n = R.nvars
    rows = [[g.diff(k) for k in range(n)] for g in J] + [grad]
    M = Matrix.from_rows(R, rows)
    return list(J) + [d for d in minors(M, n) if not d.is_zero()]


def _rotation(R: PolyRing, j: int) -> list[Poly]:
    """The gradient-like field of ``theta_j``: ``-s_j`` at ``c_j``, ``c_j`` at ``s_j``."""
    g = [R.zero()] * R.nvars
    c, s = R.gens()[2 * j - 2], R.gens()[2 * j - 1]
    g[2 * j - 2], g[2 * j - 1] = -s, c
    return g


def _critical_points(J: list[Poly], grad: list[Poly], on: Optional[list[Poly]] = None
                     ) -> tuple[list[list[float]], list[list[float]]]:
    """The real critical points of ``f`` (gradient ``grad``) on ``V(J)`` (on the mode ``V(on)``
    when given: the Lagrange minors of ``dJ``, or of the mode's own generators when ``J`` is not
    reduced along it): those where the curve is smooth, and the singular configurations among them
    (where ``dJ`` has rank below ``n - 1``: the smallest singular values of the Jacobian at the
    10^-12-boxes' centres tell)."""
    R = J[0].ring
    if on is None:
        sols = real_solutions(_critical_system(J, grad), R, 12)
    else:
        try:
            sols = real_solutions(list(on) + _critical_system(J, grad)[len(J):], R, 12)
        except RealSolvingError:
            sols = real_solutions(_critical_system(list(on), grad), R, 12)
    pts = [[float(Fraction(int(v.p), int(v.q))) for v in s.midpoint()] for s in sols.real]
    jac = [[g.diff(k) for k in range(R.nvars)] for g in J]
    smooth, singular = [], []
    for p in pts:
        sv = singular_values([[_eval(d, p) for d in row] for row in jac])
        (smooth if sv[R.nvars - 2] > 1e-8 else singular).append(p)
    return smooth, singular


def _angle(pt: list[float], j: int) -> float:
    return round(math.degrees(math.atan2(pt[2 * j - 1], pt[2 * j - 2])), 2)


def _on_circle(phi: float) -> tuple[Fraction, Fraction]:
    """A rational point of the unit circle at an angle close to ``phi`` (radians)."""
    if abs(abs(phi) - math.pi) < 1e-9:
        return Fraction(-1), Fraction(0)
    t = Fraction(math.tan(phi / 2)).limit_denominator(10 ** 6)
    return (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)


def _fibre(J: list[Poly], j: int, phi: float) -> list[Poly]:
    R = J[0].ring
    c, s = _on_circle(phi)
    cj, sj = R.gens()[2 * j - 2], R.gens()[2 * j - 1]
    return list(J) + [cj - R.const(fmpq(c.numerator, c.denominator)),
                      sj - R.const(fmpq(s.numerator, s.denominator))]


def _attained(J: list[Poly], j: int, phi: float, circuit: Optional[Callable[[list[float]], bool]] = None) -> bool:
    """Whether the angle of link ``j`` takes (nearly) the value ``phi`` on ``V(J)`` (at a point
    for which ``circuit`` holds, when given)."""
    if circuit is None:
        return count_solutions(_fibre(J, j, phi), J[0].ring)[1] > 0
    sols = real_solutions(_fibre(J, j, phi), J[0].ring, 12).real
    return any(circuit([float(Fraction(int(v.p), int(v.q))) for v in s.midpoint()]) for s in sols)


def angle_range(J: list[Poly], j: int, critical: list[list[float]],
                circuit: Optional[Callable[[list[float]], bool]] = None) -> list[tuple[float, float]]:
    """The arcs of ``theta_j`` over the real curve (the points for which ``circuit`` holds, when
    given: one circuit), from its critical points (there)."""
    values = sorted({_angle(p, j) for p in critical})
    if len(values) < 2:  # no reversal: the link turns fully (through the one value, if any) or not at all
        phi = math.radians(values[0] + 180) if values else 0.3
        return [(-180.0, 180.0)] if _attained(J, j, phi, circuit) else []
    arcs = []
    for k, a in enumerate(values):
        b = values[(k + 1) % len(values)]
        span = (b - a) % 360 or 360.0
        if _attained(J, j, math.radians(a + span / 2), circuit):
            arcs.append((a, b))
    merged: list[tuple[float, float]] = []
    for a, b in arcs:  # consecutive attained arcs join at their common end
        if merged and merged[-1][1] == a:
            merged[-1] = (merged[-1][0], b)
        else:
            merged.append((a, b))
    if len(merged) > 1 and merged[-1][1] == merged[0][0]:
        merged[0] = (merged[-1][0], merged[0][1])
        merged.pop()
    return merged


def input_output(m: Mechanism, J: list[Poly], inp: int, out: int,
                 transmission: Optional[tuple[str, int, int]] = None,
                 on: Optional[list[Poly]] = None) -> InputOutput:
    """The input–output answers for links ``inp`` and ``out`` (1-based) of ``m`` with constraint
    ideal ``J`` (numeric lengths, mobility 1), on the motion mode with prime ``on`` when given
    (a link whose angle is constant there is reported frozen, with its angle);
    ``transmission = (joint, k, j)``: the transmission angle at the joint of links ``k`` and ``j``."""
    R = J[0].ring
    curve = list(on) if on is not None else J
    frozen = _frozen(on, inp, out) if on is not None else {}
    crit = {}
    for role, link in (("output", out), ("input", inp)):
        crit[role] = ([], []) if role in frozen else _critical_points(J, _rotation(R, link), on)
    (lim, sing), (dead, sing2) = crit["output"], crit["input"]
    pair = lambda p: (_angle(p, inp), _angle(p, out))  # noqa: E731

    def arc(role: str, link: int, pts: list[list[float]]) -> list[tuple[float, float]]:
        if role not in frozen:
            return angle_range(curve, link, pts)
        at = frozen[role]
        return [] if at is None else [(at, at)]
    io = InputOutput(inp, out, arc("output", out, lim), arc("input", inp, dead),
                     sorted(map(pair, lim)), sorted(map(pair, dead)),
                     singular=sorted(set(map(pair, sing + sing2))), frozen=frozen)
    trans_pts: list[list[float]] = []
    if transmission is not None:
        io.transmission, trans_pts = _transmission(m, J, *transmission, on=on)
    split = _circuits(m, on) if on is not None else None
    if split is None:
        return io
    circuit_of, count = split
    for c in range(1, count + 1):
        def here(p: list[float], c: int = c) -> bool:
            return circuit_of(p) == c
        lim_c, dead_c = [p for p in lim if here(p)], [p for p in dead if here(p)]
        sub = InputOutput(inp, out, io.output_range if "output" in frozen else angle_range(curve, out, lim_c, here),
                          io.input_range if "input" in frozen else angle_range(curve, inp, dead_c, here),
                          sorted(map(pair, lim_c)), sorted(map(pair, dead_c)),
                          singular=sorted({pair(p) for p in sing + sing2 if here(p)}), frozen=frozen, circuit=c)
        sub.transmission = io.transmission
        if transmission is not None and io.transmission[0] != io.transmission[1]:
            sub.transmission = _extremes(m, *transmission, [p for p in trans_pts if here(p)])
        io.circuits.append(sub)
    return io


def _circuits(m: Mechanism, prime: list[Poly]) -> Optional[tuple[Callable[[list[float]], int], int]]:
    """For a mode with several real circuits whose samples split clearly
    (:func:`mech.stdlib.configurations.circuit_split`): the circuit of a point (that of the nearest
    sample) and the number of circuits; None otherwise (without sampling when the exact count,
    computed first and shared with the report, is below 2)."""
    from mech.stdlib.configurations import _circuit_count, circuit_split
    known = _circuit_count(prime, prime[0].ring)
    if known is not None and known < 2:
        return None
    import numpy as np
    x, labels, k = circuit_split(prime, prime[0].ring, len(m.links))
    if labels is None or not k or k < 2:
        return None
    lab = np.array(labels)
    return (lambda p: int(lab[np.argmin(np.linalg.norm(x - np.array(p), axis=1))])), k


def _frozen(prime: list[Poly], inp: int, out: int) -> dict[str, Optional[float]]:
    """The links among the input and output whose angle is constant on the mode ``V(prime)``
    (normal forms against its Gröbner basis, :mod:`mech.stdlib.mode_names`), with the angle."""
    from mech.stdlib.mode_names import _Mode
    P = _Mode(prime)
    R = prime[0].ring
    out_: dict[str, Optional[float]] = {}
    for role, link in (("input", inp), ("output", out)):
        c, s = R.gens()[2 * link - 2], R.gens()[2 * link - 1]
        a, b = P.constant(c), P.constant(s)
        if a is not None and b is not None:
            out_[role] = _angle([float(a), float(b)], 1)
        elif P.algebraic(c) or P.algebraic(s):
            out_[role] = None
    return out_


def modes_input_output(m: Mechanism, a: Any, inp: int, out: int,
                       transmission: Optional[tuple[str, int, int]] = None) -> ModesIO:
    """The input–output answers on each one-dimensional motion mode with real points of the
    analysis ``a`` (the whole configuration space when its modes are not known)."""
    from mech.stdlib.mode_names import mode_names
    if not a.modes:
        return ModesIO(inp, out, [input_output(m, a.ideal, inp, out, transmission)])
    names = mode_names(a)
    res = ModesIO(inp, out, [])
    for k, md in enumerate(a.modes, 1):
        if md.dim != 1 or md.real is False:
            res.skipped.append((k, "no real points" if md.real is False else f"dimension {md.dim}, no motion"))
            continue
        try:
            io = input_output(m, a.ideal, inp, out, transmission, on=md.prime)
        except RealSolvingError as e:
            res.skipped.append((k, f"not computed ({e})"))
            continue
        io.mode, io.name = k, names[k - 1].name if k <= len(names) and names[k - 1] else None
        res.modes.append(io)
    return res


def _link_vectors(m: Mechanism, R: PolyRing, joint: str, k: int, j: int) -> tuple[Poly, Poly, Poly]:
    """The dot product of links ``k`` and ``j`` from ``joint`` and their squared lengths."""
    pos, _ = m.positions(R)
    ends = []
    for link in (m.links[k - 1], m.links[j - 1]):
        other = next(p for p in link.points if p != joint and p in _joints(m))
        ends.append((pos[other][0] - pos[joint][0], pos[other][1] - pos[joint][1]))
    (ux, uy), (vx, vy) = ends
    return ux * vx + uy * vy, ux * ux + uy * uy, vx * vx + vy * vy


def _extremes(m: Mechanism, joint: str, k: int, j: int, crit: list[list[float]]) -> Optional[tuple[float, float]]:
    """``(min, max)`` of the angle at ``joint`` between links ``k`` and ``j`` over the points ``crit``."""
    if not crit:
        return None
    dot, n1, n2 = _link_vectors(m, m.ring(), joint, k, j)
    vals = []
    for p in crit:
        norm = math.sqrt(_eval(n1, p) * _eval(n2, p))
        vals.append(math.degrees(math.acos(max(-1.0, min(1.0, _eval(dot, p) / norm)))))
    return round(min(vals), 2), round(max(vals), 2)


def _transmission(m: Mechanism, J: list[Poly], joint: str, k: int, j: int,
                  on: Optional[list[Poly]] = None) -> tuple[tuple[float, float], list[list[float]]]:
    """``(min, max)`` of the angle at ``joint`` between links ``k`` and ``j`` (degrees), on the
    mode ``V(on)`` when given, and the critical points of the links' dot product."""
    R = J[0].ring
    dot, n1, n2 = _link_vectors(m, R, joint, k, j)
    if on is not None:
        from mech.stdlib.mode_names import _Mode
        P = _Mode(on)
        vals = [P.constant(f) for f in (dot, n1, n2)]
        if None not in vals:  # constant on the mode
            mu = round(math.degrees(math.acos(max(-1.0, min(1.0, float(vals[0]) / math.sqrt(vals[1] * vals[2]))))), 2)
            return (mu, mu), []
    crit = [p for part in _critical_points(J, [dot.diff(i) for i in range(R.nvars)], on) for p in part]
    found = _extremes(m, joint, k, j, crit)
    if found is None:
        raise RealSolvingError("no extreme of the transmission angle found")
    return found, crit


def _joints(m: Mechanism) -> set[str]:
    seen: dict[str, int] = {}
    for link in m.links:
        for p in link.points:
            seen[p] = seen.get(p, 0) + 1
    return {p for p, c in seen.items() if c > 1 or p in m.fixed}


def singular_values(rows: list[list[float]], sweeps: int = 60) -> list[float]:
    """The singular values of a small real matrix (one per column, largest first) by one-sided
    Jacobi rotations (Hestenes 1958; Demmel and Veselić 1992: as accurate as an SVD, to
    relative precision): the columns are rotated pairwise until orthogonal, then their norms."""
    cols = [list(c) for c in zip(*rows)]
    eps = 1e-15
    for _ in range(sweeps):
        rotated = False
        for i in range(len(cols)):
            for j in range(i + 1, len(cols)):
                a, b = cols[i], cols[j]
                alpha, beta = sum(x * x for x in a), sum(y * y for y in b)
                gamma = sum(x * y for x, y in zip(a, b))
                if abs(gamma) <= eps * math.sqrt(alpha * beta) or gamma == 0:
                    continue
                rotated = True
                zeta = (beta - alpha) / (2 * gamma)
                t = math.copysign(1.0, zeta) / (abs(zeta) + math.sqrt(1 + zeta * zeta))
                c = 1 / math.sqrt(1 + t * t)
                s = c * t
                cols[i] = [c * x - s * y for x, y in zip(a, b)]
                cols[j] = [s * x + c * y for x, y in zip(a, b)]
        if not rotated:
            break
    return sorted((math.sqrt(sum(x * x for x in c)) for c in cols), reverse=True)


def _eval(p: Poly, pt: list[float]) -> float:
    return sum(float(Fraction(int(c.p), int(c.q))) * math.prod(v ** e for v, e in zip(pt, ex))
               for ex, c in p.terms.items())


def four_bar_io(m: Mechanism, a: Any) -> Optional[ModesIO]:
    """The crank (input) to rocker (output) analysis of a four-bar (analysed in ``a``) mode by
    mode, with its transmission angle at the coupler-rocker joint (None if ``m`` is not a four-bar)."""
    from mech.stdlib.grashof import four_bar
    fb = four_bar(m)
    if fb is None:
        return None
    crank, coupler, rocker = fb.links
    return modes_input_output(m, a, crank, rocker, (fb.joints[2], coupler, rocker))


# ---------------------------------------------------------------- command
def _command(m: Mechanism, inp: Optional[int], out: Optional[int]) -> str:
    from mech.stdlib.analysis import require_complete, run_analysis
    from mech.stdlib.grashof import four_bar
    if m.symbols():
        raise MechRuntimeError(f"inputOutput needs numeric lengths (setLengths(m, ...) for {','.join(m.symbols())})")
    a = run_analysis(m, local=False)
    require_complete(a, "inputOutput")
    if a.mobility != 1:
        raise MechRuntimeError(f"inputOutput: the mechanism must have one degree of freedom (mobility {a.mobility})")
    fb = four_bar(m)
    if inp is None:
        if fb is None:
            raise MechRuntimeError("inputOutput: give the input and output links (numbers) of a mechanism "
                                   "that is not a four-bar")
        inp, out = fb.links[0], fb.links[2]
    n = len(m.links)
    for k in (inp, out):
        if not 1 <= k <= n:
            raise MechRuntimeError(f"inputOutput: there is no link {k} (the links are 1..{n})")
    if inp == out:
        raise MechRuntimeError("inputOutput: the input and the output must be different links")
    trans = None
    if fb is not None and (inp, out) == (fb.links[0], fb.links[2]):
        trans = (fb.joints[2], fb.links[1], fb.links[2])
    elif fb is not None and (inp, out) == (fb.links[2], fb.links[0]):
        trans = (fb.joints[1], fb.links[1], fb.links[0])
    try:
        io = modes_input_output(m, a, inp, out, trans)
    except RealSolvingError as e:
        raise MechRuntimeError(f"inputOutput: {e}") from None
    return "\n".join(io.lines())


@command("inputOutput", lib="mechanism.lib")
def input_output_command(m: Mechanism, inp: int = 0, out: int = 0) -> str:
    """inputOutput(m[, input, output]): the range of the output link's angle, its limit positions,
    the input's dead-centre positions and (for a four-bar) the transmission angle, in degrees;
    input and output are link numbers (default for a four-bar: the crank and the rocker).

    Example:
      LIB "mechanism.lib";
      mechanism m = "ground O A 5; bar O B 2; bar B C 5; bar C A 4";
      inputOutput(m);
      → input link 1, output link 3 (angles to the x-axis, degrees):
      →   output range: [-101.54, -36.87], [36.87, 101.54]
      →   input range: turns fully
      →   limit positions of the output (input, output): (-126.87, -36.87), (-34.05, 101.54), (34.05, -101.54), (126.87, 36.87)
      →   dead-centre positions of the input: none (the input drives the output everywhere)
      →   transmission angle: from 36.87 to 101.54 (largest deviation from 90: 53.13)
      →   on circuit 1 of 2:
      →     output range: [36.87, 101.54]
      →     input range: turns fully
      →     limit positions of the output (input, output): (-34.05, 101.54), (126.87, 36.87)
      →     dead-centre positions of the input: none (the input drives the output everywhere)
      →     transmission angle: from 36.87 to 101.54 (largest deviation from 90: 53.13)
      →   on circuit 2 of 2:
      →     output range: [-101.54, -36.87]
      →     input range: turns fully
      →     limit positions of the output (input, output): (-126.87, -36.87), (34.05, -101.54)
      →     dead-centre positions of the input: none (the input drives the output everywhere)
      →     transmission angle: from 36.87 to 101.54 (largest deviation from 90: 53.13)
    """
    if (inp == 0) != (out == 0):
        raise MechRuntimeError("inputOutput: give both the input and the output link, or neither")
    return _command(m, inp or None, out or None)
