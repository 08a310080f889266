"""``attrib``: Singular's attributes of values; mech keeps the one that matters for computations,
``isSB`` (the ideal is a standard basis: std's results carry it, commands that need a standard
basis check it)."""
from __future__ import annotations

from typing import Any

from ..dsl import ast as A
from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Ideal


@command("attrib", raw=True)
def attrib(ctx, node: A.Expr, *rest: A.Expr) -> Any:
    """attrib(I): print the attributes of I; attrib(I, "isSB"): 1 if the ideal I is marked as a
    standard basis, else 0; attrib(I, "isSB", 1) marks it as one (0 removes the mark).

    Example:
      ring r = 0,(x,y),dp;
      ideal I = x2, y;
      attrib(I, "isSB");
      → 0
      attrib(I, "isSB", 1);
      attrib(I);
      → attr:isSB, type int
    """
    value = ctx.eval(node)
    marked = isinstance(value, Ideal) and value.is_std
    if not rest:
        ctx.write("attr:isSB, type int\n" if marked else "no attributes\n")
        return None
    name = ctx.eval(rest[0])
    if not isinstance(name, str):
        raise MechRuntimeError("attrib(x, name): the attribute's name is a string")
    if len(rest) == 1:
        if name == "isSB":
            return int(marked)
        raise MechRuntimeError(f'attrib: the attribute "{name}" is not supported (mech keeps only "isSB")')
    if name != "isSB" or len(rest) > 2:
        raise MechRuntimeError(f'attrib: setting the attribute "{name}" is not supported (mech keeps only "isSB")')
    flag = ctx.eval(rest[1])
    if not isinstance(value, Ideal):
        raise MechRuntimeError("attrib(x, \"isSB\", 1): x must be an ideal")
    if not isinstance(node, A.Name):
        raise MechRuntimeError("attrib(x, \"isSB\", 1): x must be a variable")
    ctx.assign(node, Ideal(value.ring, value.gens, is_std=bool(flag)))
    return None


@command("killattrib", raw=True)
def killattrib(ctx, node: A.Expr, *rest: A.Expr) -> None:
    """killattrib(I, "isSB"): remove the standard-basis mark of the ideal variable I (killattrib(I):
    all its attributes).

    Example:
      ring r = 0,(x,y),dp;
      ideal I = std(ideal(x2, y));
      killattrib(I, "isSB");
      attrib(I, "isSB");
      → 0
    """
    value = ctx.eval(node)
    names = [ctx.eval(r) for r in rest]
    if len(names) > 1 or not all(isinstance(n, str) for n in names):
        raise MechRuntimeError("killattrib(x) or killattrib(x, name): the attribute's name is a string")
    if isinstance(value, Ideal) and value.is_std and names in ([], ["isSB"]):
        if not isinstance(node, A.Name):
            raise MechRuntimeError("killattrib(x, ...): x must be a variable")
        ctx.assign(node, Ideal(value.ring, value.gens, is_std=False))
