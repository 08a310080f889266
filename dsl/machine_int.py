"""Singular's machine int: literals beyond 2^31-1 are bigints; ``+ - * ^`` compute in 64 bits and wrap
around with Singular's warning ``int overflow(op), result may be wrong``; ``div`` and ``mod`` read their
operands as 32-bit ints (Singular casts them so: ``2^31 div 2`` is -1073741824)."""
from __future__ import annotations

from typing import Callable, Optional

from .values import BigInt

INT_MAX = 2 ** 31 - 1
_W64 = 2 ** 64
MIN64, MAX64 = -2 ** 63, 2 ** 63 - 1


def literal(value: int) -> int:
    """The value of an integer literal: an int, or a bigint beyond 2^31-1 (as Singular reads it)."""
    return BigInt(value) if value > INT_MAX else value


def int32(a: int) -> int:
    """``a`` cut to a signed 32-bit int."""
    return (a + 2 ** 31) % 2 ** 32 - 2 ** 31


def wrap64(r: int, op: str, warn: Callable[[str], None]) -> int:
    """``r`` as a signed 64-bit int; beyond that range wrapped, with Singular's warning."""
    if MIN64 <= r <= MAX64:
        return r
    warn(f"int overflow({op}), result may be wrong")
    return (r - MIN64) % _W64 + MIN64


def int_binary(op: str, a: int, b: int, warn: Callable[[str], None]) -> Optional[int]:
    """``a op b`` of two ints with Singular's machine semantics, or None for operators it leaves to the
    general arithmetic (``/``, ``:``, comparisons)."""
    if op == "+":
        return wrap64(a + b, op, warn)
    if op == "-":
        return wrap64(a - b, op, warn)
    if op == "*":
        return wrap64(a * b, op, warn)
    if op == "^" and b >= 0:
        return _power(a, b, warn)
    if op in ("div", "mod", "%"):
        from .ops import trunc_div, trunc_mod
        x, y = int32(a), int32(b)
        return trunc_div(x, y) if op == "div" else trunc_mod(x, y)
    return None


def _power(a: int, k: int, warn: Callable[[str], None]) -> int:
    """a^k in 64 bits: wrapped once, with one warning, as Singular does."""
    if abs(a) <= 1 or k * abs(a).bit_length() <= 130:  # small enough to compute exactly
        r = a ** k
        if MIN64 <= r <= MAX64:
            return r
    warn("int overflow(^), result may be wrong")
    r = pow(a, k, _W64)
    return r - _W64 if r > MAX64 else r
