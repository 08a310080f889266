"""Decomposition benchmarks: mech, Singular and Macaulay2 on primary decompositions and minimal primes.

    python benchmarks/primdec.py                      # every case, table on stdout
    python benchmarks/primdec.py --only test --repeat 3 --timeout 30

The cases: the paper's four decompositions (../shared/reference/paper), Macaulay2's MinimalPrimes
tests (``minAssGTZ``; the ideals read from the installed tests.m2 by :func:`cases.m2_examples`) and
the examples of primdec.lib's primdecGTZ, primdecSY, minAssGTZ, minAssChar, radical and equidim
(read from the installed library).  Both systems run the same setup script and time one command,
the mean CPU time of up to ``--repeat`` runs (fewer once ``--timeout`` seconds are spent; a
first run past it is reported as "> T s").  mech: ``Session.execute`` of the command in a child
process forked from a warmed-up one (a fresh session and an empty Gröbner cache each run).
Singular: ``timer`` (1 ms ticks) around the runs in one process, start-up and
``LIB "primdec.lib";`` excluded.  Macaulay2 (minimal-primes cases): ``cpuTime`` around
``minimalPrimes`` of a fresh ideal.  The results of mech and Singular are compared as values with
benchmarks/tst_compare.py: lists of primes as sets of ideals (each pair by mutual reduction against
standard bases, in Singular), primary decompositions up to embedded components, ideals as ideals;
``equidim``'s lists by their top part and the radicals of their parts.
"""
from __future__ import annotations

import argparse
import math
import multiprocessing
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Optional

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from cases import m2_examples  # noqa: E402
from tst_compare import Item, Oracle, _names, check_script, compare, long_form, parse, read_answers  # noqa: E402
from tst_source import _MARK, examples  # noqa: E402

SINGULAR = shutil.which("Singular")
M2 = shutil.which("M2")
PRIMDEC_LIB = Path("/usr/share/singular/LIB/primdec.lib")
LIB_PROCS = ("primdecGTZ", "primdecSY", "minAssGTZ", "minAssChar", "radical", "equidim")


@dataclass
class Case:
    name: str
    setup: str                   # Singular text run before the timed command
    command: str                 # the timed statement; it assigns the result to ``result``
    result: str                  # the variable holding the result
    m2: Optional[str] = None     # Macaulay2 text defining the ring and the ideal ``I`` (minimal primes)


@dataclass
class Timing:
    seconds: Optional[float]     # mean CPU seconds per run; None past the timeout or on failure
    output: str = ""             # the printed result
    note: str = ""               # "> T s", or the failure


# ---------------------------------------------------------------- the cases
def _fitting(ring: str, eqs: str, rows: int, angles: str) -> str:
    cols = len(angles.split(","))
    return (f"{ring}\nideal J = {eqs};\nmatrix D[{rows}][{cols}]; int i; int j; list v = {angles};\n"
            f"for (i=1; i<={rows}; i++) {{ for (j=1; j<={cols}; j++) {{ D[i,j] = diff(J[i], v[j]); }} }}\n"
            f"ideal F = minor(D,{rows});\n")


PAPER = [
    Case("slider2: minAssGTZ(Fitting ideal)",
         _fitting("ring r = 0, (c1,s1,c2,s2,l1,l2), (dp(4),dp(2));",
                  "l1*s1+l2*s2, c1^2+s1^2-1, c2^2+s2^2-1", 3, "c1,s1,c2,s2"), "list L = minAssGTZ(F);", "L"),
    Case("slider3: minAssGTZ(Fitting ideal)",
         _fitting("ring r = 0, (c1,s1,c2,s2,c3,s3,l1,l2,l3), (dp(6),dp(3));",
                  "l1*s1+l2*s2+l3*s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1", 4, "c1,s1,c2,s2,c3,s3"),
         "list L = minAssGTZ(F);", "L"),
    Case("fourbar: minAssGTZ(Fitting ideal)",
         _fitting("ring r = 0, (c1,s1,c2,s2,c3,s3,l1,l2,l3), (dp(6),dp(3));",
                  "l1*c1+l2*c2+l3*c3-1, l1*s1+l2*s2+l3*s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1", 5,
                  "c1,s1,c2,s2,c3,s3"), "list L = minAssGTZ(F);", "L"),
    Case("fourbar l=1: primdecGTZ(J)",
         "ring r1 = 0, (c1,s1,c2,s2,c3,s3), dp;\n"
         "ideal J = c1+c2+c3-1, s1+s2+s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1;\n", "list L = primdecGTZ(J);", "L"),
]


