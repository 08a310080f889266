"""Configuration-space analysis of a mechanism, following the paper's Sections 3–4.

* the constraint ideal ``J`` (``Mechanism.constraints``), its dimension (the mobility: for
  symbolic lengths the dimension of a generic fibre, ``dim J - #lengths``) and radicality;
* the motion modes: the primary decomposition of ``J`` (prime components with dimension and
  whether they have real points, decided exactly: :func:`has_real_points`); for a radical
  complete intersection the primes certified by a birational projection
  (``mech.kernel.projection``) when a sparse one passes its degree test, also over
  ``QQ(lengths)`` for symbolic lengths (the generic mechanism's modes; real points not decided);
* the singular variety (Theorem 1): ``J + I_r(dJ)`` with ``r = #configuration variables -
  mobility`` (the Fitting ideal of the Jacobian with respect to the configuration variables);
  when ``J`` is not radical or not equidimensional, the union of the components' singular
  loci and their pairwise intersections instead;
* with symbolic lengths, the conditions on the lengths: for each minimal prime ``P`` of the
  Fitting ideal, ``(J + P) ∩ Q[lengths]`` saturated by the product of the lengths (so
  components that need a vanishing length drop out), factorized;
* with numeric lengths, the singular configurations and at each one that is a point (rational,
  or a Galois orbit of algebraic points, over ``Q[t]/m(t)`` for a primitive element ``t``) the
  tangent cone, the local components and the type (Theorem 3), and whether a regular motion can
  pass from one local component to another (Remarks 2, 3: only if their tangent cones share a line).

The pipeline is here (the data, the steps, :func:`run_analysis`); the real-point decision is in
:mod:`mech.stdlib.realpoints`, the report formats in :mod:`mech.stdlib.reports`, the commands of
``LIB "mechanism.lib"`` in :mod:`mech.stdlib.mechanism_commands`.
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from typing import Any, Callable, ContextManager, Sequence

from mech.dsl.errors import MechRuntimeError
from mech.dsl.limits import MechLimitError, remaining, within
from mech.kernel import Poly, PolyRing
from mech.kernel.factor import factorize
from mech.kernel.collector import relaxed
from mech.kernel.cone_quadratic import linear_rank
from mech.kernel.groebner import normal_forms
from mech.kernel.ideals import (dimension, dp_ring, eliminate, ideals_equal, intersect, is_subset, move, saturate_poly,
                                std)
from mech.kernel.errors import DomainError
from mech.kernel.local import (AlgebraicPoint, SmoothSlices, dimension_over, local_components_over,
                               primitive_element, shift_to_origin, tangent_dim_over)
from mech.kernel.matrix import Matrix, minors
from mech.kernel.primdec import min_ass_gtz, radical
from mech.kernel.progress import stage
from mech.kernel.projection import project_primes
from mech.stdlib.analysis_finite import finite_analysis
from mech.stdlib.analysis_linear import (LinearReduction, component_cone, cone_at_point, cone_over_point, linear_reduction,
                                         min_ass_reduced, component_cone_over)
from mech.stdlib.mechanism import Mechanism, MechanismError
from mech.stdlib.modes import embedded_components, motion_modes
from mech.stdlib.realpoints import count_real_roots, has_real_points, linear_point


# ---------------------------------------------------------------- results
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


# ---------------------------------------------------------------- steps
def constraint_ideal(m: Mechanism) -> tuple[PolyRing, list[Poly], int]:
    """The ring, the constraint polynomials and the number of configuration variables."""
    R, gens = m.constraints()
    return R, gens, len(m.variables())


def _jacobian(gens: Sequence[Poly], nvars: int) -> Matrix:
    ring = gens[0].ring
    return Matrix.from_rows(ring, [[g.diff(j) for j in range(nvars)] for g in gens])


def fitting_ideal(gens: list[Poly], nvars: int, size: int) -> list[Poly]:
    """``I_size`` of the Jacobian with respect to the first ``nvars`` variables."""
    if size <= 0:
        return [gens[0].ring.one()]
    return [p for p in minors(_jacobian(gens, nvars), size) if not p.is_zero()]


def generically_reduced(J: list[Poly], R: PolyRing, d: int, nconfig: int | None = None) -> bool:
    """Serre's criterion for a complete intersection ``J`` (as many generators as its
    codimension; unmixed and Cohen–Macaulay): it is radical when its Jacobian singular locus
    ``J + I_c(dJ)`` has smaller dimension.  The minors of the derivatives by the first
    ``nconfig`` variables alone (fewer, and the analysis needs them anyway) generate a smaller
    ideal, so a smaller dimension with them is enough.  False: not decided."""
    c = R.nvars - d
    if len(J) != c:
        return False
    return any(dimension(list(J) + fitting_ideal(J, k, c), R) < d for k in sorted({nconfig or R.nvars, R.nvars}))


def _unit(basis: list[Poly]) -> bool:
    return any(g.is_constant() and not g.is_zero() for g in basis)


def _sorted_primes(primes: list[list[Poly]], R: PolyRing) -> list[list[Poly]]:
    """Reduced bases in minAssGTZ's order (decreasing dimension, then leading monomials), ties
    broken by the terms: the numbering of the modes does not depend on the strategy."""
    key = R.order.key
    bases = [std(P, R) for P in primes]
    return sorted(bases, key=lambda b: (-dimension(b, R), [key(g.lm()) for g in b],
                                        [[(key(e), c) for e, c in g.sorted_terms()] for g in b]))


def _timed(a: Analysis, name: str, budget: float | None, fn: Callable[..., Any], *args: Any) -> tuple[bool, Any]:
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


def _real(a: Analysis, prime: list[Poly]) -> bool | None:
    ok, real = _timed(a, "real points", REAL_BUDGET, has_real_points, prime, a.ring)
    return real if ok else None


#: Budgets (CPU seconds) of the steps after the motion modes (those of the modes' strategies
#: are in mech.stdlib.modes.STRATEGIES).
REAL_BUDGET = 60.0
SINGULAR_BUDGET = 120.0
POINT_BUDGET = 60.0


def global_analysis(m: Mechanism, decompose: bool = True, a: Analysis | None = None) -> Analysis:
    """Steps 1–2 (and, with symbolic lengths, step 3).  ``decompose=False`` skips the motion
    modes (a quick analysis, for a radical complete intersection only).  ``a``: an analysis
    to fill in (kept partly filled when a time limit interrupts)."""
    with stage("constraints"):
        R, J, n = constraint_ideal(m)
    params = list(R.names[n:])
    a = a or Analysis(m, R, J, n, params)
    a.ring, a.ideal, a.nvars, a.params, a.decomposed = R, J, n, params, decompose
    a.running = "dimension"
    with stage("dimension"):
        if _unit(std(J, R)):
            raise MechanismError(f"{m.name}: the configuration space is empty (the constraints have no "
                                 "solution, not even a complex one)")
        a.dim = dimension(J, R)
    a.mobility = a.dim - len(params)
    a.complete_intersection = len(J) == R.nvars - a.dim
    if a.dim == 0 and not params and finite_analysis(a, Mode):  # finitely many configurations: the quotient algebra
        return a
    a.running = "radicality"
    with stage("radicality"):
        a.radical = a.radical_decided = generically_reduced(J, R, a.dim, n)
        if not a.radical and (params or not decompose):
            a.radical, a.radical_decided = ideals_equal(radical(J, R), J, R), True
    if not decompose and not params and not (a.radical and a.complete_intersection):
        raise MechanismError(f"{m.name}: the quick analysis needs a radical complete intersection")
    if not params:
        _numeric_modes(a) if decompose else None
        if decompose and not a.modes_found and not (a.radical and a.complete_intersection):
            a.decomposed = False
        reals = [md.real for md in a.modes] if a.modes_found and decompose else \
            [_real(a, J)] if a.radical and a.complete_intersection else [None]
        # a radical complete intersection is equidimensional: the critical point method applies to J
        if all(r is False for r in reals):
            raise MechanismError(f"{m.name}: the mechanism does not close: the configuration space "
                                 "has no real point (the lengths are inconsistent)")
    a.fitting_size = n - a.mobility
    with stage("fitting ideal"):
        a.fitting = fitting_ideal(J, n, a.fitting_size)
    if params:
        with stage("length conditions"):
            _length_conditions(a)
        with stage("decomposition", detail="over Q(lengths)"):
            found = project_primes(J, R, len(params), _SPARSE) if decompose and a.radical and \
                a.complete_intersection and n <= _SYMBOLIC_CONFIG else None
        a.modes = [Mode(P, P, dimension(P, R) - len(params), None) for P in found.primes] if found else []
    return a


_SPARSE = 2  # projections tried (the sparse ones of kernel.projection.candidate_forms)
# symbolic modes only up to this many configuration variables: the four-bar's 6 (and 3 lengths) take
# 1 s; the five-bar's 8 did not finish in minutes, with one symbolic length as with four
_SYMBOLIC_CONFIG = 6


def _numeric_modes(a: Analysis) -> None:
    """Step 2 for numeric lengths: the motion modes (the minimal primes of J, by the strategy
    chain of :mod:`mech.stdlib.modes`), whether J is radical (when Serre's test did not prove
    it), the modes' real points and, for a non-radical J, its embedded components."""
    R, J = a.ring, a.ideal
    a.running, a.modes_found = "decomposition", False  # not found until a strategy finishes
    primes = motion_modes(a)
    a.running, a.modes_found = "", primes is not None
    if primes is None:
        a.modes_found, a.decomposed = False, False
        a.unfinished.append("motion modes: no strategy found them within its budget")
        return
    primes = _sorted_primes(primes, R)
    if not a.radical:
        with stage("radicality", detail="the intersection of the minimal primes"):
            a.radical = ideals_equal(intersect(*primes, ring=R), J, R)
    a.radical_decided = True
    dims = [dimension(P, R) for P in primes]
    a.equidimensional = len(set(dims)) == 1
    # the modes first, their real points after: a limit during the real points keeps the modes
    a.modes.extend(Mode(P, P if a.radical else None, d, None) for P, d in zip(primes, dims))
    with stage("real points", total=len(primes)) as st:
        for k, md in enumerate(a.modes):
            st.step(k, f"mode {k + 1}")
            md.real = _real(a, md.prime)
    if not a.radical:
        comps = embedded_components(a)
        a.embedded = None if comps is None else [
            Embedded(p, q, dimension(p, R), [i for i, md in enumerate(a.modes, 1) if is_subset(md.prime, p, R)],
                     tuple(pt) if (pt := linear_point(p)) else None) for q, p in comps]


