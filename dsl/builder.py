"""Building the tree of :mod:`mech.dsl.ast` from Lark's parse tree of ``singular.lark``."""
from __future__ import annotations

from typing import Any, Optional

from lark import Token, Transformer_NonRecursive, v_args
from lark.exceptions import VisitError

from .machine_int import literal
from . import ast as A
from .errors import MechSyntaxError, Source
from .types import block_types, find_type


def meta_pos(meta: Any) -> A.Pos:
    """The position of a rule's match (Lark's ``meta``; none for an empty match)."""
    if getattr(meta, "empty", False):
        return A.NOPOS
    return A.Pos(meta.line, meta.column, meta.end_line, meta.end_column)


MAX_DIGITS = 100_000  # an integer literal's digits (its value has at most ~332000 bits)


def parse_int(digits: str, tok: Optional[Token] = None) -> int:
    """The value of an integer literal (``tok``: its token, for the error position); literals
    beyond Python's 4300-digit limit of ``int(str)`` are read by flint, longer ones than
    ``MAX_DIGITS`` refused."""
    tok = tok if tok is not None else digits
    if len(digits) <= 4000:
        return int(digits)
    if len(digits) > MAX_DIGITS:
        raise MechSyntaxError(f"integer literal too long ({len(digits)} digits; at most {MAX_DIGITS})",
                              token_pos(tok) if isinstance(tok, Token) else None)
    import flint
    return int(flint.fmpz(str(digits)))


def token_pos(tok: Token) -> A.Pos:
    """The position of a token."""
    return A.Pos(tok.line, tok.column, tok.end_line, tok.end_column)


def _list(x: Optional[A.Tuple | list]) -> list:
    if x is None:
        return []
    return list(x)


