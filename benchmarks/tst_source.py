"""Cases of the Singular conformance run, read from a checkout of Singular's sources.

A case is a script: a test file ``Tst/<folder>/<name>.tst`` with the ``tst.lib`` harness stripped, or
the ``example`` section of a procedure of an in-scope library ``Singular/LIB/<lib>``.  The selection
rule (:func:`scope_reason`) scans the script's code, strings and comments masked, for constructs outside
mech's scope; the earliest such construct in the text is the case's exclusion reason.
"""
from __future__ import annotations

import binascii
import gzip
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterator, Optional

#: The test folders run, in this order.
FOLDERS = ("Short", "Buch", "Old", "Manual")
#: Libraries in mech's scope: their examples are cases, and scripts may load them.  The libraries of
#: commutative algebra over fields in the issue's scope (standard bases, elimination, decomposition,
#: singularity invariants, matrices, maps and subalgebras), ring manipulation, and inout.lib (printing, part
#: of the language); not solve.lib (floating-point roots), rootsur.lib (real root counting), normal.lib,
#: homolog.lib or mprimdec.lib (modules), nor any noncommutative, numerical or combinatorial library.
SCOPE_LIBS = ("primdec.lib", "sing.lib", "elim.lib", "polylib.lib", "matrix.lib", "general.lib", "ring.lib",
              "standard.lib", "algebra.lib", "inout.lib")
#: ``LIB "poly.lib"`` is Singular's old name of polylib.lib.
_LIB_ALIASES = {"poly.lib": "polylib.lib"}


@dataclass
class Case:
    """One script to run in both systems."""

    name: str                      # "Short/bug_1.tst", "LIB/primdec.lib:primdecGTZ"
    script: str                    # the text both systems run (harness stripped)
    reference: Optional[str] = None  # Singular's recorded output (.res.gz.uu), when the folder has one
    excluded: Optional[str] = None   # why the case is out of scope (None: in scope)
    extra: dict = field(default_factory=dict)

    @property
    def folder(self) -> str:
        return self.name.split("/", 1)[0]


# ---------------------------------------------------------------- lexing
def mask(text: str) -> str:
    """``text`` with the contents of strings and comments blanked (same length, newlines kept), so that
    regular expressions see only code; string quotes stay."""
    def blank(m: re.Match) -> str:
        t = m.group(0)
        if t.startswith('"'):
            closed = len(t) > 1 and t.endswith('"') and not t.endswith('\\"')
            return '"' + _NOT_NEWLINE.sub(" ", t[1:-1] if closed else t[1:]) + ('"' if closed else "")
        return _NOT_NEWLINE.sub(" ", t)
    return _LEXEMES.sub(blank, text)


_NOT_NEWLINE = re.compile(r"[^\n]")
_LEXEMES = re.compile(r'"(?:[^"\\]|\\.)*"?|//[^\n]*|/\*.*?(?:\*/|\Z)', re.S)


def _blank(out: list[str], lo: int, hi: int) -> None:
    for k in range(lo, hi):
        if out[k] != "\n":
            out[k] = " "


def _matching(masked: str, i: int, open_: str = "(", close: str = ")") -> int:
    """The index after the bracket closing the one at ``i`` (the end of the text if unbalanced)."""
    depth = 0
    for k in range(i, len(masked)):
        if masked[k] == open_:
            depth += 1
        elif masked[k] == close:
            depth -= 1
            if depth == 0:
                return k + 1
    return len(masked)


def _statement_start(masked: str, i: int) -> bool:
    """Whether position ``i`` begins a statement (after ``;``, ``{``, ``}``, ``else`` or the start)."""
    k = i - 1
    while k >= 0 and masked[k].isspace():
        k -= 1
    if k < 0 or masked[k] in ";{}":
        return True
    return masked[max(0, k - 3):k + 1] == "else" and (k < 4 or not (masked[k - 4].isalnum() or masked[k - 4] == "_"))


# ---------------------------------------------------------------- the tst.lib harness
_HARNESS_CALLS = ("tst_init", "tst_status", "tst_ignore")


def strip_harness(text: str) -> str:
    """The script without the ``tst.lib`` harness: ``LIB "tst.lib";`` and the calls of tst_init,
    tst_status and tst_ignore (whose output is system-dependent) are blanked, the text after a ``$``
    (Singular's end of input) dropped.  Line numbers stay those of the file."""
    masked = mask(text)
    end = masked.find("$")
    if end >= 0:
        text, masked = text[:end], masked[:end]
    spans = [m.span() for m in re.finditer(r'LIB\s*"tst\.lib"\s*;?', text) if masked[m.start()] == "L"]
    for m in re.finditer(r"\b(%s)\b\s*" % "|".join(_HARNESS_CALLS), masked):
        j = m.end()
        if j < len(masked) and masked[j] == "(":
            j = _matching(masked, j)
        k = j
        while k < len(masked) and masked[k] in " \t":
            k += 1
        spans.append((m.start(), k + 1 if k < len(masked) and masked[k] == ";" else j))
    out = list(text)
    for lo, hi in spans:
        _blank(out, lo, hi)
    return "".join(out)


