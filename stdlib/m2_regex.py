"""Regular expressions in the Macaulay2 dialect: Macaulay2's (Boost's Perl syntax) read as Python's,
for ``select(re, s)`` and ``select(re, t, s)`` (:mod:`mech.stdlib.m2_lists`)."""
from __future__ import annotations

import re
from typing import Any

from ..dsl.errors import MechTypeError
from ..dsl.values import List


#: POSIX classes of Macaulay2's (Boost's Perl) regular expressions, as Python writes them
_CLASSES = {"alpha": "a-zA-Z", "digit": "0-9", "alnum": "a-zA-Z0-9", "upper": "A-Z", "lower": "a-z",
            "space": r"\s", "punct": r"!-/:-@\[-`{-~", "xdigit": "0-9A-Fa-f", "word": r"\w"}


def regex(pattern: str) -> re.Pattern[str]:
    """Macaulay2's regular expression as Python's: POSIX classes ``[[:alpha:]]``, ``.`` matching no
    line break and ``^``/``$`` at every line (\\n, \\r\\n or \\r ends one), as Boost's Perl syntax."""
    out, i, depth = [], 0, 0
    while i < len(pattern):
        c = pattern[i]
        if c == "\\":
            out.append(pattern[i:i + 2])
            i += 2
            continue
        m = re.match(r"\[:(\w+):\]", pattern[i:]) if depth else None
        if m and m.group(1) in _CLASSES:
            out.append(_CLASSES[m.group(1)])
            i += m.end()
            continue
        if c == "[" and not depth:
            depth = 1
            out.append(c + ("^" if pattern[i + 1:i + 2] == "^" else ""))
            i += 1 + (pattern[i + 1:i + 2] == "^")
            if pattern[i:i + 1] == "]":  # a leading ] is a member
                out.append(r"\]")
                i += 1
            continue
        if c == "]" and depth:
            depth = 0
        elif not depth and c == ".":
            c = r"[^\r\n]"
        elif not depth and c == "$":
            c = r"(?=\r\n|\r|\n|\Z)"
        elif not depth and c == "^":
            c = r"(?:(?<=\n)|(?<=\r)(?!\n)|\A)"
        out.append(c)
        i += 1
    try:
        return re.compile("".join(out))
    except re.error as e:
        raise MechTypeError(f"the regular expression {pattern!r} is not valid: {e}") from None


def _format(template: str, m: re.Match[str]) -> str:
    """Boost's format string: ``$n`` (``$&`` the whole match), ``\\L``/``\\U`` lower/upper case of
    what follows (``\\E`` ends it), other escapes their character."""
    out, case, i = [], None, 0
    while i < len(template):
        c = template[i]
        piece = c
        if c == "$" and i + 1 < len(template) and (template[i + 1].isdigit() or template[i + 1] == "&"):
            j = i + 1
            while j < len(template) and template[j].isdigit():
                j += 1
            j = max(j, i + 2)
            key = template[i + 1:j]
            piece = m.group(0 if key == "&" else int(key)) or ""
            i = j
        elif c == "\\" and i + 1 < len(template):
            e = template[i + 1]
            i += 2
            if e in "LUE":
                case = None if e == "E" else e
                continue
            piece = {"n": "\n", "t": "\t"}.get(e, e)
        else:
            i += 1
        out.append(piece.lower() if case == "L" else piece.upper() if case == "U" else piece)
    return "".join(out)


def regex_select(pattern: str, text: str, template: Any = None) -> List:
    """select(re, s): the matches of ``re`` in ``s``; select(re, t, s): each match formatted by ``t``."""
    if not isinstance(text, str) or (template is not None and not isinstance(template, str)):
        raise MechTypeError("select(re, s) and select(re, t, s) take strings")
    return List([m.group(0) if template is None else _format(template, m) for m in regex(pattern).finditer(text)])
