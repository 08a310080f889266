"""Mora's algorithm (:mod:`.mora`) for ``ds`` over Z/p with its reduction loop compiled (the
optional C extension ``_mora``, kernel/_mora.c, built by setup.py beside ``_f4rows``): the
polynomials under reduction, the reducers and the S-polynomials live in C as arrays of packed
monomials, and so do the polynomials postponed by the loop; the pairs, the queue and the highest
corner stay in Python.  The loop is the Python
one step for step, so the bases are the same; without the extension :mod:`.mora` runs alone."""
from __future__ import annotations

from types import SimpleNamespace
from typing import Any

import flint

from .coeffs import PrimeField
from .order import Exp
from .poly import PolyRing, support_mask

try:
    from ._mora import normalize, pack, pool_insert, pool_new, pool_truncate, run, spoly, truncate, unpack
    C: SimpleNamespace | None = SimpleNamespace(
        normalize=normalize, pack=pack, pool_insert=pool_insert, pool_new=pool_new, pool_truncate=pool_truncate,
        run=run, spoly=spoly, truncate=truncate, unpack=unpack)
except ImportError:  # pragma: no cover - no compiler at install time
    C = None

STEPS = 1 << 62
"""The step budget passed when there is none."""


class CompiledMora:
    """The compiled pieces for one computation: a pool of reducers (sorted by sugar) and the
    conversions between ``{exponent: coefficient}`` and the packed form (``bytes``)."""

    def __init__(self, ring: PolyRing) -> None:
        self.n = ring.nvars
        self.field = ring.field
        self.p = ring.field.characteristic
        self.pool = C.pool_new(self.n, self.p)
        self.step = 8 * ((self.n + 4) // 4 + 1)  # bytes of one term
        self.words: dict[Exp, bytes] = {}  # packed monomials asked for

    @staticmethod
    def usable(ring: PolyRing) -> bool:
        """Whether the compiled loop applies: the extension is built, the ordering is ``ds``
        and the field Z/p with p < 2^31."""
        blocks = ring.order.blocks
        return (C is not None and len(blocks) == 1 and blocks[0].kind == "ds" and 1 < ring.nvars < 64
                and isinstance(ring.field, PrimeField) and ring.field.characteristic < 1 << 31)

    def pack(self, terms: dict[Exp, Any]) -> bytes | None:
        """The terms packed, leading first; None when a degree reaches 2^15."""
        return C.pack(self.n, [(e, int(c)) for e, c in terms.items()])

    def monomial(self, e: Exp) -> bytes:
        """The packed words of one monomial (for comparisons in C)."""
        b = self.words.get(e)
        if b is None:
            b = self.words[e] = C.pack(self.n, [(e, 0)])[:self.step - 8]
        return b

    def element(self, b: bytes, sugar: int) -> PackedElem | None:
        """A new basis element from an irreducible ``b`` (unit factor cancelled, made monic);
        None when it is a unit."""
        b, top = C.normalize(self.n, self.p, b)
        first = C.unpack(self.n, b[:2 * self.step])
        lm = first[0][0]
        if not any(lm):
            return None
        return PackedElem(self, b, lm, first[1][0] if len(first) > 1 else None,
                          min(sugar - sum(lm), top - sum(lm)))

    def cut_tails(self, elems: list[PackedElem], cut: int) -> None:
        """Drop the tail terms of degree above ``cut`` of the pool and of ``elems``."""
        C.pool_truncate(self.pool, cut)
        for g in elems:
            g.b = C.truncate(self.n, g.b, cut)
            g._p = None

    def terms(self, b: bytes) -> dict[Exp, Any]:
        p = self.p
        return {e: flint.nmod(c, p) for e, c in C.unpack(self.n, b)}

    def insert(self, b: bytes, ecart: int) -> None:
        C.pool_insert(self.pool, b, ecart)

    def run(self, b: bytes | None, sugar: int, head: tuple[int, Exp, int] | None, cut: int | None,
            steps: int | None, counter: int, max_sugar: int) -> tuple[int, bytes | None, int, int, int, int]:
        """Reduce ``b`` (with its ``sugar``) and then the postponed polynomials that come before
        the queue's ``head`` (sugar, leading monomial, counter; None: an empty queue), which
        wait here when postponed again, under the next ``counter``; ``b`` None: only those.
        Returns the status (0: an irreducible nonzero polynomial, with its sugar; 2: out of
        steps or degrees; 3: the queue's head comes first, or nothing is left), the polynomial,
        its sugar, the steps left, the counter and the number of postponed polynomials."""
        hs, hm, hc = (0, None, 0) if head is None else (head[0], self.monomial(head[1]), head[2])
        return C.run(self.pool, b, sugar, hs, hm, hc, -1 if cut is None else cut,
                     STEPS if steps is None else steps, counter, max_sugar)

    def spoly(self, f: bytes, g: bytes, cut: int | None) -> bytes:
        return C.spoly(f, g, self.n, self.p, -1 if cut is None else cut)


class PackedElem:
    """A basis element of the compiled run (:class:`.mora.Elem`'s leading data; its terms
    ``p`` as a dict, the leading monomial first, only when asked for)."""

    __slots__ = ("owner", "b", "lm", "tail_lm", "mask", "ecart", "_p")

    def __init__(self, owner: CompiledMora, b: bytes, lm: Exp, tail_lm: Exp | None, ecart: int) -> None:
        self.owner, self.b, self.lm, self.tail_lm, self.ecart = owner, b, lm, tail_lm, ecart
        self.mask = support_mask(lm)
        self._p: dict[Exp, Any] | None = None

    @property
    def p(self) -> dict[Exp, Any]:
        if self._p is None:
            self._p = self.owner.terms(self.b)
        return self._p

    @property
    def sugar(self) -> int:
        return self.ecart + sum(self.lm)
