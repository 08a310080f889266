"""The discriminant curves of a sweep and the cells they give: for the dyad and the 3-RPR of
docs/sweeps.md, the time of the curves (wall and CPU of this process, which a busy machine does not
lengthen) and, in this process (``scheduler=inline``), 3-RPR sweeps with every design analysed
against sweeps with the curves (grid and Latin hypercube): time, designs taking their cell's count,
and whether the counts agree.  ``python benchmarks/sweep_curves.py``."""
from __future__ import annotations

import os
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

RPR = "fix A1 0 0; fix A2 5 0; fix A3 6 6; bar A1 B1 r1; body B1 B2 4 0 B3 2 3; bar A2 B2 r2; bar A3 B3 r3"
DYAD = "fix A 0 0; fix B 3 0; bar A P r1; bar B P r2"


def timed(fn, *args, **kwargs):
    """(result, wall seconds, CPU seconds of this process)."""
    w, c = time.perf_counter(), time.process_time()
    out = fn(*args, **kwargs)
    return out, time.perf_counter() - w, time.process_time() - c


def main() -> None:
    from mech.stdlib.mechanism import parse_mechanism
    from mech.stdlib.sweep_commands import sweep_rows
    from mech.stdlib.sweep_discriminant import _CACHE, discriminant_curves
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    for name, text, values in (("dyad", DYAD, {}), ("3-RPR", RPR, {"r3": 4})):
        m = parse_mechanism(text).with_values(values)
        R, gens = m.constraints()
        curves, wall, cpu = timed(discriminant_curves, R, gens, len(m.variables()), ["r1", "r2"])
        degrees = [max(i + j for i, j in f) for f in curves.factors]
        print(f"{name} curves: {wall:.2f} s wall, {cpu:.2f} s CPU, D = {curves.D}, degrees {degrees}, "
              f"{curves.samples} points")
    m = parse_mechanism(RPR)
    for designs in ("grid r1=1:12:12 r2=1:12:12 r3=4", "lhs 150 r1=1:12 r2=1:12 r3=4 seed=5"):
        full, w0, c0 = timed(sweep_rows, m, designs, "real", scheduler="inline", shared=False)
        _CACHE.clear()  # each sweep computes its curves
        notes: list[str] = []
        cells, w1, c1 = timed(sweep_rows, m, designs, "real", scheduler="inline", notes=notes)
        inherited = sum(r["conditions"].startswith("same cell") for r in cells)
        same = [r["real"] for r in full] == [r["real"] for r in cells]
        print(f"{designs}: all analysed {w0:.1f} s wall ({c0:.1f} s CPU); with the curves {w1:.1f} s wall "
              f"({c1:.1f} s CPU, the curves included), {inherited} of {len(cells)} designs from their cell, "
              f"counts {'equal' if same else 'DIFFERENT'}")
    print(f"load average {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
