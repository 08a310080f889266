"""The interpreter's speed: statements per second of mech and Singular on the same scripts, in one run.

    python benchmarks/interpreter.py                       # print the table
    python benchmarks/interpreter.py --write               # also rewrite benchmarks/INTERPRETER.md
    python benchmarks/interpreter.py --baseline PYTHONPATH # add a column: an older mech (a package tree
                                                           # at PYTHONPATH, e.g. an unpacked commit)

Each case is a script in Singular's language, run by both systems as a file (``mech FILE``,
``Singular -q FILE``) with output to /dev/null.  The loops time themselves: the script prints the
CPU milliseconds of its loop (``timer`` with ``system("--ticks-per-sec", 1000)``), read the same way
in both systems.  The flat scripts (long files of statements one after another, parsing included)
are timed from outside: the process's CPU time with ``N`` lines minus that with none.  Best of
``--repeat`` runs, the systems alternating; statements/s = statements run / that time.  Statements
run are counted as written: each executed statement (the loop's step ``i++`` included, the
statements of called procedures included; loop conditions not counted).
"""
from __future__ import annotations

import argparse
import os
import platform
import random
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
SINGULAR = shutil.which("Singular")
PYTHON = sys.executable

#: (name, script with the loop, statements per repetition, repetitions N)
LOOP_CASES = [
    ("`for` loop of int arithmetic in a proc",
     "proc f(int n) {{ int k, j; int i; for (i = 1; i <= n; i++) {{ k = k + i; j = k - 2*i; }} return(k); }}\n"
     "int r = f({n});\n", 3, 100000),
    ("`while` loop of int arithmetic",
     "int i, s; while (i < {n}) {{ s = s + i*i mod 7; i = i + 1; }}\n", 2, 100000),
    ("poly arithmetic in a loop (`q = p*x + 1` ...)",
     "ring r = 0, (x,y), dp; poly p = x+y; poly q; int i;\n"
     "for (i = 1; i <= {n}; i++) {{ q = p*x + 1; q = q*y - x; p = q - p*x*y + 2; }}\n", 4, 20000),
    ("ideal and list entries (`I[2] = I[1]*I[3]`, `L[2] = L[1] + i`)",
     "ring r = 0, (x,y), dp; ideal I = x, y, x+y; list L = 1, 2, 3; int i, k;\n"
     "for (i = 1; i <= {n}; i++) {{ I[2] = I[1]*I[3]; L[2] = L[1] + i; k = L[2] - L[3]; }}\n", 4, 30000),
    ("proc calls with arguments and a return value",
     "proc add(int a, int b) {{ return(a + b); }}\n"
     "int i, k, j; for (i = 1; i <= {n}; i++) {{ k = add(k, i); j = add(j, 1); }}\n", 5, 30000),
    ("string concatenation",
     "string s, t, u; int i;\n"
     "for (i = 1; i <= {n}; i++) {{ s = \"a\" + string(i); t = s + \",\"; u = t + s; }}\n", 4, 50000),
    ("`for (int i=1; i<=n; i++) { s = s + i; }` at the top level",
     "int s; for (int i = 1; i <= {n}; i++) {{ s = s + i; }}\n", 2, 100000),
    ("`if` ... `else` chains in a loop",
     "int k, i; for (i = 1; i <= {n}; i++) {{ if (i mod 3 == 0) {{ k = k + 1; }} else {{ if (i mod 3 == 1) "
     "{{ k = k + 2; }} else {{ k = k - 1; }} }} }}\n", 11 / 3, 30000),  # 2 or 3 statements, and the step
    ("list appends (`L[size(L)+1] = i`)",
     "list L; int i; for (i = 1; i <= {n}; i++) {{ L[size(L) + 1] = i; }}\n", 2, 10000),
    ("a recursive proc (`fib(20)`, 21,891 calls)",
     "proc fib(int n) {{ if (n < 2) {{ return(n); }} return(fib(n - 1) + fib(n - 2)); }}\n"
     "int r = fib({n});\n", 2 * 21891 / 20, 20),  # each call: its if and one return
    ("built-in commands in a loop (`k = size(L) + deg(p) + k`)",
     "ring r = 0, (x,y), dp; poly p = x2+y; list L = 1, 2, 3, 4, 5; int i, k;\n"
     "for (i = 1; i <= {n}; i++) {{ k = size(L) + deg(p) + k; }}\n", 2, 50000),
    ("ideal, intvec and matrix entries (`I[j] = ...`, `v[j] = i`, `M[j,1] = x*i`)",
     "ring r = 0, (x,y), dp; ideal I; intvec v; matrix M[3][3]; int i;\n"
     "for (i = 1; i <= {n}; i++) {{ I[i mod 10 + 1] = x^(i mod 5) + y; v[i mod 10 + 1] = i; "
     "M[i mod 3 + 1, 1] = x*i; }}\n", 4, 20000),
]
TIMED = 'system("--ticks-per-sec", 1000); int t_0 = timer;\n{body}int t_1 = timer; t_1 - t_0;\n'

