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
    from . import _f4rows as KERNEL
except ImportError:  # no compiler at install: the pure-Python path
    KERNEL = None

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

    def add(self, codes, coefs) -> None:
        """One row: its column codes and coefficients (iterables of equal length)."""
        self.col.extend(codes)
        self.val.extend(coefs)
        self.off.append(len(self.col))

    def reduce(self, p: int, m: int, K: int, want: Sequence[int] = (), stop: bool = False):
        """``(used, E, W)``: the pair rows that raised the rank with their pivot slots, the
        reduced echelon rows ``(slot, slots, values)`` by increasing pivot slot, and the
        reduced tails ``(slots, values)`` of the reducers ``want`` (slots highest first)."""
        return KERNEL.reduce(p, m, K, len(self.ids), self.ids, self.off, self.col, self.val,
                             array("i", want), stop)


def spec_codes(spec: RowSpec) -> tuple[list[int], list[int]]:
    """A recorded row's term positions and their column codes."""
    return spec.piv_t + spec.np_t, spec.piv_j + [~s for s in spec.np_s]


def replay_step(step, coefs: list[list[int]], p: int, want: Sequence[int] = ()):
    """The kernel's ``(used, E, W)`` for a recorded step (:class:`~.f4_trace.Step`) with the
    coefficients of another prime; the step's codes are computed once and kept on it."""
    if step.flat is None:
        rows = [(j, spec) for j, spec in step.reducers] + [(-1, spec) for spec, _ in step.rows]
        step.flat = [(j, spec.k, *spec_codes(spec)) for j, spec in rows]
    flat = Flat()
    for j, k, tix, codes in step.flat:
        if j >= 0:
            flat.ids.append(j)
        flat.add(codes, map(coefs[k].__getitem__, tix))
    return flat.reduce(p, step.m, step.K, want)
