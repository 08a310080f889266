"""Standard bases for arbitrary monomial orderings (local, mixed, global) by Mora's algorithm.

For a non-global ordering ``>`` the ring of interest is the localization
``K[x]_> = S^-1 K[x]`` with ``S = {u : LM(u) = 1}`` (for local orderings such as ``ds``:
the local ring at the origin).  A standard basis of ``I`` is a finite ``G`` in ``I`` whose
leading monomials generate the leading ideal ``L(I)``.

:func:`mora` is Buchberger's algorithm with Mora's normal form, which bounds the reduction by
the *ecart* ``deg f - deg LM(f)`` and keeps reduced intermediate polynomials as reducers
(Greuel–Pfister, *A Singular Introduction to Commutative Algebra*, Alg. 1.7.6).  Strategy as
in Singular: ecarts follow the sugar (the degree of the homogenized polynomial), one queue
holds generators, pairs and postponed polynomials by sugar, a polynomial whose reduction would
raise its sugar waits while other work comes first, the reducers (basis elements and
intermediate polynomials) persist, leading unit factors ``x^a u`` are cancelled.  Its bases are
usually the ones Singular prints.  Mora's normal form terminates, but on some ideals only after
reductions into degree 50 with coefficients of thousands of digits (Singular's own ``reduce``
hangs on some of them): a :class:`Budget` bounds it, and the engine driver (:mod:`.engines`)
then falls back to Lazard's method (:mod:`.lazard`).  For ``ds`` the polynomial under
reduction lives on packed monomials (:mod:`.mora_packed`), over Z/p in compiled code when the
C extension is built (:mod:`.mora_compiled`: the same steps); the highest corner that cuts the
tails of zero-dimensional ideals is :mod:`.mora_corner`.  Under a cut (a trial's or the
corner's) the computation lives in the finite-dimensional algebra ``K[x]/m^(cut+1)``, and there
reductions take the first reducer (by sugar) without the ecart rule, as Singular does once it
knows its highest corner.  Generators in disjoint sets of
variables are computed group by group (:func:`in_groups`).

Pair criteria: the Gebauer–Möller chain criteria (statements about syzygies of the leading
terms, valid for every ordering, GP 2.5.9) and the product criterion only when it really
gives a standard representation ``spoly(f, g) = f'g - g'f``: for a local ordering
``LM(f')LM(g)`` may equal ``LM(g')LM(f)``, and then the pair must be reduced.
"""
from __future__ import annotations

import heapq
from operator import itemgetter, neg
from typing import Any, Callable, Sequence

from .mora_compiled import CompiledMora
from .mora_corner import Corner
from .mora_packed import MAX_DEGREE, PackedFront, Packing
from .order import Block, Exp, MonomialOrder
from .poly import Poly, PolyRing, add_exp, divides, support_mask

Terms = dict[Exp, Any]


class Elem:
    """A polynomial with its leading data: leading monomial, mask, length and ecart.

    ``ecart`` is ``D - deg LM`` for the degree ``D`` of the homogenized polynomial the
    element stands for (its sugar); by default ``D`` is the polynomial's own degree."""

    __slots__ = ("p", "lm", "mask", "ecart", "key", "_tail", "_rows", "_packed")

    def __init__(self, p: Terms, key: Callable, ecart: int | None = None, lm: Exp | None = None) -> None:
        self.p, self.key = p, key
        self.lm = max(p, key=key) if lm is None else lm
        self._tail: Any = False  # the second monomial, found when first asked for
        self._rows: list | None = None
        self._packed: list | None = None
        self.mask = support_mask(self.lm)
        self.ecart = max(sum(e) for e in p) - sum(self.lm) if ecart is None else ecart

    @property
    def tail_lm(self) -> Exp | None:
        """The largest monomial after the leading one (None for a term)."""
        if self._tail is False:
            lm = self.lm
            tail = [e for e in self.p if e != lm]
            self._tail = max(tail, key=self.key) if tail else None
        return self._tail

    @property
    def rows(self) -> list[tuple[int, Exp, Any]]:
        """``(degree, monomial, coefficient)`` by increasing degree."""
        if self._rows is None:
            self._rows = sorted(((sum(e), e, c) for e, c in self.p.items()), key=lambda r: r[0])
        return self._rows

    def packed(self, pk: Packing) -> list[tuple[int, Any]]:
        """``(packed monomial, coefficient)`` by increasing packed monomial (degree first)."""
        if self._packed is None:
            self._packed = sorted((pk.pack(e), c) for e, c in self.p.items())
        return self._packed

    @property
    def sugar(self) -> int:
        return self.ecart + sum(self.lm)

    def truncate(self, cut: int) -> None:
        """Drop the tail terms of degree above ``cut`` (they lie in the ideal)."""
        if max(sum(e) for e in self.p) > cut:
            self.p = {e: c for e, c in self.p.items() if e == self.lm or sum(e) <= cut}
            self._tail, self._rows, self._packed = False, None, None