#: flat scripts: a head, then lines drawn at random from these templates
PLAIN_LINES = ["k = k + {a};", "j = k * {b} - {a};", "m = j - k + {a};", "k = m mod 1000 + {b};", "b = k < j;"]
MIXED_LINES = ["k = k + {a};", "j = k * {b} - {a};", "f = {a}x2y-{b}/{c}z+y^{d};", "g = f*x + {a};",
               "f = f - g*{b};", "I = f, x*y-z, {a};", "M[1,2] = f*x;", "n = n*{b}/{c};", "s = string(f);",
               "s = string(k, \",\", n);", "if (k > {a}) {{ j = {b}; }} else {{ j = j + 1; }}",
               "for (i = 1; i <= 2; i++) {{ j = j + i; }}", "f;", "k;"]
MIXED_COUNTS = {"if": 2, "for": 7}  # statements a line runs: if + one branch; for: init, 2 x (body + step)
FLAT_HEAD = ("int k, i, j, m, b; string s; ring r = 0,(x,y,z),dp; poly f, g; ideal I; matrix M[2][2]; "
             "number n = 1;\n")
#: (title, line templates, largest literal): small literals repeat lines (a repeated line shares the
#: tree and the closure of its first), large ones make every line new (parsed and run cold)
FLAT_CASES = [("long flat script of plain int statements", PLAIN_LINES, 99),
              ("long flat script of plain int statements, literals up to 10^6 (few lines repeat)", PLAIN_LINES, 10**6),
              ("long flat script of mixed statements", MIXED_LINES, 99)]

#: lines of the flat scripts per system (Singular's larger: its start-up's noise is the same)
FLAT_SIZES = {"mech": 40000, "base": 40000, "Singular": 400000}


def flat_script(lines: list[str], n: int, top: int = 99) -> tuple[str, int]:
    """A flat script of ``n`` lines (fixed random choice, literals up to ``top``); the text and its
    statement count."""
    rng = random.Random(n)
    out, count = [FLAT_HEAD], 0
    for _ in range(n):
        line = rng.choice(lines)
        out.append(line.format(a=rng.randint(1, top), b=rng.randint(1, 9 if top == 99 else top),
                               c=rng.randint(2, 9),
                               d=rng.randint(1, 5)) + "\n")
        count += MIXED_COUNTS.get(line.split(" ")[0], 1)
    return "".join(out), count


