"""What a ring is made of (``nvars``, ``npars``, ``var``, ``par``, ``varstr``, ``parstr``,
``charstr``, ``char``, ``ordstr``) and maps between rings by name and by position (``imap``,
``fetch``)."""
from __future__ import annotations

from typing import Any

from ..dsl import ast as A
from ..dsl.errors import MechRuntimeError, MechTypeError
from ..dsl.printing import charstr as _charstr
from ..dsl.printing import ordstr as _ordstr
from ..dsl.registry import command
from ..dsl.values import Number, Ring
from ..dsl.values import typeof as _typeof
from ..kernel import Poly


@command("nvars")
def nvars(r: Ring) -> int:
    """nvars(r): the number of ring variables.

    Example:
      ring r = 0,(x,y,z),dp;
      nvars(r);
      → 3
    """
    return len(r.names)


@command("npars")
def npars(r: Ring) -> int:
    """npars(r): the number of parameters of the coefficient field.

    Example:
      ring r = (0,a,b),(x,y),dp;
      npars(r);
      → 2
    """
    return len(r.params)


@command("var")
def var(ctx, i: int) -> Poly:
    """var(i): the i-th ring variable.

    Example:
      ring r = 0,(x,y,z),dp;
      var(2);
      → y
    """
    ring = ctx.basering()
    if not 1 <= i <= len(ring.names):
        raise MechRuntimeError(f"var({i}): the ring has {len(ring.names)} variables")
    return ring.poly.gen(i - 1)


@command("par")
def par(ctx, i: int) -> Number:
    """par(i): the i-th parameter of the coefficient field.

    Example:
      ring r = (0,a,b),(x,y),dp;
      par(2);
      → (b)
    """
    ring = ctx.basering()
    if not 1 <= i <= len(ring.params):
        raise MechRuntimeError(f"par({i}): the ring has {len(ring.params)} parameters")
    return ctx._param(ring, ring.params[i - 1])


def _name_list(ctx: Any, r: Ring | int, i: int | None, what: str) -> str:
    """The variable (``what="variables"``) or parameter names of a ring, or the i-th of them."""
    if isinstance(r, int):
        r, i = ctx.basering(), r
    seq = r.names if what == "variables" else r.params
    if i is None:
        return ",".join(seq)
    if not 1 <= i <= len(seq):
        raise MechRuntimeError(f"index {i} out of range: the ring has {len(seq)} {what}")
    return seq[i - 1]


@command("varstr")
def varstr(ctx, r: Ring | int, i: int | None = None) -> str:
    """varstr(r): the variable names separated by commas; varstr(i) or varstr(r, i): the i-th.

    Example:
      ring r = 0,(x,y,z),dp;
      varstr(r);
      → x,y,z
      varstr(2);
      → y
    """
    return _name_list(ctx, r, i, "variables")


@command("parstr")
def parstr(ctx, r: Ring | int, i: int | None = None) -> str:
    """parstr(r): the parameter names separated by commas; parstr(i): the i-th.

    Example:
      ring r = (0,a,b),(x,y),dp;
      parstr(r);
      → a,b
      parstr(1);
      → a
    """
    return _name_list(ctx, r, i, "parameters")


@command("charstr")
def charstr(r: Ring) -> str:
    """charstr(r): the coefficient field: QQ, ZZ/p, or 0,a,b with parameters.

    Example:
      ring r = 32003,(x,y),dp;
      charstr(r);
      → ZZ/32003
      ring s = (0,a),(x,y),dp;
      charstr(s);
      → 0,a
    """
    return _charstr(r)


@command("char")
def char(r: Ring) -> int:
    """char(r): the characteristic of the coefficient field.

    Example:
      ring r = 32003,(x,y),dp;
      char(r);
      → 32003
    """
    return r.characteristic


@command("ordstr")
def ordstr(r: Ring) -> str:
    """ordstr(r): the monomial ordering, e.g. dp(4),dp(2),C.

    Example:
      ring r = 0,(x,y,z),(dp(2),lp(1));
      ordstr(r);
      → dp(2),lp(1),C
    """
    return _ordstr(r)