class Front:
    """A polynomial under reduction, changed in place: its terms and a heap of their ranks, so
    that the leading monomial costs a rank only for each new term; ``cut``: no term of higher
    degree is left."""

    __slots__ = ("p", "heap", "rank", "cut")

    def __init__(self, p: Terms, rank: Callable, cut: int | None = None) -> None:
        if cut is not None:
            p = {e: c for e, c in p.items() if sum(e) <= cut}
        self.p, self.rank, self.cut = p, rank, cut
        self.heap = [(rank(e), e) for e in p]
        heapq.heapify(self.heap)

    def trim(self, cut: int | None) -> None:
        """Drop the terms of degree above ``cut``."""
        if cut is not None and (self.cut is None or cut < self.cut):
            self.p = {e: c for e, c in self.p.items() if sum(e) <= cut}
            self.cut = cut

    def coeff(self, lm: Exp) -> Any:
        return self.p[lm]

    def terms(self) -> Terms:
        return self.p

    def lm(self) -> Exp:
        """The leading monomial (``p`` must not be empty)."""
        heap, p = self.heap, self.p
        while heap[0][1] not in p:
            heapq.heappop(heap)
        return heap[0][1]

    def reduce(self, lm: Exp, g: Elem) -> None:
        """``p - (LT(p)/LT(g)) g`` for ``LM(g) | lm = LM(p)``, leaving out the terms of
        degree above the cut."""
        p, heap, rank = self.p, self.heap, self.rank
        shift = tuple([a - b for a, b in zip(lm, g.lm)])
        factor = p[lm] / g.p[g.lm]
        top = None if self.cut is None else self.cut - sum(shift)
        for d, e, c in g.rows:
            if top is not None and d > top:
                break
            te = tuple([a + b for a, b in zip(e, shift)])
            v = p.get(te)
            if v is None:
                p[te] = -factor * c
                heapq.heappush(heap, (rank(te), te))
            else:
                v = v - factor * c
                if v == 0:
                    del p[te]
                else:
                    p[te] = v

    def unit_cancelled(self, lm: Exp) -> bool:
        """Replace ``p = x^a u`` (``x^a = LM``, ``u`` a unit) by its leading term; whether it was."""
        p = self.p
        if len(p) > 1 and all(divides(lm, e) for e in p):
            self.p = {lm: p[lm]}
            self.heap = [(self.rank(lm), lm)]
            return True
        return False


class BudgetExceeded(Exception):
    """Mora's normal form ran past its budget (see :class:`Budget`)."""


class Budget:
    """A bound on the work of Mora's normal forms: reduction steps and the size (bits) of
    rational coefficients.  Successful runs on random ideals (3 variables, degree 5) stay
    below 600 steps and 400 bits; runaway ones pass 512 bits within a second.
    ``corner_steps``: the steps granted once the highest corner is found (the computation then
    lives in a finite-dimensional algebra, where every reduction ends; Singular's ``tjurina``
    of vdim_overflow finds it within 20 steps and then takes 5.9 million cheap ones).
    ``degree``: the run stops when a sugar passes this many times the generators' largest
    degree (a normal form running away into high degrees)."""

    def __init__(self, steps: int = 2000, bits: int = 512, corner_steps: int = 0, degree: int | None = None) -> None:
        self.steps, self.bits, self.corner_steps, self.degree = steps, bits, corner_steps, degree

    def corner_found(self) -> None:
        """Grant :attr:`corner_steps` (once)."""
        self.steps, self.corner_steps = max(self.steps, self.corner_steps), 0

    def charge(self, c: Any) -> None:
        """Account for one reduction step of a polynomial with leading coefficient ``c``."""
        self.steps -= 1
        if self.steps < 0 or (hasattr(c, "height_bits") and c.height_bits() > self.bits):
            raise BudgetExceeded


def reduce_by(h: Terms, hlm: Exp, g: Elem, cut: int | None = None) -> Terms:
    """``h - (LT(h)/LT(g)) g`` for ``LM(g) | LM(h)``; with a ``cut``, the terms of ``g``'s
    multiple of degree above it are left out (see :class:`Corner`)."""
    shift = tuple([a - b for a, b in zip(hlm, g.lm)])
    factor = h[hlm] / g.p[g.lm]
    out = dict(h)
    top = None if cut is None else cut - sum(shift)
    for e, c in g.p.items():
        if top is not None and sum(e) > top:
            continue
        te = tuple([a + b for a, b in zip(e, shift)])
        v = out.get(te)
        if v is None:
            out[te] = -factor * c
        else:
            v = v - factor * c
            if v == 0:
                del out[te]
            else:
                out[te] = v
    return out


