"""Fuzzing the front end: random scripts built from the language's constructs, and byte-level
mutations of the corpus scripts, run through ``Session.execute`` (and a few through ``mech``).

Every run must end in a result or in a :class:`MechError` in the standard format
``FILE:LINE:COL: error: message``, the source line and a caret; never a Python exception, an
internal error or a hang.  Runs are under time and memory limits (``mech.dsl.limits``), so a
random ``std`` that takes too long ends in a (well-formed) limit error.

CI runs a fixed seed within a small budget; a bigger run from the command line::

    python -m tests.dsl.test_fuzz --seed 7 --count 5000 [--cli 200]
"""
from __future__ import annotations

import argparse
import random
import re
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from mech import MechError, MechInternalError, Session

from tests.util import ROOT

CORPUS = sorted((ROOT / "tests" / "corpus").glob("*.sing")) + sorted(Path("/work/shared/reference/paper").glob("*.sing"))
TIMEOUT = 2.0          # seconds per statement of a fuzzed script
HANG = 30.0            # a whole run taking longer than this is a hang (parsing is not under the limits)
MEMORY = 600           # MB a statement may add to the process

HEAD = re.compile(r"^(?P<file>.+?):(?P<line>\d+):(?P<col>\d+): error: (?P<msg>.+)$")
CARET = re.compile(r"^[ \t]*\^~*$")


