"""Macaulay2's sources for the conformance runner (m2_examples.py): reading its strings and
documentation formats, the cases (doc nodes with examples, TEST blocks) of the packages and pages in
scope, and the selection rule (``out_of_scope``)."""
from __future__ import annotations

import re
import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import Iterator, Optional

PACKAGES = ("PrimaryDecomposition", "MinimalPrimes", "Saturation", "Elimination", "LocalRings")
#: packages Macaulay2 1.21 loads at start-up (the others are loaded before a case runs)
PRELOADED = {"PrimaryDecomposition", "MinimalPrimes", "Saturation", "Elimination"}
#: Macaulay2Doc's pages on ideals, Gröbner bases, monomial orders, rings, maps, matrices, lists
DOC_PAGES = ("ov_ideals", "doc_ideals", "groebner", "monomorderings", "doc_rings", "ov_ringmaps",
             "doc_ringmaps", "ov_matrices", "doc_lists")
#: Macaulay2Doc's function pages (functions/NAME-doc.m2) on the same subjects
DOC_FUNCTIONS = (
    "append", "apply", "coefficientRing", "codim", "degree", "det", "diff", "dim", "drop", "entries",
    "factor", "first", "flatten", "gb", "generators", "ideal", "intersect", "jacobian", "join", "last",
    "leadCoefficient", "leadMonomial", "length", "map", "matrix", "max", "member", "min", "mingens",
    "minors", "monomialIdeal", "numgens", "position", "positions", "prepend", "reverse", "ring", "select",
    "sort", "submatrix", "subsets", "substitute", "sum", "take", "terms", "toList", "transpose", "trim",
    "unique", "use", "vars")

#: constructs outside mech's scope: reason -> names (identifiers of the code, outside strings and comments)
OUT_OF_SCOPE = {
    "modules, resolutions, chain complexes": {
        "freeResolution", "chainComplex", "complex", "Ext", "Tor", "Hom", "module", "subquotient",
        "comodule", "koszul", "homology", "HH", "cohomology", "directSum", "tensor", "Module", "ChainComplex",
        "isModule", "inducedMap", "pushForward", "basis", "hilbertPolynomial", "hilbertSeries", "poincare",
        "regularity"},
    "sheaves and varieties": {"sheaf", "OO", "Proj", "Spec", "variety", "cotangentSheaf", "tangentSheaf",
                              "CoherentSheaf", "ProjectiveVariety"},
    "non-commutative rings": {"WeylAlgebra", "SkewCommutative", "isSkewCommutative", "AssociativeAlgebras"},
    "real and complex numbers": {"RR", "CC", "numeric", "realPart", "imaginaryPart", "ii", "sqrt", "exp",
                                 "log", "sin", "cos", "pi", "RRi", "toRR", "toCC"},
    "random values": {"random", "setRandomSeed", "randomMutableMatrix", "genericMatrix0"},
    "timings": {"timing", "elapsedTiming", "benchmark", "cpuTime", "currentTime"},
    "hash tables and internals": {"new", "peek", "hashTable", "HashTable", "MutableHashTable",
                                  "MutableList", "mutableMatrix", "mutableIdentity", "keys", "values",
                                  "pairs", "cache", "frames", "gbTrace", "gbSnapshot", "engineDebugLevel",
                                  "debugLevel", "locate", "globalAssign", "installMethod", "method", "hooks", "peek'"},
    "system, files and help": {"help", "viewHelp", "examples", "methods", "code", "edit", "installPackage",
                               "check", "run", "get", "openOut", "openIn", "currentFileDirectory", "printWidth",
                               "showTex", "tex", "html", "net", "toExternalString", "schedule",
                               "Thread", "collectGarbage", "exit", "restart"},
    "Galois fields": {"GF", "ConwayPolynomials"},
}
IN_SCOPE_PACKAGES = set(PACKAGES)


@dataclass
class Case:
    """One doc node's examples or one TEST block."""
    where: str          # file:line in the sources (unique)
    origin: str         # the package or Macaulay2Doc page
    kind: str           # "example" or "test"
    name: str           # the doc node's key, or "TEST"
    code: str
    package: str = ""   # the package Macaulay2 loads first ("" if preloaded)
    excluded: str = ""  # the reason it is not run


# ---------------------------------------------------------------- reading Macaulay2 source
def skip(text: str, i: int) -> int:
    """The index after a comment or string starting at ``i`` (``i`` itself when none starts there)."""
    if text.startswith("--", i):
        j = text.find("\n", i)
        return len(text) if j < 0 else j
    if text.startswith("-*", i):
        j = text.find("*-", i + 2)
        return len(text) if j < 0 else j + 2
    if text.startswith("///", i):
        return read_string(text, i)[1]
    if text.startswith('"', i):
        return read_string(text, i)[1]
    return i


