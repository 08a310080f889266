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
from typing import Callable, Sequence

from mech.dsl.errors import MechRuntimeError
from mech.kernel import Poly, PolyRing
from mech.kernel.factor import factorize
from mech.kernel.groebner import normal_form
from mech.kernel.ideals import (dimension, dp_ring, eliminate, ideals_equal, is_subset, move, saturate_poly,
                                std)
from mech.kernel.local import (AlgebraicPoint, centre_at, classify_algebraic_point, classify_point,
                               primitive_element, tangent_cone, tangent_cone_at, tangent_cone_over)
from mech.kernel.matrix import Matrix, minors
from mech.kernel.primdec import min_ass_gtz, primdec_gtz, radical
from mech.kernel.projection import project_primes
from mech.stdlib.mechanism import Mechanism, MechanismError
from mech.stdlib.realpoints import has_real_points, linear_point


# ---------------------------------------------------------------- results
@dataclass
class Mode:
    """A motion mode: a prime component of the constraint ideal (with symbolic lengths: over
    QQ(lengths), contracted to QQ[x, lengths]; ``dim`` over QQ(lengths), ``real`` None)."""

    prime: list[Poly]
    primary: list[Poly]
    dim: int
    real: bool | None


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
    real: bool
    kind: str = ""
    tangent_cone: list[Poly] = field(default_factory=list)
    local_components: list[list[Poly]] = field(default_factory=list)
    modes: list[int] = field(default_factory=list)  # indices (1-based) of the modes through it
    transition: str = ""
    # a Galois orbit of conjugate points: the primitive element t; the cone and the components are
    # then ideals of algebraic.ring = Q[configuration, t] containing the minimal polynomial of t
    algebraic: AlgebraicPoint | None = None


@dataclass
class Analysis:
    mechanism: Mechanism
    ring: PolyRing
    ideal: list[Poly]
    nvars: int  # configuration variables
    params: list[str]
    dim: int
    mobility: int
    radical: bool
    complete_intersection: bool
    decomposed: bool = True  # False: a quick analysis without the primary decomposition of J
    modes: list[Mode] = field(default_factory=list)
    modes_by: str = "primary decomposition of J"  # how the modes were found, for the report
    fitting_size: int = 0
    fitting: list[Poly] = field(default_factory=list)
    length_components: list[LengthComponent] = field(default_factory=list)
    length_factors: list[Poly] = field(default_factory=list)
    singular: list[SingularPoint] = field(default_factory=list)


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


def is_radical(J: list[Poly], R: PolyRing, nconfig: int | None = None) -> bool:
    """Whether ``J`` is radical.  Cheap sufficient test first: a complete intersection (as many
    generators as its codimension) is unmixed and Cohen–Macaulay, so it is radical when it is
    generically reduced, i.e. when its Jacobian singular locus ``J + I_c(dJ)`` has smaller
    dimension (Serre's criterion); otherwise ``√J`` is computed and compared.  The minors of the
    derivatives by the first ``nconfig`` variables alone (fewer, and the analysis needs them
    anyway) generate a smaller ideal, so a smaller dimension with them is enough."""
    d = dimension(J, R)
    c = R.nvars - d
    if len(J) == c:
        for k in sorted({nconfig or R.nvars, R.nvars}):
            if dimension(list(J) + fitting_ideal(J, k, c), R) < d:
                return True
    return ideals_equal(radical(J, R), J, R)


def _unit(basis: list[Poly]) -> bool:
    return any(g.is_constant() and not g.is_zero() for g in basis)


