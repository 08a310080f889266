"""A fast path for the statements most scripts are made of: expression statements, assignments,
declarations, ``x++``, blocks, ``if``, ``while``, ``for``, ``break`` and ``continue``, built by recursive descent into exactly the tree the grammar gives
(positions included; ``tests/dsl/test_fastparse.py`` compares the two on the corpus and on random
statements).  Anything else (procedures, ``return``, ``LIB``, other keywords) is parsed by Lark a
run of statements at a time; when a statement does not parse here or there, :func:`parse_fast`
gives up and the caller parses the whole text with Lark, which reports the error.  About 5 times
faster than Lark's LALR parser with positions propagated, on simple statements.
"""
from __future__ import annotations

import itertools
import re
from functools import lru_cache
from typing import Any, Callable, Optional

from . import ast as A
from .split import statement_ends

_TOKEN = re.compile(r"""
    (?P<ws>(?:[ \t\f\r\n]+|//[^\n]*|/\*.*?\*/)+)
  | (?P<MONOM>[0-9]+(?:/[0-9]+)?[A-Za-z_@][A-Za-z0-9_@]*)
  | (?P<RATIONAL>[0-9]+/[0-9]+)
  | (?P<NUMBER>[0-9]+)
  | (?P<IDENT>[A-Za-z_@][A-Za-z0-9_@]*)
  | (?P<STRING>"[^"]*")
  | (?P<OP>==|!=|<>|<=|>=|&&|\|\||\+\+|--|\*\*|\.\.|[-+*/%^<>!:=()\[\],;\#{}])
""", re.S | re.X)

# binary operators by precedence level (lowest first), each token to the tree's operator
_LEVELS = [{"||": "||", "or": "||", "&&": "&&", "and": "&&"}, {"==": "==", "!=": "!=", "<>": "!="},
           {"<": "<", "<=": "<=", ">": ">", ">=": ">="}, {"+": "+", "-": "-", ":": ":"},
           {"*": "*", "/": "/", "%": "mod", "mod": "mod", "div": "div"}]
_BINARY = {tok: (level, op) for level, ops in enumerate(_LEVELS) for tok, op in ops.items()}
_UNARY = {"-": "-", "+": "+", "!": "!", "not": "!"}
_END = ("$", None)


class _Fail(Exception):
    """Not a statement of the fast path (Lark decides)."""


class _Tok:
    __slots__ = ("kind", "value", "line", "col", "end_line", "end_col")

    def __init__(self, kind: str, value: str, line: int, col: int, end_line: int, end_col: int) -> None:
        self.kind, self.value = kind, value
        self.line, self.col, self.end_line, self.end_col = line, col, end_line, end_col


def _tokens(text: str, start: int, end: int, line: int, line_start: int, keywords: frozenset,
            at: tuple[int, int]) -> list[_Tok]:
    """The tokens of ``text[start:end]`` (``line``: the line at ``start``, ``line_start``: the
    offset where that line starts), at their places in the source (``text`` starts at line and
    column ``at`` there), then an end token; keywords become tokens of their own kind."""
    out = []
    pos = start
    match = _TOKEN.match
    dline, dcol = at[0] - 1, at[1] - 1
    while pos < end:
        m = match(text, pos, end)
        if m is None:
            raise _Fail
        kind = m.lastgroup
        value = m.group()
        if kind == "ws":
            nl = value.count("\n")
            if nl:
                line += nl
                line_start = pos + value.rfind("\n") + 1
            pos = m.end()
            continue
        if kind == "IDENT" and value in keywords:
            kind = "KW"
        elif kind == "OP":
            kind = value
        col = pos - line_start + 1 + (dcol if line == 1 else 0)
        if kind == "STRING" and "\n" in value:
            nl = value.count("\n")
            new_start = pos + value.rfind("\n") + 1
            out.append(_Tok(kind, value, line + dline, col, line + nl + dline, m.end() - new_start + 1))
            line, line_start = line + nl, new_start
        else:
            out.append(_Tok(kind, value, line + dline, col, line + dline, col + len(value)))
        pos = m.end()
    out.append(_EOF)
    return out