def _length_conditions(a: Analysis) -> None:
    R, n = a.ring, a.nvars
    lengths = R.one()
    for x in R.gens()[n:]:
        lengths = lengths * x
    factors: list[Poly] = []
    for P in min_ass_gtz(a.fitting, R):
        S = std(list(a.ideal) + list(P), R)
        if _unit(S):
            a.length_components.append(LengthComponent(P, None, [], []))
            continue
        if R.order.is_elimination_for(list(range(n))):  # S is already a basis of J + P for it
            E = [g for g in S if not any(any(e[:n]) for e in g.terms)]
        else:
            E = [g for g in eliminate(S, list(range(n)), R) if not g.is_zero()]
        sat = saturate_poly(E, lengths, R) if E else []
        cond = [] if _unit(sat) else sat
        facs = []
        if len(cond) == 1:
            facs = [f for f, _ in factorize(cond[0])[1]]
            factors += [f for f in facs if f not in factors]
        a.length_components.append(LengthComponent(P, E, cond, facs))
    a.length_factors = factors


def singular_primes(a: Analysis) -> list[list[Poly]]:
    """The minimal primes of the singular variety (numeric lengths): Theorem 1's
    ``J + I_r(dJ)`` for a radical equidimensional J, otherwise the singular loci of the modes
    and their pairwise intersections (a singular point of the configuration space, not a point
    where only the constraints drop rank: those are J's embedded components).  For a radical J
    a mode ``P`` of codimension ``c`` is the only component through a point off the other modes,
    where J's generators generate ``P`` locally: the Jacobian criterion with ``I_c(dJ)`` (Peaucellier's
    modes have 16-20 generators: their own minors of size 12-13 would be millions)."""
    R, n = a.ring, a.nvars
    primes = [md.prime for md in a.modes]
    if a.radical and (a.complete_intersection or a.equidimensional):
        return min_ass_gtz(list(a.ideal) + _reduced(a.fitting, a.ideal, R), R)
    parts: list[list[Poly]] = []
    fitting = {n - a.mobility: a.fitting}
    for i, P in enumerate(primes):
        codim = n - dimension(P, R)
        basis = std(P, R)
        if a.radical:  # where P is the only mode, J = P locally: J's Jacobian decides (fewer, smaller minors)
            if codim not in fitting:
                fitting[codim] = fitting_ideal(a.ideal, n, codim)
            parts += min_ass_reduced(list(P) + _reduced(fitting[codim], basis, R), R)
        else:
            parts += min_ass_gtz(list(P) + _reduced(fitting_ideal(basis, n, codim), basis, R), R)
        for Q in primes[i + 1:]:
            parts += (min_ass_reduced if a.radical else min_ass_gtz)(list(P) + list(Q), R)
    out: list[list[Poly]] = []
    for p in parts:
        if _unit(p) or any(ideals_equal(p, q, R) for q in out):
            continue
        out.append(p)
    return [p for p in out if not any(q is not p and _contains(q, p, R) for q in out)]


