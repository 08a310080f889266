"""The tree of the Macaulay2 dialect: the shared nodes of :mod:`mech.dsl.ast` (names, literals,
operators, calls, ranges) plus the Macaulay2 constructs Singular lacks, defined here: lists
``{...}`` and arrays ``[...]``, rings ``QQ[x,y]``, options ``a => b``, functions ``(a,b) -> ...``,
assignments (``=`` and ``:=``), loops, conditionals and ``try`` as expressions, ``symbol x``."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

from . import ast as A


@dataclass(eq=False)
class Coeffs(A.Expr):
    """``ZZ/p``: the prime field of characteristic ``p``."""
    characteristic: int


@dataclass(eq=False)
class ListLit(A.Expr):
    """``{a, b}`` (``array``: ``[a, b]``); ``None`` items are empty places (``{a,,b}``)."""
    items: list[Optional[A.Expr]]
    array: bool = False


@dataclass(eq=False)
class RingCons(A.Expr):
    """``K[x, y, Option => v]``: a polynomial ring over ``K`` (or ``f[...]`` for another ``f``)."""
    base: A.Expr
    items: list[A.Expr]


@dataclass(eq=False)
class Option(A.Expr):
    key: A.Expr
    value: A.Expr


@dataclass(eq=False)
class Subscript(A.Expr):
    """``x_1`` (an indexed ring variable) or ``L_0`` (an entry, counted from 0)."""
    base: A.Expr
    index: A.Expr


@dataclass(eq=False)
class Generators(A.Expr):
    """``I_*``: the generators of an ideal as a list."""
    base: A.Expr


@dataclass(eq=False)
class HashHas(A.Expr):
    """``T#?k``: whether ``T`` has the key (or index) ``k``."""
    base: A.Expr
    key: A.Expr


@dataclass(eq=False)
class Dot(A.Expr):
    """``x.name``: a field of a value (``R.maxIdeal``, ``(options R).MonomialOrder``)."""
    base: A.Expr
    field: str


@dataclass(eq=False)
class SymbolLit(A.Expr):
    """``symbol x``: the symbol ``x`` itself, whatever its value."""
    name: str


@dataclass(eq=False)
class Length(A.Expr):
    """``#L``."""
    operand: A.Expr


@dataclass(eq=False)
class SetVar(A.Expr):
    """``name = value`` (``local``: ``name := value``, a new local variable); its value is the value assigned."""
    target: A.Expr
    value: A.Expr
    local: bool = False


@dataclass(eq=False)
class Function(A.Expr):
    """``(a, b) -> body``."""
    params: list[str]
    body: A.Expr


@dataclass(eq=False)
class Seq(A.Expr):
    """``(e1; e2; e3)``: evaluated in turn; the value of the last (none after a final ``;``)."""
    exprs: list[A.Expr]
    silent: bool


@dataclass(eq=False)
class ForLoop(A.Expr):
    var: str
    start: Optional[A.Expr]
    stop: Optional[A.Expr]
    items: Optional[A.Expr]
    collect: bool
    body: A.Expr
    when: Optional[A.Expr] = None


@dataclass(eq=False)
class WhileLoop(A.Expr):
    cond: A.Expr
    body: A.Expr


@dataclass(eq=False)
class IfExpr(A.Expr):
    cond: A.Expr
    then: A.Expr
    orelse: Optional[A.Expr]


@dataclass(eq=False)
class TryExpr(A.Expr):
    """``try e then t else f``: ``t`` (or ``e``'s value) when ``e`` runs without error, else ``f``."""
    body: A.Expr
    then: Optional[A.Expr]
    orelse: Optional[A.Expr]


@dataclass(eq=False)
class TimeExpr(A.Expr):
    """``time e`` / ``elapsedTime e``: ``e``'s value, after printing the time it took."""
    body: A.Expr
    elapsed: bool


@dataclass(eq=False)
class ReturnExpr(A.Expr):
    value: Optional[A.Expr]


@dataclass(eq=False)
class BreakExpr(A.Expr):
    value: Optional[A.Expr] = None


@dataclass(eq=False)
class Statement(A.Stmt):
    """A top-level expression; ``silent`` when a ``;`` ends it (no ``oN =`` output)."""
    expr: A.Expr
    silent: bool
