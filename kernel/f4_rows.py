"""F4's matrices reduced in compiled code (the optional C extension ``_f4rows``).

``setup.py`` builds ``kernel/_f4rows.c`` when a C compiler is present; without it (or for a
prime of 2^31 or more) F4 uses the pure-Python linear algebra of :mod:`.f4_vectors`, which
computes the same numbers by the same operations.  Rows go to C flat: per row its column
codes (``j >= 0``: pivot ``j``; ``~s``: non-pivot slot ``s``) and coefficients mod ``p``.
"""
from __future__ import annotations

from array import array
from typing import Sequence

from .f4_vectors import RowSpec

try:
    from ._f4rows import gather as GATHER, layout as LAYOUT, reduce as KERNEL
    from ._f4rows import subplan as SUBPLAN
except ImportError:  # no compiler at install: pure Python
    KERNEL = LAYOUT = GATHER = SUBPLAN = None
try:
    from ._f4rows import words as WORDS
except ImportError:  # the same bytes by int.to_bytes (an extension built before it)
    WORDS = None

LIMIT = 1 << 31  # primes the kernel handles (products of two entries fit 62 bits)


def compiled(p: int) -> bool:
    """Whether matrices modulo ``p`` go to the compiled kernel."""
    return KERNEL is not None and p < LIMIT


class Flat:
    """A matrix's rows collected flat for the kernel: reducers first (with their pivot ids),
    then the pair rows."""

    __slots__ = ("ids", "off", "col", "val")

    def __init__(self) -> None:
        self.ids = array("i")
        self.off = array("q", [0])
        self.col = array("i")
        self.val = array("Q")

    @classmethod
    def of(cls, ids: bytes, off: bytes, col: bytes, val: bytes) -> "Flat":
        """The rows as :meth:`Packed.layout` returns them (bytes, viewed as arrays without a copy:
        the reducers' pivot ids, offsets, column codes, coefficients)."""
        flat = cls.__new__(cls)
        flat.ids, flat.off = memoryview(ids).cast("i"), memoryview(off).cast("q")
        flat.col, flat.val = memoryview(col).cast("i"), memoryview(val).cast("Q")
        return flat

    def add(self, codes, coefs) -> None:
        """One row: its column codes and coefficients (iterables of equal length)."""
        self.col.extend(codes)
        self.val.extend(coefs)
        self.off.append(len(self.col))

    def reduce(self, p: int, m: int, K: int, want: Sequence[int] = (), stop: bool = False):
        """``(used, E, W)``: the pair rows that raised the rank with their pivot slots, the
        reduced echelon rows ``(slot, slots, values)`` by increasing pivot slot, and the
        reduced tails ``(slots, values)`` of the reducers ``want`` (slots highest first)."""
        return KERNEL(p, m, K, len(self.ids), self.ids, self.off, self.col, self.val,
                             array("i", want), stop)


