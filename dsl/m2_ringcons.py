"""Building Macaulay2 rings from ``K[x, y, Option => v]``: the variables (names, ``x_i``,
``x_(i,j)``, ranges ``a..d`` / ``x_1..x_n``, lists of these), the options ``MonomialOrder``,
``Global``, ``Degrees``, ``Weights`` and ``MonomialSize`` (``Join``: only degrees, ignored), and the coefficient ring (``QQ``,
``ZZ/p`` or another ring: a tower)."""
from __future__ import annotations

from typing import Any, Callable, Optional

from . import ast as A
from .errors import MechRuntimeError, MechSyntaxError, MechTypeError
from .m2_ast import ListLit, Option, RingCons, Subscript, SymbolLit
from .m2_orders import order_blocks, position
from .m2_rings import M2Ring, polynomial_ring
from .m2_values import CoeffRing, Opt, Symbol
from ..kernel import Poly
from .values import ExprList, List, to_int, typeof

#: the ring options mech reads
OPTIONS = ("MonomialOrder", "Global", "Degrees", "Weights", "MonomialSize", "Join")


def build_ring(node: RingCons, base: Any, evaluate: Callable[[A.Expr], Any], show: Callable[[Any], str]) -> M2Ring:
    """The ring of ``node`` over ``base`` (``evaluate`` evaluates a subexpression, ``show`` prints a value)."""
    if not isinstance(base, (CoeffRing, M2Ring)):
        raise MechTypeError(f"a polynomial ring is built over a ring (QQ, ZZ/p or a polynomial ring), "
                            f"not over a {typeof(base)}")
    names: list[str] = []
    options: dict[str, Any] = {}
    for item in node.items:
        if isinstance(item, Option):
            key = item.key.id if isinstance(item.key, A.Name) else ""
            if key not in OPTIONS:
                raise MechRuntimeError(f"unknown ring option '{key}' (known: {', '.join(OPTIONS)})")
            options[key] = evaluate(item.value)
        else:
            names.extend(variable_names(item, evaluate, show))
    return make_ring(base, names, options, show)


def make_ring(base: Any, names: list[str], options: dict[str, Any], show: Callable[[Any], str]) -> M2Ring:
    """The polynomial ring over ``base`` in ``names`` with these options (values, by name)."""
    if not names or len(set(names)) != len(names):
        raise MechRuntimeError("a ring needs distinct variables: QQ[x,y,z]")
    degrees, graded = _degrees(options.get("Degrees"), len(names))
    spec = options.get("MonomialOrder", Symbol("GRevLex"))
    if "Weights" in options:
        spec = List([Opt(Symbol("Weights"), options["Weights"])] + list(spec.items if isinstance(spec, List) else [spec]))
    blocks = order_blocks(spec, len(names), degrees)
    size = options.get("MonomialSize")
    ring = polynomial_ring(base, names, blocks, degrees, (2 ** (to_int(size) - 1)) if size is not None else None)
    ring.info["m2_options"] = dict(options)
    ring.info["m2_order"] = (spec, size)  # as given, for options R
    first = (spec.items[0] if isinstance(spec, List) and spec.items else spec)
    if isinstance(first, Opt) and first.key in (Symbol("GroupLex"), Symbol("GroupRevLex")):
        ring.info["group"] = first.value  # its first variables are invertible
    where = position(spec, len(names), degrees)
    if where != (len(blocks), "Up"):  # Position => ... not at its default place
        ring.info["position"] = where
    if graded is not None:  # several degree components, or degrees not positive: Macaulay2's own, kept
        ring.info["multidegrees"] = graded
    want = options.get("Global", True)
    if want is not ring.poly.order.is_global:
        raise MechRuntimeError(f"the monomial order is not {'global' if want else 'local'} (Global => {show(want)})")
    return ring