def _reduced(minors: list[Poly], ideal: list[Poly], R: PolyRing) -> list[Poly]:
    """The minors' normal forms modulo ``ideal`` (``ideal + minors`` unchanged): the Jacobian
    minors of a spatial loop have 10^5 terms, their normal forms 10^3 (Bricard's 6R loop)."""
    return [r for r in normal_forms(minors, std(ideal, R)) if not r.is_zero()]


def _contains(small: list[Poly], big: list[Poly], R: PolyRing) -> bool:
    """V(big) ⊊ V(small)?  (small ⊂ big as ideals, not equal)."""
    return is_subset(small, big, R) and not ideals_equal(small, big, R)


def _variety(a: Analysis) -> list[Poly]:
    """Generators of the configuration space's ideal: J, or for a non-radical J the
    intersection of its minimal primes (the local analysis is of the variety)."""
    if a.radical or not a.modes:
        return a.ideal
    return intersect(*[md.prime for md in a.modes], ring=a.ring)


def local_analysis(a: Analysis) -> list[SingularPoint]:
    """Step 4: the singular configurations of a mechanism with numeric lengths, each within
    :data:`POINT_BUDGET` (all of them within :data:`SINGULAR_BUDGET`)."""
    R = a.ring
    if not a.modes_found and not (a.radical and a.complete_intersection):
        a.unfinished.append("singular configurations: they need the motion modes (J is not a radical "
                            "complete intersection)")
        a.singular_done = True
        return []
    ok, primes = _timed(a, "singular configurations", SINGULAR_BUDGET, singular_primes, a)
    if not ok:
        a.singular_done = True
        return []
    minimal = _minimal_modes(a) if a.decomposed else []
    shared = _Shared(_variety(a), None, minimal, [SmoothSlices(md.prime) for md in minimal])
    shared.lr = linear_reduction(shared.variety, R)  # the points' cones in the ring without linear variables
    out = a.singular = []
    with stage("points", total=len(primes)) as st:
        for k, P in enumerate(primes):
            st.step(k, f"singular configuration {k + 1} of {len(primes)}")
            out.append(_singular_point(a, P))
    at = [(k, sp) for k, sp in enumerate(out) if sp.point is not None or sp.algebraic is not None]
    with stage("local components", total=len(at)) as st:
        for j, (k, sp) in enumerate(at):
            st.step(j, f"q{k + 1}")
            ok, _ = _timed(a, f"local components at q{k + 1}", POINT_BUDGET, _components_at, a, sp, shared)
            if not ok:
                sp.kind = "not classified (its local components ran out of their budget)"
    with stage("tangent cones", total=len(at)) as st:
        for j, (k, sp) in enumerate(at):
            st.step(j, f"q{k + 1}")
            _cone_at(a, sp, k, shared)
    for e in a.embedded or []:
        e.singular = any(is_subset(sp.prime, e.prime, R) for sp in out)
    a.singular_done = True
    return out


