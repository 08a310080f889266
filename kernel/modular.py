"""Gröbner bases over QQ by F4 modulo primes (Arnold, JSC 35, 2003; Traverso's Gröbner trace).

1. The generators are scaled to primitive integer polynomials ``F``.
2. One prime ``p0`` runs the full F4 (:class:`.f4.F4`) and records its trace; further primes
   only replay the recorded linear algebra (:func:`.f4.replay`).  A prime that does not follow
   the trace is dropped; when too many do, ``p0`` was unlucky and a new prime learns.  Primes
   dividing a leading coefficient of ``F`` are skipped.
3. The residues of the coefficients of the reduced basis are combined by the Chinese remainder
   theorem and lifted to rationals by rational reconstruction (:class:`Reconstructor`), tried
   from the first prime on (small coefficients need no second one); every lifted coefficient
   is checked against the later primes, and a complete lift is accepted once the next prime
   agrees with all of it.  While a complete lift is at hand, that prime replays the run in
   full (step 4) when this is cheap or the lift likely right: if it agrees, it is the fresh
   prime ``q`` of step 4's check modulo ``q``, made on the way (it is drawn after every prime
   the lift used, so independently of ``G``).
4. The lift ``G`` is verified (:func:`verify_basis`):

   * exactly over QQ: every generator top-reduces to 0 by ``G``, so ``I = <F>`` lies in
     ``J = <G>``;
   * the Gröbner basis property: with ``verify="exact"``, every S-pair left by the
     Gebauer–Möller criteria top-reduces to 0 over QQ, so ``G`` is the reduced Gröbner basis
     of ``J``.  By default (``"fast"``) this is checked modulo one fresh prime ``q`` instead:
     ``G mod q`` is a Gröbner basis.  If ``G`` were not one over QQ, some S-pair would have a
     nonzero remainder whose numerators ``q`` divides; ``q`` is drawn independently of ``G``
     from about 7 million primes, so this has probability below ``b / 27 / 7e6`` for
     remainders of ``b`` bits in all.  The check modulo ``q`` is first made by replaying the
     recorded run in full (every row of every matrix, also those that reduced to zero,
     :func:`.f4_trace.replay_full`): if ``q`` keeps every matrix's rank profile, the replay
     is an F4 run modulo ``q``, so ``G mod q`` equal to its result is the reduced Gröbner
     basis of ``I mod q``, a Gröbner basis (the same remainders vanish mod ``q``: the
     argument above applies unchanged).  A ``q`` that leaves the trace, or a run too large
     to keep every row, gets the direct check (one F4 matrix of all S-pairs of ``G``).

   ``J = I`` then holds when ``I`` is homogeneous: with ``p`` any prime used, the rank of a
   matrix over ``Z`` only drops mod ``p``, so ``dim I_d >= dim (I mod p)_d = #LM(G)_d =
   dim J_d >= dim I_d`` in every degree.  For other ideals it holds as soon as one prime used
   is lucky, ``LT(I mod p) = LT(I)``: then ``LT(J) = <LM(G)> = LT(I)`` with ``I ⊆ J``.  Only
   finitely many primes are unlucky, and the primes are drawn from ``(2^27, 2^28)`` by a fixed
   pseudo-random sequence (so runs are reproducible).
   A Hilbert-driven run (``counter``: homogeneous generators, the ideal's Hilbert series known
   over QQ) stops once its leading monomials have that series; the same checks hold: a replay
   at ``q`` yields elements of ``I mod q`` whose leading monomials already have the series of
   ``I``, at most that of ``LT(I mod q)``, so they form its Gröbner basis.
   If a check fails, the computation starts again from a new prime; after three failures
   :class:`ModularFailure` is raised (the ``auto`` policy of :mod:`.engines` then runs Buchberger).
"""
from __future__ import annotations

import random
from math import gcd, isqrt, lcm
from operator import le, sub
from typing import Any, Callable, Sequence