# ---------------------------------------------------------------- random scripts from the grammar
class ScriptGen:
    """Random programs of the language: declarations, rings, expressions of every operator,
    commands of the registry, control flow, procedures, and some nonsense in between."""

    TYPES = ["int", "number", "poly", "ideal", "string", "intvec", "list", "matrix", "def", "bigint", "map"]
    ORDERINGS = ["dp", "lp", "Dp", "ds", "ls", "Ds", "wp(1,2,3)", "Wp(2,1,1)", "ws(1,1,2)", "(dp(2),lp(1))",
                 "(lp(1),dp(2))", "(a(1,2,0),dp)", "M(1,1,1,0,-1,0,0,0,-1)", "(dp(1),ds(2))", "(c,dp)", "(dp,C)",
                 "wp(0,1,1)", "dp(2)", "M(1,1)", "xx"]
    CHARS = ["0", "32003", "7", "2", "(0,a)", "(7,a,b)", "4", "-1", "real", "(0,x)"]
    OPS = ["+", "-", "*", "/", "^", "div", "mod", "%", "==", "!=", "<", "<=", ">", ">=", "&&", "||", "..", ":",
           "<>", "**", "and", "or"]

    def __init__(self, rng: random.Random, commands: list[str]) -> None:
        self.r = rng
        self.commands = commands
        self.names = ["i", "j", "k", "n", "s", "f", "g", "I", "J", "L", "v", "M", "c", "r", "S", "phi", "p", "q"]

    def statements(self) -> list[str]:
        out = [self.ring_decl("r")] if self.r.random() < 0.8 else []
        return out + [self.stmt(0) for _ in range(self.r.randint(1, 12))]

    # ---- statements
    def stmt(self, depth: int) -> str:
        r = self.r
        kinds = ["decl", "decl", "expr", "expr", "assign", "incdec", "ring", "setring", "lib", "option"]
        if depth < 3:
            kinds += ["if", "for", "while", "proc", "block"]
        kind = r.choice(kinds + ["misc"])
        if kind == "decl":
            t = r.choice(self.TYPES)
            name = r.choice(self.names)
            if t == "matrix" and r.random() < 0.5:
                return f"matrix {name}[{r.randint(0, 3)}][{r.randint(1, 3)}] = {self.exprlist(1)};"
            if r.random() < 0.2:
                return f"{t} {name};"
            return f"{t} {name} = {self.exprlist(1)};"
        if kind == "expr":
            return f"{self.exprlist(0)};"
        if kind == "assign":
            return f"{self.target()} = {self.exprlist(1)};"
        if kind == "incdec":
            return f"{self.target()}{r.choice(['++', '--'])};"
        if kind == "ring":
            return self.ring_decl(r.choice(["r", "S", "R2"]))
        if kind == "setring":
            return f"setring {r.choice(['r', 'S', 'R2', 'i'])};"
        if kind == "lib":
            return f'LIB "{r.choice(["primdec.lib", "elim.lib", "poly.lib", "nosuch.lib", "sing.lib", "../x.lib"])}";'
        if kind == "option":
            return f"option({r.choice(['redSB', 'noredSB', 'prot', 'bogus', ''])});"
        if kind == "if":
            s = f"if ({self.expr(1)}) {{ {self.body(depth)} }}"
            if r.random() < 0.5:
                s += f" else {{ {self.body(depth)} }}"
            return s
        if kind == "for":
            v = r.choice(["i", "j", "k"])
            return f"for (int {v} = {r.randint(-2, 2)}; {v} < {r.randint(0, 6)}; {v}++) {{ {self.body(depth)} }}"
        if kind == "while":
            v = r.choice(["i", "j"])
            return f"int {v} = 0; while ({v} < {r.randint(0, 5)}) {{ {v}++; {self.body(depth)} }}"
        if kind == "proc":
            name = r.choice(["p", "q", "helper"])
            params = ", ".join(f"{r.choice(['int', 'poly', 'ideal', 'def', 'list', 'string'])} {n}"
                               for n in r.sample(["a", "b", "c"], r.randint(0, 2)))
            ret = f"return({self.expr(1)});" if r.random() < 0.7 else ""
            return f"proc {name}({params}) {{ {self.body(depth)} {ret} }} {name}({self.args()});"
        if kind == "block":
            return f"{{ {self.body(depth)} }}"
        return r.choice([
            "kill " + r.choice(self.names) + ";", "export " + r.choice(self.names) + ";",
            "keepring r;", "break;", "continue;", "return(1);", "help;", f"help {r.choice(self.commands)};",
            "basering;", "print(" + self.expr(1) + ");", "typeof(" + self.expr(1) + ");", ";", "listvar();",
            "map phi = r, " + self.exprlist(1) + ";", "phi(" + self.expr(1) + ");", "quit;" if r.random() < 0.1 else ";",
            "int k = " + self.expr(1) + "; k;", "string(" + self.expr(1) + ");", "execute(\"" + self.expr(1).replace('"', "") + ";\");",
            "limits(\"timeout\");", "system(\"--ticks-per-sec\");", "timer;",
        ])

    def body(self, depth: int) -> str:
        return " ".join(self.stmt(depth + 1) for _ in range(self.r.randint(0, 3)))

    def target(self) -> str:
        name = self.r.choice(self.names)
        if self.r.random() < 0.3:
            return f"{name}[{self.r.randint(-1, 4)}]"
        if self.r.random() < 0.1:
            return f"{name}[1,2]"
        return name

    def ring_decl(self, name: str) -> str:
        r = self.r
        n = r.randint(1, 4)
        vars_ = r.choice([f"({','.join('xyzw'[:n])})", f"(x(1..{n}))", "(x,y,z)", "x", "(x,y,x)", "(a,b)", f"(y(1..{n}),z)"])
        ordering = r.choice(self.ORDERINGS)
        if r.random() < 0.05:
            return f"ring {name};"
        return f"ring {name} = {r.choice(self.CHARS)}, {vars_}, {ordering};"

    # ---- expressions
    def exprlist(self, depth: int) -> str:
        return ", ".join(self.expr(depth) for _ in range(self.r.choice([1, 1, 1, 2, 3])))

    def args(self) -> str:
        return ", ".join(self.expr(2) for _ in range(self.r.randint(0, 3)))

    def expr(self, depth: int) -> str:
        r = self.r
        if depth > 4 or r.random() < 0.3:
            return self.atom()
        kind = r.random()
        if kind < 0.4:
            return f"{self.expr(depth + 1)} {r.choice(self.OPS)} {self.expr(depth + 1)}"
        if kind < 0.5:
            return f"{r.choice(['-', '!', 'not ', '+'])}{self.expr(depth + 1)}"
        if kind < 0.6:
            return f"({self.exprlist(depth + 1)})"
        if kind < 0.85:
            name = r.choice(self.commands + self.TYPES + ["p", "q", "f", "nosuch"])
            return f"{name}({', '.join(self.expr(depth + 1) for _ in range(r.randint(0, 3)))})"
        if kind < 0.95:
            return f"{self.atom()}[{self.expr(depth + 1)}]"
        return f"{self.atom()}({r.randint(1, 3)})"

    def atom(self) -> str:
        r = self.r
        return r.choice([
            str(r.randint(-3, 12)), str(r.randint(0, 2**70)), f"{r.randint(0, 9)}/{r.randint(0, 9)}",
            r.choice(["x", "y", "z", "w", "x2", "xy", "3x2y", "1/2x", "x(1)", "x(2)", "a", "b", "x^2", "y3z"]),
            r.choice(self.names), r.choice(self.names), '"' + r.choice(["", "abc", "x;y", "{", "//"]) + '"',
            r.choice(["_", "basering", "nvars(basering)", "#", "x^" + str(r.randint(0, 40)), "maxideal(2)",
                      "ideal(x,y)", "std(ideal(x2-y,xy))", "1..3", "intvec(1,2)", "list(1,\"a\")", "matrix(ideal(x,y))"]),
        ])


