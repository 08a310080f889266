"""The messages of syntax errors: what was unexpected, what was expected, where a ``;`` is missing
or which bracket is unclosed (positions just after the previous significant text)."""
from __future__ import annotations

import re
from typing import Any, Iterable

from lark import Token
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput

from . import ast as A
from .builder import token_pos
from .errors import MechSyntaxError, Source
from .split import scan


def _describe(term: str, terminals: Iterable[Any]) -> str:
    names = {"IDENT": "an identifier", "NUMBER": "a number", "RATIONAL": "a number", "MONOM": "a monomial",
             "STRING": "a string", "HASH": "'#'", "$END": "end of input"}
    if term in names:
        return names[term]
    for t in terminals:
        if t.name == term:
            return f"'{t.pattern.value}'"
    return term


def syntax_error(e: UnexpectedInput, text: str, source: Source, terminals: Iterable[Any]) -> MechSyntaxError:
    """The error the user sees for Lark's ``e`` in ``text`` (``terminals``: the grammar's)."""
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
    shell = _SHELL_COMMAND.match(text, tok.start_pos) if shown in (":", "%") and _starts_new_line(text, tok) else None
    if shell:
        return MechSyntaxError(f"{msg}: '{shell.group(0).strip()}' is a command of the interactive shell "
                               f"(mech in a terminal), not of scripts", token_pos(tok), source)
    word = _statement_word(text, tok.start_pos)
    if word and tok.type == "IDENT":
        msg += f" ('{word}' is not a type)"
    elif expected & {"IDENT", "NUMBER"}:
        msg += ", expected an expression"
    elif len(expected) == 1:
        msg += f", expected {_describe(next(iter(expected)), terminals)}"
    return MechSyntaxError(msg, token_pos(tok), source, underline=True)


_SHELL_COMMAND = re.compile(r"[:%](?:time|reset|help)\b[^\n;]*")


def _unclosed(text: str) -> str:
    """The closing bracket the end of ``text`` is missing ('' when balanced)."""
    stack = []
    pairs = {"(": ")", "[": "]", "{": "}"}
    for kind, start, _ in scan(text):
        ch = text[start] if kind == "char" else " "
        if ch in pairs:
            stack.append(pairs[ch])
        elif ch in ")]}" and stack and stack[-1] == ch:
            stack.pop()
    return stack[-1] if stack else ""


def _statement_word(text: str, offset: int) -> str:
    """The identifier just before ``offset`` if it opens a statement (``ideals I = x;``)."""
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
    for kind, start, end in scan(text[:offset]):
        if kind != "comment":
            ends.append(end)
    return ends[-1]