def _degrees(spec: Any, n: int) -> tuple[tuple[int, ...], Optional[list[tuple[int, ...]]]]:
    """(the positive degrees the monomial order weighs variables by, Macaulay2's degree vectors
    when they are not these: several components or a degree <= 0; None otherwise).  The weights
    are the degrees' products with Macaulay2's heft vector (:func:`heft`), else all 1."""
    if spec is None:
        return (), None
    items = _spliced(spec.items) if isinstance(spec, List) else None
    vecs = []
    for d in items or []:
        d = d.items if isinstance(d, List) else [d]
        if not d or not all(type(k) is int for k in d):
            raise MechRuntimeError("Degrees => {...} takes integers or lists of integers (one per variable)")
        vecs.append(tuple(d))
    if items is None or len(vecs) != n or len({len(v) for v in vecs}) > 1:
        raise MechRuntimeError(f"Degrees => {{...}} takes {n} degrees, one per variable, of one length")
    if all(len(v) == 1 and v[0] > 0 for v in vecs):
        return tuple(v[0] for v in vecs), None
    w = heft(vecs)
    weights = tuple(sum(a * b for a, b in zip(w, v)) for v in vecs) if w is not None else (1,) * n
    return weights, vecs


def _spliced(items: list) -> list:
    return [x for item in items for x in (_spliced(item.items) if isinstance(item, ExprList) else [item])]


def heft(vecs: list[tuple[int, ...]]) -> Optional[tuple[int, ...]]:
    """A heft vector of the degrees: w with w . d > 0 for every degree d, the first by increasing
    sum of nonnegative entries, then decreasing lexicographically (as Macaulay2 chooses for small
    gradings: {1, 0}, {1, 1}, {1, 2}); None when none has entries up to 8."""
    from itertools import product
    k = len(vecs[0])
    for total in range(1, 9):
        for w in sorted((w for w in product(range(total + 1), repeat=k) if sum(w) == total), reverse=True):
            if all(sum(a * b for a, b in zip(w, v)) > 0 for v in vecs):
                return w
    return None


def variable_names(node: A.Expr, evaluate: Callable[[A.Expr], Any], show: Callable[[Any], str]) -> list[str]:
    """The names of ring variables written as ``node``."""
    if isinstance(node, A.Name):
        return [node.id]
    if isinstance(node, SymbolLit):
        return [node.name]
    if isinstance(node, Subscript) and isinstance(node.base, A.Name):
        return [f"{node.base.id}_{show(evaluate(node.index))}"]
    if isinstance(node, ListLit):
        return [n for item in node.items for n in variable_names(item, evaluate, show)]
    if isinstance(node, A.Range):
        lo, hi = variable_names(node.lo, evaluate, show), variable_names(node.hi, evaluate, show)
        return _range(lo[0], hi[0], node)
    v = evaluate(node)
    if isinstance(v, Symbol):
        return [v.name]
    items = v.items if isinstance(v, (List, ExprList)) else [v]
    if all(isinstance(x, Symbol) or _variable(x) for x in items):  # symbols, or variables of a ring (their names)
        return [x.name if isinstance(x, Symbol) else x.ring.names[x.lm().index(1)] for x in items]
    raise MechSyntaxError("a ring variable is a name, x_i, x_(i,j) or a range a..d, x_1..x_n", node.pos)


def _variable(x: Any) -> bool:
    return isinstance(x, Poly) and len(x.terms) == 1 and sum(x.lm()) == 1 and x.lc() == x.ring.field.one


def _range(x: str, y: str, node: A.Expr) -> list[str]:
    a, _, i = x.rpartition("_")
    b, _, j = y.rpartition("_")
    if a and a == b and _int(i) is not None and _int(j) is not None:
        return [f"{a}_{k}" for k in range(_int(i), _int(j) + 1)]
    if a and a == b and i.startswith("(") and j.startswith("("):
        lo, hi = _tuple(i), _tuple(j)
        if lo and hi and len(lo) == len(hi):
            return [f"{a}_({','.join(map(str, t))})" for t in _box(lo, hi)]
    if len(x) == 1 and len(y) == 1 and x.isalpha() and y.isalpha() and x <= y:
        return [chr(c) for c in range(ord(x), ord(y) + 1)]
    raise MechSyntaxError("a range of variables is a..d, x_1..x_n or x_(1,1)..x_(2,3)", node.pos)


def _int(s: str):
    try:
        return int(s)
    except ValueError:
        return None


def _tuple(s: str):
    parts = [_int(p) for p in s.strip("()").split(",")]
    return None if None in parts else parts


def _box(lo: list[int], hi: list[int]) -> list[tuple[int, ...]]:
    """The index tuples from ``lo`` to ``hi`` in lexicographic order (Macaulay2's ``x_(1,1)..x_(2,2)``)."""
    out: list[tuple[int, ...]] = [()]
    for a, b in zip(lo, hi):
        out = [t + (k,) for t in out for k in range(a, b + 1)]
    return out
