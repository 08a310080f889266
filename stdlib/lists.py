"""Lists: ``delete`` and ``insert`` (``list(...)`` builds one, :mod:`mech.stdlib.conversions`)."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import NONE, List


@command("delete")
def delete(L: List, i: int) -> List:
    """delete(L, i): the list L without its i-th entry.

    Example:
      list L = 1, 2, 3;
      delete(L, 2);
      → [1]:
      →    1
      → [2]:
      →    3
    """
    if not 1 <= i <= len(L):
        raise MechRuntimeError(f"delete: index {i} out of range (the list has {len(L)} entries)")
    return List(L.items[:i - 1] + L.items[i:])


@command("insert")
def insert(L: List, v: Any, i: int = 0) -> List:
    """insert(L, v) or insert(L, v, i): the list L with v inserted after position i (default 0).

    Example:
      list L = 1, 2;
      insert(L, 5);
      → [1]:
      →    5
      → [2]:
      →    1
      → [3]:
      →    2
      insert(L, 5, 2);
      → [1]:
      →    1
      → [2]:
      →    2
      → [3]:
      →    5
    """
    if i < 0:
        raise MechRuntimeError(f"insert: position {i} out of range (at least 0)")
    items = tuple(L.items) + (NONE,) * (i - len(L))  # as Singular: a position beyond the end pads with none
    return List(items[:i] + (v,) + items[i:])
