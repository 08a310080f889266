"""elim.lib's eliminations in an auxiliary ring: ``elim`` (a standard basis in elimRing's ring, the
generators free of the eliminated variables kept), ``elim1`` and ``elim2`` (``eliminate`` in the ring
with ordering dp, or ls when the first variable kept is local); the result mapped back by name."""
from __future__ import annotations

from typing import Any

from ..dsl.convert_modules import to_module
from ..dsl.errors import MechRuntimeError
from ..dsl.minpoly import extended, get_minpoly
from ..dsl.printing import ring_str
from ..dsl.qrings import quotient_ideal
from ..dsl.registry import command
from ..dsl.rings import make_ring
from ..dsl.values import Ideal, IntVec, Matrix, OrderBlock, Ring, to_matrix
from ..dsl.values_modules import Module, Vector
from ..kernel import Poly, PolyRing
from ..kernel.algext import AlgebraicField
from .elim_lib import LIB, elim_ring
from .elim_select import nselect
from .standard import standard_basis

Value = Ideal | Module | Matrix


def _variables(ring: PolyRing, arg: Poly | IntVec | int) -> list[int]:
    """The indices (from 0) of the variables to eliminate: those of a product of variables or of an
    intvec of indices."""
    if isinstance(arg, Poly):
        return [i for i in range(ring.nvars) if any(e[i] for e in arg.terms)]
    idx = [arg] if isinstance(arg, int) else list(arg.values)
    if any(not 1 <= k <= ring.nvars for k in idx):
        raise MechRuntimeError(f"elim: variable index out of range 1..{ring.nvars}")
    return sorted({k - 1 for k in idx})


def _moved(x: Value, ring: PolyRing) -> Value:
    """x with its polynomials in ``ring`` (the same variables, another ordering)."""
    if isinstance(x, Ideal):
        return Ideal(ring, [Poly(ring, p.terms) for p in x.gens])
    if isinstance(x, Matrix):
        x = to_module(x, x.ring)
    return Module(ring, [Vector(ring, [Poly(ring, p.terms) for p in g.entries]) for g in x.gens], x.rank)


def _twin(base: Ring, kind: str) -> Ring:
    """The basering's variables and coefficients with the ordering (kind, C)."""
    ring = base.poly
    new = make_ring(base.characteristic, base.params, list(ring.names), [OrderBlock(kind, ring.nvars), OrderBlock("C")])
    if isinstance(ring.field, AlgebraicField):
        new.poly = extended(new.poly, get_minpoly(base).c)
    return new


def _eliminate_in(x: Value, variables: list[int], kind: str, base: Ring) -> Value:
    if quotient_ideal(base.poly):
        raise MechRuntimeError("elim1 cannot eliminate in a qring, use eliminate")
    new = _twin(base, kind).poly
    y = _moved(x, new)
    from . import module_ops  # imported here: overloads register in the modules' alphabetical load order
    from .ideals import _eliminate
    if isinstance(y, Ideal):
        out: Value = _eliminate(y, variables)
    else:
        m = new.one()
        for i in variables:
            m = m * new.gen(i)
        out = module_ops.eliminate(y, m)
    back = _moved(out, base.poly)
    if isinstance(x, Matrix):
        return to_matrix(back, base.poly)
    return back


def _first_kept_local(ring: PolyRing, variables: list[int]) -> bool:
    keep = [i for i in range(ring.nvars) if i not in variables]
    if not keep:
        raise MechRuntimeError("## elimination of all variables is not possible")
    one = tuple(int(i == keep[0]) for i in range(ring.nvars))
    return ring.order.compare(one, ring.zero_exp) < 0


