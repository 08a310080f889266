"""The operators on vectors and modules (Singular's rules): ``v + w``, ``v - w`` (a poly p counts as
p*gen(1)), ``p * v``, ``v * p``, ``v / c`` (each entry divided), ``-v``, ``v == w``; ``M + N`` joins
the generators, ``M * p`` and ``p * M`` multiply each generator, ``A * v`` and ``A * M`` multiply by a
matrix (a matrix, as Singular)."""
from __future__ import annotations

from typing import Any, Optional

from ..kernel import Poly, PolyRing
from .errors import MechTypeError
from .values import Ideal, Matrix, Number, to_poly, typeof
from .values_modules import Module, Vector, module_matrix, to_module, to_vector


def _bad(op: str, a: Any, b: Any) -> MechTypeError:
    return MechTypeError(f"operator {op} is not defined for {typeof(a)} and {typeof(b)}")


def _is_scalar(v: Any) -> bool:
    return isinstance(v, (int, Number, Poly)) and not isinstance(v, bool)


def _add(v: Vector, w: Vector, sign: int) -> Vector:
    n = max(v.nrows, w.nrows)
    return Vector(v.ring, [a + b if sign > 0 else a - b for a, b in zip(v.padded(n), w.padded(n))])


def module_binary(op: str, a: Any, b: Any, ring: Optional[PolyRing]) -> Any:
    """``a op b`` where a or b is a vector or a module."""
    ring = getattr(a, "ring", None) or getattr(b, "ring", None) or ring
    if op == "*" and isinstance(a, Ideal) and isinstance(b, Vector):  # I*v: the module of the g*v
        return Module(ring, [Vector(ring, [g * x for x in b.entries]) for g in a.gens])
    if op == "*" and isinstance(a, Vector) and isinstance(b, Ideal):
        return module_binary(op, b, a, ring)
    if op in ("+", "-") and isinstance(a, Matrix):  # as matrices (Singular; M + A is a module sum)
        from .ops import binary
        a2, b2 = (module_matrix(x) if isinstance(x, (Module, Vector)) else x for x in (a, b))
        return binary(op, a2, b2, ring, lambda _m: None)
    if op == "*" and isinstance(a, Ideal) and isinstance(b, Module):  # I*M: f*m for f in I, m in M
        return Module(ring, [Vector(ring, [f * x for x in m.entries]) for f in a.gens for m in b.gens], b.rank)
    if op == "*" and isinstance(a, Module) and isinstance(b, Ideal):  # M*I: m*f for m in M, f in I
        return Module(ring, [Vector(ring, [x * f for x in m.entries]) for m in a.gens for f in b.gens], a.rank)
    if isinstance(a, Module) or isinstance(b, Module):
        if op == "+" and all(isinstance(x, (Module, Vector, Ideal, Matrix)) for x in (a, b)):
            return _sum(to_module(a, ring), to_module(b, ring))
        if op == "*" and isinstance(a, Module) and _is_scalar(b):
            p = to_poly(b, ring)
            return Module(ring, [Vector(ring, [x * p for x in g.entries]) for g in a.gens], a.rank)
        if op == "*" and isinstance(b, Module) and _is_scalar(a):
            return module_binary("*", b, a, ring)
        if op == "*" and isinstance(a, Matrix) and isinstance(b, Module):
            from .ops import binary
            return binary("*", a, module_matrix(b), ring, lambda _m: None)
        raise _bad(op, a, b)
    if op in ("+", "-") and (isinstance(a, Vector) or _is_scalar(a)) and (isinstance(b, Vector) or _is_scalar(b)):
        return _add(to_vector(a, ring), to_vector(b, ring), 1 if op == "+" else -1)
    if op == "*" and _is_scalar(a) and isinstance(b, Vector):
        p = to_poly(a, ring)
        return Vector(ring, [p * x for x in b.entries])
    if op == "*" and isinstance(a, Vector) and _is_scalar(b):
        return module_binary("*", b, a, ring)
    if op in ("/", "div") and isinstance(a, Vector) and _is_scalar(b):
        from .ops import poly_quotient
        p = to_poly(b, ring)
        return Vector(ring, [poly_quotient(x, p) for x in a.entries])
    if op == "*" and isinstance(a, Matrix) and isinstance(b, Vector):
        from .ops import binary
        return binary("*", a, module_matrix(Module(ring, [b], a.ncols)), ring, lambda _m: None)
    raise _bad(op, a, b)


def _sum(a: Module, b: Module) -> Module:
    """M + N: the generators of both, without zeros and repeated generators (as Singular)."""
    gens: list[Vector] = []
    for g in a.gens + b.gens:
        if not g.is_zero() and g not in gens:
            gens.append(g)
    return Module(a.ring, gens, max(a.rank, b.rank))


def module_negate(a: Vector | Module) -> Vector | Module:
    if isinstance(a, Vector):
        return Vector(a.ring, [-x for x in a.entries])
    return Module(a.ring, [Vector(a.ring, [-x for x in g.entries]) for g in a.gens], a.rank)
