"""Procedures of Singular's algebra.lib on maps of affine algebras: ``alg_kernel``,
``is_injective``, ``is_surjective``, ``is_bijective`` (for polynomial rings with global
orderings)."""
from __future__ import annotations

from ..dsl.errors import MechRuntimeError
from ..dsl.printing import is_short, poly_str, set_short
from ..dsl.qrings import quotient_of
from ..dsl.registry import command
from ..dsl.values import Map, Ring
from ..kernel import MonomialOrder, Poly, PolyRing
from ..kernel.ideals import _lift, _prefixed
from ..kernel.groebner import normal_form
from ..kernel.engines import standard_basis
from .idealops import _lift_front, preimage_polys
from .standard import normalize

LIB = "algebra.lib"


def _check(ctx, phi: Map, pr: Ring) -> list[Poly]:
    target = ctx.basering().poly
    for ring in (target, pr.poly):
        if not ring.order.is_global or quotient_of(ring) is not None:
            raise MechRuntimeError("algebra.lib's map tests for local orderings or quotient rings are not supported")
    n = pr.poly.nvars
    return (list(phi.images) + [target.zero()] * n)[:n]


def _kernel(ctx, phi: Map, pr: Ring) -> list[Poly]:
    images = _check(ctx, phi, pr)
    return preimage_polys(pr.poly, ctx.basering().poly, images, [])


@command("alg_kernel", lib=LIB)
def alg_kernel(ctx, phi: Map, pr: Ring) -> str:
    """alg_kernel(phi, pr): the kernel of the map phi from the ring pr to the basering, as a string
    (the generators in long form, as algebra.lib returns them).

    Example:
      LIB "algebra.lib";
      ring A = 0,(x,y),dp;
      ring B = 0,(s,t),dp;
      map psi = A, s2, s3;
      alg_kernel(psi, A);
      → x^3-y^2
    """
    ker = _kernel(ctx, phi, pr)
    if not ker:
        return "0"
    src = pr.poly  # algebra.lib prints the kernel from a dp ring
    ring = PolyRing(src.field, src.names, MonomialOrder.simple("dp", src.nvars))
    ker = [Poly(ring, normalize(p).terms) for p in standard_basis([Poly(ring, p.terms) for p in ker], ring)]
    was = is_short(ring)
    set_short(ring, False)
    try:
        return ",".join(poly_str(p) for p in ker)
    finally:
        set_short(ring, was)


@command("is_injective", lib=LIB)
def is_injective(ctx, phi: Map, pr: Ring) -> int:
    """is_injective(phi, pr): 1 if the map phi from the ring pr to the basering is injective, else 0.

    Example:
      LIB "algebra.lib";
      ring A = 0,(x,y),dp;
      ring B = 0,(s,t),dp;
      map psi = A, s2, s3;
      is_injective(psi, A);
      → 0
    """
    return int(not _kernel(ctx, phi, pr))


@command("is_surjective", lib=LIB)
def is_surjective(ctx, phi: Map, pr: Ring) -> int:
    """is_surjective(phi, pr): 1 if the map phi from the ring pr to the basering is surjective (every
    variable of the basering is a polynomial in the images), else 0.

    Example:
      LIB "algebra.lib";
      ring A = 0,(x,y),dp;
      ring B = 0,(s,t),dp;
      map psi = A, s2, s3;
      is_surjective(psi, A);
      → 0
    """
    images = _check(ctx, phi, pr)
    target, source = ctx.basering().poly, pr.poly
    k = target.nvars
    big = _prefixed(source, list(target.names))  # the target's variables first, eliminated
    gens = [_lift(source.gen(i), big, k) - _lift_front(images[i], big, source.nvars)
            for i in range(source.nvars)]
    basis = standard_basis(gens, big)
    for j in range(k):
        nf = normal_form(_lift_front(target.gen(j), big, source.nvars), basis)
        if any(any(e[:k]) for e in nf.terms):
            return 0
    return 1


@command("is_bijective", lib=LIB)
def is_bijective(ctx, phi: Map, pr: Ring) -> int:
    """is_bijective(phi, pr): 1 if the map phi from the ring pr to the basering is bijective, else 0
    (with algebra.lib's comment which property fails).

    Example:
      LIB "algebra.lib";
      ring A = 0,(x,y),dp;
      ring B = 0,(s),dp;
      map psi = A, s, s2;
      is_bijective(psi, A);
      → // map not injective
      → 0
    """
    if not is_injective(ctx, phi, pr):
        ctx.write("// map not injective\n")
        return 0
    if not is_surjective(ctx, phi, pr):
        ctx.write("// map injective, but not surjective\n")
        return 0
    return 1
