"""Parsing the Macaulay2 dialect (``m2.lark``, LALR with a postlexer for line breaks) into the tree
of :mod:`mech.dsl.m2_ast`."""
from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path
from typing import Iterator, Optional

from lark import Lark, Token, Transformer_NonRecursive, v_args
from lark.exceptions import UnexpectedCharacters, UnexpectedInput

from . import ast as A
from .builder import build, meta_pos as _pos, parse_int, token_pos as _tpos
from .errors import MechSyntaxError, Source
from .m2_ast import (BreakExpr, Coeffs, Dot, ForLoop, Function, Generators, HashHas, IfExpr, Length, ListLit,
                     Option, ReturnExpr, RingCons, Seq, SetVar, Statement, Subscript, SymbolLit, TimeExpr, TryExpr,
                     WhileLoop)

GRAMMAR = Path(__file__).with_name("m2.lark")


#: tokens after which a line break ends the statement (an expression can end there)
_ENDERS = {"IDENT", "COEFFS", "NUMBER", "STRING", "RPAR", "RSQB", "RBRACE", "BREAK", "RETURN", "GENS"}
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
        digits = re.sub(r"\D", "", str(c[0]))
        return Coeffs(parse_int(digits, c[0]), pos=_tpos(c[0]))

    @v_args(meta=True)
    def int_lit(self, meta, c):
        return A.IntLit(parse_int(c[0]), pos=_tpos(c[0]))

    @v_args(meta=True)
    def str_lit(self, meta, c):
        text = str(c[0])[1:-1]
        return A.StrLit(re.sub(r"\\(.)", lambda m: {"n": "\n", "t": "\t", "r": "\r"}.get(m.group(1), m.group(1)), text),
                        pos=_tpos(c[0]))

    def exprlist(self, c):
        return [] if c == [None] else list(c)  # (): no items; (a,,b): a hole

    def seq(self, c):
        return list(c)

    @v_args(meta=True)
    def paren(self, meta, c):
        pos = _pos(meta)
        parts = c[0]  # expression lists and the ';' tokens between them
        if len(parts) == 1:
            items = parts[0]
            if len(items) == 1 and items[0] is not None:
                return items[0]
            return A.Tuple(_holes(items, pos), pos=pos)
        exprs: list[A.Expr] = []
        silent = False
        for p in parts:
            if isinstance(p, Token):
                silent = True
            elif p:
                if len(p) != 1 or p[0] is None:
                    raise MechSyntaxError("a ';' sequence takes one expression between the ';'", pos)
                exprs.extend(p)
                silent = False
        return Seq(exprs, silent, pos=pos)

    @v_args(meta=True)
    def sequence(self, meta, c):
        return A.Tuple(list(c), pos=_pos(meta))

    @v_args(meta=True)
    def list_lit(self, meta, c):
        return ListLit(_holes(c[0], _pos(meta)), pos=_pos(meta))

    @v_args(meta=True)
    def array_lit(self, meta, c):
        return ListLit(_holes(c[0], _pos(meta)), True, pos=_pos(meta))

    @v_args(meta=True)
    def ring_cons(self, meta, c):
        return RingCons(c[0], _holes(c[1], _pos(meta)), pos=_pos(meta))

    @v_args(meta=True)
    def symbol_(self, meta, c):
        return SymbolLit(str(c[0]), pos=_pos(meta))

    @v_args(meta=True)
    def generators(self, meta, c):
        return Generators(c[0], pos=_pos(meta))

    @v_args(meta=True)
    def hash_has(self, meta, c):
        return HashHas(c[0], c[1], pos=_pos(meta))

    @v_args(meta=True)
    def dot(self, meta, c):
        return Dot(c[0], str(c[1]), pos=_pos(meta))

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

    add, sub, mul, mod, pow = _bin("+"), _bin("-"), _bin("*"), _bin("%"), _bin("^")
    dsum = _bin("++")

    @v_args(meta=True)
    def div(self, meta, c):
        left, right = c
        if isinstance(right, RingCons):  # as Macaulay2 reads it: ZZ/p[x] is (ZZ/p)[x]
            return RingCons(A.BinOp("/", left, right.base, pos=_pos(meta)), right.items, pos=_pos(meta))
        return A.BinOp("/", left, right, pos=_pos(meta))
    eq, ne, lt, le, gt, ge = _bin("=="), _bin("!="), _bin("<"), _bin("<="), _bin(">"), _bin(">=")
    same, not_same, idiv, bslash, compose = _bin("==="), _bin("=!="), _bin("//"), _bin("\\"), _bin("@@")
    and_op, or_op, quotient = _bin("&&"), _bin("or"), _bin(":")
    vcat, bar, amp, tensor, range_excl = _bin("||"), _bin("|"), _bin("&"), _bin("**"), _bin("..<")

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
        if not isinstance(target, (A.Name, Subscript, A.Tuple)):
            raise MechSyntaxError("cannot assign to this expression", target.pos, underline=True)
        return SetVar(target, c[1], pos=_pos(meta))

    @v_args(meta=True)
    def local_assign(self, meta, c):
        target = c[0]
        if not isinstance(target, A.Name):
            raise MechSyntaxError("cannot assign to this expression", target.pos, underline=True)
        return SetVar(target, c[1], True, pos=_pos(meta))

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
        var, start, stop, when, kind, body = c
        return ForLoop(str(var), start, stop, None, kind.type == "LIST", body, when, pos=_pos(meta))

    @v_args(meta=True)
    def for_in(self, meta, c):
        var, items, when, kind, body = c
        return ForLoop(str(var), None, None, items, kind.type == "LIST", body, when, pos=_pos(meta))

    @v_args(meta=True)
    def while_(self, meta, c):
        return WhileLoop(c[0], c[1], pos=_pos(meta))

    @v_args(meta=True)
    def if_(self, meta, c):
        return IfExpr(c[0], c[1], c[2], pos=_pos(meta))

    @v_args(meta=True)
    def try_(self, meta, c):
        return TryExpr(c[0], c[1], c[2], pos=_pos(meta))

    @v_args(meta=True)
    def time_(self, meta, c):
        return TimeExpr(c[1], str(c[0]) == "elapsedTime", pos=_pos(meta))

    @v_args(meta=True)
    def return_(self, meta, c):
        return ReturnExpr(c[0] if c else None, pos=_pos(meta))

    @v_args(meta=True)
    def break_(self, meta, c):
        return BreakExpr(c[0] if c else None, pos=_pos(meta))


def _holes(items: list, pos: A.Pos) -> list:
    """The items of a bracket, an empty place (``f(a,,b)``) as the name ``null``."""
    return [A.Name("null", pos=pos) if x is None else x for x in items]


@lru_cache(maxsize=1)
def _parser() -> Lark:
    return Lark(GRAMMAR.read_text(), parser="lalr", propagate_positions=True, maybe_placeholders=True,
                postlex=_Lines(), lexer="contextual")


#: a line holding only ``end`` (the end of the input for Macaulay2's reader)
_END = re.compile(r"^[ \t]*end[ \t]*(?:--.*)?$", re.M)


def parse(text: str, source: Optional[Source] = None) -> A.Program:
    """The program tree of Macaulay2 code ``text``; raises :class:`MechSyntaxError` located in ``source``."""
    source = source or Source("<string>", text)
    end = _END.search(text)
    if end is not None:  # a line `end`: Macaulay2 reads no further
        text = text[:end.start()]
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


def is_complete(text: str) -> bool:
    """Whether the input can run: it parses, or its error is not an unfinished end."""
    try:
        parse(text)
    except MechSyntaxError as e:
        return not e.message.startswith("unexpected end of input")
    return True
