"""Statement templates: one-line statements that differ only in their number literals share one tree
and one closure (long scripts are mostly a few statement shapes with changing numbers).

:func:`shape` splits a statement's text into its shape (the text with each number replaced) and
its numbers as written; :func:`make` turns the tree of a statement into the :class:`Template` of
its shape, or refuses it (procedures, ``return`` and the other statements the fast parser leaves to
Lark; a number that is not a whole literal of the tree).  A :class:`~mech.dsl.ast.Relit` runs
the template's closure with its own numbers (the interpreter's ``lits``); the closure is
:mod:`~mech.dsl.compiled`'s with each literal reading its number there, and the parts that go back
to the evaluator get a copy of their subtree with the numbers put in (:meth:`Template.actual`).
Errors are moved from the template's line and columns to the statement's own
(:meth:`Template.move`).
"""
from __future__ import annotations

import re
import threading
from typing import Any, Callable, Optional

from ..kernel import Poly
from . import ast as A
from . import compiled
from .machine_int import literal

#: a number literal (or a rational's numerator or denominator, or a monomial's coefficient): digits
#: not glued to a name or to more digits (longer ones stay in the shape: the builder checks them)
_NUMBER = re.compile(r"(?<![A-Za-z0-9_@'])[0-9]{1,18}(?![0-9])")
_MARK = "\0"
_COMPILING = threading.Lock()  # compiled.templating's tables are the module's: one template at a time
KINDS = (A.Assign, A.ExprStmt, A.Decl, A.IncDec, A.If, A.For, A.While, A.Block)


_SPLIT = re.compile(f"({_NUMBER.pattern})")


def shape(piece: str) -> Optional[tuple[str, list[str]]]:
    """``(shape, numbers)`` of a one-line statement's text, None when it has no number, a string or
    a comment (their digits are not literals).  One pass: the text split at its numbers."""
    parts = _SPLIT.split(piece)
    if len(parts) == 1 or '"' in piece or "/*" in piece or "//" in piece:
        return None
    return _MARK.join(parts[0::2]), parts[1::2]


class Template:
    """The tree of one statement of a shape, the columns of its numbers, and its closure."""

    def __init__(self, tree: A.Stmt, spans: list[tuple[int, int]], slots: dict[int, tuple],
                 holders: set[int]) -> None:
        self.tree = tree
        self.spans = spans          # (start, end) column of each number in the template's line
        self.slots = slots          # id of a literal node -> (kind, its numbers' indices, node)
        self.holders = holders      # ids of the nodes with a literal node below them (or being one)
        self.fields: dict[int, list[str]] = {}  # id of a holder -> its attributes holding literals

    def compile(self) -> None:
        """The tree's closure with the literals read from ``it.lits`` (kept on the tree)."""
        fns = {i: _slot_fn(*slot) for i, slot in self.slots.items()}
        with _COMPILING, compiled.templating(fns, self.holders, self.actual):
            for stmt in _statements(self.tree):  # the inner ones too: each runs its own closure
                compiled.stmt_fn(stmt)

    def actual(self, node: Any, lits: list[str]) -> Any:
        """``node`` of the template with the numbers ``lits`` put in (a copy where it holds literals)."""
        if isinstance(node, A.Node):
            key = id(node)
            if key not in self.holders:
                return node
            slot = self.slots.get(key)
            if slot is not None:
                return _literal(slot, lits)
            fields = self.fields.get(key)
            if fields is None:  # the attributes with literals below them, found once
                fields = self.fields[key] = [k for k, v in node.__dict__.items()
                                             if k != "_fn" and k != "_seen" and self._holds(v)]
            state = {k: v for k, v in node.__dict__.items() if k != "_fn" and k != "_seen"}
            for k in fields:
                state[k] = self.actual(state[k], lits)
            new = object.__new__(type(node))
            new.__dict__.update(state)
            return new
        if isinstance(node, list):
            return [self.actual(v, lits) for v in node]
        return node

    def _holds(self, value: Any) -> bool:
        """Whether a node's attribute value has a literal in it (is or holds a holder)."""
        if isinstance(value, A.Node):
            return id(value) in self.holders
        return isinstance(value, list) and any(self._holds(v) for v in value)

    def move(self, pos: A.Pos, dline: int, lits: list[str]) -> A.Pos:
        """A position on the template's line as a position on the line ``dline`` further of the
        statement with the numbers ``lits`` (columns after a number move by its change of length)."""
        return A.Pos(pos.line + dline, self._col(pos.col, lits), pos.end_line + dline, self._col(pos.end_col, lits))

    def _col(self, col: int, lits: list[str]) -> int:
        out = col
        for (start, end), lit in zip(self.spans, lits):
            if end > col:
                break
            out += len(lit) - (end - start)
        return out


