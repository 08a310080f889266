"""Long scripts of ordinary statements: statements per second parsed and run, at several sizes
(the time must grow linearly with the size; issue 23's 50 MB script).

    python benchmarks/bigscript.py              # 1, 4 and 16 MB
    python benchmarks/bigscript.py 50           # one size in MB

Each script repeats a mix of declarations, assignments, arithmetic, ideals, an ``if`` and a ``for``
with changing numbers; it runs in one process (``mech FILE``), output to /dev/null; the table shows
the process's CPU time (start-up included) and the statements per second.
"""
from __future__ import annotations

import random
import resource
import subprocess
import sys
import tempfile
from pathlib import Path

LINES = ["k = k + {a};", "f = {a}x2y-{b}/{c}z+y^{d};", "I = f, x*y-z, {a};", "M[1,2] = f*x;",
         "if (k > {a}) {{ j = {b}; }} else {{ j = j + 1; }}", "s = \"{a}{b}\";", "n = n*{b}/{c};",
         "for (i = 1; i <= 2; i++) {{ j = j + i; }}", "f;"]


def script(megabytes: float, path: Path) -> int:
    """Write a script of about ``megabytes`` MB; its number of statements."""
    rng = random.Random(megabytes)
    head = "ring r = 0,(x,y,z),dp; poly f; ideal I; int k, i, j; number n = 1; string s; matrix M[2][2];\n"
    size, count = len(head), 7
    with path.open("w") as fh:
        fh.write(head)
        while size < megabytes * 2**20:
            line = rng.choice(LINES).format(a=rng.randint(1, 99), b=rng.randint(1, 9), c=rng.randint(2, 9),
                                            d=rng.randint(1, 5)) + "\n"
            fh.write(line)
            size += len(line)
            count += 1
    return count


def main() -> None:
    sizes = [float(a) for a in sys.argv[1:]] or [1, 4, 16]
    print("| script | statements | CPU time | statements/s |\n|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for mb in sizes:
            path = Path(tmp) / f"big{mb:g}.mech"
            n = script(mb, path)
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            subprocess.run([sys.executable, "-m", "mech", "--no-warn", str(path)], stdout=subprocess.DEVNULL,
                           check=True)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
            print(f"| {mb:g} MB | {n} | {cpu:.1f} s | {n / cpu:.0f} |")


if __name__ == "__main__":
    main()