# ---------------------------------------------------------------- byte-level mutations
SPECIAL = ['"', ";", "{", "}", "(", ")", "[", "]", ",", "/*", "*/", "//", "\n", "\\", "#", "@", "`", "$", "\x00",
           "\x7f", "é", "∀", "\ufeff", "..", "^", "**", "=", "==", "9" * 25, "-", "ring", "proc", "if", "else",
           "while(1){}", "x^99999999", "2^99999999", "LIB \"/etc/passwd\";", "kill basering;", "quit;"]


def mutate(rng: random.Random, text: str, donors: list[str]) -> str:
    """``text`` after one to four random byte-level edits."""
    for _ in range(rng.randint(1, 4)):
        n = len(text)
        i = rng.randint(0, n)
        j = min(n, i + rng.randint(0, 30))
        op = rng.randrange(8)
        if op == 0:                      # delete a span
            text = text[:i] + text[j:]
        elif op == 1:                    # insert a special token
            text = text[:i] + rng.choice(SPECIAL) + text[i:]
        elif op == 2:                    # insert random bytes
            junk = bytes(rng.randrange(256) for _ in range(rng.randint(1, 6))).decode("latin-1")
            text = text[:i] + junk + text[i:]
        elif op == 3:                    # duplicate a span
            text = text[:j] + text[i:j] + text[j:]
        elif op == 4:                    # replace one character
            if n:
                text = text[:i] + rng.choice(SPECIAL) + text[i + 1:]
        elif op == 5:                    # truncate
            text = text[:i]
        elif op == 6:                    # splice a piece of another script
            d = rng.choice(donors)
            a = rng.randint(0, len(d))
            text = text[:i] + d[a:a + rng.randint(1, 200)] + text[j:]
        else:                            # swap two spans
            k = rng.randint(0, n)
            l = min(n, k + rng.randint(0, 30))
            if j <= k:
                text = text[:i] + text[k:l] + text[j:k] + text[i:j] + text[l:]
    return text


# ---------------------------------------------------------------- running and checking
@dataclass
class Stats:
    runs: int = 0
    ok: int = 0
    errors: int = 0
    limit_errors: int = 0
    failures: list[tuple[str, str]] = field(default_factory=list)   # (problem, script)
    seconds: float = 0.0

    def add(self, other: "Stats") -> None:
        self.runs += other.runs
        self.ok += other.ok
        self.errors += other.errors
        self.limit_errors += other.limit_errors
        self.failures += other.failures
        self.seconds += other.seconds


def format_problem(err: MechError, text: str, name: str) -> str:
    """What is wrong with how ``err`` is reported ('' when it is the standard format)."""
    if isinstance(err, MechInternalError):
        return f"internal error: {err.message}"
    lines = err.format().split("\n")
    m = HEAD.match(lines[0])
    if not m:
        return f"bad first line: {lines[0]!r}"
    if m["file"] != name and not m["file"].endswith(".lib"):
        return f"wrong file name in {lines[0]!r}"
    line = int(m["line"])
    src = text.splitlines()[line - 1] if 0 < line <= len(text.splitlines()) else None
    if m["file"] != name:
        return ""
    if src is None:
        return f"line {line} is not in the script: {lines[0]!r}"
    if not src.strip():
        return ""  # nothing to show under the message
    if len(lines) < 3 or not CARET.match(lines[2]):
        return f"no source line and caret under {lines[0]!r}"
    return ""


