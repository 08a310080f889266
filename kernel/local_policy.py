"""The ``auto`` policy for standard bases in local and mixed orderings (:mod:`.engines` calls
:func:`auto_local`), chosen by measurement on benchmarks/local_bases.py.

- Homogeneous generators: Mora within :data:`MORA_HOMOGENEOUS` steps, then Lazard's method
  (:mod:`.lazard`), which homogenizes nothing, its global basis from the compiled F4
  (Singular's ``cyclic_roots_7`` in ``ds``: 4.6 s by Mora, 0.05 s by F4).
- Otherwise over Z/p, when Mora's loop runs compiled (:mod:`.mora_compiled`): when there are
  fewer generators than variables (by Krull's height theorem the ideal is not zero-dimensional,
  and no trial cut can succeed), Mora without trial cuts within :data:`MORA_QUICK` steps, Lazard
  within :data:`LAZARD_SMALL` entries, Mora without trial cuts within :data:`MORA_UNCUT` steps.
  When the zero set contains a coordinate axis (no trial cut can succeed either): Mora without
  trial cuts within :data:`MORA_UNCUT` steps while its sugar stays below :data:`SUGAR_FACTOR`
  times the generators' degree, Lazard within :data:`LAZARD_SMALL`, Mora without cuts within
  :data:`MORA_UNCUT`.  Otherwise the same with two runs first: Mora without trial cuts within
  :data:`MORA_QUICK` steps, Mora with its trial cuts within :data:`MORA_COMPILED` steps (small
  and medium local problems end there, and Lazard would pay for the components away from the
  origin).  Each Mora run is granted :data:`CORNER_STEPS` more once it finds the highest corner.
  Without the compiled loop: Mora with its trial cuts within :data:`MORA_FIRST` steps.  Then
  Lazard with F4 within :data:`LAZARD_BUDGET` matrix entries, then Mora with its trial cuts and
  Lazard without bounds.
- Over other fields: Mora within its default budget, then Lazard (modular F4 over QQ).
"""
from __future__ import annotations

from typing import Callable

from .buchberger import TooLong
from .coeffs import PrimeField
from .f4 import f4_modp
from .lazard import lazard
from .mora import Budget, BudgetExceeded, Terms, in_groups, mora_group, trial_obstacles
from .mora_compiled import CompiledMora
from .poly import Poly, PolyRing

GlobalBasis = Callable[[list[Poly], PolyRing], list[Poly]]

MORA_FIRST = 2000
"""Reduction steps (about 0.1 s) Mora gets before Lazard's method is tried over Z/p.  Measured
(steps, Mora / Lazard seconds): mora_6 1435, 0.06 / 0.02; mora1 6236, 0.28 / 0.10; mora_5
32764, 2.2 / 2.1; mora_7 29765, 2.8 / 2.5; mora_9 and mora_10 past 10^5 steps and 30 s, Lazard
2.6 / 0.07; the Puiseux parametrization in ``ls`` 0 steps, 0.3 ms / 2.9 s."""

MORA_QUICK = 3000
"""Reduction steps of compiled Mora without trial cuts first: small ideals and those that show
their highest corner early end there (steps before the corner, seconds in all: mora1 2636,
0.003, with the trials 0.006; mora_6 1435, 0.0015; each curve of vdim_overflow's milnor; its
tjurina 19, 1.7); the others lose little (mora_5 0.002 s, mora_7 0.007 s; mora_9 lost 0.03 s
here before the test for a coordinate axis sent it straight to Mora without cuts)."""

MORA_COMPILED = 80_000
"""Reduction steps of compiled Mora with its trial cuts (about 0.05-0.15 s) before Mora without
them.  Measured (steps, seconds; session 13): mora1 7772, 0.005; mora_5 65,989, 0.04; mora_7
31,925, 0.04; mora_9 (not zero-dimensional, 50 generators in 15 variables) spent them all in
0.12-0.15 s before the test for a coordinate axis skipped its trials; vdim_overflow's tjurina finds its corner in the second trial and then has
:data:`CORNER_STEPS` (1.0 s)."""

LAZARD_SMALL = 250_000
"""After :data:`MORA_COMPILED`: Lazard's method within this many matrix entries (mora_10 needs
50,000-100,000: 0.06 s; a random ideal in 4 variables of tests/kernel/test_mora_random.py
100,000-250,000, 0.02 s, where Mora without cuts runs 1 M steps into high degrees, 0.7 s;
mora_9 needs 1-4 M and runs out of these in 0.2 s), then compiled Mora without trial cuts
within :data:`MORA_UNCUT` steps (mora_9: 205,000 steps, 0.24 s)."""

MORA_UNCUT = 1_000_000

SUGAR_FACTOR = 6
"""Mora without trial cuts before Lazard's small attempt gives up when a sugar passes this many
times the generators' largest degree.  Measured largest sugar / degree: mora1 2.5, mora_5 and
mora_9 2.9, mora_7 3.7, mora_10 4.7; runaways of tests/kernel/test_mora_random.py 12 (with
factor 4 they leave after 0.01 s, 6: 0.05 s, 8: 0.2 s, none: 0.7-3 s)."""

