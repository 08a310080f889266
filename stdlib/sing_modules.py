"""sing.lib's invariants of complete intersections that are lengths of modules: the Tjurina number
of an ICIS, the length at the origin of its Tjurina module T^1 = O^k / (J(f) O^n + I O^k), where J(f)
is the Jacobian matrix (Greuel–Pfister, *A Singular Introduction*, 7.5; Looijenga, *Isolated singular
points on complete intersections*, 6).

The local length of a module M = R^k / U of finite length at the origin is found with global module
Groebner bases (:mod:`mech.kernel.modules`): M/m^N M is supported at the origin, so its global length
is the local length of M_0 / m^N M_0; by Nakayama's lemma this length stops growing exactly when
m^N M_0 = 0, where it equals the length of M_0."""
from __future__ import annotations

from itertools import combinations_with_replacement

from ..kernel import Poly
from ..kernel import hilbert as H
from ..kernel import local as L
from ..kernel import matrix as KM
from ..kernel.modules import ModuleGB, vector
from ..kernel.order import MonomialOrder
from ..kernel.poly import PolyRing


def _global_length(ring: PolyRing, rank: int, gens: list[list[Poly]], power: int) -> int:
    """The length of R^rank / (gens + m^power R^rank) (finite: supported at the origin)."""
    n = ring.nvars
    monos = []
    for combo in combinations_with_replacement(range(n), power):
        e = [0] * n
        for i in combo:
            e[i] += 1
        monos.append(tuple(e))
    vecs = [vector(col) for col in gens]
    vecs += [{(e, c): ring.field.one} for e in monos for c in range(rank)]
    gb = ModuleGB(ring, rank)
    gb.add([v for v in vecs if v])
    total = 0
    for c in range(rank):
        total += H.vdim([e for e, i in gb.leads if i == c], n)
    return total


def local_length(ring: PolyRing, rank: int, gens: list[list[Poly]]) -> int:
    """The length of (R^rank / <gens>) localized at the origin, for a module known to have finite
    length there (each generator a list of ``rank`` polynomials)."""
    dp = PolyRing(ring.field, ring.names, MonomialOrder.simple("dp", ring.nvars))
    moved = [[Poly(dp, p.terms) for p in col] for col in gens]
    power = 2
    while True:
        a = _global_length(dp, rank, moved, power)
        if a == _global_length(dp, rank, moved, power + 1):
            return a
        power *= 2


def tjurina_ci(gens: list[Poly], ring: PolyRing) -> int:
    """The Tjurina number of the complete intersection of ``gens``: at the origin in a local ring, summed
    over all points in a global one (-1 when the module has infinite length)."""
    k, n = len(gens), ring.nvars
    jac = [[f.diff(j) for j in range(n)] for f in gens]
    if ring.order.is_global:  # Singular's vdim in a global ring: the sum over all points
        cols = [[jac[i][j] for i in range(k)] for j in range(n)]
        cols += [[f if i == c else ring.zero() for i in range(k)] for f in gens for c in range(k)]
        gb = ModuleGB(ring, k)
        gb.add([v for v in (vector(c) for c in cols) if v])
        parts = [H.vdim([e for e, i in gb.leads if i == c], n) for c in range(k)]
        return -1 if any(p < 0 for p in parts) else sum(parts)
    flat = [p for row in jac for p in row]
    minors = [m for m in KM.minors(KM.Matrix(ring, k, n, flat), k) if not m.is_zero()] if k <= n else []
    if L.local_vdim(gens + minors, ring) < 0:
        return -1
    cols = [[jac[i][j] for i in range(k)] for j in range(n)]
    for f in gens:
        for c in range(k):
            cols.append([f if i == c else ring.zero() for i in range(k)])
    return local_length(ring, k, cols)
