"""Submodules of quotients of free modules in the Macaulay2 dialect (``dialect="m2"``): the
saturation ``saturate(N, J)`` of a submodule (of an image, a subquotient or the submodule an element
``v`` generates, ``saturate 0_M``), the quotient ``N : J`` (``quotient(N, J)``) by an ideal or element J, ``quotient(f, g)`` of matrices (``f // g``), ``generator M`` of a cyclic submodule, the annihilator of a
subquotient, ``ring`` and ``ambient``; the values are :mod:`mech.dsl.m2_subquotients`'s."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.m2_modules import FreeModule
from ..dsl.m2_modules import Map
from ..dsl.m2_submodules import Module, columns_of, divide, graded_ring
from ..dsl.m2_subquotients import ModuleElement, Subquotient, make, parts, spans_equal
from ..dsl.m2_rings import exact_over_zz, integers
from ..dsl.m2_vectors import Vector
from ..dsl.registry import command
from ..dsl.values import Ideal, Matrix
from ..kernel import Poly
from ..kernel import ideals as K
from ..kernel import modules as km
from .m2_trim import minimal


def _trimmed(ring: Any, polys: list[Poly]) -> list[Poly]:
    """A Gröbner basis on fewer generators, as Macaulay2 trims (:func:`.m2_trim.minimal`)."""
    basis = sorted((p for p in K.std(polys, ring=ring) if not p.is_zero()), key=lambda p: ring.order.key(p.lm()))
    return list(minimal(Ideal(ring, basis), basis).nonzero())


def colon(ring: Any, rank: int, N: list[km.Vector], J: list[Poly]) -> list[km.Vector]:
    """``N : J = {f in R^rank : g f in N for every g in J}``: the first ``rank`` coordinates of the
    syzygies of ``(g_1 e_j, ..., g_k e_j)`` (j < rank) and N placed in each of the k blocks of R^(rank k)."""
    k = len(J)
    cols = [km.vector([J[i] if b == j else ring.zero() for i in range(k) for b in range(rank)])
            for j in range(rank)]
    for i in range(k):
        cols += [{(e, c + i * rank): v for (e, c), v in n.items()} for n in N]
    syz = km.syzygies(ring, rank * k, cols)
    return [f for f in ({(e, c): v for (e, c), v in s.items() if c < rank} for s in syz) if f]


def _saturated(ring: Any, rank: int, N: list[km.Vector], J: list[Poly]) -> list[km.Vector]:
    """``N : J^infinity``: quotients by J until they stop growing; minimal generators when homogeneous."""
    if rank == 1:  # an ideal
        polys = K.saturate([km.entries(n, ring, 1)[0] for n in N], J, ring=ring)[0]
        return [km.vector([g]) for g in _trimmed(ring, polys)]
    while True:
        bigger = colon(ring, rank, N, J)
        if spans_equal(ring, rank, N, bigger):
            break
        N = bigger
    if all(km.is_homogeneous(v, [0] * rank) for v in N):
        return km.minimal_generators(ring, rank, N, [0] * rank)
    return N


@command("saturate", dialect="m2")
def saturate_module(N: Module | Subquotient | ModuleElement, J: Ideal | Poly | None = None) -> Any:
    """saturate(N, J): the saturation N : J^infinity of a submodule N of a module F/R (an image,
    a subquotient, or the submodule an element generates); without J the ideal of the variables."""
    if isinstance(N, ModuleElement):
        F, _, rels = parts(N.module)
        gens = [km.vector(list(N.entries))]
    else:
        F, gens, rels = parts(N)
        if isinstance(N, Module) and N.kind != "image":
            return N  # a cokernel is all of F/R
    ring = graded_ring(F.ring).poly
    if J is None:
        J = Ideal(ring, [ring.gen(i) for i in range(ring.nvars)])
    polys = J.nonzero() if isinstance(J, Ideal) else [J]
    sat = _saturated(ring, F.rank, [g for g in gens + rels if g], list(polys))
    return make(F, _without_relations(ring, F.rank, sat, rels), rels)


def _without_relations(ring: Any, rank: int, gens: list[km.Vector], rels: list[km.Vector]) -> list[km.Vector]:
    if not rels:
        return gens
    spanned = km.ModuleGB(ring, rank)
    spanned.add(rels)
    return [g for g in gens if not spanned.contains(g)]


def module_colon(N: Module | Subquotient, J: Ideal | Poly) -> Any:
    """``N : J`` for a submodule N of F/R (an image or a subquotient): the elements f of F/R with
    J f in N, a submodule of F/R."""
    F, gens, rels = parts(N)
    ring = graded_ring(F.ring).poly
    polys = [p for p in (J.nonzero() if isinstance(J, Ideal) else [J]) if not p.is_zero()]
    if not polys:
        return make(F, parts(F)[1], rels)
    span = [g for g in gens + rels if g]
    if F.rank == 1:
        found = [km.vector([g]) for g in _trimmed(ring, K.quotient([km.entries(n, ring, 1)[0] for n in span], polys,
                                                                ring=ring))]
    else:
        found = colon(ring, F.rank, span, polys)
        if all(km.is_homogeneous(v, [0] * F.rank) for v in found):
            found = km.minimal_generators(ring, F.rank, found, [0] * F.rank)
    return make(F, _without_relations(ring, F.rank, found, rels), rels)


@command("quotient", dialect="m2")
def quotient_module_ideal(N: Module | Subquotient, J: Ideal | Poly) -> Any:
    """quotient(N, J): the submodule N : J of elements f with J f in N."""
    return module_colon(N, J)


@command("quotient", dialect="m2")
def quotient_matrices(f: Matrix, g: Matrix) -> Map:
    """quotient(f, g): f // g, a matrix h with g * h == f (f's columns in the image of g)."""
    return divide(f, g)


