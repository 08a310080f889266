"""Syntax tree of mech programs: statements and expressions with source positions.

Every node carries ``pos`` (line, column, end line, end column; 1-based, end exclusive), which the
interpreter uses for ``file:line:col`` errors and for underlining a call.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import NamedTuple, Optional


class Pos(NamedTuple):
    """Where a node is (a named tuple: cheap to make, immutable)."""
    line: int
    col: int
    end_line: int
    end_col: int


NOPOS = Pos(0, 0, 0, 0)


@dataclass(eq=False)
class Node:
    pos: Pos = field(default=NOPOS, kw_only=True)
    _fn = None  # not a field: the closure the interpreter keeps on the instance (a class default, so
    #            that looking for one on a node without it costs no AttributeError)

    def __getstate__(self) -> dict:
        """Without the closure the interpreter keeps on the node (:mod:`~mech.dsl.compiled`)."""
        state = dict(self.__dict__)
        state.pop("_fn", None)
        state.pop("_seen", None)
        return state


# ---------------------------------------------------------------- expressions
class Expr(Node):
    pass


@dataclass(eq=False)
class Name(Expr):
    id: str


@dataclass(eq=False)
class IntLit(Expr):
    value: int


@dataclass(eq=False)
class RatLit(Expr):
    num: int
    den: int


@dataclass(eq=False)
class MonomLit(Expr):
    """A coefficient glued to a short monomial: ``3x2y`` or ``1/2x``."""
    num: int
    den: int
    monomial: str


@dataclass(eq=False)
class StrLit(Expr):
    value: str


def string_value(token: str) -> str:
    """The value of a string literal ``"..."`` as Singular reads it: a backslash takes the next
    character as it is (``\\"`` a quote, ``\\\\`` a backslash, ``\\n`` the letter n)."""
    body = token[1:-1]
    return re.sub(r"\\(.)", r"\1", body, flags=re.S) if "\\" in body else body


@dataclass(eq=False)
class Tuple(Expr):
    """A parenthesized expression list ``(a, b, c)``."""
    items: list[Expr]


@dataclass(eq=False)
class BinOp(Expr):
    op: str
    left: Expr
    right: Expr


@dataclass(eq=False)
class UnOp(Expr):
    op: str
    operand: Expr


@dataclass(eq=False)
class Range(Expr):
    lo: Expr
    hi: Expr


@dataclass(eq=False)
class Index(Expr):
    base: Expr
    indices: list[Expr]


@dataclass(eq=False)
class Call(Expr):
    func: Expr
    args: list[Expr]


@dataclass(eq=False)
class TypeCall(Expr):
    """A type name used as a conversion command: ``ideal(x, y)``."""
    type: str
    args: list[Expr]


@dataclass(eq=False)
class Backquote(Expr):
    """`` `s` ``: the variable whose name is the value of the string expression ``s``."""
    expr: Expr


# ---------------------------------------------------------------- statements
class Stmt(Node):
    pass


@dataclass(eq=False)
class ExprStmt(Stmt):
    exprs: list[Expr]


@dataclass(eq=False)
class Declarator(Node):
    name: str
    dims: list[Expr]
    indices: list[list[Expr]] = field(default_factory=list)  # `poly p(1)(2..3)`: names with indices


@dataclass(eq=False)
class Decl(Stmt):
    type: str
    items: list[Declarator]
    value: Optional[list[Expr]]


@dataclass(eq=False)
class Assign(Stmt):
    targets: list[Expr]
    values: list[Expr]


@dataclass(eq=False)
class IncDec(Stmt):
    target: Expr
    delta: int
    ignored: bool = False  # `j = i++;`: as Singular, i changes and the assignment is ignored with a warning


@dataclass(eq=False)
class Block(Stmt):
    body: list[Stmt]


@dataclass(eq=False)
class If(Stmt):
    cond: Expr
    then: list[Stmt]
    orelse: Optional[list[Stmt]]


@dataclass(eq=False)
class For(Stmt):
    init: Optional[Stmt]
    cond: Optional[Expr]
    step: Optional[Stmt]
    body: list[Stmt]


@dataclass(eq=False)
class While(Stmt):
    cond: Expr
    body: list[Stmt]


@dataclass(eq=False)
class Moved(Stmt):
    """A one-line statement whose tree was built for the same text ``dline`` lines earlier and is
    shared (long scripts repeat statements; see :mod:`~mech.dsl.fastparse`); ``pos`` is its own."""
    stmt: Stmt
    dline: int


class Relit(Stmt):
    """A one-line statement of the same shape as an earlier one (the same text but for its number
    literals, ``lits``, as written) run by that one's template (:mod:`~mech.dsl.templates`) ``dline``
    lines further down; ``pos`` is its own.  Not a dataclass: one is made per line of long scripts."""
    def __init__(self, template: object, lits: list[str], dline: int, pos: Pos) -> None:
        self.template, self.lits, self.dline, self.pos = template, lits, dline, pos


@dataclass(eq=False)
class Break(Stmt):
    pass


@dataclass(eq=False)
class Continue(Stmt):
    pass


@dataclass(eq=False)
class Return(Stmt):
    values: list[Expr]


@dataclass(eq=False)
class Param(Node):
    type: Optional[str]
    name: str
    alias: bool = False  # `alias T x`: listvar shows the caller's variable it stands for


@dataclass(eq=False)
class ProcDef(Stmt):
    name: str
    params: Optional[list[Param]]
    doc: Optional[str]
    body: list[Stmt]
    static: bool = False
    body_line: int = 0


@dataclass(eq=False)
class Kill(Stmt):
    targets: list[Expr]


@dataclass(eq=False)
class Export(Stmt):
    targets: list[Expr]


@dataclass(eq=False)
class Keepring(Stmt):
    ring: Expr


@dataclass(eq=False)
class Setring(Stmt):
    ring: Expr


@dataclass(eq=False)
class Lib(Stmt):
    name: str


@dataclass(eq=False)
class Quit(Stmt):
    pass


@dataclass(eq=False)
class Help(Stmt):
    topic: Optional[str]


@dataclass(eq=False)
class Empty(Stmt):
    pass


@dataclass(eq=False)
class Program(Node):
    body: list[Stmt]
