"""The real circuits of Watt I six-bars, exactly (the report's real answers) and by an
independent witness: the configurations sampled densely over the input angle (the four-bar
loop's two assembly branches, the dyad's two), pieces joined where they come together."""
from __future__ import annotations

import numpy as np
import pytest

from mech.stdlib.analysis import analyze
from mech.stdlib.circuit_counts import circuit_count
from mech.stdlib.mechanism import parse_mechanism


def _meet(P, rp, Q, rq, side):
    """The point at distances ``rp`` from P and ``rq`` from Q on ``side`` of PQ (per sample), and
    where it exists."""
    d = Q - P
    L = np.sqrt((d ** 2).sum(0))
    a = (rp ** 2 - rq ** 2 + L ** 2) / (2 * L)
    h2 = rp ** 2 - a ** 2
    u = d / L
    return P + a * u + side * np.sqrt(np.where(h2 >= 0, h2, 0)) * np.array([-u[1], u[0]]), h2 >= 0


def _on_body(P, Q, dist, local):
    u = (Q - P) / dist
    return P + local[0] * u + local[1] * np.array([-u[1], u[0]])


def sampled_watt_i(ground, ob, e, bc, f, ca, eh, hf, steps=200000, gap=0.05):
    """Circuits of the Watt I ``ground O A ground; body O B ob 0 E e; body B C bc 0 F f; bar C A ca;
    bar E H eh; bar H F hf`` from samples of the crank angle: each assembly branch (C's side, H's
    side) splits into runs of consecutive feasible samples; runs of different branches are joined
    where their points come within ``gap`` (where the branches meet)."""
    th = np.linspace(0, 2 * np.pi, steps, endpoint=False)
    O, A = np.zeros((2, steps)), np.array([[ground], [0.0]]) * np.ones(steps)
    B = ob * np.array([np.cos(th), np.sin(th)])
    branches = {}
    for s in (1, -1):
        C, ok_c = _meet(B, bc, A, ca, s)
        E, F = _on_body(O, B, ob, e), _on_body(B, C, bc, f)
        for t in (1, -1):
            H, ok_h = _meet(E, eh, F, hf, t)
            branches[s, t] = (np.concatenate([C, H]), ok_c & ok_h)
    parent: dict = {}

    def find(i):
        while parent[i] != i:
            i = parent[i]
        return i
    run_of = {}
    for key, (_, ok) in branches.items():
        ids = np.full(steps, -1)
        idx = np.flatnonzero(ok)
        for run in np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1) if len(idx) else []:
            parent[(key, int(run[0]))] = (key, int(run[0]))
            ids[run] = int(run[0])
        if ok[0] and ok[-1] and not ok.all():  # the run through angle 0 continues after 2 pi
            parent[find((key, int(ids[-1])))] = find((key, int(ids[0])))
        run_of[key] = ids
    keys = list(branches)
    for i, k1 in enumerate(keys):
        for k2 in keys[i + 1:]:
            (X1, ok1), (X2, ok2) = branches[k1], branches[k2]
            close = ok1 & ok2 & (np.sqrt(((X1 - X2) ** 2).sum(0)) < gap)
            for j in np.flatnonzero(close):
                parent[find((k1, int(run_of[k1][j])))] = find((k2, int(run_of[k2][j])))
    return len({find(r) for r in parent})


WATT_I = [  # lengths; the third (issue 18) has a pair of real algebraic singular configurations
    ((4, 3, (2, 2), 4, (2, 2), 2, 3, 3), 4),
    ((5, 2, (1, 2), 4, (2, 2), 3, 3, 2), 3),
]


@pytest.mark.parametrize("lengths,circuits", WATT_I, ids=["issue 18", "third"])
def test_watt_i_circuits(lengths, circuits):
    g, ob, e, bc, f, ca, eh, hf = lengths
    assert sampled_watt_i(*lengths) == circuits
    a = analyze(parse_mechanism(f"ground O A {g}; body O B {ob} 0 E {e[0]} {e[1]}; body B C {bc} 0 F {f[0]} {f[1]}; "
                                f"bar C A {ca}; bar E H {eh}; bar H F {hf}"))
    assert sum(circuit_count(m.prime, a.ring, True) for m in a.modes if m.dim == 1 and m.real) == circuits