@command("elim1", lib=LIB)
def elim1(ctx, x: Ideal | Module | Matrix, arg: Poly | IntVec | int) -> Any:
    """elim1(id, v): id with the variables of v (a product of variables or an intvec of indices)
    eliminated by ``eliminate`` in the ring with ordering dp (ls when the first variable kept is
    local), mapped back to the basering.

    Example:
      LIB "elim.lib";
      ring r = 0,(x,y,t),dp;
      elim1(ideal(x-t, y-t2), t);
      → _[1]=x2-y
    """
    base = ctx.basering()
    variables = _variables(base.poly, arg)
    return _eliminate_in(x, variables, "ls" if _first_kept_local(base.poly, variables) else "dp", base)


@command("elim2", lib=LIB)
def elim2(ctx, x: Ideal | Module | Matrix, v: IntVec | int) -> Any:
    """elim2(id, v): id with the variables of index in v eliminated by ``eliminate`` in the ring with
    ordering dp (ls when the basering's ordering is not global), mapped back to the basering.

    Example:
      LIB "elim.lib";
      ring r = 0,(x,y,t),dp;
      elim2(ideal(x-t, y-t2), 3);
      → _[1]=x2-y
    """
    base = ctx.basering()
    return _eliminate_in(x, _variables(base.poly, v), "dp" if base.poly.order.is_global else "ls", base)


@command("elim", lib=LIB)
def elim(ctx, x: Ideal | Module | Matrix, arg: Poly | IntVec | int, *opts: str) -> Any:
    """elim(id, v[, method]): id with the variables of v (a product of variables or an intvec of
    indices) eliminated: a standard basis in the ring of elimRing (the eliminated variables first),
    its generators free of them, mapped back to the basering.  The method ("std", "slimgb",
    "withWeights") changes only the way there (weights from the ring); with printlevel > 0 the ring
    is shown.

    Example:
      LIB "elim.lib";
      ring r = 0,(x,y,t),dp;
      elim(ideal(x-t, y-t2), t);
      → _[1]=x2-y
    """
    base = ctx.basering()
    ring = base.poly
    if quotient_ideal(ring):
        raise MechRuntimeError("`elim` cannot eliminate in qring, use `eliminate`")
    for o in opts:
        if o not in ("std", "slimgb", "withWeights"):
            raise MechRuntimeError('expected "std" or "slimgb" or "withWeights" as the optional string parameters')
    variables = _variables(ring, arg)
    src = x if not isinstance(x, Matrix) else to_module(x, ring)
    m = ring.one()
    for i in variables:
        m = m * ring.gen(i)
    from .module_commands import std as module_std  # here, as in _eliminate_in
    if "withWeights" in opts:
        from .weight import weight
        ideal = src if isinstance(src, Ideal) else Ideal(ring, [p for g in src.gens for p in g.entries] or [ring.zero()])
        new = elim_ring(ctx, m, weight(ideal)).items[0]
    else:
        new = elim_ring(ctx, m).items[0]
    assert isinstance(new, Ring)
    names = list(new.poly.names)
    perm = [ring.names.index(n) for n in names]

    def move(p: Poly, to: PolyRing, order: list[int]) -> Poly:
        return Poly(to, {tuple(e[i] for i in order): c for e, c in p.terms.items()})
    inverse = [names.index(n) for n in ring.names]
    if isinstance(src, Ideal):
        y: Value = Ideal(new.poly, standard_basis(Ideal(new.poly, [move(p, new.poly, perm) for p in src.gens])))
    else:
        y = module_std(Module(new.poly, [Vector(new.poly, [move(p, new.poly, perm) for p in g.entries])
                                        for g in src.gens], src.rank))
    kept = nselect(y, IntVec(list(range(1, len(variables) + 1))))
    if ctx.sysvars.get("printlevel", 0) - len(ctx.frames) + 1 > 0:
        ctx.write("// result is a SB in the following ring:\n" + ring_str(new) + "\n")
    if isinstance(kept, Ideal):
        return Ideal(ring, [move(p, ring, inverse) for p in kept.gens])
    out = Module(ring, [Vector(ring, [move(p, ring, inverse) for p in g.entries]) for g in kept.gens], kept.rank)
    return to_matrix(out, ring) if isinstance(x, Matrix) else out