import flint

from .errors import NotSupported
from .f4 import F4, PackingOverflow, initial_degree, is_groebner
from .f4_rows import compiled
from .f4_trace import Trace, TraceMismatch, replay, replay_full
from .monomials import Packing, nonnegative_matrix, packing
from .poly import support_mask

try:
    from ._f4rows import agree_rows as AGREE_ROWS, fractions as FRACTIONS, ratrec_rows as RATREC_ROWS
except ImportError:  # no compiler at install (or an older extension): the same loops in Python
    AGREE_ROWS = FRACTIONS = RATREC_ROWS = None

_SMALL_FRACTIONS: dict[tuple[int, int], Any] = {}
"""Fractions n/d with |n|, d below 2^15 as python-flint fractions by (n, d), made once (immutable,
shared by the lifts: most coefficients of small systems' bases are such fractions; kernel/_f4lift.c
keeps at most 65536)."""

PRIME_RANGE = (1 << 27, 1 << 28)
FULL_REPLAY_COST = 3.0
"""A lift not yet likely right is confirmed by a full replay (the check modulo a fresh prime on
the way) when that reduces at most this many times the entries of a replay (else by a replay,
the check then by another prime)."""


class ModularFailure(NotSupported):
    """The modular method could not produce a verified basis (use another engine)."""


class SmallSystem(Exception):
    """The first modular run was smaller than the caller's threshold (use another engine)."""


def primes(seed: int = 20031, bounds: tuple[int, int] = PRIME_RANGE):
    """An endless pseudo-random sequence of distinct primes in ``bounds``, the same for a seed (the
    primes found are kept: every computation over QQ starts with the same ones)."""
    got, more = _SEQUENCES.setdefault((seed, bounds), ([], _prime_sequence(seed, bounds)))
    i = 0
    while True:
        if i == len(got):
            got.append(next(more))
        yield got[i]
        i += 1


_SEQUENCES: dict[tuple[int, tuple[int, int]], tuple[list[int], Any]] = {}


def _prime_sequence(seed: int, bounds: tuple[int, int]):
    rng = random.Random(seed)
    seen = set()
    while True:
        q = _next_prime(rng.randrange(*bounds))
        if q < bounds[1] and q not in seen:
            seen.add(q)
            yield q


def _next_prime(n: int) -> int:
    n |= 1
    while not flint.fmpz(n).is_prime():
        n += 2
    return n


