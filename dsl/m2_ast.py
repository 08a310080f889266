"""The tree of the Macaulay2 dialect: the shared nodes of :mod:`mech.dsl.ast` (names, literals,
operators, calls, ranges) plus the Macaulay2 constructs Singular lacks, defined here: lists
``{...}``, rings ``QQ[x,y]``, options ``a => b``, functions ``(a,b) -> ...``, assignments, loops and
conditionals as expressions (``for i from 1 to n do ...``, ``for x in L list ...``)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

from . import ast as A


@dataclass(eq=False)
class Coeffs(A.Expr):
    """A coefficient ring: ``QQ`` (characteristic 0) or ``ZZ/p``."""
    characteristic: int


@dataclass(eq=False)
class ListLit(A.Expr):
    items: list[A.Expr]


@dataclass(eq=False)
class RingCons(A.Expr):
    """``K[x, y, Option => v]``: a polynomial ring over ``K``."""
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
class Length(A.Expr):
    """``#L``."""
    operand: A.Expr


@dataclass(eq=False)
class SetVar(A.Expr):
    """``name = value`` (its value is the value assigned)."""
    target: A.Expr
    value: A.Expr


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
class ReturnExpr(A.Expr):
    value: Optional[A.Expr]


@dataclass(eq=False)
class BreakExpr(A.Expr):
    pass


@dataclass(eq=False)
class Statement(A.Stmt):
    """A top-level expression; ``silent`` when a ``;`` ends it (no ``oN =`` output)."""
    expr: A.Expr
    silent: bool
