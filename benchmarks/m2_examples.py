"""Macaulay2 conformance: the EXAMPLE and TEST blocks of Macaulay2's own sources, run in Macaulay2
and in mech's Macaulay2 dialect, their values compared.

    python benchmarks/m2_examples.py --src /work/m2-src [--only PATTERN] [--timeout 60] [--jobs 2] [--write]

``--src`` is a checkout of github.com/Macaulay2/M2 (or the part of it holding
``M2/Macaulay2/packages``), best at the tag of the installed Macaulay2 (``release-1.21``).
``--write`` rewrites benchmarks/M2_EXAMPLES.md; ``--json FILE`` saves every case's result;
``--list`` lists the cases and their exclusions.

Selection (m2_sources.py).  A case is a doc node with examples (all of them, in turn, as Macaulay2's
documentation runs them) or a TEST block, in the files the packages PrimaryDecomposition,
MinimalPrimes, Saturation, Elimination and LocalRings load and in Macaulay2Doc's pages on ideals,
Gröbner bases, monomial orders, rings, ring maps, matrices and lists and its pages of the functions
on them.  A case is excluded, with its reason, when its code names a construct outside mech's scope
(``OUT_OF_SCOPE``: module constructions beyond images, kernels and cokernels of matrices, chain
complexes beyond free resolutions, sheaves, non-commutative rings, real and complex numbers,
random values, hash tables, other packages, system and help functions...), a package internal
(a name of the package's private dictionary), when one of its top-level values is of a class of
``OUT_CLASSES`` (chain complexes, whose ``toString`` shows nothing to compare...), when Macaulay2
1.21 itself fails or times out on it, or when it is a MinimalPrimes ``BENCHMARK`` test.

Running.  Both systems get the same code.  mech reads it from standard input (``mech --dialect m2 -``,
as ``M2 < file``), printing ``oN = value`` (Macaulay2's ``toString``) for the N-th statement not
ending in ``;``.  Macaulay2
runs it in its read-eval-print loop (standard input; it numbers statements as mech does) in an
output mode (``M2_MODE``) printing ``toString`` of the same statements, and judges mech's text:
when it differs from its own, Macaulay2 reads mech's text back in the value's ring and compares the
values: ideals as ideals, lists of ideals as sets (or as primary decompositions: as many primary
ideals with the same radicals and intersection), modules as subquotients of R^n (the degrees
``toString`` does not show forgotten), other lists entry by entry, other values with ``==``; in a
case listing a hash table (calling ``set``, ``keys`` or ``values``: ``HASH_ORDER``) a list also
agrees with the same elements in another order (Macaulay2's order there is its hash order).  A
function (or an iterator) agrees with a function: Macaulay2 prints where its code is in its files.
``print`` prints ``toString`` in both.  A value depending on a choice that is not part of the
mathematical value (an embedded component) is judged by a check Macaulay2 runs on mech's own choice
(``NOT_UNIQUE``, with its reason); a TEST's assertion that such a value equals Macaulay2's own choice is
replaced, in both systems, by the statement printing it (``ASSERTED_CHOICES``).  A case *agrees* when every value and printed line agrees
and mech runs to the end without error (in a TEST: every ``assert`` holds).  Otherwise it
*differs* (a value Macaulay2 judges different, a value printed by one system only, a failed
assertion), is *unsupported* (mech's error names a function, symbol, option, operator or syntax it
lacks: which, ranked in the report), an *error* (another mech error), a *crash* (an internal error
or a traceback) or a *timeout*.
"""
from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path
from typing import Optional

from m2_sources import Case, extract, source_version, tokens

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
REPORT = HERE / "M2_EXAMPLES.md"
#: classes of values that put a case out of scope (Macaulay2 reports the class of every top-level value)
OUT_CLASSES = {"ChainComplex", "ChainComplexMap", "GradedModule", "GradedModuleMap", "CoherentSheaf",
               "ProjectiveVariety", "AffineVariety", "RealField", "ComplexField", "RR", "CC", "MutableHashTable",
               "HashTable", "CacheTable", "MutableMatrix", "GaloisField", "Time"}
