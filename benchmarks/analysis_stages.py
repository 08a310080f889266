"""The analysis of mechanisms stage by stage, in mech and in the same steps hand-written in Singular.

    python benchmarks/analysis_stages.py            # every case, a Markdown table on stdout
    python benchmarks/analysis_stages.py kite watt  # some cases

mech: ``analyze`` in a fresh Session of this process, the CPU time of each stage read from its
progress events (``Session(progress=...)``).  Singular: ``timer`` (1 ms ticks) around each step
of the paper's pipeline, start-up and ``LIB`` loading excluded: ``std`` and ``dim`` of J (mech's
dimension stage), ``minAssGTZ(J)`` (the motion modes: mech's decomposition stage, whatever
strategy certifies them), ``minAssGTZ(J + I_r(dJ))`` (the singular configurations), the tangent cones at the singular
configurations that are points (sing.lib's ``tangentcone`` of J moved to the point, over ``Q(t)``
modulo the minimal polynomial of a primitive element for conjugate points: mech's local analysis,
which also classifies the points), and for
symbolic lengths the eliminations of the lengths (the length conditions).  A Singular step that
does not finish within ``--singular-timeout`` seconds is reported as such; ratios only where
Singular takes at least 10 ms (below, the timer's resolution decides).  ``--repeat N`` runs
mech and Singular alternately N times per case and keeps each stage's minimum (the machine's load
varies from one run to the next).
"""
from __future__ import annotations

import argparse
import re
import shutil
import subprocess
import sys
import time
from typing import NamedTuple

SINGULAR = shutil.which("Singular")


class Case(NamedTuple):
    name: str
    mechanism: str
    depth: str  # "full" or "quick" (quick: no motion modes, in Singular neither)


CASES = [
    Case("kite", "ground O A 1; bar O B 1; bar B C 2; bar C A 2", "full"),
    Case("fivebar (quick)", "ground O A 2; bar O B 1; bar B C 1; bar C D 1; bar D A 1", "quick"),
    Case("watt", "ground O A 1; fix G 2 0; bar O B 1; bar B C 1; body A C 1 0 E 0 1; bar E F 1; bar F G 1",
         "full"),
    Case("watt I (issue 18)", "ground O A 4; body O B 3 0 E 2 2; body B C 4 0 F 2 2; bar C A 2; bar E H 3; "
         "bar H F 3", "full"),
    Case("stephenson (quick)", "ground O A 1; fix G 2 0; bar O B 1; body B C 1 0 E 0 1; bar C A 1; bar E F 1; "
         "bar F G 1", "quick"),
    Case("four-bar, symbolic lengths", "ground O A 1; bar O B l1; bar B C l2; bar C A l3", "quick"),
    Case("watt I-B", "ground O A 4; body O B 3 0 E 1 2; body B C 4 0 F 1 2; bar C A 3; bar E H 2; bar H F 3",
         "full"),
    Case("stephenson", "ground O A 1; fix G 2 0; bar O B 1; body B C 1 0 E 0 1; bar C A 1; bar E F 1; bar F G 1",
         "full"),
]
STAGES = ["dimension", "decomposition", "singular configurations", "local analysis", "length conditions"]


def mech_stages(case: Case) -> tuple[dict[str, float], float, object]:
    """CPU seconds of each top-level stage of mech's analysis, the total, and the analysis."""
    from mech import Session
    from mech.stdlib import analysis
    from mech.stdlib.analysis import run_analysis
    from mech.kernel import engines
    from mech.stdlib.mechanism import parse_mechanism
    analysis._CACHE.clear()  # every stage runs (analyze keeps the analyses of a process)
    engines.clear_cache()  # and computes its bases (a repeat would find them)
    opened: dict[str, float] = {}
    spent: dict[str, float] = {}

    def listen(e) -> None:
        if e.path != ("analysis",):
            return
        if e.kind == "start":
            opened[e.stage] = time.process_time()
        elif e.kind == "end":
            spent[e.stage] = spent.get(e.stage, 0.0) + time.process_time() - opened[e.stage]
    start = time.process_time()
    Session(progress=listen).execute(f'LIB "mechanism.lib"; mechanism m = "{case.mechanism}"; '
                                     f'analyze(m, "json", "{case.depth}");')
    total = time.process_time() - start
    return spent, total, run_analysis(parse_mechanism(case.mechanism), decompose=case.depth == "full")


