"""sing.lib's regular elements and sequences on R^n / id for a submodule id (an ideal for n = 1):
``is_reg`` of a module, ``is_regs`` (a regular sequence) and ``is_active`` (f lowers the dimension).

f is regular on M = R^n/id when id : f = id.  The quotient comes from syzygies over the polynomial ring
(:mod:`mech.stdlib.module_ops`); localization is flat, so for a local ordering (the localization at
the origin) a vector g lies in id_loc exactly when the ideal id :_R g is not inside the maximal ideal
of the origin, i.e. when its standard basis for the ring's ordering holds a unit (leading monomial 1);
for a global ordering that standard basis is {1}."""
from __future__ import annotations

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Ideal
from ..dsl.values_modules import Module, Vector
from ..kernel import Poly
from . import module_ops
from .sing_lib import LIB, _std_dim, is_reg


def _contains(M: Module, g: Vector) -> bool:
    """g in M (M localized at the origin for a local ordering)."""
    colon = module_ops.quotient(M, Module(M.ring, [g], M.rank))
    zero = M.ring.zero_exp
    return any(not p.is_zero() and p.lm() == zero for p in colon.gens)


@command("is_reg", lib=LIB)
def is_reg_module(f: Poly, M: Module) -> int:
    """is_reg(f, M): 1 if multiplication by f is injective on R^n/M, else 0.

    Example:
      LIB "sing.lib";
      ring r = 0,(x,y),dp;
      is_reg(x, module([x,y]));
      → 1
      is_reg(x, module([y,0],[0,y]));
      → 1
      is_reg(y, module([y,0],[0,x*y]));
      → 0
    """
    ring = M.ring
    if not (ring.order.is_global or ring.order.is_local):
        raise MechRuntimeError("is_reg of a module in a mixed ordering is not supported")
    if f.is_zero():
        return 0
    q = module_ops.quotient(M, f)
    return int(all(_contains(M, g) for g in q.nonzero()))


def _plus(I: Ideal | Module, f: Poly) -> Ideal | Module:
    """I + f*R^n (I + <f> for an ideal)."""
    if isinstance(I, Ideal):
        return Ideal(I.ring, list(I.gens) + [f])
    ring = I.ring
    extra = [Vector(ring, [ring.zero()] * i + [f]) for i in range(I.rank)]
    return Module(ring, list(I.gens) + extra, I.rank)


def _level(ctx) -> int:
    """sing.lib's printlevel-voice+3 inside the command."""
    return ctx.sysvars.get("printlevel", 0) - len(ctx.frames) + 2


@command("is_regs", lib=LIB)
def is_regs(ctx, i: Ideal, *rest: Ideal | Module) -> int:
    """is_regs(i[, id]): 1 if the generators of i form a regular sequence on R^n/id (id = 0 by
    default), else 0; with printlevel >= 0 it says so, with printlevel >= 1 it shows each step.

    Example:
      LIB "sing.lib";
      ring r = 0,(x,y),dp;
      is_regs(ideal(x, y));
      → // elements are a regular sequence of length 2
      → 1
    """
    ring = i.ring
    I: Ideal | Module = rest[0] if rest else Ideal(ring, [ring.zero()])
    p = _level(ctx)
    d = len(i.nonzero())
    if not d:
        return 0
    for k, f in enumerate(i.gens[:d], 1):  # as sing.lib: the first size(i) generators
        if p >= 2:
            ctx.write(f"// checking whether element {k} is regular mod 1 .. {k - 1}\n")
        reg = is_reg(f, I) if isinstance(I, Ideal) else is_reg_module(f, I)
        if not reg:
            if p > 0:
                ctx.write(f"// elements 1..{k - 1} are regular, {k} is not regular mod 1..{k - 1}\n")
            return 0
        I = _plus(I, f)
    if p >= 1:
        ctx.write(f"// elements are a regular sequence of length {d}\n")
    return 1


def std_dimension(I: Ideal | Module) -> int:
    if isinstance(I, Ideal):
        return _std_dim(I.nonzero(), I.ring)
    from .module_commands import _basis, _module, _vecs
    return module_ops.dim(_Quiet(), _module(I.ring, _basis(I.ring, I.rank, _vecs(I)), I.rank, True))


class _Quiet:
    """A context for module dim on a standard basis (it warns about nothing)."""

    def assume_std(self, *_: object) -> None:
        return None


@command("is_active", lib=LIB)
def is_active(f: Poly, I: Ideal | Module) -> int:
    """is_active(f, id): dim(id) - dim(id + f*R^n) (1 when f is active on R^n/id, 0 when not; 1 for
    id = 0 written with no generators).

    Example:
      LIB "sing.lib";
      ring r = 0,(x,y,z),ds;
      is_active(x, ideal(yx3+y, yz3+y3z));
      → 1
    """
    if isinstance(I, Ideal) and not I.nonzero() or isinstance(I, Module) and not I.nonzero():
        return 1
    return std_dimension(I) - std_dimension(_plus(I, f))
