"""Faugère's F4 over Z/p on packed monomials, with a trace for replaying other primes.

The algorithm (Faugère, J. Pure Appl. Algebra 139, 1999): pick all critical pairs of lowest
sugar, put the two multiples of each pair into a matrix, add by *symbolic preprocessing* a
reducer ``u*g`` (``g`` in the basis) for every monomial of the matrix divisible by a leading
monomial, and row-reduce; the rows whose leading monomial is new join the basis.  Pairs are
pruned with the Gebauer–Möller criteria (Becker–Weispfenning's UPDATE).

Monomials are packed integers (:mod:`.monomials`).  The linear algebra exploits the shape of
F4 matrices.  The columns split into *pivot* columns (leading monomials of reducers; at most
one reducer each, so the reducer block ``A`` is unit upper triangular) and the few
*non-pivot* columns (monomials not divisible by any leading monomial: the staircase).  The
reducers are fully reduced by back substitution from the smallest pivot up: with the tails of
the smaller reducers already free of pivot columns, a row's reduced tail is the one-shot sum
``N_i - sum_j c_ij T_j`` over the pivot entries ``c_ij`` of its own tail, so every row costs one
scalar-times-vector per pivot entry and there is no fill-in in pivot columns.  The rows of the
critical pairs are reduced the same way, and their (small) remainder block is brought to
reduced echelon form.  A non-pivot vector ``T`` is dense but short: it is one Python integer
holding 64-bit slots, so ``acc += c * T_j`` runs in C; slots are reduced mod ``p`` (through a
memoryview of the bytes) after at most ``hmax`` products, which keeps them below ``2^64``.
Wider slots are used for primes above ``2^25``.

With ``record=True`` the run returns a :class:`Trace`: per matrix, the rows (basis index and,
per term, its pivot or slot) that mattered — the pair rows that raised the rank and the
reducers they need, transitively — and the shape of every new polynomial.
:func:`replay` redoes only that linear algebra for another prime (Traverso's Gröbner trace)
and raises :class:`TraceMismatch` when the prime does not follow the recorded path.
"""
from __future__ import annotations

from array import array
from dataclasses import dataclass, field
from typing import Sequence

from .monomials import Packing

Row = tuple[list[int], list[int]]  # (packed monomials, decreasing; coefficients mod p)


class PackingOverflow(Exception):
    """A monomial exceeds the packing's degree bound (start again with a wider packing)."""


class TraceMismatch(Exception):
    """The prime does not follow the recorded computation (unlucky prime or unlucky trace)."""


@dataclass
class _RowSpec:
    """A matrix row ``x^u * poly[k]``: terms ``piv_t`` sit in pivot columns ``piv_j``, terms
    ``np_t`` in non-pivot slots ``np_s`` (term positions index the polynomial's terms)."""

    k: int
    piv_t: list[int]
    piv_j: list[int]
    np_t: list[int]
    np_s: list[int]


@dataclass
class _Step:
    """One recorded matrix: ``K`` pivot columns, ``m`` slots, the needed reducers (by pivot
    id), the pair rows that raised the rank with the slot of their new pivot, and for each new
    polynomial (appended to the basis in this order) its pivot slot and its slots."""

    K: int
    m: int
    reducers: list[tuple[int, _RowSpec]]
    rows: list[tuple[_RowSpec, int]]
    new: list[tuple[int, list[int]]]


@dataclass
class Trace:
    """A recorded F4 run: the steps and, for the reduced basis, a final back substitution
    whose reducer ids ``final`` (in the order of the output) give the basis elements, each
    with the slots of its tail."""

    npolys: int
    steps: list[_Step] = field(default_factory=list)
    final: _Step | None = None
    final_out: list[tuple[int, list[int]]] = field(default_factory=list)
    shape: list[list[int]] = field(default_factory=list)  # monomials of the reduced basis