def singular_script(a, depth: str) -> str:
    """The pipeline's steps in Singular, each printing ``STAGE name ms``."""
    from mech.dsl.printing import poly_str
    n, k = a.nvars, len(a.params)
    order = f"(dp({n}),dp({k}))" if k else "dp"
    J = ", ".join(poly_str(g) for g in a.ideal)
    r = len(a.ideal) if a.complete_intersection else n - a.mobility
    lines = ['LIB "primdec.lib"; LIB "elim.lib"; system("--ticks-per-sec", 1000); int t; int i; int j;',
             f"ring R = 0, ({','.join(a.ring.names)}), {order};", f"ideal J = {J};",
             "t = timer; ideal S = std(J); int d = dim(S);", 'print("STAGE dimension " + string(timer - t));',
             f"matrix D[{len(a.ideal)}][{n}];",
             f"for (i = 1; i <= {len(a.ideal)}; i++) {{ for (j = 1; j <= {n}; j++) {{ D[i, j] = diff(J[i], var(j)); }} }}"]
    if k:
        config = "*".join(a.ring.names[:n])
        lengths = "*".join(a.ring.names[n:])
        lines += ["t = timer; list L = minAssGTZ(minor(D, %d)); ideal C = 1;" % r,
                  "for (i = 1; i <= size(L); i++) { ideal SP = std(J + L[i]); if (SP[1] != 1) {"
                  f" ideal E = eliminate(SP, {config}); C = intersect(C, sat(E, {lengths})[1]); }} }}",
                  "list FC = factorize(C[1]);", 'print("STAGE length conditions " + string(timer - t));']
        return "\n".join(lines)
    lines += [f"t = timer; list SV = minAssGTZ(J + minor(D, {r}));",
              'print("STAGE singular configurations " + string(timer - t));']
    lines += local_script(a)
    if depth == "full":  # last: Singular may not finish it
        lines += ["t = timer; list M = minAssGTZ(J);", 'print("STAGE decomposition " + string(timer - t));']
    return "\n".join(lines)


def local_script(a) -> list[str]:
    """The tangent cone of J (radical here) at each singular configuration that is a point: J moved
    to the point (over ``Q(t)`` with the minimal polynomial of a primitive element for a Galois orbit
    of algebraic points), ``tangentcone`` (sing.lib: a standard basis for ``ds``, its lowest forms)."""
    from mech.dsl.printing import poly_str
    from mech.stdlib.standard import normalize
    points = [s for s in a.singular if s.point is not None or s.algebraic is not None]
    if not points or not a.radical:
        return []
    names = ",".join(a.ring.names)
    lines = ['LIB "sing.lib"; t = timer;']
    for k, s in enumerate(points):
        if s.point is not None:
            lines.append(f"ring L{k} = 0, ({names}), dp;")
            shift = [f"{x}+({c})" for x, c in zip(a.ring.names, s.point)]
        else:
            pt = s.algebraic
            t = pt.ring.names[-1]
            lines.append(f"ring L{k} = (0,{t}), ({names}), dp; minpoly = {poly_str(normalize(pt.minpoly))};")
            shift = [f"{x}+({poly_str(c)})" for x, c in zip(a.ring.names, pt.coords)]
        lines.append(f"ideal J{k} = fetch(R, J); map sh{k} = L{k}, {', '.join(shift)}; "
                     f"ideal C{k} = tangentcone(sh{k}(J{k})); setring R;")
    lines.append('print("STAGE local analysis " + string(timer - t));')
    return lines


def singular_stages(script: str, timeout: float) -> dict[str, float | None]:
    """Seconds of each step Singular finished (None: the step it was in when the time ran out)."""
    try:
        out = subprocess.run([SINGULAR, "-q", "--no-warn"], input=script + "\nquit;\n", text=True,
                             capture_output=True, timeout=timeout).stdout
    except subprocess.TimeoutExpired as e:
        out = (e.stdout or b"").decode() if isinstance(e.stdout, bytes) else (e.stdout or "")
    got: dict[str, float | None] = {m[1]: int(m[2]) / 1000 for m in re.finditer(r"STAGE (.+) (\d+)\n", out)}
    for step in re.findall(r'print\("STAGE ([a-z ]+) "', script):
        if step not in got:
            got[step] = None
            break
    return got


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("cases", nargs="*", help="names (prefixes) of cases; default all")
    p.add_argument("--singular-timeout", type=float, default=120.0)
    p.add_argument("--repeat", type=int, default=1, help="alternate mech and Singular this often, keep the minima")
    args = p.parse_args(argv)
    cases = [c for c in CASES if not args.cases or any(c.name.startswith(x) for x in args.cases)]
    print("| mechanism | stage | mech CPU s | Singular s | ratio |\n|---|---|---|---|---|")
    for case in cases:
        spent, total, theirs = {}, float("inf"), {}
        for _ in range(max(args.repeat, 1)):
            got, t, a = mech_stages(case)
            total = min(total, t)
            spent = {k: min(v, spent.get(k, v)) for k, v in got.items()}
            if SINGULAR:
                ref = singular_stages(singular_script(a, case.depth), args.singular_timeout)
                theirs = {k: min((x for x in (ref.get(k), theirs.get(k)) if x is not None), default=None)
                          for k in {**theirs, **ref}}
        for stage in STAGES:
            if stage not in theirs:
                continue
            ours, ref = spent.get(stage), theirs[stage]
            ratio = f"{ours / ref:.1f}" if ours is not None and ref is not None and ref >= 0.01 else "-"
            shown = "did not finish" if ref is None else f"{ref:.3f}"
            print(f"| {case.name} | {stage} | {ours if ours is None else round(ours, 3)} | {shown} | {ratio} |")
        print(f"| {case.name} | whole analysis (mech, in process) | {total:.3f} | | |")
        sys.stdout.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
