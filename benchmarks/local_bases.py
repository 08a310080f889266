"""Standard bases in local orderings (ds, Ds, ls, blocks with a local part) and tangent cones:
mech against Singular, side by side in one run.

    python benchmarks/local_bases.py                  # every case
    python benchmarks/local_bases.py --only mora_5 --timeout 60
    python benchmarks/local_bases.py --write          # also rewrite the local section of RESULTS.md

Each case is a ring and statements in Singular syntax that define ``ideal I``, read by mech's
own front end and by Singular alike (most from Singular's test files Tst/Short/mora_*,
Tst/Old/mora*, Tst/Short/vdim_overflow; the mechanism case from examples/bricard.mech).  Each
system runs in its own process with a time limit.  Times are CPU seconds: mech times
``standard_basis(I)`` of the kernel (engine ``auto``) or ``tangent_cone(I)`` (kernel/local.py),
best of ``--repeat`` runs and of more while the runs fill less than half a second (Python
specializes the code it runs over the first runs: a computation of 0.2 ms takes 0.3 ms in its
third run); Singular times ``std(I)`` or sing.lib's ``tangentcone(I)`` with ``timer`` (1 ms
ticks), repeated until half a second has passed, the mean.

Every answer of mech is checked in Singular in the same run: for a standard basis ``M``, the
leading ideal of ``std(I + M)`` must equal that of ``std(I)`` (then ``M`` lies in the ideal of
the local ring; Singular's ``reduce`` by a local basis can run for minutes) and the leading
ideal of ``M`` must equal Singular's (then ``M`` is a standard basis of ``I``); vdim and the
number of elements are printed.  A tangent cone is compared with Singular's as an ideal of the
polynomial ring (both ways, by ``reduce`` against a ``dp`` basis).  When Singular does not
finish, the check is marked "—".
"""
from __future__ import annotations

import argparse
import datetime
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
SINGULAR = shutil.which("Singular")
FILL = 0.5
"""CPU seconds mech's runs of one case fill at least (as Singular's)."""
MARK = "## Local orderings: standard bases and tangent cones (benchmarks/local_bases.py)"


@dataclass
class LocalCase:
    name: str
    source: str      # where the ideal comes from
    ring: str        # a Singular ring declaration
    setup: str       # Singular statements defining `ideal I`
    task: str = "std"  # "std": a standard basis of I; "cone": the tangent cone at the origin


F5 = "x*y*z*(x+y+z)^2+(x+y+z)^3+x^a+y^a+z^a"
MORA9 = """ideal in =
u(5)*u(2)^2-u(3)*u(4)^2-u(3)*u(5)^2+u(5)*u(3)^2,u(6)^10,
2*u(3)*x(7)*u(4)+u(4)*u(2)*u(5)-2*x(7)*u(2)*u(5),
u(3)*u(5)^2-u(5)*u(3)^2-u(4)*u(2)*u(3),
-2*x(7)*u(2)-2*u(3)*x(8)+u(4)*u(2)+u(3)*u(5),
x(11)*u(2)-u(3)*x(10),
-4*x(12)+3*x(10)+u(4),-4*x(13)+3*x(11)+u(5),2*u(3)*x(8)-u(2)^2-u(3)^2,
z(1)*u(2)-u(6),z(2)*u(3)-u(6),
z(3)*(u(5)*u(2)-u(3)*u(4))-u(6);
ideal im =
u(3)*u(5)^2-u(5)*u(3)^2-u(4)*u(2)*u(3),
-4*x(12)+3*x(10)+u(4),-4*x(13)+3*x(11)+u(5),2*u(3)*x(8)-u(2)^2-u(3)^2,
z(3)*(u(5)*u(2)-u(3)*u(4))-u(6);
ideal I = in*im;"""
MORA10 = """ideal I =
-2*x(4)*x(5)-2*x(3)*x(6)^2-2*x(2)*x(7)-1*x(1)^3,
-2*x(1)*x(2)-2*x(4)*x(6)^2-2*x(3)*x(7)-1*x(2)^3,
-2*x(1)*x(3)-2*x(5)*x(6)^2-2*x(4)*x(7)-1*x(3)^3,
-2*x(2)*x(3)-2*x(1)*x(4)-2*x(5)*x(7)-1*x(4)^3,
-2*x(2)*x(5)-2*x(1)^2;"""
MORA1 = ("int a = 11; int b = 10; int c = 3; int t = 1;\n"
         "poly f = x^a+y^b+z^(3*c)+x^(c+2)*y^(c-1)+x^(c-1)*y^(c-1)*z3+x^(c-2)*y^c*(y2+t*x)^2;\n"
         "ideal I = jacob(f);")