def minimal_primes_cases() -> list[Case]:
    """``minAssGTZ`` (mech, Singular) and ``minimalPrimes`` (Macaulay2) on Macaulay2's MinimalPrimes tests."""
    out = []
    for name, char, names, gens, _ in m2_examples():
        ideal = ", ".join(gens)
        if re.search(r"/\s*\(?[^)]*[a-z]", ideal):  # coefficients in a fraction field (makeFiberRings)
            continue
        if not set(re.findall(r"[A-Za-z]", ideal)) <= set(names):  # the ideal lives in another ring
            continue
        field = "QQ" if char == 0 else f"ZZ/{char}"
        singular_ideal = re.sub(r"([\w)])\s*\(", r"\1*(", ideal)  # M2's "xy(x-y)" is a product
        m2_ideal = f"ideal({ideal})" if re.search(r"[*^]", ideal) else f'ideal "{ideal}"'  # "" reads a2b only
        setup = f"ring rng = {char}, ({','.join(names)}), dp;\nideal I = {singular_ideal};\n"  # no variable is rng
        out.append(Case(f"M2 {name}: minAssGTZ", setup, "list L = minAssGTZ(I);", "L",
                        m2=f"R = {field}[{','.join(names)}]; use R; I = {m2_ideal};"))
    return out


def library_cases(lib_text: str) -> list[Case]:
    """The examples of :data:`LIB_PROCS` in primdec.lib: the setup up to the statement calling the
    procedure, that statement timed (a bare call is assigned to ``def value``), printing dropped."""
    out = []
    for proc, code in examples(lib_text):
        if proc not in LIB_PROCS:
            continue
        statements = [s.strip() for s in code.split(";") if s.strip()]
        call = next(k for k, s in enumerate(statements) if re.search(rf"\b{proc}\s*\(", s))
        m = re.fullmatch(r"(?:\w+\s+)?(\w+)\s*=.*", statements[call], re.S)
        command, result = (statements[call], m.group(1)) if m else (f"def value = {statements[call]}", "value")
        setup = "".join(s + ";\n" for s in statements[:call])
        out.append(Case(f"primdec.lib {proc} example", setup, command + ";", result))
    return out


def all_cases() -> list[Case]:
    lib = library_cases(PRIMDEC_LIB.read_text(errors="replace")) if PRIMDEC_LIB.exists() else []
    return PAPER + minimal_primes_cases() + lib


# ---------------------------------------------------------------- mech, in a child process
def _mech_runs(case: Case, repeat: int, budget: float, conn) -> None:
    from mech import Session
    from mech.kernel.engines import clear_cache
    total, runs = 0.0, 0
    while runs < repeat and (runs == 0 or total < budget):
        clear_cache()
        s = Session()
        s.execute('LIB "primdec.lib";\n' + case.setup)
        t0 = time.process_time()
        s.execute(case.command)
        total += time.process_time() - t0
        runs += 1
        conn.send(("run", total / runs))
    conn.send(("done", s.execute(f"{case.result};")))


def warm_up() -> None:
    """Import mech and run each decomposition once in this process, which every child inherits: the
    first call's one-time costs (imports, compiled extensions, library parsing) are start-up."""
    from mech import Session
    for char in (0, 32003):
        Session().execute(f'LIB "primdec.lib";\nring r = {char}, (x,y,z), dp;\nideal i = (z2+1)*(z3+2)^2, y-z2;\n'
                          "list a = minAssGTZ(i); list b = primdecGTZ(i); list c = primdecSY(i);\n"
                          "list d = minAssChar(i); ideal e = radical(i); list f = equidim(i);\n")


