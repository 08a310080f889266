"""Singular's built-in ``fglmquot``: the ideal quotient of a zero-dimensional reduced standard basis by
a reduced polynomial, as a reduced standard basis (Singular computes it by linear algebra in the
quotient ring, as FGLM; mech as the ideal quotient, the same ideal and reduced basis)."""
from __future__ import annotations

from ..dsl.errors import MechRuntimeError
from ..dsl.printing import poly_str
from ..dsl.registry import command
from ..dsl.values import Ideal
from ..kernel import Poly
from ..kernel.dimension import krull_dim
from ..kernel.groebner import normal_form
from ..kernel.ideals import quotient
from .standard import standard_basis


@command("fglmquot")
def fglmquot(ctx, I: Ideal, p: Poly) -> Ideal:
    """fglmquot(I, p): the reduced standard basis of I : p, for a reduced standard basis I of a
    zero-dimensional ideal (global ordering) and a polynomial p in normal form with respect to I.

    Example:
      ring r = 0,(x,y),lp;
      fglmquot(std(ideal(x2, y2)), x);
      → _[1]=y2
      → _[2]=x
    """
    ring = I.ring
    if not ring.order.is_global:
        raise MechRuntimeError("fglmquot needs a global ordering (dp, lp, ...), not a local one")
    ctx.assume_std(I, 0)
    basis = I.nonzero()
    if krull_dim([g.lm() for g in basis], ring.nvars) != 0:
        raise MechRuntimeError("fglmquot: the ideal must be zero-dimensional")
    if normal_form(p, basis) != p:
        raise MechRuntimeError(f"The poly {poly_str(p)} has to be reduced")
    if p.is_zero():
        return Ideal(ring, [ring.one()], is_std=True)
    found = quotient(basis, [p], ring=ring)
    return Ideal(ring, standard_basis(Ideal(ring, found)), is_std=True)
