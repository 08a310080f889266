"""The Macaulay2 dialect: ``m2.lark`` parsed into mech's AST, and the interpreter that runs it.

The tree uses the shared nodes of :mod:`mech.dsl.ast` (names, literals, operators, calls, ranges)
plus the few Macaulay2 constructs Singular lacks, defined here: lists ``{...}``, rings ``QQ[x,y]``,
options ``a => b``, functions ``(a,b) -> ...``, assignments, loops and conditionals as expressions
(``for i from 1 to n do ...``, ``for x in L list ...``).  :class:`M2Interpreter` is mech's
interpreter with Macaulay2's name rules (global variables of any type; assigning a ring makes its
variables visible, as Macaulay2's ``use``), its commands (``stdlib/m2.py``, registered with
``dialect="m2"``) and its output (``m2_printing.py``: ``o1 = ...`` for statements not ending in ``;``).
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache
from pathlib import Path
from typing import Any, Iterator, Optional

from lark import Lark, Token, Transformer_NonRecursive, v_args
from lark.exceptions import UnexpectedCharacters, UnexpectedInput

from ..kernel import Poly
from . import ast as A
from . import ops
from .errors import MechError, MechNameError, MechRuntimeError, MechSyntaxError, MechTypeError, Source
from .interpreter import Frame, Interpreter, Var, _Break, _Return
from .m2_printing import Opt, Symbol, to_string
from .parser import _pos, _tpos, build
from .rings import make_ring
from .values import NONE, ExprList, Ideal, List, Matrix, Number, OrderBlock, Ring, to_int, typeof

GRAMMAR = Path(__file__).with_name("m2.lark")


# ---------------------------------------------------------------- nodes Singular has no form for
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


# ---------------------------------------------------------------- parsing
#: tokens after which a line break ends the statement (an expression can end there)
_ENDERS = {"IDENT", "COEFFS", "NUMBER", "STRING", "RPAR", "RSQB", "RBRACE", "BREAK", "RETURN"}
_OPEN = {"LPAR", "LSQB", "LBRACE"}
_CLOSE = {"RPAR", "RSQB", "RBRACE"}


class _Lines:
    """Postlexer: a line break separates statements only outside brackets after a complete expression."""

    always_accept = ("_NL",)

    def process(self, stream: Iterator[Token]) -> Iterator[Token]:
        depth, prev = 0, None
        for tok in stream:
            if tok.type == "_NL":
                if depth == 0 and prev in _ENDERS:
                    yield tok
                    prev = None
                continue
            if tok.type in _OPEN:
                depth += 1
            elif tok.type in _CLOSE:
                depth = max(depth - 1, 0)
            prev = tok.type
            yield tok


class _Build(Transformer_NonRecursive):
    """Lark callbacks building the tree."""

    @v_args(meta=True)
    def start(self, meta, c):
        body: list[A.Stmt] = []
        for item in c:
            if item is None:
                continue
            if isinstance(item, Token):
                if item.type == "SEMI" and body:
                    body[-1].silent = True
                continue
            body.append(Statement(item, False, pos=item.pos))
        return A.Program(body, pos=_pos(meta))

    @v_args(meta=True)
    def name(self, meta, c):
        return A.Name(str(c[0]), pos=_tpos(c[0]))

    @v_args(meta=True)
    def coeffs(self, meta, c):
        text = str(c[0])
        char = int(text.split("/")[1]) if "/" in text else 0
        if text.startswith("ZZ") and "/" not in text:
            raise MechSyntaxError("the integers ZZ are not a field: use QQ or ZZ/p", _tpos(c[0]))
        return Coeffs(char, pos=_tpos(c[0]))

    @v_args(meta=True)
    def int_lit(self, meta, c):
        return A.IntLit(int(c[0]), pos=_tpos(c[0]))

    @v_args(meta=True)
    def str_lit(self, meta, c):
        text = str(c[0])[1:-1]
        return A.StrLit(re.sub(r"\\(.)", lambda m: {"n": "\n", "t": "\t"}.get(m.group(1), m.group(1)), text),
                        pos=_tpos(c[0]))

    def exprlist(self, c):
        return list(c)

    def seq(self, c):
        return list(c)

    @v_args(meta=True)
    def paren(self, meta, c):
        pos = _pos(meta)
        if c[0] is None:
            return A.Tuple([], pos=pos)
        parts = c[0]  # expression lists and the ';' tokens between them
        if len(parts) == 1:
            items = parts[0]
            return items[0] if len(items) == 1 else A.Tuple(items, pos=pos)
        exprs: list[A.Expr] = []
        silent = False
        for p in parts:
            if isinstance(p, Token):
                silent = True
            elif p is not None:
                if len(p) != 1:
                    raise MechSyntaxError("a ';' sequence takes one expression between the ';'", pos)
                exprs.extend(p)
                silent = False
        return Seq(exprs, silent, pos=pos)

    @v_args(meta=True)
    def sequence(self, meta, c):
        return A.Tuple(list(c), pos=_pos(meta))

    @v_args(meta=True)
    def list_lit(self, meta, c):
        return ListLit(c[0] or [], pos=_pos(meta))

    @v_args(meta=True)
    def ring_cons(self, meta, c):
        return RingCons(c[0], c[1] or [], pos=_pos(meta))

    @v_args(meta=True)
    def subscript(self, meta, c):
        return Subscript(c[0], c[1], pos=_pos(meta))

    @v_args(meta=True)
    def hash_index(self, meta, c):
        return A.Index(c[0], [c[1]], pos=_pos(meta))

    @v_args(meta=True)
    def hash_index_neg(self, meta, c):
        return A.Index(c[0], [A.UnOp("-", c[1], pos=c[1].pos)], pos=_pos(meta))

    @v_args(meta=True)
    def length(self, meta, c):
        return Length(c[0], pos=_pos(meta))

    @v_args(meta=True)
    def apply(self, meta, c):
        f, arg = c
        args = arg.items if isinstance(arg, A.Tuple) else [arg]
        return A.Call(f, args, pos=_pos(meta))

    def _bin(op):  # noqa: N805 - a factory used in the class body
        @v_args(meta=True)
        def build(self, meta, c):
            return A.BinOp(op, c[0], c[1], pos=_pos(meta))
        return build

    add, sub, mul, div, mod, pow = _bin("+"), _bin("-"), _bin("*"), _bin("/"), _bin("%"), _bin("^")
    eq, ne, lt, le, gt, ge = _bin("=="), _bin("!="), _bin("<"), _bin("<="), _bin(">"), _bin(">=")
    and_op, or_op, quotient = _bin("&&"), _bin("||"), _bin(":")

    @v_args(meta=True)
    def neg(self, meta, c):
        return A.UnOp("-", c[0], pos=_pos(meta))

    @v_args(meta=True)
    def not_op(self, meta, c):
        return A.UnOp("!", c[0], pos=_pos(meta))

    @v_args(meta=True)
    def range(self, meta, c):
        return A.Range(c[0], c[1], pos=_pos(meta))

    @v_args(meta=True)
    def assign(self, meta, c):
        target = c[0]
        if not isinstance(target, (A.Name, Subscript)):
            raise MechSyntaxError("cannot assign to this expression", target.pos, underline=True)
        return SetVar(target, c[1], pos=_pos(meta))

    @v_args(meta=True)
    def lambda_(self, meta, c):
        params = c[0].items if isinstance(c[0], A.Tuple) else [c[0]]
        if not all(isinstance(p, A.Name) for p in params):
            raise MechSyntaxError("a function's parameters are names: (a, b) -> ...", c[0].pos, underline=True)
        return Function([p.id for p in params], c[1], pos=_pos(meta))

    @v_args(meta=True)
    def option(self, meta, c):
        return Option(c[0], c[1], pos=_pos(meta))

    @v_args(meta=True)
    def for_range(self, meta, c):
        var, start, stop, kind, body = c
        return ForLoop(str(var), start, stop, None, kind.type == "LIST", body, pos=_pos(meta))

    @v_args(meta=True)
    def for_in(self, meta, c):
        var, items, kind, body = c
        return ForLoop(str(var), None, None, items, kind.type == "LIST", body, pos=_pos(meta))

    @v_args(meta=True)
    def while_(self, meta, c):
        return WhileLoop(c[0], c[1], pos=_pos(meta))

    @v_args(meta=True)
    def if_(self, meta, c):
        return IfExpr(c[0], c[1], c[2], pos=_pos(meta))

    @v_args(meta=True)
    def return_(self, meta, c):
        return ReturnExpr(c[0] if c else None, pos=_pos(meta))

    @v_args(meta=True)
    def break_(self, meta, c):
        return BreakExpr(pos=_pos(meta))


@lru_cache(maxsize=1)
def _parser() -> Lark:
    return Lark(GRAMMAR.read_text(), parser="lalr", propagate_positions=True, maybe_placeholders=True,
                postlex=_Lines(), lexer="contextual")


def parse(text: str, source: Optional[Source] = None) -> A.Program:
    """The program tree of Macaulay2 code ``text``; raises :class:`MechSyntaxError` located in ``source``."""
    source = source or Source("<string>", text)
    try:
        return build(_Build(), _parser().parse(text), source)
    except UnexpectedCharacters as e:
        ch = text[e.pos_in_stream] if e.pos_in_stream < len(text) else ""
        msg = "unterminated string" if ch == '"' else f"unexpected character '{ch}'"
        raise MechSyntaxError(msg, A.Pos(e.line, e.column, e.line, e.column + 1), source) from None
    except UnexpectedInput as e:
        tok = getattr(e, "token", None)
        if tok is None or tok.type == "$END":
            line = text.count("\n") + 1
            col = len(text) - (text.rfind("\n") + 1) + 1
            raise MechSyntaxError("unexpected end of input: incomplete statement",
                                  A.Pos(line, col, line, col + 1), source) from None
        if tok.value == "*" and text[tok.start_pos - 1:tok.start_pos] == "-":
            raise MechSyntaxError("unterminated comment: -* without its *-", _tpos(tok), source) from None
        shown = "line break" if tok.type == "_NL" else tok.value
        raise MechSyntaxError(f"unexpected '{shown}'", _tpos(tok), source, underline=True) from None


# ---------------------------------------------------------------- running

#: Macaulay2 symbols mech knows (option names and monomial orders)
SYMBOLS = {"MonomialOrder", "Lex", "GRevLex", "GLex", "RevLex", "Weights", "Eliminate", "Global", "Degrees",
           "Variables"}


@dataclass(eq=False)
class M2Function:
    """A function ``(a, b) -> body``, named after the variable it was first assigned to."""
    params: list[str]
    body: A.Expr
    source: Source
    captured: dict  # the enclosing function's variables when this one was made
    name: str = "-*Function*-"


@dataclass(eq=False)
class CommandRef:
    """A command used as a value (``apply(L, dim)``)."""
    command: Any

    @property
    def name(self) -> str:
        return self.command.name


class M2Interpreter(Interpreter):
    """mech's interpreter reading the Macaulay2 dialect: same values, kernel and evaluation of the
    shared nodes; Macaulay2's variables (global, untyped), commands, operators and output."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.commands = self.registry.DIALECTS.get("m2", {})
        self.count = 0  # the number N of the statement, as Macaulay2's oN
        self._exec[Statement] = self._exec_statement
        self._eval.update({
            Coeffs: lambda n: n, ListLit: self._eval_list, RingCons: self._eval_ring, Option: self._eval_option,
            Subscript: self._eval_subscript, Length: self._eval_length, SetVar: self._eval_set,
            Function: self._eval_function, Seq: self._eval_seq,
            ForLoop: self._eval_for, WhileLoop: self._eval_while, IfExpr: self._eval_if,
            ReturnExpr: self._eval_return, BreakExpr: self._eval_break,
        })

    #: the REPL numbers inputs (``i3 :`` and its ``o3 = ...``), scripts their statements
    numbers_inputs = False

    def execute(self, text: str, name: str = "<string>") -> None:
        source = Source(name, text)
        if self.numbers_inputs:
            self.count += 1
        self.run(parse(text, source), source)

    def _exec_statement(self, s: Statement) -> None:
        if not self.numbers_inputs:
            self.count += 1
        v = self.eval(s.expr)
        if not s.silent and v is not NONE:
            self.last = v
            blank = "\n" if self.numbers_inputs else ""  # the shell sets outputs off as Macaulay2 does
            self.write(f"{blank}o{self.count} = {to_string(v)}\n")

    def basering(self) -> Ring:
        if self.ring is None:
            raise MechRuntimeError("no ring active: define one first, e.g. R = QQ[x,y,z]")
        return self.ring

    # ------------------------------------------------------------ names
    def lookup(self, name: str) -> Optional[Var]:
        frame = self.frames[-1]
        if frame.level and name in frame.vars:
            return frame.vars[name]
        return self.globals.get(name)

    def set_var(self, name: str, value: Any) -> None:
        """``name = value``: a local of the running function if it has one, else a global."""
        if isinstance(value, Ring):
            if not value.name:
                value.name = name
            self.ring = value
        elif isinstance(value, M2Function) and value.name == "-*Function*-":
            value.name = name
        frame = self.frames[-1]
        table = frame.vars if frame.level and name in frame.vars else self.globals
        var = table.get(name)
        if var is None:
            table[name] = Var(name, "def", value, None, frame.level if table is frame.vars else 0)
        else:
            var.value = value

    def declare(self, name: str, typ: str, value: Any) -> Var:
        """A variable set from Python (``session[name] = value``): Macaulay2's variables are untyped."""
        self.set_var(name, value)
        return self.lookup(name)

    def _eval_name(self, node: A.Name) -> Any:
        name = node.id
        var = self.lookup(name)
        if var is not None:
            return var.value
        ring = self.ring
        if ring is not None and ring.var_index(name) is not None:
            return ring.poly.gen(ring.var_index(name))
        if name in ("true", "false"):
            return name == "true"
        if name == "null":
            return NONE
        if name in SYMBOLS:
            return Symbol(name)
        if name in self.commands:
            return CommandRef(self.commands[name])
        raise MechNameError(f"unknown identifier '{name}'" + ("" if ring else " (no ring is active)"))

    def _eval_set(self, node: SetVar) -> Any:
        value = self.eval(node.value)
        if isinstance(node.target, Subscript):
            raise MechRuntimeError("cannot assign to an entry: Macaulay2's lists are immutable")
        self.set_var(node.target.id, value)
        return value

    def _eval_subscript(self, node: Subscript) -> Any:
        base = node.base
        if isinstance(base, A.Name) and self.lookup(base.id) is None:
            i = self.eval(node.index)
            name = f"{base.id}_{to_string(i)}"
            if self.ring is not None and self.ring.var_index(name) is not None:
                return self.ring.poly.gen(self.ring.var_index(name))
            raise MechNameError(f"unknown identifier '{name}'")
        return self._entry(self.eval(base), self.eval(node.index))

    def _eval_index(self, node: A.Index) -> Any:
        return self._entry(self.eval(node.base), self.eval(node.indices[0]))

    def _entry(self, base: Any, k: Any) -> Any:
        """``base_k`` (``base#k``): entries counted from 0, negative ones from the end."""
        if type(base) is int and isinstance(k, Ring):  # 0_R: the number in the ring R
            return k.poly.const(k.poly.field(base))
        if isinstance(base, Ring):
            seq, what = [base.poly.gen(i) for i in range(len(base.names))], "ring's variables"
        elif isinstance(base, Ideal):
            seq, what = base.gens, "ideal's generators"
        elif isinstance(base, (List, ExprList)):
            seq, what = base.items, "list"
        elif isinstance(base, Matrix) and isinstance(k, ExprList) and len(k.items) == 2:
            i, j = (to_int(x) for x in k.items)
            if not (0 <= i < base.nrows and 0 <= j < base.ncols):
                raise MechRuntimeError(f"index ({i},{j}) out of range for a {base.nrows} x {base.ncols} matrix")
            return base.get(i + 1, j + 1)
        elif isinstance(base, str):
            seq, what = base, "string"
        else:
            raise MechTypeError(f"a {typeof(base)} cannot be indexed")
        i = to_int(k)
        if not -len(seq) <= i < len(seq):
            raise MechRuntimeError(f"index {i} out of range (the {what} has {len(seq)} entries, counted from 0)")
        return seq[i]

    def _eval_length(self, node: Length) -> int:
        v = self.eval(node.operand)
        if isinstance(v, (List, ExprList)):
            return len(v.items)
        if isinstance(v, str):
            return len(v)
        raise MechTypeError(f"# needs a list, sequence or string, not a {typeof(v)}")

    # ------------------------------------------------------------ values
    def _values(self, nodes: list[A.Expr]) -> list[Any]:
        """Arguments evaluated one by one (a sequence stays one value, as in Macaulay2)."""
        return [self.eval(n) for n in nodes]

    def _eval_list(self, node: ListLit) -> List:
        return List(self._values(node.items))

    def _eval_option(self, node: Option) -> Opt:
        return Opt(self.eval(node.key), self.eval(node.value))

    def _eval_range(self, node: A.Range) -> ExprList:
        lo, hi = to_int(self.eval(node.lo)), to_int(self.eval(node.hi))
        return ExprList(list(range(lo, hi + 1)))

    def _eval_tuple(self, node: A.Tuple) -> Any:
        return ExprList(self._values(node.items)) if node.items else NONE

    def _eval_function(self, node: Function) -> M2Function:
        frame = self.frames[-1]
        return M2Function(node.params, node.body, self.source, dict(frame.vars) if frame.level else {})

    def _eval_seq(self, node: Seq) -> Any:
        v: Any = NONE
        for e in node.exprs:
            v = self.eval(e)
        return NONE if node.silent else v

    def _eval_ring(self, node: RingCons) -> Ring:
        from ..stdlib.m2 import order_blocks
        base = self.eval(node.base)
        if not isinstance(base, Coeffs):
            raise MechTypeError(f"a polynomial ring is built over QQ or ZZ/p, not over a {typeof(base)}")
        names: list[str] = []
        options: dict[str, Any] = {}
        for item in node.items:
            if isinstance(item, Option):
                key = item.key.id if isinstance(item.key, A.Name) else ""
                if key not in ("MonomialOrder", "Global"):
                    raise MechRuntimeError(f"unknown ring option '{key}' (known: MonomialOrder, Global)")
                options[key] = self.eval(item.value)
            else:
                names.extend(self._variable_names(item))
        if not names or len(set(names)) != len(names):
            raise MechRuntimeError("a ring needs distinct variables: QQ[x,y,z]")
        blocks = order_blocks(options.get("MonomialOrder", Symbol("GRevLex")), len(names))
        ring = make_ring(base.characteristic, (), names, blocks + [OrderBlock("C")])
        if options.get("Global", True) is not ring.poly.order.is_global:
            want = "global" if options.get("Global", True) else "local"
            raise MechRuntimeError(f"the monomial order is not {want} (Global => "
                                   f"{to_string(options.get('Global', True))})")
        return ring

    def _variable_names(self, node: A.Expr) -> list[str]:
        if isinstance(node, A.Name):
            return [node.id]
        if isinstance(node, Subscript) and isinstance(node.base, A.Name):
            return [f"{node.base.id}_{to_int(self.eval(node.index))}"]
        if isinstance(node, A.Range):
            lo, hi = self._variable_names(node.lo), self._variable_names(node.hi)
            a, _, i = lo[0].rpartition("_")
            b, _, j = hi[0].rpartition("_")
            if a and a == b and i.isdigit() and j.isdigit():
                return [f"{a}_{k}" for k in range(int(i), int(j) + 1)]
            x, y = lo[0], hi[0]
            if len(x) == 1 and len(y) == 1 and x <= y:
                return [chr(c) for c in range(ord(x), ord(y) + 1)]
        raise MechSyntaxError("a ring variable is a name, x_i or a range x_1..x_n", node.pos)

    # ------------------------------------------------------------ control
    def _eval_for(self, node: ForLoop) -> Any:
        if node.items is not None:
            seq = self.eval(node.items)
            if not isinstance(seq, (List, ExprList)):
                raise MechTypeError(f"for ... in needs a list, not a {typeof(seq)}")
            values: Any = list(seq.items)
        else:
            start = to_int(self.eval(node.start)) if node.start is not None else 0
            if node.stop is None:
                raise MechRuntimeError("for i from a to b: the upper bound is missing")
            values = range(start, to_int(self.eval(node.stop)) + 1)
        out = []
        for x in values:
            self.set_var(node.var, x)
            try:
                v = self.eval(node.body)
            except _Break:
                break
            if node.collect:
                out.append(v)
        return List(out) if node.collect else NONE

    def _eval_while(self, node: WhileLoop) -> Any:
        while self._truth(self.eval(node.cond)):
            try:
                self.eval(node.body)
            except _Break:
                break
        return NONE

    def _eval_if(self, node: IfExpr) -> Any:
        if self._truth(self.eval(node.cond)):
            return self.eval(node.then)
        return self.eval(node.orelse) if node.orelse is not None else NONE

    def _truth(self, v: Any) -> bool:
        if not isinstance(v, bool):
            raise MechTypeError(f"a condition is true or false, not a {typeof(v)}")
        return v

    def _eval_return(self, node: ReturnExpr) -> Any:
        raise _Return(self.eval(node.value) if node.value is not None else NONE)

    def _eval_break(self, node: BreakExpr) -> Any:
        raise _Break()

    # ------------------------------------------------------------ calls and operators
    def _eval_call(self, node: A.Call) -> Any:
        f = node.func
        if isinstance(f, A.Name) and self.lookup(f.id) is None and f.id in self.commands:
            return self.call_command(self.commands[f.id], node.args)
        v = self.eval(f)
        if isinstance(v, CommandRef):
            return self.call_command(v.command, node.args)
        if isinstance(v, M2Function):
            return self.call_function(v, self._values(node.args), node)
        if v == Symbol("Eliminate") and len(node.args) == 1:
            return Opt(v, self.eval(node.args[0]))
        raise MechTypeError(f"a {typeof(v)} cannot be applied to arguments")

    def call_command(self, cmd: Any, arg_nodes: list[A.Expr]) -> Any:
        """A command applied to a sequence it takes as one argument (``toString (1,2)``) gets it whole."""
        if len(arg_nodes) > 1 and all(len(ov.names) == 1 and not ov.has_varargs for ov in cmd.overloads):
            arg_nodes = [A.Tuple(arg_nodes, pos=arg_nodes[0].pos)]
        v = super().call_command(cmd, arg_nodes)
        if cmd.overloads[0].func.__annotations__.get("return") in ("bool", bool):
            return bool(v)  # the registry gives Singular's 0 and 1
        return v

    def call_function(self, fn: M2Function, args: list[Any], node: Optional[A.Expr] = None) -> Any:
        """Call a Macaulay2 function with evaluated arguments in a new scope."""
        if len(args) != len(fn.params):
            if len(fn.params) == 1:
                args = [ExprList(args)]
            else:
                raise MechTypeError(f"{fn.name} expects {len(fn.params)} arguments, got {len(args)}")
        if len(self.frames) > 1000:
            raise MechRuntimeError("function calls nested deeper than 1000")
        level = len(self.frames)
        frame = Frame(level, {**fn.captured, **{p: Var(p, "def", a, None, level) for p, a in zip(fn.params, args)}})
        self.frames.append(frame)
        saved = self.source
        self.source = fn.source
        try:
            return self.eval(fn.body)
        except _Return as r:
            return r.value
        finally:
            self.frames.pop()
            self.source = saved

    def _binary(self, op: str, a: Any, b: Any) -> Any:
        from ..stdlib import m2 as lib
        ring = self.ring.poly if self.ring else None
        if op == ":":
            return lib.quotient(a, b)
        if op == "/" and type(a) is int and type(b) is int:
            if b == 0:
                raise MechRuntimeError("division by 0")
            if ring is None:
                return Fraction(a, b)
            return Number(ring, ring.field(a) / ring.field(b))
        if Fraction in (type(a), type(b)) and {type(a), type(b)} <= {int, Fraction} and op in "+-*/^":
            return _rational(op, a, b)
        if op in "+*" and isinstance(a, Ideal) and isinstance(b, Ideal):  # generators as Macaulay2 lists them
            if a.ring is not b.ring:
                raise MechTypeError(f"the ideals of {op} are in different rings")
            gens = a.gens + b.gens if op == "+" else tuple(f * g for f in a.gens for g in b.gens)
            return Ideal(a.ring, gens)
        if op == "%" and isinstance(a, (Poly, Number, int)) and isinstance(b, Ideal):
            return lib.remainder(a, b)
        if op in ("==", "!="):
            same = lib.equal(a, b)
            return same if op == "==" else not same
        if op in ("<", "<=", ">", ">="):
            return bool(ops.compare(op, a, b, ring))
        if isinstance(a, bool) or isinstance(b, bool):
            raise MechTypeError(f"no operator {op} for true/false")
        return ops.binary(op, a, b, ring, self.warn_in_line)

    def _eval_binop(self, node: A.BinOp) -> Any:
        if node.op == "&&":
            return self._truth(self.eval(node.left)) and self._truth(self.eval(node.right))
        if node.op == "||":
            return self._truth(self.eval(node.left)) or self._truth(self.eval(node.right))
        return super()._eval_binop(node)

    def _eval_unop(self, node: A.UnOp) -> Any:
        if node.op == "!":
            return not self._truth(self.eval(node.operand))
        return super()._eval_unop(node)