def check(text: str, name: str = "<fuzz>", session: Session | None = None) -> tuple[str, str]:
    """Run ``text``; ("ok" | "error" | "limit", "") or ("fail", what went wrong)."""
    s = session or Session(timeout=TIMEOUT, max_memory=MEMORY)
    start = time.monotonic()
    try:
        s.execute(text, name)
        outcome = ("ok", "")
    except MechError as e:
        problem = format_problem(e, text, name)
        kind = "limit" if "limit of" in e.message else "error"
        outcome = ("fail", problem) if problem else (kind, "")
    except BaseException as e:  # noqa: BLE001 - exactly what must never happen
        if isinstance(e, KeyboardInterrupt):
            raise
        outcome = ("fail", f"Python exception {type(e).__name__}: {e}")
    elapsed = time.monotonic() - start
    if elapsed > HANG:
        outcome = ("fail", f"took {elapsed:.0f} s")
    return outcome


def campaign(seed: int, count: int, kind: str) -> Stats:
    """``count`` runs of generated ("grammar") or mutated ("mutation") scripts from ``seed``."""
    from mech.dsl import registry
    registry.load_plugins()
    rng = random.Random(f"{kind}:{seed}")
    commands = sorted(registry.COMMANDS)
    gen = ScriptGen(rng, commands)
    donors = [p.read_text() for p in CORPUS]
    stats = Stats()
    t0 = time.monotonic()
    for _ in range(count):
        if kind == "grammar":  # the whole script, then its statements one by one in one session (a REPL)
            statements = gen.statements()
            repl = Session(timeout=TIMEOUT, max_memory=MEMORY)
            runs = [("\n".join(statements), None)] + [(st, repl) for st in statements]
        else:
            runs = [(mutate(rng, rng.choice(donors), donors), None)]
        for text, session in runs:
            outcome, problem = check(text, session=session)
            stats.runs += 1
            if outcome == "fail":
                stats.failures.append((problem, text))
            elif outcome == "ok":
                stats.ok += 1
            elif outcome == "limit":
                stats.limit_errors += 1
            else:
                stats.errors += 1
    stats.seconds = time.monotonic() - t0
    return stats


def check_cli(text: str, tmp: Path) -> str:
    """Run ``text`` as a script through ``mech``; '' or what went wrong."""
    path = tmp / "fuzz.sing"
    path.write_bytes(text.encode("utf-8", "surrogatepass"))
    try:
        r = subprocess.run([sys.executable, "-m", "mech", "--timeout", str(TIMEOUT), "--max-memory", "2000", str(path)],
                           capture_output=True, timeout=HANG + 30, cwd=tmp)
    except subprocess.TimeoutExpired:
        return "hang"
    err = r.stderr.decode("utf-8", "replace")
    if "Traceback" in err:
        return "traceback: " + err[-500:]
    if r.returncode not in (0, 1):
        return f"exit status {r.returncode}: {err[-300:]}"
    if r.returncode == 1:
        m = HEAD.match(err.split("\n", 1)[0])
        if not m:
            return f"bad error format: {err[:300]!r}"
    return ""


# ---------------------------------------------------------------- the CI budget
def _report(stats: Stats) -> str:
    lines = [f"{stats.runs} runs: {stats.ok} ok, {stats.errors} errors, {stats.limit_errors} limit errors, "
             f"{len(stats.failures)} failures"]
    for problem, text in stats.failures[:5]:
        lines.append(f"--- {problem}\n{text[:2000]}")
    return "\n".join(lines)


def test_fuzz_generated_scripts():
    stats = campaign(seed=0, count=150, kind="grammar")
    assert not stats.failures, _report(stats)
    assert stats.ok > 0 and stats.errors > 0