CORNER_STEPS = 20_000_000
"""Steps compiled Mora is granted once the highest corner is found (about 0.4 µs each there:
reductions in ``K[x]/m^(cut+1)`` without Mora's ecart rule); vdim_overflow's ``tjurina`` takes
5.3 million."""

MORA_HOMOGENEOUS = 200
"""Reduction steps Mora gets on homogeneous generators before Lazard's method (about 10 ms;
Singular's mora2 "standard" case: 0.5 ms by Mora, 2 ms by Lazard)."""

LAZARD_BUDGET = 16_000_000
"""Matrix entries of the F4 run inside Lazard's method (and 1250 times as many operations of
its dense reduction, :data:`.f4.DENSE_PER_ENTRY`; a few seconds) before Mora takes over again:
mora_5 took 5.1 M entries and 5.5 G operations, mora_7 6.4 M and 13.8 G."""


def auto_local(gens: list[Poly], ring: PolyRing, global_basis: GlobalBasis) -> list[Terms]:
    """A standard basis of the ideal of the nonzero ``gens`` (non-global ``ring``) by the policy
    above, for each group of generators in their own variables (:func:`.mora.in_groups`; copies
    of a group once); ``global_basis(gens, ring)``: the ``auto`` Gröbner basis for a global
    ordering."""
    return in_groups(gens, ring, lambda part, sub: _auto_group(part, sub, global_basis))


def _auto_group(gens: list[Poly], ring: PolyRing, global_basis: GlobalBasis) -> list[Terms]:
    if all(_homogeneous(g) for g in gens):
        try:  # tiny problems end sooner in Mora than in setting up F4's ring
            return mora_group(gens, ring, Budget(MORA_HOMOGENEOUS), shared=True)
        except BudgetExceeded:
            return lazard(gens, ring, global_basis)
    if not isinstance(ring.field, PrimeField):
        try:
            return mora_group(gens, ring, Budget())
        except BudgetExceeded:
            return lazard(gens, ring, global_basis)
    if CompiledMora.usable(ring):
        basis = _compiled_routes(gens, ring)
        if basis is not None:
            return basis
    else:
        try:
            return mora_group(gens, ring, Budget(MORA_FIRST), shared=True)
        except BudgetExceeded:
            pass
    try:
        return lazard(gens, ring, _f4_within(LAZARD_BUDGET))
    except TooLong:
        pass
    try:
        return mora_group(gens, ring, Budget())
    except BudgetExceeded:
        return lazard(gens, ring, global_basis)


def _compiled_routes(gens: list[Poly], ring: PolyRing) -> list[Terms] | None:
    """The routes within bounds when Mora's loop runs compiled (see the module docstring); None
    when every one runs out.  When Krull's bound rules out trial cuts, Lazard's small attempt
    comes before Mora without cuts (mora_10: 0.06 s against 0.11 s); else Mora without cuts
    comes first while its sugar stays within :data:`SUGAR_FACTOR` times the generators' degree
    (mora_9: 0.3 s, where Lazard's attempt runs out in 0.2 s; random ideals in 4 variables that
    drive Mora's normal form to degree 85 from generators of degree 7 leave within 0.05 s, and
    Lazard takes them in 0.01-0.02 s).  When the zero set contains a coordinate axis
    (:func:`.mora.contains_axis`) no trial cut can succeed either, and the first run is Mora
    without cuts under the sugar bound (mora_9: 0.24 s in all, where the quick run and the trials
    spent 0.16 s before it)."""
    def quick() -> list[Terms]:
        return mora_group(gens, ring, Budget(MORA_QUICK, corner_steps=CORNER_STEPS), shared=True, trials=False)

    def trials() -> list[Terms]:
        return mora_group(gens, ring, Budget(MORA_COMPILED, corner_steps=CORNER_STEPS), shared=True)

    def lazard_small() -> list[Terms]:
        return lazard(gens, ring, _f4_within(LAZARD_SMALL))

    def uncut() -> list[Terms]:
        return mora_group(gens, ring, Budget(MORA_UNCUT, corner_steps=CORNER_STEPS), shared=True, trials=False)

    def uncut_low() -> list[Terms]:
        budget = Budget(MORA_UNCUT, corner_steps=CORNER_STEPS, degree=SUGAR_FACTOR)
        return mora_group(gens, ring, budget, shared=True, trials=False)

    krull, axis = trial_obstacles(gens)
    if krull:
        routes = [quick, lazard_small, uncut]
    elif axis:
        routes = [uncut_low, lazard_small, uncut]
    else:
        routes = [quick, trials, uncut_low, lazard_small, uncut]
    for route in routes:
        try:
            return route()
        except (BudgetExceeded, TooLong):
            pass
    return None


def _f4_within(budget: int) -> GlobalBasis:
    def run(gens: list[Poly], ring: PolyRing) -> list[Poly]:
        out = []
        for b in f4_modp(gens, ring, budget):
            p = Poly(ring, b)
            p._lm = next(iter(b))  # F4's bases carry the leading exponent first
            out.append(p)
        return out
    return run


def _homogeneous(g: Poly) -> bool:
    degrees = {sum(e) for e in g.terms}
    return len(degrees) == 1
