"""Whole scripts, end to end: the wall time of the process (start-up included) and its peak
memory, for mech and, when installed, Singular on the same script.

    python benchmarks/scripts.py            # start-up, the paper's scripts, examples/*.mech
    python benchmarks/scripts.py --write    # also rewrite benchmarks/SCRIPTS.md

Each script runs ``--repeat`` times per system; the table shows the best wall time.  The
paper's scripts are the reference runs of ../shared/reference/paper/ (Singular syntax, read
unchanged by both systems); examples/*.mech are mech's own (mechanism syntax: mech only).
"""
from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
PAPER = ROOT.parent / "shared" / "reference" / "paper"
SINGULAR = shutil.which("Singular")
MECH = shutil.which("mech") or ""
SCRATCH = tempfile.mkdtemp(prefix="mech-bench-")
# children may write and use bytecode caches, as an installed mech does (the first run warms them)
ENV = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}


def timed(cmd: list[str], stdin: str | None = None) -> dict:
    """Wall seconds, peak RSS (MB) and exit status of one run of ``cmd`` (in a scratch
    directory, where the examples write their plots)."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            cwd=SCRATCH, text=True, env=ENV)
    proc.stdin.write(stdin or "")
    proc.stdin.close()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    proc.returncode = os.waitstatus_to_exitcode(status)
    err = proc.stderr.read()
    return {"wall": wall, "rss": usage.ru_maxrss / 1024, "rc": proc.returncode, "err": err.strip()[-200:]}


def best(cmd: list[str], repeat: int, stdin: str | None = None) -> dict:
    runs = [timed(cmd, stdin) for _ in range(repeat + 1)][1:]  # the first run warms the caches
    return min(runs, key=lambda r: r["wall"])


def rows(repeat: int) -> list[tuple[str, dict, dict | None]]:
    mech = [MECH] if MECH else [sys.executable, "-m", "mech"]
    out = [("start-up (`mech -c '1;'` / `Singular -q`)", best(mech + ["-c", "1;"], repeat),
            best([SINGULAR, "-q", "--no-warn"], repeat, "1;\nquit;\n") if SINGULAR else None)]
    for script in sorted(PAPER.glob("*.sing")):
        text = script.read_text()
        out.append((f"paper: {script.name}", best(mech + [str(script)], repeat),
                    best([SINGULAR, "-q", "--no-warn"], repeat, text + "\nquit;\n") if SINGULAR else None))
    for script in sorted((ROOT / "examples").glob("*.mech")):
        out.append((f"examples/{script.name}", best(mech + [str(script)], repeat), None))
    return out


def fmt(r: dict | None) -> str:
    if r is None:
        return "—"
    if r["rc"]:
        return f"exit {r['rc']}"
    return f"{r['wall'] * 1000:.0f} ms" if r["wall"] < 1 else f"{r['wall']:.2f} s"


def table(results: list[tuple[str, dict, dict | None]]) -> list[str]:
    lines = ["| script | mech | Singular | mech / Singular | mech peak RSS |", "|---|---|---|---|---|"]
    for name, m, s in results:
        ratio = f"{m['wall'] / s['wall']:.1f}" if s and not s["rc"] and not m["rc"] else "—"
        lines.append(f"| {name} | {fmt(m)} | {fmt(s)} | {ratio} | {m['rss']:.0f} MB |")
    return lines


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--write", action="store_true", help="write benchmarks/SCRIPTS.md")
    args = ap.parse_args()
    results = rows(args.repeat)
    lines = table(results)
    print("\n".join(lines))
    for name, m, _ in results:
        if m["rc"]:
            print(f"{name}: mech failed: {m['err']}", file=sys.stderr)
    if args.write:
        sys.path.insert(0, str(HERE))
        from run import machine
        text = ["# Benchmarks: whole scripts", "",
                "Produced by `python benchmarks/scripts.py --write`: wall time of the whole process (start-up "
                f"included), best of {args.repeat} runs, and mech's peak resident memory.", ""]
        (HERE / "SCRIPTS.md").write_text("\n".join(text + machine() + [""] + lines) + "\n")


if __name__ == "__main__":
    main()
