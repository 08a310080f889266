"""Step 4 of a mechanism's analysis (:mod:`mech.stdlib.analysis`), for numeric lengths: the singular
configurations (Theorem 1: the minimal primes of ``J + I_r(dJ)``, the Fitting ideal of the Jacobian;
for a non-radical or not equidimensional J the modes' singular loci and their pairwise intersections)
and at each one that is a point (rational, or a Galois orbit of algebraic points, over ``Q[t]/m(t)``
for a primitive element ``t``) the local components, the kind of point (Theorem 3), whether a regular
motion can pass from one local component to another (Remarks 2, 3: only if their tangent cones share
a line) and the tangent cone."""
from __future__ import annotations

import itertools
from dataclasses import dataclass
from typing import Callable, Sequence

from mech.dsl.limits import within
from mech.kernel import Poly, PolyRing
from mech.kernel.cone_quadratic import linear_rank
from mech.kernel.errors import DomainError
from mech.kernel.groebner import normal_forms
from mech.kernel.ideals import dimension, dp_ring, ideals_equal, intersect, is_subset, is_unit, move, std
from mech.kernel.local import (SmoothSlices, dimension_over, local_components_over, primitive_element,
                               shift_to_origin, tangent_dim_over)
from mech.kernel.matrix import Matrix, minors
from mech.kernel.primdec import min_ass_gtz
from mech.kernel.progress import stage
from mech.stdlib.analysis_data import REAL_BUDGET, Analysis, Mode, SingularPoint, real_points, timed
from mech.stdlib.analysis_linear import (LinearReduction, component_cone, component_cone_over, cone_at_point,
                                         cone_over_point, linear_reduction, min_ass_reduced)
from mech.stdlib.realpoints import count_real_roots, linear_point

#: CPU seconds for all the singular configurations, and for each point's local components and cone.
SINGULAR_BUDGET = 120.0
POINT_BUDGET = 60.0


def _jacobian(gens: Sequence[Poly], nvars: int) -> Matrix:
    ring = gens[0].ring
    return Matrix.from_rows(ring, [[g.diff(j) for j in range(nvars)] for g in gens])


def fitting_ideal(gens: list[Poly], nvars: int, size: int) -> list[Poly]:
    """``I_size`` of the Jacobian with respect to the first ``nvars`` variables."""
    if size <= 0:
        return [gens[0].ring.one()]
    return [p for p in minors(_jacobian(gens, nvars), size) if not p.is_zero()]


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
        if is_unit(p) or any(ideals_equal(p, q, R) for q in out):
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
    ok, primes = timed(a, "singular configurations", SINGULAR_BUDGET, singular_primes, a)
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
            ok, _ = timed(a, f"local components at q{k + 1}", POINT_BUDGET, _components_at, a, sp, shared)
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
        ok, sp.algebraic = timed(a, "real points", REAL_BUDGET, primitive_element, P, R)
        sp.real = bool(count_real_roots(sp.algebraic.minpoly) > 0) if ok else None
    elif point is None:
        sp.real = real_points(a, P)
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
        ok, cone = timed(a, f"tangent cone at q{k + 1}", POINT_BUDGET, cone_over_point, variety, lr, sp.algebraic)
    elif a.decomposed and sp.local_components:
        ok, cone = within(CONE_BUDGET, cone_at_point, variety, lr, sp.point, cpu=True)
        if not ok:
            cone = _union_cone(_component_cones(sp, shared, a.ring))
            sp.cone_note = (f"as a set: the union of the local components' cones (the ideal of lowest "
                            f"forms ran out of its {CONE_BUDGET:g} s budget)")
            ok = True
    else:
        ok, cone = timed(a, f"tangent cone at q{k + 1}", POINT_BUDGET, cone_at_point, variety, lr, sp.point)
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
