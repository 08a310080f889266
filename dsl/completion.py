"""Tab completion for the REPL: variables in scope, ring variables and parameters, commands
(with the library that provides them), keywords and types; library names after ``LIB "``,
topics after ``help`` or ``?``, the shell's own commands after ``:``."""
from __future__ import annotations

import re
from typing import Callable, Iterator

from prompt_toolkit.completion import CompleteEvent, Completer, Completion
from prompt_toolkit.document import Document

from .highlight import KEYWORDS, SYSTEM_VARIABLES, type_words
from .interpreter import Interpreter
from .split import scan

#: The shell's own commands (handled by the REPL, not the language) and what they do.
SHELL_COMMANDS = {
    ":help": "the shell's keys and commands",
    ":reset": "a fresh session (forget all rings and variables)",
    ":time": ":time on / :time off: print each command's time (as timer = 1;)",
}

_WORD = re.compile(r"[A-Za-z_@][A-Za-z0-9_@]*$")
_LIB = re.compile(r'\bLIB\s*"([^"]*)$')
_HELP = re.compile(r'(?:\bhelp\s+|^\s*\?\s*)([A-Za-z_@][A-Za-z0-9_@]*)?$')
_SHELL = re.compile(r"^\s*([:%][A-Za-z]*)$")


def candidates(interp: Interpreter, before: str) -> tuple[str, list[tuple[str, str]]]:
    """``(prefix, [(text, description), ...])``: the word that ends ``before`` (the input up to the
    cursor) and its completions, in the order they are offered (variables, ring variables,
    commands, keywords)."""
    m = _LIB.search(before)
    if m:
        return m.group(1), _matching(m.group(1), [(name, "library") for name in _libraries(interp)])
    m = _SHELL.match(before)
    if m:
        word = m.group(1)
        return word, [(word[0] + name[1:], what) for name, what in SHELL_COMMANDS.items()
                      if name.startswith(":" + word[1:])]
    if _inside_string_or_comment(before):
        return "", []
    m = _HELP.search(before)
    if m:
        word = m.group(1) or ""
        return word, _matching(word, _procs(interp) + _commands(interp))
    m = _WORD.search(before)
    word = m.group(0) if m else ""
    return word, _matching(word, _names(interp) + _commands(interp) + _words())


def _matching(prefix: str, items: list[tuple[str, str]]) -> list[tuple[str, str]]:
    seen: set[str] = set()
    out = []
    for name, what in items:
        if name.startswith(prefix) and name not in seen:
            seen.add(name)
            out.append((name, what))
    return out


def _names(interp: Interpreter) -> list[tuple[str, str]]:
    items = sorted((v.name, v.type) for v in interp.visible_names().values() if v.name != "#")
    ring = interp.ring
    if ring is not None:
        where = f" of {ring.name}" if ring.name else ""
        items += [(n, f"ring variable{where}") for n in ring.names]
        items += [(n, "parameter") for n in ring.params]
    return items


def _procs(interp: Interpreter) -> list[tuple[str, str]]:
    return sorted((v.name, "proc") for v in interp.visible_names().values() if v.type == "proc")


def _commands(interp: Interpreter) -> list[tuple[str, str]]:
    out = []
    for name, cmd in sorted(interp.registry.COMMANDS.items(), key=lambda kv: kv[0].lower()):
        if not cmd.lib or cmd.lib in interp.loaded_libs:
            out.append((name, "command"))
        else:
            out.append((name, f'LIB "{cmd.lib}";'))
    return out


def _words() -> list[tuple[str, str]]:
    return ([(w, "keyword") for w in sorted(KEYWORDS)] + [(t, "type") for t in sorted(type_words())]
            + [(s, "system variable") for s in SYSTEM_VARIABLES])


def _libraries(interp: Interpreter) -> list[str]:
    names = set(interp.registry.LIBRARIES) | {p.name for d in interp.registry.LIBRARY_DIRS for p in d.glob("*.lib")}
    return sorted(names)


def _inside_string_or_comment(text: str) -> bool:
    """Whether the end of ``text`` is inside a string or a comment."""
    last = None
    for last in scan(text):
        pass
    if last is None or last[2] < len(text):
        return False
    kind, start, end = last
    if kind == "comment":
        return text.startswith("//", start) or not text.endswith("*/", start + 2)
    return kind == "string" and (end - start < 2 or not text.endswith('"'))


class MechCompleter(Completer):
    """prompt_toolkit completer over the interpreter ``get_interp()`` returns (it changes on ``:reset``)."""

    def __init__(self, get_interp: Callable[[], Interpreter]) -> None:
        self.get_interp = get_interp

    def get_completions(self, document: Document, complete_event: CompleteEvent) -> Iterator[Completion]:
        prefix, items = candidates(self.get_interp(), document.text_before_cursor)
        for text, what in items:
            yield Completion(text, start_position=-len(prefix), display_meta=what)