CYCLIC = ("poly s1=a+b+c+d+e+f; poly s2=ab+bc+cd+de+ef+fa; poly s3=abc+bcd+cde+edf+efa+fab;\n"
          "poly s4=abcd+bcde+cdef+defa+efab+fabc; poly s5=abcde+bcdef+cdefa+defab+efabc+fabcd;\n"
          "poly s6=abcdef+g^6; ideal I=s1,s2,s3,s4,s5,s6;")
STANDARD = ("poly s1=1x3y2t4+21328x5yt3+10667x2y4t3+21328x2yz3t3+10666xy6t2+10667y9;\n"
            "poly s2=1x2y2z2t2+3z8; poly s3=5x4y2t4+4xy5t4+2x2y2z3t3+1y7t3+11x10; ideal I=s1,s2,s3;")
SIX = "".join(f"poly f{k}=y({k})^7-x({k})^9+x({k})^4*y({k})^4;\n" for k in range(1, 7)) + \
    "poly g=f1+f2+f3+f4+f5+f6;\n"


def _bricard() -> str:
    """The Bricard 6R loop's ideal J (examples/bricard.mech, as the mechanism analysis builds it)
    moved to its singular configuration (-1,0,-1,0,-1,0,-1,0)."""
    return (HERE / "data" / "bricard_J.sing").read_text()


CASES = [
    LocalCase("mora_5", "Tst/Short/mora_5", "ring r = 32003, (x,y,z), ds;",
              f"int a = 20; poly f = {F5}; ideal I = jacob(f), f;"),
    LocalCase("mora_6", "Tst/Short/mora_6", "ring r = 32003, (w,x,y,z), ds;",
              f"int a = 7; poly f = {F5}; ideal I = jacob(f), f;"),
    LocalCase("mora_7", "Tst/Short/mora_7", "ring r = 32003, (x,y,z,u), ds;",
              "int a = 7; poly f = x*y*z*u*(x+y+z+u)+(x+y+z+u)^2+x^a+y^a+z^a+u^a; ideal I = jacob(f);"),
    LocalCase("mora_9", "Tst/Short/mora_9", "ring r = 32003, (z(3..1),x(13..7),u(6..2)), ds;", MORA9),
    LocalCase("mora_10", "Tst/Short/mora_10", "ring r = 32003, (x(1..7)), ds;", MORA10),
    LocalCase("mora1", "Tst/Old/mora1", "ring r = 32003, (x,y,z), ds;", MORA1),
    LocalCase("mora2 cyclic_roots_7", "Tst/Old/mora2", "ring r = 32003, (a,b,c,d,e,f,g), ds;", CYCLIC),
    LocalCase("mora2 standard", "Tst/Old/mora2", "ring r = 32003, (t,x,y,z), (ls(1),ds(3));", STANDARD),
    LocalCase("mora2 Puiseux", "Tst/Old/mora2", "ring r = 32003, (t,x,y), ls;",
              "poly s1=x-t72; poly s2=y-t84-t111-t160; ideal I=s1,s2;"),
    LocalCase("vdim_overflow milnor", "Tst/Short/vdim_overflow", "ring r = 32003, (x(1..6),y(1..6)), ds;",
              SIX + "ideal I = jacob(g);"),
    LocalCase("vdim_overflow tjurina", "Tst/Short/vdim_overflow", "ring r = 32003, (x(1..6),y(1..6)), ds;",
              SIX + "ideal I = jacob(g), g;"),
    LocalCase("space curve germ", "benchmarks/cases.py", "ring r = 0, (x,y,z), ds;",
              "ideal I = 7*x*y*z+z^5, x^2+y^3+z^7, 5*z^5+y^5;"),
    LocalCase("T(4,5,6) jacobian", "benchmarks/cases.py", "ring r = 0, (x,y,z), ds;",
              "ideal I = 4*x^3+y*z, 5*y^4+x*z, 6*z^5+x*y;"),
    LocalCase("x^5+y^5+z^5+x^2y^2z^2 jacobian, Ds", "benchmarks/cases.py", "ring r = 0, (x,y,z), Ds;",
              "poly f = x^5+y^5+z^5+x^2*y^2*z^2; ideal I = jacob(f);"),
    LocalCase("T(4,5,6) tangent cone", "benchmarks/cases.py", "ring r = 0, (x,y,z), dp;",
              "ideal I = 4*x^3+y*z, 5*y^4+x*z, 6*z^5+x*y;", task="cone"),
    LocalCase("Bricard 6R tangent cone", "examples/bricard.mech", "", "", task="cone"),
]