def primitive(terms: dict) -> dict:
    """The primitive integer multiple (positive content) of a polynomial over QQ."""
    cs = terms.values()
    den = lcm(*[int(c.q) for c in cs])
    nums = [int(c.p) for c in cs] if den == 1 else [int(c.p) * (den // int(c.q)) for c in cs]
    cont = gcd(*nums)
    if cont != 1:
        nums = [v // cont for v in nums]
    return dict(zip(terms, nums))


def ratrec(a: int, m: int, bound: int) -> tuple[int, int] | None:
    """``n/d`` with ``n = a d mod m``, ``|n| <= bound``, ``0 < d <= bound`` (Wang), or None."""
    r0, r1, s0, s1 = m, a % m, 0, 1
    while r1 > bound:
        q = r0 // r1
        r0, r1 = r1, r0 - q * r1
        s0, s1 = s1, s0 - q * s1
    if s1 == 0 or abs(s1) > bound or gcd(r1, abs(s1)) != 1:
        return None
    return (r1, s1) if s1 > 0 else (-r1, -s1)


COMPILED_MODULUS = 1 << 62
"""Moduli (and primes) below which the reconstruction and its check run in C (kernel/_f4lift.c)."""


class Reconstructor:
    """Rational reconstruction of coefficient lists, resumed where the last attempt failed:
    coefficients lifted from fewer primes are kept (the final check against a further prime
    covers them).  A running common denominator ``den`` makes most coefficients one
    multiplication: ``a den mod m`` is already the small numerator."""

    def __init__(self, sizes: list[int]) -> None:
        self.out: list[list[tuple[int, int]]] = [[(0, 1)] * k for k in sizes]
        self.reset()

    def reset(self) -> None:
        self.i = self.j = 0
        self.den = 1
        self.lift: list[list[Any]] = []  # the last complete lift, from a modulus of ``bits`` bits
        self.bits = 0
        self.height: int | None = None  # the lift's height in bits, when the compiled lift gave it

    def check(self, residues: list[list[int]], p: int) -> bool:
        """Rewind to the first lifted coefficient that disagrees with the residues mod p;
        whether one did."""
        out = self.out
        if AGREE_ROWS is not None and p < COMPILED_MODULUS:
            try:
                first = AGREE_ROWS(out, residues, p, self.i, self.j)
            except OverflowError:  # an entry beyond 64 bits: the loop below
                pass
            else:
                if first is None:
                    return False
                self.i, self.j, self.den = *first, 1
                return True
        for i in range(min(self.i + 1, len(out))):
            row, rs = out[i], residues[i]
            for j in range(self.j if i == self.i else len(row)):
                n, d = row[j]
                if (n - rs[j] * d) % p or d % p == 0:
                    self.i, self.j, self.den = i, j, 1
                    return True
        return False

    def attempt(self, values: list[list[int]], m: int) -> list[list[Any]] | None:
        if RATREC_ROWS is not None and m < COMPILED_MODULUS:  # the same loop in C
            self.i, self.j, self.den, height = RATREC_ROWS(values, self.out, m, self.i, self.j, self.den)
            return self._complete(m, height) if height >= 0 else None
        bound = isqrt(m // 2)
        half = m // 2
        i, j, den, out = self.i, self.j, self.den, self.out
        while i < len(values):
            cs, row = values[i], out[i]
            for j in range(j, len(cs)):
                a = cs[j]
                b = a * den % m
                if b > half:
                    b -= m
                if -bound <= b <= bound and den <= bound:
                    row[j] = (b, den)
                else:
                    r = ratrec(a, m, bound)
                    if r is None:
                        self.i, self.j, self.den = i, j, den
                        return None
                    row[j] = r
                    den = den * r[1] // gcd(den, r[1])
                    if den > bound:
                        den = r[1]
            i, j = i + 1, 0
        self.i, self.j, self.den = i, j, den
        return self._complete(m)

    def _complete(self, m: int, height: int | None = None) -> list[list[Any]]:
        """The complete lift as rationals, from a modulus ``m`` (``height``: its height in bits,
        if known)."""
        if FRACTIONS is not None:
            self.lift = FRACTIONS(self.out, flint.fmpq, _SMALL_FRACTIONS)
        else:
            fmpq = flint.fmpq  # fmpq(n) is made faster than fmpq(n, 1)
            self.lift = [[fmpq(n) if d == 1 else fmpq(n, d) for n, d in row] for row in self.out]
        self.bits = m.bit_length()
        self.height = height
        return self.lift

    def confident(self) -> bool:
        """Whether the last complete lift's coefficients lie far below the bound, where a wrong
        lift is unlikely: a residue mod m is n/d with |n|, d < 2^h for fewer than 2^(2h+1)
        residues, here at most m/32 (and a wrong lift of many coefficients is far rarer)."""
        height = self.height
        if height is None:
            height = max([c.height_bits() for row in self.lift for c in row], default=0)
        return 2 * height + 6 < self.bits


class Lifter:
    """Chinese remaindering of coefficient lists, prime by prime."""

    def __init__(self) -> None:
        self.m = 1
        self.values: list[list[int]] | None = None

    def add(self, residues: list[list[int]], p: int) -> None:
        if self.values is None:
            self.values, self.m = [list(cs) for cs in residues], p
            return
        m = self.m
        inv = pow(m, -1, p)
        self.values = [[x + m * ((r - x) * inv % p) for x, r in zip(xs, rs)]
                       for xs, rs in zip(self.values, residues)]
        self.m = m * p


def f4_qq(gens: Sequence, ring, verify: str = "fast", max_primes: int = 2000,
          small_work: int = 0, counter: Callable | None = None) -> list[dict]:
    """The reduced Gröbner basis over QQ by modular F4, as ``{exponent: fmpq}`` dicts
    (see the module docstring; ``verify`` is ``"fast"``, ``"exact"`` or ``"none"``).
    Raises :class:`SmallSystem` if the first run handles fewer than ``small_work`` matrix
    entries.  ``counter``: for homogeneous generators, makes a
    :class:`.hilbert_driven.Counter` of the ideal's Hilbert series (Hilbert-driven F4)."""
    ints = [primitive(g.terms) for g in gens]
    maxdeg = initial_degree(gens)
    stream = primes()
    for attempt in range(3):
        while True:
            P = packing(ring.order, maxdeg)
            shapes, coefs = _pack(ints, P)
            try:
                result = _modular(shapes, coefs, P, stream, max_primes, small_work, counter)
                break
            except PackingOverflow:
                maxdeg = 2 * maxdeg + 1
        if result is None:
            continue
        shape, G, trace, certified = result
        basis = P.term_dicts(list(zip(shape, G)))
        replayed = (lambda q: True) if certified else (lambda q: _replayed_basis_agrees(trace, coefs, G, q))
        packed = (P.guard, list(zip(shapes, coefs)), list(zip(shape, G)))
        if verify == "none" or verify_basis(basis, ints, ring, stream, verify == "exact", replayed, packed):
            return basis
    raise ModularFailure("modular F4: no verified basis after 3 attempts (use another engine)")


def _pack(ints: list[dict], P: Packing):
    shapes, coefs = [], []
    for t in ints:
        items = sorted(zip(P.pack_all(t.keys()), t.values()), reverse=True)
        shapes.append([m for m, _ in items])
        coefs.append([c for _, c in items])
    return shapes, coefs


def _modular(shapes, coefs, P: Packing, stream, max_primes: int, small_work: int = 0,
             counter: Callable | None = None):
    """``(monomials, rational coefficients, trace, certified)`` of the lifted basis, or None to
    start again.  A lift is tried from the first prime on (small coefficients need no more)
    and accepted once a further prime agrees with all of it.  While a lift is at hand, that
    prime replays the trace in full (:func:`.f4_trace.replay_full`) if this costs at most
    :data:`FULL_REPLAY_COST` replays or the lift's coefficients lie far below the
    reconstruction's bound (a likely right lift), and ``certified`` says
    that it did: the lift modulo that prime is then the reduced Gröbner basis of the ideal
    modulo it, the check of :func:`verify_basis` modulo a fresh prime, made on the way."""
    used = 0
    while used < max_primes:
        p0 = next(stream)
        used += 1
        if any(cs[0] % p0 == 0 for cs in coefs):
            continue
        rows = [(ms, [c % p0 for c in cs]) for ms, cs in zip(shapes, coefs)]
        engine = F4(rows, P, p0, record=True, counter=None if counter is None else counter())
        basis = engine.run()
        if engine.work < small_work:
            raise SmallSystem
        small_work = 0
        trace = engine.trace
        shape = trace.shape
        lifter = Lifter()
        lifter.add([cs for _, cs in basis], p0)
        rec = Reconstructor([len(cs) for _, cs in basis])
        candidate = rec.attempt(lifter.values, lifter.m)
        cheap_full = None  # whether a full replay costs little (worked out when needed)
        misses = good = 0
        while used < max_primes:
            p = next(stream)
            used += 1
            if any(cs[0] % p == 0 for cs in coefs):
                continue
            try:
                want_full = candidate is not None and rec.confident()
                if candidate is not None and not want_full:
                    if cheap_full is None:
                        cheap_full = trace.full_cost() <= FULL_REPLAY_COST
                    want_full = cheap_full
                res, full = _replay(trace, [[c % p for c in cs] for cs in coefs], p, want_full)
            except TraceMismatch:
                misses += 1
                if misses > good + 2:
                    break  # p0 was unlucky: learn again
                continue
            good += 1
            if not rec.check(res, p) and candidate is not None:
                return shape, candidate, trace, full
            lifter.add(res, p)
            candidate = rec.attempt(lifter.values, lifter.m)
    return None


def _replay(trace: Trace, polys: list[list[int]], p: int, full: bool) -> tuple[list[list[int]], bool]:
    """The basis modulo ``p`` by the trace, and whether by a full replay (tried when ``full``;
    a prime that keeps the rows the run used but not the rank of every matrix still serves
    the lift)."""
    if full and trace.full and compiled(p):
        try:
            return replay_full(trace, polys, p), True
        except TraceMismatch:
            pass
    return replay(trace, polys, p), False


def verify_basis(basis: list[dict], ints: list[dict], ring, stream, exact: bool = False,
                 replayed: Callable[[int], bool | None] | None = None, packed: tuple | None = None) -> bool:
    """Check a lifted reduced basis (see the module docstring).

    ``basis``: dicts with the leading exponent first (as :func:`f4_qq` builds them).
    Always exact: every generator top-reduces to 0 over QQ.  The Gröbner basis property is
    checked exactly over QQ (``exact``), or else modulo one fresh prime ``q``: by
    ``replayed(q)`` when given (True: ``G mod q`` is the reduced basis of the ideal mod
    ``q``; None: ``q`` cannot tell), else (or on None) by one F4 matrix of all S-pairs left
    by the Gebauer–Möller criteria.  ``packed``: ``(guard, generators, elements)``, the
    generators ``ints`` and the basis as (packed monomials decreasing, coefficients) of one
    packing with these guard bits; the generators are then top-reduced on packed monomials
    (:func:`_top_reduces_packed`)."""
    if len(basis) == 1 and len(basis[0]) == 1 and not any(next(iter(basis[0]))):
        return True  # the unit ideal: nothing to check beyond the lift
    red = None
    if exact:
        red = ExactReducer(basis, ring.order, [next(iter(b)) for b in basis])
        if not red.is_groebner():
            return False
    else:
        checked = 0
        while checked < 1:
            q = next(stream)
            agrees = replayed(q) if replayed is not None else None
            if agrees is not None:
                if not agrees:
                    return False
                checked += 1
                continue
            rows = _reduce_mod(basis, ring.order, q)
            if rows is None:
                continue
            if not _is_groebner_mod(rows, ring.order, q):
                return False
            checked += 1
    leads = None if packed is None else [ms[0] for ms, _ in packed[2]]
    for k, f in enumerate(ints):
        reduced = None if packed is None else _top_reduces_packed(packed[1][k], packed[2], leads, packed[0])
        if reduced is None:  # not packed, or a product left the packing: in flint
            red = red or ExactReducer(basis, ring.order, [next(iter(b)) for b in basis])
            reduced = red.reduces_to_zero(f)
        if not reduced:
            return False
    return True


def _top_reduces_packed(f: tuple[list, list], elements: list[tuple[list, list]], leads: list[int],
                        guard: int) -> bool | None:
    """Whether ``f`` top-reduces to 0 over QQ by the ``elements`` (all as packed monomials,
    decreasing, and their rational or integer coefficients; ``leads``: their leading
    monomials), exactly; None once a product
    ``x^u * m`` sets a guard bit (a field past its width: packed arithmetic would no longer be
    exact; the caller then reduces in flint).  Packed monomials compare as the ordering does,
    and ``a`` divides ``b`` iff ``(b | guard) - a`` keeps every guard bit."""
    terms = dict(zip(*f))
    while terms:
        m = max(terms)
        mg = m | guard
        for k, lm in enumerate(leads):
            if (mg - lm) & guard == guard:
                break
        else:
            return False
        ms, cs = elements[k]
        c = terms.pop(m)
        if cs[0] != 1:
            c = c / cs[0]
        u = m - lm
        get = terms.get
        for x, a in zip(ms[1:], cs[1:]):
            y = u + x
            if y & guard:
                return None
            v = get(y, 0) - c * a
            if v:
                terms[y] = v
            else:
                terms.pop(y, None)
    return True


def _replayed_basis_agrees(trace: Trace, coefs: list[list[int]], G: list[list[Any]], q: int) -> bool | None:
    """Whether the lifted basis ``G`` (rational coefficients in the trace's shape) is, modulo
    ``q``, the reduced Gröbner basis of the ideal modulo ``q``, by a full replay of the trace
    (:func:`.f4_trace.replay_full`); None if ``q`` cannot tell (it divides a leading
    coefficient or a denominator, or does not follow the trace)."""
    if any(cs[0] % q == 0 for cs in coefs):
        return None
    mod = []
    for cs in G:
        row = []
        for c in cs:
            d = int(c.q) % q
            if d == 0:
                return None
            row.append(int(c.p) * pow(d, -1, q) % q)
        mod.append(row)
    try:
        return replay_full(trace, [[c % q for c in cs] for cs in coefs], q) == mod
    except TraceMismatch:
        return None


def _reduce_mod(basis: list[dict], order, q: int):
    """The basis mod q as (exponents, coefficients) pairs, or None if q divides a denominator."""
    out = []
    for b in basis:
        items = []
        for e, c in b.items():
            d = int(c.q) % q
            if d == 0:
                return None
            items.append((e, int(c.p) * pow(d, -1, q) % q))
        out.append(items)
    return out


def _is_groebner_mod(polys, order, q: int) -> bool:
    maxdeg = 15
    top = max(sum(e) for items in polys for e, _ in items)
    while maxdeg < 2 * top:
        maxdeg = 2 * maxdeg + 1
    while True:
        P = packing(order, maxdeg)
        rows = []
        for items in polys:
            packed = sorted(((P.pack(e), c) for e, c in items), reverse=True)
            rows.append(([m for m, _ in packed], [c for _, c in packed]))
        try:
            return is_groebner(rows, P, q)
        except PackingOverflow:
            maxdeg = 2 * maxdeg + 1


class ExactReducer:
    """Top-reduction over QQ by a reduced basis, with python-flint's ``fmpq_mpoly``.

    Orderings flint has (``lp``, ``Dp``, ``dp`` as one block) are flint's own (``lex``,
    ``deglex``, ``degrevlex``: the same comparisons, variables in the ring's order).  Any
    other ``x^e`` is mapped to ``y^(W e, e)`` in ``QQ[y_1..y_2n]`` with the lexicographic
    ordering: a ring embedding that maps leading terms to leading terms (``W`` is the
    ordering's nonnegative matrix), so flint does the arithmetic and finds leading terms."""

    def __init__(self, basis: list[dict], order, leads: list[tuple] | None = None) -> None:
        n = self.n = order.nvars
        blocks = order.blocks
        native = _FLINT_ORDERINGS.get(blocks[0].kind) if len(blocks) == 1 and blocks[0].size == n else None
        if native is not None:
            self.W = None
            self.lead = 0  # the leading exponent starts at this position of flint's exponent
            self.ctx = flint.fmpq_mpoly_ctx.get(("x", n), native)
            if leads is not None:  # the elements (leading exponents known) go to flint when first needed
                self.basis, self.lms = basis, list(leads)
                self.polys = [None] * len(basis)
                self.masks = [support_mask(e) for e in self.lms]
                return
            self.polys = [self.ctx.from_dict(b) for b in basis]
        else:
            self.lead = n
            self.W = W = nonnegative_matrix(order)
            self.ctx = flint.fmpq_mpoly_ctx.get(("y", 2 * n), "lex")
            self.xctx = flint.fmpq_mpoly_ctx.get(("x", n), "lex")
            ys = self.ctx.gens()
            self.images = []
            for j in range(n):
                m = ys[n + j]
                for i in range(n):
                    if W[i][j]:
                        m = m * ys[i] ** W[i][j]
                self.images.append(m)
            self.polys = [self.image(b) for b in basis]
        self.lms = [p.monomial(0)[self.lead:] for p in self.polys]
        self.masks = [support_mask(e) for e in self.lms]

    def _poly(self, k: int):
        """Basis element ``k`` in flint."""
        if self.polys[k] is None:
            self.polys[k] = self.ctx.from_dict(self.basis[k])
        return self.polys[k]

    def image(self, terms: dict):
        """The image of a polynomial (substitution of monomials, done by flint)."""
        if self.W is None:
            return self.ctx.from_dict(terms)
        return self.xctx.from_dict(terms).compose(*self.images, ctx=self.ctx)

    def _term(self, u, c):
        W = self.W
        if W is None:
            return self.ctx.from_dict({u: c})
        return self.ctx.from_dict({tuple([sum(w * x for w, x in zip(r, u)) for r in W]) + tuple(u): c})

    def reduces_to_zero(self, terms: dict) -> bool:
        f = self.image({e: flint.fmpq(c) for e, c in terms.items()})
        return self._top_reduce(f)

    def _top_reduce(self, f) -> bool:
        n, lms, masks = self.lead, self.lms, self.masks
        while not f.is_zero():
            e = f.monomial(0)[n:]
            m = support_mask(e)
            for k, lm in enumerate(lms):
                if masks[k] & ~m == 0 and all(map(le, lm, e)):
                    break
            else:
                return False
            u = tuple(map(sub, e, lm))
            f = f - self._term(u, f.leading_coefficient()) * self._poly(k)
        return True

    def is_groebner(self) -> bool:
        """Every S-pair left by the Gebauer–Möller criteria top-reduces to 0 over QQ."""
        self.polys = [self._poly(k) for k in range(len(self.polys))]
        for i, j, L in _pairs(self.lms):
            ui = tuple([a - b for a, b in zip(L, self.lms[i])])
            uj = tuple([a - b for a, b in zip(L, self.lms[j])])
            one = flint.fmpq(1)
            s = self._term(ui, one) * self.polys[i] - self._term(uj, one) * self.polys[j]
            if not self._top_reduce(s):
                return False
        return True


_FLINT_ORDERINGS = {"lp": "lex", "Dp": "deglex", "dp": "degrevlex"}
"""Singular's orderings flint has (on one block of all variables)."""


def _pairs(lms: list) -> list[tuple[int, int, tuple]]:
    """The pairs of a basis with these leading exponents left by the Gebauer–Möller
    criteria (adding the elements one by one)."""
    def lcm(a, b):
        return tuple([x if x > y else y for x, y in zip(a, b)])

    def divides(a, b):
        return all(x <= y for x, y in zip(a, b))

    pairs: list[tuple[int, int, tuple]] = []
    for h, H in enumerate(lms):
        cands = []
        for i in range(h):
            L = lcm(lms[i], H)
            cands.append((i, L, L == tuple(x + y for x, y in zip(lms[i], H))))
        kept: dict[tuple, tuple] = {}
        for c in cands:
            if any(d[1] != c[1] and divides(d[1], c[1]) for d in cands):
                continue
            prev = kept.get(c[1])
            if prev is None or (c[2] and not prev[2]):
                kept[c[1]] = c
        pairs = [(i, j, L) for i, j, L in pairs
                 if not (divides(H, L) and lcm(lms[i], H) != L and lcm(lms[j], H) != L)]
        pairs += [(i, h, L) for i, L, coprime in kept.values() if not coprime]
    return pairs