def _singular_point(a: Analysis, P: list[Poly]) -> SingularPoint:
    """A singular configuration: its dimension, its point (rational coordinates, or a primitive element
    for a Galois orbit of algebraic points), whether it is real and the modes through it."""
    R = a.ring
    d = dimension(P, R)
    point = _rational_point(P) or linear_point(P)
    sp = SingularPoint(P, tuple(point) if point else None, d, True if point else None)
    if point is None and d == 0:  # a Galois orbit of algebraic points: real iff m(t) has a real root
        ok, sp.algebraic = _timed(a, "real points", REAL_BUDGET, primitive_element, P, R)
        sp.real = bool(count_real_roots(sp.algebraic.minpoly) > 0) if ok else None
    elif point is None:
        sp.real = _real(a, P)
    sp.modes = [i for i, md in enumerate(a.modes, 1) if _on(md.prime, point)] if point else \
        [i for i, md in enumerate(a.modes, 1) if is_subset(md.prime, P, R)]
    return sp


def _rational_point(prime: list[Poly]) -> list | None:
    """The point of a prime whose reduced basis is ``x_i - c_i`` for every variable (as minAssGTZ
    gives a rational point), read off; None otherwise (:func:`linear_point` decides then)."""
    ring = prime[0].ring if prime else None
    if ring is None or len(prime) != ring.nvars:
        return None
    point: list = [None] * ring.nvars
    for g in prime:
        lm = g.lm()
        if sum(lm) != 1 or len(g.terms) > 2 or any(sum(e) > 0 and e != lm for e in g.terms):
            return None
        i = lm.index(1)
        point[i] = -g.terms.get(ring.zero_exp, ring.field.zero) / g.terms[lm]
    return None if any(v is None for v in point) else point