def run(cmd: list[str], path: Path, env: dict) -> tuple[float, str]:
    """CPU seconds (user + system) of running ``cmd`` on the script ``path``, and its output."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    proc = subprocess.run(cmd + [str(path)], stdin=subprocess.DEVNULL, capture_output=True, env=env, text=True,
                          cwd=path.parent)  # not the repository: ``python -m mech`` would find its mech/ there
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode or proc.stderr or "   ? " in proc.stdout:  # Singular reports its errors on stdout
        raise RuntimeError(f"{cmd[0]} failed on {path}: {(proc.stderr or proc.stdout)[-400:]}")
    return after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime, proc.stdout


def systems(baseline: str | None) -> dict[str, tuple[list[str], dict]]:
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    out = {"mech": ([PYTHON, "-m", "mech", "--no-warn"], env)}
    if baseline:
        out["base"] = ([PYTHON, "-m", "mech", "--no-warn"], dict(env, PYTHONPATH=baseline))
    if SINGULAR:
        out["Singular"] = ([SINGULAR, "-q", "--no-warn"], env)
    return out


def _script(tmp: Path, name: str, text: str) -> Path:
    path = tmp / f"{name}.sing"
    path.write_text(text + ("\nquit;\n" if name == "Singular" else "\n"))
    return path


def loop_rates(which: dict, repeat: int, tmp: Path) -> list[tuple[str, dict[str, float]]]:
    """Statements/s of the loops: statements over the CPU time the script prints."""
    out = []
    for title, body, per, n in LOOP_CASES:
        rates: dict[str, float] = {}
        for _ in range(repeat):  # systems alternate, so a change of the machine's load touches all
            for name, (cmd, env) in which.items():
                _, stdout = run(cmd, _script(tmp, name, TIMED.format(body=body.format(n=n))), env)
                ms = int(stdout.split()[-1])
                rates[name] = max(rates.get(name, 0.0), per * n / max(ms / 1000, 1e-3))
        out.append((title, rates))
        print(title, {k: round(v) for k, v in rates.items()}, file=sys.stderr, flush=True)
    return out


def flat_rates(which: dict, repeat: int, tmp: Path) -> list[tuple[str, dict[str, float]]]:
    """Statements/s of the flat scripts: (time with N lines - time with none) over their statements."""
    out = []
    for title, lines, top in FLAT_CASES:
        rates: dict[str, float] = {}
        for _ in range(repeat):
            for name, (cmd, env) in which.items():
                text, count = flat_script(lines, FLAT_SIZES[name], top)
                full, _ = run(cmd, _script(tmp, name, text), env)
                empty, _ = run(cmd, _script(tmp, name, FLAT_HEAD), env)
                rates[name] = max(rates.get(name, 0.0), count / max(full - empty, 1e-3))
        out.append((title, rates))
        print(title, {k: round(v) for k, v in rates.items()}, file=sys.stderr, flush=True)
    return out


def rows(which: dict, repeat: int, only: str = "") -> list[tuple[str, dict[str, float]]]:
    with tempfile.TemporaryDirectory() as tmp:
        return ((loop_rates(which, repeat, Path(tmp)) if only != "flat" else [])
                + (flat_rates(which, repeat, Path(tmp)) if only != "loops" else []))


def fmt(rate: float | None) -> str:
    if rate is None:
        return "—"
    return f"{rate / 1e6:.2f} M" if rate >= 1e6 else f"{rate / 1e3:.1f} k" if rate >= 1e3 else f"{rate:.0f}"


def table(results: list[tuple[str, dict[str, float]]], baseline: str | None) -> list[str]:
    head = "| case | mech | Singular | Singular / mech |"
    rule = "|---|---|---|---|"
    if baseline:
        head += " mech at the baseline | speed-up |"
        rule += "---|---|"
    lines = [head, rule]
    for name, r in results:
        m, s, b = r.get("mech"), r.get("Singular"), r.get("base")
        row = f"| {name} | {fmt(m)} | {fmt(s)} | {s / m:.{0 if s >= 10 * m else 1}f}× |" if s else f"| {name} | {fmt(m)} | — | — |"
        if baseline:
            row += f" {fmt(b)} | {m / b:.1f}× |"
        lines.append(row)
    return lines


NOTES = """
What bounds each row: loops and procedure bodies run closures made once per statement
(`dsl/compiled.py`), so their cost is the Python calls of the statement itself (name lookup, the
operation, the assignment) and, for polynomials, the kernel's arithmetic. The flat scripts pay per
statement the parsing (the fast parser, or the tree shared with an earlier identical line) and the
top-level statement's frame (limits, engine, error positions); a line that runs once is not
compiled (compiling would cost more than it saves), so those rows move least.
"""


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--write", action="store_true", help="rewrite benchmarks/INTERPRETER.md")
    ap.add_argument("--baseline", help="PYTHONPATH of an older mech package tree, for a speed-up column")
    ap.add_argument("--label", default="", help="what the baseline is (for the table's text)")
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--only", choices=["loops", "flat"], default="", help="only these cases (not with --write)")
    args = ap.parse_args()
    if args.only and args.write:
        ap.error("--write needs all the cases")
    which = systems(args.baseline)
    load = os.getloadavg()
    t0 = time.time()
    results = rows(which, args.repeat, args.only)
    lines = table(results, args.baseline)
    print("\n".join(lines))
    if args.write:
        sing = subprocess.run([SINGULAR, "-v", "-q", "--no-warn"], input="quit;", capture_output=True,
                              text=True).stdout.splitlines()[0].strip("/ ") if SINGULAR else "absent"
        text = [
            "# Benchmarks: the interpreter",
            "",
            "Produced by `python benchmarks/interpreter.py --write"
            + (" --baseline ...`" if args.baseline else "`") + ": statements per second, mech and Singular "
            "on the same scripts in one run (see the script's docstring for how statements are counted "
            f"and timed: CPU time, best of {args.repeat}).",
            "",
            f"- date: {time.strftime('%Y-%m-%d %H:%M')}, {time.time() - t0:.0f} s",
            f"- CPU: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, shared: load average "
            f"{load[0]:.1f} {load[1]:.1f} {load[2]:.1f} at the start",
            f"- Python {platform.python_version()}; Singular: {sing}",
        ]
        if args.baseline:
            text.append(f"- baseline: {args.label or args.baseline}")
        (HERE / "INTERPRETER.md").write_text("\n".join(text + [""] + lines) + "\n" + NOTES)


if __name__ == "__main__":
    main()
