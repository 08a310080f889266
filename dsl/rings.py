"""Reading a ring declaration ``ring r = CHAR, VARS, ORDERING;`` into a :class:`~mech.dsl.values.Ring`.

The three parts arrive as expression trees and are read as ring data, not evaluated as values:
``CHAR`` is ``0``, a prime, or ``(0,a,b)`` / ``(p,a)`` with parameters; ``VARS`` is a name,
``x(1..5)``, or a parenthesized list of those; ``ORDERING`` is ``dp``, ``wp(1,2,3)``,
``(dp(4),lp(2),C)``, ``(a(1,1),dp)``, ``M(1,1,0,-1)`` ...  Sizes, weights and index ranges are
int expressions, evaluated by the caller's ``evaluate``.
"""
from __future__ import annotations

import math
import re
from typing import Any, Callable

from ..kernel import GF, QQ, Block, MonomialOrder, PolyRing
from . import ast as A
from .boundary import convert_exception
from .errors import MechRuntimeError
from .values_modules import note_blocks
from .values import IntVec, OrderBlock, Ring

Evaluate = Callable[[A.Expr], Any]

ORDERINGS = {"lp", "dp", "Dp", "wp", "Wp", "ls", "ds", "Ds", "ws", "Ws", "a", "M", "c", "C"}
WEIGHTED = {"wp", "Wp", "ws", "Ws", "a"}
OrderItem = tuple[str, list[int] | None]  # a block as written: its name, its arguments (None: no parentheses)

_ring_cache: dict[tuple, PolyRing] = {}


def _ints(v: Any, what: str) -> list[int]:
    if isinstance(v, bool):
        v = int(v)
    if isinstance(v, int):
        return [v]
    if isinstance(v, IntVec):
        return list(v.values)
    if getattr(type(v), "type_name", "") == "intmat":  # M(A): the entries row by row
        return list(v.values)
    raise MechRuntimeError(f"{what} must be an int or an intvec")


MAX_WEIGHT = 2**31 - 1  # ordering sizes and weights are Singular ints


def _int_args(args: list[A.Expr], evaluate: Evaluate, what: str) -> list[int]:
    out: list[int] = []
    for a in args:
        out.extend(_ints(evaluate(a), what))
    if any(abs(v) > MAX_WEIGHT for v in out):
        raise MechRuntimeError(f"{what} must be at most {MAX_WEIGHT} in absolute value")
    return out


def default_ring() -> Ring:
    """``ring r;``: Singular's default ring ``32003, (x,y,z), dp``."""
    return make_ring(32003, (), ["x", "y", "z"], [OrderBlock("dp", 3), OrderBlock("C")])


def build_ring(items: list[A.Expr], evaluate: Evaluate, warn: Callable[[str], None] = lambda _: None) -> Ring:
    """The ring of a declaration ``ring r = items;`` (an invalid characteristic becomes 32003, with a
    warning through ``warn``, as in Singular)."""
    if len(items) != 3:
        raise MechRuntimeError("a ring is declared as ring r = characteristic, (variables), ordering;")
    char, params = _at(items[0], lambda: _characteristic(items[0], evaluate))
    if char > 1 and not _is_prime(char):
        warn(f"{char} is invalid as characteristic of the ground field. 32003 is used.")
        char = 32003
    names = _at(items[1], lambda: _names(items[1], evaluate))
    clash = sorted(set(names) & set(params))
    if clash:
        raise MechRuntimeError(f"'{clash[0]}' is both a parameter and a variable", items[1].pos, None, True)
    blocks = _at(items[2], lambda: _ordering(items[2], evaluate, len(names)))
    return _at(items[0], lambda: make_ring(char, params, names, blocks))


def _is_prime(n: int) -> bool:
    import flint
    return bool(flint.fmpz(n).is_prime())


def _at(node: A.Expr, build: Callable[[], Any]) -> Any:
    """Run ``build``, locating its errors (the kernel's too) at ``node``, the part of the declaration
    they concern."""
    try:
        return build()
    except Exception as e:
        raise convert_exception(e).locate(node.pos, None, True) from None


def _characteristic(node: A.Expr, evaluate: Evaluate) -> tuple[int, tuple[str, ...]]:
    params: list[str] = []
    if isinstance(node, A.Tuple):
        params = _names(A.Tuple(node.items[1:], pos=node.pos), evaluate)
        node = node.items[0]
    if isinstance(node, A.Name) and node.id in ("real", "complex"):
        raise MechRuntimeError(f"{node.id} coefficients are not supported (use 0 for the rationals)")
    if isinstance(node, A.Name) and node.id == "QQ":  # Singular's name of the rationals (charstr gives it)
        return 0, tuple(params)
    v = evaluate(node)
    if isinstance(v, bool) or not isinstance(v, int):
        raise MechRuntimeError("the characteristic must be 0 or a prime number")
    return v, tuple(params)