def _choose(reducers: Sequence[Elem], lm: Exp, ecart: int) -> Elem | None:
    """A reducer whose leading monomial divides ``lm``: the first (reducers are kept by
    increasing sugar) unless its ecart exceeds ``ecart``; then one of least ecart, shorter
    ones first, stopping at the first whose ecart is at most ``ecart``."""
    mask = support_mask(lm)
    best = None
    for g in reducers:
        if g.mask & ~mask or not divides(g.lm, lm):
            continue
        if best is None or g.ecart < best.ecart or (g.ecart == best.ecart and len(g.p) < len(best.p)):
            best = g
        if best.ecart <= ecart:
            break
    return best


def mora_normal_form(f: Terms, reducers: Sequence[Elem], key: Callable,
                     budget: Budget | None = None) -> Terms:
    """Mora's weak normal form (GP Alg. 1.7.6 with sugar ecarts): ``h`` with ``u f - h`` in
    the ideal of the reducers for a unit ``u`` (``LM(u) = 1``), and ``h = 0`` or ``LM(h)``
    divisible by no leading monomial of a reducer.  Only leading terms are reduced.
    Raises :class:`BudgetExceeded` when a ``budget`` is given and runs out."""
    pool = sorted(reducers, key=lambda g: g.sugar)
    h, sugar = f, max(sum(e) for e in f) if f else 0
    while h:
        h = cancel_unit(h, key)
        lm = max(h, key=key)
        ecart = sugar - sum(lm)
        g = _choose(pool, lm, ecart)
        if g is None:
            return h
        if budget is not None:
            budget.charge(h[lm])
        if g.ecart > ecart:
            _insert(pool, Elem(h, key, ecart))
            sugar += g.ecart - ecart
        h = reduce_by(h, lm, g)
    return h


def _insert(pool: list[Elem], g: Elem) -> None:
    """Insert keeping ``pool`` sorted by sugar (after the elements of equal sugar)."""
    s = g.sugar
    i = len(pool)
    while i and pool[i - 1].sugar > s:
        i -= 1
    pool.insert(i, g)


def cancel_unit(h: Terms, key: Callable) -> Terms:
    """``lc(h) x^a`` when ``h = x^a u`` with ``x^a = LM(h)`` and ``u`` a unit of ``K[x]_>``
    (every term of ``h`` divisible by its leading monomial); ``h`` otherwise."""
    if len(h) > 1:
        lm = max(h, key=key)
        if all(divides(lm, e) for e in h):
            return {lm: h[lm]}
    return h


def monic(h: Terms, key: Callable) -> Terms:
    """``h`` divided by its leading coefficient."""
    lm = max(h, key=key)
    inv = 1 / h[lm]
    return {e: c * inv for e, c in h.items()}


def _lifts(f: Elem, g: Elem) -> bool:
    """Whether the pair (f, g) satisfies the product criterion with a standard
    representation: coprime leading monomials and ``LM(f')LM(g) != LM(g')LM(f)``."""
    if f.mask & g.mask:
        return False
    if f.tail_lm is None or g.tail_lm is None:
        return True
    return add_exp(f.tail_lm, g.lm) != add_exp(g.tail_lm, f.lm)


# Lazy reduction (as in Singular): a polynomial whose reduction would raise its sugar
# goes back to the queue when other work comes first, and so does one whose sugar rose
# LAZY_DEGREE above its start or that took more than LAZY_PASS reductions.
LAZY_DEGREE = 1
LAZY_PASS = 2


class _Pair:
    __slots__ = ("i", "j", "lcm", "mask", "packed", "alive")

    def __init__(self, i: int, j: int, lcm: Exp, mask: int, packed: int) -> None:
        self.i, self.j, self.lcm, self.mask, self.packed, self.alive = i, j, lcm, mask, packed, True