def _statements(stmt: A.Stmt) -> list[A.Stmt]:
    """``stmt`` and the statements inside it (of blocks, branches and loops), innermost first."""
    out: list[A.Stmt] = []
    for inner in (getattr(stmt, "init", None), getattr(stmt, "step", None), *getattr(stmt, "body", ()),
                  *getattr(stmt, "then", ()), *(getattr(stmt, "orelse", None) or ())):
        if inner is not None:
            out.extend(_statements(inner))
    out.append(stmt)
    return out


def make(tree: A.Stmt, piece: str, col: int, lits: list[str]) -> Optional[Template]:
    """The template of the one-line statement ``tree`` (text ``piece`` starting at column ``col``,
    numbers ``lits``), or None when its numbers are not exactly its literals."""
    if type(tree) not in KINDS:
        return None
    spans = []
    for m in _NUMBER.finditer(piece):
        spans.append((col + m.start(), col + m.end()))
    if len(spans) != len(lits):
        return None
    at = {start: k for k, (start, _) in enumerate(spans)}
    slots: dict[int, tuple] = {}
    holders: set[int] = set()
    used: set[int] = set()

    def walk(node: Any) -> bool:
        if isinstance(node, list):
            found = False
            for v in node:
                found = walk(v) | found
            return found
        if not isinstance(node, A.Node):
            return False
        kind = type(node)
        if kind is A.IntLit or kind is A.RatLit or kind is A.MonomLit:
            slot = _slot(node, kind, at, spans, piece, col)
            if slot is None:
                return False
            slots[id(node)] = slot
            used.update(slot[1])
            holders.add(id(node))
            return True
        found = False
        for k, v in node.__dict__.items():
            if k != "pos" and k != "_fn" and k != "_seen":
                found = walk(v) | found
        if found:
            holders.add(id(node))
        return found

    walk(tree)
    if len(used) != len(spans):  # a number that is no literal of the tree (or part of a longer one)
        return None
    return Template(tree, spans, slots, holders)


def _slot(node: Any, kind: type, at: dict, spans: list, piece: str, col: int) -> Optional[tuple]:
    """(kind, indices of its numbers, node) of a literal node starting at a number, else None."""
    k = at.get(node.pos.col)
    if k is None or node.pos.line != node.pos.end_line:
        return None
    end = spans[k][1]
    if kind is A.IntLit:
        return (kind, (k,), node) if node.pos.end_col == end else None
    den = k + 1 if (k + 1 < len(spans) and piece[end - col:end - col + 1] == "/"
                    and spans[k + 1][0] == end + 1) else None
    if kind is A.RatLit:
        return (kind, (k, den), node) if den is not None and node.pos.end_col == spans[den][1] else None
    return (kind, (k,) if den is None else (k, den), node)  # a monomial: its coefficient


def _literal(slot: tuple, lits: list[str]) -> A.Expr:
    """The literal node of ``slot`` with the numbers ``lits``."""
    kind, idx, node = slot
    if kind is A.IntLit:
        return A.IntLit(literal(int(lits[idx[0]])), pos=node.pos)
    if kind is A.RatLit:
        return A.RatLit(int(lits[idx[0]]), int(lits[idx[1]]), pos=node.pos)
    den = int(lits[idx[1]]) if len(idx) > 1 else 1
    return A.MonomLit(int(lits[idx[0]]), den, node.monomial, pos=node.pos)


def _slot_fn(kind: type, idx: tuple, node: Any) -> Callable[[Any], Any]:
    if kind is A.IntLit:
        k = idx[0]
        return lambda it: literal(int(it.lits[k]))
    slot = (kind, idx, node)
    if kind is A.MonomLit:
        return _monomial_fn(slot)
    return lambda it: it._eval_node(_literal(slot, it.lits))


def _monomial_fn(slot: tuple) -> Callable[[Any], Any]:
    """A monomial literal's closure: its monomial found once per ring (the evaluator's
    ``_eval_monom`` otherwise, and for every error)."""
    _, idx, node = slot
    k, d = idx[0], (idx[1] if len(idx) > 1 else None)
    last: list = [None, None]  # the ring's polynomial ring and the monomial in it

    def fn(it: Any) -> Any:
        ring = it.ring
        lits = it.lits
        den = 1 if d is None else int(lits[d])
        if ring is None or den == 0:
            return it._eval_node(_literal(slot, lits))
        if last[0] is not ring.poly:
            m = it._monomial(node.monomial)
            if m is None:
                return it._eval_node(_literal(slot, lits))
            last[0], last[1] = ring.poly, m
        field = ring.poly.field
        c = field(int(lits[k])) / field(den)
        if c == 0:
            return ring.poly.zero()
        return Poly(ring.poly, {e: v * c for e, v in last[1].terms.items()})  # the monomial times c
    return fn