def indexed_names(node: A.Expr, evaluate: Evaluate) -> list[str] | None:
    """The names ``x(1)``, ``x(2)``, ... that ``x(1..2)`` or ``y(1..2)(1..3)`` stand for, and the one name
    ``a(3,2)`` of several int indices (None when the node is not such a call or an index is not an int or
    intvec)."""
    levels: list[list[A.Expr]] = []
    while isinstance(node, A.Call):
        levels.append(node.args)
        node = node.func
    if not isinstance(node, A.Name) or not levels:
        return None
    names = [node.id]
    for args in reversed(levels):
        values = [evaluate(a) for a in args]
        if any(isinstance(v, bool) or not isinstance(v, (int, IntVec)) for v in values):
            return None
        if len(values) > 1:  # a(3,2,3): one name with several int indices, as Singular
            if not all(isinstance(v, int) for v in values):
                return None
            names = [f"{n}({','.join(map(str, values))})" for n in names]
            continue
        idx = _ints(values[0], "an index") if values else []
        if not idx:
            return None
        names = [f"{n}({i})" for n in names for i in idx]
    return names


def _names(node: A.Expr, evaluate: Evaluate) -> list[str]:
    items = node.items if isinstance(node, A.Tuple) else [node]
    names: list[str] = []
    for it in items:
        if isinstance(it, A.Name):
            names.append(it.id)
            continue
        indexed = indexed_names(it, evaluate)
        if indexed is None:
            raise MechRuntimeError("expected a variable name such as x or x(1..5)")
        names.extend(indexed)
    if len(set(names)) != len(names):
        raise MechRuntimeError("variable names must be distinct")
    if not names:
        raise MechRuntimeError("a ring needs at least one variable")
    return names


def _ordering(node: A.Expr, evaluate: Evaluate, nvars: int) -> list[OrderBlock]:
    items: list[OrderItem] = []
    for it in node.items if isinstance(node, A.Tuple) else [node]:
        if isinstance(it, A.Name):
            items.append((it.id, None))
        elif isinstance(it, A.Call) and isinstance(it.func, A.Name):
            items.append((it.func.id, _int_args(it.args, evaluate, "an ordering's size or weights")))
        else:
            raise MechRuntimeError("expected an ordering such as dp, wp(1,2,3) or (dp(2),lp(1))")
    return _merge_lp([_unit_weights(b) for b in order_blocks(items, nvars)])


def _unit_weights(b: OrderBlock) -> OrderBlock:
    """As Singular's ring declarations: ``wp(1,..,1)`` is ``dp`` (``Wp``: ``Dp``)."""
    if b.kind in ("wp", "Wp") and all(w == 1 for w in b.weights):
        return OrderBlock(b.kind.replace("w", "d").replace("W", "D"), b.size)
    return b


def parse_ordering(text: str, nvars: int) -> list[OrderBlock]:
    """The blocks of an ordering written as a string, ``"(dp(3),ws(1,2,3),ds)"`` (what library
    procedures take; as Singular's ``ring(L)`` from a ring list, unlike a ring declaration, it keeps
    ``wp(1,..,1)`` and ``(dp(1),lp(2))`` as written)."""
    items = ordering_items(text)
    if not items:
        raise MechRuntimeError(f"not an ordering: \"{text}\"")
    return order_blocks(items, nvars)


def ordering_items(text: str) -> list[OrderItem]:
    """The blocks of an ordering string, each with its integer arguments."""
    items: list[OrderItem] = []
    for kind, args in re.findall(r"([A-Za-z]+)\s*(\([^()]*\))?", text):
        try:
            items.append((kind, [int(a) for a in args[1:-1].split(",") if a.strip()] if args else None))
        except ValueError:
            raise MechRuntimeError(f"not an ordering: \"{text}\" (sizes and weights are integers)") from None
    return items