def global_analysis(m: Mechanism, decompose: bool = True) -> Analysis:
    """Steps 1–2 (and, with symbolic lengths, step 3).  ``decompose=False`` skips the primary
    decomposition of J (a quick analysis, for a radical complete intersection only)."""
    R, J, n = constraint_ideal(m)
    params = list(R.names[n:])
    basis = std(J, R)
    if _unit(basis):
        raise MechanismError(f"{m.name}: the configuration space is empty (the constraints have no "
                             "solution, not even a complex one)")
    d = dimension(J, R)
    a = Analysis(m, R, J, n, params, d, d - len(params), is_radical(J, R, n), len(J) == R.nvars - d,
                 decompose)
    if not decompose and not (a.radical and a.complete_intersection):
        raise MechanismError(f"{m.name}: the quick analysis needs a radical complete intersection")
    if not params:
        for primary, prime in _decomposition(a) if decompose else []:
            a.modes.append(Mode(prime, primary, dimension(prime, R), has_real_points(prime, R)))
        # a radical complete intersection is equidimensional: the critical point method applies to J
        if not (any(md.real for md in a.modes) if decompose else has_real_points(J, R)):
            raise MechanismError(f"{m.name}: the mechanism does not close: the configuration space "
                                 "has no real point (the lengths are inconsistent)")
    a.fitting_size = n - a.mobility
    a.fitting = fitting_ideal(J, n, a.fitting_size)
    if params:
        _length_conditions(a)
        found = project_primes(J, R, len(params), _SPARSE) if decompose and a.radical and \
            a.complete_intersection and n <= _SYMBOLIC_CONFIG else None
        a.modes = [Mode(P, P, dimension(P, R) - len(params), None) for P in found.primes] if found else []
    return a


_SPARSE = 2  # projections tried (the sparse ones of kernel.projection.candidate_forms)
# symbolic modes only up to this many configuration variables: the four-bar's 6 (and 3 lengths) take
# 1 s; the five-bar's 8 did not finish in minutes, with one symbolic length as with four
_SYMBOLIC_CONFIG = 6


def _decomposition(a: Analysis) -> list[tuple[list[Poly], list[Poly]]]:
    """(primary, prime) pairs of J: ``[(J, J)]`` when a sparse birational projection
    (kernel.projection) proves a radical complete intersection (unmixed) prime; otherwise
    primdecGTZ (also when the projection finds several primes: primdecGTZ's numbering of the
    modes is kept, as its order of primes with equal leading monomials is its own)."""
    if a.radical and a.complete_intersection:
        found = project_primes(a.ideal, a.ring, 0, _SPARSE)
        if found is not None and len(found.primes) == 1:
            a.modes_by = "J is prime, certified by a birational projection"
            return [(found.primes[0], found.primes[0])]
    return primdec_gtz(a.ideal, a.ring)


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
    """The minimal primes of the singular variety (numeric lengths)."""
    R, n = a.ring, a.nvars
    primes = [md.prime for md in a.modes]
    dims = {md.dim for md in a.modes}
    if a.radical and (a.complete_intersection or len(dims) == 1):
        return min_ass_gtz(list(a.ideal) + a.fitting, R)
    parts: list[list[Poly]] = []
    for i, P in enumerate(primes):
        codim = n - dimension(P, R)
        parts += min_ass_gtz(list(P) + fitting_ideal(std(P, R), n, codim), R)
        for Q in primes[i + 1:]:
            parts += min_ass_gtz(list(P) + list(Q), R)
    out: list[list[Poly]] = []
    for p in parts:
        if _unit(p) or any(ideals_equal(p, q, R) for q in out):
            continue
        out.append(p)
    return [p for p in out if not any(q is not p and _contains(q, p, R) for q in out)]


def _contains(small: list[Poly], big: list[Poly], R: PolyRing) -> bool:
    """V(big) ⊊ V(small)?  (small ⊂ big as ideals, not equal)."""
    return is_subset(small, big, R) and not ideals_equal(small, big, R)


