"""Faugère's F4 over Z/p on packed monomials, with a trace for replaying other primes.

The algorithm (Faugère, J. Pure Appl. Algebra 139, 1999): pick all critical pairs of lowest
degree (the normal strategy: the weighted degree of the lcm for graded orderings, the sugar
for the others, whose lcm degrees grow too fast), put the two multiples of each pair into a
matrix, add by *symbolic preprocessing* a reducer ``u*g`` (``g`` in the basis) for every
monomial of the matrix divisible by a leading monomial, and row-reduce; the rows whose leading
monomial is new join the basis.  Pairs are pruned with the Gebauer–Möller criteria
(Becker–Weispfenning's UPDATE; :mod:`.f4_pairs`, compiled when built).

Monomials are packed integers (:mod:`.monomials`).  The linear algebra exploits the shape of
F4 matrices.  The columns split into *pivot* columns (leading monomials of reducers; one
reducer each, so the reducer block ``A`` is unit upper triangular) and the few *non-pivot*
columns (monomials divisible by no leading monomial: the staircase).  The reducers are fully
reduced by back substitution from the smallest pivot up: once the tails of the smaller
reducers are free of pivot columns, a row's reduced tail is the one-shot sum
``T_i = N_i - sum_j c_ij T_j`` over the pivot entries ``c_ij`` of its own tail, so a row costs
one scalar-times-vector per pivot entry and pivot columns never fill in.  The rows of the
critical pairs are reduced the same way and their (small) remainder block is brought to
reduced echelon form (:mod:`.f4_vectors`).

With ``record=True`` the run keeps a :class:`~.f4_trace.Trace` for :func:`~.f4_trace.replay`.
When the compiled kernel is built (:mod:`.f4_rows`), the linear algebra of a matrix modulo a
prime below ``2^31`` runs there in one call, on the same rows.
"""
from __future__ import annotations

from functools import partial
from itertools import islice
from typing import Sequence

import flint

from .buchberger import TooLong
from .f4_rows import LAYOUT, CodedRow, Flat, Packed, Plan, compiled
from .f4_pairs import pair_rows, pair_set
from .f4_trace import Step, Trace
from .f4_vectors import RowSpec, Vectors, echelon, support
from .monomials import Packing, packing

Row = tuple[list[int], list[int]]  # (packed monomials, decreasing; coefficients mod p)


FULL_TRACE_WORK = 1_000_000  # matrix entries up to which a trace keeps every row (memory)
DENSE_PER_ENTRY = 1250  # a budget of n entries allows 1250 n for the dense reduction's cost bound


class PackingOverflow(Exception):
    """A monomial exceeds the packing's degree bound (start again with a wider packing)."""


