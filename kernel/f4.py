"""Faugère's F4 over Z/p on packed monomials, with a trace for replaying other primes.

The algorithm (Faugère, J. Pure Appl. Algebra 139, 1999): pick all critical pairs of lowest
degree (the normal strategy: the weighted degree of the lcm for graded orderings, the sugar
for the others, whose lcm degrees grow too fast), put the two multiples of each pair into a
matrix, add by *symbolic preprocessing* a reducer ``u*g`` (``g`` in the basis) for every
monomial of the matrix divisible by a leading monomial, and row-reduce; the rows whose leading
monomial is new join the basis.  Pairs are pruned with the Gebauer–Möller criteria
(Becker–Weispfenning's UPDATE).

Monomials are packed integers (:mod:`.monomials`).  The linear algebra exploits the shape of
F4 matrices.  The columns split into *pivot* columns (leading monomials of reducers; one
reducer each, so the reducer block ``A`` is unit upper triangular) and the few *non-pivot*
columns (monomials divisible by no leading monomial: the staircase).  The reducers are fully
reduced by back substitution from the smallest pivot up: once the tails of the smaller
reducers are free of pivot columns, a row's reduced tail is the one-shot sum
``T_i = N_i - sum_j c_ij T_j`` over the pivot entries ``c_ij`` of its own tail, so a row costs
one scalar-times-vector per pivot entry and pivot columns never fill in.  The rows of the
critical pairs are reduced the same way and their (small) remainder block is brought to
reduced echelon form.

A non-pivot vector is dense but short: one Python integer of 64-bit slots, slot ``s`` holding
the coefficient of the ``s``-th smallest non-pivot monomial (so the tails of reducers with small
pivots are short integers), and ``acc += c * T_j`` runs in C.  Slots stay below ``2^64`` for up
to ``hmax`` products; then every slot is reduced mod ``p`` at once by word-parallel arithmetic
(two folds ``x = h 2^s + l -> h (2^s mod p) + l``, a Barrett quotient and two conditional
subtractions, each one operation on the whole integer).  Primes above ``2^28`` use wider slots
and reduce slot by slot.

With ``record=True`` the run keeps a :class:`Trace`: per matrix, the rows (basis index and,
per term, its pivot or slot) that mattered — the pair rows that raised the rank and the
reducers they need, transitively — and the shape of each new polynomial.  :func:`replay`
redoes only that linear algebra for another prime (Traverso's Gröbner trace) and raises
:class:`TraceMismatch` when the prime does not follow the recorded path.
"""
from __future__ import annotations

from array import array
from collections import deque
from dataclasses import dataclass, field
from operator import lshift, mul
from typing import Callable, Sequence

