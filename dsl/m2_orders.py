"""Macaulay2's monomial orders (``MonomialOrder => ...`` of a ring) as Singular's ordering blocks."""
from __future__ import annotations

from typing import Any

from .errors import MechRuntimeError
from .m2_printing import Opt, Symbol, to_string
from .rings import MAX_WEIGHT
from .values import List, OrderBlock

_KINDS = {"GRevLex": "dp", "Lex": "lp", "GLex": "Dp"}


def order_blocks(spec: Any, n: int) -> list[OrderBlock]:
    """Singular's blocks for Macaulay2's ``MonomialOrder => spec`` on ``n`` variables: GRevLex (dp),
    Lex (lp), GLex (Dp), ``Weights => w`` (a weight row, then GRevLex), ``Eliminate k`` (the weight
    row 1,..,1,0,..,0, then GRevLex) and lists of these (``{GRevLex => 2, Lex => 3}``: blocks)."""
    items = spec.items if isinstance(spec, List) else [spec]
    blocks: list[OrderBlock] = []
    covered = 0
    for k, item in enumerate(items):
        last = k == len(items) - 1
        if isinstance(item, Symbol) and item.name in _KINDS:
            if not last:
                raise MechRuntimeError(f"{item.name} without a size covers the remaining variables: put it last")
            size = n - covered
        elif isinstance(item, Opt) and isinstance(item.key, Symbol) and item.key.name in _KINDS:
            size = item.value
            if type(size) is not int or not 0 < size <= MAX_WEIGHT:
                raise MechRuntimeError(f"{item.key.name} => n takes a positive number of variables")
        elif isinstance(item, Opt) and isinstance(item.key, Symbol) and item.key.name in ("Weights", "Eliminate"):
            if item.key.name == "Weights":
                w = item.value.items if isinstance(item.value, List) else None
                if w is None or not all(type(x) is int for x in w) or len(w) > n - covered:
                    raise MechRuntimeError(f"Weights => {{...}} takes at most {n - covered} integers")
                if any(abs(x) > MAX_WEIGHT for x in w):
                    raise MechRuntimeError(f"Weights => {{...}}: a weight must be at most {MAX_WEIGHT} in absolute value")
            else:
                if type(item.value) is not int or not 0 <= item.value <= n - covered:
                    raise MechRuntimeError(f"Eliminate k takes 0 <= k <= {n - covered}")
                w = [1] * item.value
            blocks.append(OrderBlock("a", 0, tuple([0] * covered + list(w) + [0] * (n - covered - len(w)))))
            continue
        else:
            raise MechRuntimeError(f"unknown monomial order {to_string(item)} (known: GRevLex, Lex, GLex, "
                                   f"Weights => {{...}}, Eliminate k, and lists of these)")
        if covered + size > n:
            raise MechRuntimeError(f"the monomial order covers more than the {n} variables")
        blocks.append(OrderBlock(_KINDS[item.key.name if isinstance(item, Opt) else item.name], size))
        covered += size
    if covered < n:
        blocks.append(OrderBlock("dp", n - covered))
    return blocks
