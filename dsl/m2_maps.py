"""Ring maps of the Macaulay2 dialect applied to values (``f x``, ``f I``, ``f {a, b}``): the
substitution of the images for the source's variables, in normal form in the target ring."""
from __future__ import annotations

from typing import Any

from ..kernel import Poly
from .errors import MechRuntimeError, MechTypeError
from .m2_modules import FreeModule
from .m2_rings import TEXT, M2Ring, normal
from .m2_values import RingMap
from .values import ExprList, Ideal, List, Matrix, Number, typeof


def apply_map(f: RingMap, v: Any) -> Any:
    """The image of a polynomial, ideal, matrix, free module or list under the ring map ``f``."""
    from .maps import map_value
    if not isinstance(f.target, M2Ring):
        raise MechRuntimeError(f"mech does not compute in {TEXT['value'](f.target)} (a fraction field)")
    if isinstance(v, (List, ExprList)):
        return type(v)([apply_map(f, x) for x in v.items])
    if type(v) is int:
        return normal(f.target.poly.const(f.target.poly.field(v)))
    if isinstance(v, FreeModule) and v.ring is f.source:  # f M, f ** M: the free module over the target
        return FreeModule(f.target, tuple(f.degree_map((d,))[0] if f.degree_map else d for d in v.degrees))
    if not isinstance(v, (Poly, Ideal, Matrix, Number)) or getattr(v.ring, "owner", None) is not f.source:
        raise MechTypeError(f"the map applies to elements of its source ring, not to a {typeof(v)}")
    out = map_value(v, f.images, f.target.poly)
    if isinstance(out, Poly):
        return normal(out)
    if isinstance(out, Ideal):
        return Ideal(out.ring, [normal(g) for g in out.gens])
    if isinstance(out, Matrix):
        return Matrix(out.ring, out.nrows, out.ncols, [normal(g) for g in out.entries])
    return out