def order_blocks(items: list[OrderItem], nvars: int) -> list[OrderBlock]:
    """The blocks of an ordering for ``nvars`` variables, as Singular reads them: a block without a size
    (only the last) covers the variables left, ``a`` is cut to them, a module ordering ``C`` is added
    when none is given."""
    blocks: list[OrderBlock] = []
    covered = 0
    for k, (kind, args) in enumerate(items):
        if kind not in ORDERINGS:
            raise MechRuntimeError(f"unknown ordering '{kind}' (known: lp dp Dp wp Wp ls ds Ds ws Ws a M c C)")
        if kind in ("c", "C"):
            if args:
                raise MechRuntimeError(f"the module ordering {kind} takes no arguments")
            blocks.append(OrderBlock(kind))
            continue
        if kind in WEIGHTED:
            if not args:
                raise MechRuntimeError(f"the ordering {kind} needs weights, e.g. {kind}(1,2,3)")
            if kind == "a":  # as in Singular, a weight prefix is cut to the variables left
                args = args[:nvars - covered]
                if not args:
                    continue
            blocks.append(OrderBlock(kind, len(args), tuple(args)))
        elif kind == "M":
            n = math.isqrt(len(args or []))
            if not args or n * n != len(args):
                raise MechRuntimeError("a matrix ordering M(...) needs n*n entries")
            blocks.append(OrderBlock("M", n, tuple(args)))
        else:
            if args is None:
                rest = nvars - covered
                if any(a is not None or later not in ("c", "C") for later, a in items[k + 1:]):
                    raise MechRuntimeError(f"the ordering {kind} without a size must be the last block")
                size = rest
            elif len(args) != 1:
                raise MechRuntimeError(f"the ordering {kind} takes one size, e.g. {kind}(3)")
            else:
                size = args[0]
            if size <= 0:
                raise MechRuntimeError(f"the ordering {kind} must cover at least one variable")
            blocks.append(OrderBlock(kind, size))
        if kind != "a":
            covered += blocks[-1].size
    if covered != nvars:
        raise MechRuntimeError(f"the ordering covers {covered} variables, the ring has {nvars}")
    if not any(b.kind in ("c", "C") for b in blocks):
        blocks.append(OrderBlock("C"))
    return blocks


def _merge_lp(blocks: list[OrderBlock]) -> list[OrderBlock]:
    """As Singular: a degree block of one variable before an lp block is lp, and adjacent lp blocks
    are one ((dp(1),lp(2)) is lp(3)): the same ordering."""
    out: list[OrderBlock] = []
    for k, b in enumerate(blocks):
        nxt = blocks[k + 1] if k + 1 < len(blocks) else None
        if b.kind in ("dp", "Dp", "wp", "Wp") and b.size == 1 and nxt is not None and nxt.kind == "lp":
            b = OrderBlock("lp", 1)
        if b.kind == "lp" and out and out[-1].kind == "lp":
            b = OrderBlock("lp", out.pop().size + b.size)
        out.append(b)
    return out


def make_ring(char: int, params: tuple[str, ...] | list[str], names: list[str], blocks: list[OrderBlock]) -> Ring:
    """A ring from its data; equal data share one kernel ring (so their values mix)."""
    params = tuple(params)
    key = (char, params, tuple(names), tuple(blocks))
    poly = _ring_cache.get(key)
    if poly is None:
        field = _field(char, params)
        kblocks = [k for b in blocks if b.kind not in ("c", "C") for k in _kernel_blocks(b)]
        order = MonomialOrder(kblocks, len(names))
        poly = _ring_cache[key] = PolyRing(field, names, order)
        note_blocks(poly, tuple(blocks))
    return Ring(poly, params, tuple(blocks))


def _kernel_blocks(b: OrderBlock) -> list[Block]:
    """The kernel's blocks for one block as written: Singular orders by ``wp(w)`` (``Wp(w)``) with a
    weight <= 0 as by ``(a(w), dp)`` (``(a(w), Dp)``); ``ws`` keeps its reverse lexicographic tie-break."""
    if b.kind in ("wp", "Wp") and any(w <= 0 for w in b.weights):
        return [Block("a", b.size, b.weights), Block(b.kind.replace("w", "d").replace("W", "D"), b.size)]
    return [Block(b.kind, b.size, b.weights)]


def _field(char: int, params: tuple[str, ...]) -> Any:
    if char == 0:
        base = QQ
    else:
        base = GF(char)
    if not params:
        return base
    from ..kernel.ratfunc import RationalFunctionField
    return RationalFunctionField(char, params)


def ring_sum(a: Ring, b: Ring) -> Ring:
    """Singular's ``R + S``: the ring over both coefficient fields (QQ and Z/p give Z/p) in the
    variables of R then S, ordered by R's blocks then S's (R's module component block kept first or
    last); R + R is R."""
    from ..kernel.algext import AlgebraicField
    from .qrings import quotient_of
    if a.poly == b.poly and a.params == b.params:
        return a
    for r in (a, b):
        if quotient_of(r.poly) is not None or isinstance(r.poly.field, AlgebraicField):
            raise MechRuntimeError("the sum of quotient rings or rings with a minpoly is not supported")
    shared = set(a.names + a.params) & set(b.names + b.params)
    if shared:
        raise MechRuntimeError(f"ring sum: both rings have the names {', '.join(sorted(shared))}")
    ca, cb = a.characteristic, b.characteristic
    if ca and cb and ca != cb:
        raise MechRuntimeError(f"ring sum: the characteristics {ca} and {cb} differ")
    comp = [bl for bl in a.blocks if bl.kind in ("c", "C")]
    first = bool(comp) and a.blocks[0].kind in ("c", "C")
    inner = [bl for bl in a.blocks + b.blocks if bl.kind not in ("c", "C")]
    blocks = (comp + inner) if first else (inner + comp)
    return make_ring(ca or cb, a.params + b.params, list(a.names + b.names), blocks)
