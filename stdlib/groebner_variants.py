"""Singular's built-in variants of standard bases: ``facstd`` (the factorizing Groebner algorithm: a
list of ideals whose zero sets cover V(I)), ``mstd`` (a standard basis and minimal generators taken
from it) and ``janet`` (the Janet basis: the reduced Groebner basis completed so that its leading
monomials form the Janet-involutive basis of the leading ideal; Gerdt and Blinkov, *Involutive bases
of polynomial ideals*, 1998)."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Ideal, List
from ..kernel import Poly
from ..kernel.groebner import normal_form
from ..kernel.poly import divides
from .factorize import singular_factorization
from .standard import normalize, standard_basis

Exp = tuple[int, ...]


# ---------------------------------------------------------------- facstd
def _contains(big: list[Poly], small: list[Poly]) -> bool:
    """Whether the ideal of the standard basis ``big`` contains every element of ``small``."""
    return all(normal_form(p, big).is_zero() for p in small)


def _split(gens: list[Poly], nonzero: list[Poly], out: list[list[Poly]]) -> None:
    ring = gens[0].ring
    basis = standard_basis(Ideal(ring, gens))
    if any(g.is_constant() for g in basis):
        return
    for g in basis:
        factors = [f for f, _ in singular_factorization(g)[1]
                   if not any(normalize(f) == normalize(h) for h in nonzero)]
        if not factors:
            return  # g is a product of factors assumed nonzero: no zeros here
        if len(factors) > 1 or normalize(factors[0]) != normalize(g):
            for f in factors:
                _split(basis + [f], nonzero, out)
            return
    out.append(basis)


@command("facstd")
def facstd(I: Ideal, *nonzero: Poly | Ideal) -> List:
    """facstd(I[, J]): the factorizing Groebner algorithm: standard bases of ideals, no one containing
    another, whose zero sets together are V(I); a generator that factors splits the computation, one
    branch per irreducible factor; the factors of the polynomials J are assumed nonzero (left out).

    Example:
      ring r = 0,(x,y),dp;
      facstd(ideal(x2y - xy2, x3 - x2y));
      → [1]:
      →    _[1]=x-y
      → [2]:
      →    _[1]=x
    """
    ring = I.ring
    if not ring.order.is_global:
        raise MechRuntimeError("facstd needs a global ordering (dp, lp, ...), not a local one")
    excluded: list[Poly] = []
    for j in nonzero:
        for p in ([j] if isinstance(j, Poly) else j.nonzero()):
            excluded += [f for f, _ in singular_factorization(p)[1]]
    if not I.nonzero():
        return List([Ideal(ring, [ring.zero()], is_std=True)])
    found: list[list[Poly]] = []
    _split(I.nonzero(), excluded, found)
    kept = [b for i, b in enumerate(found)
            if not any(j != i and _contains(b, c) and not (_contains(c, b) and j > i) for j, c in enumerate(found))]
    kept.reverse()  # Singular lists the branches of the last factor first
    return List([Ideal(ring, b, is_std=True) for b in kept]) if kept else List([Ideal(ring, [ring.one()], is_std=True)])


# ---------------------------------------------------------------- mstd
@command("mstd")
def mstd(I: Ideal) -> List:
    """mstd(I): the list of a standard basis of I and of generators of I chosen among its elements,
    by increasing degree, each not in the ideal of those before (minimal generators for a homogeneous I).

    Example:
      ring r = 0,(x,y),dp;
      mstd(ideal(x2, xy, x2+xy, y3));
      → [1]:
      →    _[1]=xy
      →    _[2]=x2
      →    _[3]=y3
      → [2]:
      →    _[1]=xy
      →    _[2]=x2
      →    _[3]=y3
    """
    ring = I.ring
    if not ring.order.is_global:
        raise MechRuntimeError("mstd needs a global ordering (dp, lp, ...), not a local one")
    basis = standard_basis(I)
    kept: list[Poly] = []
    for g in sorted(basis, key=lambda p: (p.total_degree(), ring.order.key(p.lm()))):
        if not kept or not normal_form(g, standard_basis(Ideal(ring, kept))).is_zero():
            kept.append(g)
    kept.sort(key=lambda p: ring.order.key(p.lm()))
    zero = [ring.zero()]
    return List([Ideal(ring, basis or zero, is_std=True), Ideal(ring, kept or zero)])


# ---------------------------------------------------------------- janet
def _multiplicative(u: Exp, monos: list[Exp]) -> list[bool]:
    """Janet's multiplicative variables of u in the set monos: x_i is multiplicative if u has the largest
    degree in x_i among the elements agreeing with u in x_1..x_{i-1}."""
    out = []
    for i in range(len(u)):
        top = max(v[i] for v in monos if v[:i] == u[:i])
        out.append(u[i] == top)
    return out


def _janet_divisible(w: Exp, monos: list[Exp], mult: dict[Exp, list[bool]]) -> bool:
    return any(divides(v, w) and all(mult[v][i] or w[i] == v[i] for i in range(len(w))) for v in monos)


def janet_completion(monos: list[Exp]) -> list[Exp]:
    """The Janet basis of the monomial ideal generated by the (minimal) monomials ``monos``: the
    non-multiplicative prolongations not Janet-divisible by the set are added, the smallest (by degree,
    then lexicographically) first."""
    basis = list(monos)
    while True:
        mult = {u: _multiplicative(u, basis) for u in basis}
        missing = [w for u in basis for i, m in enumerate(mult[u]) if not m
                   for w in [tuple(k + (j == i) for j, k in enumerate(u))]
                   if not _janet_divisible(w, basis, mult)]
        if not missing:
            return basis
        basis.append(min(missing, key=lambda w: (sum(w), tuple(-k for k in w))))


@command("janet")
def janet(ctx, I: Ideal, *opts: Any) -> Ideal:
    """janet(I): the Janet basis of I (printing its length first): the reduced Groebner basis completed
    by the elements m - NF(m) for the monomials m that complete its leading monomials to their Janet
    basis (the variables in the ring's order), sorted by increasing leading monomial.

    Example:
      ring r = 0,(x,y),dp;
      janet(ideal(x2, y2));
      → Length of Janet basis: 3
      → _[1]=y2
      → _[2]=x2
      → _[3]=xy2
    """
    ring = I.ring
    if not ring.order.is_global:
        raise MechRuntimeError("janet needs a global ordering (dp, lp, ...), not a local one")
    basis = standard_basis(I)
    leads = {g.lm(): g for g in basis if not g.is_zero()}
    out: list[Poly] = []
    for m in janet_completion(list(leads)):
        if m in leads:
            out.append(leads[m])
        else:
            mono = Poly(ring, {m: ring.field.one})
            out.append(normalize(mono - normal_form(mono, basis)))
    out.sort(key=lambda p: ring.order.key(p.lm()))
    ctx.write(f"Length of Janet basis: {len(out)}\n")
    return Ideal(ring, out or [ring.zero()])
