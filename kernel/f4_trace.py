"""The trace of an F4 run modulo one prime, replayed modulo others (Traverso's Gröbner trace).

A :class:`Trace` keeps, per matrix, the rows (basis index and, per term, its pivot or slot)
that mattered -- the pair rows that raised the rank and the reducers they need, transitively
-- and the shape of each new polynomial.  :func:`replay` redoes only that linear algebra for
another prime and raises :class:`TraceMismatch` when the prime does not follow the recorded
path.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Sequence

from .f4_rows import SUBPLAN, CodedRow, as_spec, compiled, replay_step
from .f4_vectors import RowSpec, Vectors, echelon


class TraceMismatch(Exception):
    """The prime does not follow the recorded computation (unlucky prime or unlucky trace)."""


class Step:
    """One recorded matrix: ``K`` pivot columns, ``m`` slots, the needed reducers (by pivot
    id), the pair rows that raised the rank with the slot of their new pivot, and for each new
    polynomial (appended to the basis in this order) its slots, leading one first.

    ``rows_of()`` gives every row of the matrix (the reducers by pivot id, the pair rows), and
    ``used`` the pair rows that raised the rank with their pivot slots; the needed reducers are
    those these rows (and the reducers ``roots``) need, transitively.  Both are worked out when
    first asked for: a run whose replays are all full (:func:`replay_full`, from the recorded
    plans) never needs them.  ``full``: every reducer, every pair row and ``used``, for a full
    replay (None: not kept); ``plans``: the rows laid out for replays (f4_rows.Plan)."""

    def __init__(self, K: int, m: int, rows_of: Callable[[], tuple[list, list]], used: list,
                 new: list[list[int]], roots: Sequence[int] = ()) -> None:
        self.K, self.m, self.new, self.used, self.roots = K, m, new, used, roots
        self.keeps_full = False
        self.plans: dict = {}
        self._rows_of = rows_of
        self._every: tuple[list, list] | None = None
        self._reducers: list[tuple[int, RowSpec | CodedRow]] | None = None
        self._rows: list[tuple[RowSpec | CodedRow, int]] | None = None

    def every(self) -> tuple[list, list]:
        """Every row: the reducers by pivot id and the pair rows."""
        if self._every is None:
            self._every, self._rows_of = self._rows_of(), None
        return self._every

    @property
    def full(self) -> tuple[list, list, list] | None:
        return (*self.every(), self.used) if self.keeps_full else None

    @property
    def reducers(self) -> list[tuple[int, RowSpec | CodedRow]]:
        if self._reducers is None:
            self.settle()
        return self._reducers

    @property
    def rows(self) -> list[tuple[RowSpec | CodedRow, int]]:
        if self._rows is None:
            self.settle()
        return self._rows

    def settle(self) -> None:
        """Work out the needed reducers and the rows that raised the rank; unless the step keeps
        every row, let the others go."""
        if self._rows is not None:
            return
        red, crows = self.every()
        rows = [(crows[r], s0) for r, s0 in self.used]
        needed = set()
        stack = list(self.roots) + [j for spec, _ in rows for j in spec.piv_j]
        while stack:
            j = stack.pop()
            if j not in needed:
                needed.add(j)
                stack.extend(red[j].piv_j)
        self._reducers = [(j, red[j]) for j in sorted(needed)]
        self._rows = rows
        if not self.keeps_full:
            self._every = ([], [])

    def rows_plan(self):
        """The plan (f4_rows.Plan) of the rows a replay needs, cut in C from the plan of the
        whole matrix when the step keeps one; None otherwise (the rows are then laid out)."""
        plan = self.plans.get("rows")
        if plan is None and "full" in self.plans and SUBPLAN is not None:
            plan = self.plans["rows"] = self.plans["full"].sub(self.K, [r for r, _ in self.used], self.roots)
        return plan

    def let_go(self) -> None:
        """Keep only what a replay needs (no full replay)."""
        self.settle()
        self.keeps_full = False
        self._every = ([], [])
        self.plans.pop("full", None)


@dataclass
class Trace:
    """A recorded F4 run: the steps, ``unit`` if it ended with 1 in the ideal, and the final
    back substitution giving the reduced basis: ``final_out`` lists, in the output order, the
    pivot id of each element and the slots of its tail; ``shape`` holds the monomials."""

    npolys: int
    steps: list[Step] = field(default_factory=list)
    unit: bool = False
    final: Step | None = None
    final_out: list[tuple[int, list[int]]] = field(default_factory=list)
    shape: list[list[int]] = field(default_factory=list)
    full: bool = True  # whether every step kept all its rows (see :func:`replay_full`)

    def full_cost(self) -> float:
        """The entries a full replay reduces per entry of a replay (inf without a full trace)."""
        if not self.full:
            return float("inf")
        if SUBPLAN is not None and all("full" in st.plans for st in self.steps):  # from the plans
            every = sum(len(st.plans["full"].col) for st in self.steps)
            kept = sum(len(st.rows_plan().col) for st in self.steps)
        else:
            kept = sum(len(_codes(r)) for st in self.steps for r in [r for _, r in st.reducers] + [r for r, _ in st.rows])
            every = sum(len(_codes(r)) for st in self.steps for r in st.every()[0] + st.every()[1])
        return every / max(kept, 1)


def replay(trace: Trace, polys: Sequence[list[int]], p: int) -> list[list[int]]:
    """The coefficients mod ``p`` of the reduced basis recorded in ``trace`` (monomials in
    ``trace.shape``), given the generators' coefficients mod ``p`` in the recorded shape."""
    if compiled(p):
        return _replay_compiled(trace, polys, p)
    vec = Vectors(p)
    coefs: list[list[int]] = [list(c) for c in polys]
    neg = [[p - c for c in cs] for cs in coefs]
    for st in trace.steps:
        if not st.rows:
            continue
        T = [0] * st.K
        combine = vec.combiner(st.m)
        for j, row in st.reducers:
            spec = as_spec(row)
            T[j] = combine(spec, coefs[spec.k], neg[spec.k], T)
        D = [combine(spec, coefs[spec.k], neg[spec.k], T) for spec in (as_spec(row) for row, _ in st.rows)]
        E, used = echelon(vec, D, st.m)
        if [s0 for _, s0 in used] != [s0 for _, s0 in st.rows]:
            raise TraceMismatch("a pair row reduced differently")
        for slots in st.new:
            cs = _values_on(vec, E[slots[0]], st.m, slots)
            coefs.append(cs)
            neg.append([p - c for c in cs])
    if trace.unit:
        return [[1]]
    st = trace.final
    T = [0] * st.K
    combine = vec.combiner(st.m)
    for j, row in st.reducers:
        spec = as_spec(row)
        T[j] = combine(spec, coefs[spec.k], neg[spec.k], T)
    return [[1] + _values_on(vec, T[j], st.m, slots) for j, slots in trace.final_out]


