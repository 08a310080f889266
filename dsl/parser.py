"""Parsing mech's Singular dialect (``singular.lark``, LALR) into the tree of :mod:`mech.dsl.ast`.

:func:`parse` returns a :class:`~mech.dsl.ast.Program` or raises :class:`MechSyntaxError`;
:func:`parse_pieces` parses a program a piece of whole statements at a time (the interpreter runs
each piece before parsing the next: long scripts stay small in memory, and after a syntax error the
statements before it have run); :func:`split_complete` finds where complete top-level statements
end (the REPL reads until one is complete).
"""
from __future__ import annotations

import itertools
import re
from functools import lru_cache
from pathlib import Path
from typing import Any, Iterator, Optional

from lark import Lark, Token, Transformer_NonRecursive, v_args
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, VisitError

from . import ast as A
from .errors import MechSyntaxError, Source

GRAMMAR = Path(__file__).with_name("singular.lark")


#: The first words of mechanism.lib's description statements (``mechanism m { ... }``).
MECHANISM_STATEMENTS = ("ground", "fix", "bar", "prismatic", "body", "slider")


def _pos(meta: Any) -> A.Pos:
    if getattr(meta, "empty", False):
        return A.NOPOS
    return A.Pos(meta.line, meta.column, meta.end_line, meta.end_column)


def _tpos(tok: Token) -> A.Pos:
    return A.Pos(tok.line, tok.column, tok.end_line, tok.end_column)


def _list(x: Optional[A.Tuple | list]) -> list:
    if x is None:
        return []
    return list(x)