class _Words:
    """Monomials of ``n`` variables as one integer of 16-bit fields (exponents below 2^15, the
    top bit of each field a guard): lcm, divisibility and degree in a few integer operations,
    for the pair criteria (``a`` divides ``b`` when ``((b | guard) - a) & guard == guard``)."""

    def __init__(self, n: int) -> None:
        self.shifts = [16 * i for i in range(n)]
        self.guard = sum(0x8000 << s for s in self.shifts)
        self.ones = sum(1 << s for s in self.shifts)
        self.top = 16 * (n - 1)

    def pack(self, e: Exp) -> int:
        return sum(v << s for v, s in zip(e, self.shifts))

    def unpack(self, w: int) -> Exp:
        return tuple([(w >> s) & 0xFFFF for s in self.shifts])

    def lcm(self, a: int, b: int) -> int:
        keep = ((((a | self.guard) - b) & self.guard) >> 15) * 0xFFFF  # the fields where a >= b
        return (a & keep) | (b & ~keep)

    def lcms(self, packs: list[int], active: list[bool], b: int) -> list[tuple[int, int, int]]:
        """``(degree, lcm, i)`` of ``lcm(packs[i], b)`` for the ``active`` ones (:meth:`lcm`
        inlined: a new element meets every old one; the degree is the fields' sum, which a
        multiplication by ``ones`` lands in the top field)."""
        guard, ones, top = self.guard, self.ones, self.top
        out = []
        for i, a in enumerate(packs):
            if active[i]:
                keep = ((((a | guard) - b) & guard) >> 15) * 0xFFFF
                lc = (a & keep) | (b & ~keep)
                out.append(((lc * ones >> top) & 0xFFFF, lc, i))
        return out


def _leading_rank(ring: PolyRing) -> Callable[[Exp], tuple]:
    """A sort key that puts larger monomials first (the ordering's key negated)."""
    blocks, key = ring.order.blocks, ring.order.key
    if len(blocks) == 1 and blocks[0].kind == "ds" and ring.nvars > 1:
        return lambda e: (sum(e), e[::-1])
    if len(blocks) == 1 and blocks[0].kind == "dp" and ring.nvars > 1:
        return lambda e: (-sum(e), e[::-1])
    return lambda e: tuple(map(neg, key(e)))


# Trial cuts (see mora): multiples of the generators' largest degree, and the steps one may take
TRIAL_CUTS = (2, 3, 4, 6)
TRIAL_STEPS = 200_000


def mora(gens: Sequence[Poly], ring: PolyRing, budget: Budget | None = None,
         shared: bool = False, trials: bool = True) -> list[Terms]:
    """A minimal standard basis (as dicts, each with its leading monomial first, leading-term
    reduced, monic) by Buchberger's
    algorithm with Mora's normal form: the Gebauer–Möller criteria, a queue of generators,
    pairs and postponed polynomials ordered by sugar, and one growing set of reducers
    (basis elements and the intermediate polynomials Mora's normal form keeps).

    For a local degree ordering the highest corner is used as soon as it is known
    (:class:`Corner`), and first the computation is tried in ``K[x]_> / m^(k+1)`` for a few
    trial degrees ``k``: a standard basis ``G`` of ``J = I + m^(k+1)`` whose leading ideal
    contains every monomial of degree ``k`` gives ``m^k`` in ``J = I + m m^k``, so ``m^k`` in
    ``I`` by Nakayama's lemma, ``J = I`` and ``G`` is a standard basis of ``I``.  Otherwise
    (the local ideal is not zero-dimensional, or its corner lies higher) the computation
    runs without a cut; a trial cut is skipped when an earlier trial left a monomial of that
    degree outside its leading monomials, and the next trial is then one degree above it.  Raises :class:`BudgetExceeded` when a ``budget`` is given and runs
    out; the trials are skipped when the ideal of the local ring is seen not to be
    zero-dimensional, so that no trial can succeed: there are fewer generators than variables in
    them (Krull's height theorem, :func:`positive_dimensional`), or its zero set contains a
    coordinate axis (:func:`contains_axis`); each trial has its own budget of :data:`TRIAL_STEPS` steps, or with ``shared`` the
    trials and the final run all draw on ``budget``; ``trials=False`` skips the trial cuts.
    Generators in disjoint sets of variables are computed group by group (:func:`in_groups`)."""
    live = [g for g in gens if not g.is_zero()]
    return in_groups(live, ring, lambda part, sub: mora_group(part, sub, budget, shared, trials))


def mora_group(live: list[Poly], ring: PolyRing, budget: Budget | None = None, shared: bool = False,
               trials: bool = True) -> list[Terms]:
    """:func:`mora` on nonzero generators that :func:`in_groups` does not split."""
    if live and trials and Corner(ring).enabled and not any(trial_obstacles(live)):
        top = max(g.total_degree() for g in live)
        seen = -1  # a trial's leading monomials left a monomial of this degree outside: skip cuts below
        cuts = [factor * max(top, 1) for factor in TRIAL_CUTS]
        while cuts:
            k = cuts.pop(0)
            if k <= seen:
                continue
            try:
                trial = budget if shared or budget is None else Budget(TRIAL_STEPS, budget.bits)
                basis, corner = _mora(live, ring, trial, k)
            except BudgetExceeded:
                if shared:
                    raise
                break
            if corner.found and corner.cut < k:
                return basis
            if corner.seen is not None and corner.seen >= k:
                cuts.insert(0, corner.seen + 1)  # the least cut above the monomial left outside
            seen = max(seen, corner.seen if corner.seen is not None else -1)
    return _mora(live, ring, budget)[0]