import flint

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
    polynomial (appended to the basis in this order) its slots, leading one first."""

    K: int
    m: int
    reducers: list[tuple[int, _RowSpec]]
    rows: list[tuple[_RowSpec, int]]
    new: list[list[int]]


@dataclass
class Trace:
    """A recorded F4 run: the steps, ``unit`` if it ended with 1 in the ideal, and the final
    back substitution giving the reduced basis: ``final_out`` lists, in the output order, the
    pivot id of each element and the slots of its tail; ``shape`` holds the monomials."""

    npolys: int
    steps: list[_Step] = field(default_factory=list)
    unit: bool = False
    final: _Step | None = None
    final_out: list[tuple[int, list[int]]] = field(default_factory=list)
    shape: list[list[int]] = field(default_factory=list)


class _Vectors:
    """Dense vectors mod ``p`` packed into Python integers of ``slot``-bit slots.

    For ``p < 2^28`` a slot has ``2 bits(p) + 8`` bits rounded up to whole bytes, so at least
    256 products ``c * entry`` add up without overflow, and slots are normalized word-parallel;
    larger primes get 64-bit multiples and are normalized slot by slot.  The functions for
    vectors of ``m`` slots (:meth:`normalizer`, :meth:`combiner`) are closures over their
    constants, made once per length."""

    def __init__(self, p: int) -> None:
        self.p = p
        b = p.bit_length()
        need = 2 * b + 8
        self.swar = need <= 64
        self.slot = max(16, -(-need // 8) * 8) if self.swar else -(-need // 64) * 64
        self.nbytes = self.slot // 8
        self.hmax = max(1, ((1 << self.slot) - p) // max(1, (p - 1) ** 2) - 1)
        self._norms: dict[int, Callable[[int], int]] = {}
        self._combiners: dict[int, Callable] = {}
        if self.swar:
            self._plan(b)

    def _plan(self, b: int) -> None:
        """Fold splits ``x = h 2^s + l -> h (2^s mod p) + l`` taking the slots below ``2^k``
        with ``2k < slot + b``; then the Barrett quotient ``x (2^k // p) >> k`` is at most one
        too small and one conditional subtraction finishes."""
        w = self.slot
        xbits, folds = w, []
        while 2 * xbits > w + b - 1:
            s = (xbits + b) // 2
            folds.append((s, pow(2, s, self.p)))
            xbits = max(xbits - s + b, s) + 1
        self.folds = folds
        self.k = xbits
        self.M = (1 << self.k) // self.p

    def normalizer(self, m: int) -> Callable[[int], int]:
        """The function reducing every slot of an ``m``-slot vector (slots below ``2^slot``)."""
        norm = self._norms.get(m)
        if norm is not None:
            return norm
        if not self.swar:
            def norm(x: int) -> int:
                return self.pack(self.values(x, m))
        else:
            w, p, k, M, top = self.slot, self.p, self.k, self.M, self.slot - 1
            ones = int.from_bytes((1).to_bytes(self.nbytes, "little") * m, "little")
            folds = [(s, c, ones * ((1 << (w - s)) - 1), ones * ((1 << s) - 1)) for s, c in self.folds]
            mq, K = ones * ((1 << (w - k)) - 1), ones * ((1 << (w - 1)) - p)
            if len(folds) == 2:
                (s1, c1, h1, l1), (s2, c2, h2, l2) = folds

                def norm(x: int) -> int:
                    x = ((x >> s1) & h1) * c1 + (x & l1)
                    x = ((x >> s2) & h2) * c2 + (x & l2)
                    x -= (((x * M) >> k) & mq) * p
                    return x - (((x + K) >> top) & ones) * p
            else:
                def norm(x: int) -> int:
                    for s, c, h, low in folds:
                        x = ((x >> s) & h) * c + (x & low)
                    x -= (((x * M) >> k) & mq) * p
                    return x - (((x + K) >> top) & ones) * p
        self._norms[m] = norm
        return norm

    def combiner(self, m: int) -> Callable[[_RowSpec, list[int], list[int], list[int]], int]:
        """The function giving a row's reduced non-pivot part ``N - sum c_j T_j`` (normalized)
        from the row, the polynomial's coefficients and their negatives, and the reduced
        reducers ``T``."""
        comb = self._combiners.get(m)
        if comb is not None:
            return comb
        norm, hmax, w = self.normalizer(m), self.hmax, self.slot
        scale = w.__mul__
        wide = w == 64

        def comb(row: _RowSpec, coefs: list[int], neg: list[int], T: list[int]) -> int:
            np_t = row.np_t
            if not np_t:
                acc = 0
            elif wide and len(np_t) > 8:
                vals = [0] * m
                deque(map(vals.__setitem__, row.np_s, map(coefs.__getitem__, np_t)), maxlen=0)
                acc = int.from_bytes(array("Q", vals), "little")
            else:
                acc = sum(map(lshift, map(coefs.__getitem__, np_t), map(scale, row.np_s)))
            piv_t = row.piv_t
            if not piv_t:
                return acc
            if len(piv_t) <= hmax:
                return norm(sum(map(mul, map(neg.__getitem__, piv_t), map(T.__getitem__, row.piv_j)), acc))
            piv_j = row.piv_j
            for i in range(0, len(piv_t), hmax):
                acc = norm(sum(map(mul, map(neg.__getitem__, piv_t[i:i + hmax]),
                                   map(T.__getitem__, piv_j[i:i + hmax])), acc))
            return acc
        self._combiners[m] = comb
        return comb

    def pack(self, vals: list[int]) -> int:
        """The vector with the given slots (each below ``2^64``)."""
        words = array("Q", vals).tobytes()
        nb = self.nbytes
        if nb == 8:
            return int.from_bytes(words, "little")
        if nb > 8:  # wide slots: one word of value, zero words above it
            buf = bytearray(nb * len(vals))
            for k in range(8):
                buf[k::nb] = words[k::8]
            return int.from_bytes(buf, "little")
        buf = bytearray(nb * len(vals))
        for k in range(nb):  # keep the low nb bytes of every word
            buf[k::nb] = words[k::8]
        return int.from_bytes(buf, "little")

    def values(self, x: int, m: int) -> list[int]:
        """The ``m`` slots of ``x``, reduced mod p."""
        p, nb = self.p, self.nbytes
        b = x.to_bytes(nb * m, "little")
        if nb == 8:
            return [v % p for v in memoryview(b).cast("Q").tolist()]
        if nb > 8:
            return [int.from_bytes(b[i:i + nb], "little") % p for i in range(0, len(b), nb)]
        buf = bytearray(8 * m)
        for k in range(nb):  # widen every slot to a word, C-speed slice copies
            buf[k::8] = b[k::nb]
        return [v % p for v in memoryview(buf).cast("Q").tolist()]

    def lead(self, x: int) -> int:
        """The highest nonzero slot of a nonzero vector."""
        return (x.bit_length() - 1) // self.slot

    def add_multiples(self, x: int, terms: list[tuple[int, int]], m: int) -> int:
        """``x + sum c * y`` for ``(c, y)`` in ``terms`` (all entries below p), normalized."""
        norm = self.normalizer(m)
        for i in range(0, len(terms), self.hmax):
            x = norm(sum(c * y for c, y in terms[i:i + self.hmax]) + x)
        return x


def _echelon(vec: _Vectors, rows: list[int], m: int,
             expect: list[int] | None = None) -> tuple[dict[int, int], list[tuple[int, int]]]:
    """Reduced echelon form of the packed rows: ``{pivot slot: packed monic row}`` and the
    (row index, pivot slot) of the rows that raised the rank.  With ``expect`` (replay) every
    row must raise the rank at the given slot.

    Rows are first reduced by the earlier pivot rows in turn (reading each entry mod p, so
    the vector is normalized only once per row), then back-substituted from the last pivot."""
    p, w = vec.p, vec.slot
    mask, hmax = (1 << w) - 1, vec.hmax
    norm = vec.normalizer(m)
    piv: list[tuple[int, int]] = []
    used: list[tuple[int, int]] = []
    for r, x in enumerate(rows):
        if x:
            n = 0
            for s, y in piv:
                c = ((x >> (w * s)) & mask) % p
                if c:
                    x += (p - c) * y
                    n += 1
                    if n == hmax:
                        x, n = norm(x), 0
            if n:
                x = norm(x)
        s0 = vec.lead(x) if x else None
        if expect is not None and s0 != expect[r]:
            raise TraceMismatch("a pair row reduced differently")
        if s0 is None:
            continue
        c = (x >> (w * s0)) & mask
        if c != 1:
            x = norm(x * pow(c, -1, p))
        piv.append((s0, x))
        used.append((r, s0))
    E: dict[int, int] = {}
    for i in range(len(piv) - 1, -1, -1):
        s0, x = piv[i]
        terms = [(p - c, E[s]) for s, _ in piv[i + 1:] if (c := (x >> (w * s)) & mask)]
        E[s0] = vec.add_multiples(x, terms, m) if terms else x
    return E, used


def _support(vec: _Vectors, x: int, m: int) -> tuple[list[int], list[int]]:
    """The nonzero slots of a vector, highest first, and their values."""
    vals = vec.values(x, m)
    slots = [s for s in range(m - 1, -1, -1) if vals[s]]
    return slots, [vals[s] for s in slots]


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
        self.active: list[bool] = []   # basis elements usable as reducers and in new pairs
        self.pairs: list[tuple[int, int, int, int]] = []  # (sugar, lcm, i, j); j < 0: an input row
        self.divisor: dict[int, int] = {}  # monomial -> reducer, or -1 - (basis size scanned)
        self.trace = Trace(len(polys)) if record else None
        self.work = 0  # matrix entries handled, a measure of the size of the computation
        for ms, cs in polys:
            k = self._add(ms, cs, is_basis=False)
            key = packing.weighted_degree(ms[0]) if packing.graded else self.tdeg[k]
            self.pairs.append((key, ms[0], k, -1))

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
        self.active.append(is_basis)
        return len(self.mons) - 1

    def _update(self, h: int) -> None:
        """Add basis element ``h``: new pairs and pruned old ones (Gebauer–Möller).  The
        criteria compare lcms by their exponent fields only (word-parallel, no repacking)."""
        P = self.P
        g, eg, eall = P.guard, P.eguard, P.eall
        lcm_e = P.lcm_e
        mons, active = self.mons, self.active
        H = mons[h][0]
        He = H & eall
        cands = []
        for i in range(h):
            if active[i]:
                li = mons[i][0]
                Le = lcm_e(li, H)
                cands.append((Le, i, Le == (li & eall) + He))
        # criterion M: drop (i,h) if another new pair's lcm properly divides its lcm;
        # criterion F: among equal lcms keep one, a coprime one if there is one.  In increasing
        # order of the exponent fields (lexicographic, so divisors come first) it suffices to
        # test the lcms kept so far.
        cands.sort()
        kept: dict[int, tuple] = {}
        for c in cands:
            Le = c[0]
            prev = kept.get(Le)
            if prev is not None:
                if c[2] and not prev[2]:
                    kept[Le] = c
                continue
            Lg = Le | eg
            for d in kept:
                if (Lg - d) & eg == eg:
                    break
            else:
                kept[Le] = c
        degree, sugar, graded = P.degree, self.sugar, P.graded
        dH, sh = degree(H), sugar[h]
        new = []
        for Le, i, coprime in kept.values():
            if coprime:
                continue
            li = mons[i][0]
            L = P.lcm(li, H)
            dL = degree(L)
            if dL > P.maxdeg:
                raise PackingOverflow
            key = P.weighted_degree(L) if graded else max(sugar[i] + dL - degree(li), sh + dL - dH)
            new.append((key, L, i, h))
        # criterion B on the old pairs
        old = []
        for pr in self.pairs:
            s, L, i, j = pr
            if j >= 0 and ((L | g) - H) & g == g:
                Le = L & eall
                if lcm_e(mons[i][0], H) != Le and lcm_e(mons[j][0], H) != Le:
                    continue
            old.append(pr)
        self.pairs = old + new
        for i in range(h):
            if active[i] and ((mons[i][0] | g) - H) & g == g:
                active[i] = False
        active[h] = True

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
        degree, maxdeg = P.degree, P.maxdeg
        mons, tdeg = self.mons, self.tdeg
        reducers = sorted(((mons[k][0], k) for k in range(len(mons)) if self.active[k]),
                          key=lambda t: len(mons[t[1]]))
        rowmons: dict[tuple[int, int], list[int]] = {}
        nonpivot: list[int] = []
        seen: set[int] = set(pivots)
        queue = list(specs) + list(pivots.values())
        find = self._find_reducer
        while queue:
            spec = queue.pop()
            if spec in rowmons:
                continue
            k, u = spec
            if degree(u) + tdeg[k] > maxdeg:
                raise PackingOverflow
            rm = [u + x for x in mons[k]] if u else mons[k]
            rowmons[spec] = rm
            fresh = set(rm).difference(seen)
            seen.update(fresh)
            for x in fresh:
                r = find(x, reducers)
                if r >= 0:
                    s = (r, x - mons[r][0])
                    pivots[x] = s
                    queue.append(s)
                else:
                    nonpivot.append(x)
        return rowmons, nonpivot

    @staticmethod
    def _spec(rm: list[int], k: int, where: dict[int, int], skip_lead: bool) -> _RowSpec:
        piv_t, piv_j, np_t, np_s = [], [], [], []
        for t in range(1 if skip_lead else 0, len(rm)):
            c = where[rm[t]]
            if c >= 0:
                piv_t.append(t)
                piv_j.append(c)
            else:
                np_t.append(t)
                np_s.append(~c)
        return _RowSpec(k, piv_t, piv_j, np_t, np_s)

    def _matrix(self, crow_specs: list[tuple[int, int]], pivots: dict[int, tuple[int, int]]):
        """Build and reduce a matrix.  Returns the reduced reducers ``T`` (by pivot id), the
        pivot columns (increasing), the non-pivot monomials (increasing: slot order), the
        echelon form of the reduced pair rows, the rows that raised the rank, and the row specs
        (reducers by pivot id, pair rows) for the trace."""
        rowmons, nonpivot = self._symbolic(crow_specs, pivots)
        self.work += sum(map(len, rowmons.values()))
        pivcols = sorted(pivots)
        nonpivot.sort()
        K, m = len(pivcols), len(nonpivot)
        where = dict(zip(pivcols, range(K)))
        where.update(zip(nonpivot, range(-1, -m - 1, -1)))
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
        E, used = _echelon(vec, D, m)
        return T, pivcols, nonpivot, E, used, red_specs, c_specs

    def _record(self, K: int, m: int, red_specs: list[_RowSpec], rows: list[tuple[_RowSpec, int]],
                new: list[list[int]], roots: Sequence[int] = ()) -> _Step:
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

    def _pair_rows(self, sel: list[tuple[int, int, int, int]]):
        """The rows of the selected pairs: per lcm one row becomes its reducer, the others
        are to be reduced (``(k, u)`` stands for ``x^u * poly[k]``)."""
        pivots: dict[int, tuple[int, int]] = {}
        crows: list[tuple[int, int]] = []
        seen: set[tuple[int, int]] = set()
        mons = self.mons
        for s, L, i, j in sel:
            for k in ((i,) if j < 0 else (i, j)):
                spec = (k, L - mons[k][0])
                if spec in seen:
                    continue
                seen.add(spec)
                if j >= 0 and L not in pivots:
                    pivots[L] = spec
                else:
                    crows.append(spec)
        return pivots, crows

    def _step(self) -> bool:
        """Process the pairs of lowest degree; returns False when 1 is in the ideal."""
        d = min(pr[0] for pr in self.pairs)
        sel = [pr for pr in self.pairs if pr[0] == d]
        self.pairs = [pr for pr in self.pairs if pr[0] != d]
        pivots, crows = self._pair_rows(sel)
        if not crows:
            return True
        T, pivcols, nonpivot, E, used, red_specs, c_specs = self._matrix(crows, pivots)
        m = len(nonpivot)
        new = [_support(self.vec, E[s0], m) for s0 in sorted(E)]  # increasing leading monomial
        if self.trace is not None and used:
            rows = [(c_specs[r], s0) for r, s0 in used]
            self.trace.steps.append(self._record(len(pivcols), m, red_specs, rows, [s for s, _ in new]))
        for slots, vals in new:
            k = self._add([nonpivot[s] for s in slots], vals, True, d)
            if self.mons[k][0] == 0:
                return False
            self._update(k)
        return True

    # -- the whole computation ---------------------------------------------------------------
    def run(self) -> list[Row]:
        """The reduced Gröbner basis, monic, by increasing leading monomial."""
        while self.pairs:
            if not self._step():
                if self.trace is not None:
                    self.trace.unit = True
                    self.trace.shape = [[0]]
                return [([0], [1])]
        return self._reduce()

    def _reduce(self) -> list[Row]:
        """Tail-reduce the minimal basis with one more back substitution."""
        g = self.P.guard
        mons = self.mons
        lms = [mons[k][0] for k in range(len(mons)) if self.active[k]]
        keep = [k for k in range(len(mons)) if self.active[k]
                and not any(((mons[k][0] | g) - lm) & g == g and lm != mons[k][0] for lm in lms)]
        keep.sort(key=lambda k: mons[k][0])
        pivots = {mons[k][0]: (k, 0) for k in keep}
        T, pivcols, nonpivot, _, _, red_specs, _ = self._matrix([], pivots)
        m = len(nonpivot)
        where = dict(zip(pivcols, range(len(pivcols))))
        out, final = [], []
        for k in keep:
            lm = mons[k][0]
            j = where[lm]
            slots, vals = _support(self.vec, T[j], m)
            out.append(([lm] + [nonpivot[s] for s in slots], [1] + vals))
            final.append((j, slots))
        if self.trace is not None:
            self.trace.final = self._record(len(pivcols), m, red_specs, [], [], [j for j, _ in final])
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
    pivots, crows = eng._pair_rows(eng.pairs)
    if not crows:
        return True
    return not eng._matrix(crows, pivots)[3]


def replay(trace: Trace, polys: Sequence[list[int]], p: int) -> list[list[int]]:
    """The coefficients mod ``p`` of the reduced basis recorded in ``trace`` (monomials in
    ``trace.shape``), given the generators' coefficients mod ``p`` in the recorded shape."""
    vec = _Vectors(p)
    coefs: list[list[int]] = [list(c) for c in polys]
    neg = [[p - c for c in cs] for cs in coefs]
    for st in trace.steps:
        T = [0] * st.K
        combine = vec.combiner(st.m)
        for j, spec in st.reducers:
            T[j] = combine(spec, coefs[spec.k], neg[spec.k], T)
        D = [combine(spec, coefs[spec.k], neg[spec.k], T) for spec, _ in st.rows]
        E, _ = _echelon(vec, D, st.m, [s0 for _, s0 in st.rows])
        for slots in st.new:
            cs = _values_on(vec, E[slots[0]], st.m, slots)
            coefs.append(cs)
            neg.append([p - c for c in cs])
    if trace.unit:
        return [[1]]
    st = trace.final
    T = [0] * st.K
    combine = vec.combiner(st.m)
    for j, spec in st.reducers:
        T[j] = combine(spec, coefs[spec.k], neg[spec.k], T)
    return [[1] + _values_on(vec, T[j], st.m, slots) for j, slots in trace.final_out]


def _values_on(vec: _Vectors, x: int, m: int, slots: list[int]) -> list[int]:
    """The entries of ``x`` in the given slots, which must hold all its nonzero entries."""
    vals = vec.values(x, m)
    out = [vals[s] for s in slots]
    if m - vals.count(0) != len(out) - out.count(0):
        raise TraceMismatch("a polynomial has a term the recorded run did not have")
    return out


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
    bound = 63
    while bound < 4 * d:
        bound = 2 * bound + 1
    return bound


def f4_modp(gens: Sequence, ring) -> list[dict]:
    """The reduced Gröbner basis over Z/p by F4, as ``{exponent: coefficient}`` dicts."""
    p = ring.field.characteristic
    maxdeg = initial_degree(gens)
    while True:
        P = Packing(ring.order, maxdeg)
        rows = pack_polys(gens, P, int)
        try:
            basis = F4([r for r in rows if r[0]], P, p).run()
            break
        except PackingOverflow:
            maxdeg = 2 * maxdeg + 1
    unpack, nmod = P.unpack, flint.nmod
    return [{unpack(m): nmod(c, p) for m, c in zip(ms, cs)} for ms, cs in basis]


SMALL_WORK = 600
"""Below this much work (matrix entries) in the first modular run, :func:`f4_auto` leaves a
system over QQ to Buchberger, whose smaller overhead wins there (measured on random systems
in three variables: the crossover is near 1000)."""


def f4(gens: Sequence, ring, small_work: int = 0) -> list[dict]:
    """Engine for :func:`.groebner.groebner`: the reduced Gröbner basis of ``gens`` (nonzero
    polynomials over QQ or Z/p, global ordering) as ``{exponent: coefficient}`` dicts, sorted
    by increasing leading monomial, each with its leading exponent first.  Over QQ, systems
    needing less than ``small_work`` (and bases the modular method fails to verify) go to
    Buchberger."""
    from .coeffs import PrimeField, RationalField
    from .groebner import buchberger, reduce_basis
    if any(g.is_constant() for g in gens):
        return [{ring.zero_exp: ring.field.one}]
    if isinstance(ring.field, PrimeField):
        return f4_modp(gens, ring)
    if not isinstance(ring.field, RationalField):
        raise ValueError(f"F4 needs coefficients in QQ or Z/p, not {ring.field!r}")
    from .modular import ModularFailure, SmallSystem, f4_qq
    try:
        return f4_qq(gens, ring, small_work=small_work)
    except (ModularFailure, SmallSystem):
        return _lm_first(reduce_basis(buchberger(gens, ring), ring), ring)


def f4_auto(gens: Sequence, ring) -> list[dict]:
    """The ``auto`` engine: F4 over QQ and Z/p for degree orderings (Buchberger for small
    systems over QQ), Buchberger over other fields and for block and lex orderings, where
    F4's degree-by-degree matrices grow far past the sugar strategy's work."""
    from .coeffs import PrimeField, RationalField
    if ring.order.is_graded and isinstance(ring.field, (PrimeField, RationalField)):
        return f4(gens, ring, SMALL_WORK)
    from .groebner import buchberger, reduce_basis
    return _lm_first(reduce_basis(buchberger(gens, ring), ring), ring)


def _lm_first(basis: list[dict], ring) -> list[dict]:
    """The dicts reordered with the leading exponent first (the engine contract)."""
    key = ring.order.key
    out = []
    for b in basis:
        lm = max(b, key=key)
        d = {lm: b[lm]}
        d.update(b)
        out.append(d)
    return out


f4.returns_reduced = True  # type: ignore[attr-defined]
f4_auto.returns_reduced = True  # type: ignore[attr-defined]
