"""The motion modes of a mechanism with numeric lengths: the minimal primes of ``J``, found by a
chain of strategies, each with a time budget (:data:`STRATEGIES`); when one runs out or cannot
decide, the next runs; when all fail the analysis goes on without modes and says so.  For a
``J`` that is not radical, its embedded components (:func:`embedded_components`).

The strategies (their proofs are in the kernel modules named):

* ``slice`` (radical complete intersections): a zero-dimensional slice of ``V(J)`` whose
  ``deg V`` points are one Galois orbit proves ``J`` prime (``mech.kernel.slices``); several
  orbits bound the number of modes.
* ``reduction`` (radical complete intersections in at most :data:`SMALL` variables: one loop):
  GTZ's reduction to dimension zero over ``K(u)`` for an independent set ``u``
  (``mech.kernel.zerodim.Reduction``) gives the minimal primes of ``J`` that meet ``K[u]`` in 0;
  they are all of them when their degrees add up to ``deg J`` (``J`` radical and unmixed is the
  intersection of its minimal primes, all of its dimension, each counted once in its degree), with
  none of ``minAssGTZ``'s splittings and saturations.
* ``minimal primes``: ``minAssGTZ`` (``mech.kernel.primdec``), first with a short budget (it
  finishes at once on small mechanisms), skipped when the slice found a Galois orbit of
  :data:`HIGH_DEGREE` points or more on a curve (a mode of high degree: the interpolated
  projection is the faster route there).
* ``interpolated projection`` (radical complete intersections of dimension 1): the eliminant of
  a projection to the plane interpolated from slices, its factors certify the primes; their
  ideals are interpolated from points modulo primes and proved over QQ
  (``mech.kernel.curve_ideals``), else found by saturations.  It runs
  before a longer ``minAssGTZ`` try, which it makes unnecessary once it has proved the number of
  modes and their degrees.
* ``sparse projection`` (radical complete intersections): the eliminant of a projection by
  sparse forms ``c_j + s_j`` (``mech.kernel.projection``).
* ``loops`` (planar linkages with several loops): the minimal primes of each loop's equations
  combined (``mech.stdlib.analysis_parts``: Peaucellier's inversor).
* ``minimal primes`` again with a long budget, unless the interpolated projection has proved
  the number of modes and their degrees (``a.mode_degrees``) but ran out while computing their
  ideals: then the report gives that count without the ideals.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Optional

from mech.dsl.limits import within
from mech.kernel import Poly
from mech.kernel.curve_ideals import ideal_of_components
from mech.kernel.hilbert import mult
from mech.kernel.ideals import dp_ring, is_subset, move, std
from mech.kernel.primdec import min_ass_gtz, primdec_gtz
from mech.kernel.progress import stage
from mech.kernel.projection import project_primes, split_by_factors
from mech.kernel.slices import curve_image, slice_orbits
from mech.kernel.zerodim import Reduction
from mech.stdlib.analysis_parts import loop_groups, modes_by_parts

Found = list[list[Poly]]  # the minimal primes


@dataclass(frozen=True)
class Strategy:
    """One way to the motion modes: ``run(a)`` gives the minimal primes or None (cannot
    decide); ``applies(a)``; ``budget`` in seconds of CPU time; ``label``: how the report
    says the modes were found."""

    name: str
    budget: float
    applies: Callable[[Any], bool]
    run: Callable[[Any], Optional[Found]]
    label: str


def _radical_ci(a: Any) -> bool:
    return a.radical and a.complete_intersection


def _by_slice(a: Any) -> Optional[Found]:
    orbits = slice_orbits(a.ideal, a.ring)
    if orbits is None:
        return None
    a.mode_bound, a.slice_orbits = len(orbits), orbits
    return [list(a.ideal)] if len(orbits) == 1 else None


#: A Galois orbit of this many points on a slice lies on one mode of at least that degree: then the
#: interpolated projection runs before the short ``minAssGTZ`` try, which does not finish in its 2 s
#: on such six-bars (Stephenson's orbits 2, 2, 2, 6, 6; Watt I-B's 6, 10: the projection proves their
#: modes in 1-2 s), while modes of low degree (Watt's eight orbits of 2 points) decompose at once.
HIGH_DEGREE = 6


def _short_min_ass_first(a: Any) -> bool:
    """Whether the short ``minAssGTZ`` try runs before the projections: unless a slice has shown a
    mode of high degree on a curve that the interpolated projection takes."""
    high = a.slice_orbits is not None and max(a.slice_orbits) >= HIGH_DEGREE
    return not (high and _radical_ci(a) and a.dim == 1)


def _by_reduction(a: Any) -> Optional[Found]:
    glob = dp_ring(a.ring)
    basis = std(move(a.ideal, glob), glob)
    primes = Reduction(basis, glob).primes()
    if sum(_degree(P) for P in primes) != _degree(basis):
        return None  # a mode inside V(h): minAssGTZ's saturations find it
    return [std(move(P, a.ring), a.ring) for P in primes]


def _degree(basis: list[Poly]) -> int:
    """The degree of the affine variety of a basis for a degree ordering (of its leading ideal)."""
    return mult([g.lm() for g in basis], basis[0].ring.nvars)


def _by_min_ass(a: Any) -> Optional[Found]:
    return min_ass_gtz(a.ideal, a.ring)


def _by_curve(a: Any) -> Optional[Found]:
    image = curve_image(a.ideal, a.ring)
    if image is None:
        return None
    a.mode_degrees = sorted(g.total_degree() for g in image.factors)  # proved, even if the split runs out
    if len(image.factors) == 1:
        return [list(a.ideal)]  # one factor: J is prime
    ok, primes = within(IDEALS_BUDGET, ideal_of_components, a.ideal, a.ring, image.forms, image.factors, cpu=True)
    if ok and primes is not None:
        return primes
    ok, found = within(SPLIT_BUDGET, split_by_factors, a.ideal, a.ring, image.forms, image.degree,
                       image.image_ring, image.factors, cpu=True)
    if not ok:
        a.notes.append(f"strategy interpolated projection: proved {len(image.factors)} modes, their ideals "
                       f"(saturations) ran out of the {SPLIT_BUDGET:g} s budget")
    return found.primes if ok else None


#: CPU seconds for the ideals of the modes once a projection has proved their number: first
#: interpolated from points modulo primes and proved (``mech.kernel.curve_ideals``), then by
#: saturations.
IDEALS_BUDGET = 20.0
SPLIT_BUDGET = 5.0


def _by_projection(a: Any) -> Optional[Found]:
    found = project_primes(a.ideal, a.ring, 0, 2)
    return found.primes if found else None


#: The chain, in order.  Budgets are seconds of CPU time (a busy machine does not shorten them); the whole analysis
#: also stops at the statement's time limit (mech --timeout), with a partial report.
STRATEGIES: list[Strategy] = [
    Strategy("reduction", 2, lambda a: _radical_ci(a) and a.ring.nvars <= SMALL, _by_reduction, "minimal primes of J"),
    Strategy("slice", 10, _radical_ci, _by_slice, "J is prime, certified by a linear slice"),
    Strategy("minimal primes", 2, _short_min_ass_first, _by_min_ass, "minimal primes of J"),
    Strategy("interpolated projection", 60, lambda a: _radical_ci(a) and a.dim == 1, _by_curve,
             "minimal primes of J, certified by a projection interpolated from slices"),
    Strategy("sparse projection", 30, lambda a: _radical_ci(a) and a.dim > 1, _by_projection,
             "minimal primes of J, certified by a birational projection"),
    Strategy("loops", 30, lambda a: a.mode_degrees is None and loop_groups(a.ideal) is not None,
             lambda a: modes_by_parts(a.ideal, a.ring), "minimal primes of J, from the minimal primes of its loops"),
    Strategy("minimal primes", 300, lambda a: a.mode_degrees is None, _by_min_ass, "minimal primes of J"),
]


#: Up to this many variables (one loop: four-bars, kites) the reduction, then ``minAssGTZ``, finish in a
#: few tens of milliseconds, less than the slice takes when it finds several orbits (the kite: 13 ms):
#: their short tries run first.
SMALL = 6


def _chain(a: Any) -> list[Strategy]:
    """The strategies that apply, in :data:`STRATEGIES`' order but for small rings (:data:`SMALL`),
    where the short ``minAssGTZ`` try comes before the slice."""
    chain = [s for s in STRATEGIES if s.applies(a)]
    names = [s.name for s in chain]
    if a.ring.nvars <= SMALL and "slice" in names and "minimal primes" in names:
        short = chain.pop(names.index("minimal primes"))
        chain.insert(names.index("slice"), short)
    return chain


def motion_modes(a: Any) -> Optional[Found]:
    """The minimal primes of ``a.ideal`` by the first strategy that finds them (``a.modes_by``
    says which, ``a.notes`` what ran out), None when none does."""
    chain = _chain(a)
    with stage("decomposition", total=len(chain)) as st:
        for k, s in enumerate(chain):
            if not s.applies(a):  # an earlier strategy settled what this one would find
                continue
            st.step(k, f"strategy {s.name} (budget {s.budget:g} s)")
            ok, found = within(s.budget, s.run, a, cpu=True)
            if ok and found is not None:
                a.modes_by = s.label if len(found) > 1 or s.name != "minimal primes" else "minimal primes of J"
                return found
            if not ok:
                a.notes.append(f"strategy {s.name}: ran out of its {s.budget:g} s budget")
        st.status = "failed"
    return None


EMBEDDED_BUDGET = 60.0


def embedded_components(a: Any) -> Optional[list[tuple[list[Poly], list[Poly]]]]:
    """The embedded components of a non-radical ``J`` as (primary, prime) pairs, the primary
    components of the modes set on them (``primdecGTZ`` within :data:`EMBEDDED_BUDGET`); None
    when it runs out."""
    with stage("embedded components") as st:
        ok, comps = within(EMBEDDED_BUDGET, primdec_gtz, a.ideal, a.ring, cpu=True)
        if not ok:
            st.status = "budget"
            a.notes.append(f"embedded components: primdecGTZ ran out of its {EMBEDDED_BUDGET:g} s budget")
            return None
    minimal = [md.prime for md in a.modes]
    out = []
    for primary, prime in comps:
        for md in a.modes:
            if is_subset(md.prime, prime, a.ring) and is_subset(prime, md.prime, a.ring):
                md.primary = primary
                break
        else:
            if any(is_subset(P, prime, a.ring) for P in minimal):
                out.append((primary, prime))
    return out