def _on(prime: list[Poly], point: Sequence) -> bool:
    """Whether the rational point lies on ``V(prime)``."""
    p = [prime[0].ring.field(v) for v in point] if prime else []
    return all(g.evaluate(p) == 0 for g in prime)


@dataclass
class _Shared:
    """What the local analyses of all the singular points share: the variety's generators, their
    :func:`linear_reduction`, the minimal motion modes (empty without the modes) and their
    :class:`~mech.kernel.local.SmoothSlices` (the certificates that a mode stays prime over a field)."""

    variety: list[Poly]
    lr: LinearReduction | None
    minimal: list[Mode]
    slices: list[SmoothSlices]


def _components_at(a: Analysis, sp: SingularPoint, shared: _Shared) -> None:
    """The local components at a singular configuration that is a point (rational or algebraic), the kind
    of point and the transition test (their tangent cones)."""
    if not a.decomposed:
        sp.kind = _no_components(a)
    elif sp.point is None:
        _algebraic_components(sp, shared)
    else:
        through = _modes_through(shared.minimal, sp.point)
        sp.local_components = [shift_to_origin(md.prime, sp.point) for md in through]
        R = a.ring
        sp.kind = _kind_at(sp.local_components, [md.dim for md in through], lambda c: R.nvars - linear_rank(c, R))
        sp.transition = _transition(_component_cones(sp, shared, a.ring) if len(through) > 1 else [])


def _component_cones(sp: SingularPoint, shared: _Shared, R: PolyRing) -> list[list[Poly]]:
    """The tangent cones of the local components at a rational point (each of the dimension of its mode)."""
    dims = [md.dim for md in _modes_through(shared.minimal, sp.point)]
    return [component_cone(c, d, R) for c, d in zip(sp.local_components, dims)]


