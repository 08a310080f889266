"""``print(x, format)`` (the formatted text as a string) and standard.lib's ``sprintf``/``printf``.

Formats: ``%s`` the value as ``string`` writes it, ``%p`` as ``print`` shows it, ``%2s``/``%2p`` the same
followed by a newline.  ``sprintf(fmt, ...)`` copies fmt, replacing each conversion ``%s``, ``%p``,
``%2s``, ... by the next argument so formatted; ``%n`` and ``%2`` give a newline without taking an argument;
when the arguments run out the rest of fmt is copied as it is (as standard.lib does).  A list argument is
flattened by one level, as in Singular's procedure calls."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.printing import print_form, value_str
from ..dsl.registry import command
from ..dsl.values import List

_FORMATS = ("%l", "%s", "%2l", "%2s", "%t", "%;", "%p", "%b", "%n", "%2")


@command("print")
def print_format(x: Any, fmt: str) -> str:
    """print(x, format): x formatted as a string: "%s" as string(x), "%p" as print(x) shows it, "%2s" and
    "%2p" the same followed by a newline.

    Example:
      ring r = 0,(x,y),dp;
      print(ideal(x2, y), "%s");
      → x2,y
      print(ideal(x2, y), "%p");
      → x2,
      → y
    """
    base = fmt.replace("%2", "%", 1) if fmt.startswith("%2") else fmt
    if base == "%s":
        text = value_str(x)
    elif base == "%p":
        text = print_form(x)
    else:
        raise MechRuntimeError(f'print(x, "{fmt}"): the format {fmt} is not supported (only %s, %p, %2s, %2p)')
    return text + "\n" if fmt.startswith("%2") else text


def _flatten(args: tuple[Any, ...]) -> list[Any]:
    out: list[Any] = []
    for a in args:
        out.extend(a.items if isinstance(a, List) else [a])
    return out


@command("sprintf")
def sprintf(fmt: str, *args: Any) -> str:
    """sprintf(fmt, ...): fmt with its conversions (%s, %p, %2s, %2p; %n and %2 a newline) replaced by the
    arguments formatted as print(x, format) does.

    Example:
      ring r = 0,(x,y),dp;
      sprintf("s:%s,%n p:%p", 1, ideal(x, y));
      → s:1,
      →  p:x,
      → y
    """
    rest = _flatten(args)
    if len(fmt) <= 1:
        return fmt
    out = ""
    while True:
        if not rest:
            return out + fmt
        pos, conv = -1, ""
        for k, ch in enumerate(fmt):
            if ch == "%":
                conv = next((f for f in _FORMATS if fmt.startswith(f, k)), "")
                if conv:
                    pos = k
                    break
        if pos < 0:
            return out + fmt
        if conv in ("%2", "%n"):
            out += fmt[:pos] + "\n"
        else:
            out += fmt[:pos] + print_format(rest.pop(0), conv)
        if len(fmt) <= pos + len(conv):
            return out
        fmt = fmt[pos + len(conv):]


@command("printf")
def printf(ctx, fmt: str, *args: Any) -> None:
    """printf(fmt, ...): print sprintf(fmt, ...).

    Example:
      printf("%s and %s", 1, 2);
      → 1 and 2
    """
    ctx.write(sprintf(fmt, *args) + "\n")