def read_string(text: str, i: int) -> tuple[str, int]:
    """The string literal at ``i`` (``"..."`` with escapes or ``///...///``) and the index after it."""
    out = []
    if text.startswith("///", i):
        j = i + 3
        while j < len(text):
            if text.startswith("////", j):
                out.append("/")
                j += 1
            elif text.startswith("///", j):
                return "".join(out), j + 3
            else:
                out.append(text[j])
                j += 1
        return "".join(out), len(text)
    j = i + 1
    escapes = {"n": "\n", "t": "\t", '"': '"', "\\": "\\", "r": "\r"}
    while j < len(text) and text[j] != '"':
        if text[j] == "\\" and j + 1 < len(text):
            out.append(escapes.get(text[j + 1], text[j + 1]))
            j += 2
        else:
            out.append(text[j])
            j += 1
    return "".join(out), j + 1


def tokens(text: str) -> Iterator[tuple[int, str]]:
    """(index, token) of the code outside comments and strings: words, numbers, punctuation; a string
    literal is the token ``"`` (its index is where it starts)."""
    i = 0
    while i < len(text):
        j = skip(text, i)
        if j != i:
            if text[i] in '"/':
                yield i, '"'
            i = j
            continue
        ch = text[i]
        if ch.isspace():
            i += 1
            continue
        m = re.compile(r"[A-Za-z][A-Za-z0-9']*|[0-9]+(?:\.[0-9]+)?|\S").match(text, i)
        yield i, m.group()
        i = m.end()


def closing(text: str, i: int) -> int:
    """The index after the bracket closing the one at ``i``."""
    depth = 0
    for j, tok in tokens_from(text, i):
        if tok in "([{":
            depth += 1
        elif tok in ")]}":
            depth -= 1
            if depth == 0:
                return j + 1
    return len(text)


def tokens_from(text: str, i: int) -> Iterator[tuple[int, str]]:
    for j, tok in tokens(text[i:]):
        yield i + j, tok


def dedent(lines: list[str]) -> str:
    """The lines without their common indentation (tabs count as 8 spaces), trailing blank lines dropped."""
    lines = [ln.expandtabs(8).rstrip() for ln in lines]
    while lines and not lines[-1].strip():
        lines.pop()
    while lines and not lines[0].strip():
        lines.pop(0)
    indent = min((len(ln) - len(ln.lstrip()) for ln in lines if ln.strip()), default=0)
    return "\n".join(ln[indent:] for ln in lines)


def line_of(text: str, i: int) -> int:
    return text.count("\n", 0, i) + 1


# ---------------------------------------------------------------- extracting the cases
def old_style_examples(body: str) -> list[str]:
    """The inputs of the ``EXAMPLE`` items of a ``document {...}`` body: a string, a list of
    strings or ``lines ///...///``."""
    out: list[str] = []
    toks = list(tokens(body))
    for k, (i, tok) in enumerate(toks):
        if tok != "EXAMPLE" or k + 1 == len(toks):
            continue
        j, nxt = toks[k + 1]
        if nxt == "lines" and k + 2 < len(toks):
            j = toks[k + 2][0]
        if nxt == "{":
            end = closing(body, j)
            items = [read_string(body, p)[0] for p, t in tokens_from(body[:end], j) if t == '"']
        elif body[j] in '"/':
            items = [read_string(body, j)[0]]
        else:
            continue
        out.extend(dedent(s.split("\n")) for s in items)
    return out


def document_key(body: str) -> str:
    """The first key of ``Key => ...`` in a ``document {...}`` body."""
    m = re.search(r"\bKey\s*=>\s*", body)
    if not m:
        return "?"
    i = m.end()
    if body[i] == "{":
        i += 1
        while body[i].isspace():
            i += 1
    if body[i] in '"/':
        return read_string(body, i)[0]
    depth, j = 0, i
    for j, tok in tokens_from(body, i):
        if tok in "([{":
            depth += 1
        elif tok in ")]}":
            if depth == 0:
                break
            depth -= 1
        elif tok == "," and depth == 0:
            break
    return " ".join(body[i:j].split())


def simpledoc_nodes(text: str) -> list[tuple[str, list[str], int]]:
    """(key, example inputs, line of the node counted from 0) of the nodes of a SimpleDoc string
    (``doc ///...///``); the examples are the blocks under ``Example``."""
    lines = [ln.expandtabs(8) for ln in text.split("\n")]

    def indent(k: int) -> int:
        return len(lines[k]) - len(lines[k].lstrip())

    nodes: list[tuple[str, list[str], int]] = []
    key, examples, start = "", [], 0
    k = 0
    while k < len(lines):
        word = lines[k].strip()
        end = k + 1
        while end < len(lines) and (not lines[end].strip() or indent(end) > indent(k)):
            end += 1
        if word == "Node":
            nodes.append((key, examples, start))
            key, examples, start = "", [], k
        elif word == "Key" and not key:
            key = next((b.strip() for b in lines[k + 1:end] if b.strip()), "")
        elif word == "Example":
            examples.append(dedent(lines[k + 1:end]))
        else:
            k += 1
            continue
        k = end if word != "Node" else k + 1
    nodes.append((key, examples, start))
    return [(key.strip('"'), [e for e in ex if e], line) for key, ex, line in nodes if any(ex)]


