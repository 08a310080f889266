"""The benchmark systems.

A :class:`Case` is a ring and generators in Singular syntax, so that mech (through its own
front end), Singular and SymPy all read the same text.  To add a row (e.g. a paper example),
append a ``Case`` to :data:`CASES`; ``sympy=False`` skips SymPy (block orderings, which SymPy
does not have, or systems far beyond its reach).
"""
from __future__ import annotations

from dataclasses import dataclass, field
import re
from itertools import product
from pathlib import Path


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


def eco(n: int) -> tuple[list[str], list[str]]:
    """eco-n (Morgan, *Solving Polynomial Systems Using Continuation*, 1987): for k = 1..n-1,
    ``(x_k + sum_{i=1}^{n-k-1} x_i x_{i+k}) x_n - k``, and ``x_1 + ... + x_{n-1} + 1``."""
    names = [f"x{i + 1}" for i in range(n)]
    gens = []
    for k in range(1, n):
        p = _var(k - 1, n)
        for i in range(1, n - k):
            p = _add(p, _mul(_var(i - 1, n), _var(i + k - 1, n)))
        gens.append(_add(_mul(p, _var(n - 1, n)), {(0,) * n: k}, -1))
    p = {(0,) * n: 1}
    for i in range(n - 1):
        p = _add(p, _var(i, n))
    gens.append(p)
    return names, [_render(g, names) for g in gens]


def noon(n: int) -> tuple[list[str], list[str]]:
    """noon-n (Noonburg's neural network, SIAM J. Appl. Math. 49, 1989), scaled to integers:
    ``10 x_i sum_{j != i} x_j^2 - 11 x_i + 10``."""
    names = [f"x{i + 1}" for i in range(n)]
    gens = []
    for i in range(n):
        s: Poly = {}
        for j in range(n):
            if j != i:
                s = _add(s, _mul(_var(j, n), _var(j, n)))
        p = _add(_mul({tuple(1 if k == i else 0 for k in range(n)): 10}, s), _var(i, n), -11)
        gens.append(_add(p, {(0,) * n: 10}))
    return names, [_render(g, names) for g in gens]


def reimer(n: int) -> tuple[list[str], list[str]]:
    """reimer-n (the PoSSo test suite): for k = 2..n+1, ``sum_i (-1)^(i+1) 2 x_i^k - 1``."""
    names = [f"x{i + 1}" for i in range(n)]
    gens = []
    for k in range(2, n + 2):
        p: Poly = {(0,) * n: -1}
        for i in range(n):
            p = _add(p, {tuple(k if j == i else 0 for j in range(n)): 2 * (-1) ** i})
        gens.append(p)
    return names, [_render(g, names) for g in gens]


def hcyclic(n: int) -> tuple[list[str], list[str]]:
    """homogeneous cyclic-n: cyclic-n with ``x_1...x_n - h^n`` (variables x1..xn, h)."""
    names, gens = cyclic(n)
    assert gens[-1].endswith("-1")
    return names + ["h"], gens[:-1] + [gens[-1][:-2] + f"-h^{n}"]


M2_EXAMPLES = Path("/usr/share/Macaulay2/MinimalPrimes/tests.m2")


def m2_examples() -> list[tuple[str, int, list[str], list[str], str]]:
    """The ideals of Macaulay2's MinimalPrimes tests (read from an installed Macaulay2, never
    copied here): ``(name, characteristic, variables, generators, M2 text)`` for those with
    single-letter variables over QQ or ZZ/p, in Singular's short syntax."""
    if not M2_EXAMPLES.exists():
        return []
    text = M2_EXAMPLES.read_text()
    out = []
    for k, block in enumerate(text.split("TEST ///")[1:]):
        block = block.split("///")[0]
        ring = re.search(r"R\s*=\s*(QQ|ZZ/(\d+)|kk)\s*\[([^\]]*)\]", block)
        ideal = re.search(r'I\s*=\s*ideal\s*"([^"]*)"', block) or re.search(r"I\s*=\s*ideal\s*\(([^;]*?)\)\s*\n", block)
        if not ring or not ideal:
            continue
        field = ring.group(1)
        if field == "kk":
            m = re.search(r"kk\s*=\s*(QQ|ZZ/(\d+))", block)
            if not m:
                continue
            field, char = m.group(1), int(m.group(2) or 0)
        else:
            char = int(ring.group(2) or 0)
        names = [v.strip() for v in ring.group(3).split(",")]
        if not all(re.fullmatch(r"[a-z]", v) for v in names):
            continue
        gens = [g.strip() for g in " ".join(ideal.group(1).split()).split(",") if g.strip()]
        comment = re.search(r"--\s*(\w[\w-]*)\s*\(DGP", block)
        name = comment.group(1) if comment else f"MinimalPrimes test {k + 1}"
        out.append((name, char, names, gens, block))
    return out