def test_fuzz_mutated_corpus():
    stats = campaign(seed=0, count=150, kind="mutation")
    assert not stats.failures, _report(stats)
    assert stats.errors > 0


def test_fuzz_through_the_cli(tmp_path):
    rng = random.Random(1)
    donors = [p.read_text() for p in CORPUS]
    scripts = [mutate(rng, rng.choice(donors), donors) for _ in range(3)]
    scripts += ['ring r = 0,(x,y),dp;\nx+;\n', 'int i = 1;\n"unterminated\n', "\x00\x01\xff;", "}"]
    problems = [(p, s) for s in scripts if (p := check_cli(s, tmp_path))]
    assert not problems, problems


# Inputs the fuzzer found mishandled (an internal error, a hang, a broken message), now answered right.
REGRESSIONS = [
    ("ring r = 7, x, (a(1,2,0),dp); poly f = x^33; f;", "x33\n"),          # a(...) longer than the variables
    ("ring r = 0, (x,y), (dp(2),a(1,2)); x + y;", "x+y\n"),
    ("ring r = (7,a), x, dp; 7/8 < 3;", "1\n"),                          # constants are ordered, as in Singular
    ("ring r = (7,a), x, dp; number(2) == number(3);", "0\n"),
    ('LIB "a\nb";', "error: unknown library 'a"),                         # its message printed on one line
    ("3^99999999;", "// ** int overflow(^), result may be wrong\n1826112817018578603\n"),  # Singular's wrap
    ("ring r = 0, x, dp; (3x)^100000000;", "error: number too large"),
    ("}", "error: unexpected '}', expected an expression"),                # not "expected ';'"
    ('1;\n< "file";', "error: unexpected '<', expected an expression"),
]


@pytest.mark.parametrize("code, expected", REGRESSIONS, ids=[c for c, _ in REGRESSIONS])
def test_fuzz_regressions(code, expected):
    try:
        got = Session(timeout=TIMEOUT).execute(code, "<fuzz>")
    except MechError as e:
        assert format_problem(e, code, "<fuzz>") == ""
        got = "error: " + e.message
    assert got.startswith(expected) if expected.startswith("error") else got == expected


def test_error_format_checker_rejects_bad_reports():
    err = MechInternalError("internal error: KeyError: 'x'")
    assert format_problem(err, "x;", "<fuzz>").startswith("internal error")
    s = Session()
    try:
        s.execute("ring r = 0,(x),dp;\npoly f = x +* 2;", "<fuzz>")
    except MechError as e:
        assert format_problem(e, "ring r = 0,(x),dp;\npoly f = x +* 2;", "<fuzz>") == ""


# ---------------------------------------------------------------- bigger runs
def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description="Fuzz mech's front end (see the module docstring).")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--count", type=int, default=1000, help="runs of each kind (generated, mutated)")
    p.add_argument("--cli", type=int, default=0, help="also run this many mutated scripts through `mech`")
    p.add_argument("--show", type=int, default=5, help="failures to print")
    args = p.parse_args(argv)
    total = Stats()
    for kind in ("grammar", "mutation"):
        stats = campaign(args.seed, args.count, kind)
        print(f"{kind}: {_report(Stats(stats.runs, stats.ok, stats.errors, stats.limit_errors))} "
              f"({len(stats.failures)} failures, {stats.seconds:.0f} s)", flush=True)
        total.add(stats)
    if args.cli:
        import tempfile
        rng = random.Random(f"cli:{args.seed}")
        donors = [p.read_text() for p in CORPUS]
        with tempfile.TemporaryDirectory() as tmp:
            for _ in range(args.cli):
                text = mutate(rng, rng.choice(donors), donors)
                problem = check_cli(text, Path(tmp))
                total.runs += 1
                if problem:
                    total.failures.append((problem, text))
        print(f"cli: {args.cli} runs", flush=True)
    for problem, text in total.failures[:args.show]:
        print(f"--- {problem}\n{text[:3000]}\n")
    print(f"seed {args.seed}: {total.runs} inputs, {len(total.failures)} failures")
    return 1 if total.failures else 0


if __name__ == "__main__":
    sys.exit(main())