def cases_in(path: Path, rel: str, origin: str, package: str) -> list[Case]:
    """The doc nodes with examples and the TEST blocks of one source file."""
    text = path.read_text(encoding="utf-8", errors="replace")
    out: list[Case] = []
    toks = list(tokens(text))
    for k, (i, tok) in enumerate(toks):
        if tok == "end" and (i == 0 or text[i - 1] == "\n"):  # Macaulay2 reads no further
            break
        if k + 1 == len(toks) or (k and toks[k - 1][1] in (".", "#", "=", ":")):
            continue
        j, nxt = toks[k + 1]
        where = f"{rel}:{line_of(text, i)}"
        if tok == "document" and nxt == "{":
            body = text[j:closing(text, j)]
            inputs = old_style_examples(body)
            if inputs:
                out.append(Case(where, origin, "example", document_key(body), "\n".join(inputs), package))
        elif tok in ("doc", "document") and text[j] in '"/':
            for key, inputs, line in simpledoc_nodes(read_string(text, j)[0]):
                out.append(Case(f"{rel}:{line_of(text, j) + line}", origin, "example", key, "\n".join(inputs),
                                package))
        elif tok in ("TEST", "SIMPLETEST", "BENCHMARK") and text[j] in '"/(g':
            code = test_code(text, j, path.parent)
            if code is None:
                continue
            case = Case(where, origin, "test", "TEST", dedent(code.split("\n")), package)
            if tok == "BENCHMARK":
                case.excluded = "a MinimalPrimes BENCHMARK test (slow by design)"
            out.append(case)
    return out


def test_code(text: str, j: int, folder: Path) -> Optional[str]:
    """The code of ``TEST ///...///``, ``TEST "..."`` or ``TEST get(currentFileDirectory | "f.m2")``."""
    if text[j] in '"/':
        return read_string(text, j)[0]
    m = re.compile(r'get\s*\(\s*currentFileDirectory\s*\|\s*"([^"]+)"\s*\)').match(text, j)
    if m and (folder / m.group(1)).is_file():
        return (folder / m.group(1)).read_text(encoding="utf-8", errors="replace")
    return None


def loaded_files(main: Path) -> list[Path]:
    """A package's file and the files it loads (``load "./Pkg/file.m2"``), recursively, in order."""
    seen: list[Path] = []

    def visit(p: Path) -> None:
        if p in seen or not p.is_file():
            return
        seen.append(p)
        text = p.read_text(encoding="utf-8", errors="replace")
        for m in re.finditer(r'^\s*load\s*\(?\s*"([^"]+)"', text, re.M):
            visit((main.parent / m.group(1)).resolve() if m.group(1).startswith("./" + main.stem)
                  else (p.parent / m.group(1)).resolve())
    visit(main.resolve())
    return seen


def extract(src: Path) -> list[Case]:
    """Every case of the selection (see the module's docstring), exclusions marked."""
    pkgs = src / "M2" / "Macaulay2" / "packages"
    if not pkgs.is_dir():
        raise SystemExit(f"m2_examples: no M2/Macaulay2/packages under {src}")
    out: list[Case] = []
    for pkg in PACKAGES:
        for path in loaded_files(pkgs / f"{pkg}.m2"):
            rel = str(path.relative_to(pkgs.resolve()))
            out.extend(cases_in(path, rel, pkg, "" if pkg in PRELOADED else pkg))
    doc = pkgs / "Macaulay2Doc"
    files = [doc / f"{p}.m2" for p in DOC_PAGES] + [doc / "functions" / f"{f}-doc.m2" for f in DOC_FUNCTIONS]
    for path in files:
        if path.is_file():
            rel = str(path.relative_to(pkgs))
            page = "functions" if path.parent.name == "functions" else path.stem
            out.extend(cases_in(path, rel, f"Macaulay2Doc/{page}", ""))
    for case in out:
        case.excluded = case.excluded or out_of_scope(case.code)
    return out


def out_of_scope(code: str) -> str:
    """Why the code is outside mech's scope ("" when it is inside): the first construct of
    ``OUT_OF_SCOPE`` it names, another package it loads, a float."""
    for pos, tok in tokens(code):
        for reason, names in OUT_OF_SCOPE.items():
            if tok in names:
                return f"{reason}: {tok}"
        if tok in ("needsPackage", "loadPackage", "needs", "load"):
            m = re.compile(r'\s*\(?\s*"([^"]+)"').match(code, pos + len(tok))
            if m is None or m.group(1) not in IN_SCOPE_PACKAGES:
                return f"other packages: {tok} {m.group(1) if m else ''}".rstrip()
        if "." in tok and tok[0].isdigit():
            return f"real and complex numbers: {tok}"
    return ""


def source_version(src: Path) -> str:
    """The sources' Macaulay2 version and commit (git, or the SOURCE note of an extracted copy)."""
    version = (src / "M2" / "VERSION").read_text().strip() if (src / "M2" / "VERSION").is_file() else "?"
    git = subprocess.run(["git", "-C", str(src), "rev-parse", "HEAD"], capture_output=True, text=True)
    if git.returncode == 0:
        return f"{version}, commit {git.stdout.strip()}"
    note = src / "SOURCE"
    return f"{version} ({note.read_text().strip()})" if note.is_file() else version
