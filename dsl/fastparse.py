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

from .machine_int import literal
from . import ast as A
from .split import statement_ends
from .templates import make, shape

_TOKEN = re.compile(r"""[ \t]*+(?:   # spaces before a token are taken with it: one match a token
    (?P<ws>(?:[ \t\f\r\n]+|//[^\n]*|/\*.*?\*/)+|\Z)
  | (?P<MONOM>[0-9]+(?:/[0-9]+)?[A-Za-z_@][A-Za-z0-9_@]*)
  | (?P<RATIONAL>[0-9]+/[0-9]+)
  | (?P<NUMBER>[0-9]+)
  | (?P<IDENT>[A-Za-z_@][A-Za-z0-9_@]*)
  | (?P<STRING>"(?:[^"\\]|\\.)*")
  | (?P<OP>==|!=|<>|<=|>=|&&|\|\||\+\+|--|\*\*|\.\.|[-+*/%^<>!:=()\[\],;\#{}]))
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


_new_pos = tuple.__new__  # _new_pos(A.Pos, (line, col, end_line, end_col)): without the named tuple's __new__


def _tokens(text: str, start: int, end: int, line: int, line_start: int, keywords: frozenset,
            at: tuple[int, int]) -> list[tuple]:
    """The tokens of ``text[start:end]`` (``line``: the line at ``start``, ``line_start``: the
    offset where that line starts), at their places in the source (``text`` starts at line and
    column ``at`` there), then an end token; keywords become tokens of their own kind."""
    out = []
    append = out.append
    pos = start
    match = _TOKEN.match
    dline, dcol = at[0] - 1, at[1] - 1
    shift = dcol if line == 1 else 0
    while pos < end:
        m = match(text, pos, end)
        if m is None:
            raise _Fail
        kind = m.lastgroup
        value = m.group(kind)
        new = m.end()
        pos = new - len(value)
        if kind == "ws":
            nl = value.count("\n")
            if nl:
                line += nl
                line_start = pos + value.rfind("\n") + 1
                shift = 0
            pos = new
            continue
        if kind == "IDENT":
            if value in keywords:
                kind = "KW"
        elif kind == "OP":
            kind = value
        col = pos - line_start + 1 + shift
        if kind == "STRING" and "\n" in value:
            nl = value.count("\n")
            new_start = pos + value.rfind("\n") + 1
            append((kind, value, line + dline, col, line + nl + dline, new - new_start + 1))
            line, line_start, shift = line + nl, new_start, 0
        else:
            append((kind, value, line + dline, col, line + dline, col + new - pos))
        pos = new
    append(_EOF)
    return out


# the tokens of a line without comments, each with the blanks before it (one ``findall`` a line)
_LINE_TOKEN = re.compile(r"""([ \t]*)(
    [0-9]+(?:/[0-9]+)?[A-Za-z_@][A-Za-z0-9_@]*|[0-9]+/[0-9]+|[0-9]+|[A-Za-z_@][A-Za-z0-9_@]*|"(?:[^"\\]|\\.)*"
  | ==|!=|<>|<=|>=|&&|\|\||\+\+|--|\*\*|\.\.|[-+*/%^<>!:=()\[\],;\#{}])""", re.X)
_NAME_START = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_@")


def _line_tokens(piece: str, line: int, col: int, keywords: frozenset) -> Optional[list[tuple]]:
    """The tokens of a one-line statement ``piece`` without comments starting at ``line`` and
    ``col``, as :func:`_tokens` gives them (about twice as fast); None for a text it leaves to
    :func:`_tokens` (a character none of its tokens takes)."""
    out = []
    append = out.append
    start = col
    for blank, value in _LINE_TOKEN.findall(piece):
        col += len(blank)
        end = col + len(value)
        c = value[0]
        if c in _NAME_START:
            kind = "KW" if value in keywords else "IDENT"
        elif c.isdigit():
            kind = "NUMBER" if value.isdigit() else "RATIONAL" if value.replace("/", "", 1).isdigit() else "MONOM"
        elif c == '"':
            kind = "STRING"
        else:
            kind = value
        append((kind, value, line, col, line, end))
        col = end
    if col - start != len(piece.rstrip(" \t")):
        return None
    append(_EOF)
    return out


_LEAF = frozenset(("IDENT", "#", "NUMBER", "RATIONAL", "MONOM", "STRING"))  # tokens that are whole atoms
_AFTER_ATOM = frozenset(("[", "(", "^", "**", "++", "--"))  # tokens that extend an atom


def _leaf(tok: tuple) -> A.Expr:
    """The node of a one-token atom."""
    kind, value = tok[0], tok[1]
    pos = _new_pos(A.Pos, tok[2:])
    if kind == "IDENT" or kind == "#":
        return A.Name(value, pos=pos)
    if kind == "NUMBER":
        return A.IntLit(literal(_int(value)), pos=pos)
    if kind == "RATIONAL":
        num, den = value.split("/")
        return A.RatLit(_int(num), _int(den), pos=pos)
    if kind == "MONOM":
        k = 0
        while value[k].isdigit() or value[k] == "/":
            k += 1
        num, _, den = value[:k].partition("/")
        return A.MonomLit(_int(num), _int(den) if den else 1, value[k:], pos=pos)
    return A.StrLit(A.string_value(value), pos=pos)


def _span(first: tuple, last: tuple) -> A.Pos:
    return _new_pos(A.Pos, (first[2], first[3], last[4], last[5]))


class _Parser:
    """Recursive descent over one statement's tokens (tuples: kind, value, line, col, end line,
    end col).  Each parse returns ``(node, first, last)``: the node and the first and last token of
    its text (a parenthesized expression's node has the inner position, its text the parentheses:
    the grammar's positions work so)."""

    def __init__(self, toks: list[tuple], types: frozenset) -> None:
        self.toks, self.i, self.types = toks, 0, types      # toks end with _EOF

    def peek(self, k: int = 0) -> tuple:
        return self.toks[min(self.i + k, len(self.toks) - 1)]

    def take(self, kind: str) -> tuple:
        tok = self.toks[self.i]
        if tok[0] != kind:
            raise _Fail
        self.i += 1
        return tok

    pos = staticmethod(_span)

    # ---- expressions
    def exprlist(self) -> tuple[list, tuple, tuple]:
        node, first, last = self.expr()
        items = [node]
        while self.toks[self.i][0] == ",":
            self.i += 1
            node, _, last = self.expr()
            items.append(node)
        return items, first, last

    def expr(self) -> tuple:
        lo, first, last = self.binary(0)
        if self.toks[self.i][0] == "..":
            self.i += 1
            hi, _, last = self.binary(0)
            return A.Range(lo, hi, pos=_span(first, last)), first, last
        return lo, first, last

    def binary(self, level: int) -> tuple:
        """Left-associative binary operators of precedence ``level`` and above (precedence climbing)."""
        left, first, last = self.unary()
        toks = self.toks
        while True:
            tok = toks[self.i]
            found = _BINARY.get(tok[1]) if tok[0] == "KW" or tok[0] == tok[1] else None
            if found is None or found[0] < level:
                return left, first, last
            self.i += 1
            right, _, last = self.binary(found[0] + 1)
            left = A.BinOp(found[1], left, right, pos=_span(first, last))

    def unary(self) -> tuple:
        toks, i = self.toks, self.i
        tok = toks[i]
        kind = tok[0]
        if kind in _LEAF and toks[i + 1][0] not in _AFTER_ATOM:  # the common case: a plain atom
            self.i = i + 1
            return _leaf(tok), tok, tok
        op = _UNARY.get(tok[1]) if kind == "KW" or kind == tok[1] else None
        if op is None:
            return self.power()
        self.i += 1
        operand, _, last = self.unary()
        return A.UnOp(op, operand, pos=_span(tok, last)), tok, last

    def power(self) -> tuple:
        base, first, last = self.postfix()
        while self.toks[self.i][0] in ("^", "**"):
            self.i += 1
            if self.peek()[0] == "-":
                self.i += 1
                right, _, last = self.postfix()
                right = A.UnOp("-", right, pos=right.pos)
            else:
                right, _, last = self.postfix()
            base = A.BinOp("^", base, right, pos=_span(first, last))
        return base, first, last

    def postfix(self) -> tuple:
        node, first, last = self.atom()
        while True:
            kind = self.toks[self.i][0]
            if kind == "[":
                self.i += 1
                items, _, _ = self.exprlist()
                last = self.take("]")
                node = A.Index(node, items, pos=_span(first, last))
            elif kind == "(":
                self.i += 1
                args = self.exprlist()[0] if self.peek()[0] != ")" else []
                last = self.take(")")
                node = A.Call(node, args, pos=_span(first, last))
            else:
                return node, first, last

    def atom(self) -> tuple:
        tok = self.toks[self.i]
        kind = tok[0]
        self.i += 1
        if kind in _LEAF:
            return _leaf(tok), tok, tok
        if kind == "(":
            items, _, _ = self.exprlist()
            last = self.take(")")
            node = items[0] if len(items) == 1 else A.Tuple(items, pos=_span(tok, last))
            return node, tok, last
        if kind == "KW" and tok[1] in self.types and self.peek()[0] == "(":
            self.i += 1
            args = self.exprlist()[0] if self.peek()[0] != ")" else []
            last = self.take(")")
            return A.TypeCall(tok[1], args, pos=_span(tok, last)), tok, last
        raise _Fail

    # ---- statements
    def statement(self) -> tuple[A.Stmt, tuple]:
        """One statement and its last token (its ``;`` or ``}``)."""
        first = self.toks[self.i]
        kind = first[0]
        if kind == ";":
            self.i += 1
            return A.Empty(pos=_span(first, first)), first
        if kind == "{":
            block, last = self.block()
            return block, last
        if kind == "KW" and first[1] in _CONTROL:
            return _CONTROL[first[1]](self)
        stmt = self.simple()
        return stmt, self.take(";")

    def block(self) -> tuple[A.Block, tuple]:
        first = self.take("{")
        body = []
        while self.peek()[0] != "}":
            if self.peek()[0] == "$":
                raise _Fail
            body.append(self.statement()[0])
        last = self.take("}")
        return A.Block(body, pos=_span(first, last)), last

    def if_stmt(self) -> tuple[A.If, tuple]:
        first = self.take("KW")
        self.take("(")
        cond = self.expr()[0]
        self.take(")")
        then, last = self.block()
        orelse = None
        if self.peek()[1] == "else" and self.peek()[0] == "KW":
            self.i += 1
            if self.peek()[1] == "if" and self.peek()[0] == "KW":
                nested, last = self.if_stmt()
                orelse = [nested]
            else:
                blk, last = self.block()
                orelse = blk.body
        return A.If(cond, then.body, orelse, pos=_span(first, last)), last

    def while_stmt(self) -> tuple[A.While, tuple]:
        first = self.take("KW")
        self.take("(")
        cond = self.expr()[0]
        self.take(")")
        body, last = self.block()
        return A.While(cond, body.body, pos=_span(first, last)), last

    def for_stmt(self) -> tuple[A.For, tuple]:
        first = self.take("KW")
        self.take("(")
        init = self.simple() if self.peek()[0] != ";" else None
        self.take(";")
        cond = self.expr()[0] if self.peek()[0] != ";" else None
        self.take(";")
        step = self.simple() if self.peek()[0] != ")" else None
        self.take(")")
        body, last = self.block()
        return A.For(init, cond, step, body.body, pos=_span(first, last)), last

    def jump(self) -> tuple[A.Stmt, tuple]:
        tok = self.take("KW")
        node = (A.Break if tok[1] == "break" else A.Continue)(pos=_span(tok, tok))
        return node, self.take(";")

    def simple(self) -> A.Stmt:
        """An expression statement, assignment, declaration or ``x++`` (without its ``;``)."""
        toks = self.toks
        first = toks[self.i]
        kind = first[0]
        if kind == "IDENT" and toks[self.i + 1][0] == "=":  # name = ...: the common assignment
            self.i += 2
            values, _, last = self.exprlist()
            target = _new_pos(A.Pos, first[2:])
            return A.Assign([A.Name(first[1], pos=target)], values, pos=_span(first, last))
        if kind == "KW":
            if first[1] in self.types and self.peek(1)[0] == "IDENT":
                return self.decl()
            if not (first[1] in self.types or first[1] in _UNARY):
                raise _Fail
        start = self.i
        try:
            target, _, _ = self.postfix()
            kind = self.peek()[0]
        except _Fail:
            kind = ""
        if kind in ("++", "--"):
            last = self.take(kind)
            _check_target(target)
            return A.IncDec(target, 1 if kind == "++" else -1, pos=_span(first, last))
        self.i = start
        targets, _, last = self.exprlist()
        if self.peek()[0] == "=":
            self.i += 1
            values, _, last = self.exprlist()
            for t in targets:
                _check_target(t)
            return A.Assign(targets, values, pos=_span(first, last))
        return A.ExprStmt(targets, pos=_span(first, last))

    def decl(self) -> A.Decl:
        first = self.take("KW")
        items = [self.declarator()]
        while self.peek()[0] == ",":
            self.i += 1
            items.append(self.declarator())
        last = self.toks[self.i - 1]
        value = None
        if self.peek()[0] == "=":
            self.i += 1
            value, _, last = self.exprlist()
        return A.Decl(first[1], items, value, pos=_span(first, last))

    def declarator(self) -> A.Declarator:
        name = last = self.take("IDENT")
        dims = []
        while self.peek()[0] == "[" and len(dims) < 2:
            self.i += 1
            dims.append(self.expr()[0])
            last = self.take("]")
        return A.Declarator(name[1], dims, pos=_span(name, last))


_CONTROL = {"if": _Parser.if_stmt, "while": _Parser.while_stmt, "for": _Parser.for_stmt, "break": _Parser.jump,
            "continue": _Parser.jump}
_EOF = ("$", "", 0, 0, 0, 0)
_SKIP = re.compile(r"(?:[ \t\f\r\n]+|//[^\n]*|/\*.*?\*/)*+", re.S)  # blanks and comments before a statement
MAX_SHARED = 4096  # statement trees and templates kept for reuse (about 2 KB each)
_ONCE, _NONE = "once", "none"  # a shape seen once (its template is made the second time), a shape without one
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
def _words(words: tuple[str, ...], types: tuple[str, ...]) -> tuple[frozenset, frozenset]:
    return frozenset(words) | frozenset(types), frozenset(types)


def parse_fast(text: str, at: tuple[int, int], words: tuple[str, ...], types: tuple[str, ...],
               lark_parse: Callable[[str, tuple[int, int]], A.Program], shared: bool = False,
               ends: Optional[list[int]] = None) -> Optional[A.Program]:
    """The program tree of ``text`` (which starts at line and column ``at`` of its source), or None
    when a statement does not parse (the caller then parses all of ``text`` with Lark).
    ``words``: the grammar's keywords; ``types``: the type names; ``lark_parse``: Lark's
    parse of a run of other statements starting at a given line and column.  With ``shared``, a
    one-line statement whose text was parsed before at the same column reuses that tree (as an
    :class:`~mech.dsl.ast.Moved` when it was on another line): for running, not for inspecting.
    ``ends``: the statements' ends in ``text`` when the caller has found them."""
    keywords, type_set = _words(words, types)
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
                    shaped = shape(piece)
                    if shaped is not None:  # numbers: the template of its shape, from its second time
                        skey = (shaped[0], col)
                        template = cache.get(skey)
                        if template is None or template is _ONCE:
                            template = _template(text, prev, end, line, line_start, keywords, at, type_set,
                                                 piece, col, shaped[1]) if template is _ONCE else _ONCE
                            _remember(cache, skey, template)
                        if template is not _ONCE and template is not _NONE:
                            if pending >= 0:
                                flush(prev)
                            here += dline
                            body.append(A.Relit(template, shaped[1], here - template.tree.pos.line,
                                                _new_pos(A.Pos, (here, col, here, col + len(piece)))))
                            if span:
                                span[1] = (here, col + len(piece))
                            else:
                                span.extend([(here, col), (here, col + len(piece))])
                            line, prev, line_start = here - dline, end, starts
                            continue
                    key = (piece, col) if shaped is None or template is _NONE else None  # a shape's first time
                    hit = cache.get(key) if key is not None else None
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
                toks = None
                if cache is not None and "\n" not in piece and "//" not in piece and "/*" not in piece:
                    toks = _line_tokens(piece, here + dline, col, keywords)
                if toks is None:
                    toks = _tokens(text, prev, end, line, line_start, keywords, at)
                parser = _Parser(toks, type_set)
                stmt, last = parser.statement()
                if parser.i != len(toks) - 1:
                    raise _Fail
                if key is not None:
                    _remember(cache, key, stmt)
            except (_Fail, RecursionError):
                stmt = None
                if pending < 0:
                    pending = prev
            else:
                if pending >= 0:
                    flush(prev)
                body.append(stmt)
                if span:
                    span[1] = (last[4], last[5])
                else:
                    span.extend([(stmt.pos.line, stmt.pos.col), (last[4], last[5])])
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


def _remember(cache: dict, key: tuple, value: Any) -> None:
    if len(cache) >= MAX_SHARED:  # the older half goes (the frequent come back at once)
        for old in list(itertools.islice(cache, MAX_SHARED // 2)):
            del cache[old]
    cache[key] = value


def _template(text: str, start: int, end: int, line: int, line_start: int, keywords: frozenset,
              at: tuple[int, int], types: frozenset, piece: str, col: int, lits: list[str]) -> Any:
    """The template of the statement ``text[start:end]`` (its text ``piece`` at column ``col``,
    its numbers ``lits``), or _NONE when it has none (not a statement of the fast path, or refused)."""
    try:
        toks = _tokens(text, start, end, line, line_start, keywords, at)
        parser = _Parser(toks, types)
        stmt, _ = parser.statement()
        if parser.i != len(toks) - 1:
            return _NONE
    except (_Fail, RecursionError):
        return _NONE
    return make(stmt, piece, col, lits) or _NONE


def _extend(span: list, pos: A.Pos) -> None:
    """Widen the program's extent (first start, last end) by ``pos``."""
    if not span:
        span.extend([(pos.line, pos.col), (pos.end_line, pos.end_col)])
    else:
        span[1] = (pos.end_line, pos.end_col)
