"""Further argument forms of Singular built-ins that its manual shows: the first Hilbert series of a
standard basis for a weighted degree ``hilb(I, 1, w)``, and the first minors of a matrix reduced modulo
an ideal ``minor(M, k, I, n[, algorithm])`` (Laplace's order: the row sets, for each the column sets, in
colexicographic order)."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, Matrix
from ..kernel import hilbert as H
from ..kernel import matrix as KM
from .standard import _reduce

Series = list[int]


def weighted_numerator(gens: list[tuple[int, ...]], w: list[int]) -> Series:
    """The numerator Q(t) of the Hilbert series of K[x]/(gens) for deg x_i = w_i, by the recursion
    Q(M + (m)) = Q(M) - t^deg(m) Q(M : m)."""
    if not gens:
        return [1]
    *rest, m = gens
    colon = H.minimal_monomials([tuple(max(a - b, 0) for a, b in zip(g, m)) for g in rest]) if rest else []
    if any(sum(g) == 0 for g in colon):
        colon_q: Series = [0]
    else:
        colon_q = weighted_numerator(colon, w)
    d = sum(a * b for a, b in zip(m, w))
    out = list(weighted_numerator(rest, w)) + [0] * (d + len(colon_q))
    for i, c in enumerate(colon_q):
        out[d + i] -= c
    while len(out) > 1 and out[-1] == 0:
        out.pop()
    return out


@command("hilb")
def hilb_weighted(ctx, I: Ideal, which: int, w: IntVec) -> IntVec:
    """hilb(I, 1, w): the coefficients of the first Hilbert series numerator of R/I (I a standard basis)
    for the weights w of the variables, with a trailing 0.

    Example:
      ring r = 0,(x,y),dp;
      hilb(std(ideal(x2, y)), 1, intvec(1,3));
      → 1,0,-1,-1,0,1,0
    """
    if which != 1:
        raise MechRuntimeError("hilb(I, n, w): only the first Hilbert series (n = 1) is supported with weights")
    ctx.assume_std(I, 0)
    weights = list(w.values)
    if len(weights) != I.ring.nvars or any(v <= 0 for v in weights):
        raise MechRuntimeError("hilb(I, 1, w): w must give a positive weight to each variable")
    lms = [g.lm() for g in I.nonzero()]
    if any(sum(e) == 0 for e in lms):
        return IntVec([0, 0])
    return IntVec(weighted_numerator(H.minimal_monomials(lms), weights) + [0])


@command("minor")
def minor_mod(ctx, M: Matrix, k: int, I: Ideal, n: int, algorithm: str = "Laplace") -> Ideal:
    """minor(M, k, I, n[, "Laplace"|"Bareiss"]): the first n nonzero k x k minors of M reduced modulo the
    standard basis I (n < 0: the first -n minors, zero or not), the row sets and for each the column
    sets taken in colexicographic order.

    Example:
      ring r = 0,(a,b,c,d,e,f),dp;
      matrix m[2][3] = a,b,c,d,e,f;
      minor(m, 2, std(ideal(a)), 2);
      → _[1]=-bd
      → _[2]=-cd
    """
    if algorithm not in ("Laplace", "Bareiss"):
        raise MechRuntimeError(f'minor: unknown algorithm "{algorithm}" (Laplace or Bareiss)')
    rows = [[M.get(i, j) for j in range(1, M.ncols + 1)] for i in range(1, M.nrows + 1)]
    ring = M.ring
    memo: dict[Any, Any] = {}
    out = []
    want = abs(n)
    for rs in KM._colex(M.nrows, k):
        for cs in KM._colex(M.ncols, k):
            if len(out) >= want:
                break
            p = _reduce(ctx, KM._laplace(rows, list(rs), list(cs), memo), I)
            if n < 0 or not p.is_zero():
                out.append(p)
    return Ideal(ring, out or [ring.zero()])