# ---------------------------------------------------------------- the selection rule
_WORDS = {
    "system(...) call": "system",
    "timing, memory or random values": "timer rtimer memory datetime random sparseid sparsemat sparsepoly "
                                       "sparsetriag sparseHomogIdeal randomid randommat randomLast "
                                       "randomBinomial genericid kmemory",
    "noncommutative ring": "nc_algebra ncalgebra plural opposite oppose envelope twostd bracket Weyl makeWeyl "
                           "freeAlgebra makeLetterplaceRing letplaceGBasis superCommutative exteriorAlgebra "
                           "rightstd isCommutative ncdetection exteriorBasis",
    "resolutions and homological algebra": "resolution smatrix res mres sres lres nres hres fres minres betti "
                                           "prune mpresmat kres Ext Ext_R Tor",
    "links and files": "link open close read write dump getdump status fprintf waitall waitfirst monitor",
    "newstruct, bigintmat, polyhedra and other special types": "newstruct bigintmat cone fan polytope polymake "
                                                               "pyobject reference shared cring blackbox package",
    "interactive help (help, example, browser)": "help example browser pause",
    "numerical solving": "laguerre uressolve solve",
}
_WORD_REASON = {w: reason for reason, words in _WORDS.items() for w in words.split()}
_PREFIX_REASON = {"tst_": "tst.lib helper", "nc_": "noncommutative ring",
                  "gfan": "newstruct, bigintmat, polyhedra and other special types"}
_PREFIXES = tuple(_PREFIX_REASON)
_PATTERNS = [("protocol output (option(prot))", re.compile(r"\boption\s*\(\s*prot\b")),
             ("packages (::)", re.compile(r"\w::")),
             ("links and files: <", re.compile(r"(?:\A|[;{}])\s*<\s*\""))]
_IDENT = re.compile(r"(?<![\w@])[A-Za-z_]\w*")


def scope_reason(script: str) -> Optional[str]:
    """Why ``script`` is outside mech's scope (the earliest construct), or None when it is in scope."""
    masked = mask(script)
    found: list[tuple[int, str]] = []
    for m in _IDENT.finditer(masked):
        word = m.group(0)
        reason = _WORD_REASON.get(word)
        if reason is None and word.startswith(_PREFIXES):
            reason = next(r for p, r in _PREFIX_REASON.items() if word.startswith(p))
        if reason:
            found.append((m.start(), f"{reason}: {word}"))
            break
    for reason, rx in _PATTERNS:
        m = rx.search(masked)
        if m:
            found.append((m.start(), reason))
    for m in re.finditer(r'LIB\s*\(?\s*"([^"]*)"', script):
        if masked[m.start()] != "L":
            continue
        lib = _LIB_ALIASES.get(Path(m.group(1)).name, Path(m.group(1)).name)
        if lib not in SCOPE_LIBS and lib != "tst.lib":
            found.append((m.start(), f"library {lib}"))
    for pos, why in _ring_decls(masked):
        found.append((pos, why))
    return min(found)[1] if found else None


def _ring_decls(masked: str) -> Iterator[tuple[int, str]]:
    """Ring declarations over coefficient domains outside mech's scope."""
    for m in re.finditer(r"\bring\s+\w+\s*=\s*", masked):
        end = masked.find(";", m.end())
        body = masked[m.end():end if end >= 0 else len(masked)]
        char = _top_level_split(body)[0].strip()
        inner = char[1:-1] if char.startswith("(") and char.endswith(")") else char
        first = _top_level_split(inner)[0].strip().replace(" ", "")
        why = _coefficients(first, len(_top_level_split(inner)) > 1)
        if not why and re.fullmatch(r"[A-Za-z_]\w*", first) and \
                re.search(rf"\bq?ring\s+{first}\b", masked[:m.start()]):
            why = "a ring as the coefficient domain (not a field)"
        if why:
            yield m.start(), why


