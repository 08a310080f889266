"""A Pygments lexer for mech's Singular language (the REPL colours input with it; docs can use it too).

Commands of the registry are ``Name.Builtin``, system variables (``basering``, ``timer``...)
``Name.Builtin.Pseudo``; the REPL's own commands (``:reset``, ``%time on``, ``?std``) are
``Keyword.Pseudo`` at the start of a line.
"""
from __future__ import annotations

from typing import Any, Iterable, Iterator, Optional

from pygments.lexer import RegexLexer, words
from pygments.token import Comment, Keyword, Name, Number, Operator, Punctuation, String, Text, Whitespace

from .types import type_names

#: Statement keywords and word operators of the language.
KEYWORDS = ("if", "else", "for", "while", "proc", "static", "return", "break", "continue", "kill", "export",
            "keepring", "setring", "LIB", "quit", "exit", "help", "and", "or", "not", "div", "mod")
#: The built-in type names (declarations ``poly f = ...;``); :func:`type_words` adds the libraries' types.
TYPES = ("int", "bigint", "number", "poly", "ideal", "matrix", "list", "string", "intvec", "intmat", "map",
         "def", "ring", "qring", "vector", "module", "resolution", "link")
#: Names the interpreter itself gives a value.
SYSTEM_VARIABLES = ("basering", "timer", "rtimer", "voice", "printlevel")

IDENT = r"[A-Za-z_@][A-Za-z0-9_@]*"


def type_words() -> tuple[str, ...]:
    """The type keywords: the built-in types and those libraries registered (:mod:`mech.dsl.types`)."""
    return TYPES + type_names()


def _registry_commands() -> frozenset[str]:
    from . import registry
    registry.load_plugins()
    return frozenset(registry.COMMANDS)


class MechLexer(RegexLexer):
    """mech / Singular source.  ``commands`` (an option) replaces the registry's command names."""

    name = "mech"
    aliases = ["mech", "singular"]
    filenames = ["*.mech", "*.sing", "*.lib"]
    mimetypes = ["text/x-mech"]

    tokens = {
        "root": [
            (r"(?m)^[ \t]*[:%?][A-Za-z]*", Keyword.Pseudo),
            (r"[ \t\r\n\f]+", Whitespace),
            (r"//.*?$", Comment.Single),
            (r"/\*[\s\S]*?(\*/|\Z)", Comment.Multiline),
            (r'"(?:[^"\\]|\\.)*"?', String),
            (words(KEYWORDS, suffix=r"\b"), Keyword),
            (words(TYPES, suffix=r"\b"), Keyword.Type),
            (words(SYSTEM_VARIABLES, suffix=r"\b"), Name.Builtin.Pseudo),
            (r"\d+/\d+", Number),
            (r"\d+", Number.Integer),
            (IDENT, Name),
            (r"#", Name.Variable.Magic),
            (r"==|!=|<>|<=|>=|&&|\|\||\+\+|--|\*\*|\.\.|[-+*/%^<>!=:&|]", Operator),
            (r"[()\[\]{},;.]", Punctuation),
            (r".", Text),
        ]
    }

    def __init__(self, **options: object) -> None:
        super().__init__(**options)
        given: Optional[Iterable[str]] = options.get("commands")  # type: ignore[assignment]
        self._commands = frozenset(given) if given is not None else None

    def get_tokens_unprocessed(self, text: str, stack: Iterable[str] = ("root",)
                               ) -> Iterator[tuple[int, Any, str]]:
        if self._commands is None:
            self._commands = _registry_commands()
        plugin_types = frozenset(type_names())
        for index, token, value in super().get_tokens_unprocessed(text, stack):
            if token is Name and value in plugin_types:
                token = Keyword.Type
            elif token is Name and value in self._commands:
                token = Name.Builtin
            yield index, token, value
