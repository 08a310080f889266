"""Singular's ``type x;``: the name, the type and the value of a variable, as ``// i int 3``; values
printed on several lines (ideals, matrices, lists, maps, rings) come under a header line."""
from __future__ import annotations

from typing import Any

from ..dsl.printing import render
from ..dsl.registry import command
from ..dsl.values import NONE, Ideal, List, Map, Matrix, Ring, typeof
from ..dsl.values_modules import Module


@command("type")
def type_(ctx, x: Any) -> Any:
    """type x: the name, type and value of x, as Singular's type command shows them.

    Example:
      int i = 3;
      type i;
      → // i int 3
      ring r = 0,(x,y),dp;
      ideal I = x, y2;
      type I;
      → // I ideal
      → I[1]=x
      → I[2]=y2
    """
    name = ctx.argnames[0] if ctx.argnames and ctx.argnames[0] else "_"
    t = typeof(x)
    text = render(x, name)
    if isinstance(x, (Matrix,)) or t == "intmat":
        header = f"// {name} {t}  {x.nrows} x {x.ncols}"
    elif isinstance(x, List):
        header = f"// {name} list , size {len(x.items)}"
    elif isinstance(x, Module):
        header = f"// {name} module , rk {x.rank}"
    elif isinstance(x, Map):
        header = f"// {name} map  from {x.source.name}"
    elif isinstance(x, (Ideal, Ring)) or "\n" in text:
        header = f"// {name} {t} "
    else:
        ctx.write(f"// {name} {t} {text}\n")
        return NONE
    ctx.write(header + "\n" + text + "\n")
    return NONE
