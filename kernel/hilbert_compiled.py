"""The Hilbert-driven Buchberger algorithm (:mod:`.hilbert_driven`) modulo ``p < 2^50`` in
compiled code (the optional C extension ``_bba``, kernel/_bba.c), and over QQ by a modular lift.

Modulo ``p`` the homogenized generators, the basis and the pairs live in C as packed monomials
(:class:`~.monomials.Packing`); Python keeps the Hilbert series (:class:`.hilbert_driven.Counter`)
and asks C, degree by degree, to reduce S-polynomials until the degree has its new leading
monomials.  C then dehomogenizes the basis and reduces it.  Without a series (:func:`buchberger_modp`,
:func:`buchberger_qq`) the same code is Buchberger's algorithm with the sugar strategy: the ``dp``
bases of the homogenized generators that give the series, and ``auto``'s budgeted attempt.

Every run modulo ``p`` gives a Gröbner basis of the ideal modulo ``p`` whatever ``p``: with
``h`` the Hilbert function of the quotient by ``J`` (the homogenized ideal over QQ), that of
``J mod p`` is at least ``h`` in every degree (ranks only drop modulo ``p``), so a degree that
found the new leading monomials the series asks for is complete, and one whose pairs ran out
is complete as in Buchberger's algorithm.

Over QQ (:func:`hilbert_qq`) the reduced bases at several primes of the same shape (monomials)
are combined by the Chinese remainder theorem and lifted by rational reconstruction (:class:`Lift`:
in C up to two primes, then :class:`.modular.Reconstructor`) until the next prime's basis agrees
with the lift ``G``; a
prime whose basis has another shape is dropped, and when more primes disagree than agree the
first one was unlucky and the lift starts again from a later prime.  ``G mod q`` is then the
reduced Gröbner basis of the ideal modulo a prime ``q`` not used to build ``G``, the
probabilistic Gröbner basis check of :mod:`.modular` ("fast"); every generator is checked to
top-reduce to 0 by ``G`` exactly over QQ (in C on 128-bit integers while they suffice,
``_bba.in_ideal``), so ``G`` generates an ideal containing the ideal, and equal to it as soon as
one prime used is lucky (as for :func:`.modular.f4_qq` on inhomogeneous ideals).  The primes lie
below ``2^50`` (products in C by a double-precision quotient), so two of them lift coefficients
of 49 bits.
"""
from __future__ import annotations

import heapq
from array import array
from functools import lru_cache
from math import gcd
from types import SimpleNamespace
from typing import Any, Sequence

import flint

from .buchberger import Overflow, subtract_shifted
from .coeffs import PrimeField, RationalField
from .hilbert_driven import Basis, Counter, _homogenized
from .modular import Lifter, ModularFailure, Reconstructor, primes, primitive
from .monomials import Packing, packing
from .order import Exp, MonomialOrder
from .poly import Poly, PolyRing

try:
    from ._bba import exponents, in_ideal, layout, min_degree, ratlift, reduced, state, step
    _bba: SimpleNamespace | None = SimpleNamespace(exponents=exponents, in_ideal=in_ideal, layout=layout,
                                                   min_degree=min_degree, ratlift=ratlift, reduced=reduced,
                                                   state=state, step=step)
except ImportError:  # pragma: no cover - no compiler at install time
    _bba = None

PRIMES = (1 << 49, 1 << 50)
"""The primes of the lift (the compiled arithmetic takes ``p < 2^50``: two primes lift coefficients
of 49 bits, where four of 31 bits took 61)."""

MAX_CHARACTERISTIC = 1 << 31
"""Rings over Z/p with ``p`` below this use the compiled algorithm (as the other engines)."""

C_LIFT_BITS = 124
"""The lift's rational reconstruction runs in C (128-bit integers) while the product of the primes
has at most this many bits."""

MAX_PRIMES = 60
"""The lift gives up (:class:`~.modular.ModularFailure`) after this many primes."""