class _Build(Transformer_NonRecursive):  # iterative: deeply nested input cannot overflow the stack
    """Lark callbacks building AST nodes from the parse tree."""

    # ---- expressions
    @v_args(meta=True)
    def name(self, meta, c):
        return A.Name(str(c[0]), pos=_tpos(c[0]))

    @v_args(meta=True)
    def int_lit(self, meta, c):
        return A.IntLit(int(c[0]), pos=_tpos(c[0]))

    @v_args(meta=True)
    def rat_lit(self, meta, c):
        num, den = str(c[0]).split("/")
        return A.RatLit(int(num), int(den), pos=_tpos(c[0]))

    @v_args(meta=True)
    def monom_lit(self, meta, c):
        s = str(c[0])
        i = 0
        while s[i].isdigit() or s[i] == "/":
            i += 1
        coeff, mono = s[:i], s[i:]
        num, _, den = coeff.partition("/")
        return A.MonomLit(int(num), int(den) if den else 1, mono, pos=_tpos(c[0]))

    @v_args(meta=True)
    def str_lit(self, meta, c):
        return A.StrLit(str(c[0])[1:-1], pos=_tpos(c[0]))

    def exprlist(self, c):
        return list(c)

    @v_args(meta=True)
    def paren(self, meta, c):
        items = c[0]
        if len(items) == 1:
            return items[0]
        return A.Tuple(items, pos=_pos(meta))

    @v_args(meta=True)
    def type_call(self, meta, c):
        return A.TypeCall(c[0], _list(c[1]), pos=_pos(meta))

    @v_args(meta=True)
    def call(self, meta, c):
        return A.Call(c[0], _list(c[1]), pos=_pos(meta))

    @v_args(meta=True)
    def index(self, meta, c):
        return A.Index(c[0], c[1], pos=_pos(meta))

    @v_args(meta=True)
    def range(self, meta, c):
        return A.Range(c[0], c[1], pos=_pos(meta))

    def type_name(self, c):
        return str(c[0])

    def _bin(op):  # noqa: N805 - a factory used in the class body
        @v_args(meta=True)
        def build(self, meta, c):
            return A.BinOp(op, c[0], c[1], pos=_pos(meta))
        return build

    add, sub, mul, div, mod = _bin("+"), _bin("-"), _bin("*"), _bin("/"), _bin("mod")
    intdiv, pow, repeat = _bin("div"), _bin("^"), _bin(":")
    eq, ne, lt, le, gt, ge = _bin("=="), _bin("!="), _bin("<"), _bin("<="), _bin(">"), _bin(">=")
    and_op, or_op = _bin("&&"), _bin("||")

    @v_args(meta=True)
    def pow_neg(self, meta, c):
        return A.BinOp("^", c[0], A.UnOp("-", c[1], pos=c[1].pos), pos=_pos(meta))

    def _un(op):  # noqa: N805
        @v_args(meta=True)
        def build(self, meta, c):
            return A.UnOp(op, c[0], pos=_pos(meta))
        return build

    neg, pos, not_op = _un("-"), _un("+"), _un("!")

    # ---- statements
    @v_args(meta=True)
    def start(self, meta, c):
        return A.Program(list(c), pos=_pos(meta))

    @v_args(meta=True)
    def expr_stmt(self, meta, c):
        return A.ExprStmt(c[0], pos=_pos(meta))

    @v_args(meta=True)
    def empty_stmt(self, meta, c):
        return A.Empty(pos=_pos(meta))

    @v_args(meta=True)
    def declarator(self, meta, c):
        return A.Declarator(str(c[0]), list(c[1:]), pos=_pos(meta))

    @v_args(meta=True)
    def decl(self, meta, c):
        typ, rest = c[0], c[1:]
        value = rest[-1]
        return A.Decl(typ, list(rest[:-1]), value, pos=_pos(meta))

    @v_args(meta=True)
    def mech_def(self, meta, c):
        typ, name, lines = c[0], c[1], c[2:]
        if typ != "mechanism":
            raise MechSyntaxError(f"a {{ ... }} description declares a mechanism, not a {typ}", _tpos(name))
        for words in lines:
            if str(words[0]) not in MECHANISM_STATEMENTS:
                raise MechSyntaxError(f"unknown mechanism statement '{words[0]}' (expected "
                                      f"{', '.join(MECHANISM_STATEMENTS)})", _tpos(words[0]), underline=True)
        text = "; ".join(" ".join(str(w) for w in words) for words in lines)
        return A.Decl("mechanism", [A.Declarator(str(name), [], pos=_tpos(name))],
                      [A.StrLit(text, pos=_pos(meta))], pos=_pos(meta))

    def mech_line(self, c):
        return c

    def mech_word(self, c):
        tok = c[-1]
        return Token(tok.type, "".join(str(t) for t in c), tok.start_pos, tok.line, tok.column,
                     tok.end_line, tok.end_column) if len(c) > 1 else tok

    @v_args(meta=True)
    def assign(self, meta, c):
        for t in c[0]:
            _check_target(t)
        return A.Assign(c[0], c[1], pos=_pos(meta))

    @v_args(meta=True)
    def incr_stmt(self, meta, c):
        _check_target(c[0])
        return A.IncDec(c[0], 1, pos=_pos(meta))

    @v_args(meta=True)
    def decr_stmt(self, meta, c):
        _check_target(c[0])
        return A.IncDec(c[0], -1, pos=_pos(meta))

    @v_args(meta=True)
    def break_stmt(self, meta, c):
        return A.Break(pos=_pos(meta))

    @v_args(meta=True)
    def continue_stmt(self, meta, c):
        return A.Continue(pos=_pos(meta))

    @v_args(meta=True)
    def return_stmt(self, meta, c):
        return A.Return(_list(c[0]), pos=_pos(meta))

    @v_args(meta=True)
    def kill_stmt(self, meta, c):
        return A.Kill(c[0], pos=_pos(meta))

    @v_args(meta=True)
    def export_stmt(self, meta, c):
        return A.Export(c[0], pos=_pos(meta))

    @v_args(meta=True)
    def keepring_stmt(self, meta, c):
        return A.Keepring(c[0], pos=_pos(meta))

    @v_args(meta=True)
    def setring_stmt(self, meta, c):
        return A.Setring(c[0], pos=_pos(meta))

    @v_args(meta=True)
    def lib_stmt(self, meta, c):
        return A.Lib(str(c[0])[1:-1], pos=_pos(meta))

    @v_args(meta=True)
    def quit_stmt(self, meta, c):
        return A.Quit(pos=_pos(meta))

    @v_args(meta=True)
    def help_stmt(self, meta, c):
        return A.Help(c[0], pos=_pos(meta))

    def help_topic(self, c):
        t = str(c[0])
        return t[1:-1] if t.startswith('"') else t

    def help_keyword(self, c):
        return str(c[0])

    @v_args(meta=True)
    def block(self, meta, c):
        return A.Block(list(c), pos=_pos(meta))

    @v_args(meta=True)
    def if_stmt(self, meta, c):
        cond, then, orelse = c[0], c[1], c[2] if len(c) > 2 else None
        if isinstance(orelse, A.Block):
            orelse = orelse.body
        elif orelse is not None:
            orelse = [orelse]
        return A.If(cond, then.body, orelse, pos=_pos(meta))

    @v_args(meta=True)
    def for_stmt(self, meta, c):
        init, cond, step, body = c
        return A.For(init, cond, step, body.body, pos=_pos(meta))

    @v_args(meta=True)
    def while_stmt(self, meta, c):
        return A.While(c[0], c[1].body, pos=_pos(meta))

    @v_args(meta=True)
    def proc_def(self, meta, c):
        static, name, params, doc, body = c
        return A.ProcDef(str(name), params, str(doc)[1:-1] if doc is not None else None, body.body,
                         static is not None, body.pos.line, pos=_pos(meta))

    def params(self, c):
        return [p for p in c if p is not None]

    @v_args(meta=True)
    def param(self, meta, c):
        if len(c) == 2:
            return A.Param(c[0], str(c[1]), pos=_pos(meta))
        return A.Param(None, str(c[0]), pos=_pos(meta))


