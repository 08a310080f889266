"""The benchmark systems.

A :class:`Case` is a ring and generators in Singular syntax, so that mech (through its own
front end), Singular and SymPy all read the same text.  To add a row (e.g. a paper example),
append a ``Case`` to :data:`CASES`; ``sympy=False`` skips SymPy (block orderings, which SymPy
does not have, or systems far beyond its reach).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from itertools import product


@dataclass
class Case:
    name: str
    char: int                  # 0 for QQ, else a prime
    variables: list[str]
    ordering: str              # Singular syntax: dp, lp, Dp, (dp(4),dp(2)), wp(1,2,3), ...
    gens: list[str]            # polynomials in Singular syntax (*, ^, +, -, integers, a/b)
    sympy: bool = True         # run SymPy's groebner (only for lp, dp, Dp)
    notes: str = field(default="")

    @property
    def field(self) -> str:
        return "QQ" if self.char == 0 else f"Z/{self.char}"


Poly = dict[tuple[int, ...], int]


def _render(p: Poly, names: list[str]) -> str:
    out = []
    for e, c in sorted(p.items(), reverse=True):
        mono = "*".join(n if k == 1 else f"{n}^{k}" for n, k in zip(names, e) if k)
        if not mono:
            term = str(abs(c))
        else:
            term = mono if abs(c) == 1 else f"{abs(c)}*{mono}"
        out.append(("-" if c < 0 else "+") + term)
    s = "".join(out)
    return s[1:] if s.startswith("+") else s


def _add(p: Poly, q: Poly, c: int = 1) -> Poly:
    r = dict(p)
    for e, v in q.items():
        r[e] = r.get(e, 0) + c * v
        if r[e] == 0:
            del r[e]
    return r


def _mul(p: Poly, q: Poly) -> Poly:
    r: Poly = {}
    for (e, a), (f, b) in product(p.items(), q.items()):
        g = tuple(x + y for x, y in zip(e, f))
        r[g] = r.get(g, 0) + a * b
    return {e: c for e, c in r.items() if c}


def _var(i: int, n: int) -> Poly:
    return {tuple(1 if j == i else 0 for j in range(n)): 1}


def katsura(n: int) -> tuple[list[str], list[str]]:
    """katsura-n in the variables x0..xn (as in ``reference/bench/katsura.sing``)."""
    names = [f"x{i}" for i in range(n + 1)]
    N = n + 1

    def X(i: int) -> Poly:
        i = abs(i)
        return _var(i, N) if i <= n else {}
    one = {(0,) * N: 1}
    p: Poly = {}
    for j in range(-n, n + 1):
        p = _add(p, X(j))
    gens = [_add(p, one, -1)]
    for m in range(n):
        p = {}
        for j in range(-n, n + 1):
            p = _add(p, _mul(X(j), X(m - j)))
        gens.append(_add(p, X(m), -1))
    return names, [_render(g, names) for g in gens]


def cyclic(n: int) -> tuple[list[str], list[str]]:
    """cyclic-n in the variables x1..xn (as in ``reference/bench/cyclic.sing``)."""
    names = [f"x{i + 1}" for i in range(n)]
    gens = []
    for d in range(1, n):
        p: Poly = {}
        for i in range(n):
            t = {(0,) * n: 1}
            for k in range(d):
                t = _mul(t, _var((i + k) % n, n))
            p = _add(p, t)
        gens.append(p)
    t = {(0,) * n: 1}
    for i in range(n):
        t = _mul(t, _var(i, n))
    gens.append(_add(t, {(0,) * n: 1}, -1))
    return names, [_render(g, names) for g in gens]


def _standard() -> list[Case]:
    cases = []
    for char in (0, 32003):
        for n in (5, 6, 7):
            names, gens = katsura(n)
            cases.append(Case(f"katsura-{n}", char, names, "dp", gens, sympy=n < 7))
        for n in (5, 6):
            names, gens = cyclic(n)
            cases.append(Case(f"cyclic-{n}", char, names, "dp", gens))
    # eliminations with block orderings
    elim = ["x^2+y*u-1", "y^2-x*v", "z^3-u^2*v", "x*y*z-u-v"]
    for char in (0, 32003):
        cases.append(Case("block (dp(3),dp(2))", char, ["x", "y", "z", "u", "v"], "(dp(3),dp(2))", elim,
                          sympy=False, notes="the block-ordered system of tests/kernel/test_groebner.py"))
    names, gens = katsura(5)
    cases.append(Case("katsura-5 (lp(2),dp(4))", 0, names, "(lp(2),dp(4))", gens, sympy=False))
    fourbar = ["4+3*c3-2*c1-4*c2", "3*s3-2*s1-4*s2", "x-2*c1-2*c2+s2", "y-2*s1-2*s2-c2",
               "c1^2+s1^2-1", "c2^2+s2^2-1", "c3^2+s3^2-1"]
    cases.append(Case("four-bar coupler curve", 0, ["c1", "s1", "c2", "s2", "c3", "s3", "x", "y"],
                      "(dp(6),dp(2))", fourbar, sympy=False,
                      notes="eliminates the joint angles of a four-bar linkage: a sextic in x, y"))
    return cases


CASES: list[Case] = _standard()
"""The rows of the table, in order; append paper examples here."""