class F4:
    """One F4 computation modulo ``p`` on packed polynomials.

    ``polys`` are the generators as (monomials decreasing, coefficients mod p) with nonzero
    leading coefficient; zero coefficients may occur (they keep the shape prime-independent).
    """

    def __init__(self, polys: Sequence[Row], packing: Packing, p: int, record: bool = False,
                 budget: float = float("inf"), counter=None) -> None:
        self.P = packing
        self.p = p
        self.vec = Vectors(p)
        self.mons: list[list[int]] = []
        self.coefs: list[list[int]] = []
        self.neg: list[list[int]] | None = None if compiled(p) else []  # -c mod p, for the Python rows
        self.tdeg: list[int] = []
        self.sugar: list[int] = []
        self.active: list[bool] = []   # basis elements usable as reducers and in new pairs
        # (key, lcm, i, j), j < 0: an input row; the key is the weighted degree or the sugar
        self.pairs = pair_set(packing, packing.graded and counter is None)
        self.divisor: dict[int, int] = {}  # monomial -> reducer, or -1 - (basis size scanned)
        self.trace = Trace(len(polys)) if record else None
        self.packed = Packed(packing) if compiled(p) and LAYOUT is not None else None
        self._plan = None  # the last matrix's rows flat (compiled layout, recording)
        self.work = 0  # matrix entries handled, a measure of the size of the computation
        # TooLong once a matrix takes the work past ``budget``, or the dense reduction's cost bound
        # (entries times non-pivot columns, summed over the matrices) past DENSE_PER_ENTRY times it
        self.budget = budget
        self.dense = 0
        # homogeneous input only: the leading ideal's Hilbert function against the ideal's
        # (:class:`.hilbert_driven.Counter`); pairs of a degree already complete are dropped
        self.counter = counter
        for ms, cs in polys:
            k = self._add(ms, cs, is_basis=False)
            key = packing.weighted_degree(ms[0]) if packing.graded and counter is None else self.tdeg[k]
            self.pairs.push(key, k)

    # -- bookkeeping -------------------------------------------------------------------
    def _add(self, ms: list[int], cs: list[int], is_basis: bool, sugar: int | None = None) -> int:
        P = self.P
        if P.degree_first:  # the leading monomial has the largest total degree
            td = (ms[0] >> P.dshift) & P.emask
        else:
            dshift, emask = P.dshift, P.emask
            td = max([(m >> dshift) & emask for m in ms])
        if td > P.maxdeg:
            raise PackingOverflow
        if sugar is None:
            sugar = td
        self.mons.append(ms)
        self.coefs.append(cs)
        if self.neg is not None:
            self.neg.append([self.p - c for c in cs])
        self.tdeg.append(td)
        self.sugar.append(sugar)
        self.active.append(is_basis)
        self.pairs.add(int(ms[0]), sugar)
        return len(self.mons) - 1

    def _update(self, h: int) -> None:
        """Add basis element ``h``: new pairs and pruned old ones (Gebauer–Möller)."""
        if not self.pairs.update(h, self.active):
            raise PackingOverflow

    # -- one matrix ----------------------------------------------------------------------
    def _find_reducer(self, x: int, reducers: list[tuple[int, int]]) -> int:
        """A basis element whose leading monomial divides ``x`` (-1 if none), cached."""
        g = self.P.guard
        xg = x | g
        got = self.divisor.get(x)
        if got is not None:
            if got >= 0:
                if self.active[got]:
                    return got
            else:
                mons, active = self.mons, self.active
                for k in range(-1 - got, len(mons)):
                    if active[k] and (xg - mons[k][0]) & g == g:
                        self.divisor[x] = k
                        return k
                self.divisor[x] = -1 - len(mons)
                return -1
        for lm, k in reducers:
            if (xg - lm) & g == g:
                self.divisor[x] = k
                return k
        self.divisor[x] = -1 - len(self.mons)
        return -1

    def _symbolic(self, specs: list[tuple[int, int]], pivots: dict[int, tuple[int, int]]):
        """Symbolic preprocessing: a reducer for every divisible monomial of the rows.

        ``pivots`` maps a column to its reducer ``(k, u)`` and is completed here; returns the
        monomial lists of all rows by spec and the non-pivot monomials."""
        P = self.P
        dshift, emask, maxdeg = P.dshift, P.emask, P.maxdeg
        mons, tdeg = self.mons, self.tdeg
        reducers = sorted(((mons[k][0], k) for k in range(len(mons)) if self.active[k]),
                          key=lambda t: len(mons[t[1]]))
        rowmons: dict[tuple[int, int], list[int]] = {}
        nonpivot: list[int] = []
        seen: set[int] = set(pivots)
        queue = list(specs) + list(pivots.values())
        find, cached, active = self._find_reducer, self.divisor.get, self.active
        while queue:
            spec = queue.pop()
            if spec in rowmons:
                continue
            k, u = spec
            if ((u >> dshift) & emask) + tdeg[k] > maxdeg:  # the degree of u times poly k
                raise PackingOverflow
            rm = [u + x for x in mons[k]] if u else mons[k]  # (u + x: the monomials may be fmpz)
            rowmons[spec] = rm
            fresh = set(rm).difference(seen)
            seen.update(fresh)
            for x in fresh:
                r = cached(x)
                if r is None or r < 0 or not active[r]:
                    r = find(x, reducers)
                if r >= 0:
                    s = (r, x - mons[r][0])
                    pivots[x] = s
                    queue.append(s)
                else:
                    nonpivot.append(x)
        return rowmons, nonpivot

    @staticmethod
    def _spec(rm: list[int], k: int, where: dict[int, int], skip_lead: bool) -> RowSpec:
        piv_t, piv_j, np_t, np_s = [], [], [], []
        for t in range(1 if skip_lead else 0, len(rm)):
            c = where[rm[t]]
            if c >= 0:
                piv_t.append(t)
                piv_j.append(c)
            else:
                np_t.append(t)
                np_s.append(~c)
        return RowSpec(k, piv_t, piv_j, np_t, np_s)

    def _layout(self, crow_specs: list[tuple[int, int]], pivots: dict[int, tuple[int, int]]):
        """Symbolic preprocessing and the matrix's columns: the rows' monomials, the pivot columns
        and the non-pivot monomials (both increasing), and each column's code (pivot ``j`` >= 0,
        non-pivot slot ``s`` as ``-1 - s``)."""
        rowmons, nonpivot = self._symbolic(crow_specs, pivots)
        work = sum(map(len, rowmons.values()))
        self.work += work
        self.dense += work * len(nonpivot)
        if self.work > self.budget or self.dense > DENSE_PER_ENTRY * self.budget:
            raise TooLong
        pivcols = sorted(pivots)
        nonpivot.sort()
        where = dict(zip(pivcols, range(len(pivcols))))
        where.update(zip(nonpivot, range(-1, -len(nonpivot) - 1, -1)))
        return rowmons, pivcols, nonpivot, where

    def _matrix(self, crow_specs: list[tuple[int, int]], pivots: dict[int, tuple[int, int]]):
        """Build and reduce a matrix.  Returns the reduced reducers ``T`` (by pivot id), the
        pivot columns (increasing), the non-pivot monomials (increasing: slot order), the
        echelon form of the reduced pair rows, the rows that raised the rank, and the row specs
        (reducers by pivot id, pair rows) for the trace."""
        rowmons, pivcols, nonpivot, where = self._layout(crow_specs, pivots)
        K, m = len(pivcols), len(nonpivot)
        vec, coefs, neg, spec = self.vec, self.coefs, self.neg, self._spec
        combine = vec.combiner(m)
        T = [0] * K
        red_specs = []
        for j, col in enumerate(pivcols):
            k, u = pivots[col]
            s = spec(rowmons[(k, u)], k, where, True)
            red_specs.append(s)
            T[j] = combine(s, coefs[k], neg[k], T)
        c_specs = [spec(rowmons[(k, u)], k, where, False) for (k, u) in crow_specs]
        D = [combine(s, coefs[s.k], neg[s.k], T) for s in c_specs]
        E, used = echelon(vec, D, m)
        return T, pivcols, nonpivot, E, used, red_specs, c_specs

    def _matrix_compiled(self, crow_specs: list[tuple[int, int]], pivots: dict[int, tuple[int, int]],
                         want: list[int] = (), stop: bool = False):
        """:meth:`_matrix` by the compiled kernel (:mod:`.f4_rows`): returns the pivot columns,
        the non-pivot monomials, the kernel's ``(used, E, W)`` (``W``: the reduced tails of the
        reducers with leading monomials ``want``) and, when recording, a callable giving the
        rows as :class:`~.f4_rows.CodedRow` (reducers by pivot id, pair rows)."""
        if self.packed is not None:
            return self._matrix_packed(crow_specs, pivots, want, stop)
        rowmons, pivcols, nonpivot, where = self._layout(crow_specs, pivots)
        K, m = len(pivcols), len(nonpivot)
        coefs, get = self.coefs, where.__getitem__
        flat = Flat()
        flat.ids.extend(range(K))
        rows = [(1, pivots[col]) for col in pivcols] + [(0, spec) for spec in crow_specs]
        if self.trace is None:
            col, val, off = flat.col.extend, flat.val.extend, flat.off
            for start, spec in rows:
                col(map(get, islice(rowmons[spec], start, None)))
                val(coefs[spec[0]][start:])
                off.append(len(flat.col))
            recorded = None
        else:
            recorded = []
            for start, spec in rows:
                codes = list(map(get, islice(rowmons[spec], start, None)))
                flat.add(codes, coefs[spec[0]][start:])
                recorded.append(CodedRow(spec[0], start, codes))
            recorded = partial(tuple, (recorded[:K], recorded[K:]))
        out = flat.reduce(self.p, m, K, [where[x] for x in want], stop)
        return pivcols, nonpivot, out, recorded

    def _matrix_packed(self, crow_specs: list[tuple[int, int]], pivots: dict[int, tuple[int, int]],
                       want: Sequence[int], stop: bool):
        """:meth:`_matrix_compiled` with the symbolic preprocessing compiled too
        (:class:`~.f4_rows.Packed`); the reducer of a monomial is the first active element, by
        increasing length, whose leading monomial divides it."""
        out = self.packed.layout(self.mons, self.coefs, self.tdeg, self.active, crow_specs, pivots)
        if out is None:
            raise PackingOverflow
        pivcols, nonpivot, flat, rk, rstart, work = out
        self.work += work
        self.dense += work * len(nonpivot)
        if self.work > self.budget or self.dense > DENSE_PER_ENTRY * self.budget:
            raise TooLong
        K = len(pivcols)
        if want:
            where = dict(zip(pivcols, range(K)))
            want = [where[x] for x in want]
        result = flat.reduce(self.p, len(nonpivot), K, want, stop)
        recorded = None
        if self.trace is not None:
            recorded = partial(_coded_rows, flat.off, flat.col, rk, K)
            self._plan = Plan.of_flat(flat, rk, rstart)
        return pivcols, nonpivot, result, recorded

    def _step(self) -> bool:
        """Process the pairs of lowest degree; returns False when 1 is in the ideal."""
        d, pivots, crows = self.pairs.take_rows()
        if not crows:
            return True
        if compiled(self.p):
            pivcols, nonpivot, (used, E, _), rows_of = self._matrix_compiled(crows, pivots)
            m = len(nonpivot)
            new = [(slots, vals) for _, slots, vals in E]  # increasing leading monomial
        else:
            T, pivcols, nonpivot, E, used, red_specs, c_specs = self._matrix(crows, pivots)
            m = len(nonpivot)
            new = [support(self.vec, E[s0], m) for s0 in sorted(E)]  # increasing leading monomial
            rows_of = partial(tuple, (red_specs, c_specs))
        if self.trace is not None:
            step = Step(len(pivcols), m, rows_of, used, [s for s, _ in new])
            if self.trace.full and self.work <= FULL_TRACE_WORK:  # every row, for a full replay
                step.keeps_full = True
                if self._plan is not None:  # the rows as the kernel reduced them, for full replays
                    step.plans["full"] = self._plan
            else:
                step.settle()
                if self.trace.full:  # too large to keep: no full replay, the rows are let go
                    self.trace.full = False
                    for st in self.trace.steps:
                        st.let_go()
            self.trace.steps.append(step)
        monomial = nonpivot.__getitem__
        for slots, vals in new:
            k = self._add(list(map(monomial, slots)), vals, True, d)
            if self.mons[k][0] == 0:
                return False
            self._update(k)
            if self.counter is not None:
                self.counter.add(self.P.unpack(self.mons[k][0]))
        return True

    # -- the whole computation ---------------------------------------------------------------
    def run(self) -> list[Row]:
        """The reduced Gröbner basis, monic, by increasing leading monomial."""
        counter = self.counter
        while self.pairs:
            if counter is not None:  # Hilbert-driven (Traverso): skip what reduces to zero
                d = self.pairs.lowest()
                need, done = counter.missing(d)
                if done:
                    self.pairs.clear()
                    break
                if need <= 0:
                    self.pairs.drop(d)
                    continue
            if not self._step():
                if self.trace is not None:
                    self.trace.unit = True
                    self.trace.shape = [[0]]
                return [([0], [1])]
        return self._reduce()

    def _reduce(self) -> list[Row]:
        """Tail-reduce the minimal basis with one more back substitution."""
        mons = self.mons
        keep = sorted(self.pairs.minimal(self.active), key=lambda k: mons[k][0])  # the minimal elements
        pivots = {mons[k][0]: (k, 0) for k in keep}
        lead = [mons[k][0] for k in keep]
        if compiled(self.p):
            pivcols, nonpivot, (_, _, tails), rows_of = self._matrix_compiled([], pivots, lead)
        else:
            T, pivcols, nonpivot, _, _, red_specs, _ = self._matrix([], pivots)
            column = dict(zip(pivcols, range(len(pivcols))))
            tails = [support(self.vec, T[column[lm]], len(nonpivot)) for lm in lead]
            rows_of = partial(tuple, (red_specs, []))
        m = len(nonpivot)
        where = dict(zip(pivcols, range(len(pivcols))))
        out, final = [], []
        for lm, (slots, vals) in zip(lead, tails):
            j = where[lm]
            out.append(([lm, *map(nonpivot.__getitem__, slots)], [1] + vals))
            final.append((j, slots))
        if self.trace is not None:
            self.trace.final = Step(len(pivcols), m, rows_of, [], [], [j for j, _ in final])
            if self._plan is not None:  # the matrix as the kernel reduced it, to cut replays from
                self.trace.final.plans["full"] = self._plan
            self.trace.final_out = final
            self.trace.shape = [ms for ms, _ in out]
        return out


