"""Macaulay2's monomial orders (``MonomialOrder => ...`` of a ring) as Singular's ordering blocks."""
from __future__ import annotations

from typing import Any, Sequence

from .errors import MechRuntimeError
from .m2_values import Opt, Symbol
from .rings import MAX_WEIGHT
from .values import ExprList, List, OrderBlock

#: Macaulay2's orders of a block: (Singular's kind, with degrees other than 1: the weighted kind);
#: GLex weighs every variable by 1 whatever its degree (Macaulay2: ``Weights => {1, ..., 1}, Lex``)
_KINDS = {"GRevLex": ("dp", "wp"), "Lex": ("lp", "lp"), "GLex": ("Dp", "Dp"), "RevLex": ("rs", "rs")}
#: options of an order list that do not change the order
_IGNORED = {"Position", "MonomialSize"}


def _items(spec: Any) -> list[Any]:
    """The blocks of an order spec, sequences (``3:1``) spliced in."""
    out: list[Any] = []
    for item in (spec.items if isinstance(spec, List) else [spec]):
        out.extend(item.items if isinstance(item, ExprList) else [item])
    return out


def order_blocks(spec: Any, n: int, degrees: Sequence[int] = (), fill: bool = True) -> list[OrderBlock]:
    """Singular's blocks for Macaulay2's ``MonomialOrder => spec`` on ``n`` variables of these
    ``degrees``: GRevLex (dp, or wp by the degrees), Lex (lp), GLex (Dp), RevLex (the
    negative unit matrix: x^a > x^b when the first nonzero entry of a - b is negative),
    ``Weights => w`` (a weight row), ``Eliminate k`` (the weight
    row 1,..,1,0,..,0), a number k (GRevLex on k variables), ``ProductOrder {k1, k2}`` (GRevLex
    blocks), ``GroupLex => k`` / ``GroupRevLex => k`` (the first k variables invertible: lex or revlex
    on their integer exponents), ``Kind => k`` or ``Kind => {weights}``
    and lists of these (``{GRevLex => 2, Lex => 3}``: blocks); variables left over get GRevLex
    (``fill``: unless False)."""
    degrees = list(degrees) or [1] * n
    items = _items(spec)
    blocks: list[OrderBlock] = []
    covered = 0
    for k, item in enumerate(items):
        last = k == len(items) - 1
        key = item.key.name if isinstance(item, Opt) and isinstance(item.key, Symbol) else None
        if key in _IGNORED:
            continue
        if isinstance(item, Symbol) and item.name in _KINDS:
            if not last:
                raise MechRuntimeError(f"{item.name} without a size covers the remaining variables: put it last")
            kind, size, weights = item.name, n - covered, None
        elif type(item) is int:
            kind, size, weights = "GRevLex", item, None
        elif key in _KINDS:
            kind, weights = key, None
            if key == "GLex":
                raise MechRuntimeError("GLex => ...: Macaulay2 takes GLex only without a size (the remaining variables)")
            if isinstance(item.value, List):  # {6:1} too: sequences spliced
                weights = [w for x in item.value.items for w in (x.items if isinstance(x, ExprList) else [x])]
                size = len(weights)
            else:
                size = item.value
            if type(size) is not int or not 0 < size <= MAX_WEIGHT or (weights and not all(type(w) is int and w > 0 for w in weights)):
                raise MechRuntimeError(f"{key} => n takes a positive number of variables or a list of positive weights")
        elif key in ("GroupLex", "GroupRevLex"):  # invertible variables (the ring's first): lex or revlex
            if k != 0 or type(item.value) is not int or not 0 < item.value <= n:
                raise MechRuntimeError(f"{key} => k takes the first 0 < k <= {n} variables, as the order's first block")
            blocks.append(_block("Lex" if key == "GroupLex" else "RevLex", [1] * item.value))
            covered += item.value
            continue
        elif key == "ProductOrder":  # blocks of GRevLex, as many variables as its numbers say
            sizes = _items(item.value)
            if not all(type(k) is int and k > 0 for k in sizes) or covered + sum(sizes) > n:
                raise MechRuntimeError(f"ProductOrder {{n1, n2, ...}} takes positive sizes covering at most {n} variables")
            for size in sizes:
                blocks.append(_block("GRevLex", degrees[covered:covered + size]))
                covered += size
            continue
        elif key in ("Weights", "Eliminate"):
            blocks.append(_prefix(key, item.value, n, covered))
            continue
        else:
            raise MechRuntimeError(f"unknown monomial order {_show(item)} (known: GRevLex, Lex, GLex, RevLex, "
                                   f"Weights => {{...}}, Eliminate k, ProductOrder, numbers, and lists of these)")
        if covered + size > n:
            raise MechRuntimeError(f"the monomial order covers more than the {n} variables")
        blocks.append(_block(kind, weights or degrees[covered:covered + size]))
        covered += size
    if covered < n and fill:
        blocks.append(_block("GRevLex", degrees[covered:]))
    return blocks


def position(spec: Any, n: int, degrees: Sequence[int] = ()) -> tuple[int, str]:
    """Where ``Position => Up|Down`` puts the free modules' basis index among the order's blocks:
    (the number of blocks before it, "Up" or "Down"); without it: after all blocks, Up."""
    items = _items(spec)
    for k, item in enumerate(items):
        if isinstance(item, Opt) and isinstance(item.key, Symbol) and item.key.name == "Position":
            way = item.value.name if isinstance(item.value, Symbol) else ""
            if way not in ("Up", "Down"):
                raise MechRuntimeError("Position => Up or Position => Down")
            return len(order_blocks(List(items[:k]), n, degrees, fill=False)), way
    return len(order_blocks(spec, n, degrees)), "Up"


def _block(kind: str, weights: list[int]) -> OrderBlock:
    plain, weighted = _KINDS[kind]
    if kind == "RevLex":
        size = len(weights)
        rows = [[-1 if j == i else 0 for j in range(size)] for i in range(size)]  # the first exponent, smaller first
        return OrderBlock("M", size, tuple(v for r in rows for v in r))
    if all(w == 1 for w in weights) or plain == weighted:
        return OrderBlock(plain, len(weights))
    return OrderBlock(weighted, len(weights), tuple(weights))


def _prefix(key: str, value: Any, n: int, covered: int) -> OrderBlock:
    """``Weights => w`` or ``Eliminate k``: a weight row on the variables from ``covered`` on."""
    if key == "Weights":
        w = list(value.items) if isinstance(value, (List, ExprList)) else None  # 4:1 too
        if w is None or not all(type(x) is int for x in w) or len(w) > n - covered:
            raise MechRuntimeError(f"Weights => {{...}} takes at most {n - covered} integers")
        if any(abs(x) > MAX_WEIGHT for x in w):
            raise MechRuntimeError(f"Weights => {{...}}: a weight must be at most {MAX_WEIGHT} in absolute value")
    else:
        if type(value) is not int or not 0 <= value <= n - covered:
            raise MechRuntimeError(f"Eliminate k takes 0 <= k <= {n - covered}")
        w = [1] * value
    return OrderBlock("a", 0, tuple(w + [0] * (n - covered - len(w))))  # from the variable after `covered`


def _show(item: Any) -> str:
    from .m2_printing import to_string
    return to_string(item)
