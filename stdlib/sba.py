"""Singular's ``sba(I[, variant, ordering])``: a standard basis computed by a signature-based algorithm.
The result is a standard basis of I, so mech computes it with its own engines (``std``); the integer
arguments choose Singular's variant of the signature algorithm and do not change the ideal (Singular's
generators can come in another order for some variants)."""
from __future__ import annotations

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Ideal
from .standard import standard_basis


@command("sba")
def sba(I: Ideal, *variant: int) -> Ideal:
    """sba(I[, a, b]): a standard basis of I (the integers choose the signature-based algorithm's
    variant in Singular; mech's standard basis is the same ideal).

    Example:
      ring r = 32003,(x,y,z),dp;
      sba(ideal(x2-y, xy-z, z3-x));
      → _[1]=y2-xz
      → _[2]=xy-z
      → _[3]=x2-y
      → _[4]=z3-x
    """
    if len(variant) > 2 or not all(isinstance(v, int) for v in variant):
        raise MechRuntimeError("sba(I[, int, int]): wrong arguments")
    return Ideal(I.ring, standard_basis(I), is_std=True)
