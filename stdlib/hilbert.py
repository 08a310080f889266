"""Hilbert series and what follows from them, computed from the leading monomials of a standard
basis: Singular's ``hilb``, ``degree``, ``mult``, ``vdim`` and ``kbase`` (``dim`` is in
:mod:`mech.stdlib.standard`).  Like Singular they warn ``// ** I is no standard basis`` and use the
leading monomials of the generators as they are when the argument is not marked as one."""
from __future__ import annotations

from ..dsl.errors import MechRuntimeError
from ..dsl.qrings import with_quotient
from ..dsl.values import Ideal, IntVec
from ..kernel import hilbert as H
from ..dsl.registry import command


def _leading(ctx, I: Ideal) -> list[tuple[int, ...]]:
    ctx.assume_std(I, 0)
    return [g.lm() for g in with_quotient(I.nonzero(), I.ring)]


def _local(I: Ideal) -> bool:
    return not I.ring.order.is_global


@command("vdim")
def vdim(ctx, I: Ideal) -> int:
    """vdim(I): the vector space dimension of R/I for a standard basis I (-1 if infinite).

    Example:
      ring r = 0,(x,y),dp;
      vdim(std(ideal(x2, y3)));
      → 6
      vdim(std(ideal(x2)));
      → -1
    """
    return H.vdim(_leading(ctx, I), I.ring.nvars)


@command("mult")
def mult(ctx, I: Ideal) -> int:
    """mult(I): the degree (global ordering) or multiplicity (local ordering) of R/I for a
    standard basis I.

    Example:
      ring r = 0,(x,y,z),dp;
      mult(std(ideal(x2+y2+z2)));
      → 2
      ring s = 0,(x,y),ds;
      mult(std(ideal(x2-y3)));
      → 2
    """
    return H.mult(_leading(ctx, I), I.ring.nvars)


@command("degree")
def degree(ctx, I: Ideal) -> None:
    """degree(I): prints the dimension and the degree (or, for a local ordering, the
    multiplicity) of R/I for a standard basis I, as Singular's // dimension ... lines.

    Example:
      ring r = 0,(x,y,z),dp;
      degree(std(ideal(xy, xz)));
      → // dimension (proj.)  = 1
      → // degree (proj.)   = 1
    """
    info = H.degree(_leading(ctx, I), I.ring.nvars, _local(I))
    ctx.write("\n".join(info.lines()) + "\n")


@command("hilb")
def hilb(ctx, I: Ideal, which: int = 0) -> IntVec | None:
    """hilb(I): prints the first and second Hilbert series numerators of R/I (// c t^k lines) and
    the degree lines, for a standard basis I; hilb(I, 1) and hilb(I, 2) return the coefficients of
    the first or second numerator as an intvec (with a trailing 0).

    Example:
      ring r = 0,(x,y),dp;
      ideal I = std(ideal(x2, xy));
      hilb(I);
      → //         1 t^0
      → //        -2 t^2
      → //         1 t^3
      →
      → //         1 t^0
      → //         1 t^1
      → //        -1 t^2
      → // dimension (proj.)  = 0
      → // degree (proj.)   = 1
      hilb(I, 1);
      → 1,0,-2,1,0
    """
    lms = _leading(ctx, I)
    n = I.ring.nvars
    if which == 0:
        ctx.write("\n".join(H.hilb_lines(lms, n, _local(I))) + "\n")
        return None
    if which not in (1, 2):
        raise MechRuntimeError(f"hilb(I, {which}): the second argument must be 1 or 2")
    q, p, _ = H.hilbert_numerators(lms, n)
    return IntVec((q if which == 1 else p) + [0])


@command("kbase")
def kbase(ctx, I: Ideal, k: int | None = None) -> Ideal:
    """kbase(I) or kbase(I, k): the monomials not in the leading ideal of the standard basis I
    (a vector space basis of R/I; 0 if R/I is infinite-dimensional), or those of degree k.

    Example:
      ring r = 0,(x,y),dp;
      ideal I = std(ideal(x2, y2));
      kbase(I);
      → _[1]=xy
      → _[2]=y
      → _[3]=x
      → _[4]=1
      kbase(I, 1);
      → _[1]=y
      → _[2]=x
    """
    ring = I.ring
    mons = H.kbase(_leading(ctx, I), ring.nvars, k)
    return Ideal(ring, [ring.monomial(e) for e in mons])
