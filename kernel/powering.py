"""Powers by repeated squaring, for any multiplication (polynomials, matrices, ideals, field elements)."""
from __future__ import annotations

from operator import mul as _mul
from typing import Any, Callable


def power(base: Any, k: int, one: Any, mul: Callable[[Any, Any], Any] = _mul) -> Any:
    """``base^k`` for an integer ``k >= 0`` with ``mul`` as the product and ``one`` as ``base^0``."""
    result = one
    while k:
        if k & 1:
            result = mul(result, base)
        k >>= 1
        if k:
            base = mul(base, base)
    return result