class _Parser:
    """Recursive descent over one statement's tokens.  Each parse returns ``(node, first, last)``:
    the node and the first and last token of its text (a parenthesized expression's node has the
    inner position, its text the parentheses: the grammar's positions work so)."""

    def __init__(self, toks: list[_Tok], types: frozenset) -> None:
        self.toks, self.i, self.types = toks, 0, types      # toks end with _EOF

    def peek(self, k: int = 0) -> _Tok:
        return self.toks[min(self.i + k, len(self.toks) - 1)]

    def take(self, kind: str) -> _Tok:
        tok = self.toks[self.i]
        if tok.kind != kind:
            raise _Fail
        self.i += 1
        return tok

    @staticmethod
    def pos(first: _Tok, last: _Tok) -> A.Pos:
        return A.Pos(first.line, first.col, last.end_line, last.end_col)

    # ---- expressions
    def exprlist(self) -> tuple[list, _Tok, _Tok]:
        node, first, last = self.expr()
        items = [node]
        while self.toks[self.i].kind == ",":
            self.i += 1
            node, _, last = self.expr()
            items.append(node)
        return items, first, last

    def expr(self) -> tuple:
        lo, first, last = self.binary(0)
        if self.toks[self.i].kind == "..":
            self.i += 1
            hi, _, last = self.binary(0)
            return A.Range(lo, hi, pos=self.pos(first, last)), first, last
        return lo, first, last

    def binary(self, level: int) -> tuple:
        """Left-associative binary operators of precedence ``level`` and above (precedence climbing)."""
        left, first, last = self.unary()
        while True:
            tok = self.toks[self.i]
            found = _BINARY.get(tok.value) if tok.kind in ("KW", tok.value) else None
            if found is None or found[0] < level:
                return left, first, last
            self.i += 1
            right, _, last = self.binary(found[0] + 1)
            left = A.BinOp(found[1], left, right, pos=self.pos(first, last))

    def unary(self) -> tuple:
        tok = self.toks[self.i]
        op = _UNARY.get(tok.value) if tok.kind in ("KW", tok.value) else None
        if op is None:
            return self.power()
        self.i += 1
        operand, _, last = self.unary()
        return A.UnOp(op, operand, pos=self.pos(tok, last)), tok, last

    def power(self) -> tuple:
        base, first, last = self.postfix()
        while self.toks[self.i].kind in ("^", "**"):
            self.i += 1
            if self.peek().kind == "-":
                self.i += 1
                right, _, last = self.postfix()
                right = A.UnOp("-", right, pos=right.pos)
            else:
                right, _, last = self.postfix()
            base = A.BinOp("^", base, right, pos=self.pos(first, last))
        return base, first, last

    def postfix(self) -> tuple:
        node, first, last = self.atom()
        while True:
            kind = self.toks[self.i].kind
            if kind == "[":
                self.i += 1
                items, _, _ = self.exprlist()
                last = self.take("]")
                node = A.Index(node, items, pos=self.pos(first, last))
            elif kind == "(":
                self.i += 1
                args = self.exprlist()[0] if self.peek().kind != ")" else []
                last = self.take(")")
                node = A.Call(node, args, pos=self.pos(first, last))
            else:
                return node, first, last

    def atom(self) -> tuple:
        tok = self.toks[self.i]
        kind = tok.kind
        self.i += 1
        if kind == "IDENT" or kind == "#":
            return A.Name(tok.value, pos=A.Pos(tok.line, tok.col, tok.end_line, tok.end_col)), tok, tok
        p = lambda: A.Pos(tok.line, tok.col, tok.end_line, tok.end_col)  # noqa: E731
        if kind == "NUMBER":
            return A.IntLit(_int(tok.value), pos=p()), tok, tok
        if kind == "RATIONAL":
            num, den = tok.value.split("/")
            return A.RatLit(_int(num), _int(den), pos=p()), tok, tok
        if kind == "MONOM":
            s = tok.value
            k = 0
            while s[k].isdigit() or s[k] == "/":
                k += 1
            num, _, den = s[:k].partition("/")
            return A.MonomLit(_int(num), _int(den) if den else 1, s[k:], pos=p()), tok, tok
        if kind == "STRING":
            return A.StrLit(tok.value[1:-1], pos=p()), tok, tok
        if kind == "(":
            items, _, _ = self.exprlist()
            last = self.take(")")
            node = items[0] if len(items) == 1 else A.Tuple(items, pos=self.pos(tok, last))
            return node, tok, last
        if kind == "KW" and tok.value in self.types and self.peek().kind == "(":
            self.i += 1
            args = self.exprlist()[0] if self.peek().kind != ")" else []
            last = self.take(")")
            return A.TypeCall(tok.value, args, pos=self.pos(tok, last)), tok, last
        raise _Fail

    # ---- statements
    def statement(self) -> tuple[A.Stmt, _Tok]:
        """One statement and its last token (its ``;`` or ``}``)."""
        first = self.peek()
        if first.kind == ";":
            self.i += 1
            return A.Empty(pos=self.pos(first, first)), first
        if first.kind == "{":
            block, last = self.block()
            return block, last
        if first.kind == "KW" and first.value in _CONTROL:
            return _CONTROL[first.value](self)
        stmt = self.simple()
        return stmt, self.take(";")

    def block(self) -> tuple[A.Block, _Tok]:
        first = self.take("{")
        body = []
        while self.peek().kind != "}":
            if self.peek().kind == "$":
                raise _Fail
            body.append(self.statement()[0])
        last = self.take("}")
        return A.Block(body, pos=self.pos(first, last)), last

    def if_stmt(self) -> tuple[A.If, _Tok]:
        first = self.take("KW")
        self.take("(")
        cond = self.expr()[0]
        self.take(")")
        then, last = self.block()
        orelse = None
        if self.peek().value == "else" and self.peek().kind == "KW":
            self.i += 1
            if self.peek().value == "if" and self.peek().kind == "KW":
                nested, last = self.if_stmt()
                orelse = [nested]
            else:
                blk, last = self.block()
                orelse = blk.body
        return A.If(cond, then.body, orelse, pos=self.pos(first, last)), last

    def while_stmt(self) -> tuple[A.While, _Tok]:
        first = self.take("KW")
        self.take("(")
        cond = self.expr()[0]
        self.take(")")
        body, last = self.block()
        return A.While(cond, body.body, pos=self.pos(first, last)), last

    def for_stmt(self) -> tuple[A.For, _Tok]:
        first = self.take("KW")
        self.take("(")
        init = self.simple() if self.peek().kind != ";" else None
        self.take(";")
        cond = self.expr()[0] if self.peek().kind != ";" else None
        self.take(";")
        step = self.simple() if self.peek().kind != ")" else None
        self.take(")")
        body, last = self.block()
        return A.For(init, cond, step, body.body, pos=self.pos(first, last)), last

    def jump(self) -> tuple[A.Stmt, _Tok]:
        tok = self.take("KW")
        node = (A.Break if tok.value == "break" else A.Continue)(pos=self.pos(tok, tok))
        return node, self.take(";")

    def simple(self) -> A.Stmt:
        """An expression statement, assignment, declaration or ``x++`` (without its ``;``)."""
        first = self.peek()
        if first.kind == "KW":
            if first.value in self.types and self.peek(1).kind == "IDENT":
                return self.decl()
            if not (first.value in self.types or first.value in _UNARY):
                raise _Fail
        start = self.i
        try:
            target, _, _ = self.postfix()
            kind = self.peek().kind
        except _Fail:
            kind = ""
        if kind in ("++", "--"):
            last = self.take(kind)
            _check_target(target)
            return A.IncDec(target, 1 if kind == "++" else -1, pos=self.pos(first, last))
        self.i = start
        targets, _, last = self.exprlist()
        if self.peek().kind == "=":
            self.i += 1
            values, _, last = self.exprlist()
            for t in targets:
                _check_target(t)
            return A.Assign(targets, values, pos=self.pos(first, last))
        return A.ExprStmt(targets, pos=self.pos(first, last))

    def decl(self) -> A.Decl:
        first = self.take("KW")
        items = [self.declarator()]
        while self.peek().kind == ",":
            self.i += 1
            items.append(self.declarator())
        last = self.toks[self.i - 1]
        value = None
        if self.peek().kind == "=":
            self.i += 1
            value, _, last = self.exprlist()
        return A.Decl(first.value, items, value, pos=self.pos(first, last))

    def declarator(self) -> A.Declarator:
        name = last = self.take("IDENT")
        dims = []
        while self.peek().kind == "[" and len(dims) < 2:
            self.i += 1
            dims.append(self.expr()[0])
            last = self.take("]")
        return A.Declarator(name.value, dims, pos=self.pos(name, last))