#: a case calling one of these lists a hash table's elements in Macaulay2's hash order, which is not
#: part of the value: its lists are compared as sets (``toList set {3,1,2}``, ``keys``, ``values``)
HASH_ORDER = {"set", "keys", "values"}
AGREE = ("same", "equal", "equivalent", "as a set", "a function", "not unique")
#: values that depend on a choice Macaulay2 makes and that is not part of the mathematical value:
#: case -> (reason, statements, printed lines, check).  The statements' values and the first printed
#: lines are not compared as text; instead Macaulay2 runs ``check`` after the case (with mech's printed
#: lines in ``mechPrints`` and mech's values in ``mechOut``) and it emits whether mech's values are right
#: for mech's own choice, which must itself be valid
NOT_UNIQUE = {
    "PrimaryDecomposition/doc.m2:87": (
        "an embedded component is not unique: mech's components (its printed lines) are checked to form a "
        "primary decomposition of I equivalent to Macaulay2's (as many primary ideals, the same radicals and "
        "intersection) and its degrees to be those of its own components",
        {8}, 16,
        "mechC = apply(take(mechPrints, 16), s -> mechRead(I, s)); "
        "mechEmit {\"U\", toString(#mechC == 16 and mechDecomposition(C, mechC) and mechOut#?8 "
        "and mechOut#8 == toString apply(mechC, degree))};"),
    "LocalRings/tests.m2:459": (
        "minimal generators of an ideal of a local ring are not unique: mech's are checked to be as many as "
        "Macaulay2's and to generate the same ideal of the local ring",
        {7}, 0,
        "mechM = if mechOut#?7 then mechRead(J, mechOut#7); "
        "mechEmit {\"U\", toString(instance(mechM, Matrix) and numcols mechM == numcols mingens J "
        "and ideal mechM == J)};"),
    "LocalRings/tests.m2:398": (
        "minimal generators of an ideal of a local ring are not unique (the test asserts Macaulay2's own, "
        "a FIXME there): the statement prints them instead, and mech's are checked to be as many as "
        "Macaulay2's and to generate the same ideal of the local ring",
        {7}, 0,
        "mechM = if mechOut#?7 then mechRead(IP, mechOut#7); "
        "mechEmit {\"U\", toString(instance(mechM, Matrix) and numcols mechM == numcols mingens IP "
        "and ideal mechM == IP)};"),
    "LocalRings/legacy.m2:199": (
        "generators of a module that is not graded are not unique (Macaulay2's mingens are not even minimal "
        "there): mech's are checked to generate the same module",
        {3}, 0,
        "mechM = if mechOut#?3 then mechRead(R, mechOut#3); "
        "mechEmit {\"U\", toString(instance(mechM, Matrix) "
        "and image mechM == image matrix entries matrix {{a-1,a,b},{a-1,a,b}})};"),
    "LocalRings/legacy.m2:220": (
        "generators of a kernel (modulo, localModulo) are not unique: mech's are checked to generate the same "
        "module as Macaulay2's (localModulo: with as many columns)",
        {5, 6}, 0,
        "mechM = if mechOut#?5 then mechRead(R, mechOut#5); mechL = if mechOut#?6 then mechRead(R, mechOut#6); "
        "mechEmit {\"U\", toString(instance(mechM, Matrix) and image mechM == image matrix entries modulo(m, n) "
        "and instance(mechL, Matrix) and numcols mechL == numcols localModulo(m, n) "
        "and image mechL == image matrix entries localModulo(m, n))};"),
    "LocalRings/legacy.m2:323": (
        "localMingens is a solution of a division, one among many (here the same generator times another "
        "constant): mech's is checked to have as many columns as Macaulay2's and the same image",
        {4}, 0,
        "mechM = if mechOut#?4 then mechRead(R, mechOut#4); "
        "mechEmit {\"U\", toString(instance(mechM, Matrix) and numcols mechM == numcols G "
        "and image mechM == image matrix entries G)};"),
}
#: assertions of a TEST that compare a value of ``NOT_UNIQUE`` with Macaulay2's own choice: case ->
#: (assertion, the statement both systems run instead, printing the value the case's check judges)
ASSERTED_CHOICES = {
    "LocalRings/tests.m2:398": ("assert(mingens IP == matrix{{d*i-f*g}})", "mingens IP"),
}
STATUSES = ("agree", "differ", "unsupported", "error", "crash", "timeout")


@dataclass
class Result:
    case: Case
    status: str = ""            # one of STATUSES, or "excluded"
    reason: str = ""            # the blocking construct, or what differs
    detail: str = ""            # mech's message, Macaulay2's error
    values: int = 0             # statements whose values were compared
    agreed: int = 0             # ... and agreed (as text or as values)
    as_values: int = 0          # ... of which as values only (equal values, equivalent decompositions)
    seconds: dict = field(default_factory=dict)


# ---------------------------------------------------------------- running Macaulay2 and mech
M2 = shutil.which("M2") or "M2"
MECH = [sys.executable, "-m", "mech", "--dialect", "m2"]
SEP, FS = "\x1d", "\x1f"  # a record of Macaulay2's output mode is SEP fields joined by FS SEP

