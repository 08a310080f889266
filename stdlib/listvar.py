"""``listvar``: the variables of the session, as Singular lists them (newest first, the objects of a
ring indented under it)."""
from __future__ import annotations

from typing import Any, Optional

from ..dsl import ast as A
from ..dsl.errors import MechRuntimeError, MechTypeError
from ..dsl.registry import command
from ..dsl.values_modules import Module
from ..dsl.values import Ideal, IntVec, List, Map, Matrix, Number, Proc, Ring, typeof
from ..kernel import Poly


def describe(value: Any, basering: Optional[Ring]) -> str:
    """What listvar prints after a variable's name and level."""
    if isinstance(value, bool) or isinstance(value, int):
        return f"int {value}"
    if isinstance(value, str):  # as Singular: at most 20 characters of the first line
        head = value[:20].split("\n")[0]
        return f"string {head}" + (f"..., {len(value)} char(s)" if len(value) > 20 or "\n" in value[:20] else "")
    if isinstance(value, IntVec):
        return f"intvec ({len(value)})"
    if isinstance(value, List):
        return f"list, size: {len(value)}"
    if isinstance(value, Ring):
        return "*ring" if value is basering else "ring"
    if isinstance(value, Poly):
        return "poly"
    if isinstance(value, Number):
        return "number"
    if isinstance(value, Ideal):
        return f"ideal{' (SB)' if value.is_std else ''}, {len(value.gens)} generator(s)"
    if isinstance(value, Module):
        return f"module{' (SB)' if value.is_std else ''}, rk {value.rank}, {len(value.gens)} generator(s)"
    if isinstance(value, Matrix):
        return f"matrix {value.nrows} x {value.ncols}"
    if isinstance(value, Map):
        return f"map from {value.source.name}"
    shape = getattr(value, "listvar_text", None)
    return shape() if callable(shape) else typeof(value)


def _text(var: Any, basering: Optional[Ring]) -> str:
    return f"alias for {var.alias}" if getattr(var, "alias", None) else describe(var.value, basering)


def _line(name: str, level: int, text: str, nested: bool) -> str:
    lead = "//      " if nested else "// "
    return f"{lead}{name:<30} [{level}]  {text}\n"


@command("listvar", raw=True)
def listvar(ctx, *nodes: A.Expr) -> None:
    """listvar(): the variables visible here, newest first, with level and type (the basering's
    objects indented under it); listvar(all): the objects of every ring; listvar(r): the ring r and
    its objects; listvar(x): the variable x; listvar(type): the variables of that type (rings: with
    Singular's predefined coefficient rings ZZ and QQ).

    Example:
      int a = 3;
      ring r = 0,(x,y),dp;
      ideal i = x, y;
      listvar();
      → // r                              [0]  *ring
      → //      i                              [0]  ideal, 2 generator(s)
      → // a                              [0]  int 3
    """
    basering = ctx.ring
    frames = [f for f in ctx.frames if f.level in (0, len(ctx.frames) - 1)]
    frames.sort(key=lambda f: -f.level)
    if nodes:
        node = nodes[0]
        if len(nodes) > 1 or not isinstance(node, A.Name):
            raise MechTypeError("listvar takes no argument, all, or a ring")
        if node.id == "proc":
            raise MechRuntimeError("listvar(proc): listing procedures (Singular's lists its libraries') is not "
                                   "supported")
        if node.id in _TYPES:
            _of_type(ctx, frames, node.id, basering)
            return
        if node.id != "all":
            ring = ctx.eval(node)
            if not isinstance(ring, Ring):
                var = ctx.lookup(node.id)
                ctx.write(_line(node.id, var.level, _text(var, basering), False))
                return
            other_name = ring is basering and getattr(ring, "name", None) not in (None, node.id)
            ctx.write(_line(node.id, 0, "ring(*)" if other_name else describe(ring, basering), False))
            for f in frames:
                for var in reversed(list(_ring_vars(ctx, f, ring).values())):
                    ctx.write(_line(var.name, var.level, describe(var.value, basering), False))
            return
    every = bool(nodes)
    out: list[str] = []
    shown = False  # the basering is listed with its objects once; other names of it show ring(*)
    for f in frames:
        for var in reversed(list(f.vars.values())):
            if isinstance(var.value, Proc):
                continue
            if var.value is basering and basering is not None and shown:
                out.append(_line(var.name, var.level, "ring(*)", False))
                continue
            out.append(_line(var.name, var.level, _text(var, basering), False))
            shown = shown or var.value is basering
            if isinstance(var.value, Ring) and (every or var.value is basering):
                for g in frames:
                    for dep in reversed(list(_ring_vars(ctx, g, var.value).values())):
                        out.append(_line(dep.name, dep.level, _text(dep, basering), True))
        if f.proc is not None and f.proc.params is None and "#" not in f.vars:  # its empty argument list
            out.append(_line("#", f.level, "list, size: 0", False))
    ctx.write("".join(out))


#: the types listvar(type) lists ("ring" adds Singular's predefined coefficient rings ZZ and QQ)
_TYPES = ("int", "bigint", "number", "poly", "ideal", "matrix", "list", "string", "intvec", "intmat", "map",
          "ring", "vector", "module")


def _of_type(ctx: Any, frames: list, typ: str, basering: Optional[Ring]) -> None:
    """listvar(type): the visible variables of that type, newest first (the basering's objects too)."""
    out = []
    for f in frames:
        found = list(f.vars.values())
        if basering is not None:
            found += list(_ring_vars(ctx, f, basering).values())
        for var in reversed(found):
            if typeof(var.value) == typ or (typ == "ring" and isinstance(var.value, Ring)):
                out.append(_line(var.name, var.level, _text(var, basering), False))
    if typ == "ring":
        out += [_line(name, 0, "cring", False) for name in ("ZZ", "QQ")]
    ctx.write("".join(out))


def _ring_vars(ctx: Any, frame: Any, ring: Ring) -> dict:
    return ring.objects if frame.level == 0 else frame.ring_vars.get(ring, {})
