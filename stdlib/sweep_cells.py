"""Designs of a two-parameter sweep grouped by the cells of the discriminant curves.

Two designs are joined when the segment between them meets none of the curves (nor an axis: a zero
length is special); this is decided exactly, from the real roots of each curve's polynomial
restricted to the segment. Designs joined by a chain of such segments lie in one connected
component of the complement of the curves, where the number of real assembly modes is constant:
one of them is analysed, the others get its count. Designs on a curve are never grouped.

* A full grid (:func:`grid_cells`): neighbours in a row or a column, each grid line's roots
  isolated once.
* Any other design set (random, Latin hypercube, a CSV file; :func:`scattered_cells`): the sign
  vector of the curves' polynomials at a design is a first filter (designs with different signs are
  in different cells), but one sign vector can belong to several components, so each design is
  joined to a nearby earlier design of its sign vector only when the segment between them is
  free of the curves (up to ``tries`` nearest ones are tried); a design joined to none is analysed.

:func:`check_cells` is the converse check on a computed table: designs of one group with different
counts (never, when the curves are right).
"""
from __future__ import annotations

import math
from fractions import Fraction
from typing import Any, Sequence

from flint import fmpq, fmpq_mpoly_ctx, fmpq_poly

from mech.kernel.real_roots import count_real_roots, isolate_real_roots

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


def design_cells(points: dict[int, tuple[Fraction, Fraction]], curves: Sequence[Terms]) -> dict[int, int]:
    """Each design mapped to the smallest id of its group: :func:`grid_cells` for a full grid,
    else :func:`scattered_cells`."""
    return grid_cells(points, curves) or scattered_cells(points, curves)


def scattered_cells(points: dict[int, tuple[Fraction, Fraction]], curves: Sequence[Terms],
                    tries: int = 4) -> dict[int, int]:
    """For any designs: each design off the curves mapped to the smallest id of its group (joined
    to an earlier design of its sign vector by a segment free of the curves); designs on a curve
    map to themselves."""
    barriers = list(curves) + [{(1, 0): Fraction(1)}, {(0, 1): Fraction(1)}]
    ctx = fmpq_mpoly_ctx.get(("a", "b"), "lex")
    polys = [ctx.from_dict({e: fmpq(c.numerator, c.denominator) for e, c in f.items()}) for f in barriers]
    where = {i: (float(a), float(b)) for i, (a, b) in points.items()}
    x0, y0 = min((x for x, _ in where.values()), default=0.0), min((y for _, y in where.values()), default=0.0)
    width = max(max((x for x, _ in where.values()), default=0.0) - x0, 1e-12)
    height = max(max((y for _, y in where.values()), default=0.0) - y0, 1e-12)
    side = max(1, int(math.sqrt(len(points) / 2)))  # about two designs a bucket

    def bucket(i: int) -> tuple[int, int]:
        x, y = where[i]
        return min(side - 1, int((x - x0) / width * side)), min(side - 1, int((y - y0) / height * side))
    group: dict[int, int] = {}
    buckets: dict[tuple[int, int], list[int]] = {}
    signs: dict[int, tuple[int, ...]] = {}
    for i in sorted(points):
        pt = points[i]
        values = [f(fmpq(pt[0].numerator, pt[0].denominator), fmpq(pt[1].numerator, pt[1].denominator)) for f in polys]
        group[i] = i
        if any(v == 0 for v in values):
            continue  # on a curve: analysed itself
        signs[i] = tuple(v > 0 for v in values)
        bx, by = bucket(i)
        near = [j for dx in (-1, 0, 1) for dy in (-1, 0, 1) for j in buckets.get((bx + dx, by + dy), ())
                if signs[j] == signs[i]]
        near.sort(key=lambda j: ((where[j][0] - where[i][0]) ** 2 + (where[j][1] - where[i][1]) ** 2, j))
        for j in near[:tries]:
            if _segment_free(polys, pt, points[j]):
                group[i] = group[j]
                break
        buckets.setdefault((bx, by), []).append(i)
    return group


def _segment_free(polys: list[Any], p: tuple[Fraction, Fraction], q: tuple[Fraction, Fraction]) -> bool:
    """Whether no polynomial vanishes on the segment from ``p`` to ``q`` (at neither end, and its
    restriction ``g(s)`` has no root in ``(0, 1)``)."""
    s, = _SEGMENT.gens()
    start = [fmpq(x.numerator, x.denominator) for x in p]
    step = [fmpq((y - x).numerator, (y - x).denominator) for x, y in zip(p, q)]
    line = (start[0] + step[0] * s, start[1] + step[1] * s)
    for f in polys:
        terms = f.compose(*line, ctx=_SEGMENT).to_dict()
        g = fmpq_poly([terms.get((k,), 0) for k in range(max(e for e, in terms) + 1)]) if terms else fmpq_poly([])
        if g.degree() > 0 and count_real_roots(g, fmpq(0), fmpq(1)):
            return False
    return True


_SEGMENT = fmpq_mpoly_ctx.get(("s",), "lex")


def check_cells(rows: Sequence[dict[str, Any]], x: str, y: str, answer: str, curves: Sequence[Terms]) -> list[str]:
    """The problems of a computed table against the curves: designs of one group (neighbours of a
    grid, or designs joined by segments free of the curves) with different answers (empty: agrees)."""
    points = {int(r["id"]): (Fraction(str(r[x])), Fraction(str(r[y]))) for r in rows}
    answers = {int(r["id"]): r[answer] for r in rows}
    groups = design_cells(points, curves)
    return [f"design {i} ({answers[i]}) and design {g} ({answers[g]}) are in one cell"
            for i, g in groups.items() if answers[i] != answers[g] and answers[i] != "" and answers[g] != ""]