def _cone_at(a: Analysis, sp: SingularPoint, k: int, shared: _Shared) -> None:
    """The tangent cone of the variety at the singular configuration ``q{k + 1}`` (a point): at a rational
    point with several local components within :data:`CONE_BUDGET` (else the union of their cones, as a
    set), otherwise within :data:`POINT_BUDGET`."""
    variety, lr = shared.variety, shared.lr
    if sp.point is None:
        ok, cone = _timed(a, f"tangent cone at q{k + 1}", POINT_BUDGET, cone_over_point, variety, lr, sp.algebraic)
    elif a.decomposed and sp.local_components:
        ok, cone = within(CONE_BUDGET, cone_at_point, variety, lr, sp.point, cpu=True)
        if not ok:
            cone = _union_cone(_component_cones(sp, shared, a.ring))
            sp.cone_note = (f"as a set: the union of the local components' cones (the ideal of lowest "
                            f"forms ran out of its {CONE_BUDGET:g} s budget)")
            ok = True
    else:
        ok, cone = _timed(a, f"tangent cone at q{k + 1}", POINT_BUDGET, cone_at_point, variety, lr, sp.point)
    if ok:
        sp.tangent_cone = cone
    else:
        sp.cone_note = f"not computed: it ran out of its {POINT_BUDGET:g} s budget"


#: CPU seconds for the tangent cone of J at a singular configuration (a local standard basis: Bricard's
#: 6R loop's does not finish in minutes, in Singular neither), after its kind and local components.
CONE_BUDGET = 20.0


def _modes_through(modes: list[Mode], point: tuple) -> list[Mode]:
    """The modes whose variety contains the rational point: their primes centred there are the local
    components (translation keeps a dp basis a dp basis; the reports print reduced bases)."""
    return [md for md in modes if _on(md.prime, point)]


def _kind_at(components: list[list[Poly]], dims: list[int], tangent_dim: Callable[[list[Poly]], int]) -> str:
    """Theorem 3 and Definition 3 (``kernel.local.classify_point``'s kind): several components meet, or
    the one component's tangent space at the origin (``tangent_dim`` of its generators) has its dimension."""
    if len(components) > 1:
        return "components meet"
    return "regular" if tangent_dim(components[0]) == dims[0] else "singular"


def _union_cone(cones: list[list[Poly]]) -> list[Poly]:
    """The tangent cone as a set, the union of the components' cones (their intersection, in dp)."""
    glob = dp_ring(cones[0][0].ring)
    return move(intersect(*(move(c, glob) for c in cones), ring=glob), cones[0][0].ring)


def _algebraic_components(sp: SingularPoint, shared: _Shared) -> None:
    """The local components at the conjugate points of a zero-dimensional prime that is not a rational
    point (``sp.algebraic``: a primitive element ``t``), over ``K = Q[t]/m(t)``, from the motion modes
    (the minimal primes of J over Q); the kind and the transition test."""
    pt = sp.algebraic
    # kernel.local.classify_algebraic_point's kind, without the tangent space of the components' union
    # (their intersection over K: 0.4 s on Watt I-B), which only matters for one component
    comps = local_components_over(None, pt, [md.prime for md in shared.minimal], min_ass_reduced, shared.slices)
    if not comps:
        raise DomainError("no component through the points: primes must be the ideal's minimal primes")
    sp.local_components = comps
    dims = [dimension_over(c, pt) for c in comps]
    origin = [pt.ring.zero()] * (pt.ring.nvars - 1)
    sp.kind = _kind_at(comps, dims, lambda c: tangent_dim_over(c, origin, pt.ring, pt.minpoly, dims[0]))
    sp.transition = _transition([component_cone_over(c, pt, d) for c, d in zip(comps, dims)] if len(comps) > 1 else [])


def _no_components(a: Analysis) -> str:
    why = "the motion modes were not found" if any(u.startswith("motion modes") for u in a.unfinished) \
        else "quick analysis"
    return f"singular point (local components not computed: {why})"


def mode_generators(a: Analysis, i: int) -> list[Poly]:
    """Generators of mode ``i`` (1-based) for computations that only need its ideal: J's own
    generators when J is radical with this one mode (then J is the mode's prime), fewer and of lower
    degree than the prime's reduced basis (the geared five-bar: 8 of degree <= 2 against 17 of degree
    <= 4; the algebra of its real circuits' critical points in 0.2 s against 20 s), else the prime's
    basis."""
    if a.radical and a.radical_decided and len(a.modes) == 1 and i == 1:
        return list(a.ideal)
    return a.modes[i - 1].prime


def _minimal_modes(a: Analysis) -> list[Mode]:
    """The motion modes without the embedded ones (their primes are the minimal primes of J)."""
    # a prime contains another prime only if it has a smaller dimension (distinct primes)
    return [md for md in a.modes if not any(_contains(Q.prime, md.prime, a.ring) for Q in a.modes if Q.dim > md.dim)]