class Packed:
    """F4's basis elements as the compiled symbolic preprocessing (``kernel/_f4sym.c``) takes
    them: per element its monomials as ``nw`` little-endian words and its coefficients as
    64-bit words (bytes), converted once per element."""

    def __init__(self, P) -> None:
        self.nw = -(-P.bits // 64)
        self.nb = 8 * self.nw
        self.guard = P.guard.to_bytes(self.nb, "little")
        self.fields = (P.dshift, P.ebits, P.maxdeg)
        self.mons: list[bytes] = []
        self.coefs: list[bytes] = []

    def _sync(self, mons: list[list[int]], coefs: list[list[int]]) -> None:
        nb, nw = self.nb, self.nw
        for k in range(len(self.mons), len(mons)):
            if WORDS is not None:
                self.mons.append(WORDS(mons[k], nw))
            else:
                self.mons.append(b"".join([int(x).to_bytes(nb, "little") for x in mons[k]]))
            try:
                self.coefs.append(array("Q", coefs[k]).tobytes())
            except TypeError:  # coefficients of another type (python-flint's nmod)
                self.coefs.append(array("Q", map(int, coefs[k])).tobytes())

    def layout(self, mons: list[list[int]], coefs: list[list[int]], tdeg: list[int], active: list[bool],
               specs: list[tuple[int, int]], pivots: dict[int, tuple[int, int]]):
        """Symbolic preprocessing and the matrix's rows (see ``kernel/_f4sym.c``; the reducers
        are the ``active`` elements, shortest first): ``(pivcols, nonpivot, flat, rk, rstart,
        work)`` (``rk``, ``rstart``: each row's basis element and first term, as a
        :class:`Plan` takes them), or None when a row exceeds the packing."""
        self._sync(mons, coefs)
        dshift, ebits, maxdeg = self.fields
        out = LAYOUT(self.nw, self.guard, dshift, ebits, maxdeg, self.mons, tdeg, self.coefs, active, specs, pivots)
        if out is None:
            return None
        pivcols, nonpivot, ids, off, col, val, rk, rstart, work = out
        return pivcols, nonpivot, Flat.of(ids, off, col, val), memoryview(rk).cast("i"), memoryview(rstart).cast("i"), work


class CodedRow:
    """A recorded row as the kernel takes it: the terms of ``x^u * poly[k]`` from position
    ``start`` on (1 for a reducer: its leading term is its pivot) with their column codes.
    F4 records these instead of :class:`~.f4_vectors.RowSpec` when the kernel runs."""

    __slots__ = ("k", "start", "codes", "_spec")

    def __init__(self, k: int, start: int, codes: Sequence[int]) -> None:
        self.k, self.start, self.codes, self._spec = k, start, codes, None

    @property
    def piv_j(self) -> list[int]:
        return [c for c in self.codes if c >= 0]

    def spec(self) -> RowSpec:
        """The row as a :class:`~.f4_vectors.RowSpec` (for the pure-Python path), kept."""
        if self._spec is None:
            piv_t, piv_j, np_t, np_s = [], [], [], []
            for t, c in enumerate(self.codes, self.start):
                if c >= 0:
                    piv_t.append(t)
                    piv_j.append(c)
                else:
                    np_t.append(t)
                    np_s.append(~c)
            self._spec = RowSpec(self.k, piv_t, piv_j, np_t, np_s)
        return self._spec


def as_spec(row: RowSpec | CodedRow) -> RowSpec:
    """A recorded row as a :class:`~.f4_vectors.RowSpec`."""
    return row.spec() if isinstance(row, CodedRow) else row


def replay_step(reducers, rows, step, coefs: list[list[int]], p: int, want: Sequence[int] = (), key: str = "rows"):
    """The kernel's ``(used, E, W)`` for recorded rows (reducers as ``(pivot id, row)``,
    pair rows) of a matrix shaped as ``step`` (:class:`~.f4_trace.Step`), with the
    coefficients of another prime.  Rows recorded as :class:`CodedRow` are laid out once
    (a :class:`Plan` kept in ``step.plans[key]``); a replay then only gathers coefficients."""
    plan = step.plans.get(key)
    if plan is None and GATHER is not None and all(isinstance(r, CodedRow) for r in rows) \
            and all(isinstance(r, CodedRow) for _, r in reducers):
        plan = step.plans[key] = Plan([j for j, _ in reducers], [r for _, r in reducers] + list(rows))
    if plan is not None:
        try:
            return plan.reduce(coefs, p, step.m, step.K, want)
        except TypeError:  # coefficients that are not Python ints
            pass
    flat = Flat()
    for j, row in reducers:
        flat.ids.append(j)
        _add_recorded(flat, row, coefs)
    for row in rows:
        _add_recorded(flat, row, coefs)
    return flat.reduce(p, step.m, step.K, want)


class Plan:
    """Recorded rows of a matrix flat for the kernel, without coefficients: column codes,
    offsets, and per row its polynomial and first term; :meth:`reduce` gathers the
    coefficients of a prime (in C) and reduces."""

    __slots__ = ("ids", "off", "col", "rk", "rstart")

    def __init__(self, ids: list[int], rows: list[CodedRow]) -> None:
        self.ids = array("i", ids)
        self.off, self.col = array("q", [0]), array("i")
        self.rk, self.rstart = array("i"), array("i")
        for row in rows:
            self.col.extend(row.codes)
            self.off.append(len(self.col))
            self.rk.append(row.k)
            self.rstart.append(row.start)

    @classmethod
    def of_flat(cls, flat: Flat, rk: Sequence[int], rstart: Sequence[int]) -> "Plan":
        """The plan of a matrix's rows as they were reduced (``flat``; polynomial and first
        term of each row, int32 buffers as :meth:`Packed.layout` gives them)."""
        plan = cls.__new__(cls)
        plan.ids, plan.off, plan.col = flat.ids, flat.off, flat.col
        plan.rk, plan.rstart = rk, rstart
        return plan

    def sub(self, K: int, rows: Sequence[int], roots: Sequence[int] = ()) -> "Plan":
        """The plan of the pair rows ``rows`` (numbered after the ``K`` reducers, which this plan
        holds as rows ``0..K-1`` by pivot id) and the reducers they and the pivots ``roots`` need,
        transitively (cut out in C)."""
        ids, off, col, rk, rstart = SUBPLAN(self.off, self.col, self.rk, self.rstart, K,
                                            array("i", rows), array("i", roots))
        plan = Plan.__new__(Plan)
        plan.ids, plan.off, plan.col = array("i", ids), array("q", off), array("i", col)
        plan.rk, plan.rstart = array("i", rk), array("i", rstart)
        return plan

    def reduce(self, coefs: list[list[int]], p: int, m: int, K: int, want: Sequence[int] = ()):
        """The kernel's ``(used, E, W)`` with the coefficients ``coefs`` (by polynomial)."""
        val = GATHER(coefs, self.rk, self.rstart, self.off)
        return KERNEL(p, m, K, len(self.ids), self.ids, self.off, self.col, val, array("i", want), False)


def _add_recorded(flat: Flat, row: RowSpec | CodedRow, coefs: list[list[int]]) -> None:
    if isinstance(row, CodedRow):
        flat.add(row.codes, coefs[row.k][row.start:])
    else:  # recorded by the pure-Python path
        flat.add(row.piv_j + [~s for s in row.np_s], map(coefs[row.k].__getitem__, row.piv_t + row.np_t))
