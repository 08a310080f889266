"""The analysis of mechanisms stage by stage, in mech and in the same steps hand-written in Singular.

    python benchmarks/analysis_stages.py            # every case, a Markdown table on stdout
    python benchmarks/analysis_stages.py kite watt  # some cases

mech: ``analyze`` in a fresh Session of this process, the CPU time of each stage read from its
progress events (``Session(progress=...)``).  Singular: ``timer`` (1 ms ticks) around each step
of the paper's pipeline, start-up and ``LIB`` loading excluded: ``std`` and ``dim`` of J (mech's
dimension stage), ``minAssGTZ(J)`` (the motion modes: mech's decomposition stage, whatever
strategy certifies them), ``minAssGTZ(J + I_r(dJ))`` (the singular configurations), then at the
singular configurations that are points, from mech's motion modes and points (the same input for
both): the points (a primitive element's basis ``std(P + (t - form))`` for a Galois orbit of
algebraic points, and the modes through each point by ``reduce``), the local components (at a
rational point the modes through it, moved there; at conjugate points ``minAssGTZ`` of each mode
through them moved there, in ``ring (0,t), (x), ds`` with the minimal polynomial: Singular's local
components; at a point with several, sing.lib's ``tangentcone`` of each for the transition test),
and the tangent cones (sing.lib's ``tangentcone`` of J moved to the point, over ``Q(t)`` with the
minimal polynomial for conjugate points); for symbolic lengths the eliminations of the lengths
(the length conditions).  The steps that may not finish (the decomposition, the local components)
run in Singular processes of their own, each within ``--singular-timeout`` seconds, reported as
"did not finish" otherwise; ratios only where Singular takes at least 10 ms (below, the timer's
resolution decides).  ``--repeat N`` runs mech and Singular alternately N times per case and
keeps each stage's minimum (the machine's load varies from one run to the next).
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
STAGES = ["dimension", "decomposition", "singular configurations", "points", "local components", "tangent cones",
          "length conditions"]


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


def singular_script(a, depth: str) -> list[str]:
    """The pipeline's steps in Singular, each printing ``STAGE name ms``: one script per process (the
    steps that may not finish, the decomposition and the local components, have their own)."""
    from mech.dsl.printing import poly_str
    n, k = a.nvars, len(a.params)
    order = f"(dp({n}),dp({k}))" if k else "dp"
    J = ", ".join(poly_str(g) for g in a.ideal)
    r = len(a.ideal) if a.complete_intersection else n - a.mobility
    # the timer's variable is not ``t``: an int named t would stand for the parameter t of Q(t)
    head = ['LIB "primdec.lib"; LIB "elim.lib"; LIB "sing.lib"; system("--ticks-per-sec", 1000); int tic; int i; '
            'int j;', f"ring R = 0, ({','.join(a.ring.names)}), {order};", f"ideal J = {J};"]
    lines = head + ["tic = timer; ideal S = std(J); int d = dim(S);", 'print("STAGE dimension " + string(timer - tic));',
                    f"matrix D[{len(a.ideal)}][{n}];",
                    f"for (i = 1; i <= {len(a.ideal)}; i++) {{ for (j = 1; j <= {n}; j++) "
                    "{ D[i, j] = diff(J[i], var(j)); } }"]
    if k:
        config = "*".join(a.ring.names[:n])
        lengths = "*".join(a.ring.names[n:])
        lines += ["tic = timer; list L = minAssGTZ(minor(D, %d)); ideal C = 1;" % r,
                  "for (i = 1; i <= size(L); i++) { ideal SP = std(J + L[i]); if (SP[1] != 1) {"
                  f" ideal E = eliminate(SP, {config}); C = intersect(C, sat(E, {lengths})[1]); }} }}",
                  "list FC = factorize(C[1]);", 'print("STAGE length conditions " + string(timer - tic));']
        return ["\n".join(lines)]
    lines += [f"tic = timer; list SV = minAssGTZ(J + minor(D, {r}));",
              'print("STAGE singular configurations " + string(timer - tic));']
    scripts = ["\n".join(lines + points_script(a) + cones_script(a))]
    if depth == "full":
        scripts.append("\n".join(head + components_script(a)))
        scripts.append("\n".join(head + ["tic = timer; list M = minAssGTZ(J);",
                                          'print("STAGE decomposition " + string(timer - tic));']))
    return scripts


def _points(a) -> list:
    """The singular configurations that are points (rational, or a Galois orbit of algebraic points)."""
    return [s for s in a.singular if s.point is not None or s.algebraic is not None]


def _ideal(polys) -> str:
    from mech.dsl.printing import poly_str
    return ", ".join(poly_str(g) for g in polys) or "0"


def _point_ring(a, k: int, s, order: str) -> list[str]:
    """``ring L{k}`` (over ``Q(t)`` with the minimal polynomial for conjugate points) and ``map sh{k}``
    moving the point to the origin."""
    from mech.dsl.printing import poly_str
    from mech.stdlib.standard import normalize
    names = ",".join(a.ring.names)
    if s.point is not None:
        shift = [f"{x}+({c})" for x, c in zip(a.ring.names, s.point)]
        return [f"ring L{k} = 0, ({names}), {order};", f"map sh{k} = R, {', '.join(shift)};"]
    pt = s.algebraic
    shift = [f"{x}+({poly_str(c)})" for x, c in zip(a.ring.names, pt.coords)]
    return [f"ring L{k} = (0,{pt.ring.names[-1]}), ({names}), {order}; minpoly = {poly_str(normalize(pt.minpoly))};",
            f"map sh{k} = R, {', '.join(shift)};"]


def points_script(a) -> list[str]:
    """The points of the singular configurations: for a Galois orbit of algebraic points the basis of
    ``P + (t - form)`` for ``(dp(n), dp(1))`` (the primitive element's shape basis), and at every point the
    modes through it (``reduce`` of each mode modulo the point's prime)."""
    from mech.dsl.printing import poly_str
    points = _points(a)
    if not points:
        return []
    n, names = a.nvars, ",".join(a.ring.names)
    lines = [f"ideal M{i} = {_ideal(md.prime)};" for i, md in enumerate(a.modes)] + ["tic = timer;"]
    for k, s in enumerate(points):
        lines.append(f"ideal P{k} = std(ideal({_ideal(s.prime)}));")
        lines += [f"int on{k}_{i} = size(reduce(M{i}, P{k})) == 0;" for i in range(len(a.modes))]
        if s.point is None:
            pt = s.algebraic
            lines += [f"ring E{k} = 0, ({names},{pt.ring.names[-1]}), (dp({n}),dp(1));",
                      f"ideal G{k} = std(imap(R, P{k}) + ideal({pt.ring.names[-1]} - ({poly_str(pt.form)})));", "setring R;"]
    lines.append('print("STAGE points " + string(timer - tic));')
    return lines


def components_script(a) -> list[str]:
    """The local components at each point, from the motion modes through it: at a rational point the
    modes moved there (a prime stays prime in the localization), at conjugate points ``minAssGTZ`` of
    each mode moved there in a ``ds`` ring over ``Q(t)`` (Singular's minimal primes in the local ring);
    with several components sing.lib's ``tangentcone`` of each (the transition test)."""
    points = _points(a)
    if not points or not a.decomposed:
        return []
    lines = [f"ideal M{i} = {_ideal(md.prime)};" for i, md in enumerate(a.modes)] + ["tic = timer;"]
    for k, s in enumerate(points):
        through = [i - 1 for i in s.modes]
        lines += _point_ring(a, k, s, "ds") + [f"list C{k};"]
        for i in through:
            if s.point is not None:
                lines.append(f"C{k} = insert(C{k}, sh{k}(M{i}));")
            else:
                lines.append(f"C{k} = C{k} + minAssGTZ(sh{k}(M{i}));")
        lines.append(f"if (size(C{k}) > 1) {{ for (i = 1; i <= size(C{k}); i++) {{ ideal T = tangentcone(C{k}[i]); }} }}")
        lines.append("setring R;")
    lines.append('print("STAGE local components " + string(timer - tic));')
    return lines


def cones_script(a) -> list[str]:
    """The tangent cone of J (radical here) at each singular configuration that is a point: J moved
    to the point (over ``Q(t)`` with the minimal polynomial of a primitive element for a Galois orbit
    of algebraic points), ``tangentcone`` (sing.lib: a standard basis for ``ds``, its lowest forms)."""
    points = _points(a)
    if not points or not a.radical:
        return []
    lines = ["tic = timer;"]
    for k, s in enumerate(points):
        lines += _point_ring(a, k, s, "dp")
        lines.append(f"ideal TC{k} = tangentcone(sh{k}(J)); setring R;")
    lines.append('print("STAGE tangent cones " + string(timer - tic));')
    return lines


def singular_stages(scripts: list[str], timeout: float) -> dict[str, float | None]:
    """Seconds of each step Singular finished (None: the step it was in when the time ran out), each
    script in a process of its own."""
    got: dict[str, float | None] = {}
    for script in scripts:
        try:
            out = subprocess.run([SINGULAR, "-q", "--no-warn"], input=script + "\nquit;\n", text=True,
                                 capture_output=True, timeout=timeout).stdout
        except subprocess.TimeoutExpired as e:
            out = (e.stdout or b"").decode() if isinstance(e.stdout, bytes) else (e.stdout or "")
        done = {m[1]: int(m[2]) / 1000 for m in re.finditer(r"STAGE (.+) (\d+)\n", out)}
        got.update(done)
        for step in re.findall(r'print\("STAGE ([a-z ]+) "', script):
            if step not in done:
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
