"""Monomials packed into Python integers, for the F4 engine.

A global monomial ordering is a nonnegative integer weight matrix ``W`` of full rank (every
global ordering has one: add to a row with a negative entry a multiple of an earlier row
that is positive in that column, which leaves the ordering unchanged, and drop dependent
rows).  A monomial ``x^e`` is stored as one integer whose bit fields are, from the most
significant down, ``W e`` (one field per row), the total degree ``|e|``, and ``e`` itself.
Every field is nonnegative and keeps its top bit clear, so

* multiplication of monomials is integer addition, division is subtraction;
* comparing two packed integers compares the monomials in the ordering (``W e`` decides,
  the lower fields only break ties that cannot happen since ``W`` has full rank);
* ``a | b`` is one masked subtraction: ``((b | G) - a) & G == G`` where ``G`` holds the
  guard (top) bit of every field, because no field of ``b - a`` then borrows from the next.

Field widths are chosen for a total-degree bound ``maxdeg``; code building larger monomials
must check :meth:`Packing.fits` and start again with a wider packing.
"""
from __future__ import annotations

from fractions import Fraction
from functools import lru_cache
from itertools import chain
from typing import Sequence

from .order import Exp, MonomialOrder

try:
    from ._f4rows import exponents as EXPONENTS, pack as PACK, term_dicts as TERM_DICTS
except ImportError:  # no compiler at install (or an older extension): packed and unpacked in Python
    EXPONENTS = PACK = TERM_DICTS = None


def nonnegative_matrix(order: MonomialOrder) -> list[list[int]]:
    """A nonnegative ``n x n`` integer matrix of full rank defining the same (global) ordering."""
    return [list(r) for r in _nonnegative(tuple(map(tuple, order.matrix)), order.nvars)]


