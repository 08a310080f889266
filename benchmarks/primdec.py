"""Primary decomposition benchmarks: the paper's decompositions in mech and in Singular.

    python benchmarks/primdec.py              # every case, table on stdout
    python benchmarks/primdec.py --repeat 5

Both systems run the same setup script (the paper's ideals, ../shared/reference/paper) and then
time one command, the mean CPU time of ``--repeat`` runs.  mech: ``Session.execute`` of the
command in this process (a fresh session and an empty Gröbner cache each run).  Singular: ``timer``
(1 ms ticks) around ``--repeat`` runs in one process, start-up and ``LIB "primdec.lib";``
excluded.
"""
from __future__ import annotations

import argparse
import re
import shutil
import subprocess
import time
from typing import NamedTuple

SINGULAR = shutil.which("Singular")


class Case(NamedTuple):
    name: str
    setup: str
    command: str


def _fitting(ring: str, eqs: str, rows: int, angles: str) -> str:
    cols = len(angles.split(","))
    return (f"{ring}\nideal J = {eqs};\nmatrix D[{rows}][{cols}]; int i; int j; list v = {angles};\n"
            f"for (i=1; i<={rows}; i++) {{ for (j=1; j<={cols}; j++) {{ D[i,j] = diff(J[i], v[j]); }} }}\n"
            f"ideal F = minor(D,{rows});\n")


CASES = [
    Case("slider2: minAssGTZ(Fitting ideal), 6 primes",
         _fitting("ring r = 0, (c1,s1,c2,s2,l1,l2), (dp(4),dp(2));",
                  "l1*s1+l2*s2, c1^2+s1^2-1, c2^2+s2^2-1", 3, "c1,s1,c2,s2"), "list L = minAssGTZ(F);"),
    Case("slider3: minAssGTZ(Fitting ideal), 11 primes",
         _fitting("ring r = 0, (c1,s1,c2,s2,c3,s3,l1,l2,l3), (dp(6),dp(3));",
                  "l1*s1+l2*s2+l3*s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1", 4, "c1,s1,c2,s2,c3,s3"),
         "list L = minAssGTZ(F);"),
    Case("fourbar: minAssGTZ(Fitting ideal), 10 primes",
         _fitting("ring r = 0, (c1,s1,c2,s2,c3,s3,l1,l2,l3), (dp(6),dp(3));",
                  "l1*c1+l2*c2+l3*c3-1, l1*s1+l2*s2+l3*s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1", 5,
                  "c1,s1,c2,s2,c3,s3"), "list L = minAssGTZ(F);"),
    Case("fourbar l=1: primdecGTZ(J), 3 motion modes",
         "ring r1 = 0, (c1,s1,c2,s2,c3,s3), dp;\n"
         "ideal J = c1+c2+c3-1, s1+s2+s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1;\n", "list L = primdecGTZ(J);"),
]


def time_mech(case: Case, repeat: int) -> tuple[float, int]:
    """Mean CPU time of the command and the number of components."""
    from mech import Session
    from mech.kernel.engines import clear_cache
    total, size = 0.0, 0
    for _ in range(repeat):
        clear_cache()
        s = Session()
        s.execute('LIB "primdec.lib";\n' + case.setup)
        t0 = time.process_time()
        s.execute(case.command)
        total += time.process_time() - t0
        size = int(s.execute("size(L);"))
    return total / repeat, size


def time_singular(case: Case, repeat: int) -> tuple[float, int] | None:
    """Mean CPU time of the command in Singular and the number of components (None without Singular)."""
    if not SINGULAR:
        return None
    script = ('LIB "primdec.lib";\nsystem("--ticks-per-sec", 1000);\n' + case.setup +
              f"int k; int t = timer;\nfor (k = 1; k <= {repeat}; k++) {{\n  {case.command}\n"
              f"  if (k < {repeat}) {{ kill L; }}\n}}\nt = timer - t;\n"
              'print("RESULT " + string(t) + " " + string(size(L)));\nquit;\n')
    out = subprocess.run([SINGULAR, "-q", "--no-warn"], input=script, text=True, capture_output=True,
                         timeout=600).stdout
    m = re.search(r"RESULT (\d+) (\d+)", out)
    if not m:
        raise RuntimeError(f"Singular failed on {case.name}: {out[-500:]}")
    return int(m.group(1)) / 1000 / repeat, int(m.group(2))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeat", type=int, default=10)
    args = parser.parse_args()
    print("| decomposition | components | mech | Singular 4.3.1 | mech / Singular |")
    print("|---|---|---|---|---|")
    for case in CASES:
        mt, msize = time_mech(case, args.repeat)
        sing = time_singular(case, args.repeat)
        if sing is None:
            print(f"| {case.name} | {msize} | {mt * 1000:.0f} ms | — | — |")
            continue
        st, ssize = sing
        ratio = f"{mt / st:.1f}" if st else f"> {mt / 0.001:.0f}"
        sizes = str(msize) if msize == ssize else f"{msize} (Singular {ssize})"
        print(f"| {case.name} | {sizes} | {mt * 1000:.0f} ms | {st * 1000:.0f} ms | {ratio} |", flush=True)


if __name__ == "__main__":
    main()
