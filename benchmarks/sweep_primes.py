"""Would distributing mech's own heavy steps pay?  The candidate: one prime per task in modular
Gröbner bases (kernel/modular.py: the first prime learns an F4 trace, every further prime replays
it).  This times, for a few systems over QQ, the replays of K primes in this process and as Dask
tasks on a warm 2-worker LocalCluster (the trace and the input scattered once, primes in K/8
batches), and prints the speed-up.  ``python benchmarks/sweep_primes.py [K]``."""
from __future__ import annotations

import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))


def system(name: str):
    """(ring, generators) of a benchmark system in dp."""
    from benchmarks.cases import cyclic, katsura
    from mech import Session
    fam, n = name.split("-")
    names, gens = (katsura if fam == "katsura" else cyclic)(int(n))
    s = Session(warnings=False)
    s.execute(f"ring r = 0,({','.join(names)}),dp; ideal I = {', '.join(gens)};")
    ideal = s["I"]
    return ideal.ring, list(ideal.gens)


def replays(trace, coefs, ps):
    from mech.kernel.f4_trace import TraceMismatch, replay
    out = 0
    for p in ps:
        try:
            replay(trace, [[c % p for c in cs] for cs in coefs], p)
            out += 1
        except TraceMismatch:
            pass
    return out


def main(k: int = 48) -> None:
    from distributed import Client, LocalCluster
    from mech.kernel.f4 import F4, initial_degree
    from mech.kernel.modular import _pack, primes, primitive
    from mech.kernel.monomials import Packing
    start = time.perf_counter()
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0")
    client = Client(cluster)
    client.run(lambda: __import__("mech.kernel.f4_trace"))
    print(f"LocalCluster (2 workers) started in {time.perf_counter() - start:.1f} s")
    print("| system | learn (1st prime) | replay per prime | K primes in-process | K primes on 2 workers | speed-up |")
    print("|---|---|---|---|---|---|")
    try:
        for name in ("katsura-6", "katsura-7", "cyclic-6"):
            ring, gens = system(name)
            ints = [primitive(g.terms) for g in gens]
            P = Packing(ring.order, initial_degree(gens))
            shapes, coefs = _pack(ints, P)
            stream = primes()
            p0 = next(stream)
            t = time.perf_counter()
            engine = F4([(ms, [c % p0 for c in cs]) for ms, cs in zip(shapes, coefs)], P, p0, record=True)
            engine.run()
            learn = time.perf_counter() - t
            ps = [next(stream) for _ in range(k)]
            t = time.perf_counter()
            replays(engine.trace, coefs, ps)
            local = time.perf_counter() - t
            t = time.perf_counter()
            trace_f, coefs_f = client.scatter([engine.trace, coefs], broadcast=True)
            size = max(1, k // 8)
            futures = [client.submit(replays, trace_f, coefs_f, ps[i:i + size], pure=False) for i in range(0, k, size)]
            client.gather(futures)
            remote = time.perf_counter() - t
            print(f"| {name} | {learn:.2f} s | {local / k * 1000:.0f} ms | {local:.2f} s | {remote:.2f} s | "
                  f"{local / remote:.2f}x |")
    finally:
        client.close()
        cluster.close()


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 48)
