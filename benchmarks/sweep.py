"""Sweep throughput: designs per second in this process (no Dask), on a Dask LocalCluster with 1 and
2 worker processes (cluster start-up included: what a user waits for), and the scaling efficiency
(rate with 2 workers / twice the rate with 1).  ``python benchmarks/sweep.py [--write]`` (--write:
benchmarks/SWEEP.md)."""
from __future__ import annotations

import os
import platform
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

CASES = [
    ("3-RPR real assembly modes, 12 x 12 grid", "fix A1 0 0; fix A2 5 0; fix A3 6 6; bar A1 B1 r1; "
     "body B1 B2 4 0 B3 2 3; bar A2 B2 r2; bar A3 B3 r3", "grid r1=1:12:12 r2=1:12:12 r3=4", "real"),
    ("four-bar mobility and real circuits, 6 x 6 grid", "ground O A 2; bar O B l1; bar B C l2; bar C A 4",
     "grid l1=1:6:6 l2=1:6:6", "mobility,real"),
    ("four-bar Grashof type, 50 x 50 grid", "ground O A 2; bar O B l1; bar B C l2; bar C A 4",
     "grid l1=1/2:5:50 l2=1/2:5:50", "grashof"),
]


def rate(mech: str, designs: str, answers: str, scheduler) -> float:
    from mech.stdlib.mechanism import parse_mechanism
    from mech.stdlib.sweep_commands import sweep_rows
    start = time.perf_counter()
    rows = sweep_rows(parse_mechanism(mech), designs, answers, scheduler=scheduler, progress=False,
                      shared=False)  # every design analysed: the raw rate (no discriminant cells)
    assert not any(r["error"] for r in rows)
    return len(rows) / (time.perf_counter() - start)


def cluster(workers: int):
    """A started LocalCluster whose workers have run a first sweep (mech imported), and the seconds
    that took."""
    from distributed import LocalCluster
    start = time.perf_counter()
    c = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=":0")
    name, mech, designs, answers = CASES[1]
    rate(mech, "grid l1=1:2:4 l2=3", answers, c.scheduler_address)
    return c, time.perf_counter() - start


def main() -> None:
    lines = ["# Sweep throughput", "",
             f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores (shared with other jobs), "
             f"Python {platform.python_version()}; `python benchmarks/sweep.py --write`. Designs per second "
             "from the call to the last row; the LocalCluster already started and warm (its start-up, "
             "first tasks included, is given below); efficiency = rate(2 workers) / (2 x rate(1 worker)).", "",
             "| sweep | designs | in-process | LocalCluster 1 worker | LocalCluster 2 workers | efficiency |",
             "|---|---|---|---|---|---|"]
    from mech.stdlib.sweep_designs import design_set
    clusters = {n: cluster(n) for n in (1, 2)}
    for name, mech, designs, answers in CASES:
        inline = rate(mech, designs, answers, "inline")
        one = rate(mech, designs, answers, clusters[1][0].scheduler_address)
        two = rate(mech, designs, answers, clusters[2][0].scheduler_address)
        n = len(design_set(designs).designs)
        lines.append(f"| {name} | {n} | {inline:.1f} | {one:.1f} | {two:.1f} | {two / (2 * one):.0%} |")
        print(lines[-1], flush=True)
    lines += ["", "LocalCluster start-up with a first small sweep: " +
              ", ".join(f"{n} worker{'s' if n > 1 else ''} {t:.1f} s" for n, (c, t) in clusters.items())]
    for c, _ in clusters.values():
        c.close()
    print(lines[-1])
    if "--write" in sys.argv:  # the sections after the table (## ...) are kept
        path = ROOT / "benchmarks" / "SWEEP.md"
        old = path.read_text() if path.exists() else ""
        rest = old[old.find("\n## ") + 1:] if "\n## " in old else ""
        path.write_text("\n".join(lines) + "\n" + ("\n" + rest if rest else ""))


if __name__ == "__main__":
    main()