RESTRICTABLE = ("ds", "Ds", "ls", "dp", "Dp", "lp")
"""Orderings that compare monomials in some of the variables as the same ordering of those
variables alone (in their order) does."""


def in_groups(gens: list[Poly], ring: PolyRing, solve: Callable[[list[Poly], PolyRing], list[Terms]]) -> list[Terms]:
    """``solve(part, part_ring)`` (a standard basis) on each group of generators of :func:`_separate`,
    the bases together: a standard basis of the ideal (``[1]`` when a group gives the unit ideal).
    A group is solved in the ring of its own variables when the ordering allows
    (:data:`RESTRICTABLE`: a standard basis there is one in ``ring``, its standard representations
    stay standard); groups equal up to renaming their variables in order (a sum of copies of one
    singularity, as in Singular's vdim_overflow test) are solved once."""
    parts = _separate(gens, ring.nvars)
    if len(parts) == 1:
        return solve(gens, ring)
    blocks = ring.order.blocks
    kind = blocks[0].kind if len(blocks) == 1 and blocks[0].kind in RESTRICTABLE else None
    known: dict[tuple, list[Terms]] = {}
    out = []
    for used, part in parts:
        basis = solve(part, ring) if kind is None else _part_basis(part, used, ring, kind, solve, known)
        if basis and ring.zero_exp in basis[0]:
            return basis  # the unit ideal (a minimal basis has one element then, with the term 1)
        out.extend(basis)
    return out


def _part_basis(part: list[Poly], used: list[int], ring: PolyRing, kind: str,
                solve: Callable[[list[Poly], PolyRing], list[Terms]], known: dict[tuple, list[Terms]]) -> list[Terms]:
    """``solve`` on one group of :func:`in_groups` in the ring of its variables ``used`` (ordered
    by ``kind``), unless ``known`` holds the basis of a copy; the basis in ``ring``."""
    step = used[1] - used[0] if len(used) > 1 else 1
    spaced = all(b - a == step for a, b in zip(used, used[1:]))
    where = slice(used[0], used[-1] + 1, step)  # evenly spaced variables: one slice
    if spaced:
        local = [{e[where]: c for e, c in g.terms.items()} for g in part]
    else:
        restrict = itemgetter(*used)
        local = [{restrict(e): c for e, c in g.terms.items()} for g in part]
    key = (len(used), tuple(tuple(g.items()) for g in local))  # copies built alike list their terms alike
    basis = known.get(key)
    if basis is None:
        sub = PolyRing(ring.field, [ring.names[i] for i in used], MonomialOrder([Block(kind, len(used))]))
        basis = known[key] = solve([Poly(sub, g) for g in local], sub)
    full = [0] * ring.nvars
    out = []
    for b in basis:
        terms = {}
        for e, c in b.items():
            if spaced:
                full[where] = e
            else:
                for i, v in zip(used, e):
                    full[i] = v
            terms[tuple(full)] = c
        out.append(terms)
    return out


def _variables(gens: Sequence[Poly]) -> tuple[list[int], set[int]]:
    """The variables occurring in ``gens``, and those of which a pure power is a term."""
    terms = [e for g in gens for e in g.terms]
    if not terms:
        return [], set()
    used = [i for i, column in enumerate(zip(*terms)) if any(column)]
    others = len(terms[0]) - 1
    powers = {e.index(max(e)) for e in terms if e.count(0) == others}
    return used, powers


def trial_obstacles(gens: Sequence[Poly]) -> tuple[bool, bool]:
    """``(positive_dimensional(gens), contains_axis(gens))`` from one pass over the terms: either
    shows the ideal of the local ring is not zero-dimensional, so that no trial cut can succeed."""
    used, powers = _variables(gens)
    return len(gens) < len(used), not powers.issuperset(used)


def positive_dimensional(gens: Sequence[Poly]) -> bool:
    """Whether there are fewer generators than variables in them: the ideal of the local ring
    then has positive dimension (Krull's height theorem: its height is at most the number of
    generators), or is the whole ring."""
    return len(gens) < len(_variables(gens)[0])


def contains_axis(gens: Sequence[Poly]) -> bool:
    """Whether some variable occurring in ``gens`` has no pure power among their terms: the ideal
    then lies in the ideal of that variable's coordinate axis (every term is divisible by another
    variable), its zero set contains the axis, and the ideal of the local ring is not
    zero-dimensional (Singular's mora_9: five such variables)."""
    used, powers = _variables(gens)
    return not powers.issuperset(used)


