"""Long scripts of ordinary statements: time per MB and statements per second, parsed and run, at
several sizes (the time must grow linearly with the size; issue 23's 50 MB script).

    python benchmarks/bigscript.py                     # 1, 5, 10 and 50 MB
    python benchmarks/bigscript.py 1 5                 # these sizes (MB)
    python benchmarks/bigscript.py --write [--names] FILE 50   # only write a 50 MB script to FILE
    python benchmarks/bigscript.py --loop              # statements/s of a loop (running only)
    python benchmarks/bigscript.py --names 1 10        # every statement with new names (new shapes)

Each script repeats a mix of assignments of ints, numbers and polynomials, arithmetic, ideals,
matrix entries, strings printed into a variable (``s = string(f);``), printed values, an ``if`` and
a ``for``, with changing numbers, and declares its ring again every 500 statements; it runs in one
process (``mech FILE``), output to /dev/null; the table shows the process's CPU time (start-up
included), seconds per MB, statements per second and the process's peak memory (resident), and
the same for Singular on the same script (``Singular -q FILE``, a ``quit;`` appended) when installed.
"""
from __future__ import annotations

import os
import random
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Optional

RING = "ring r = 0,(x,y,z),dp; poly f, g; ideal I; matrix M[2][2]; number n = 1;\n"
HEAD = "int k, i, j; string s;\n" + RING
LINES = ["k = k + {a};", "j = k * {b} - {a};", "f = {a}x2y-{b}/{c}z+y^{d};", "g = f*x + {a};",
         "f = f - g*{b};", "I = f, x*y-z, {a};", "M[1,2] = f*x;", "n = n*{b}/{c};", "s = string(f);",
         "s = string(k, \",\", n);", "if (k > {a}) {{ j = {b}; }} else {{ j = j + 1; }}",
         "for (i = 1; i <= 2; i++) {{ j = j + i; }}", "f;", "k;"]
RING_EVERY = 500  # statements between two ring declarations
#: ``--names``: each line declares a new variable (``{n}``) from an earlier one (``{m}``): every
#: statement a new shape, parsed cold (no template applies)
NAMED_LINES = ["int k{n} = k{m} mod 1000 * {b} + {a};", "poly f{n} = {a}x2y-{b}/{c}z+y^{d};",
               "int j{n} = k{m} - {a};", "k{m};", "string s{n} = string(k{m}) + \"{a}\";"]


def script(megabytes: float, path: Path, names: bool = False) -> int:
    """Write a script of about ``megabytes`` MB (``names``: of :data:`NAMED_LINES`); its number of
    statements."""
    rng = random.Random(megabytes)
    size, count, ints = len(HEAD), 9, [0]  # ints: the k{n} declared (--names)
    with path.open("w") as fh:
        fh.write(HEAD + ("int k0 = 1;\n" if names else ""))
        while size < megabytes * 2**20:
            if count % RING_EVERY == 0 and not names:
                line = RING
                count += 6
            else:
                form = rng.choice(NAMED_LINES if names else LINES)
                line = form.format(a=rng.randint(1, 99), b=rng.randint(1, 9), c=rng.randint(2, 9),
                                   d=rng.randint(1, 5), n=count, m=rng.choice(ints[-8:])) + "\n"
                if form.startswith("int k"):
                    ints.append(count)
                count += 1
            fh.write(line)
            size += len(line)
    return count


def run(path: Path, cmd: Optional[list[str]] = None) -> tuple[float, float]:
    """CPU seconds and peak memory (MB) of ``mech FILE`` or ``cmd FILE`` (output dropped)."""
    cmd = cmd or [sys.executable, "-m", "mech", "--no-warn"]
    proc = subprocess.Popen([*cmd, str(path)], stdout=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode:
        raise SystemExit(f"{cmd[0]} {path} failed ({proc.returncode})")
    return usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024


def run_singular(path: Path) -> Optional[tuple[float, float]]:
    """``run`` for Singular on a copy of the script ending in ``quit;``; None without Singular."""
    singular = shutil.which("Singular")
    if singular is None:
        return None
    copy = path.with_suffix(".sing")
    shutil.copyfile(path, copy)
    with copy.open("a") as fh:
        fh.write("quit;\n")
    try:
        return run(copy, [singular, "-q", "--no-warn"])
    finally:
        copy.unlink()


def loop(count: int = 200000) -> None:
    """Statements per second of a loop of simple statements (parsed once, run ``count`` times)."""
    from mech import Session
    s = Session()
    s.execute("int k, j; int i;")
    t = time.process_time()
    s.execute(f"for (i = 1; i <= {count}; i++) {{ k = k + i; j = k - 2*i; }}")
    cpu = time.process_time() - t
    print(f"loop: {3 * count} statements in {cpu:.2f} s CPU: {3 * count / cpu:.0f} statements/s")


def main() -> None:
    args = sys.argv[1:]
    if args[:1] == ["--write"]:
        names = args[1:2] == ["--names"]
        print(script(float(args[2 + names]), Path(args[1 + names]), names), "statements")
        return
    if args[:1] == ["--loop"]:
        loop()
        return
    names = args[:1] == ["--names"]
    sizes = [float(a) for a in args[names:]] or [1, 5, 10, 50]
    print("| script | statements | CPU time | s/MB | statements/s | peak memory | Singular: CPU time | "
          "statements/s | peak memory | mech / Singular |\n|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for mb in sizes:
            path = Path(tmp) / f"big{mb:g}.mech"
            n = script(mb, path, names)
            cpu, peak = run(path)
            sing = run_singular(path)
            other = (f"{sing[0]:.1f} s | {n / sing[0]:.0f} | {sing[1]:.0f} MB | {cpu / sing[0]:.1f}" if sing
                     else "— | — | — | —")
            print(f"| {mb:g} MB | {n} | {cpu:.1f} s | {cpu / mb:.2f} | {n / cpu:.0f} | {peak:.0f} MB | {other} |",
                  flush=True)


if __name__ == "__main__":
    main()
