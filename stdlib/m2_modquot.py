"""Quotients of submodules in the Macaulay2 dialect (``dialect="m2"``): ``quotient(M, N)`` and
``M : N`` for submodules M, N of one free module (N may be the free module itself), the ideal
``{r : r N ⊆ M}``."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.m2_modules import FreeModule
from ..dsl.m2_submodules import Module, columns_of, graded_ring
from ..dsl.registry import command
from ..dsl.values import Ideal
from ..kernel import Poly
from ..kernel import ideals as K
from ..kernel import modules as km
from .m2_trim import minimal as _minimal


def module_quotient(M: Module, N: Module | FreeModule) -> Ideal:
    """M : N, the intersection over N's generators n of M : n (the first entries of the syzygies of
    n and M's generators)."""
    F = N if isinstance(N, FreeModule) else N.ambient
    if M.kind != "image" or (isinstance(N, Module) and N.kind != "image") or M.ambient != F:
        raise MechRuntimeError("M : N takes submodules (images) of one free module, or the free module as N")
    graded_ring(M.ring)
    ring, rank = M.ring, F.rank
    zero = km.ring_zero_exp(ring)
    gens = columns_of(M.matrix)
    others = [{(zero, i): ring.field.one} for i in range(rank)] if isinstance(N, FreeModule) else columns_of(N.matrix)
    parts = []
    for n in others:
        if not n:
            continue
        syz = km.syzygies(ring, rank, [n, *gens])
        parts.append([Poly(ring, {e: c for (e, k), c in s.items() if k == 0}) for s in syz] or [ring.zero()])
    polys = K.intersect(*parts, ring=ring) if len(parts) > 1 else parts[0] if parts else [ring.one()]
    I = Ideal(ring, polys)
    return _minimal(I, sorted((p for p in K.std(polys, ring=ring) if not p.is_zero()),
                              key=lambda p: ring.order.key(p.lm())))


@command("quotient", dialect="m2")
def quotient_modules(M: Module, N: Any) -> Ideal:
    """quotient(M, N) of submodules of one free module: the ideal M : N."""
    if not isinstance(N, (Module, FreeModule)):
        raise MechRuntimeError("quotient(M, N) of a module M takes a module N")
    return module_quotient(M, N)