def _separate(gens: list[Poly], n: int) -> list[tuple[list[int], list[Poly]]]:
    """The generators grouped by the variables they share, in the order of their first
    generators, each group with its variables; one group (with every variable) when they cannot
    be split or one of them is a constant.  Standard bases of the groups together are one of the
    whole ideal, for every ordering: an S-polynomial of ``f`` and ``g`` in disjoint variables is
    ``tail(f) g - tail(g) f``, whose two products have different leading monomials (one is
    ``LM(tail f) LM(g)``, the other ``LM(tail g) LM(f)``): a standard representation."""
    zero = (0,) * n
    if len(gens) < 2 or any(zero in g.terms for g in gens):
        return [(list(range(n)), gens)]
    groups: list[tuple[int, list[int]]] = []  # (the variables as a mask, the generators' positions)
    for k, g in enumerate(gens):
        mask = 0
        for i, column in enumerate(zip(*g.terms)):
            if any(column):
                mask |= 1 << i
        members = [k]
        rest = []
        for group in groups:
            if group[0] & mask:
                mask |= group[0]
                members += group[1]
            else:
                rest.append(group)
        rest.append((mask, members))
        groups = rest
    if len(groups) == 1:
        return [(list(range(n)), gens)]
    groups.sort(key=lambda group: min(group[1]))
    return [([i for i in range(n) if mask >> i & 1], [gens[k] for k in sorted(members)]) for mask, members in groups]