_CONTROL = {"if": _Parser.if_stmt, "while": _Parser.while_stmt, "for": _Parser.for_stmt, "break": _Parser.jump,
            "continue": _Parser.jump}
_EOF = _Tok("$", "", 0, 0, 0, 0)
_SKIP = re.compile(r"(?:[ \t\f\r\n]+|//[^\n]*|/\*.*?\*/)*+", re.S)  # blanks and comments before a statement
MAX_SHARED = 4096  # statement trees kept for reuse (about 2 KB each)
_SHARED: dict[tuple, dict[tuple[str, int], A.Stmt]] = {}


def _int(digits: str) -> int:
    if len(digits) > 4000:  # long literals: the builder's checks and messages
        raise _Fail
    return int(digits)


def _check_target(t: A.Expr) -> None:
    base = t
    while isinstance(base, A.Index):
        base = base.base
    if not isinstance(base, A.Name):
        raise _Fail


@lru_cache(maxsize=8)
def _words(terminals: tuple, types: tuple) -> tuple[frozenset, frozenset]:
    ident = re.compile(r"[A-Za-z_@][A-Za-z0-9_@]*")
    keywords = frozenset(v for kind, v in terminals if kind == "str" and ident.fullmatch(v))
    return keywords | frozenset(types), frozenset(types)