def _source(case: LocalCase) -> str:
    if case.name.startswith("Bricard"):
        return _bricard()
    return f"{case.ring}\n{case.setup}\n"


# -- children -----------------------------------------------------------------------------
def child_mech(case: LocalCase, repeat: int, out: str) -> dict:
    from mech import Session
    from mech.kernel.engines import clear_cache, standard_basis
    from mech.kernel.local import tangent_cone
    s = Session(warnings=False)
    s.execute(_source(case))
    ideal = s["I"]
    gens, ring = list(ideal.gens), ideal.ring
    best = None
    runs, spent = 0, 0.0
    while runs < repeat or spent < FILL:
        runs += 1
        clear_cache()
        c0, w0 = time.process_time(), time.perf_counter()
        G = standard_basis(gens, ring) if case.task == "std" else tangent_cone(gens, ring)
        c1, w1 = time.process_time(), time.perf_counter()
        spent += c1 - c0
        if best is None or c1 - c0 < best[0]:
            best = (c1 - c0, w1 - w0)
    Path(out).write_text(",\n".join(g.to_str() for g in G) or "0")
    return {"cpu": best[0], "wall": best[1], "size": len(G)}


def run_mech(case: LocalCase, repeat: int, timeout: float, out: str) -> dict:
    cmd = [sys.executable, str(Path(__file__).resolve()), "--child", case.name, "--repeat", str(repeat),
           "--out", out]
    try:
        res = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"timeout": timeout}
    if res.returncode:
        return {"error": res.stderr.strip().splitlines()[-1] if res.stderr.strip() else f"exit {res.returncode}"}
    return json.loads(res.stdout.strip().splitlines()[-1])


def _singular(script: str, timeout: float) -> str | None:
    try:
        res = subprocess.run([SINGULAR, "-q", "--no-warn"], input=script, text=True, capture_output=True,
                             timeout=timeout)
    except subprocess.TimeoutExpired:
        return None
    return res.stdout


def _command(case: LocalCase) -> str:
    return "std(I)" if case.task == "std" else "tangentcone(I)"


def run_singular(case: LocalCase, timeout: float) -> dict:
    reps, out = 1, {}
    for _ in range(2):
        script = (f'LIB "sing.lib";\n{_source(case)}system("--ticks-per-sec", 1000);\n'
                  f"int k; ideal G; int c0 = timer; int w0 = rtimer;\n"
                  f"for (k = 0; k < {reps}; k++) {{ G = {_command(case)}; }}\n"
                  f'"RESULT"; timer - c0; rtimer - w0; size(G);\nquit;\n')
        text = _singular(script, timeout)
        if text is None:
            return {"timeout": timeout}
        if "RESULT" not in text:
            return {"error": text.strip()[-200:]}
        cpu, wall, size = (int(v) for v in text.split("RESULT", 1)[1].split()[:3])
        out = {"cpu": cpu / 1000 / reps, "wall": wall / 1000 / reps, "size": size}
        if cpu >= 500 or reps > 1:
            break
        reps = min(500, max(2, math.ceil(500 / max(cpu, 1))))
    return out


def check(case: LocalCase, basis_file: str, timeout: float) -> str:
    """mech's answer judged in Singular (see the module docstring)."""
    mech_ideal = Path(basis_file).read_text()
    if case.task == "std":
        script = (f"{_source(case)}ideal M = {mech_ideal};\nideal J = std(I);\nideal JM = lead(std(J + M));\n"
                  "ideal LM = lead(M); attrib(LM, \"isSB\", 1); ideal LJ = lead(J); attrib(LJ, \"isSB\", 1);\n"
                  '"CHECK"; size(reduce(JM, LJ)); size(reduce(LJ, LM)); size(reduce(LM, LJ)); vdim(J); size(J);\n'
                  "quit;\n")
        text = _singular(script, timeout)
        if text is None or "CHECK" not in text:
            return "—"
        a, b, c, v, n = text.split("CHECK", 1)[1].split()[:5]
        ok = a == b == c == "0"
        return (f"{'yes' if ok else 'NO'} (vdim {v}, Singular {n} elements)" if ok
                else f"NO: std(I + M) has {a} leading monomials more, leading ideals differ by {b}/{c}")
    script = (f'LIB "sing.lib";\n{_source(case)}ideal T = tangentcone(I);\n'
              f"ideal M = {mech_ideal};\n"
              "def R0 = basering; list L = ringlist(R0); L[3] = list(list(\"dp\", 1:nvars(R0)), list(\"C\", 0));\n"
              "def S = ring(L); setring S; ideal T = std(imap(R0, T)); ideal M = std(imap(R0, M));\n"
              '"CHECK"; size(reduce(M, T)); size(reduce(T, M)); dim(T); mult(T);\nquit;\n')
    text = _singular(script, timeout)
    if text is None or "CHECK" not in text:
        return "—"
    a, b, d, m = text.split("CHECK", 1)[1].split()[:4]
    return f"yes (dim {d}, mult {m})" if a == b == "0" else f"NO: {a}/{b} generators differ"


