"""Design-space sweeps: one mechanism with symbolic lengths, analysed at many designs.

A :class:`SweepSpec` is the mechanism, the answers asked for and the per-design time limit; a
design gives numbers to (some of) its symbolic lengths. :func:`analyse_design` computes one
design's row, :func:`run_batch` a batch of them (what a Dask task runs). The exact work shared by
all designs is done once by :func:`shared_work`: the length conditions of the generic mechanism
(over ``Q(lengths)``; :func:`mech.stdlib.analysis.global_analysis`), under which a design has no
singular configuration at all — so for a design on none of them the singular configurations are
not computed (0, proved), and the row names the conditions a design lies on. Running the batches
(locally on all cores or on a Dask cluster), storing and resuming are in
:mod:`mech.stdlib.sweep_run`; the picture in :mod:`mech.stdlib.sweep_map`; the command
``sweep`` of the language in :mod:`mech.stdlib.sweep_commands`.

Answers (columns of a row): ``mobility``; ``modes`` (the number of motion modes, the primary
decomposition of J); ``real`` (mobility 0: the number of real assembly modes, distinct real
solutions of J; mobility 1: the number of real circuits of the configuration curve; exact);
``grashof`` (a four-bar's Grashof type, :func:`mech.stdlib.grashof.grashof`); ``singular`` (the number of
singular configurations as ``analyze`` lists them, and ``singular_types`` their types). Every row
also has ``id``, the parameters, ``conditions`` (the generic length conditions vanishing at the
design, when the shared work finished), ``seconds`` and ``error``.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Callable

from mech.dsl.errors import MechRuntimeError
from mech.stdlib.mechanism import Mechanism

ANSWERS = ("mobility", "modes", "real", "grashof", "singular")
DEFAULT_ANSWERS = ("mobility", "real")
SHARED_LIMIT = 20.0  # seconds for the shared symbolic work


@dataclass
class SweepSpec:
    """What every design of a sweep computes."""

    mechanism: Mechanism
    answers: tuple[str, ...] = DEFAULT_ANSWERS
    timeout: float | None = None  # seconds per design (None: no limit)
    deadline: float | None = None  # wall-clock time (time.time()) when the whole sweep must stop

    def columns(self, params: list[str]) -> list[str]:
        extra = [a for a in ANSWERS if a in self.answers]
        if "singular" in self.answers:
            extra.append("singular_types")
        return ["id"] + params + extra + ["conditions", "seconds", "error"]


@dataclass
class Shared:
    """The exact work done once for all designs: the generic length conditions (each as the
    generators whose common zeros are the designs with singular configurations on that
    component; ``None``: every design may have some). ``dominant``: some component covers all
    designs, so nothing is skipped."""

    params: list[str]
    components: list[list[dict[tuple[int, ...], Fraction]]] = field(default_factory=list)
    names: list[str] = field(default_factory=list)  # the length conditions, printed
    conditions: list[dict[tuple[int, ...], Fraction]] = field(default_factory=list)
    dominant: bool = True
    note: str = ""
    curves: list[dict[tuple[int, int], Fraction]] = field(default_factory=list)  # discriminant curves
    curve_labels: list[str] = field(default_factory=list)


def parse_answers(text: str | list[str] | tuple[str, ...]) -> tuple[str, ...]:
    """``"mobility,real"`` (or a list of names) as a tuple of known answers."""
    names = text.replace(",", " ").split() if isinstance(text, str) else list(text)
    bad = [n for n in names if n not in ANSWERS]
    if bad or not names:
        raise MechRuntimeError(f"sweep: unknown answer '{bad[0] if bad else ''}' (known: {', '.join(ANSWERS)})")
    return tuple(dict.fromkeys(names))


def check_parameters(m: Mechanism, names: list[str]) -> None:
    """Every swept name must be a symbolic length of ``m``, and every symbolic length swept."""
    symbols = m.symbols()
    unknown = [n for n in names if n not in symbols]
    if unknown:
        raise MechRuntimeError(f"sweep: '{unknown[0]}' is not a symbolic length of the mechanism "
                               f"(it has {', '.join(symbols) or 'none'})")
    missing = [n for n in symbols if n not in names]
    if missing:
        raise MechRuntimeError(f"sweep: the designs give no value to {', '.join(missing)} (fix it with "
                               f"{missing[0]}=VALUE in the designs, or setLengths)")


# ---------------------------------------------------------------- the shared symbolic work
def _terms(p: Any, first: int) -> dict[tuple[int, ...], Fraction]:
    """A polynomial in the lengths (variables from index ``first`` on) as exponent -> coefficient."""
    return {e[first:]: Fraction(int(c.p), int(c.q)) for e, c in p.terms.items()}


def _value(terms: dict[tuple[int, ...], Fraction], point: list[Fraction]) -> Fraction:
    total = Fraction(0)
    for e, c in terms.items():
        t = c
        for x, k in zip(point, e):
            if k:
                t *= x ** k
        total += t
    return total


def shared_work(spec: SweepSpec, params: list[str], limit: float = SHARED_LIMIT) -> Shared:
    """The generic mechanism's length conditions (``limit`` seconds or ``spec.timeout``, the
    larger, at most; when they do not finish nothing is skipped)."""
    from mech.dsl.limits import within
    from mech.dsl.printing import poly_str
    from mech.stdlib.analysis import global_analysis
    out = Shared(list(params))
    seconds = max(spec.timeout or 0, limit)
    try:
        ok, a = within(seconds, global_analysis, spec.mechanism, False)
    except Exception as e:  # noqa: BLE001 - the shared work is an optimisation: every design still runs
        ok, a = False, _message(e)
    if not ok:
        why = a if isinstance(a, str) else f"not found in {seconds:g} s"
        out.note = f"no shared length conditions ({why}): every design analysed in full"
        return out
    first = a.nvars
    order = list(a.ring.names[first:])
    perm = [order.index(p) for p in params]
    for lc in a.length_components:
        if lc.elimination is None:
            continue  # J + P has no point: no singular configuration from this component
        if not lc.elimination:
            out.note = "a component of the singular variety lies over every design: nothing skipped"
            return out
        gens = [_terms(g, first) for g in (lc.conditions or [a.ring.one()])]
        out.components.append([{tuple(e[i] for i in perm): c for e, c in g.items()} for g in gens])
    out.conditions = [{tuple(e[i] for i in perm): c for e, c in _terms(f, first).items()} for f in a.length_factors]
    out.names = [poly_str(f) for f in a.length_factors]
    out.dominant = False
    return out


def on_conditions(shared: Shared, point: list[Fraction]) -> tuple[bool, str]:
    """Whether the design may have singular configurations (a length is 0, or it lies on a
    component's conditions), and the length conditions vanishing there."""
    names = ", ".join(dict.fromkeys([n for n, f in zip(shared.names, shared.conditions) if _value(f, point) == 0]
                                    + [n for n, f in zip(shared.curve_labels, shared.curves) if _value(f, point) == 0]))
    if shared.dominant or any(x == 0 for x in point):
        return True, names
    return any(all(_value(g, point) == 0 for g in comp) for comp in shared.components), names


# ---------------------------------------------------------------- one design
#: The error of a design not analysed because the whole sweep's time ran out (never written: the
#: design is analysed when the sweep is resumed).
STOPPED = "stopped: the sweep's time limit"


def _budget(spec: SweepSpec) -> tuple[float | None, bool]:
    """The design's time limit: ``spec.timeout``, or less when the sweep's own deadline comes
    first (then True)."""
    if spec.deadline is None:
        return spec.timeout, False
    left = spec.deadline - time.time() - 0.1  # stop just before the statement's limit fires
    if spec.timeout is None or left < spec.timeout:
        return left, True
    return spec.timeout, False


def _message(e: BaseException) -> str:
    return getattr(e, "message", None) or str(e) or type(e).__name__


def analyse_design(spec: SweepSpec, shared: Shared, ident: int, design: dict[str, Fraction]) -> dict[str, Any]:
    """One row: the answers at ``design`` (errors and the time limit recorded in the row)."""
    start = time.perf_counter()
    row: dict[str, Any] = {"id": ident, **{k: _show(v) for k, v in design.items()}}
    point = [design[p] for p in shared.params]
    may_be_singular, row["conditions"] = on_conditions(shared, point)
    errors: list[str] = []
    budget, capped = _budget(spec)
    if capped and budget <= 0:
        return {**row, "error": STOPPED}
    from mech.dsl.limits import within
    try:
        ok, _ = within(budget, _answers, spec, design, may_be_singular, row, errors)
        if not ok:
            if capped:
                return {**row, "error": STOPPED}
            errors.append(f"time limit of {spec.timeout:g} s exceeded")
    except Exception as e:  # noqa: BLE001 - a failure is the row's answer, never the sweep's end
        errors.append(_message(e))
    row["seconds"] = round(time.perf_counter() - start, 4)
    row["error"] = "; ".join(errors)
    return row


def _show(v: Fraction) -> str:
    return str(v.numerator) if v.denominator == 1 else f"{v.numerator}/{v.denominator}"


def _answers(spec: SweepSpec, design: dict[str, Fraction], may_be_singular: bool,
             row: dict[str, Any], errors: list[str]) -> None:
    from mech.kernel.ideals import dimension
    from mech.stdlib.analysis import constraint_ideal
    m = spec.mechanism.with_values({k: (int(v) if v.denominator == 1 else v) for k, v in design.items()})
    if "grashof" in spec.answers:
        row["grashof"] = _guard(errors, "grashof", lambda: grashof_type(m))
    if not set(spec.answers) - {"grashof"}:
        return
    R, J, n = constraint_ideal(m)
    mobility = dimension(J, R)
    if "mobility" in spec.answers:
        row["mobility"] = mobility
    if "real" in spec.answers:
        row["real"] = _guard(errors, "real", lambda: real_count(J, R, mobility))
    if "modes" in spec.answers or ("singular" in spec.answers and may_be_singular):
        _full(m, spec, row, errors)
    elif "singular" in spec.answers:
        row["singular"], row["singular_types"] = 0, ""


def _guard(errors: list[str], what: str, fn: Callable[[], Any]) -> Any:
    try:
        return fn()
    except MechRuntimeError as e:
        errors.append(f"{what}: {_message(e)}")
        return ""


def _full(m: Mechanism, spec: SweepSpec, row: dict[str, Any], errors: list[str]) -> None:
    """Motion modes and singular configurations, as ``analyze`` finds them."""
    from mech.stdlib.analysis import global_analysis, local_analysis
    from mech.stdlib.mechanism import MechanismError
    try:
        a = global_analysis(m)
    except MechanismError as e:
        errors.append(_message(e).split(": ", 1)[-1])
        return
    if "modes" in spec.answers:
        row["modes"] = len(a.modes)
    if "singular" in spec.answers:
        found = local_analysis(a)
        row["singular"] = len(found)
        row["singular_types"] = "; ".join(s.kind or "not a point" for s in found)


def real_count(J: list, R: Any, mobility: int) -> int | str:
    """Real assembly modes (mobility 0) or real circuits (mobility 1), exactly; "" otherwise."""
    from mech.kernel.real_roots import RealSolvingError
    try:
        if mobility == 0:
            from mech.kernel.real_solve import count_solutions
            return count_solutions(J, R)[1]
        if mobility == 1:
            from mech.kernel.real_curve import curve_topology
            return curve_topology(J, R, None).count
    except RealSolvingError as e:
        raise MechRuntimeError(str(e)) from None
    return 0 if mobility < 0 else ""


def grashof_type(m: Mechanism) -> str:
    """The Grashof type of a four-bar (:mod:`mech.stdlib.grashof`)."""
    from mech.stdlib.grashof import four_bar
    fb = four_bar(m)
    if fb is None:
        raise MechRuntimeError("not a four-bar (two fixed pivots, three links chained between them)")
    return fb.classify().kind


def run_batch(spec: SweepSpec, shared: Shared, batch: list[tuple[int, dict[str, Fraction]]]) -> list[dict[str, Any]]:
    """The rows of a batch of designs (one Dask task)."""
    return [analyse_design(spec, shared, i, d) for i, d in batch]