def time_mech(case: Case, repeat: int, timeout: float) -> Timing:
    """mech's mean CPU time: runs until ``repeat`` or ``timeout`` seconds; the first past it is cut."""
    ctx = multiprocessing.get_context("fork")
    parent, child = ctx.Pipe(duplex=False)
    proc = ctx.Process(target=_mech_runs, args=(case, repeat, timeout, child), daemon=True)
    proc.start()
    child.close()
    mean: Optional[float] = None
    deadline = time.monotonic() + timeout + 10  # wall: set-up and a loaded machine
    try:
        while True:
            if not parent.poll(max(0.0, deadline - time.monotonic())):
                break
            kind, value = parent.recv()
            if kind == "done":
                return Timing(mean, value)
            mean = value
            deadline = time.monotonic() + timeout + 10
    except (EOFError, ConnectionError):
        return Timing(None, note="failed")
    finally:
        if proc.is_alive():
            proc.kill()
        proc.join()
    return Timing(mean, note="" if mean is not None else f"> {timeout:g} s")


# ---------------------------------------------------------------- Singular and Macaulay2
def _run(cmd: list[str], script: str, timeout: float) -> Optional[str]:
    """The standard output of a system running ``script``, None past the wall-clock timeout."""
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
        f.write(script)
    try:
        return subprocess.run(cmd + [f.name], text=True, capture_output=True, timeout=timeout).stdout
    except subprocess.TimeoutExpired:
        return None
    finally:
        os.unlink(f.name)


def time_singular(case: Case, repeat: int, timeout: float) -> Timing:
    """Singular's mean CPU time (``timer``) over ``repeat`` runs (more, up to 1000, until 0.5 s: 1 ms
    ticks; fewer past ``timeout``), and the printed result after a ring marker (tst_compare reads
    the ring from it)."""
    ms = int(timeout * 1000)
    script = ('LIB "primdec.lib";\nsystem("--ticks-per-sec", 1000);\n' + case.setup +
              f"int k@; int t@ = timer; int n@ = 0;\n"
              f"while (n@ == 0 || (timer - t@ < {ms} && (n@ < {repeat} || (timer - t@ < 500 && n@ < 1000)))) {{\n"
              f"  if (n@ > 0) {{ kill {case.result}; }}\n  {case.command}\n  n@ = n@ + 1;\n}}\n"
              f"t@ = timer - t@;\n{_MARK}\n{case.result};\n"
              'print("RESULT " + string(t@) + " " + string(n@));\nquit;\n')
    out = _run([SINGULAR, "-q", "--no-warn"], script, 2 * timeout + 10)
    if out is None:
        return Timing(None, note=f"> {timeout:g} s")
    m = re.search(r"RESULT (\d+) ([1-9]\d*)", out)
    if not m:
        return Timing(None, note="failed")
    mean = int(m.group(1)) / 1000 / int(m.group(2))
    return Timing(mean, out[:m.start()]) if mean <= timeout else Timing(None, note=f"> {timeout:g} s")


def time_m2(case: Case, repeat: int, timeout: float) -> Timing:
    """Macaulay2's mean CPU time (``cpuTime``) of ``minimalPrimes`` on a fresh ideal (M2 caches on it)."""
    script = ("Total = 0; Runs = 0; Primes = null;\n"  # names no ring variable (single letters) shadows
              f"while Runs < {repeat} and (Runs == 0 or Total < {timeout}) do ({case.m2} "
              "Start = cpuTime(); Primes = minimalPrimes I; Total = Total + cpuTime() - Start; Runs = Runs + 1);\n"
              'print "RESULT"; print(Total / Runs); print(#Primes);\n')
    out = _run([M2, "--script"], script, 2 * timeout + 10)
    if out is None:
        return Timing(None, note=f"> {timeout:g} s")
    if "RESULT" not in out:
        return Timing(None, note="failed")
    mean, size = out.split("RESULT", 1)[1].split()[:2]
    return Timing(float(mean), size) if float(mean) <= timeout else Timing(None, note=f"> {timeout:g} s")


def agree(singular: Timing, mech: Timing, equidimensional: bool = False) -> str:
    """"yes" when the printed results are equal as values (tst_compare's rules), else the difference."""
    if singular.seconds is None or mech.seconds is None:
        return "—"

    def answer(questions: list) -> dict:
        out = _run([SINGULAR, "-q", "--no-warn"], check_script(questions) + "quit;\n", 600)
        return read_answers(questions, out or "")
    if equidimensional:
        return _same_equidim(parse(singular.output), parse(mech.output))
    why = compare(parse(singular.output), parse(mech.output), Oracle(answer))
    return "yes" if why is None else f"NO: {why}"