def is_groebner(polys: Sequence[Row], packing: Packing, p: int) -> bool:
    """Whether monic polynomials with distinct, pairwise non-dividing leading monomials form
    a Gröbner basis mod ``p``: every S-pair left by the Gebauer–Möller criteria reduces to 0
    (all of them in one matrix)."""
    eng = F4([], packing, p)
    for ms, cs in polys:
        eng._update(eng._add(ms, cs, True))
    pivots, crows = pair_rows(eng.pairs.everything(), [int(ms[0]) for ms in eng.mons])
    if not crows:
        return True
    if compiled(p):
        return not eng._matrix_compiled(crows, pivots, stop=True)[2][0]
    return not eng._matrix(crows, pivots)[3]


def pack_polys(gens: Sequence, packing: Packing, coeff) -> list[Row]:
    """Generators as packed rows (decreasing monomials), coefficients through ``coeff``."""
    rows = []
    for g in gens:
        items = sorted(zip(packing.pack_all(g.terms.keys()), g.terms.values()), reverse=True)
        rows.append(([m for m, _ in items], [coeff(c) for _, c in items]))
    return rows


def initial_degree(gens: Sequence) -> int:
    """A first total-degree bound for the packing (doubled on overflow)."""
    d = max(g.total_degree() for g in gens)
    bound = 63
    while bound < 4 * d:
        bound = 2 * bound + 1
    return bound