class _Vectors:
    """Dense vectors mod ``p`` packed into Python integers, ``words`` 64-bit words a slot."""

    def __init__(self, p: int) -> None:
        self.p = p
        self.words = (2 * p.bit_length() + 13 + 63) // 64
        self.hmax = max(1, ((1 << (64 * self.words)) - p) // max(1, (p - 1) ** 2)) - 1

    def pack(self, vals: list[int]) -> int:
        if self.words == 1:
            return int.from_bytes(array("Q", vals), "little")
        buf = [0] * (self.words * len(vals))
        buf[::self.words] = vals
        return int.from_bytes(array("Q", buf), "little")

    def unpack(self, v: int, m: int) -> list[int]:
        """The slots of ``v`` reduced mod p."""
        p, w = self.p, self.words
        if w == 1:
            return [x % p for x in memoryview(v.to_bytes(8 * m, "little")).cast("Q").tolist()]
        b = v.to_bytes(8 * w * m, "little")
        s = 8 * w
        return [int.from_bytes(b[i:i + s], "little") % p for i in range(0, len(b), s)]

    def scatter(self, coefs: list[int], ts: list[int], ss: list[int], m: int) -> int:
        """The packed vector with ``coefs[t]`` in slot ``s`` for ``t, s`` in ``ts, ss``."""
        if not ts:
            return 0
        vals = [0] * m
        for t, s in zip(ts, ss):
            vals[s] = coefs[t]
        return self.pack(vals)

    def combine(self, row: _RowSpec, coefs: list[int], neg: list[int], T: list[int], m: int) -> tuple[int, list[int]]:
        """``N - sum c_j T_j`` for a row (normalized): its packed vector and its slots."""
        acc = self.scatter(coefs, row.np_t, row.np_s, m)
        piv_t, piv_j = row.piv_t, row.piv_j
        hmax = self.hmax
        if len(piv_t) <= hmax:
            for t, j in zip(piv_t, piv_j):
                acc += neg[t] * T[j]
        else:
            for start in range(0, len(piv_t), hmax):
                for t, j in zip(piv_t[start:start + hmax], piv_j[start:start + hmax]):
                    acc += neg[t] * T[j]
                acc = self.pack(self.unpack(acc, m))
        vals = self.unpack(acc, m)
        return self.pack(vals), vals


def _echelon(vec: _Vectors, rows: list[tuple[int, list[int]]], m: int,
             expect: list[int] | None = None) -> tuple[dict[int, list], list[tuple[int, int]]]:
    """Reduced echelon form of the packed rows: ``{pivot slot: [packed, slots]}`` (monic) and
    the (row index, pivot slot) of the rows that raised the rank.  With ``expect`` (replay)
    every row must raise the rank at the given slot."""
    p = vec.p
    E: dict[int, list] = {}
    used: list[tuple[int, int]] = []
    for r, (packed, vals) in enumerate(rows):
        hits = [(s, vals[s]) for s in E if vals[s]]
        if hits:
            acc = packed
            for s, c in hits:
                acc += (p - c) * E[s][0]
            vals = vec.unpack(acc, m)
        s0 = next((i for i, v in enumerate(vals) if v), None)
        if expect is not None and s0 != expect[r]:
            raise TraceMismatch("a pair row reduced differently")
        if s0 is None:
            continue
        if vals[s0] != 1:
            inv = pow(vals[s0], -1, p)
            vals = [v * inv % p for v in vals]
        packed = vec.pack(vals)
        for e in E.values():
            c = e[1][s0]
            if c:
                e[1] = vec.unpack(e[0] + (p - c) * packed, m)
                e[0] = vec.pack(e[1])
        E[s0] = [packed, vals]
        used.append((r, s0))
    return E, used


class F4:
    """One F4 computation modulo ``p`` on packed polynomials.

    ``polys`` are the generators as (monomials decreasing, coefficients mod p) with nonzero
    leading coefficient; zero coefficients may occur (they keep the shape prime-independent).
    """

    def __init__(self, polys: Sequence[Row], packing: Packing, p: int, record: bool = False) -> None:
        self.P = packing
        self.p = p
        self.vec = _Vectors(p)
        self.mons: list[list[int]] = []
        self.coefs: list[list[int]] = []
        self.neg: list[list[int]] = []
        self.tdeg: list[int] = []
        self.sugar: list[int] = []
        self.is_basis: list[bool] = []
        self.active: list[bool] = []   # basis elements whose leading monomial is minimal so far
        self.pairs: list[tuple[int, int, int, int]] = []  # (sugar, lcm, i, j); j < 0: an input row
        self.trace = Trace(len(polys)) if record else None
        for ms, cs in polys:
            k = self._add(ms, cs, is_basis=False)
            self.pairs.append((self.tdeg[k], ms[0], k, -1))

    # -- bookkeeping -------------------------------------------------------------------
    def _add(self, ms: list[int], cs: list[int], is_basis: bool, sugar: int | None = None) -> int:
        P = self.P
        td = max(map(P.degree, ms))
        if not P.fits(td):
            raise PackingOverflow
        self.mons.append(ms)
        self.coefs.append(cs)
        self.neg.append([self.p - c for c in cs])
        self.tdeg.append(td)
        self.sugar.append(td if sugar is None else sugar)
        self.is_basis.append(is_basis)
        self.active.append(is_basis)
        return len(self.mons) - 1

    def _update(self, h: int) -> None:
        """Add basis element ``h``: new pairs and pruned old ones (Gebauer–Möller)."""
        P = self.P
        divides, lcm, degree = P.divides, P.lcm, P.degree
        H, sh = self.mons[h][0], self.sugar[h]
        dH = degree(H)
        cands = []
        for i in range(len(self.mons) - 1):
            if self.active[i]:
                li = self.mons[i][0]
                L = lcm(li, H)
                dL = degree(L)
                if dL > P.maxdeg:
                    raise PackingOverflow
                s = max(self.sugar[i] + dL - degree(li), sh + dL - dH)
                cands.append((s, L, i, L == li + H))
        # criterion M: drop (i,h) if another new pair's lcm properly divides its lcm;
        # criterion F: among equal lcms keep one, a coprime one if there is one
        kept: dict[int, tuple] = {}
        for c in cands:
            L = c[1]
            if any(d[1] != L and divides(d[1], L) for d in cands):
                continue
            prev = kept.get(L)
            if prev is None or (c[3] and not prev[3]):
                kept[L] = c
        new = [(s, L, i, h) for (s, L, i, coprime) in kept.values() if not coprime]
        # criterion B on the old pairs
        old = []
        mons = self.mons
        for pr in self.pairs:
            s, L, i, j = pr
            if j >= 0 and divides(H, L) and lcm(mons[i][0], H) != L and lcm(mons[j][0], H) != L:
                continue
            old.append(pr)
        self.pairs = old + new
        for i in range(len(self.mons) - 1):
            if self.active[i] and divides(H, self.mons[i][0]):
                self.active[i] = False
        self.active[h] = True

    # -- one matrix ----------------------------------------------------------------------
    def _symbolic(self, specs: list[tuple[int, int]], pivots: dict[int, tuple[int, int]]):
        """Symbolic preprocessing: a reducer for every divisible monomial of the rows.

        ``pivots`` maps a column to its reducer ``(k, u)`` and is completed here; returns the
        monomial lists of all rows by spec and the non-pivot monomials."""
        P = self.P
        divides, degree = P.divides, P.degree
        maxdeg = P.maxdeg
        reducers = [(self.mons[k][0], k) for k in range(len(self.mons)) if self.active[k]]
        reducers.sort(key=lambda t: len(self.mons[t[1]]))
        rowmons: dict[tuple[int, int], list[int]] = {}
        nonpivot: list[int] = []
        seen: set[int] = set(pivots)
        queue = list(specs) + [s for s in pivots.values()]
        while queue:
            spec = queue.pop()
            if spec in rowmons:
                continue
            k, u = spec
            if degree(u) + self.tdeg[k] > maxdeg:
                raise PackingOverflow
            rm = [u + x for x in self.mons[k]] if u else self.mons[k]
            rowmons[spec] = rm
            for x in rm:
                if x in seen:
                    continue
                seen.add(x)
                for lm, kk in reducers:
                    if divides(lm, x):
                        s = (kk, x - lm)
                        pivots[x] = s
                        queue.append(s)
                        break
                else:
                    nonpivot.append(x)
        return rowmons, nonpivot

    def _spec(self, rm: list[int], k: int, where: dict[int, int], skip_lead: bool) -> _RowSpec:
        piv_t, piv_j, np_t, np_s = [], [], [], []
        for t in range(1 if skip_lead else 0, len(rm)):
            c = where[rm[t]]
            if c >= 0:
                piv_t.append(t)
                piv_j.append(c)
            else:
                np_t.append(t)
                np_s.append(-1 - c)
        return _RowSpec(k, piv_t, piv_j, np_t, np_s)

    def _matrix(self, crow_specs: list[tuple[int, int]], pivots: dict[int, tuple[int, int]]):
        """Build and reduce a matrix.  Returns the reducer tails ``T`` (by pivot id), the
        pivot columns (increasing), the slot monomials, the reduced pair rows' echelon form,
        the used rows and the row specs (for the trace)."""
        rowmons, nonpivot = self._symbolic(crow_specs, pivots)
        pivcols = sorted(pivots)
        nonpivot.sort(reverse=True)
        K, m = len(pivcols), len(nonpivot)
        where = dict(zip(pivcols, range(K)))
        where.update(zip(nonpivot, range(-1, -m - 1, -1)))
        vec, coefs, neg = self.vec, self.coefs, self.neg
        T = [0] * K
        red_specs = []
        for j, col in enumerate(pivcols):
            k, u = pivots[col]
            spec = self._spec(rowmons[(k, u)], k, where, True)
            red_specs.append(spec)
            T[j] = vec.combine(spec, coefs[k], neg[k], T, m)[0]
        c_specs = [self._spec(rowmons[(k, u)], k, where, False) for (k, u) in crow_specs]
        D = [vec.combine(s, coefs[s.k], neg[s.k], T, m) for s in c_specs]
        E, used = _echelon(vec, D, m)
        return T, pivcols, nonpivot, E, used, red_specs, c_specs

    def _record(self, K: int, m: int, red_specs: list[_RowSpec], rows: list[tuple[_RowSpec, int]],
                new: list[tuple[int, list[int]]], roots: Sequence[int] = ()) -> _Step:
        """A trace step keeping only the reducers the given rows (and reducers ``roots``)
        need, transitively."""
        needed = set()
        stack = list(roots) + [j for spec, _ in rows for j in spec.piv_j]
        while stack:
            j = stack.pop()
            if j not in needed:
                needed.add(j)
                stack.extend(red_specs[j].piv_j)
        return _Step(K, m, [(j, red_specs[j]) for j in sorted(needed)], rows, new)

    def _step(self) -> bool:
        """Process the pairs of lowest sugar; returns False when 1 is in the ideal."""
        d = min(pr[0] for pr in self.pairs)
        sel = [pr for pr in self.pairs if pr[0] == d]
        self.pairs = [pr for pr in self.pairs if pr[0] != d]
        pivots: dict[int, tuple[int, int]] = {}
        crows: list[tuple[int, int]] = []
        seen: set[tuple[int, int]] = set()
        lm = lambda k: self.mons[k][0]  # noqa: E731
        for s, L, i, j in sel:
            for k in ((i,) if j < 0 else (i, j)):
                spec = (k, L - lm(k))
                if spec in seen:
                    continue
                seen.add(spec)
                if j >= 0 and L not in pivots:
                    pivots[L] = spec
                else:
                    crows.append(spec)
        if not crows:
            return True
        T, pivcols, nonpivot, E, used, red_specs, c_specs = self._matrix(crows, pivots)
        new = []
        for s0 in sorted(E, reverse=True):  # increasing leading monomial
            vals = E[s0][1]
            support = [s for s in range(s0, len(vals)) if vals[s]]
            new.append((s0, support))
        if self.trace is not None and used:
            rows = [(c_specs[r], s0) for r, s0 in used]
            self.trace.steps.append(self._record(len(pivcols), len(nonpivot), red_specs, rows, new))
        for s0, support in new:
            vals = E[s0][1]
            k = self._add([nonpivot[s] for s in support], [vals[s] for s in support], True, d)
            if self.mons[k][0] == 0:
                return False
            self._update(k)
        return True

    # -- the whole computation ---------------------------------------------------------------
    def run(self) -> list[Row]:
        """The reduced Gröbner basis, monic, by increasing leading monomial."""
        while self.pairs:
            if not self._step():
                return self._unit()
        return self._reduce()

    def _unit(self) -> list[Row]:
        if self.trace is not None:
            self.trace.steps.append(_Step(0, 0, [], [], []))  # marker: the unit ideal
            self.trace.shape = [[0]]
        return [([0], [1])]

    def _reduce(self) -> list[Row]:
        """Tail-reduce the minimal basis with one more back substitution."""
        divides = self.P.divides
        lms = [self.mons[k][0] for k in range(len(self.mons)) if self.active[k]]
        keep = [k for k in range(len(self.mons)) if self.active[k]
                and not any(l != self.mons[k][0] and divides(l, self.mons[k][0]) for l in lms)]
        keep.sort(key=lambda k: self.mons[k][0])
        pivots = {self.mons[k][0]: (k, 0) for k in keep}
        T, pivcols, nonpivot, _, _, red_specs, _ = self._matrix([], pivots)
        where = dict(zip(pivcols, range(len(pivcols))))
        out, final = [], []
        for k in keep:
            lm = self.mons[k][0]
            j = where[lm]
            vals = self.vec.unpack(T[j], len(nonpivot))
            support = [s for s, v in enumerate(vals) if v]
            out.append(([lm] + [nonpivot[s] for s in support], [1] + [vals[s] for s in support]))
            final.append((j, support))
        if self.trace is not None:
            self.trace.final = self._record(len(pivcols), len(nonpivot), red_specs, [], [],
                                            [j for j, _ in final])
            self.trace.final_out = final
            self.trace.shape = [ms for ms, _ in out]
        return out


def replay(trace: Trace, polys: Sequence[list[int]], p: int) -> list[list[int]]:
    """The coefficients mod ``p`` of the reduced basis recorded in ``trace`` (monomials in
    ``trace.shape``), given the generators' coefficients mod ``p`` in the recorded shape."""
    vec = _Vectors(p)
    coefs: list[list[int]] = [list(c) for c in polys]
    neg = [[p - c for c in cs] for cs in coefs]
    for st in trace.steps:
        if st.K == 0 and st.m == 0 and not st.rows:
            return [[1]]
        T = [0] * st.K
        for j, spec in st.reducers:
            T[j] = vec.combine(spec, coefs[spec.k], neg[spec.k], T, st.m)[0]
        D = [vec.combine(spec, coefs[spec.k], neg[spec.k], T, st.m) for spec, _ in st.rows]
        E, _ = _echelon(vec, D, st.m, [s0 for _, s0 in st.rows])
        for s0, support in st.new:
            vals = E[s0][1]
            _check_support(vals, support)
            cs = [vals[s] for s in support]
            coefs.append(cs)
            neg.append([p - c for c in cs])
    st = trace.final
    T = [0] * st.K
    for j, spec in st.reducers:
        T[j] = vec.combine(spec, coefs[spec.k], neg[spec.k], T, st.m)[0]
    out = []
    for j, support in trace.final_out:
        vals = vec.unpack(T[j], st.m)
        _check_support(vals, support)
        out.append([1] + [vals[s] for s in support])
    return out


def _check_support(vals: list[int], support: list[int]) -> None:
    if len(vals) - vals.count(0) != sum(1 for s in support if vals[s]):
        raise TraceMismatch("a polynomial has a term the recorded run did not have")


def pack_polys(gens: Sequence, packing: Packing, coeff) -> list[Row]:
    """Generators as packed rows (decreasing monomials), coefficients through ``coeff``."""
    rows = []
    for g in gens:
        items = sorted(((packing.pack(e), c) for e, c in g.terms.items()), reverse=True)
        rows.append(([m for m, _ in items], [coeff(c) for _, c in items]))
    return rows


def initial_degree(gens: Sequence) -> int:
    """A first total-degree bound for the packing (doubled on overflow)."""
    d = max(g.total_degree() for g in gens)
    bound = 15
    while bound < 4 * d:
        bound = 2 * bound + 1
    return bound


def f4_modp(gens: Sequence, ring) -> list[dict]:
    """The reduced Gröbner basis over Z/p by F4, as ``{exponent: coefficient}`` dicts."""
    p = ring.field.characteristic
    F = ring.field
    maxdeg = initial_degree(gens)
    while True:
        P = Packing(ring.order, maxdeg)
        rows = pack_polys(gens, P, int)
        try:
            basis = F4([r for r in rows if r[0]], P, p).run()
            break
        except PackingOverflow:
            maxdeg = 2 * maxdeg + 1
    unpack = P.unpack
    return [{unpack(m): F(c) for m, c in zip(ms, cs)} for ms, cs in basis]
