"""Design sets of a sweep: the parameter points at which a mechanism is analysed.

A design set is described by a short text (the language, the CLI and Python share it):

* ``grid l1=1:4:50 l2=1/2:3:20`` — every combination of ``n`` equally spaced exact values from
  ``a`` to ``b`` (``name=a:b:n``; ``name=v`` fixes a parameter);
* ``random N l1=1:4 l2=1:4 [seed=S] [digits=D]`` — ``N`` uniform points, each coordinate rounded
  to ``D`` decimals (default 3; exact rationals keep the analyses exact and small);
* ``lhs N ...`` — a Latin hypercube of ``N`` points (one point in each of ``N`` slices of every
  range; McKay, Beckman and Conover 1979), rounded the same way;
* ``csv FILE`` — one design a row, a header naming the parameters.

Designs are numbered from 0 in a fixed order (the same seed gives the same designs), which is what
lets an interrupted sweep resume where it stopped.
"""
from __future__ import annotations

import csv
import itertools
import random
import re
from dataclasses import dataclass
from fractions import Fraction

from mech.dsl.convert import parse_decimal
from mech.dsl.errors import MechRuntimeError

Design = dict[str, Fraction]

SYNTAX = ("grid NAME=a:b:n ... | random N NAME=a:b ... [seed=S] [digits=D] | lhs N NAME=a:b ... "
          "[seed=S] [digits=D] | csv FILE")


@dataclass
class DesignSet:
    """The designs (parameter name -> exact value), in their fixed order."""

    names: list[str]
    designs: list[Design]
    description: str


def _number(text: str, where: str) -> Fraction:
    try:
        return parse_decimal(text)
    except ValueError as e:
        raise MechRuntimeError(f"designs: {where}: {e}") from None


def _count(text: str, where: str) -> int:
    if not re.fullmatch(r"\d+", text) or int(text) < 1:
        raise MechRuntimeError(f"designs: {where}: expected a positive count, got '{text}'")
    return int(text)


def _ranges(words: list[str], with_count: bool) -> tuple[dict[str, list[Fraction] | Fraction], dict[str, str]]:
    """``name=a:b[:n]`` and ``name=v`` words, and ``seed=``/``digits=`` options."""
    ranges: dict[str, list[Fraction] | Fraction] = {}
    options: dict[str, str] = {}
    for w in words:
        name, eq, value = w.partition("=")
        if not eq or not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name):
            raise MechRuntimeError(f"designs: '{w}' is not NAME=a:b{':n' if with_count else ''} ({SYNTAX})")
        if name in ("seed", "digits") and not with_count:
            options[name] = value
            continue
        parts = value.split(":")
        if len(parts) == 1:
            ranges[name] = _number(parts[0], w)
        elif len(parts) == (3 if with_count else 2):
            lo, hi = _number(parts[0], w), _number(parts[1], w)
            if with_count:
                n = _count(parts[2], w)
                ranges[name] = [lo] if n == 1 else [lo + (hi - lo) * i / (n - 1) for i in range(n)]
            else:
                ranges[name] = [lo, hi]
        else:
            raise MechRuntimeError(f"designs: '{w}': expected NAME=a:b{':n' if with_count else ''} or NAME=v")
    if not ranges:
        raise MechRuntimeError(f"designs: no parameter given ({SYNTAX})")
    return ranges, options


def _grid(words: list[str]) -> tuple[list[str], list[Design]]:
    ranges, _ = _ranges(words, True)
    names = list(ranges)
    axes = [v if isinstance(v, list) else [v] for v in ranges.values()]
    return names, [dict(zip(names, point)) for point in itertools.product(*axes)]


def _sampled(words: list[str], latin: bool) -> tuple[list[str], list[Design]]:
    if not words:
        raise MechRuntimeError(f"designs: give the number of designs ({SYNTAX})")
    n = _count(words[0], words[0])
    ranges, options = _ranges(words[1:], False)
    seed = int(_number(options.get("seed", "0"), "seed"))
    digits = int(_number(options.get("digits", "3"), "digits"))
    rng = random.Random(seed)
    names = list(ranges)
    columns: dict[str, list[Fraction]] = {}
    for name, r in ranges.items():
        if not isinstance(r, list):
            columns[name] = [r] * n
            continue
        if latin:  # one point in each of the n slices, slices in random order per parameter
            slots = list(range(n))
            rng.shuffle(slots)
            units = [(k + rng.random()) / n for k in slots]
        else:
            units = [rng.random() for _ in range(n)]
        lo, hi = r
        columns[name] = [_round(lo + (hi - lo) * Fraction(u), digits) for u in units]
    return names, [{name: columns[name][i] for name in names} for i in range(n)]


def _round(x: Fraction, digits: int) -> Fraction:
    return Fraction(round(x * 10 ** digits), 10 ** digits)


def _csv(words: list[str]) -> tuple[list[str], list[Design]]:
    if len(words) != 1:
        raise MechRuntimeError("designs: csv FILE (one file name)")
    try:
        with open(words[0], newline="", encoding="utf-8-sig") as fh:
            rows = list(csv.reader(fh))
    except OSError as e:
        raise MechRuntimeError(f"designs: cannot read {words[0]}: {e.strerror}") from None
    if not rows:
        raise MechRuntimeError(f"designs: {words[0]} is empty")
    names = [h.strip() for h in rows[0]]
    designs = []
    for k, row in enumerate(rows[1:], 2):
        if not any(c.strip() for c in row):
            continue
        if len(row) != len(names):
            raise MechRuntimeError(f"designs: {words[0]}:{k}: {len(row)} values, {len(names)} columns")
        designs.append({n: _number(v, f"{words[0]}:{k}") for n, v in zip(names, row)})
    return names, designs


def design_set(text: str) -> DesignSet:
    """The designs described by ``text`` (see the module's docstring)."""
    words = text.replace(",", " ").split()
    if not words:
        raise MechRuntimeError(f"designs: empty description ({SYNTAX})")
    kind, rest = words[0].lower(), words[1:]
    if kind == "grid":
        names, designs = _grid(rest)
    elif kind in ("random", "lhs"):
        names, designs = _sampled(rest, kind == "lhs")
    elif kind == "csv":
        names, designs = _csv(text.split(None, 1)[1:] if len(words) > 1 else [])
    else:
        raise MechRuntimeError(f"designs: unknown kind '{words[0]}' ({SYNTAX})")
    return DesignSet(names, designs, text)
