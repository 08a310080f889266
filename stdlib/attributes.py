"""``attrib``: Singular's attributes of values.  The one that matters for computations is ``isSB``
(the ideal is a standard basis: std's results carry it, commands that need a standard basis check
it); other attributes are kept with the variable (a ring's with the ring) for the script to read."""
from __future__ import annotations

from typing import Any, Optional

from ..dsl import ast as A
from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import NONE, Ideal, Ring, typeof
from ..dsl.values_modules import Module


@command("attrib", raw=True)
def attrib(ctx, node: A.Expr, *rest: A.Expr) -> Any:
    """attrib(x): print the attributes of the variable x; attrib(x, name): the attribute's value
    (attrib(I, "isSB"): 1 if the ideal I is marked as a standard basis, else 0; attrib(r, "global"):
    1 if the ring r has a global ordering; a ring lists Singular's internal attributes cf_class, global,
    maxExp, ring_cf, isLetterplaceRing first); attrib(x, name, value) sets it (attrib(I, "isSB", 1)
    marks I as a standard basis, 0 removes the mark).

    Example:
      ring r = 0,(x,y),dp;
      ideal I = x2, y;
      attrib(I, "isSB");
      → 0
      attrib(I, "isSB", 1);
      attrib(I);
      → attr:isSB, type int
      attrib(r, "global");
      → 1
    """
    value = ctx.eval(node)
    marked = isinstance(value, Ideal) and value.is_std or \
        isinstance(value, Module) and (value.is_std or len(value.nonzero()) <= 1)  # as Singular's modules
    table = _table(ctx, node, value, create=False)
    if not rest:
        lines = [f"attr:{k}, type int" for k in _RING_INTERNAL] if isinstance(value, Ring) else []
        lines += (["attr:isSB, type int"] if marked else []) + \
            [f"attr:{k}, type {typeof(v)} " for k, v in reversed(list((table or {}).items()))]  # (sic)
        ctx.write("\n".join(lines) + "\n" if lines else "no attributes\n")
        return None
    name = ctx.eval(rest[0])
    if not isinstance(name, str):
        raise MechRuntimeError("attrib(x, name): the attribute's name is a string")
    if len(rest) == 1:
        if name == "isSB":
            return int(marked)
        if name == "global" and isinstance(value, Ring):
            return int(value.poly.order.is_global)
        if name == "isLetterplaceRing" and isinstance(value, Ring):
            return 0
        if name in _RING_INTERNAL and isinstance(value, Ring):
            raise MechRuntimeError(f'attrib(r, "{name}"): Singular\'s internal attribute of its ring data is not '
                                   "supported")
        return (table or {}).get(name, NONE)
    if len(rest) > 2:
        raise MechRuntimeError("attrib(x, name, value) takes three arguments")
    flag = ctx.eval(rest[1])
    if name != "isSB":
        if name in _RESERVED:
            raise MechRuntimeError(f'attrib: the attribute "{name}" is not supported')
        _table(ctx, node, value, create=True)[name] = flag
        return None
    if not isinstance(value, Ideal):
        raise MechRuntimeError("attrib(x, \"isSB\", 1): x must be an ideal")
    if not isinstance(node, A.Name):
        raise MechRuntimeError("attrib(x, \"isSB\", 1): x must be a variable")
    kept = dict(table or {})
    ctx.assign(node, Ideal(value.ring, value.gens, is_std=bool(flag)))
    if kept:
        ctx.lookup(node.id).attributes = kept
    return None


#: the internal attributes Singular lists first for every ring (attrib(r))
_RING_INTERNAL = ("cf_class", "global", "maxExp", "ring_cf", "isLetterplaceRing")

#: attributes with a meaning in Singular that mech does not give them
_RESERVED = frozenset(("global", "rank", "qringNF", "maxExp", "ring_cf", "cf_class",
                       "isLetterplaceRing", "isSCA", "isCommutative"))


def _table(ctx, node: A.Expr, value: Any, create: bool) -> Optional[dict]:
    """The user attributes of a ring or of the variable ``node`` (None when it has none)."""
    if isinstance(value, Ring):
        return value.attributes
    var = ctx.lookup(node.id) if isinstance(node, A.Name) else None
    if var is None:
        if create:
            raise MechRuntimeError("attrib(x, name, value): x must be a variable")
        return None
    if var.attributes is None and create:
        var.attributes = {}
    return var.attributes


@command("killattrib", raw=True)
def killattrib(ctx, node: A.Expr, *rest: A.Expr) -> None:
    """killattrib(x, name): remove the attribute ``name`` of the variable x ("isSB": the
    standard-basis mark of an ideal); killattrib(x): all its attributes.

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
        kept = dict(_table(ctx, node, value, create=False) or {})
        ctx.assign(node, Ideal(value.ring, value.gens, is_std=False))
        ctx.lookup(node.id).attributes = kept or None
    table = _table(ctx, node, value, create=False)
    if table:
        if names:
            table.pop(names[0], None)
        else:
            table.clear()