#: Macaulay2's output mode for the runner: for each top-level value its class, and for a printed
#: one its toString and the verdict on mech's text for the same statement (mechOut): "same" text,
#: "equal" values, "equivalent" primary decompositions (as many primary ideals, the same radicals
#: and intersection: embedded components are not unique), "as a set" (the same elements in another
#: order, in a case that lists a hash table: HASH_ORDER), "a function" (Macaulay2 shows a function's
#: place in its own sources, -*Function[file:line]*-, mech -*Function*-), "differ", "unreadable", "missing"
M2_MODE = r"""
mechEmit = L -> (<< "\035" << demark("\037", L) << "\035" << endl;);
mechRing = x -> (
    if instance(x, Ideal) or instance(x, MonomialIdeal) or instance(x, RingElement) or instance(x, Matrix)
       or instance(x, Module) then ring x
    else if instance(x, VisibleList) then (for y in x do (r := mechRing y; if r =!= null then return r); null)
    else null);
mechRead = (x, t) -> (
    R := mechRing x;
    if R === null then return value t;
    syms := apply(gens R, baseName);
    old := apply(syms, s -> value s);
    use R;
    y := try value t else mechUnreadable;
    scan(syms, old, (s, v) -> s <- v);
    y);
mechIdeal = z -> if instance(z, MonomialIdeal) then ideal z else z;
mechFlat = M -> (
    R := ring M; F := R^(rank ambient M);
    g := if M.?generators then map(F,, matrix entries M.generators);
    r := if M.?relations then map(F,, matrix entries M.relations);
    if g === null and r === null then F else if r === null then image g
    else if g === null then coker r else subquotient(g, r));
mechSame = (x, y) -> (
    x = mechIdeal x; y = mechIdeal y;
    if instance(x, Ideal) and instance(y, Ideal) then (
        if ring y =!= ring x then y = try sub(y, ring x) else return false;
        x == y)
    else if instance(x, Module) and instance(y, Module) then (
        ring x === ring y and rank ambient x == rank ambient y and mechFlat x == mechFlat y)
    else if instance(x, VisibleList) and instance(y, VisibleList) then (
        class x === class y and #x == #y and (
            if #x > 0 and all(x, i -> instance(mechIdeal i, Ideal)) then (
                rest := toList y;
                all(x, i -> (k := position(rest, j -> mechSame(i, j));
                             if k === null then false else (rest = drop(rest, {k, k}); true))))
            else all(#x, k -> mechSame(x#k, y#k))))
    else try (x == y) === true else false);
mechIdeals = L -> instance(L, List) and #L > 0 and all(L, i -> instance(mechIdeal i, Ideal));
mechDecomposition = (x, y) -> (
    mechIdeals x and mechIdeals y and #x == #y and all(y, i -> isPrimary mechIdeal i)
    and mechSame(apply(x, i -> radical mechIdeal i), apply(y, i -> radical mechIdeal i))
    and intersect apply(x, mechIdeal) == intersect apply(y, mechIdeal));
mechVerdict = x -> (
    if not mechOut#?lineNumber then return "missing";
    t := mechOut#lineNumber;
    if t == toString x then return "same";
    if match("^-\\*Function", toString x) and match("^-\\*Function\\*-$", t) then return "a function";
    y := try mechRead(x, t) else mechUnreadable;
    if y === mechUnreadable then "unreadable"
    else if (try mechSame(x, y) else false) then "equal"
    else if (try mechDecomposition(x, y) else false) then "equivalent"
    else if mechHashOrder and (try mechSet(x, y) else false) then "as a set" else "differ");
mechSet = (x, y) -> instance(x, List) and instance(y, List) and #x == #y and set x === set y;
Thing#{MechRunner,Print} = x -> mechEmit {"V", toString lineNumber, toString class x, toString x, mechVerdict x};
Thing#{MechRunner,NoPrint} = x -> mechEmit {"K", toString lineNumber, toString class x};
Nothing#{MechRunner,Print} = Nothing#{MechRunner,NoPrint} = identity;
Thing#{MechRunner,print} = x -> mechEmit {"P", toString x};
echoOff();
topLevelMode = MechRunner;
"""

#: Macaulay2's facts the classification needs: names of the packages' internals, classes of globals
M2_INFO = r"""
needsPackage "LocalRings";
scan({PrimaryDecomposition, MinimalPrimes, Saturation, Elimination, LocalRings}, P ->
    scan(keys P#"private dictionary", k -> if not isGlobalSymbol k then << "private " << k << endl));
scan(dictionaryPath, d -> scan(keys d, k -> (v := value d#k;
    << "global " << k << " " << (if instance(v, Function) then "function" else toString class v) << endl)));
<< "version " << version#"VERSION" << endl;
exit 0
"""