def parse_fast(text: str, at: tuple[int, int], terminals: Any, types: tuple[str, ...],
               lark_parse: Callable[[str, tuple[int, int]], A.Program], shared: bool = False,
               ends: Optional[list[int]] = None) -> Optional[A.Program]:
    """The program tree of ``text`` (which starts at line and column ``at`` of its source), or None
    when a statement does not parse (the caller then parses all of ``text`` with Lark).
    ``terminals``: the grammar's (for its keywords); ``types``: the type names; ``lark_parse``: Lark's
    parse of a run of other statements starting at a given line and column.  With ``shared``, a
    one-line statement whose text was parsed before at the same column reuses that tree (as an
    :class:`~mech.dsl.ast.Moved` when it was on another line): for running, not for inspecting.
    ``ends``: the statements' ends in ``text`` when the caller has found them."""
    keywords, type_set = _words(tuple((t.pattern.type, t.pattern.value) for t in terminals), types)
    cache = _SHARED.setdefault((keywords, type_set), {}) if shared and MAX_SHARED else None
    dline, dcol = at[0] - 1, at[1] - 1

    def shift(line: int, col: int) -> tuple[int, int]:
        return line + dline, col + (dcol if line == 1 else 0)

    body: list[A.Stmt] = []
    span: list[tuple[int, int]] = []        # (line, col) of the program's first token and its end
    pending = -1                            # where a run of statements for Lark starts (-1: none)
    prev, line, line_start = 0, 1, 0

    def flush(upto: int) -> None:
        nonlocal pending
        if pending < 0:
            return
        line0 = text.count("\n", 0, pending) + 1
        col0 = pending - (text.rfind("\n", 0, pending) + 1) + 1
        try:
            program = lark_parse(text[pending:upto], shift(line0, col0))
        except Exception:
            raise _Fail from None
        pending = -1
        if program.body:
            body.extend(program.body)
            _extend(span, program.pos)

    try:
        for end in statement_ends(text) if ends is None else ends:
            key = None
            if cache is not None:
                start = _SKIP.match(text, prev, end).end()
                piece = text[start:end]
                if "\n" not in piece:
                    nl = text.count("\n", prev, start)
                    here = line + nl
                    starts = text.rfind("\n", prev, start) + 1 if nl else line_start  # its line's start
                    col = start - starts + 1
                    if here == 1:
                        col += dcol
                    key = (piece, col)
                    hit = cache.get(key)
                    if hit is not None:
                        if pending >= 0:
                            flush(prev)
                        here += dline
                        hpos = hit.pos
                        body.append(hit if hpos.line == here else A.Moved(
                            hit, here - hpos.line, pos=A.Pos(here, hpos.col, here, hpos.end_col)))
                        if span:
                            span[1] = (here, col + len(piece))
                        else:
                            span.extend([(here, col), (here, col + len(piece))])
                        line, prev, line_start = here - dline, end, starts
                        continue
            try:
                toks = _tokens(text, prev, end, line, line_start, keywords, at)
                parser = _Parser(toks, type_set)
                stmt, last = parser.statement()
                if parser.i != len(toks) - 1:
                    raise _Fail
                if key is not None:
                    if len(cache) >= MAX_SHARED:  # the older half goes (the frequent come back at once)
                        for old in list(itertools.islice(cache, MAX_SHARED // 2)):
                            del cache[old]
                    cache[key] = stmt
            except (_Fail, RecursionError):
                stmt = None
                if pending < 0:
                    pending = prev
            else:
                flush(prev)
                body.append(stmt)
                _extend(span, A.Pos(stmt.pos.line, stmt.pos.col, last.end_line, last.end_col))
            line += text.count("\n", prev, end)
            line_start = text.rfind("\n", 0, end) + 1
            prev = end
        if text[prev:].strip():
            if pending < 0:
                pending = prev
            prev = len(text)
        flush(prev)
    except _Fail:
        return None
    if not span:
        return A.Program(body)
    (line0, col0), (line1, col1) = span
    return A.Program(body, pos=A.Pos(line0, col0, line1, col1))


def _extend(span: list, pos: A.Pos) -> None:
    """Widen the program's extent (first start, last end) by ``pos``."""
    if not span:
        span.extend([(pos.line, pos.col), (pos.end_line, pos.end_col)])
    else:
        span[1] = (pos.end_line, pos.end_col)
