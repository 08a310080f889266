"""The data of a mechanism's analysis (:mod:`mech.stdlib.analysis`), filled in step by step: the motion
modes, embedded components, conditions on symbolic lengths and singular configurations, and how a step
runs within a budget of CPU time (a step that runs out is noted unfinished: the report says so)."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable

from mech.dsl.limits import within
from mech.kernel import Poly, PolyRing
from mech.kernel.local import AlgebraicPoint
from mech.kernel.progress import stage
from mech.stdlib.mechanism import Mechanism
from mech.stdlib.realpoints import has_real_points


@dataclass
class Mode:
    """A motion mode: a minimal prime of the constraint ideal (with symbolic lengths: over
    QQ(lengths), contracted to QQ[x, lengths]; ``dim`` over QQ(lengths), ``real`` None);
    ``primary`` its primary component of J when known (J radical: the prime), else None;
    ``real`` None also when the real-point decision ran out of its budget."""

    prime: list[Poly]
    primary: list[Poly] | None
    dim: int
    real: bool | None


@dataclass
class Embedded:
    """An embedded component of a non-radical J (an associated prime that is not minimal):
    where J is not reduced, the constraints' Jacobian drops rank at points of the modes
    (``modes``: 1-based indices of the modes containing it).  ``singular``: whether it lies
    in a singular configuration of the configuration space (None: not known)."""

    prime: list[Poly]
    primary: list[Poly]
    dim: int
    modes: list[int]
    point: tuple | None
    singular: bool | None = None


@dataclass
class LengthComponent:
    """A minimal prime ``P`` of the Fitting ideal and ``(J + P) ∩ Q[lengths]``."""

    prime: list[Poly]
    elimination: list[Poly] | None  # None: J + P is the unit ideal
    conditions: list[Poly]  # after saturation by the lengths; [] if only degenerate lengths
    factors: list[Poly]


@dataclass
class SingularPoint:
    """A singular configuration (a prime of the singular variety)."""

    prime: list[Poly]
    point: tuple | None  # rational coordinates, None for an algebraic point or a curve
    dim: int
    real: bool | None
    kind: str = ""
    tangent_cone: list[Poly] = field(default_factory=list)
    local_components: list[list[Poly]] = field(default_factory=list)
    modes: list[int] = field(default_factory=list)  # indices (1-based) of the modes through it
    transition: str = ""
    # a Galois orbit of conjugate points: the primitive element t; the cone and the components are
    # then ideals of algebraic.ring = Q[configuration, t] containing the minimal polynomial of t
    algebraic: AlgebraicPoint | None = None
    cone_note: str = ""  # how the tangent cone was found when it is not the ideal of lowest forms


@dataclass
class Analysis:
    mechanism: Mechanism
    ring: PolyRing
    ideal: list[Poly]
    nvars: int  # configuration variables
    params: list[str]
    dim: int = -1
    mobility: int = -1
    radical: bool = False
    radical_decided: bool = False  # False: the analysis stopped before deciding (the report says so)
    complete_intersection: bool = False
    decomposed: bool = True  # False: without the motion modes (quick, or no strategy found them)
    modes: list[Mode] = field(default_factory=list)
    modes_by: str = "minimal primes of J"  # how the modes were found, for the report
    modes_found: bool = True  # False: every strategy of mech.stdlib.modes ran out
    mode_bound: int | None = None  # at most this many modes (Galois orbits of a slice)
    slice_orbits: list[int] | None = None  # the sizes of those orbits (each on one mode)
    mode_degrees: list[int] | None = None  # the modes' degrees, proved by a projection (mech.stdlib.modes)
    equidimensional: bool = True
    embedded: list[Embedded] | None = field(default_factory=list)  # None: not computed
    fitting_size: int = 0
    fitting: list[Poly] = field(default_factory=list)
    length_components: list[LengthComponent] = field(default_factory=list)
    length_factors: list[Poly] = field(default_factory=list)
    singular: list[SingularPoint] = field(default_factory=list)
    singular_done: bool = False  # the singular configurations were computed
    notes: list[str] = field(default_factory=list)  # strategies that ran out, budgets
    unfinished: list[str] = field(default_factory=list)  # steps not done (a partial report)
    running: str = ""  # the step running now (for the partial report)
    finite: Any = None  # dim J = 0: mech.stdlib.analysis_finite.Finite (assembly modes, Jacobian ranks)


#: CPU seconds of each real-point decision (of a mode, of a singular configuration).
REAL_BUDGET = 60.0


def timed(a: Analysis, name: str, budget: float | None, fn: Callable[..., Any], *args: Any) -> tuple[bool, Any]:
    """``fn(*args)`` as the stage ``name`` within ``budget`` seconds; when it runs out the
    step is noted unfinished and ``(False, None)`` returned."""
    a.running = name
    with stage(name) as st:
        ok, out = within(budget, fn, *args, cpu=True)
        if not ok:
            st.status = "budget"
            a.unfinished.append(f"{name}: ran out of its {budget:g} s budget")
    a.running = ""
    return ok, out


def real_points(a: Analysis, prime: list[Poly]) -> bool | None:
    """Whether ``V(prime)`` has real points (None: the decision ran out of :data:`REAL_BUDGET`)."""
    ok, real = timed(a, "real points", REAL_BUDGET, has_real_points, prime, a.ring)
    return real if ok else None