def m2_string(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def run(cmd: list[str], stdin: str, timeout: float, cwd: str) -> tuple[int, str, str, float, bool]:
    """(exit status, stdout, stderr, seconds, timed out) of one process (killed with its group on time-out)."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, cwd=cwd, start_new_session=True, errors="replace")
    try:
        out, err = proc.communicate(stdin, timeout=timeout)
        return proc.returncode, out, err, time.perf_counter() - t0, False
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, 9)
        out, err = proc.communicate()
        return -9, out, err, time.perf_counter() - t0, True


def m2_info(timeout: float) -> dict:
    """Macaulay2's version, the private names of the packages, the class of every global name."""
    with tempfile.TemporaryDirectory() as tmp:
        rc, out, err, _, _ = run([M2, "-q", "--silent", "--no-prompts"], M2_INFO, timeout, tmp)
    info: dict = {"private": set(), "globals": {}, "version": "?"}
    for line in out.splitlines():
        kind, _, rest = line.partition(" ")
        if kind == "private":
            info["private"].add(rest)
        elif kind == "global":
            name, _, cls = rest.partition(" ")
            info["globals"][name] = cls
        elif kind == "version":
            info["version"] = rest
    if not info["globals"]:
        raise SystemExit(f"m2_examples: cannot run Macaulay2 ({M2}): {err.strip()[:300]}")
    return info


def run_mech(code: str, timeout: float, tmp: str) -> dict:
    """mech's values (statement number -> text), printed lines, first error, exit status."""
    rc, out, err, secs, timed_out = run(MECH + ["-"], code + "\n", timeout, tmp)  # standard input: oN = ...
    values: dict[int, str] = {}
    prints: list[str] = []
    for line in out.splitlines():
        m = re.match(r"o(\d+) = (.*)$", line)
        if m:
            values[int(m.group(1))] = m.group(2)
        elif not re.match(r" *-- (used |[0-9.e-]+s elapsed)", line):  # the time used, after `time`
            prints.append(line)
    return {"values": values, "prints": prints, "rc": rc, "err": err, "seconds": secs, "timeout": timed_out}


def run_m2(case: Case, mech_values: dict[int, str], timeout: float, tmp: str,
           mech_prints: list[str] = ()) -> dict:
    """Macaulay2's values with its verdicts on mech's, printed lines, classes, first error (and the
    verdict of the case's NOT_UNIQUE check)."""
    table = ", ".join(f"{n} => {m2_string(t)}" for n, t in sorted(mech_values.items()))
    prints = ", ".join(m2_string(t) for t in mech_prints)
    check = NOT_UNIQUE[case.where][3] + "\n" if case.where in NOT_UNIQUE else ""
    pre = Path(tmp) / "mode.m2"
    load = f'needsPackage "{case.package}";\n' if case.package else ""
    hashed = "true" if HASH_ORDER & {t for _, t in tokens(case.code)} else "false"
    pre.write_text(f"{load}mechOut = new HashTable from {{{table}}};\nmechPrints = {{{prints}}};\nmechHashOrder = {hashed};\n{M2_MODE}")
    cmd = [M2, "-q", "--silent", "--no-prompts", "--stop", "--no-randomize", "-e", f'load "{pre}"']
    rc, out, err, secs, timed_out = run(cmd, case.code + "\n" + check, timeout, tmp)
    values: dict[int, tuple[str, str]] = {}
    classes: set[str] = set()
    prints: list[str] = []
    unique = ""
    for rec in re.findall(f"{SEP}(.*?){SEP}", out, re.S):
        f = rec.split(FS)
        if f[0] == "V" and len(f) == 5:
            values[int(f[1])] = (f[3], f[4])
            classes.add(f[2])
        elif f[0] == "K" and len(f) == 3:
            classes.add(f[2])
        elif f[0] == "P":
            prints.extend(f[1].split("\n"))
        elif f[0] == "U" and len(f) == 2:
            unique = f[1]
    error = next((ln.strip() for ln in err.splitlines() if "error" in ln), err.strip()[:200] if rc else "")
    return {"values": values, "classes": classes, "prints": prints, "rc": rc, "error": error,
            "seconds": secs, "timeout": timed_out, "unique": unique}


# ---------------------------------------------------------------- classifying
#: mech's error messages naming a construct it lacks: pattern -> the construct (from the groups)
UNSUPPORTED = [
    (r"unknown identifier '([^']+)'", "{name}"),
    (r"unexpected (?:character|'|end of input)|unterminated", "{syntax}"),
    (r"cannot assign to this expression", "{keyword}"),
    (r"wrong arguments for (\S+): got \(([^)]*)\)", "{0}({1})"),
    (r"wrong number of arguments for (\S+): got (\d+)", "{0} with {1} arguments"),
    (r"a (.+?) cannot be applied to arguments", "applying a {0} to arguments"),
    (r"a (.+?) cannot be indexed", "indexing a {0}"),
    (r"no operator (\S+) for (?:a |an )?(\S+) and (?:a |an )?(\S+)", "operator {0} on {1}, {2}"),
    (r"operator (\S+) (?:is not defined|needs).*?(?:for|not) (.+)$", "operator {0} on {1}"),
    (r"unary minus is not defined for (.+)", "unary minus on {0}"),
    (r"cannot compare (.+)", "comparing {0}"),
    (r"unknown ring option '([^']*)'", "ring option {0}"),
    (r"unknown monomial order (.*?) \(known", "monomial order {0}"),
    (r"the integers ZZ are not a field", "ZZ as a value"),
    (r"polynomial ring is built over QQ or ZZ/p, not over a ring", "polynomial rings over polynomial rings"),
    (r"polynomial ring is built over QQ or ZZ/p, not over a (.+)", "polynomial rings over a {0}"),
    (r"no ring active", "integers as ring elements (no ring)"),
    (r"cannot assign to an entry", "assigning to an entry"),
    (r"a ring variable is a name", "ring variables of another form"),
    (r"# needs a list, sequence or string, not a (.+)", "# of a {0}"),
    (r"expected polynomials, got a (.+)", "polynomials from a {0}"),
    (r"expected ring variables", "a polynomial where mech expects ring variables"),
    (r"for \.\.\. in needs a list, not a (.+)", "for ... in over a {0}"),
    (r"takes a list of (\w+)", "{0} in another form"),
    (r"is not a function", "calling a value that is not a function"),
    (r"a condition is true or false, not a (.+)", "a {0} as a condition"),
]
#: Macaulay2's operators, the longest first (to name the one at a syntax error)
M2_OPERATORS = sorted(["===>", "<===", "<==>", "=!=", "===", "==>", "..<", "^**", "=>", "==", "!=", ":=", "<-",
                       "->", "**", "//", "\\\\", "_*", "^*", "||", "|-", "@@", "..", "#?", ".?", "<<", ">>",
                       "++", "^^", "|", "@", "&", "~", "$", "\\", "."], key=len, reverse=True)


def mech_error(err: str) -> tuple[str, int, int]:
    """The message, line and column of mech's first error (``file:line:col: error: message``)."""
    for line in err.splitlines():
        m = re.search(r"(?::(\d+):(\d+))?: error: (.*)$", line)
        if m:
            return m.group(3).strip(), int(m.group(1) or 0), int(m.group(2) or 0)
    return (err.strip().splitlines()[-1] if err.strip() else "no output"), 0, 0


def syntax_construct(line: str, col: int) -> str:
    """The Macaulay2 construct at a syntax error in column ``col`` (from 1) of ``line``."""
    i = col - 1
    for op in M2_OPERATORS:
        if any(line.startswith(op, k) for k in range(max(i - len(op) + 1, 0), i + 1)):
            return f"operator {op}"
    rest, before = line[i:], line[:i].rstrip()
    if rest.startswith("else") and re.search(r"\btry\b", before):
        return "try ... else"
    if rest.startswith("["):
        return "operator ^[...]" if before.endswith("^") else "arrays [...]"
    if rest[:1] in (",", ")") and before.endswith(("(", ",")):
        return "empty arguments f(a,,b)"
    m = re.match(r"\w+|\S", rest)
    return f"'{m.group()}'" if m else "an incomplete statement"


def blocking(message: str, info: dict, line: str = "", col: int = 0) -> tuple[str, str]:
    """(status, construct) for mech's error message (at column ``col`` of the source ``line``):
    *unsupported* with the construct it lacks, *crash* for internal errors, *differ* for a failed
    assertion, else *error*."""
    if "internal error" in message or "Traceback" in message:
        return "crash", re.sub(r"internal error: ", "", message)[:120]
    if re.search(r"\bassertion\b", message):
        return "differ", "assertion failed"
    for pattern, template in UNSUPPORTED:
        m = re.search(pattern, message)
        if not m:
            continue
        if template == "{name}":
            name = m.group(1)
            kind = info["globals"].get(name)
            if name == "ZZ":
                return "unsupported", "ZZ as a value"
            if kind is None:
                return "unsupported", "names without a value used as symbols"
            return "unsupported", (f"function {name}" if kind == "function" else f"{kind} {name}")
        if template == "{syntax}":
            return "unsupported", "syntax: " + syntax_construct(line, col)
        if template == "{keyword}":
            word = re.match(r"\w*", line[max(col - 1, 0):]).group()
            kind = info["globals"].get(word)
            return "unsupported", f"{kind} {word}" if kind and kind != "function" else "assigning to an expression"
        return "unsupported", template.format(*m.groups())
    return "error", message


def internals(case: Case, info: dict) -> str:
    """The package's internal names (not exported) the code uses and does not define."""
    toks = [t for _, t in tokens(case.code)]
    defined = {t for k, t in enumerate(toks[:-1]) if toks[k + 1] in ("=", ":")}
    used = sorted({t for t in toks if t in info["private"] and t not in defined and len(t) > 1})
    return ", ".join(used)


def classify(case: Case, mech: dict, m2: dict, info: dict) -> Result:
    """The case's result from both runs (see the module's docstring)."""
    res = Result(case, seconds={"mech": round(mech["seconds"], 2), "M2": round(m2["seconds"], 2)})
    out_cls = sorted(m2["classes"] & OUT_CLASSES)
    if m2["timeout"]:
        res.status, res.reason = "excluded", "Macaulay2 1.21 times out"
    elif m2["rc"]:
        res.status, res.reason, res.detail = "excluded", "Macaulay2 1.21 fails on it", m2["error"]
    elif out_cls:
        res.status, res.reason = "excluded", f"values outside mech's scope: {', '.join(out_cls)}"
    if res.status:
        return res
    verdicts = {n: v for n, (_, v) in m2["values"].items()}
    mech_prints, m2_prints = mech["prints"], m2["prints"]
    if case.where in NOT_UNIQUE and m2["unique"] == "true":  # judged by the check (NOT_UNIQUE)
        reason, statements, lines, _ = NOT_UNIQUE[case.where]
        verdicts.update({n: "not unique" for n in statements if n in verdicts})
        mech_prints, m2_prints = mech_prints[lines:], m2_prints[lines:]
        res.reason = f"compared by a unique value: {reason}"
    elif case.where in NOT_UNIQUE and mech["rc"] == 0:
        verdicts.update({n: "differ" for n in NOT_UNIQUE[case.where][1]})
    res.values = len(mech["values"])
    res.agreed = sum(v in AGREE for v in verdicts.values())
    res.as_values = sum(v in AGREE[1:] for v in verdicts.values())
    wrong = [(n, v) for n, v in sorted(verdicts.items()) if v in ("differ", "unreadable")]
    extra = sorted(set(mech["values"]) - set(verdicts))
    finished = mech["rc"] == 0 and not mech["timeout"]
    missing = [n for n, v in sorted(verdicts.items()) if v == "missing"] if finished else []
    shown = min(len(mech_prints), len(m2_prints)) if not finished else None
    if wrong:
        n, v = wrong[0]
        res.status = "differ"
        res.reason = f"o{n}: Macaulay2 {m2['values'][n][0]!r}, mech {mech['values'][n]!r}" + \
            (" (mech's text unreadable)" if v == "unreadable" else "")
    elif extra:
        res.status, res.reason = "differ", f"mech prints o{extra[0]} = {mech['values'][extra[0]]!r}, Macaulay2 nothing"
    elif missing:
        res.status, res.reason = "differ", f"Macaulay2 prints o{missing[0]} = {m2['values'][missing[0]][0]!r}, mech nothing"
    elif mech_prints[:shown] != m2_prints[:shown]:
        res.status, res.reason = "differ", f"printed lines: Macaulay2 {m2_prints[:3]}, mech {mech_prints[:3]}"
    elif mech["timeout"]:
        res.status, res.reason = "timeout", "mech times out"
    elif not finished:
        message, line, col = mech_error(mech["err"])
        message += " (Traceback)" if "Traceback" in mech["err"] else ""
        lines = case.code.split("\n")
        res.status, res.reason = blocking(message, info, lines[line - 1] if 0 < line <= len(lines) else "", col)
        res.detail = message
    else:
        res.status = "agree"
    return res


def mech_lacks(results: list[Result], info: dict) -> Counter:
    """Macaulay2's functions that the in-scope cases not agreeing use (and do not define) and that
    mech's Macaulay2 dialect does not know: function -> number of cases."""
    uses: dict[int, set[str]] = {}
    for r in results:
        if r.status in STATUSES and r.status != "agree":
            toks = [t for _, t in tokens(r.case.code)]
            defined = {t for k, t in enumerate(toks[:-1]) if toks[k + 1] in ("=", ":")}
            uses[id(r)] = {t for t in toks if info["globals"].get(t) == "function" and t not in defined}
    names = set().union(*uses.values()) if uses else set()
    probe = ("import sys\nfrom mech import MechError, Session\ns = Session(dialect='m2')\n"
             "for n in sys.stdin.read().split():\n    try:\n        v = s.eval(n)\n"
             "    except MechError:\n        v = None\n"
             "    if v is None or type(v).__name__ == 'Symbol':  # a name without a value\n        print(n)\n")
    with tempfile.TemporaryDirectory() as tmp:
        lacking = set(run([sys.executable, "-c", probe], "\n".join(sorted(names)), 300, tmp)[1].split())
    return Counter(n for used in uses.values() for n in used & lacking)


def run_case(case: Case, info: dict, timeout: float) -> Result:
    if case.excluded:
        return Result(case, "excluded", case.excluded)
    used = internals(case, info)
    if used:
        return Result(case, "excluded", f"package internals: {used}")
    if case.where in ASSERTED_CHOICES:
        claim, value = ASSERTED_CHOICES[case.where]
        case = replace(case, code=case.code.replace(claim, value))
    with tempfile.TemporaryDirectory(prefix="m2ex-") as tmp:
        mech = run_mech(case.code, timeout, tmp)
        m2 = run_m2(case, mech["values"], timeout, tmp, mech["prints"])
    return classify(case, mech, m2, info)


# ---------------------------------------------------------------- the report
def mech_commit() -> str:
    head = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
    dirty = subprocess.run(["git", "-C", str(ROOT), "status", "--porcelain", "--untracked-files=no"],
                           capture_output=True, text=True)
    return head.stdout.strip() + (" (with uncommitted changes)" if dirty.stdout.strip() else "")


def counts_table(results: list[Result], key, title: str) -> list[str]:
    groups: dict[str, Counter] = {}
    for r in results:
        groups.setdefault(key(r), Counter())[r.status] += 1
    lines = [f"| {title} | in scope | " + " | ".join(STATUSES) + " | agree % | excluded |",
             "|---|" + "---|" * (len(STATUSES) + 3)]
    total = Counter()
    for name in sorted(groups):
        total.update(groups[name])
    for name, c in [*sorted(groups.items()), ("**all**", total)]:
        scope = sum(c[s] for s in STATUSES)
        pct = f"{100 * c['agree'] / scope:.0f}%" if scope else "—"
        lines.append(f"| {name} | {scope} | " + " | ".join(str(c[s]) for s in STATUSES) + f" | {pct} | {c['excluded']} |")
    return lines


def cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def report(results: list[Result], meta: dict) -> str:
    scope = [r for r in results if r.status != "excluded"]
    agree = sum(r.status == "agree" for r in scope)
    lines = [
        "# Macaulay2's own examples in mech's Macaulay2 dialect", "",
        "Produced by `python benchmarks/m2_examples.py --src SRC --write` (selection, running and comparison: "
        "the docstring of benchmarks/m2_examples.py).  A case is a doc node's examples or a TEST block.  "
        "*agree*: every value Macaulay2 prints, mech prints (as text, or as a value Macaulay2 judges equal: "
        "ideals as ideals, lists of ideals as sets, lists of a hash table's elements as sets); *differ*: a value Macaulay2 judges different, a value "
        "printed by one system only, a failed assertion; *unsupported*: mech stops on a construct it lacks "
        "(ranked below); *error*: another mech error; *crash*: an internal error.", "",
        f"- date: {meta['date']}; full run {meta['seconds']:.0f} s with {meta['jobs']} jobs, time-out {meta['timeout']:g} s",
        f"- Macaulay2 {meta['m2_version']} (`{M2}`); sources: {meta['source']}",
        f"- mech commit {meta['mech']}",
        f"- cases: {len(results)} found, {len(scope)} in scope, **{agree} agree ({100 * agree / max(len(scope), 1):.0f}%)**; "
        f"statements compared: {sum(r.values for r in scope)}, agreeing {sum(r.agreed for r in scope)} "
        f"({sum(r.as_values for r in scope)} of them as values, not as text)", "",
        "## By kind", "", *counts_table(results, lambda r: r.case.kind, "kind"), "",
        "## By package or page", "", *counts_table(results, lambda r: r.case.origin, "package / page"), "",
        "## Missing features", "",
        "The construct on which mech stops in each *unsupported* case (the first one only), by the number of cases "
        "it blocks.", "", "| construct | cases | for example |", "|---|---|---|"]
    blocked: dict[str, list[Result]] = {}
    for r in scope:
        if r.status == "unsupported":
            blocked.setdefault(r.reason, []).append(r)
    for reason, rs in sorted(blocked.items(), key=lambda kv: (-len(kv[1]), kv[0])):
        lines.append(f"| {cell(reason)} | {len(rs)} | {rs[0].case.where} |")
    lines += ["", "Every Macaulay2 function that mech's dialect lacks, by the number of in-scope cases not agreeing "
              "that use it (anywhere in their code, not only first):", "",
              ", ".join(f"{name} {n}" for name, n in sorted(meta["lacks"].items(), key=lambda kv: (-kv[1], kv[0])))
              or "none"]
    unique = [r for r in scope if r.case.where in NOT_UNIQUE]
    lines += ["", f"## Compared by a unique value ({len(unique)})", "",
              "Values that depend on a choice Macaulay2 makes and that is not part of the mathematical value "
              "(`NOT_UNIQUE`): Macaulay2 checks mech's own choice instead of comparing the text.", ""]
    lines += [f"- {r.case.where} ({cell(r.case.name)}): {r.status}; {cell(NOT_UNIQUE[r.case.where][0])}"
              for r in unique] or ["none"]
    for status, title in (("differ", "Different values"), ("crash", "Crashes"), ("error", "Errors"),
                          ("timeout", "Time-outs")):
        rs = [r for r in scope if r.status == status]
        lines += ["", f"## {title} ({len(rs)})", ""]
        lines += [f"- {r.case.where} ({cell(r.case.name)}): {cell(r.reason)}" for r in rs] or ["none"]
    lines += ["", "## Excluded", "", "| reason | cases |", "|---|---|"]
    excluded = Counter(re.sub(r":.*", "", r.reason) for r in results if r.status == "excluded")
    lines += [f"| {cell(k)} | {v} |" for k, v in excluded.most_common()]
    lines += ["", "## Every case", "", "| case | node | kind | status | reason |", "|---|---|---|---|---|"]
    lines += [f"| {r.case.where} | {cell(r.case.name)} | {r.case.kind} | {r.status} | {cell(r.reason)} |"
              for r in results]
    return "\n".join(lines) + "\n"


def main(argv: Optional[list[str]] = None) -> int:
    p = argparse.ArgumentParser(description=" ".join(__doc__.split("\n\n")[0].split()))
    p.add_argument("--src", type=Path, required=True, help="a checkout of Macaulay2's sources (github.com/Macaulay2/M2)")
    p.add_argument("--only", help="run only the cases whose file:line or node matches this regular expression")
    p.add_argument("--timeout", type=float, default=60, help="seconds per case and system (default 60)")
    p.add_argument("--jobs", type=int, default=2, help="cases run at once (default 2)")
    p.add_argument("--write", action="store_true", help=f"rewrite {REPORT.relative_to(ROOT)}")
    p.add_argument("--json", type=Path, help="save every case's result to this file")
    p.add_argument("--list", action="store_true", help="list the cases and their exclusions, run nothing")
    args = p.parse_args(argv)
    if args.write and args.only:
        p.error("--write writes the report of every case: not with --only")
    cases = extract(args.src)
    if args.only:
        cases = [c for c in cases if re.search(args.only, f"{c.where} {c.name}")]
    if args.list:
        for c in cases:
            print(f"{c.where}\t{c.kind}\t{c.name}\t{c.excluded or 'in scope'}")
        return 0
    t0 = time.perf_counter()
    info = m2_info(120)
    if subprocess.run(MECH + ["-c", "1;"], capture_output=True).returncode:
        raise SystemExit(f"m2_examples: mech does not run with {sys.executable} (run this with mech's Python)")
    with ThreadPoolExecutor(max_workers=max(args.jobs, 1)) as pool:
        results = list(pool.map(lambda c: run_case(c, info, args.timeout), cases))
    meta = {"date": time.strftime("%Y-%m-%d %H:%M"), "seconds": time.perf_counter() - t0, "jobs": args.jobs,
            "timeout": args.timeout, "m2_version": info["version"], "source": source_version(args.src),
            "mech": mech_commit(), "lacks": mech_lacks(results, info)}
    for r in results:
        if r.status not in ("agree", "excluded"):
            print(f"{r.status:12} {r.case.where} {r.case.name}: {r.reason}")
    c = Counter(r.status for r in results)
    print(", ".join(f"{s} {c[s]}" for s in (*STATUSES, "excluded")), f"({meta['seconds']:.0f} s)")
    if args.json:
        args.json.write_text(json.dumps([asdict(r) for r in results], indent=1))
    if args.write:
        REPORT.write_text(report(results, meta))
    return 0


if __name__ == "__main__":
    sys.exit(main())