def local_analysis(a: Analysis) -> list[SingularPoint]:
    """Step 4: the singular configurations of a mechanism with numeric lengths."""
    R = a.ring
    out = []
    for P in singular_primes(a):
        d = dimension(P, R)
        point = linear_point(P)
        sp = SingularPoint(P, tuple(point) if point else None, d,
                           True if point else has_real_points(P, R))
        sp.modes = [i for i, md in enumerate(a.modes, 1)
                    if all(_vanishes(g, P, R) for g in md.prime)]
        if point is not None and not a.decomposed:
            sp.kind = "singular point (local components not computed: quick analysis)"
            sp.tangent_cone = tangent_cone_at(a.ideal, point)
        elif point is not None:
            info = classify_point(a.ideal, point, _minimal_modes(a))
            sp.kind = info.kind
            sp.tangent_cone = info.tangent_cone
            sp.local_components = info.components
            sp.transition = _transition(info.components, R)
        elif d == 0:
            _algebraic_local(a, sp)
        out.append(sp)
    a.singular = out
    return out


def _algebraic_local(a: Analysis, sp: SingularPoint) -> None:
    """Step 4 at the conjugate points of a zero-dimensional prime that is not a rational point:
    over ``K = Q[t]/m(t)`` for a primitive element ``t``, with the motion modes (the minimal
    primes of J over Q) as the starting point of the local components over K."""
    pt = sp.algebraic = primitive_element(sp.prime, a.ring)
    if not a.decomposed:
        sp.kind = "singular point (local components not computed: quick analysis)"
        sp.tangent_cone = tangent_cone_over(centre_at(a.ideal, pt), pt)
        return
    info = classify_algebraic_point(a.ideal, pt, _minimal_modes(a))
    sp.kind, sp.tangent_cone, sp.local_components = info.kind, info.tangent_cone, info.components
    sp.transition = _transition(info.components, pt.ring, lambda c: tangent_cone_over(c, pt))


def _minimal_modes(a: Analysis) -> list[list[Poly]]:
    """The minimal primes of J: the motion modes' primes without the embedded ones."""
    primes = [md.prime for md in a.modes]
    return [P for P in primes if not any(_contains(Q, P, a.ring) for Q in primes if Q is not P)]


def _vanishes(g: Poly, P: list[Poly], R: PolyRing) -> bool:
    return normal_form(g, std(P, R)).is_zero()


def _transition(components: list[list[Poly]], R: PolyRing,
                cone: Callable[[list[Poly]], list[Poly]] | None = None) -> str:
    """Remarks 2 and 3: a regular motion (non-zero velocity) from one local component to
    another needs a common tangent direction: their tangent cones must meet outside 0
    (``cone``: the tangent cone function, by default over Q)."""
    if len(components) < 2:
        return "one local component: no change of motion mode here"
    cones = [cone(c) if cone else tangent_cone(c, c[0].ring) for c in components]
    shared = []
    glob = dp_ring(cones[0][0].ring)
    for (i, a), (j, b) in itertools.combinations(enumerate(cones, 1), 2):
        if dimension(move(list(a) + list(b), glob), glob) > 0:
            shared.append(f"{i} and {j}")
    if not shared:
        return ("the local components meet transversally (their tangent cones share no line): "
                "a regular motion cannot pass from one motion mode to another here")
    return ("local components " + ", ".join(shared) + " share a tangent direction: a regular "
            "motion may pass between them")


def analyze(m: Mechanism) -> Analysis:
    """All steps."""
    a = global_analysis(m)
    if not a.params:
        local_analysis(a)
    return a


# ---------------------------------------------------------------- running it
_CACHE: dict[str, Analysis] = {}


def run_analysis(m: Mechanism, local: bool = True, decompose: bool = True) -> Analysis:
    """The (cached) analysis of ``m`` (step 4 too with ``local``; ``decompose=False``: quick); bad
    mechanisms and empty configuration spaces become errors."""
    key = f"{m} {decompose}"
    a = _CACHE.get(key)
    try:
        if a is None:
            a = _CACHE[key] = global_analysis(m, decompose)
        if local and not a.params and not a.singular:
            local_analysis(a)
    except MechanismError as e:
        raise MechRuntimeError(str(e)) from None
    return a


def require_numeric(a: Analysis, what: str) -> None:
    if a.params:
        raise MechRuntimeError(f"{what} needs numeric lengths: the mechanism has symbolic lengths "
                               f"{','.join(a.params)} (use setLengths(m, ...))")
