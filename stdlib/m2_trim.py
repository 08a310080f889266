"""Macaulay2's trimming of a Gröbner basis to fewer generators (``quotient``, ``saturate`` and the
ideal commands of the dialect return ideals trimmed this way)."""
from __future__ import annotations

from ..dsl.values import Ideal
from ..kernel import Poly
from ..kernel import ideals as K
from .standard import normalize


def minimal(I: Ideal, polys: list[Poly]) -> Ideal:
    """The ideal of the Gröbner basis ``polys`` (increasing) on fewer generators, as Macaulay2
    trims: from the largest down, an element in the ideal of the others is dropped."""
    keep = [normalize(p) for p in polys]
    for k in range(len(keep) - 1, -1, -1):
        others = keep[:k] + keep[k + 1:]
        if others and K.is_subset([keep[k]], others, ring=I.ring):
            keep = others
    return Ideal(I.ring, keep, is_std=len(keep) == len(polys))