def _coefficients(first: str, has_params: bool) -> Optional[str]:
    low = re.sub(r"\[.*\]$", "", first.lower())  # the new syntax QQ[x,y]
    low = low[1:-1] if low.startswith("(") and low.endswith(")") else low
    if low.startswith(("real", "complex")):
        return "real or complex coefficients"
    if low.startswith("integer") or low == "zz":
        return "integer coefficients"
    m = re.fullmatch(r"(?:zz/)?(\d+)(\^\d+)?", low)
    if m:
        n = int(m.group(1))
        if m.group(2) or (n > 1 and not _is_prime(n) and (has_params or low.startswith("zz/"))):
            return "Galois fields and Z/n with n not prime"
    elif low.startswith("zz/"):
        return "Galois fields and Z/n with n not prime"
    return None


def _top_level_split(text: str) -> list[str]:
    parts, depth, start = [], 0, 0
    for k, c in enumerate(text):
        depth += c in "([" and 1 or c in ")]" and -1 or 0
        if c == "," and depth == 0:
            parts.append(text[start:k])
            start = k + 1
    return parts + [text[start:]]


def _is_prime(n: int) -> bool:
    return n > 1 and all(n % d for d in range(2, int(n ** 0.5) + 1))


# ---------------------------------------------------------------- library examples
def examples(lib_text: str) -> Iterator[tuple[str, str]]:
    """(procedure, example code) for each non-static procedure of a library with an example section;
    the code without the ``"EXAMPLE:";`` banner and ``echo = 2;``."""
    masked = mask(lib_text)
    proc: Optional[str] = None
    for m in re.finditer(r"^[ \t]*(?:(static)\s+)?proc\s+(\w+)|^[ \t]*example\s*(?=\{)", masked, re.M):
        if m.group(2):
            proc = None if m.group(1) else m.group(2)
            continue
        if proc is None:
            continue
        brace = masked.index("{", m.start())
        body = lib_text[brace + 1:_matching(masked, brace, "{", "}") - 1]
        body = re.sub(r'^\s*"EXAMPLE:"\s*;', "", body)
        body = re.sub(r"\becho\s*=\s*\d+\s*;", "", body)
        yield proc, body.strip("\n") + "\n"
        proc = None


# ---------------------------------------------------------------- reading the checkout
def read_reference(path: Path) -> Optional[str]:
    """The text of a uuencoded gzipped result file (``name.res.gz.uu``), None when absent."""
    if not path.exists():
        return None
    data, inside = bytearray(), False
    for line in path.read_text(errors="replace").splitlines():
        if line.startswith("begin "):
            inside = True
        elif line.strip() == "end":
            break
        elif inside and line:
            try:
                data += binascii.a2b_uu(line)
            except binascii.Error:
                nbytes = (((ord(line[0]) - 32) & 63) * 4 + 5) // 3  # padding some encoders strip
                data += binascii.a2b_uu(line[:nbytes])
    try:
        return gzip.decompress(bytes(data)).decode("utf-8", "replace")
    except (OSError, EOFError):
        return None


def collect(src: Path) -> list[Case]:
    """Every case of the checkout at ``src``, each with its exclusion reason (None: in scope)."""
    cases: list[Case] = []
    for folder in FOLDERS:
        for path in sorted((src / "Tst" / folder).glob("*.tst")):
            script = strip_harness(path.read_text(errors="replace"))
            reference = read_reference(path.with_suffix(".res.gz.uu"))
            cases.append(Case(f"{folder}/{path.name}", script, reference, scope_reason(script)))
    for lib in SCOPE_LIBS:
        path = src / "Singular" / "LIB" / lib
        if not path.exists():
            continue
        for proc, code in examples(path.read_text(errors="replace")):
            script = f'LIB "{lib}";\n{code}'
            cases.append(Case(f"LIB/{lib}:{proc}", script, None, scope_reason(script)))
    return cases


# ---------------------------------------------------------------- ring markers (Singular's run only)
MARKER = "@@RING@@"
_MARK = f'"{MARKER}"+string(basering)+"@@"+string(minpoly)+"@@"+string(ideal(basering));'


def instrument(script: str) -> str:
    """The script with a statement after each ``ring``, ``qring``, ``setring`` and ``minpoly =``
    statement printing a marker line: the ring declaration, minimal polynomial and quotient ideal of
    the basering.  Only Singular runs it: the markers tell in which ring each printed ideal lives."""
    masked = mask(script)
    inserts = []
    for m in re.finditer(r"\b(?:ring|qring|setring|minpoly)\b", masked):
        if not _statement_start(masked, m.start()):
            continue
        if m.group(0) == "minpoly" and not re.match(r"minpoly\s*=", masked[m.start():]):
            continue
        end = masked.find(";", m.end())
        if end >= 0:
            inserts.append(end + 1)
    out, last = [], 0
    for k in inserts:
        out += [script[last:k], _MARK]
        last = k
    return "".join(out) + script[last:]