def usable(ring: PolyRing) -> bool:
    """Whether the compiled algorithm applies: the extension is built and the field is QQ or
    Z/p with ``p < 2^31``."""
    f = ring.field
    return _bba is not None and (isinstance(f, RationalField)
                                 or isinstance(f, PrimeField) and f.characteristic < MAX_CHARACTERISTIC)


@lru_cache(maxsize=64)
def _layout(pk: Packing):
    nw = (pk.bits + 64) // 64
    width = 8 * nw
    return _bba.layout(nw, pk.guard.to_bytes(width, "little"), b"".join(u.to_bytes(width, "little") for u in pk.units),
                       tuple(pk.eshifts), pk.dshift, pk.ebits)


def _encode(pk: Packing, terms: dict[Exp, int], p: int = 0) -> tuple[bytes, bytes]:
    """The integer terms as (monomials, coefficients) bytes, leading first: the coefficients mod
    ``p`` (uint64), or for ``p = 0`` as they are (int64: OverflowError past 63 bits).  Exponents
    may come as flint integers: the packed monomial is made a Python int."""
    width = 8 * ((pk.bits + 64) // 64)
    items = sorted(((int(pk.pack(e)), c % p if p else c) for e, c in terms.items()), reverse=True)
    items = [(m, c) for m, c in items if c]
    coefs = array("Q" if p else "q", [c for _, c in items])
    return b"".join(m.to_bytes(width, "little") for m, _ in items), coefs.tobytes()


class _Series:
    """The Hilbert series of the leading monomials found (:class:`.hilbert_driven.Counter`),
    kept across the primes of one lift: primes of the same shape find the same leading monomials
    in the same order, so each numerator is computed once.  A state is a node of the tree of
    sequences of leading monomials met so far (0: none).

    The pairs that reduced to zero in a degree at the first prime through a node are reduced last
    at the next ones (:meth:`deferred`): a degree is complete once it has the new leading
    monomials the series asks for, whichever pairs gave them (module docstring), so the order of
    the pairs changes the work, not the result's correctness; at primes of the same shape the
    pairs that gave new elements come in the same order with the same basis before each, so the
    basis is the same as without deferring."""

    def __init__(self, target: list[int], nvars: int) -> None:
        self.counters = [Counter(target, nvars)]
        self.children: list[dict[Exp, int]] = [{}]
        self.zeros: dict[tuple[int, int], bytes] = {}

    def add(self, node: int, m: Exp) -> int:
        """The node after ``m`` joined the leading monomials of ``node``."""
        child = self.children[node].get(m)
        if child is None:
            before = self.counters[node]
            c = Counter(before.target, before.n)
            c.q, c.gens = before.q, list(before.gens)
            c.add(m)
            child = self.children[node][m] = len(self.counters)
            self.counters.append(c)
            self.children.append({})
        return child

    def missing(self, node: int, d: int) -> tuple[int, bool]:
        return self.counters[node].missing(d)

    def deferred(self, node: int, d: int) -> bytes:
        """A byte per pair of degree ``d`` at ``node`` (sorted as in C), set for those to reduce
        last; empty: none known."""
        return self.zeros.get((node, d), b"")

    def reduced_to_zero(self, node: int, d: int, zeros: bytes) -> None:
        self.zeros.setdefault((node, d), zeros)


class _AllPairs:
    """No Hilbert series: every pair is reduced (Buchberger's algorithm, normal strategy)."""

    def missing(self, node: int, d: int) -> tuple[int, bool]:
        return 1 << 62, False

    def add(self, node: int, m: Exp) -> int:
        return 0

    def deferred(self, node: int, d: int) -> bytes:
        return b""

    def reduced_to_zero(self, node: int, d: int, zeros: bytes) -> None:
        pass


def _reduced_modp(hpolys: Sequence[dict[Exp, int]], hring: PolyRing, ring: PolyRing, series: _Series | _AllPairs,
                  p: int, limit: int = 0):
    """The reduced basis modulo ``p`` of the ideal of the homogenized generators ``hpolys``
    (integer coefficients, none of whose leading coefficients ``p`` divides), dehomogenized when
    ``hring`` is not ``ring``: (``ring``'s packing, list of (monomials, coefficients) bytes) by
    increasing leading monomial.  :class:`~.buchberger.TooLong` once the reductions
    have summed more than ``limit`` terms (if not 0)."""
    maxdeg = max(64, 2 * max(sum(e) for t in hpolys for e in t))
    while True:
        hpk, pk = packing(hring.order, maxdeg), packing(ring.order, maxdeg)
        if max(hpk.bits, pk.bits) >= 8 * 64:
            raise ModularFailure("monomials too wide for the compiled Buchberger")
        try:
            st = _bba.state(_layout(hpk), p, [_encode(hpk, t, p) for t in hpolys], limit)
            path = 0
            unpack = hpk.unpack
            while True:
                d = _bba.min_degree(st)
                if d < 0:
                    break
                need, done = series.missing(path, d)
                if done:
                    break
                lms, zeros = _bba.step(st, d, need, series.deferred(path, d))
                series.reduced_to_zero(path, d, zeros)
                for lm in lms:
                    path = series.add(path, unpack(lm))
            return pk, _bba.reduced(st, None if hring is ring else _layout(pk))
        except Overflow:
            maxdeg *= 4


def _as_dicts(pk: Packing, basis, coefficient) -> list[dict[Exp, Any]]:
    layout = _layout(pk)
    return [dict(zip(_bba.exponents(layout, ms), map(coefficient, array("Q", cs)))) for ms, cs in basis]


def hilbert_modp(gens: Sequence[Poly], ring: PolyRing, degree_basis: Basis) -> list[dict[Exp, Any]]:
    """The reduced Gröbner basis over Z/p (``p < 2^31``) by the compiled Hilbert-driven
    algorithm, as ``{exponent: nmod}`` dicts by increasing leading monomial."""
    hring, hgens, target = _homogenized(gens, ring, degree_basis)
    p = ring.field.characteristic
    pk, basis = _reduced_modp([{e: int(c) for e, c in g.terms.items()} for g in hgens], hring, ring,
                                  _Series(target, hring.nvars), p)
    return _as_dicts(pk, basis, lambda c: flint.nmod(c, p))


def hilbert_qq(gens: Sequence[Poly], ring: PolyRing, degree_basis: Basis) -> list[dict[Exp, Any]]:
    """The reduced Gröbner basis over QQ by the compiled Hilbert-driven algorithm modulo primes
    and a lift (see the module docstring), as ``{exponent: fmpq}`` dicts by increasing leading
    monomial; :class:`~.modular.ModularFailure` if no verified lift is found."""
    hring, hgens, target = _homogenized(gens, ring, degree_basis)
    hints = [primitive(g.terms) for g in hgens]
    series = _Series(target, hring.nvars)
    return _lift_qq(lambda p: _reduced_modp(hints, hring, ring, series, p), hints, hring, gens, ring)


def buchberger_modp(gens: Sequence[Poly], ring: PolyRing, limit: int = 0) -> list[dict[Exp, Any]]:
    """The reduced Gröbner basis over Z/p (``p < 2^31``) by Buchberger's algorithm in C (the
    sugar strategy, the Gebauer–Möller criteria), as ``{exponent: nmod}`` dicts by increasing
    leading monomial; :class:`~.buchberger.TooLong` past ``limit`` terms summed (if not 0)."""
    p = ring.field.characteristic
    pk, basis = _reduced_modp([{e: int(c) for e, c in g.terms.items()} for g in gens], ring, ring,
                                  _AllPairs(), p, limit)
    return _as_dicts(pk, basis, lambda c: flint.nmod(c, p))


def buchberger_qq(gens: Sequence[Poly], ring: PolyRing, limit: int = 0, max_primes: int = MAX_PRIMES) -> list[dict[Exp, Any]]:
    """:func:`buchberger_modp` over QQ, lifted from primes and verified as in the module
    docstring.  For homogeneous generators ``J = <G>`` is then the ideal (the dimension count of
    :mod:`.modular`: ``J`` contains the ideal and ``dim J_d = dim (I mod p)_d <= dim I_d``), for
    others as soon as one prime used is lucky.  :class:`~.modular.ModularFailure` after
    ``max_primes`` primes."""
    ints = [primitive(g.terms) for g in gens]
    return _lift_qq(lambda p: _reduced_modp(ints, ring, ring, _AllPairs(), p, limit), ints, ring, gens, ring,
                    max_primes)


def lift_primes(seed: int = 30011):
    """An endless pseudo-random sequence of distinct primes in :data:`PRIMES`."""
    return primes(seed, PRIMES)


def _lift_qq(modp, ints: list[dict[Exp, int]], iring: PolyRing, gens: Sequence[Poly], ring: PolyRing,
             max_primes: int = MAX_PRIMES):
    """The reduced basis over QQ lifted from ``modp(p)`` (a packing and the reduced basis modulo
    ``p`` as bytes) at primes not dividing the leading coefficients of the integer polynomials
    ``ints`` of ``iring``, checked against ``gens`` (see the module docstring)."""
    key = iring.order.key
    leads = [t[max(t, key=key)] for t in ints]
    stream = lift_primes()
    used = 0
    while used < max_primes:
        shape = pk = None
        lift = Lift()
        misses = good = 0
        while used < max_primes:
            p = next(stream)
            used += 1
            if any(c % p == 0 for c in leads):
                continue
            ppk, basis = modp(p)
            ms = [m for m, _ in basis]
            flat = b"".join(c for _, c in basis)
            if shape is None:
                shape, pk = ms, ppk
                layout = _layout(pk)
                sizes = [len(c) // 8 for _, c in basis]
            elif ms != shape:
                misses += 1
                if misses > good + 2:
                    break  # the first prime was unlucky: start again
                continue
            else:
                good += 1
                coefs = lift.checked(flat, p)
                if coefs is not None:
                    out, k = [], 0
                    for m, size in zip(shape, sizes):
                        out.append(dict(zip(_bba.exponents(layout, m), coefs[k:k + size])))
                        k += size
                    if _generators_reduce_to_zero(pk, shape, lift.fractions, out, gens, ring.order):
                        return out
                    break
            lift.add(flat, p)
    raise ModularFailure("compiled Buchberger's lift: no verified basis")


def _generators_reduce_to_zero(pk: Packing, shape: list[bytes], fractions: tuple[list[int], list[int]] | None,
                               lift: list[dict[Exp, Any]], gens: Sequence[Poly], order: MonomialOrder) -> bool:
    """Whether every generator top-reduces to 0 by the lift exactly: in C on 128-bit integers
    (``_bba.in_ideal``) from the numerators and denominators of the C reconstruction
    (``fractions``, the coefficients of the basis elements of monomials ``shape`` in turn), else
    (past 128 bits, or a lift by :class:`.modular.Reconstructor`) by :func:`reduce_to_zero`."""
    if fractions is not None:
        try:
            polys = [_encode(pk, primitive(g.terms)) for g in gens]
        except OverflowError:  # a coefficient of more than 63 bits
            polys = None
        if polys is not None:
            nums, dens = memoryview(array("q", fractions[0])), memoryview(array("q", fractions[1]))
            reducers, k = [], 0
            width = 8 * ((pk.bits + 64) // 64)
            for ms in shape:
                size = len(ms) // width
                reducers.append((ms, nums[k:k + size], dens[k:k + size]))
                k += size
            answer = _bba.in_ideal(_layout(pk), reducers, polys)
            if answer is not None:
                return answer
    return reduce_to_zero(lift, [g.terms for g in gens], order)


class Lift:
    """Residues of the coefficients (one flat uint64 array per prime) lifted to QQ: in C while
    the product of the primes has at most :data:`C_LIFT_BITS` bits (two primes), then by
    :class:`.modular.Lifter` and :class:`.modular.Reconstructor`."""

    def __init__(self) -> None:
        self.residues: list[bytes] = []
        self.primes: list[int] = []
        self.modulus = 1
        self.lifter: Lifter | None = None
        self.rec: Reconstructor | None = None
        self.candidate: list | None = None
        self.fractions: tuple[list[int], list[int]] | None = None
        """The numerators and denominators of the last lift :meth:`checked` made in C."""

    def add(self, flat: bytes, p: int) -> None:
        self.residues.append(flat)
        self.primes.append(p)
        self.modulus *= p
        if self.modulus.bit_length() > C_LIFT_BITS:
            if self.lifter is None:
                self.lifter, self.rec = Lifter(), Reconstructor([len(flat) // 8])
                for r, q in zip(self.residues, self.primes):
                    self.lifter.add([array("Q", r).tolist()], q)
            else:
                self.lifter.add([array("Q", flat).tolist()], p)
            self.candidate = self.rec.attempt(self.lifter.values, self.lifter.m)

    def checked(self, flat: bytes, q: int) -> list | None:
        """The lift from the primes so far if it agrees with the residues modulo ``q``, else None."""
        if not self.primes:
            return None
        if self.lifter is None:
            self.fractions = _bba.ratlift(self.residues, self.primes, flat, q)
            return None if self.fractions is None else list(map(flint.fmpq, *self.fractions))
        self.fractions = None
        if not self.rec.check([array("Q", flat).tolist()], q) and self.candidate is not None:
            return self.candidate[0]
        return None


def reduce_to_zero(basis: list[dict[Exp, Any]], polys: Sequence[dict[Exp, Any]], order: MonomialOrder) -> bool:
    """Whether every polynomial top-reduces to 0 by ``basis`` (leading exponent first in each
    dict) for ``order``, exactly.  Fraction-free on integers (:class:`_IntegerReducer`): each
    polynomial and each basis element is scaled to a primitive integer polynomial (nonzero
    scalars do not change whether a reduction ends in 0), and a step ``a p - c x^s g`` with
    ``a c = lc(g) p_m / gcd`` cancels the top term ``p_m`` of ``p`` without a division."""
    maxdeg = max(8, 2 * max(sum(e) for f in list(polys) + basis for e in f))
    while True:
        pk = packing(order, maxdeg)
        try:
            red = _IntegerReducer(pk, basis)
            return all(red.reduces_to_zero({pk.pack(e): c for e, c in primitive(f).items()}) for f in polys)
        except Overflow:
            maxdeg *= 4


class _IntegerReducer:
    """Basis elements as primitive integer polynomials on packed monomials, each packed when it
    first serves (the generators' reductions use few of them)."""

    def __init__(self, pk: Packing, basis: list[dict[Exp, Any]]) -> None:
        self.pk = pk
        self.guard = pk.guard
        self.items = [(pk.pack(next(iter(b))), b) for b in basis]
        self.done: dict[int, tuple[int, dict[int, int]]] = {}

    def find(self, m: int) -> tuple[int, dict[int, int]] | None:
        g = self.guard
        mg = m | g
        for k, (lm, p) in enumerate(self.items):
            if (mg - lm) & g == g:
                hit = self.done.get(k)
                if hit is None:
                    pk_pack = self.pk.pack
                    hit = self.done[k] = (lm, {pk_pack(e): c for e, c in primitive(p).items()})
                return hit
        return None

    def reduces_to_zero(self, f: dict[int, int]) -> bool:
        """Whether the integer polynomial ``f`` top-reduces to 0."""
        guard = self.guard
        p = dict(f)
        heap = [-m for m in p]
        heapq.heapify(heap)
        while heap:
            m = -heapq.heappop(heap)
            c = p.get(m)
            if c is None:
                continue
            hit = self.find(m)
            if hit is None:
                return False
            lm, g = hit
            a = g[lm]
            d = gcd(a, c)
            a, c = a // d, c // d
            if a != 1:
                if a == -1:
                    a, c = 1, -c
                else:
                    for k in p:
                        p[k] *= a
            subtract_shifted(p, heap, g, m - lm, c, guard)
            if len(p) > 1 and a != 1:
                cont = gcd(*p.values())
                if cont != 1:
                    for k in p:
                        p[k] //= cont
        return True
