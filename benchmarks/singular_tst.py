"""mech on Singular's own tests: the conformance run.

    python benchmarks/singular_tst.py --src /path/to/Singular-src             # every in-scope case
    python benchmarks/singular_tst.py --src SRC --only 'Short/bug_*' --timeout 30 --jobs 2
    python benchmarks/singular_tst.py --src SRC --list                         # the selection only
    python benchmarks/singular_tst.py --src SRC --write                        # rewrite SINGULAR_TST.md
    python benchmarks/singular_tst.py --src SRC --results R.jsonl              # also keep mech's outputs
    python benchmarks/singular_tst.py --src SRC --rejudge R.jsonl --show --only bug_5   # judge them again

SRC is a checkout of Singular's sources (the test files stay there, never in this repository).  The
cases are the test scripts of Tst/Short, Tst/Buch, Tst/Old and Tst/Manual with the tst.lib harness
stripped, and the example sections of the in-scope libraries (``tst_source.py``: the selection rule).
Each runs in the installed Singular (the expected output: a live run, cached by script) and in mech
(``python -m mech --no-warn``); ``tst_compare.py`` compares the outputs as text, else as values.

Categories: agree; differ (another value than Singular's, or going on where Singular reports an error);
unsupported (mech says it lacks a command, type, library, identifier, overload or syntax: the first such
construct is the case's blocking feature); error (another error of mech's); crash (an internal error, a
traceback, a signal); timeout (over the time or memory limit).  Cases where Singular itself fails (an
error the recorded result does not have: a test newer than the installed Singular), warns of an overflow
or runs out of time are set aside, as are the cases outside mech's scope.
"""
from __future__ import annotations

import argparse
import datetime
import fnmatch
import hashlib
import json
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, replace
from pathlib import Path
from typing import Optional

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from tst_checks import CHECKS, edit, judge_checked  # noqa: E402
from tst_compare import Oracle, check_script, compare, normalize, parse, read_answers, split_error  # noqa: E402
from tst_report import Result, report  # noqa: E402
from tst_source import Case, collect, instrument  # noqa: E402

MEMORY_MB = 3000  # each process's limit


# ---------------------------------------------------------------- running the systems
def _limit_memory() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_MB << 20, MEMORY_MB << 20))


def run(cmd: list[str], script: str, filename: str, timeout: float) -> tuple[str, str, Optional[int], float]:
    """(stdout, stderr, exit status or None on timeout, wall seconds) of ``cmd FILE`` in a scratch
    directory, FILE holding ``script``."""
    with tempfile.TemporaryDirectory(prefix="tst-") as tmp:
        path = Path(tmp) / filename
        path.write_text(script)
        t0 = time.perf_counter()
        try:
            res = subprocess.run(cmd + [str(path)], cwd=tmp, capture_output=True, timeout=timeout,
                                 stdin=subprocess.DEVNULL, preexec_fn=_limit_memory)
        except subprocess.TimeoutExpired as e:
            return _text(e.stdout), _text(e.stderr), None, time.perf_counter() - t0
        return _text(res.stdout), _text(res.stderr), res.returncode, time.perf_counter() - t0


def _text(data: Optional[bytes]) -> str:
    return (data or b"").decode("utf-8", "replace")


class Singular:
    """The installed Singular, its outputs cached by script."""

    def __init__(self, exe: str, cache: Path, timeout: float) -> None:
        self.cmd = [exe, "-q", "--no-rc"]  # with warnings: an overflow warning disqualifies the output
        self.version = subprocess.run([exe, "--version"], capture_output=True, text=True).stdout.splitlines()[0]
        self.cache, self.timeout = cache, timeout
        cache.mkdir(parents=True, exist_ok=True)

    def output(self, script: str) -> Optional[str]:
        """Singular's output of a script, None when it runs out of time."""
        key = hashlib.sha256(f"{self.cmd}\n{self.version}\n{self.timeout}\n{script}".encode()).hexdigest()
        path = self.cache / f"{key}.json"
        if path.exists():
            return json.loads(path.read_text())["out"]
        out, _, status, _ = run(self.cmd, script, "case.sing", self.timeout)
        out = None if status is None else out
        path.write_text(json.dumps({"out": out}))
        return out

    def answer(self, questions: list) -> dict:
        out, _, _, _ = run(self.cmd, check_script(questions), "check.sing", 4 * self.timeout)
        return read_answers(questions, out)

    def check(self, script: str) -> str:
        """Singular's output of a check script (``tst_checks``)."""
        return run(self.cmd, script, "check.sing", 4 * self.timeout)[0]


