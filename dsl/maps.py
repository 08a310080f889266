"""Ring maps: applying a map ``phi(I)`` and the image of any value under a substitution of the
variables (also what imap and fetch use)."""
from __future__ import annotations

from typing import Any, Callable, Optional

from ..kernel import Poly
from . import ast as A
from .errors import MechRuntimeError, MechTypeError
from .values_modules import Module, Vector
from .values import ExprList, Ideal, List, Map, Matrix, Number


class Maps:
    """Applying ring maps (part of the interpreter)."""

    def apply_map(self, m: Map, arg_nodes: list[A.Expr]) -> Any:
        if len(arg_nodes) != 1:
            raise MechTypeError("a map is applied to one argument: phi(I)")
        node = arg_nodes[0]
        value = None
        if isinstance(node, A.Name):
            var = self.lookup_in_ring(m.source, node.id)
            if var is not None:
                value = var.value
        if value is None:
            saved = self.ring
            self.ring = m.source
            try:
                value = self.eval(node)
            finally:
                self.ring = saved
        nvars = len(m.source.names)
        images = list(m.images[:nvars]) + [m.ring.zero()] * (nvars - len(m.images))
        from ..kernel.maps import map_polys
        return map_value(value, images, m.ring, lambda polys, source: map_polys(polys, images, m.ring, source))


def map_value(v: Any, images: tuple | list, target: Any, how: Optional[Callable] = None) -> Any:
    """The image of a value under the substitution x_i -> images[i] into ``target``, coefficients
    converted by :func:`mech.kernel.maps.coefficient_map` (parameters by name, as imap does);
    ``how(polys, source)`` replaces the substitution (e.g. :func:`mech.kernel.maps.map_polys`)."""
    if how is None:
        def how(polys: list, source: Any) -> list:
            from ..kernel.maps import coefficient_map
            coeff = coefficient_map(source, target)
            out = []
            for p in polys:
                acc = target.zero()
                for e, c in p.terms.items():
                    t = coeff(c)
                    for i, k in enumerate(e):
                        if k:
                            t = t * images[i] ** k
                    acc = acc + t
                out.append(acc)
            return out

    def each(polys: Any) -> list:
        polys = list(polys)
        return how(polys, polys[0].ring) if polys else []
    if isinstance(v, Poly):
        return each([v])[0]
    if isinstance(v, Number):
        p = each([v.to_poly()])[0]
        if not p.is_constant():
            raise MechRuntimeError("the image of a number is not a number")
        return Number(target, p.lc() if p.terms else target.field.zero)
    if isinstance(v, Ideal):
        return Ideal(target, each(v.gens))
    if isinstance(v, Matrix):
        return Matrix(target, v.nrows, v.ncols, each(v.entries))
    if isinstance(v, Map):
        return Map(v.source, target, tuple(each(v.images)))
    if isinstance(v, Vector):
        return Vector(target, each(v.entries))
    if isinstance(v, Module):
        return Module(target, [Vector(target, each(g.entries)) for g in v.gens], v.rank)
    if isinstance(v, List):
        return List([map_value(x, images, target, how) for x in v.items])
    if isinstance(v, ExprList):
        return ExprList([map_value(x, images, target, how) for x in v.items])
    return v