def _replay_compiled(trace: Trace, polys: Sequence[list[int]], p: int) -> list[list[int]]:
    """:func:`replay` with the matrices reduced by the compiled kernel (:mod:`.f4_rows`)."""
    coefs: list[list[int]] = [list(c) for c in polys]
    for st in trace.steps:
        if not st.used:
            continue
        used, E, _ = _replay_needed(st, coefs, p)
        if [s0 for _, s0 in used] != [s0 for _, s0 in st.used]:
            raise TraceMismatch("a pair row reduced differently")
        rows = {s0: (slots, vals) for s0, slots, vals in E}
        for slots in st.new:
            coefs.append(_on_slots(*rows[slots[0]], slots))
    if trace.unit:
        return [[1]]
    _, _, W = _replay_needed(trace.final, coefs, p, [j for j, _ in trace.final_out])
    return [[1] + _on_slots(*w, slots) for w, (_, slots) in zip(W, trace.final_out)]


def _replay_needed(st: Step, coefs: list[list[int]], p: int, want: Sequence[int] = ()):
    """The kernel's ``(used, E, W)`` for the rows of a step a replay needs: cut from the plan
    of the whole matrix when the step has one (no rows laid out in Python), else laid out."""
    plan = st.rows_plan()
    if plan is not None:
        try:
            return plan.reduce(coefs, p, st.m, st.K, want)
        except TypeError:  # coefficients that are not Python ints
            pass
    return replay_step(st.reducers, [row for row, _ in st.rows], st, coefs, p, want)


def replay_full(trace: Trace, polys: Sequence[list[int]], p: int) -> list[list[int]]:
    """:func:`replay` of every row of every matrix, also the pair rows that reduced to zero
    (the trace must be ``full``; needs the compiled kernel for ``p``).  Raises
    :class:`TraceMismatch` unless every matrix has the recorded rank profile: the replay is
    then an F4 run modulo ``p`` (the same pairs, selected by leading monomials alone, and the
    same symbolic preprocessing up to superfluous reducers), so the result is the reduced
    Gröbner basis of the ideal modulo ``p``."""
    if not trace.full or not compiled(p):
        raise TraceMismatch("no full trace to replay")
    coefs: list[list[int]] = [list(c) for c in polys]
    for st in trace.steps:
        plan = st.plans.get("full")
        if plan is not None:  # the rows as the run reduced them
            used, E, _ = plan.reduce(coefs, p, st.m, st.K)
        else:
            used, E, _ = replay_step(list(enumerate(st.every()[0])), st.every()[1], st, coefs, p, key="full")
        if used != st.used:
            raise TraceMismatch("a matrix reduced differently")
        # the same rank profile: the echelon rows are the new elements, in the recorded order
        for (_, support, vals), slots in zip(E, st.new):
            coefs.append(_on_slots(support, vals, slots))
    if trace.unit:
        return [[1]]
    _, _, W = _replay_needed(trace.final, coefs, p, [j for j, _ in trace.final_out])
    return [[1] + _on_slots(*w, slots) for w, (_, slots) in zip(W, trace.final_out)]


def _on_slots(support: list[int], vals: list[int], slots: list[int]) -> list[int]:
    """The entries of a vector (its nonzero slots and values) in the given slots, which must
    hold all its nonzero entries."""
    if support == slots:  # the usual case: the recorded support, in the kernel's order
        return vals
    got = dict(zip(support, vals))
    out = [got.pop(s, 0) for s in slots]
    if got:
        raise TraceMismatch("a polynomial has a term the recorded run did not have")
    return out


def _values_on(vec: Vectors, x: int, m: int, slots: list[int]) -> list[int]:
    """The entries of ``x`` in the given slots, which must hold all its nonzero entries."""
    vals = vec.values(x, m)
    out = [vals[s] for s in slots]
    if m - vals.count(0) != len(out) - out.count(0):
        raise TraceMismatch("a polynomial has a term the recorded run did not have")
    return out


def _codes(row: RowSpec | CodedRow):
    """A recorded row's entries (their pivots and slots)."""
    return row.codes if isinstance(row, CodedRow) else row.piv_t + row.np_t