def _check_target(t: A.Expr) -> None:
    """Assignment targets are names, possibly indexed (``I[2]``, ``D[i,j]``, ``L[2][1]``)."""
    base = t
    while isinstance(base, A.Index):
        base = base.base
    if not isinstance(base, A.Name):
        raise MechSyntaxError("cannot assign to this expression", t.pos, underline=True)


@lru_cache(maxsize=1)
def _parser() -> Lark:
    return Lark(GRAMMAR.read_text(), parser="lalr", propagate_positions=True, cache=True,
                maybe_placeholders=True)


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


def parse(text: str, source: Optional[Source] = None, at: tuple[int, int] = (1, 1)) -> A.Program:
    """The program tree of ``text``; raises :class:`MechSyntaxError` located in ``source``
    (``at``: the line and column where ``text`` starts there)."""
    source = source or Source("<string>", text)
    try:
        tree = _parser().parse(text)
        if at != (1, 1):
            _shift(tree, at)
        return build(_Build(), tree, source)
    except MechSyntaxError as e:
        e.source = source
        raise
    except UnexpectedInput as e:
        err = _syntax_error(e, text, source)
        err.pos = _moved(err.pos, at)
        raise err from None


def _describe(term: str) -> str:
    names = {"IDENT": "an identifier", "NUMBER": "a number", "RATIONAL": "a number", "MONOM": "a monomial",
             "STRING": "a string", "HASH": "'#'", "$END": "end of input"}
    if term in names:
        return names[term]
    for t in _parser().terminals:
        if t.name == term:
            return f"'{t.pattern.value}'"
    return term


def _syntax_error(e: UnexpectedInput, text: str, source: Source) -> MechSyntaxError:
    if isinstance(e, UnexpectedCharacters):
        ch = text[e.pos_in_stream] if e.pos_in_stream < len(text) else ""
        if ch == '"':
            msg = "unterminated string"
        elif text.startswith("/*", e.pos_in_stream):
            msg = "unterminated comment"
        else:
            msg = f"unexpected character '{ch}'"
        return MechSyntaxError(msg, A.Pos(e.line, e.column, e.line, e.column + 1), source)
    expected = set(getattr(e, "expected", ()) or ())
    tok = getattr(e, "token", None)
    at_end = isinstance(e, UnexpectedEOF) or tok is None or tok.type == "$END"
    if at_end:
        line, col = _after_previous(text, len(text))
        unclosed = _unclosed(text)
        if unclosed:
            msg = f"unexpected end of input: missing '{unclosed}'"
        elif "SEMICOLON" in expected:
            msg = "expected ';'"
        else:
            msg = "unexpected end of input: incomplete statement"
        return MechSyntaxError(msg, A.Pos(line, col, line, col + 1), source)
    if "SEMICOLON" in expected and _starts_new_line(text, tok) and _unterminated(text, tok.start_pos):
        line, col = _after_previous(text, tok.start_pos)
        return MechSyntaxError("expected ';'", A.Pos(line, col, line, col + 1), source)
    shown = tok.value if tok.type != "STRING" else "string"
    msg = f"unexpected '{shown}'"
    word = _statement_word(text, tok.start_pos)
    if word and tok.type == "IDENT":
        msg += f" ('{word}' is not a type)"
    elif expected & {"IDENT", "NUMBER"}:
        msg += ", expected an expression"
    elif len(expected) == 1:
        msg += f", expected {_describe(next(iter(expected)))}"
    return MechSyntaxError(msg, _tpos(tok), source, underline=True)