def _mora(gens: Sequence[Poly], ring: PolyRing, budget: Budget | None = None,
          cut: int | None = None) -> tuple[list[Terms], Corner]:
    """:func:`mora` on ``K[x]_> / m^(cut+1)`` (terms of degree above ``cut`` dropped) or, without
    a cut, on ``K[x]_>``; the basis and the corner found."""
    key = ring.order.key
    sign = 1 if ring.order.is_global else -1
    basis: list[Elem] = []
    active: list[bool] = []
    words = _Words(ring.nvars)
    packs: list[int] = []  # the basis' leading monomials packed
    pairs: list[_Pair] = []
    pool: list[Elem] = []  # reducers, sorted by sugar
    queue: list[tuple] = []  # (sugar, rank of LM, counter, pair or (h, sugar))
    counter = 0
    corner = Corner(ring, cut, _variables(gens)[0])

    def rank(e: Exp) -> tuple:  # smallest first for global orderings, largest first otherwise
        return tuple(sign * v for v in key(e))

    lead = _leading_rank(ring)
    blocks = ring.order.blocks
    ds = len(blocks) == 1 and blocks[0].kind == "ds"
    compiled = CompiledMora(ring) if CompiledMora.usable(ring) else None
    packing = Packing(ring.nvars) if ds and compiled is None else None
    if ds:
        rank = lead  # the same order as ``rank`` above, sooner computed

    def front(terms: Terms) -> Front | PackedFront | bytes:
        if compiled is not None:
            b = compiled.pack(terms)
            if b is None:
                raise BudgetExceeded
            return b
        if packing is not None:
            if max((sum(e) for e in terms), default=0) > MAX_DEGREE:
                raise BudgetExceeded
            return PackedFront(terms, packing, corner.cut)
        return Front(terms, lead, corner.cut)

    def push(sugar: int, lm: Exp, item: Any) -> None:
        nonlocal counter
        counter += 1
        heapq.heappush(queue, (sugar, rank(lm), counter, item, lm))

    def drop_dead() -> None:
        """Drop the dead pairs at the head of the queue."""
        while queue and isinstance(queue[0][3], _Pair) and not queue[0][3].alive:
            heapq.heappop(queue)

    def first_in_queue(sugar: int, lm: Exp) -> bool:
        """Whether work of this sugar and leading monomial would be taken before the rest."""
        drop_dead()
        return not queue or (sugar, rank(lm)) <= queue[0][:2]

    def update(h: Elem) -> None:
        k = len(basis)
        basis.append(h)
        active.append(True)
        hp = words.pack(h.lm)
        if not k:
            packs.append(hp)
            return  # no pairs, nothing to deactivate
        hmask = h.mask
        lcm, guard = words.lcm, words.guard
        # the new pairs whose lcm no other new lcm of lower degree divides (Gebauer–Möller's M;
        # divisibility is transitive, so checking the kept ones of lower degree suffices)
        new = words.lcms(packs, active, hp)
        packs.append(hp)
        new.sort(key=itemgetter(0))
        kept: list[tuple[int, int, int, int]] = []  # (degree, mask, packed lcm, i)
        lower = 0  # kept[:lower] have a degree below the current one
        for d, lc, i in new:
            while lower < len(kept) and kept[lower][0] < d:
                lower += 1
            m = basis[i].mask | hmask
            top = lc | guard
            for j in range(lower):
                _, km, kl, _ = kept[j]
                if not km & ~m and (top - kl) & guard == guard:  # kl divides lc
                    break
            else:
                kept.append((d, m, lc, i))
        by_lcm: dict[int, tuple[_Pair, bool]] = {}
        for _, m, lc, i in kept:
            lifts = _lifts(basis[i], h)
            prev = by_lcm.get(lc)
            if prev is None or (lifts and not prev[1]):
                by_lcm[lc] = (_Pair(i, k, words.unpack(lc), m, lc), lifts)
        if pairs:
            dead = False
            for p in pairs:
                if p.alive and not hmask & ~p.mask and ((p.packed | guard) - hp) & guard == guard \
                        and lcm(packs[p.i], hp) != p.packed and lcm(packs[p.j], hp) != p.packed:
                    p.alive = False
                if not p.alive:
                    dead = True
            if dead:
                pairs[:] = [p for p in pairs if p.alive]
        for a, lifts in by_lcm.values():
            if not lifts:
                pairs.append(a)
                push(sum(a.lcm) + max(basis[a.i].ecart, h.ecart), a.lcm, a)
        for i in range(k):
            if active[i] and not hmask & ~basis[i].mask and ((packs[i] | guard) - hp) & guard == guard:
                active[i] = False

    max_sugar = None if budget is None or budget.degree is None else \
        budget.degree * max(1, max((g.total_degree() for g in gens), default=1))
    waiting = 0  # polynomials postponed inside the compiled loop (they wait there, not in ``queue``)

    def run_compiled(w: bytes | None, sugar: int) -> tuple[bytes, int] | None:
        """:func:`reduce` in compiled code, which goes on with the polynomials postponed there
        while they come before the queue's head; an irreducible nonzero polynomial or None."""
        nonlocal counter, waiting
        drop_dead()
        head = (queue[0][0], queue[0][4], queue[0][2]) if queue else None
        status, h, sugar, left, counter, waiting = compiled.run(
            w, sugar, head, corner.cut, None if budget is None else budget.steps, counter,
            MAX_DEGREE if max_sugar is None else max_sugar)
        if budget is not None:
            budget.steps = left
        if status == 2:
            raise BudgetExceeded
        return (h, sugar) if status == 0 else None

    def reduce(w: Front, sugar: int) -> tuple[Terms, int] | None:
        """Reduce until irreducible (returned with its sugar; {} for zero) or postponed
        (None)."""
        if compiled is not None:
            return run_compiled(w, sugar)
        w.trim(corner.cut)
        if corner.cut is not None:
            return reduce_cut(w, sugar)
        limit, passes = sugar + LAZY_DEGREE, 0
        while w.p:
            lm = w.lm()
            w.unit_cancelled(lm)
            ecart = sugar - sum(lm)
            g = _choose(pool, lm, ecart)
            if g is None:
                return w.terms(), sugar
            if budget is not None:
                budget.charge(w.coeff(lm))
            if g.ecart > ecart:
                if not first_in_queue(sugar, lm):
                    push(sugar, lm, (w, sugar))
                    return None
                _insert(pool, Elem(dict(w.terms()), key, ecart, lm))
                sugar += g.ecart - ecart
                if (max_sugar is not None and sugar > max_sugar) or (sugar > MAX_DEGREE and packing is not None):
                    raise BudgetExceeded
            w.reduce(lm, g)
            if not w.p:
                break
            passes += 1
            if sugar >= limit or passes > LAZY_PASS:
                lm = w.lm()
                if not first_in_queue(sugar, lm):
                    if _choose(pool, lm, sugar - sum(lm)) is None:
                        return w.terms(), sugar
                    push(sugar, lm, (w, sugar))
                    return None
        return w.terms(), sugar

    def reduce_cut(w: Front, sugar: int) -> tuple[Terms, int]:
        """Reduce until irreducible in ``K[x]/m^(cut+1)``: a finite-dimensional algebra, where
        each step replaces the leading term by smaller terms of a finite set of monomials, so
        that the reduction ends without Mora's ecart rule; the first reducer each time (by
        sugar), and nothing is postponed.  (In ``tjurina`` of Singular's vdim_overflow test the ecart rule
        took 3.4 million steps on one S-polynomial of 7 terms, 16 s, with four curves.)"""
        while w.p:
            lm = w.lm()
            w.unit_cancelled(lm)
            g = _choose(pool, lm, MAX_DEGREE)  # the first divisor (the pool is sorted by sugar)
            if g is None:
                break
            if budget is not None:
                budget.charge(w.coeff(lm))
            w.reduce(lm, g)
        return w.terms(), sugar

    for g in gens:
        if not g.is_zero():
            d = g.total_degree()
            push(d, g.lm(), (front(dict(g.terms)), d))
    while queue or waiting:
        done = run_compiled(None, 0) if waiting else None
        if done is None:
            if not queue:
                continue  # (its dead pairs dropped, the postponed polynomials reduced to zero)
            sugar, _, _, item, _ = heapq.heappop(queue)
            if isinstance(item, _Pair):
                if not item.alive:
                    continue
                item.alive = False  # dropped from ``pairs`` at the next update
                if corner.cut is not None and sum(item.lcm) > corner.cut:
                    continue  # every term of the S-polynomial is above the cut
                if compiled is not None:
                    w = compiled.spoly(basis[item.i].b, basis[item.j].b, corner.cut)
                    if w is None:
                        raise BudgetExceeded
                else:
                    w = front(_spoly(basis[item.i], basis[item.j], item.lcm))
            else:
                w, sugar = item
            done = reduce(w, sugar)
            if done is None or not done[0]:
                continue
        h, sugar = done
        if compiled is not None:
            elem = compiled.element(h, sugar)
            if elem is None:
                return [{ring.zero_exp: ring.field.one}], corner
            compiled.insert(elem.b, elem.ecart)
        else:
            h = monic(cancel_unit(h, key), key)
            lm = max(h, key=key)
            if lm == ring.zero_exp:
                return [{ring.zero_exp: ring.field.one}], corner
            h = {lm: h[lm], **h}  # the leading monomial first, as the basis is returned
            elem = Elem(h, key, min(sugar - sum(lm), max(sum(e) for e in h) - sum(lm)), lm)
            _insert(pool, elem)
        update(elem)
        if corner.update(elem.lm, lambda: [b.lm for b, a in zip(basis, active) if a]):
            if budget is not None:
                budget.corner_found()
            if compiled is not None:
                compiled.cut_tails(basis, corner.cut)
            for g in pool:
                g.truncate(corner.cut)
    return [b.p for b, a in zip(basis, active) if a], corner  # each with its leading monomial first