@command("generator", dialect="m2")
@exact_over_zz
def generator_module(M: Module) -> Vector:
    """generator M: the one generator of a cyclic submodule (image f) of a free module: of its
    minimal generators, or over ZZ itself of the Hermite normal form of its lattice."""
    if M.kind != "image":
        raise MechRuntimeError("generator M takes a submodule (image f) of a free module")
    F = M.matrix.target
    if F.ring is integers():
        from flint import fmpz_mat
        rows = [[int(M.matrix.get(i + 1, j + 1).lc().p) if not M.matrix.get(i + 1, j + 1).is_zero() else 0
                 for i in range(F.rank)] for j in range(M.matrix.ncols)]
        basis = [r for r in (fmpz_mat(rows).hnf().tolist() if rows else []) if any(r)]
        gens = [[F.ring.poly.one() * int(x) for x in r] for r in basis]
    else:
        ring, cols = graded_ring(F.ring).poly, columns_of(M.matrix)
        degrees = list(F.degrees) if all(km.is_homogeneous(v, F.degrees) for v in cols if v) else None
        gens = [km.entries(v, ring, F.rank) for v in km.minimal_generators(ring, F.rank, cols, degrees)]
    if len(gens) != 1:
        raise MechRuntimeError("generator M: the module is not generated by one element")
    return Vector(F, gens[0])


@command("annihilator", dialect="m2")
@command("ann", dialect="m2")
def annihilator_subquotient(M: Subquotient) -> Ideal:
    """ann M: the ring elements r with r M = 0 (r g in the relations for every generator g)."""
    F, gens, rels = parts(M)
    ring = graded_ring(F.ring).poly
    from ..kernel.ideals import intersect
    zero_parts = []
    for g in gens:
        syz = km.syzygies(ring, F.rank, [g, *rels])
        zero_parts.append([Poly(ring, {e: c for (e, k), c in s.items() if k == 0}) for s in syz] or [ring.zero()])
    polys = intersect(*zero_parts, ring=ring) if zero_parts else [ring.one()]
    gens_ = [p for p in polys if not p.is_zero()]
    return Ideal(ring, gens_, is_std=not gens_)


@command("ring", dialect="m2")
def ring_of_subquotient(M: Subquotient | ModuleElement) -> Any:
    """ring M: the ring of a subquotient module or of a module's element."""
    return M.ring.owner


@command("ambient", dialect="m2")
def ambient_subquotient(M: Subquotient) -> FreeModule:
    """ambient M: the free module of which M is a subquotient."""
    return M.ambient