def _unclosed(text: str) -> str:
    """The closing bracket the end of ``text`` is missing ('' when balanced)."""
    stack = []
    pairs = {"(": ")", "[": "]", "{": "}"}
    for kind, start, _ in _scan(text):
        ch = text[start] if kind == "char" else " "
        if ch in pairs:
            stack.append(pairs[ch])
        elif ch in ")]}" and stack and stack[-1] == ch:
            stack.pop()
    return stack[-1] if stack else ""


def _statement_word(text: str, offset: int) -> str:
    """The identifier just before ``offset`` if it opens a statement (``ideals I = x;``)."""
    import re
    m = re.search(r"(^|[;{}])\s*([A-Za-z_@][A-Za-z0-9_@]*)\s*$", text[:offset])
    return m.group(2) if m else ""


def _starts_new_line(text: str, tok: Token) -> bool:
    before = text[:tok.start_pos].rstrip(" \t")
    return before.endswith("\n") or before == ""


def _unterminated(text: str, offset: int) -> bool:
    """Whether a statement before ``offset`` lacks its ``;`` (not at the start, nor after ``; { }``)."""
    k = _significant_end(text, offset)
    return k > 0 and text[k - 1] not in ";{}"


def _after_previous(text: str, offset: int) -> tuple[int, int]:
    """Line and column just after the last significant character before ``offset``."""
    k = _significant_end(text, offset)
    line = text.count("\n", 0, k) + 1
    col = k - (text.rfind("\n", 0, k) + 1) + 1
    return line, col


def _significant_end(text: str, offset: int) -> int:
    """End of the last character before ``offset`` that is not blank or inside a comment."""
    ends = [0]
    for kind, start, end in _scan(text[:offset]):
        if kind != "comment":
            ends.append(end)
    return ends[-1]


def _scan(text: str):
    """Significant lexical items of ``text``: ("string"|"comment"|"char", start, end)."""
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c in " \t\r\n\f":
            i += 1
        elif text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            yield "comment", i, j
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            yield "comment", i, j
            i = j
        elif c == '"':
            j = text.find('"', i + 1)
            j = n if j < 0 else j + 1
            yield "string", i, j
            i = j
        else:
            yield "char", i, i + 1
            i += 1


def split_complete(text: str) -> tuple[int, bool]:
    """``(end, open)``: the offset just after the last complete top-level statement of ``text``
    and whether the text after it holds an unfinished statement (unclosed brackets, string or
    comment, or significant text without its ``;``)."""
    depth, boundary, pending, after_brace, prev_end = 0, 0, False, False, 0
    for kind, start, end in _scan(text):
        if kind == "comment":
            if not text.startswith("*/", end - 2) and text.startswith("/*", start):
                return boundary, True
            continue
        if kind == "string" and (end - start < 2 or text[end - 1] != '"'):
            return boundary, True
        if after_brace:
            after_brace = False
            if not text.startswith("else", start):
                boundary, pending = prev_end, False
        pending = True
        ch = text[start] if kind == "char" else " "
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
            if ch == "}" and depth == 0:
                after_brace, prev_end = True, end
        elif ch == ";" and depth == 0:
            boundary, pending = end, False
    if after_brace:
        return prev_end, False
    return boundary, pending or depth > 0


# ---------------------------------------------------------------- long programs, piece by piece
PIECE = 1 << 16          # statements are parsed in pieces of about this many characters
MAX_STATEMENT = 10**6    # characters; parsing takes about 1 KB of memory per character