# ---------------------------------------------------------------- classifying one case
_ERROR_LINE = re.compile(r"error occurred in or before \S+ line (\d+)")
_ERROR = re.compile(r"^\s*\? ")
_LIMIT = re.compile(r"(?:time|memory) limit of .* exceeded|out of memory")
_UNSUPPORTED = [
    (re.compile(r"unknown command '([^']+)' \(it is in (\S+):"), "command {0} (mech has it in {1}; not loaded)"),
    (re.compile(r"unknown command '([^']+)'"), "command {0}"),
    (re.compile(r"^(\w+) is not provided"), "command {0}"),
    (re.compile(r"type '([^']+)' is not supported"), "type {0}"),
    (re.compile(r"^type conversion (\S+) is not supported"), "conversion {0}"),
    (re.compile(r"unknown library '([^']+)'"), "library {0}"),
    (re.compile(r"unknown identifier '([^']+)' in (\w+)\(\.\.\.\)"), "identifier {0} in {1}(...)"),
    (re.compile(r"unknown identifier '([^']+)'"), "identifier {0}"),
    (re.compile(r"'([^']+)' is not declared"), "identifier {0}"),
    (re.compile(r"unknown ordering '([^']+)'"), "ordering {0}"),
    (re.compile(r"unknown option '([^']+)'"), "option {0}"),
    (re.compile(r"^wrong arguments for (\w+): got \(([^)]*)\)"), "arguments {0}({1})"),
    (re.compile(r"^wrong number of arguments for (\w+): got (\d+)"), "arguments {0} with {1} arguments"),
    (re.compile(r"^(unexpected .*|expected .*)$"), "syntax: {0}"),
    (re.compile(r"^operator (\S+) is not defined for (.+)$"), "operator {0} for {1}"),
    (re.compile(r"^(\w+) needs a global ordering"), "{0} in a local ordering"),
    (re.compile(r"^(\w+) is not available over the coefficient field (\S+)"), "{0} over coefficient field {1}"),
    (re.compile(r"^(.*\bnot (?:supported|implemented|available)\b.*)$"), "{0}"),
]


#: Singular's system variables: an unknown one is the missing feature itself, wherever it is used.
_SYSTEM_VARIABLES = {"minpoly", "short", "echo", "printlevel", "noether", "TRACE", "degBound", "multBound",
                     "voice", "pagewidth", "pagelength", "timer", "rtimer"}


def _enclosing_call(line: str, col: int) -> Optional[str]:
    """The name of the call whose parentheses hold column ``col`` (1-based) of ``line``."""
    depth = 0
    for k in range(min(col, len(line) + 1) - 2, -1, -1):
        if line[k] == ")":
            depth += 1
        elif line[k] == "(":
            if depth == 0:
                m = re.search(r"(\w+)\s*$", line[:k])
                return m.group(1) if m else None
            depth -= 1
    return None


def _error_lines(text: str) -> set[int]:
    return {int(n) for n in _ERROR_LINE.findall(text)}


def singular_side(case: Case, singular: Singular) -> tuple[Optional[Result], str, Optional[str]]:
    """(a set-aside result or None, Singular's output up to its first error, that error)."""
    s_out = singular.output(instrument(case.script))
    if s_out is None:
        return Result(case.name, "set aside", "Singular runs out of time"), "", None
    s_text, s_error = split_error(s_out)
    overflow = next((ln for ln in s_text.splitlines() if ln.startswith("// **") and "OVERFLOW" in ln), None)
    if overflow:
        return Result(case.name, "set aside", "Singular warns of an overflow", overflow[6:]), s_text, s_error
    if s_error is not None:  # intended when the recorded result has the same error
        ref = case.reference or ""
        messages = {ln.strip()[2:] for ln in ref.splitlines() if _ERROR.match(ln)}
        if s_error not in messages and not _error_lines(s_out[len(s_text):]) & _error_lines(ref):
            return Result(case.name, "set aside", "fails in the installed Singular", s_error), s_text, s_error
    return None, s_text, s_error


