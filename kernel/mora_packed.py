"""The working polynomial of Mora's normal form (:mod:`.mora`) for ``ds`` on packed monomials.

A monomial ``x^e`` in ``n`` variables is one integer: the exponent of ``x_i`` in bits
``[B i, B (i + 1))`` (the last variable highest) and the total degree above them.  Then the
product of monomials is the sum of their integers, and for ``ds`` (lower degree first, then
reverse lexicographic) a monomial is larger exactly when its integer is smaller: the leading
monomial is the heap's minimum, and a degree cut is one comparison.  Each field keeps a guard
bit, so exponents stay below ``2^(B-1)`` (:data:`MAX_DEGREE`).
"""
from __future__ import annotations

import heapq
from typing import Any

from .order import Exp

B = 16
MAX_DEGREE = (1 << (B - 1)) - 1
"""Larger degrees would overflow a field: Mora's algorithm stops (``BudgetExceeded``)."""


class Packing:
    """Packing and unpacking of the exponents of ``n`` variables."""

    def __init__(self, n: int) -> None:
        self.n = n
        self.top = B * n
        self.mask = (1 << B) - 1
        self.guard = sum(1 << (B * i + B - 1) for i in range(n))

    def pack(self, e: Exp) -> int:
        k = sum(e)
        for i in range(self.n - 1, -1, -1):
            k = (k << B) | e[i]
        return k

    def unpack(self, k: int) -> Exp:
        m = self.mask
        return tuple([(k >> (B * i)) & m for i in range(self.n)])

    def limit(self, cut: int | None) -> int | None:
        """The smallest packed monomial of degree above ``cut``."""
        return None if cut is None else (cut + 1) << self.top


class PackedFront:
    """:class:`.mora.Front` for ``ds``: the terms by packed monomial, a heap of them (the
    smallest is the leading one), and a degree cut."""

    __slots__ = ("p", "heap", "pk", "limit", "cut")

    def __init__(self, terms: dict[Exp, Any], pk: Packing, cut: int | None = None) -> None:
        pack = pk.pack
        p = {pack(e): c for e, c in terms.items()}
        limit = pk.limit(cut)
        if limit is not None:
            p = {k: c for k, c in p.items() if k < limit}
        self.p, self.pk, self.cut, self.limit = p, pk, cut, limit
        self.heap = list(p)
        heapq.heapify(self.heap)

    def trim(self, cut: int | None) -> None:
        if cut is not None and (self.cut is None or cut < self.cut):
            self.cut, self.limit = cut, self.pk.limit(cut)
            self.p = {k: c for k, c in self.p.items() if k < self.limit}

    def _lead(self) -> int:
        heap, p = self.heap, self.p
        while heap[0] not in p:
            heapq.heappop(heap)
        return heap[0]

    def lm(self) -> Exp:
        return self.pk.unpack(self._lead())

    def coeff(self, lm: Exp) -> Any:
        return self.p[self._lead()]

    def terms(self) -> dict[Exp, Any]:
        unpack = self.pk.unpack
        return {unpack(k): c for k, c in self.p.items()}

    def reduce(self, lm: Exp, g: Any) -> None:
        """``p - (LT(p)/LT(g)) g`` for ``LM(g) | LM(p)``, leaving out the terms above the cut."""
        p, heap, push = self.p, self.heap, heapq.heappush
        lead = self._lead()
        rows = g.packed(self.pk)
        shift = lead - self.pk.pack(g.lm)
        factor = p[lead] / g.p[g.lm]
        limit = self.limit
        for k, c in rows:
            te = k + shift
            if limit is not None and te >= limit:
                break
            v = p.get(te)
            if v is None:
                p[te] = -factor * c
                push(heap, te)
            else:
                v = v - factor * c
                if v == 0:
                    del p[te]
                else:
                    p[te] = v

    def unit_cancelled(self, lm: Exp) -> bool:
        """Replace ``p = x^a u`` (``x^a = LM``, ``u`` a unit) by its leading term; whether it was."""
        p = self.p
        if len(p) == 1:
            return False
        lead = self._lead()
        guard = self.pk.guard
        if all(((k | guard) - lead) & guard == guard for k in p):
            self.p = {lead: p[lead]}
            self.heap = [lead]
            return True
        return False