LOCAL = [  # standard bases in local orderings: isolated singularities and space curve germs
    ("space curve germ", ["x", "y", "z"], ["7*x*y*z+z^5", "x^2+y^3+z^7", "5*z^5+y^5"]),
    ("jacobian of x^5+y^5+z^5+x^2*y^2*z^2", ["x", "y", "z"],
     ["5*x^4+2*x*y^2*z^2", "5*y^4+2*x^2*y*z^2", "5*z^4+2*x^2*y^2*z"]),
    ("T(4,5,6) jacobian", ["x", "y", "z"], ["4*x^3+y*z", "5*y^4+x*z", "6*z^5+x*y"]),
]


def _standard() -> list[Case]:
    cases = []
    families = [("katsura", katsura, (5, 6, 7, 8, 9)), ("cyclic", cyclic, (5, 6, 7)), ("eco", eco, (7, 8)),
                ("noon", noon, (5, 6)), ("reimer", reimer, (5,)), ("hcyclic", hcyclic, (5, 6))]
    gerdt = [e for e in m2_examples() if e[0] == "gerdt"]
    for char in (0, 32003):
        for fam, make, sizes in families:
            for n in sizes:
                names, gens = make(n)
                cases.append(Case(f"{fam}-{n}", char, names, "dp", gens, sympy=n <= 6 and fam != "hcyclic"))
        for _, _, names, gens, _ in gerdt:
            cases.append(Case("gerdt", char, names, "dp", gens, sympy=False, notes="DGP/PoSSo, from Macaulay2's files"))
    # lexicographic bases and eliminations (zero-dimensional: FGLM)
    for char in (0, 32003):
        for name, (names, gens) in [("katsura-4", katsura(4)), ("katsura-5", katsura(5)), ("cyclic-5", cyclic(5))]:
            cases.append(Case(name, char, names, "lp", gens, sympy=name == "katsura-4"))
        for name, (names, gens), order in [("katsura-5", katsura(5), "(dp(3),dp(3))"),
                                            ("katsura-6", katsura(6), "(dp(3),dp(4))"),
                                            ("cyclic-6", cyclic(6), "(dp(3),dp(3))")]:
            cases.append(Case(name, char, names, order, gens, sympy=False))
    # eliminations with block orderings (positive-dimensional: Hilbert-driven)
    elim = ["x^2+y*u-1", "y^2-x*v", "z^3-u^2*v", "x*y*z-u-v"]
    for char in (0, 32003):
        cases.append(Case("block (dp(3),dp(2))", char, ["x", "y", "z", "u", "v"], "(dp(3),dp(2))", elim,
                          sympy=False, notes="the block-ordered system of tests/kernel/test_groebner.py"))
    fourbar = ["4+3*c3-2*c1-4*c2", "3*s3-2*s1-4*s2", "x-2*c1-2*c2+s2", "y-2*s1-2*s2-c2",
               "c1^2+s1^2-1", "c2^2+s2^2-1", "c3^2+s3^2-1"]
    cases.append(Case("four-bar coupler curve", 0, ["c1", "s1", "c2", "s2", "c3", "s3", "x", "y"],
                      "(dp(6),dp(2))", fourbar, sympy=False,
                      notes="eliminates the joint angles of a four-bar linkage: a sextic in x, y"))
    fivebar = ["c1+c2+c3+c4-2", "s1+s2+s3+s4", "c1^2+s1^2-1", "c2^2+s2^2-1", "c3^2+s3^2-1", "c4^2+s4^2-1",
               "y1-c1-s1", "y2-c2-s2", "y3-c3-s3"]
    cases.append(Case("five-bar projection", 0, ["c1", "s1", "c2", "s2", "c3", "s3", "c4", "s4", "y1", "y2", "y3"],
                      "(dp(8),dp(3))", fivebar, sympy=False, notes="examples/fivebar.mech's elimination"))
    for name, names, gens in LOCAL:
        cases.append(Case(name, 0, names, "ds", gens, sympy=False))
    cases.append(Case("ring of 10^4 variables", 0, ["x(1..10000)"], "dp", [], sympy=False,
                      notes="ring creation only"))
    return cases


CASES: list[Case] = _standard()
"""The rows of the table, in order; append paper examples here."""