def run_mech(case: Case, mech_cmd: list[str], timeout: float) -> dict:
    """mech's run of a case: stdout, stderr, exit status (None: killed at 3x the timeout), seconds."""
    filename = case.name.split("/")[-1].replace(":", "-")
    cmd = mech_cmd + ["--no-warn", "--timeout", f"{timeout:g}", "--max-memory", str(MEMORY_MB // 2)]
    out, err, status, secs = run(cmd, case.script, filename, 3 * timeout)
    return {"out": out, "err": err, "status": status, "seconds": round(secs, 2)}


def judge(name: str, s_text: str, s_error: Optional[str], mech: dict, answer) -> Result:
    """The category of a case from both outputs; ``answer`` settles algebraic questions."""
    out, err, status = mech["out"], mech["err"], mech["status"]
    first = next((ln for ln in err.splitlines() if ": error: " in ln or ln.startswith("Traceback")), "")
    message = first.split(": error: ", 1)[-1].strip()
    source = err.splitlines()[1] if first and len(err.splitlines()) > 1 else ""
    col = re.match(r".*?:\d+:(\d+): error: ", first)
    if col and re.match(r"type '(\w+)' is not supported", message):  # a declaration or a conversion?
        typ = message.split("'")[1]
        if source[int(col.group(1)) - 1:].startswith(typ + "("):
            message = f"type conversion {typ}(...) is not supported"
    ident = re.match(r"unknown identifier '(\w+)'", message)
    if col and ident and ident.group(1) not in _SYSTEM_VARIABLES:  # an argument of which command?
        call = _enclosing_call(source, int(col.group(1)))
        if call:
            message = f"unknown identifier '{ident.group(1)}' in {call}(...)"
    source = source.strip()
    r = _judge(name, s_text, s_error, out, err, status, message, source, Oracle(answer))
    r.seconds = mech.get("seconds", 0.0)
    return r


def _judge(name: str, s_text: str, s_error: Optional[str], out: str, err: str, status: Optional[int],
           message: str, source: str, oracle: Oracle) -> Result:
    if status is None or _LIMIT.match(message):
        return Result(name, "timeout", message or "process time limit", source)
    if status not in (0, 1) or "Traceback" in err or message.startswith("internal error"):
        return Result(name, "crash", message or f"exit status {status}", source or err[-300:])
    if status == 0 and s_error is None and normalize(out) == normalize(s_text):
        return Result(name, "agree", "text" if normalize(out) else "both print nothing")
    S, M = parse(s_text), parse(out)
    accepts = "accepts"  # Singular reports an error, mech goes on
    if status == 0:
        why = compare(S, M, oracle)
        if s_error is None:
            return Result(name, "differ", "value", why) if why else Result(name, "agree", "values")
        if compare(S, M[:len(S)], oracle) is None:
            return Result(name, "differ", accepts, f"Singular reports an error (`{s_error}`), mech does not")
        return Result(name, "differ", "value", why)
    why = compare(S[:len(M)], M, oracle)
    if why:
        if s_error is not None and len(M) > len(S) and compare(S, M[:len(S)], oracle) is None:
            return Result(name, "differ", accepts,
                          f"Singular reports an error (`{s_error}`) where mech prints `{M[len(S)].show()}`")
        return Result(name, "differ", "value", why)
    key = _unsupported(message)
    if s_error is not None and len(S) == len(M) and not _missing(key):
        return Result(name, "agree", "both report an error", f"Singular: {s_error}; mech: {message}")
    return Result(name, "unsupported", key, source) if key else Result(name, "error", message, source)


def _unsupported(message: str) -> Optional[str]:
    """The construct an error of mech's says it lacks (None: another error)."""
    for rx, fmt in _UNSUPPORTED:
        m = rx.search(message)
        if m:
            key = fmt.format(*m.groups())  # a field up to the names of its parameters: GF(7)(...)
            return re.sub(r"\((?=[A-Za-z])[^()]*\)", "(...)", key) if "field" in fmt else key
    return None


def _missing(key: Optional[str]) -> bool:
    """Whether an unsupported construct is a feature mech lacks, not a rejection of the input that
    Singular may share (a syntax error, an undefined name, arguments of the wrong types)."""
    if key is None or key.startswith(("syntax:", "arguments ")):
        return False
    return not key.startswith("identifier ") or key.split()[1] in _SYSTEM_VARIABLES


def _commit(path: Path) -> str:
    res = subprocess.run(["git", "-C", str(path), "rev-parse", "HEAD"], capture_output=True, text=True)
    if res.returncode == 0:
        return res.stdout.strip()
    marker = path / "SOURCE_COMMIT"
    return marker.read_text().strip() if marker.exists() else "unknown"


# ---------------------------------------------------------------- main
def main(argv: Optional[list[str]] = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--src", type=Path, required=True, help="a checkout of Singular's sources")
    p.add_argument("--only", action="append", metavar="PATTERN",
                   help="cases whose name (Short/bug_1.tst, LIB/primdec.lib:primdecGTZ) matches the glob or "
                        "contains the text; repeatable")
    p.add_argument("--timeout", type=float, default=30, help="seconds per statement (3x per script)")
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--list", action="store_true", help="print the selection with the exclusion reasons")
    p.add_argument("--show", action="store_true", help="print both outputs of each case")
    p.add_argument("--write", action="store_true", help="rewrite benchmarks/SINGULAR_TST.md")
    p.add_argument("--results", type=Path, help="write each case's result and mech's raw output as JSON lines")
    p.add_argument("--rejudge", type=Path, metavar="RESULTS",
                   help="judge mech's outputs stored by an earlier --results run again instead of running mech")
    p.add_argument("--singular", default=shutil.which("Singular"), help="the Singular executable")
    p.add_argument("--mech", default=f"{sys.executable} -m mech", help="the mech command")
    p.add_argument("--cache", type=Path, default=Path(os.environ.get("XDG_CACHE_HOME", Path.home() / ".cache"))
                   / "mech-singular-tst", help="where Singular's outputs are cached")
    args = p.parse_args(argv)
    cases = [c for c in collect(args.src) if _selected(c.name, args.only)]
    if args.list:
        for c in cases:
            print(f"{c.name}\t{c.excluded or 'in scope'}")
        return 0
    if not args.singular:
        p.error("Singular is not installed (--singular PATH)")
    singular = Singular(args.singular, args.cache, 3 * args.timeout)
    stored = {}
    if args.rejudge:
        stored = {d["name"]: d["mech"] for d in map(json.loads, args.rejudge.read_text().splitlines()) if d.get("mech")}
    todo = [c for c in cases if c.excluded is None]
    excluded = [c for c in cases if c.excluded is not None]
    t0 = time.perf_counter()
    if args.results:
        args.results.write_text("")  # filled case by case, so that a run stopped early keeps what it did
    runs = _run_all(todo, singular, args.mech.split(), args.timeout, args.jobs, stored, args.show, args.results)
    minutes = (time.perf_counter() - t0) / 60
    if args.results:
        args.results.write_text("".join(json.dumps({**asdict(r), "mech": raw}) + "\n" for r, raw in runs))
    meta = {"date": datetime.date.today().isoformat(), "minutes": minutes, "jobs": args.jobs,
            "timeout": args.timeout, "singular": singular.version, "src_commit": _commit(args.src),
            "mech_commit": _commit(HERE.parent),
            "command": "python benchmarks/singular_tst.py --src SRC" +
                       "".join(f" --only '{o}'" for o in args.only or ()) +
                       f" --timeout {args.timeout:g} --jobs {args.jobs} --write"}
    text = report([r for r, _ in runs], excluded, meta)
    if args.write:
        (HERE / "SINGULAR_TST.md").write_text(text)
    if not args.show:
        print(text)
    return 0


def _selected(name: str, patterns: Optional[list[str]]) -> bool:
    return not patterns or any(fnmatch.fnmatch(name, p) if any(ch in p for ch in "*?[") else p in name
                               for p in patterns)


def _run_all(cases: list[Case], singular: Singular, mech_cmd: list[str], timeout: float, jobs: int,
             stored: dict, show: bool, results: Optional[Path] = None) -> list[tuple[Result, Optional[dict]]]:
    """Each case's result and mech's raw run (None when mech did not run), in the order of ``cases``;
    each appended to ``results`` (JSON lines) as it finishes."""
    done = 0
    lock = threading.Lock()

    def one(case: Case) -> tuple[Result, Optional[dict]]:
        nonlocal done
        raw, s_text, s_error = None, "", None
        check = CHECKS.get(case.name)
        try:
            script = edit(case.script, check) if check else case.script
            if script is None:
                raise ValueError("the script lacks a text its check edits (tst_checks.py)")
            case = replace(case, script=script)
            aside, s_text, s_error = singular_side(case, singular)
            if aside is None:
                raw = stored.get(case.name) or run_mech(case, mech_cmd, timeout)
                if check:
                    r = judge_checked(check, s_text, raw["out"], singular.check, lambda s, m: judge(
                        case.name, s, s_error, {**raw, "out": m}, singular.answer))
                else:
                    r = judge(case.name, s_text, s_error, raw, singular.answer)
            else:
                r = aside
        except Exception as e:  # the runner's own failure on one case must not end the run
            r = Result(case.name, "set aside", f"runner failure: {type(e).__name__}: {e}")
        with lock:
            done += 1
            if results:
                with results.open("a") as f:
                    f.write(json.dumps({**asdict(r), "mech": raw}) + "\n")
        print(f"[{done}/{len(cases)}] {case.name}: {r.category} {r.key} ({r.seconds:.1f} s)", file=sys.stderr,
              flush=True)
        if show:
            mech = f"(exit {raw['status']})\n{raw['out']}{raw['err']}" if raw else "(not run)\n"
            print(f"==== {case.name}\n---- Singular{' (error: ' + s_error + ')' if s_error else ''}\n"
                  f"{normalize(s_text)}\n---- mech {mech}---- {r.category}: {r.key} {r.detail}\n", flush=True)
        return r, raw
    with ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        return list(pool.map(one, cases))


if __name__ == "__main__":
    sys.exit(main())