# -- the parent -----------------------------------------------------------------------------
def fmt(r: dict) -> str:
    if "timeout" in r:
        return f"> {r['timeout']:.0f} s"
    if "error" in r:
        return "error"
    t = r["cpu"]
    return f"{t * 1000:.1f} ms" if t < 1 else f"{t:.2f} s"


def ratio(a: dict, b: dict) -> tuple[str, float | None]:
    if "error" in a or "error" in b or "timeout" in b or not b.get("cpu"):
        return "—", None
    if "timeout" in a:
        return f"> {a['timeout'] / b['cpu']:.0f}", a["timeout"] / b["cpu"]
    q = a["cpu"] / b["cpu"]
    return (f"{q:.2f}" if q < 10 else f"{q:.0f}"), q


def load() -> str:
    return " ".join(f"{x:.1f}" for x in os.getloadavg())


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--only", nargs="*", help="cases whose name contains one of these texts")
    ap.add_argument("--timeout", type=float, default=60, help="limit per computation (s)")
    ap.add_argument("--repeat", type=int, default=2, help="mech's runs per case (best taken)")
    ap.add_argument("--write", action="store_true", help="rewrite the local section of RESULTS.md")
    ap.add_argument("--child", help=argparse.SUPPRESS)
    ap.add_argument("--out", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:
        case = next(c for c in CASES if c.name == args.child)
        print(json.dumps(child_mech(case, args.repeat, args.out)))
        return
    cases = [c for c in CASES if not args.only or any(o in c.name for o in args.only)]
    start = f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC, load average {load()}"
    print(start, flush=True)
    rows = ["| case | from | ordering | task | mech | Singular | mech / Singular | elements (mech) | "
            "checked in Singular |", "|---|---|---|---|---|---|---|---|---|"]
    quotients = []
    with tempfile.TemporaryDirectory() as tmp:
        for case in cases:
            out = str(Path(tmp) / "basis.txt")
            mech = run_mech(case, args.repeat, args.timeout, out)
            sing = run_singular(case, args.timeout)
            ok = check(case, out, args.timeout) if "cpu" in mech else "—"
            text, q = ratio(mech, sing)
            if q is not None:
                quotients.append(q)
            ring_line = next(line for line in _source(case).splitlines() if line.startswith("ring"))
            order = ring_line.rstrip(";").rsplit(", ", 1)[1]
            rows.append(f"| {case.name} | {case.source} | {order} | {case.task} | {fmt(mech)} | {fmt(sing)} | "
                        f"{text} | {mech.get('size', '—')} | {ok} |")
            print(rows[-1], flush=True)
    gm = math.exp(sum(map(math.log, quotients)) / len(quotients)) if quotients else float("nan")
    summary = (f"Geometric mean of mech / Singular over the {len(quotients)} cases Singular finished: "
               f"**{gm:.2f}** (a mech timeout counts with its limit).")
    end = f"load average at the end {load()}"
    print(summary, end, sep="\n")
    if args.write:
        write(rows, summary, start, end, args)


def write(rows: list[str], summary: str, start: str, end: str, args) -> None:
    path = HERE / "RESULTS.md"
    text = path.read_text()
    head = text.split(MARK, 1)[0].rstrip("\n")
    only = f" --only {' '.join(repr(o) for o in args.only)}" if args.only else ""
    section = [MARK, "",
               f"Run of {start} (2 cores shared with other jobs; {end}). Command: "
               f"`python benchmarks/local_bases.py --timeout {args.timeout:g} --repeat {args.repeat}{only} --write`.",
               "Times are CPU seconds of one computation (mech best of the repeats, at least half a second of them; "
               "Singular mean over repetitions filling half a second); ratios within this run. Method and checks: the docstring of "
               "benchmarks/local_bases.py.", "", *rows, "", summary, ""]
    path.write_text(head + "\n\n" + "\n".join(section))


if __name__ == "__main__":
    main()