def _in_ring(ctx: Any, ring_node: A.Expr, name_node: A.Expr, cmd: str) -> tuple[Ring, Any]:
    src = ctx.eval(ring_node)
    if not isinstance(src, Ring):
        raise MechTypeError(f"{cmd}: the first argument must be a ring, not {_typeof(src)}")
    if isinstance(name_node, A.Name):
        var = ctx.lookup_in_ring(src, name_node.id)
        if var is not None:
            return src, var.value
    saved = ctx.ring
    ctx.ring = src
    try:
        return src, ctx.eval(name_node)
    finally:
        ctx.ring = saved


@command("imap", raw=True)
def imap(ctx, ring_node: A.Expr, obj_node: A.Expr) -> Any:
    """imap(r, f): the object f of ring r mapped into the basering, each variable to the variable
    or parameter of the same name (to 0 if the basering has none), parameters likewise by name.

    Example:
      ring r = 0,(x,y,z),dp;
      poly f = x2+yz;
      ring s = 0,(z,x),dp;
      imap(r, f);
      → x2
    """
    from ..dsl.maps import map_value
    from ..kernel.maps import imap as imap_polys
    src, v = _in_ring(ctx, ring_node, obj_node, "imap")
    target = ctx.basering().poly
    if "Imap" in ctx.options:
        ctx.write("".join(f"{line}\n" for line in imap_report(src.poly, target)))
    return map_value(v, [], target, lambda polys, source: imap_polys(polys, source, target))


def imap_report(source: Any, target: Any) -> list[str]:
    """The lines Singular prints for imap under option(Imap): where each variable and parameter of
    the source goes (``// var x: nr 2 -> nr 3``, ``// par a: par 1 -> nr 1``), those going nowhere left out."""
    def where(name: str) -> str | None:
        if name in target.names:
            return f"nr {target.names.index(name) + 1}"
        params = getattr(target.field, "params", ())
        return f"par {params.index(name) + 1}" if name in params else None
    lines = [(f"var {n}: nr {k}", where(n)) for k, n in enumerate(source.names, 1)]
    lines += [(f"par {n}: par {k}", where(n)) for k, n in enumerate(getattr(source.field, "params", ()), 1)]
    return [f"// {head} -> {dest}" for head, dest in lines if dest]


@command("fetch", raw=True)
def fetch(ctx, ring_node: A.Expr, obj_node: A.Expr) -> Any:
    """fetch(r, f): the object f of ring r mapped into the basering, the i-th variable to the i-th
    (to 0 if the basering has fewer), parameters likewise by position.

    Example:
      ring r = 0,(x,y,z),dp;
      poly f = x2+yz;
      ring s = 0,(a,b,c),dp;
      fetch(r, f);
      → a2+bc
    """
    from ..dsl.maps import map_value
    from ..kernel.maps import fetch as fetch_polys
    _, v = _in_ring(ctx, ring_node, obj_node, "fetch")
    target = ctx.basering().poly
    return map_value(v, [], target, lambda polys, source: fetch_polys(polys, source, target))


@command("pardeg")
def pardeg(n: Number) -> int:
    """pardeg(n): the degree of the number n in the parameters (of its numerator; -1 for 0).

    Example:
      ring r = (0,a,b),x,dp;
      pardeg(a2b+a);
      → 3
    """
    return _pardeg(n.c)


@command("pardeg")
def pardeg_poly(p: Poly) -> int:
    if not p.is_constant():
        raise MechRuntimeError("pardeg takes a number")
    return _pardeg(p.lc() if not p.is_zero() else 0)


def _pardeg(c: Any) -> int:
    """The total degree of the coefficient's numerator in the parameters (-1 for 0)."""
    if c == 0:
        return -1
    num = getattr(c, "num", None)
    return 0 if num is None else max(sum(e) for e in num.to_dict())