class TreeBuilder(Transformer_NonRecursive):  # iterative: deeply nested input cannot overflow the stack
    """Lark callbacks building AST nodes from the parse tree."""

    # ---- expressions
    @v_args(meta=True)
    def name(self, meta, c):
        return A.Name(str(c[0]), pos=token_pos(c[0]))

    @v_args(meta=True)
    def int_lit(self, meta, c):
        return A.IntLit(literal(parse_int(c[0])), pos=token_pos(c[0]))

    @v_args(meta=True)
    def rat_lit(self, meta, c):
        num, den = str(c[0]).split("/")
        return A.RatLit(parse_int(num, c[0]), parse_int(den, c[0]), pos=token_pos(c[0]))

    @v_args(meta=True)
    def monom_lit(self, meta, c):
        s = str(c[0])
        i = 0
        while s[i].isdigit() or s[i] == "/":
            i += 1
        coeff, mono = s[:i], s[i:]
        num, _, den = coeff.partition("/")
        return A.MonomLit(parse_int(num, c[0]), parse_int(den, c[0]) if den else 1, mono, pos=token_pos(c[0]))

    @v_args(meta=True)
    def str_lit(self, meta, c):
        return A.StrLit(A.string_value(str(c[0])), pos=token_pos(c[0]))

    def exprlist(self, c):
        return list(c)

    @v_args(meta=True)
    def paren(self, meta, c):
        items = c[0]
        if len(items) == 1:
            return items[0]
        return A.Tuple(items, pos=meta_pos(meta))

    @v_args(meta=True)
    def type_call(self, meta, c):
        return A.TypeCall(c[0], _list(c[1]), pos=meta_pos(meta))

    @v_args(meta=True)
    def type_ref(self, meta, c):  # a type's name as a value: listvar(poly)
        return A.Name(str(c[0]), pos=meta_pos(meta))

    @v_args(meta=True)
    def vector_lit(self, meta, c):  # [p1, p2, ...]: the vector with these entries
        return A.TypeCall("vector", _list(c[0]), pos=meta_pos(meta))

    def proc_cast(self, c):  # proc(L[1]): the procedure the value holds, called by a following (...)
        return c[0]

    @v_args(meta=True)
    def call(self, meta, c):
        return A.Call(c[0], _list(c[1]), pos=meta_pos(meta))

    @v_args(meta=True)
    def index(self, meta, c):
        return A.Index(c[0], c[1], pos=meta_pos(meta))

    @v_args(meta=True)
    def range(self, meta, c):
        return A.Range(c[0], c[1], pos=meta_pos(meta))

    def type_name(self, c):
        return str(c[0])

    def _bin(op):  # noqa: N805 - a factory used in the class body
        @v_args(meta=True)
        def build(self, meta, c):
            return A.BinOp(op, c[0], c[1], pos=meta_pos(meta))
        return build

    add, sub, mul, div, mod = _bin("+"), _bin("-"), _bin("*"), _bin("/"), _bin("mod")
    intdiv, pow, repeat = _bin("div"), _bin("^"), _bin(":")
    eq, ne, lt, le, gt, ge = _bin("=="), _bin("!="), _bin("<"), _bin("<="), _bin(">"), _bin(">=")
    and_op, or_op = _bin("&&"), _bin("||")

    @v_args(meta=True)
    def pow_neg(self, meta, c):
        return A.BinOp("^", c[0], A.UnOp("-", c[1], pos=c[1].pos), pos=meta_pos(meta))

    def _un(op):  # noqa: N805
        @v_args(meta=True)
        def build(self, meta, c):
            return A.UnOp(op, c[0], pos=meta_pos(meta))
        return build

    neg, pos, not_op = _un("-"), _un("+"), _un("!")

    # ---- statements
    @v_args(meta=True)
    def start(self, meta, c):
        return A.Program(list(c), pos=meta_pos(meta))

    @v_args(meta=True)
    def expr_stmt(self, meta, c):
        return A.ExprStmt(c[0], pos=meta_pos(meta))

    @v_args(meta=True)
    def backquote(self, meta, c):
        return A.Backquote(c[0], pos=meta_pos(meta))

    @v_args(meta=True)
    def last_string(self, meta, c):
        return A.ExprStmt([A.StrLit(A.string_value(str(c[0])), pos=token_pos(c[0]))], pos=meta_pos(meta))

    @v_args(meta=True)
    def empty_stmt(self, meta, c):
        return A.Empty(pos=meta_pos(meta))

    @v_args(meta=True)
    def type_stmt(self, meta, c):  # `type x;`: the command type (stdlib/type_command.py)
        pos = meta_pos(meta)
        return A.ExprStmt([A.Call(A.Name("type", pos=pos), [c[0]], pos=pos)], pos=pos)

    @v_args(meta=True)
    def dangling_else(self, meta, c):  # Singular warns of an `else` without `if` and skips its block
        return A.Empty(pos=meta_pos(meta))

    @v_args(meta=True)
    def declarator(self, meta, c):
        return A.Declarator(str(c[0]), list(c[1:]), pos=meta_pos(meta))

    @v_args(meta=True)
    def indexed_declarator(self, meta, c):
        return A.Declarator(str(c[0]), [], [list(x) for x in c[1:]], pos=meta_pos(meta))

    @v_args(meta=True)
    def decl(self, meta, c):
        typ, rest = c[0], c[1:]
        value = rest[-1]
        return A.Decl(typ, list(rest[:-1]), value, pos=meta_pos(meta))

    @v_args(meta=True)
    def block_decl(self, meta, c):
        typ, name, lines = c[0], c[1], c[2:]
        plugin = find_type(typ)
        accepted = plugin.block_statements() if plugin is not None else None
        if accepted is None:
            kinds = " or a ".join(block_types()) or "type of a library"
            raise MechSyntaxError(f"a {{ ... }} description declares a {kinds}, not a {typ}", token_pos(name))
        for words in lines:
            if str(words[0]) not in accepted:
                raise MechSyntaxError(f"unknown {typ} statement '{words[0]}' (expected "
                                      f"{', '.join(accepted)})", token_pos(words[0]), underline=True)
        text = "; ".join(" ".join(str(w) for w in words) for words in lines)
        return A.Decl(typ, [A.Declarator(str(name), [], pos=token_pos(name))],
                      [A.StrLit(text, pos=meta_pos(meta))], pos=meta_pos(meta))

    def block_line(self, c):
        return c

    def block_word(self, c):
        tok = c[-1]
        return Token(tok.type, "".join(str(t) for t in c), tok.start_pos, tok.line, tok.column,
                     tok.end_line, tok.end_column) if len(c) > 1 else tok

    @v_args(meta=True)
    def assign(self, meta, c):
        for t in c[0]:
            _check_target(t)
        return A.Assign(c[0], c[1], pos=meta_pos(meta))

    @v_args(meta=True)
    def incr_stmt(self, meta, c):
        _check_target(c[0])
        return A.IncDec(c[0], 1, pos=meta_pos(meta))

    @v_args(meta=True)
    def decr_stmt(self, meta, c):
        _check_target(c[0])
        return A.IncDec(c[0], -1, pos=meta_pos(meta))

    @v_args(meta=True)
    def assign_incr(self, meta, c):
        _check_target(c[1])
        return A.IncDec(c[1], 1, True, pos=meta_pos(meta))

    @v_args(meta=True)
    def assign_decr(self, meta, c):
        _check_target(c[1])
        return A.IncDec(c[1], -1, True, pos=meta_pos(meta))

    @v_args(meta=True)
    def break_stmt(self, meta, c):
        return A.Break(pos=meta_pos(meta))

    @v_args(meta=True)
    def continue_stmt(self, meta, c):
        return A.Continue(pos=meta_pos(meta))

    @v_args(meta=True)
    def return_stmt(self, meta, c):
        return A.Return(_list(c[0]), pos=meta_pos(meta))

    @v_args(meta=True)
    def kill_stmt(self, meta, c):
        return A.Kill(c[0], pos=meta_pos(meta))

    @v_args(meta=True)
    def export_stmt(self, meta, c):
        return A.Export(c[0], pos=meta_pos(meta))

    @v_args(meta=True)
    def keepring_stmt(self, meta, c):
        return A.Keepring(c[0], pos=meta_pos(meta))

    @v_args(meta=True)
    def setring_stmt(self, meta, c):
        return A.Setring(c[0], pos=meta_pos(meta))

    @v_args(meta=True)
    def lib_stmt(self, meta, c):
        return A.Lib(str(c[0])[1:-1], pos=meta_pos(meta))

    @v_args(meta=True)
    def quit_stmt(self, meta, c):
        return A.Quit(pos=meta_pos(meta))

    @v_args(meta=True)
    def help_stmt(self, meta, c):
        return A.Help(c[0], pos=meta_pos(meta))

    def help_topic(self, c):
        t = str(c[0])
        return t[1:-1] if t.startswith('"') else t

    def help_keyword(self, c):
        return str(c[0])

    @v_args(meta=True)
    def block(self, meta, c):
        return A.Block([s for s in c if s is not None], pos=meta_pos(meta))

    @v_args(meta=True)
    def if_stmt(self, meta, c):
        cond, then, orelse = c[0], c[1], c[2] if len(c) > 2 else None
        if isinstance(orelse, A.Block):
            orelse = orelse.body
        elif orelse is not None:
            orelse = [orelse]
        return A.If(cond, then.body, orelse, pos=meta_pos(meta))

    @v_args(meta=True)
    def for_stmt(self, meta, c):
        init, cond, step, body = c
        return A.For(init, cond, step, body.body, pos=meta_pos(meta))

    @v_args(meta=True)
    def while_stmt(self, meta, c):
        return A.While(c[0], c[1].body, pos=meta_pos(meta))

    @v_args(meta=True)
    def proc_def(self, meta, c):
        static, name, params, doc, body = c
        return A.ProcDef(str(name), params, str(doc)[1:-1] if doc is not None else None, body.body,
                         static is not None, body.pos.line, pos=meta_pos(meta))

    def params(self, c):
        return [p for p in c if p is not None]

    @v_args(meta=True)
    def param(self, meta, c):
        if len(c) == 2:
            return A.Param(c[0], str(c[1]), pos=meta_pos(meta))
        return A.Param(None, str(c[0]), pos=meta_pos(meta))

    @v_args(meta=True)
    def alias_param(self, meta, c):
        return A.Param(c[0], str(c[1]), True, pos=meta_pos(meta))


def _check_target(t: A.Expr) -> None:
    """Assignment targets are names, possibly indexed (``I[2]``, ``D[i,j]``, ``L[2][1]``)."""
    base = t
    while isinstance(base, A.Index):
        base = base.base
    while isinstance(base, A.Call):  # `len(3) = ...`: a variable declared with an index
        base = base.func
    if not isinstance(base, A.Name):
        raise MechSyntaxError("cannot assign to this expression", t.pos, underline=True)


def build(builder: Transformer_NonRecursive, tree: Any, source: Source) -> A.Program:
    """``builder.transform(tree)``, a syntax error raised while building located in ``source``."""
    try:
        return builder.transform(tree)
    except VisitError as e:
        err = e.orig_exc
        if isinstance(err, MechSyntaxError):
            err.source = source
            raise err from None
        raise