def _same_equidim(singular: list[Item], mech: list[Item]) -> str:
    """``equidim``'s lists (not unique below the top dimension) agree when they have the same length,
    the same last element (the top-dimensional part) and elements of the same radicals (Singular's
    lower parts need not intersect to the ideal, mech's do); decided by Singular."""
    s, m = singular[-1], mech[-1]
    if s.kind != "list" or m.kind != "list" or len(s.elems) != len(m.elems):
        return "NO: different lengths"
    decl = s.ring[0] if s.ring else ""
    names = _names(decl)

    def ideals(item: Item, tag: str) -> str:
        return "".join(f"ideal {tag}{k} = {', '.join(long_form(g, names) for g in e[0].gens)};\n"
                       for k, e in enumerate(item.elems))
    n = len(s.elems)
    script = (f'LIB "primdec.lib";\nring r = {decl};\n' + ideals(s, "S") + ideals(m, "M") +
              "proc same(ideal a, ideal b) { return(size(reduce(a, std(b))) + size(reduce(b, std(a))) == 0); }\n"
              f"int ok = same(S{n - 1}, M{n - 1});\n"
              + "".join(f"ok = ok && same(radical(S{k}), radical(M{k}));\n" for k in range(n))
              + '"@@OK " + string(ok);\nquit;\n')
    out = _run([SINGULAR, "-q", "--no-warn"], script, 600) or ""
    return "yes (up to lower-dimensional parts)" if "@@OK 1" in out else "NO: the equidimensional parts differ"


def components(output: str) -> str:
    """The number of elements of a printed list (``[k]:`` headers at the left margin), or "ideal"."""
    heads = re.findall(r"^\[(\d+)\]:$", output, re.M)
    return str(max(map(int, heads))) if heads else "ideal"


# ---------------------------------------------------------------- the table
def _seconds(t: Timing) -> str:
    if t.seconds is None:
        return t.note
    if t.seconds < 0.01:
        return f"{t.seconds * 1000:.1f} ms"
    return f"{t.seconds * 1000:.0f} ms" if t.seconds < 10 else f"{t.seconds:.1f} s"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeat", type=int, default=10, help="runs per case at most (default 10)")
    parser.add_argument("--timeout", type=float, default=60, help="seconds per case and system (default 60)")
    parser.add_argument("--only", default="", help="cases whose name contains this text")
    args = parser.parse_args()
    if not SINGULAR:
        sys.exit("primdec.py compares with Singular: Singular is not installed")
    print("| case | components | mech | Singular 4.3.1 | mech / Singular | Macaulay2 minimalPrimes | same result |")
    print("|---|---|---|---|---|---|---|")
    warm_up()
    ratios: dict[str, float] = {}
    for case in all_cases():
        if args.only not in case.name:
            continue
        mech = time_mech(case, args.repeat, args.timeout)
        sing = time_singular(case, args.repeat, args.timeout)
        m2 = time_m2(case, args.repeat, args.timeout) if case.m2 and M2 else None
        ratio = "—"
        if mech.seconds is not None and sing.seconds is not None:
            ratios[case.name] = mech.seconds / max(sing.seconds, 0.001)  # 1 ms: Singular's tick
            ratio = f"{ratios[case.name]:.1f}" if sing.seconds else f"> {ratios[case.name]:.0f}"
        size = components(sing.output or mech.output) if (sing.output or mech.output) else "—"
        m2_text = "—" if m2 is None else _seconds(m2) + (f" ({m2.output} primes)" if m2.seconds is not None else "")
        print(f"| {case.name} | {size} | {_seconds(mech)} | {_seconds(sing)} | {ratio} | {m2_text} | "
              f"{agree(sing, mech, 'equidim' in case.command)} |", flush=True)
    if ratios:
        mean = math.exp(sum(map(math.log, ratios.values())) / len(ratios))
        print(f"\nGeometric mean of mech / Singular over the {len(ratios)} cases both finished: {mean:.2f}")
        above = [f"{name} ({r:.1f})" for name, r in sorted(ratios.items(), key=lambda x: -x[1]) if r > 3]
        print(f"Above 3×: {', '.join(above) if above else 'none'}")


if __name__ == "__main__":
    main()