_SPECIAL = re.compile(r'"[^"]*"?|//[^\n]*|/\*.*?(?:\*/|\Z)|[][(){};]', re.S)
_BLANK = re.compile(r'(?:\s+|//[^\n]*|/\*.*?(?:\*/|\Z))*+', re.S)  # possessive: no backtracking memory
_ELSE = re.compile(r'(?:\s+|//[^\n]*|/\*.*?\*/)*+else(?![A-Za-z0-9_@])', re.S)


def statement_ends(text: str) -> Iterator[int]:
    """The offsets just after each complete top-level statement of ``text`` (its ``;``, or the
    ``}`` closing it when no ``else`` follows); what follows the last is blank or incomplete."""
    depth = 0
    for m in _SPECIAL.finditer(text):
        ch = m.group()
        if len(ch) > 1 or ch == '"':
            continue
        if ch in "([{":
            depth += 1
        elif ch in ")]":
            depth -= 1
        elif ch == "}":
            depth -= 1
            if depth == 0 and not _ELSE.match(text, m.end()):
                yield m.end()
        elif depth == 0:
            yield m.end()


def parse_pieces(text: str, source: Source) -> Iterator[A.Program]:
    """``text`` parsed a piece of whole statements at a time, for running each piece before the
    next is parsed: memory stays small for long scripts, the statements before a syntax error run
    before it is raised, and a statement longer than ``MAX_STATEMENT`` is refused unparsed."""
    start, prev, before, line = 0, 0, 0, 1
    for end in itertools.chain(statement_ends(text), [len(text)]):
        if end - prev > MAX_STATEMENT and end - _BLANK.match(text, prev).end() > MAX_STATEMENT:
            if prev > start:
                yield from _piece(text, start, prev, line, before, source)
            pos = _at(text, _BLANK.match(text, prev).end(), start, line)
            raise MechSyntaxError(f"statement too long ({end - prev} characters; at most {MAX_STATEMENT})",
                                  A.Pos(*pos, *pos), source)
        last, prev = prev, end
        if end > start and (end - start >= PIECE or end == len(text)):
            yield from _piece(text, start, end, line, before, source)
            line += text.count("\n", start, end)
            start, before = end, last


def _piece(text: str, start: int, end: int, line: int, before: int, source: Source) -> Iterator[A.Program]:
    """The statements of ``text[start:end]`` (which starts on ``line``; the statement before it
    starts at ``before``).  After a syntax error: the statements before the failing one, one by
    one, then its error, found with the statement before it (the messages look back)."""
    try:
        program = parse(text[start:end], source, _at(text, start, start, line))
    except MechSyntaxError:
        pass
    else:
        yield program
        return
    piece = text[start:end]
    a = 0
    for b in [*statement_ends(piece), len(piece)]:
        try:
            program = parse(piece[a:b], source, _at(text, start + a, start, line))
        except MechSyntaxError as err:
            parse(text[before:start + b], source, _at(text, before, start, line))
            raise err
        yield program
        before, a = start + a, b


def _at(text: str, offset: int, start: int, line: int) -> tuple[int, int]:
    """Line and column of ``offset`` in ``text``, whose offset ``start`` is on ``line``."""
    if offset >= start:
        line += text.count("\n", start, offset)
    else:
        line -= text.count("\n", offset, start)
    return line, offset - (text.rfind("\n", 0, offset) + 1) + 1


def _moved(pos: Optional[A.Pos], at: tuple[int, int]) -> Optional[A.Pos]:
    """A position in a piece of text starting at ``at`` as a position in the whole text."""
    if pos is None or pos.line == 0 or at == (1, 1):
        return pos
    line, col = at
    return A.Pos(pos.line + line - 1, pos.col + (col - 1 if pos.line == 1 else 0),
                 pos.end_line + line - 1, pos.end_col + (col - 1 if pos.end_line == 1 else 0))


def _shift(tree: Any, at: tuple[int, int]) -> None:
    """Move the positions of a piece's parse tree to where the piece starts (``at``)."""
    dline, dcol = at[0] - 1, at[1] - 1
    for t in tree.iter_subtrees():
        items = [t.meta] if not t.meta.empty else []
        items += [c for c in t.children if isinstance(c, Token)]
        for x in items:
            if x.line == 1:
                x.column += dcol
            if x.end_line == 1:
                x.end_column += dcol
            x.line += dline
            x.end_line += dline