def _transition(cones: list[list[Poly]]) -> str:
    """Remarks 2 and 3: a regular motion (non-zero velocity) from one local component to
    another needs a common tangent direction: their tangent ``cones`` (one per local component;
    none given when there is one component) must meet outside 0."""
    if len(cones) < 2:
        return "one local component: no change of motion mode here"
    shared = []
    glob = dp_ring(cones[0][0].ring)
    for (i, a), (j, b) in itertools.combinations(enumerate(cones, 1), 2):
        if _meet_outside_zero(move(list(a) + list(b), glob), glob):
            shared.append(f"{i} and {j}")
    if not shared:
        return ("the local components meet transversally (their tangent cones share no line): "
                "a regular motion cannot pass from one motion mode to another here")
    return ("local components " + ", ".join(shared) + " share a tangent direction: a regular "
            "motion may pass between them")


def _meet_outside_zero(cones: list[Poly], ring: PolyRing) -> bool:
    """Whether the cones' union of generators (homogeneous) vanishes on a line: for linear forms
    (tangent spaces) whether their rank is below the number of variables, else a positive dimension."""
    if all(g.total_degree() == 1 for g in cones):
        return linear_rank(cones, ring) < ring.nvars
    return dimension(cones, ring) > 0


def analyze(m: Mechanism) -> Analysis:
    """All steps."""
    a = global_analysis(m)
    if not a.params and not a.singular_done:
        local_analysis(a)
    return a


# ---------------------------------------------------------------- running it
#: Allocations between two collections of Python's young generation during an analysis (default 700).
YOUNG_THRESHOLD = 20000


def relaxed_gc() -> ContextManager[None]:
    """Python's cyclic garbage collector less often while an analysis runs: its many small bases,
    polynomials and real roots are freed by reference counting, but every 700 allocations a
    collection walks the young objects and, through the older generations, the session's (a tenth
    of the four-bar example's time)."""
    return relaxed(YOUNG_THRESHOLD)


_CACHE: dict[str, Analysis] = {}
RESERVE = 0.1  # the share of the statement's remaining time kept for the partial report (also after a late budget)


def run_analysis(m: Mechanism, local: bool = True, decompose: bool = True) -> Analysis:
    """The (cached) analysis of ``m`` (step 4 too with ``local``; ``decompose=False``: quick); bad
    mechanisms and empty configuration spaces become errors.  Under a statement time limit
    (``mech --timeout``) the analysis stops before it with what it finished: ``a.unfinished``
    says what not (:func:`require_complete`)."""
    key = f"{m} {decompose}"
    a = _CACHE.get(key)
    left = remaining()
    budget = None if left is None else max(left * (1 - RESERVE), 0.05)
    holder = a or Analysis(m, *constraint_ideal(m), [])

    def steps() -> None:
        if a is None:
            global_analysis(m, decompose, holder)
        if local and not holder.params and not holder.singular_done:
            local_analysis(holder)
    try:
        with stage("analysis"), relaxed_gc():
            ok, _ = within(budget, steps, reserve=None if left is None else left * RESERVE)
    except MechanismError as e:
        raise MechRuntimeError(str(e)) from None
    if not ok:
        holder.unfinished.append(f"{holder.running or 'the analysis'}: interrupted by the time limit"
                                 + (", and the steps after it" if holder.running else ""))
        _CACHE.pop(key, None)
        return holder
    _CACHE[key] = holder
    return holder


def require_complete(a: Analysis, what: str) -> None:
    """A :class:`MechLimitError` when a time limit cut the analysis short."""
    if any("time limit" in u for u in a.unfinished):
        raise MechLimitError(f"time limit exceeded in {what}: the analysis did not finish "
                             f"({'; '.join(a.unfinished)})")


def require_numeric(a: Analysis, what: str) -> None:
    if a.params:
        raise MechRuntimeError(f"{what} needs numeric lengths: the mechanism has symbolic lengths "
                               f"{','.join(a.params)} (use setLengths(m, ...))")