def f4_modp(gens: Sequence, ring, budget: float = float("inf"), counter=None) -> list[dict]:
    """The reduced Gröbner basis over Z/p by F4, as ``{exponent: coefficient}`` dicts;
    :class:`~.buchberger.TooLong` once its matrices have more than ``budget`` entries.
    ``counter``: for homogeneous generators, makes a :class:`.hilbert_driven.Counter`."""
    p = ring.field.characteristic
    maxdeg = initial_degree(gens)
    while True:
        P = packing(ring.order, maxdeg)
        rows = pack_polys(gens, P, int)
        try:
            basis = F4([r for r in rows if r[0]], P, p, budget=budget,
                       counter=None if counter is None else counter()).run()
            break
        except PackingOverflow:
            maxdeg = 2 * maxdeg + 1
    return P.term_dicts(basis, flint.nmod(1, p))  # one * c: an nmod, made faster than by nmod(c, p)


def reduce_modp(basis: Sequence[dict], ring) -> list[dict]:
    """The reduced Gröbner basis over Z/p (sorted by increasing leading monomial) of a Gröbner
    basis given as ``{exponent: nmod}`` dicts: the minimal elements' tails fully reduced in one
    F4 back substitution (:meth:`F4._reduce`), as :func:`.buchberger.reduce_basis` over QQ."""
    p = ring.field.characteristic
    key = ring.order.key
    polys = [b for b in basis if b]
    maxdeg = 63
    while maxdeg < 4 * max(sum(e) for b in polys for e in b) + 2:
        maxdeg = 2 * maxdeg + 1
    while True:
        P = packing(ring.order, maxdeg)
        eng = F4([], P, p)
        seen: set[int] = set()
        try:
            for b in polys:
                lc = b[max(b, key=key)]
                inv = int(lc) if lc == 1 else int(1 / lc)
                items = sorted(((P.pack(e), int(c) * inv % p) for e, c in b.items()), reverse=True)
                if items[0][0] in seen:  # an equal leading monomial: the earlier element serves
                    continue
                seen.add(items[0][0])
                eng._add([m for m, _ in items], [c for _, c in items], True)
            out = eng._reduce()
            break
        except PackingOverflow:
            maxdeg = 2 * maxdeg + 1
    return P.term_dicts(out, flint.nmod(1, p))


def _coded_rows(off, col, rk, K: int) -> tuple[list[CodedRow], list[CodedRow]]:
    """The rows of a matrix laid out flat (offsets, column codes) as :class:`~.f4_rows.CodedRow`
    (slices of the codes): the ``K`` reducers by pivot id, then the pair rows, of the basis
    elements ``rk`` (one per row)."""
    rows = [CodedRow(k, 1 if r < K else 0, col[off[r]:off[r + 1]]) for r, k in enumerate(rk)]
    return rows[:K], rows[K:]
