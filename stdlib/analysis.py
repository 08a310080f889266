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

Steps 1–3 and the pipeline are here (:func:`global_analysis`, :func:`analyze`, :func:`run_analysis`); the
data in :mod:`mech.stdlib.analysis_data`, step 4 (the singular configurations and the points) in
:mod:`mech.stdlib.analysis_points`; the real-point decision is in :mod:`mech.stdlib.realpoints`, the report
formats in :mod:`mech.stdlib.reports`, the commands of ``LIB "mechanism.lib"`` in
:mod:`mech.stdlib.mechanism_commands`.
"""
from __future__ import annotations

from typing import ContextManager

from mech.dsl.errors import MechRuntimeError
from mech.dsl.limits import MechLimitError, remaining, within
from mech.kernel import Poly, PolyRing
from mech.kernel.collector import relaxed
from mech.kernel.factor import factorize
from mech.kernel.ideals import dimension, eliminate, ideals_equal, intersect, is_subset, is_unit, saturate_poly, std
from mech.kernel.primdec import min_ass_gtz, radical
from mech.kernel.progress import stage
from mech.kernel.projection import project_primes
from mech.stdlib.analysis_data import Analysis, Embedded, LengthComponent, Mode, SingularPoint, real_points
from mech.stdlib.analysis_finite import finite_analysis
from mech.stdlib.analysis_points import fitting_ideal, local_analysis
from mech.stdlib.mechanism import Mechanism, MechanismError
from mech.stdlib.modes import embedded_components, motion_modes
from mech.stdlib.realpoints import linear_point

__all__ = ["Analysis", "Embedded", "LengthComponent", "Mode", "SingularPoint", "analyze", "constraint_ideal",
           "global_analysis", "local_analysis", "mode_generators", "relaxed_gc", "require_complete",
           "require_numeric", "run_analysis"]


# ---------------------------------------------------------------- steps
def constraint_ideal(m: Mechanism) -> tuple[PolyRing, list[Poly], int]:
    """The ring, the constraint polynomials and the number of configuration variables."""
    R, gens = m.constraints()
    return R, gens, len(m.variables())


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


def _sorted_primes(primes: list[list[Poly]], R: PolyRing) -> list[list[Poly]]:
    """Reduced bases in minAssGTZ's order (decreasing dimension, then leading monomials), ties
    broken by the terms: the numbering of the modes does not depend on the strategy."""
    key = R.order.key
    bases = [std(P, R) for P in primes]
    return sorted(bases, key=lambda b: (-dimension(b, R), [key(g.lm()) for g in b],
                                        [[(key(e), c) for e, c in g.sorted_terms()] for g in b]))


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
        if is_unit(std(J, R)):
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
            [real_points(a, J)] if a.radical and a.complete_intersection else [None]
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
            md.real = real_points(a, md.prime)
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
        if is_unit(S):
            a.length_components.append(LengthComponent(P, None, [], []))
            continue
        if R.order.is_elimination_for(list(range(n))):  # S is already a basis of J + P for it
            E = [g for g in S if not any(any(e[:n]) for e in g.terms)]
        else:
            E = [g for g in eliminate(S, list(range(n)), R) if not g.is_zero()]
        sat = saturate_poly(E, lengths, R) if E else []
        cond = [] if is_unit(sat) else sat
        facs = []
        if len(cond) == 1:
            facs = [f for f, _ in factorize(cond[0])[1]]
            factors += [f for f in facs if f not in factors]
        a.length_components.append(LengthComponent(P, E, cond, facs))
    a.length_factors = factors


def mode_generators(a: Analysis, i: int) -> list[Poly]:
    """Generators of mode ``i`` (1-based) for computations that only need its ideal: J's own
    generators when J is radical with this one mode (then J is the mode's prime), fewer and of lower
    degree than the prime's reduced basis (the geared five-bar: 8 of degree <= 2 against 17 of degree
    <= 4; the algebra of its real circuits' critical points in 0.2 s against 20 s), else the prime's
    basis."""
    if a.radical and a.radical_decided and len(a.modes) == 1 and i == 1:
        return list(a.ideal)
    return a.modes[i - 1].prime


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
