"""general.lib's ``killall``: kill the top level's variables, all, of one type, or all but some, as the
library procedure does it: it walks ``names(Top)`` (the newest name first) and its own local variables
``j``, ``no_kill``, ``@joni``, ``@marie`` hide global ones of those names (these stay), and the forms
with arguments leave the two newest names alone (its loop stops before them).  Singular's
``killall("not", ...)`` also kills the packages of the libraries on its way, its own (General) too,
which ends it before the variables defined after ``LIB "general.lib";``: mech's library commands are
built in, and it kills those variables as the help says."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Proc, Ring, typeof

_PROC_LOCALS = {"j": "int", "no_kill": "int", "@joni": "int", "@marie": "list"}


@command("killall", lib="general.lib")
def killall(ctx, *kinds: Any) -> None:
    """killall(): kill every global variable but procedures; killall("proc"): the user's procedures;
    killall(t): the variables of type t; killall("not", t1, ...): all but those of the types or
    names t1, ... (see the module's note on the names the procedure leaves).

    Example:
      LIB "general.lib";
      ring r = 0,(x,y),dp; int k = 1; string s = "a"; list L = 1, 2;
      killall("list");
      listvar();
      → // L                              [0]  list, size: 2
      → // s                              [0]  string a
      → // k                              [0]  int 1
      → // r                              [0]  *ring
    """
    for k, t in enumerate(kinds, 1):
        if not isinstance(t, str):
            raise MechRuntimeError(f"Need string as {k}th argument")
    names = list(reversed(ctx.frames[0].vars))  # names(Top): the newest first
    if not kinds:
        doomed = [n for n in names if n not in _PROC_LOCALS and not isinstance(_value(ctx, n), Proc)]
    elif kinds == ("proc",):
        doomed = [n for n in names if n != "killall" and isinstance(_value(ctx, n), Proc)]
    else:
        walked = [n for n in names[2:] if n not in _PROC_LOCALS]
        if kinds[0] != "not":
            doomed = [n for n in walked if _type(ctx, n) == kinds[0] and _type(ctx, n) != "proc"]
        else:
            doomed = [n for n in walked if _type(ctx, n) != "proc"
                      and not any(_type(ctx, n) == t or n == t for t in kinds[1:])]
    for n in doomed:
        var = ctx.frames[0].vars.get(n)
        if var is not None:
            ctx._remove(var)
            if isinstance(var.value, Ring) and var.value is ctx.ring:
                ctx.ring = None


def _value(ctx: Any, name: str) -> Any:
    var = ctx.frames[0].vars.get(name)
    return var.value if var is not None else None


def _type(ctx: Any, name: str) -> str:
    return _PROC_LOCALS.get(name) or typeof(_value(ctx, name))