@lru_cache(maxsize=256)
def _nonnegative(matrix: tuple[tuple[int, ...], ...], n: int) -> tuple[tuple[int, ...], ...]:
    rows: list[list[int]] = []
    echelon: list[list[Fraction]] = []  # for the rank test
    for r in matrix:
        if not independent_row(echelon, r):
            continue
        r = list(r)
        for j in range(n):
            if r[j] < 0:
                s = next(s for s in reversed(rows) if s[j] > 0)  # exists for a global ordering
                c = -(r[j] // s[j])
                r = [a + c * b for a, b in zip(r, s)]
        rows.append(r)
        if len(rows) == n:
            break
    return tuple(map(tuple, rows))


def independent_row(echelon: list[list[Fraction]], row: Sequence[int]) -> bool:
    """Whether ``row`` is independent of the rows in ``echelon`` (which it then joins)."""
    v = [Fraction(x) for x in row]
    for e in echelon:
        piv = next(i for i, x in enumerate(e) if x)
        if v[piv]:
            f = v[piv] / e[piv]
            v = [a - f * b for a, b in zip(v, e)]
    if any(v):
        echelon.append(v)
        return True
    return False


class Packing:
    """Packed monomials in ``nvars`` variables for a global ordering, total degree <= ``maxdeg``
    (immutable: :func:`packing` shares one per ordering and degree)."""

    def __init__(self, order: MonomialOrder, maxdeg: int) -> None:
        n = self.nvars = order.nvars
        self.maxdeg = maxdeg
        W = nonnegative_matrix(order)
        ebits = maxdeg.bit_length() + 1
        widths = [(max(r) * maxdeg).bit_length() + 1 for r in W] + [ebits] * (n + 1)
        shifts, pos = [], 0
        for w in reversed(widths):
            shifts.append(pos)
            pos += w
        shifts.reverse()
        self.bits = pos
        self.weight_shifts, self.weight_widths = shifts[:n], widths[:n]  # the fields of W e
        # a graded ordering (first weight row positive): its weighted degree is the top field
        self.graded = all(v > 0 for v in W[0])
        self.first_weights = tuple(W[0])
        self.degree_first = all(v == 1 for v in W[0])  # the ordering compares total degrees first
        self.wshift = shifts[0]
        self.guard = sum(1 << (s + w - 1) for s, w in zip(shifts, widths))
        self.eshifts = shifts[n + 1:]
        self._eshifts = tuple(self.eshifts)
        # the exponent fields in 64 bits: unpacked in C
        self._compiled_unpack = EXPONENTS is not None and TERM_DICTS is not None and n * ebits <= 64
        self.dshift = shifts[n]
        self.emask = (1 << ebits) - 1
        # the exponent fields are the lowest ones: their mask, guard bits and field width
        self.ebits = ebits
        self.eall = (1 << (n * ebits)) - 1
        self.eguard = sum(1 << (ebits * i + ebits - 1) for i in range(n))

        # the packed form of each variable: W's column, degree 1, exponent 1
        self.units = [sum(W[i][j] << shifts[i] for i in range(n)) + (1 << shifts[n])
                      + (1 << shifts[n + 1 + j])
                      for j in range(n)]
        self._units = tuple(self.units)
        # the same by exponent field, lowest first (the last variable's field is the lowest)
        self._field_units = self.units[::-1]

    def fits(self, degree: int) -> bool:
        return degree <= self.maxdeg

    def pack(self, e: Exp) -> int:
        return sum(k * u for k, u in zip(e, self.units) if k)

    def pack_all(self, exponents: Sequence[Exp]) -> list[int]:
        """:meth:`pack` of each exponent vector (in C when the packed monomials fit 128 bits)."""
        if PACK is not None:
            packed = PACK(exponents, self._units)
            if packed is not None:
                return packed
        return [self.pack(e) for e in exponents]

    def unpack(self, m: int) -> Exp:
        mask = self.emask
        return tuple([(m >> s) & mask for s in self.eshifts])

    def unpack_all(self, monomials) -> dict[int, Exp]:
        """The exponents of packed monomials, by monomial (each unpacked once): in C when the
        exponent fields fit the lowest 64 bits, else the exponent fields (the lowest bits) cut
        out first, then one field of every monomial at a time."""
        if self._compiled_unpack:
            return EXPONENTS(monomials, self._eshifts, self.ebits)
        mask, eall = self.emask, self.eall
        ms = list(set(monomials))
        low = [m & eall for m in ms]
        columns = [[e >> s & mask for e in low] for s in self.eshifts]
        return dict(zip(ms, zip(*columns))) if columns else dict.fromkeys(ms, ())

    def term_dicts(self, rows: Sequence[tuple[Sequence[int], Sequence]], scale=None) -> list[dict]:
        """Rows ``(packed monomials, coefficients)`` as ``{exponent: coefficient}`` dicts in the
        rows' order, each coefficient multiplied by ``scale`` unless it is None (in C when the
        exponent fields fit 64 bits)."""
        if self._compiled_unpack:
            return TERM_DICTS(rows, self._eshifts, self.ebits, scale)
        exp = self.unpack_all(chain.from_iterable(ms for ms, _ in rows)).__getitem__
        if scale is None:
            return [dict(zip(map(exp, ms), cs)) for ms, cs in rows]
        return [dict(zip(map(exp, ms), map(scale.__mul__, cs))) for ms, cs in rows]

    def weighted_degree(self, m: int) -> int:
        """The first weight row applied to the exponent (the degree of a graded ordering)."""
        return m >> self.wshift

    def degree(self, m: int) -> int:
        return (m >> self.dshift) & self.emask

    def divides(self, a: int, b: int) -> bool:
        g = self.guard
        return ((b | g) - a) & g == g

    def lcm_e(self, a: int, b: int) -> int:
        """The exponent fields of ``lcm(a, b)`` (word-parallel maximum), enough to compare lcms
        and test their divisibility with :attr:`eguard`."""
        eall, g = self.eall, self.eguard
        ea, eb = a & eall, b & eall
        sel = (((ea | g) - eb) & g) >> (self.ebits - 1)
        sel *= (1 << self.ebits) - 1
        return (ea & sel) | (eb & ~sel)

    def lcm(self, a: int, b: int) -> int:
        """``lcm(a, b)``: ``a`` times the variables' powers by which ``b`` exceeds it, found
        word-parallel in the exponent fields (usually few)."""
        ebits, mask = self.ebits, self.emask
        eall, g = self.eall, self.eguard
        ea, eb = a & eall, b & eall
        keep = ((((ea | g) - eb) & g) >> (ebits - 1)) * mask  # the fields where a >= b
        d = (eb & ~keep) - (ea & ~keep)  # b - a where b exceeds a, else 0 (no borrows)
        units = self._field_units
        while d:
            f = ((d & -d).bit_length() - 1) // ebits
            x = (d >> (f * ebits)) & mask
            a += x * units[f]
            d -= x << (f * ebits)
        return a


@lru_cache(maxsize=64)
def packing(order: MonomialOrder, maxdeg: int) -> Packing:
    """The shared :class:`Packing` of ``order`` and ``maxdeg`` (building one costs about as much
    as a small normal form, and the analyses ask for the same few thousands of times)."""
    return Packing(order, maxdeg)