def _rational(op: str, a: Fraction | int, b: Fraction | int) -> Fraction | int:
    """Arithmetic of rational numbers outside a ring (``1/2 + 1``); integral results are ints."""
    if op == "^" and type(b) is not int:
        raise MechTypeError("a rational number's exponent is an integer")
    if op == "/" and b == 0:
        raise MechRuntimeError("division by 0")
    v = {"+": lambda: a + b, "-": lambda: a - b, "*": lambda: a * b, "/": lambda: Fraction(a) / b,
         "^": lambda: Fraction(a) ** b}[op]()
    return int(v) if v.denominator == 1 else v


# ---------------------------------------------------------------- the interactive shell
def is_complete(text: str) -> bool:
    """Whether the input can run: it parses, or its error is not an unfinished end."""
    try:
        parse(text)
    except MechSyntaxError as e:
        return not e.message.startswith("unexpected end of input")
    return True


def run_m2_repl(warnings: bool = True, read: Optional[Any] = None, out: Optional[Any] = None) -> int:
    """Macaulay2's prompt ``iN :`` with outputs ``oN = ...`` until end of input or ``exit``."""
    import sys
    out = out or sys.stdout
    read = read or input
    it = M2Interpreter(out=out, flush=True, warnings=warnings)
    it.numbers_inputs = True
    while True:
        prompt = f"\ni{it.count + 1} : "
        try:
            text = read(prompt)
            while not is_complete(text):
                text += "\n" + read(" " * len(prompt.strip("\n")))
        except EOFError:
            out.write("\n")
            return 0
        if text.strip() in ("exit", "quit", "end"):
            return 0
        if not text.strip():
            continue
        try:
            it.execute(text, "<stdin>")
        except MechError as e:
            it.unwind()
            out.write(e.format())
        except KeyboardInterrupt:
            it.unwind()
            out.write("interrupted\n")
