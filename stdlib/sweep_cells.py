"""Designs of a two-parameter grid grouped by the cells of the discriminant curves.

Two neighbouring designs of a grid (same row or same column) are joined when the segment between
them meets none of the curves (nor an axis: a zero length is special); this is decided exactly, from
the real roots of each curve's polynomial restricted to the grid line. Designs joined by a chain of
such segments lie in one connected component of the complement of the curves, where the number of
real assembly modes is constant: one of them is analysed, the others get its count. Designs on a
curve are never grouped. :func:`check_cells` is the converse check on a computed table: neighbours
with different counts must be separated by a curve.
"""
from __future__ import annotations

from fractions import Fraction
from typing import Any, Sequence

from flint import fmpq, fmpq_poly

from mech.kernel.real_roots import isolate_real_roots

Terms = dict[tuple[int, int], Fraction]


def value(f: Terms, a: Fraction, b: Fraction) -> Fraction:
    """``f(a, b)``."""
    return sum((c * a ** i * b ** j for (i, j), c in f.items()), Fraction(0))


def on_curves(curves: Sequence[Terms], a: Fraction, b: Fraction) -> list[int]:
    """The indices of the curves through ``(a, b)``."""
    return [k for k, f in enumerate(curves) if value(f, a, b) == 0]


def _restricted(f: Terms, fixed: Fraction, axis: int) -> fmpq_poly:
    """``f`` on the line where parameter ``axis`` is ``fixed``, as a polynomial in the other one."""
    coeffs: dict[int, Fraction] = {}
    for (i, j), c in f.items():
        k, e = (j, i) if axis == 0 else (i, j)
        coeffs[k] = coeffs.get(k, Fraction(0)) + c * fixed ** e
    top = max((k for k, c in coeffs.items() if c), default=-1)
    return fmpq_poly([fmpq(coeffs.get(k, Fraction(0)).numerator, coeffs.get(k, Fraction(0)).denominator)
                      for k in range(top + 1)])


def _blocked(poly: fmpq_poly, grid: list[Fraction]) -> set[int]:
    """The segments ``[grid[i], grid[i+1]]`` that contain a real root of ``poly``."""
    if poly.degree() < 1:
        return set()  # no root (a constant), or zero: the whole line lies on the curve, its designs too
    out: set[int] = set()
    lo_g, hi_g = fmpq(grid[0].numerator, grid[0].denominator), fmpq(grid[-1].numerator, grid[-1].denominator)
    points = [fmpq(x.numerator, x.denominator) for x in grid]
    for r in isolate_real_roots(poly):
        if r.hi < lo_g or r.lo > hi_g:
            continue
        lo, hi = r.lo, r.hi
        while True:
            inside = [i for i, x in enumerate(points) if lo < x < hi]
            if not inside:
                break
            if r.exact is not None:
                lo = hi = r.exact
                break
            x = points[inside[len(inside) // 2]]
            v = r.poly(x)
            if v == 0:
                lo = hi = x
                break
            if (v > 0) == (r.poly(lo) > 0):
                lo = x
            else:
                hi = x
        for i in range(len(points) - 1):  # a segment meeting [lo, hi]
            if points[i] <= hi and lo <= points[i + 1]:
                out.add(i)
    return out


def grid_cells(points: dict[int, tuple[Fraction, Fraction]], curves: Sequence[Terms]) -> dict[int, int] | None:
    """For designs forming a full grid: each design off the curves mapped to the smallest id of its
    group (designs on a curve map to themselves); None when the designs are not a grid."""
    xs = sorted({a for a, _ in points.values()})
    ys = sorted({b for _, b in points.values()})
    if len(xs) * len(ys) != len(points) or len(xs) < 2 or len(ys) < 2:
        return None
    barriers = list(curves) + [{(1, 0): Fraction(1)}, {(0, 1): Fraction(1)}]
    at = {(a, b): i for i, (a, b) in points.items()}
    free = {i for i, (a, b) in points.items() if not on_curves(barriers, a, b)}
    parent = {i: i for i in points}

    def find(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    def join(i: int, j: int) -> None:
        if i in free and j in free:
            ri, rj = find(i), find(j)
            parent[max(ri, rj)] = min(ri, rj)
    for axis, (fixed_values, grid) in enumerate(((ys, xs), (xs, ys))):
        for fixed in fixed_values:
            blocked: set[int] = set()
            for f in barriers:
                blocked |= _blocked(_restricted(f, fixed, 1 - axis), grid)
            for k in range(len(grid) - 1):
                if k in blocked:
                    continue
                p, q = ((grid[k], fixed), (grid[k + 1], fixed)) if axis == 0 else ((fixed, grid[k]), (fixed, grid[k + 1]))
                join(at[p], at[q])
    return {i: find(i) for i in points}


def check_cells(rows: Sequence[dict[str, Any]], x: str, y: str, answer: str, curves: Sequence[Terms]) -> list[str]:
    """The problems of a computed grid table against the curves: neighbours with different answers
    not separated by a curve, and designs of one group with different answers (empty: agrees)."""
    points = {int(r["id"]): (Fraction(str(r[x])), Fraction(str(r[y]))) for r in rows}
    answers = {int(r["id"]): r[answer] for r in rows}
    groups = grid_cells(points, curves)
    if groups is None:
        return ["the designs are not a grid"]
    return [f"design {i} ({answers[i]}) and design {g} ({answers[g]}) are in one cell"
            for i, g in groups.items() if answers[i] != answers[g] and answers[i] != "" and answers[g] != ""]
