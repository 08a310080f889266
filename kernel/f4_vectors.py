"""Dense vectors modulo a word-size prime packed into Python integers, and the reduced
echelon form of a few of them: the linear algebra of F4 (:mod:`.f4`).

A matrix row is described by a :class:`RowSpec`: its terms in *pivot* columns (leading
monomials of reducers) and in *non-pivot* slots (the staircase).  A non-pivot vector is dense
but short: one Python integer of 64-bit slots, slot ``s`` holding the coefficient of the
``s``-th smallest non-pivot monomial (so the tails of reducers with small pivots are short
integers), and ``acc += c * T_j`` runs in C.  Slots stay below ``2^64`` for up to ``hmax``
products; then every slot is reduced mod ``p`` at once by word-parallel arithmetic (two folds
``x = h 2^s + l -> h (2^s mod p) + l``, a Barrett quotient and two conditional subtractions,
each one operation on the whole integer).  Primes above ``2^28`` use wider slots and reduce
slot by slot.
"""
from __future__ import annotations

from array import array
from collections import deque
from dataclasses import dataclass
from operator import lshift, mul
from typing import Callable


@dataclass
class RowSpec:
    """A matrix row ``x^u * poly[k]``: terms ``piv_t`` sit in pivot columns ``piv_j``, terms
    ``np_t`` in non-pivot slots ``np_s`` (term positions index the polynomial's terms)."""

    k: int
    piv_t: list[int]
    piv_j: list[int]
    np_t: list[int]
    np_s: list[int]


class Vectors:
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

    def combiner(self, m: int) -> Callable[[RowSpec, list[int], list[int], list[int]], int]:
        """The function giving a row's reduced non-pivot part ``N - sum c_j T_j`` (normalized)
        from the row, the polynomial's coefficients and their negatives, and the reduced
        reducers ``T``."""
        comb = self._combiners.get(m)
        if comb is not None:
            return comb
        norm, hmax, w = self.normalizer(m), self.hmax, self.slot
        scale = w.__mul__
        wide = w == 64

        def comb(row: RowSpec, coefs: list[int], neg: list[int], T: list[int]) -> int:
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


def echelon(vec: Vectors, rows: list[int], m: int) -> tuple[dict[int, int], list[tuple[int, int]]]:
    """Reduced echelon form of the packed rows: ``{pivot slot: packed monic row}`` and the
    (row index, pivot slot) of the rows that raised the rank.

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
        if not x:
            continue
        s0 = vec.lead(x)
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


def support(vec: Vectors, x: int, m: int) -> tuple[list[int], list[int]]:
    """The nonzero slots of a vector, highest first, and their values."""
    vals = vec.values(x, m)
    slots = [s for s in range(m - 1, -1, -1) if vals[s]]
    return slots, [vals[s] for s in slots]