def _spoly(f: Elem, g: Elem, lc: Exp) -> Terms:
    sf = tuple([a - b for a, b in zip(lc, f.lm)])
    sg = tuple([a - b for a, b in zip(lc, g.lm)])
    cf, cg = f.p[f.lm], g.p[g.lm]
    out: Terms = {}
    for e, c in f.p.items():
        out[tuple([a + b for a, b in zip(e, sf)])] = c * cg
    for e, c in g.p.items():
        te = tuple([a + b for a, b in zip(e, sg)])
        v = out.get(te)
        v = -c * cf if v is None else v - c * cf
        if v == 0:
            out.pop(te, None)
        else:
            out[te] = v
    return out


def elems(basis: Sequence[Poly]) -> list[Elem]:
    """Reducers for :func:`mora_normal_form` from polynomials."""
    return [Elem(dict(b.terms), b.ring.order.key) for b in basis if not b.is_zero()]



def finished(basis: list[Terms], ring: PolyRing, minimal: bool = False) -> list[Poly]:
    """A standard basis as :func:`.engines.standard_basis` returns it for a non-global ordering,
    from dicts that each hold their leading monomial first (as :func:`mora` and
    :func:`.lazard.lazard` give them): minimal (an element whose leading monomial another's
    divides is dropped; of equal ones the first is kept), monic, sorted from the largest leading
    monomial down.  ``minimal``: the basis is minimal already (:func:`mora`'s and
    :func:`.lazard.lazard`'s are), and is not checked."""
    one = ring.field.one
    items = [(next(iter(b)), b) for b in basis if b]
    if not minimal:
        items = _minimal(items)
    rank = _leading_rank(ring)
    items.sort(key=lambda t: rank(t[0]))
    out = []
    for m, b in items:
        c = b[m]
        if c != one:
            inv = 1 / c
            b = {e: v * inv for e, v in b.items()}
        p = Poly(ring, b)
        p._lm = m
        out.append(p)
    return out


def _minimal(items: list[tuple[Exp, Terms]]) -> list[tuple[Exp, Terms]]:
    """The items whose leading monomial no other's divides (of equal ones the first)."""
    items = sorted(items, key=lambda t: sum(t[0]))  # a divisor comes first (stable: equal ones in order)
    kept: list[tuple[Exp, int]] = []
    out = []
    for m, b in items:
        mask = support_mask(m)
        if any(not kmask & ~mask and divides(lm, m) for lm, kmask in kept):
            continue
        kept.append((m, mask))
        out.append((m, b))
    return out
