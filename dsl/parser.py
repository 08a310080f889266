"""Parsing mech's Singular dialect (``singular.lark``, LALR) into the tree of :mod:`mech.dsl.ast`.

:func:`parse` returns a :class:`~mech.dsl.ast.Program` or raises :class:`MechSyntaxError`;
:func:`parse_pieces` parses a program a piece of whole statements at a time (the interpreter runs
each piece before parsing the next: long scripts stay small in memory, and after a syntax error the
statements before it have run).  The tree is built in :mod:`~mech.dsl.builder`, error messages in
:mod:`~mech.dsl.syntax_errors`, statement ends found in :mod:`~mech.dsl.split`.
"""
from __future__ import annotations

import itertools
import re
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Any, Iterator, Optional

from . import ast as A
from . import registry
from .fastparse import parse_fast
from .errors import MechSyntaxError, Source
from .split import statement_ends
from .types import type_names

if TYPE_CHECKING:
    from lark import Lark

GRAMMAR = Path(__file__).with_name("singular.lark")


def _parser() -> Lark:
    """The LALR parser of the grammar with the type keywords of the registered types."""
    registry.load_plugins()
    return _parser_for(type_names())


@lru_cache(maxsize=4)
def _parser_for(plugin_types: tuple[str, ...]) -> Lark:
    from lark import Lark  # on the first statement the fast path leaves to Lark (start-up time)
    grammar = GRAMMAR.read_text()
    if plugin_types:
        grammar += "\n%extend type_name: " + " | ".join(f'"{t}"' for t in plugin_types) + "\n"
    return Lark(grammar, parser="lalr", propagate_positions=True, cache=True, maybe_placeholders=True)


def parse(text: str, source: Optional[Source] = None, at: tuple[int, int] = (1, 1),
          shared: bool = False, ends: Optional[list[int]] = None) -> A.Program:
    """The program tree of ``text``; raises :class:`MechSyntaxError` located in ``source``
    (``at``: the line and column where ``text`` starts there).  Simple statements take the fast
    path (:mod:`~mech.dsl.fastparse`; ``shared``: statements parsed before may share their trees,
    for running; ``ends``: where its statements end, when known), the others and errors Lark's parser."""
    source = source or Source("<string>", text)
    registry.load_plugins()
    words, builtin_types = grammar_words()
    program = parse_fast(text, at, words, builtin_types + type_names(),
                         lambda piece, where: _parse_lark(piece, source, where), shared, ends)
    return program if program is not None else _parse_lark(text, source, at)


@lru_cache(maxsize=1)
def grammar_words() -> tuple[tuple[str, ...], tuple[str, ...]]:
    """The grammar's words: its keywords (the string terminals that are identifiers) and its
    built-in type names (the rule ``type_name``), read from ``singular.lark`` without building
    Lark's parser (``tests/dsl/test_fastparse.py`` compares them with the parser's terminals)."""
    text = re.sub(r"(?m)^\s*//[^\n]*|\s//\s[^\n]*", "", GRAMMAR.read_text())  # comments
    words = tuple(sorted(set(re.findall(r'"([A-Za-z_@][A-Za-z0-9_@]*)"', text))))
    rule = re.search(r"(?ms)^!?type_name\s*:(.*?)(?=^\S|\Z)", text)
    return words, tuple(re.findall(r'"([^"]+)"', rule.group(1))) if rule else ()


def _parse_lark(text: str, source: Source, at: tuple[int, int]) -> A.Program:
    from lark.exceptions import UnexpectedInput

    from .builder import TreeBuilder, build
    from .syntax_errors import syntax_error
    try:
        tree = _parser().parse(text)
        if at != (1, 1):
            _shift(tree, at)
        return build(TreeBuilder(), tree, source)
    except MechSyntaxError as e:
        e.source = source
        raise
    except UnexpectedInput as e:
        err = syntax_error(e, text, source, _parser().terminals)
        err.pos = _moved(err.pos, at)
        raise err from None


# ---------------------------------------------------------------- long programs, piece by piece
PIECE = 1 << 16          # statements are parsed in pieces of about this many characters
MAX_STATEMENT = 10**6    # characters; parsing takes about 1 KB of memory per character

_BLANK = re.compile(r'(?:\s+|//[^\n]*|/\*.*?(?:\*/|\Z))*+', re.S)  # possessive: no backtracking memory


def parse_pieces(text: str, source: Source) -> Iterator[A.Program]:
    """``text`` parsed a piece of whole statements at a time, for running each piece before the
    next is parsed: memory stays small for long scripts, the statements before a syntax error run
    before it is raised, and a statement longer than ``MAX_STATEMENT`` is refused unparsed."""
    start, prev, before, line = 0, 0, 0, 1
    ends: list[int] = []  # the statements' ends in the piece being gathered
    for end in itertools.chain(statement_ends(text), [-1]):
        final = end < 0
        if final:
            end = len(text)
        if end - prev > MAX_STATEMENT and end - _BLANK.match(text, prev).end() > MAX_STATEMENT:
            if prev > start:
                yield from _piece(text, start, prev, line, before, source, ends)
            pos = _at(text, _BLANK.match(text, prev).end(), start, line)
            raise MechSyntaxError(f"statement too long ({end - prev} characters; at most {MAX_STATEMENT})",
                                  A.Pos(*pos, *pos), source)
        last, prev = prev, end
        if not final:
            ends.append(end - start)
        if end > start and (end - start >= PIECE or end == len(text)):
            yield from _piece(text, start, end, line, before, source, ends)
            line += text.count("\n", start, end)
            start, before, ends = end, last, []


def _piece(text: str, start: int, end: int, line: int, before: int, source: Source,
           ends: list[int]) -> Iterator[A.Program]:
    """The statements of ``text[start:end]`` (which starts on ``line``; the statement before it
    starts at ``before``; ``ends``: where they end in the piece).  After a syntax error: the
    statements before the failing one, one by one, then its error, found with the statement
    before it (the messages look back)."""
    try:
        program = parse(text[start:end], source, _at(text, start, start, line), True, ends)
    except MechSyntaxError:
        pass
    else:
        yield program
        return
    piece = text[start:end]
    a = 0
    for b in [*statement_ends(piece), len(piece)]:
        try:
            program = parse(piece[a:b], source, _at(text, start + a, start, line), True)
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
    from lark import Token
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
