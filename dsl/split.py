"""Where statements end, without parsing: :func:`split_complete` (the REPL reads until a statement is
complete), :func:`statement_ends` (long programs are parsed a piece of whole statements at a time)
and :func:`scan`, the significant lexical items (strings, comments, characters)."""
from __future__ import annotations

import re
from typing import Iterator


def scan(text: str) -> Iterator[tuple[str, int, int]]:
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
    for kind, start, end in scan(text):
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


_SPECIAL = re.compile(r'"(?:[^"\\]|\\.)*"?|//[^\n]*|/\*.*?(?:\*/|\Z)|[][(){};]', re.S)
_SIMPLE = re.compile(r'(?:[^][(){};"/]++|/(?![/*]))*+;')
_ELSE = re.compile(r'(?:\s+|//[^\n]*|/\*.*?\*/)*+else(?![A-Za-z0-9_@])', re.S)


def statement_ends(text: str) -> Iterator[int]:
    """The offsets just after each complete top-level statement of ``text`` (its ``;``, or the
    ``}`` closing it when no ``else`` follows); what follows the last is blank or incomplete."""
    depth, pos = 0, 0
    simple, special = _SIMPLE.match, _SPECIAL.search
    while True:
        if depth == 0:
            m = simple(text, pos)
            if m is not None:  # a statement without brackets, strings or comments: one match
                pos = m.end()
                yield pos
                continue
        m = special(text, pos)
        if m is None:
            return
        pos = m.end()
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
