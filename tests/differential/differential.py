"""Differential testing against Singular: random ideals (sparse polynomials with small coefficients
over QQ and Z/32003) in random orderings, blocks included, sent through mech's language and through
Singular 4.3.1; the results are parsed into polynomials and compared.

* global orderings: ``std`` as reduced bases (Singular under ``option(redSB)``), and ``eliminate``
  (both results brought to reduced bases by ``std``);
* local and mixed orderings: the leading ideal of ``std`` (its minimal monomial generators), which
  every standard basis shares;
* decompositions of intersections of random ideals (some with squared generators, so that
  primaries are not prime): ``minAssGTZ`` as sets of primes, ``primdecGTZ`` as the set of
  associated primes plus the primary components of the minimal ones (embedded components are
  not unique); every component brought to its reduced basis by ``std``;
* ``tangentcone`` of random ideals through the origin, as reduced bases.

A case passes when the bases are equal as sets of monic polynomials; the printed bases are also
compared line by line (a difference there alone is a printing mismatch).  mech runs each case
under a time limit; a case that exceeds it is counted, not failed.

    python -m tests.differential.differential --seed 1 --count 200 [--char 0|32003] [--show 5]
"""
from __future__ import annotations

import argparse
import random
import re
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass, field
from fractions import Fraction

SINGULAR = shutil.which("Singular")
P = 32003
NAMES = "xyzwuv"
GLOBAL = ["dp", "lp", "Dp", "wp", "Wp", "dp-blocks", "lp-dp", "dp-lp", "a-dp", "a-lp", "M", "Dp-wp"]
LOCAL = ["ds", "ls", "Ds", "ws", "dp-ds", "ds-dp", "lp-ls"]


@dataclass
class Case:
    number: int
    kind: str                # "std" | "eliminate" | "local" | "minass" | "primdec" | "tangentcone"
    char: int
    names: str
    ordering: str
    gens: list[str]
    elim: str = ""           # the product of the variables to eliminate

    def ring(self) -> str:
        return f"ring r = {self.char}, ({','.join(self.names)}), {self.ordering};"

    def command(self) -> str:
        if self.kind == "eliminate":
            return f"std(eliminate(I, {self.elim}));"
        if self.kind == "minass":
            return ('list L = minAssGTZ(I); int k;\n'
                    'for (k = 1; k <= size(L); k++) { "@@comp"; std(L[k]); } kill k;')
        if self.kind == "primdec":
            return ('list L = primdecGTZ(I); int k;\n'
                    'for (k = 1; k <= size(L); k++) { "@@comp"; std(L[k][1]); "@@prime"; std(L[k][2]); } kill k;')
        if self.kind == "tangentcone":
            return "std(tangentcone(I));"
        return "std(I);"

    def ideal(self) -> str:
        if self.kind in ("minass", "primdec"):
            return f"intersect({', '.join(self.gens)})"
        return ", ".join(self.gens)

    def script(self) -> str:
        """The case as a script both systems read."""
        return f"{self.ring()}\nideal I = {self.ideal()};\n{self.command()}\n"


# ---------------------------------------------------------------- random cases
def _weights(rng: random.Random, n: int) -> str:
    return ",".join(str(rng.randint(1, 4)) for _ in range(n))


def random_ordering(rng: random.Random, n: int, kind: str) -> str:
    k = rng.randint(1, n - 1) if n > 1 else 1
    if kind in ("dp", "lp", "Dp", "ds", "ls", "Ds"):
        return kind
    if kind in ("wp", "Wp", "ws"):
        return f"{kind}({_weights(rng, n)})"
    if n == 1:
        return "dp" if kind in GLOBAL else "ds"
    blocks = {"dp-blocks": ("dp", "dp"), "lp-dp": ("lp", "dp"), "dp-lp": ("dp", "lp"), "dp-ds": ("dp", "ds"),
              "ds-dp": ("ds", "dp"), "lp-ls": ("lp", "ls"), "Dp-wp": ("Dp", "wp")}
    if kind in blocks:
        a, b = blocks[kind]
        second = f"wp({_weights(rng, n - k)})" if b == "wp" else f"{b}({n - k})"
        return f"({a}({k}),{second})"
    if kind in ("a-dp", "a-lp"):  # not all zero: Singular's eliminate loops forever on (a(0,0),lp)
        w = [rng.randint(0, 3) for _ in range(n)]
        w[rng.randrange(n)] = rng.randint(1, 3)
        w = ",".join(map(str, w))
        return f"(a({w}),{kind[2:]})"
    if kind == "M":  # first row positive (global), the others random, the matrix invertible
        from mech.kernel import Block, MonomialOrder
        from mech.kernel.errors import OrderingError
        while True:
            entries = [rng.randint(1, 3) for _ in range(n)] + [rng.randint(-2, 2) for _ in range(n * n - n)]
            try:
                MonomialOrder([Block("M", n, tuple(entries))])
            except OrderingError:
                continue
            return "M(" + ",".join(map(str, entries)) + ")"
    raise ValueError(kind)


def random_poly(rng: random.Random, names: str, char: int, max_deg: int, constant: float) -> str:
    """A sparse polynomial: 1 to 4 terms of degree 1 to ``max_deg`` (a constant term with
    probability ``constant``), small coefficients."""
    terms = []
    for i in range(rng.randint(1, 4)):
        c = rng.choice([1, 1, -1, 2, -2, 3, -3, 5, -7])
        if char == 0 and rng.random() < 0.15:
            c = f"{c}/{rng.choice([2, 3, 5])}"
        exp = [0] * len(names)
        for _ in range(0 if i and rng.random() < constant else rng.randint(1, max_deg)):
            exp[rng.randrange(len(names))] += 1
        mono = "*".join(f"{v}^{e}" if e > 1 else v for v, e in zip(names, exp) if e)
        terms.append(f"{c}*{mono}" if mono else str(c))
    return "+".join(terms).replace("+-", "-")


KINDS = {"std": 6, "eliminate": 2, "local": 2, "minass": 2, "primdec": 2, "tangentcone": 1}


def random_piece(rng: random.Random, names: str, char: int) -> str:
    """One of the ideals a decomposition case intersects: 1 to n-1 sparse generators of degree
    at most 2 (constant terms allowed), one of them squared now and then."""
    gens = [random_poly(rng, names, char, 2, 0.4) for _ in range(rng.randint(1, len(names) - 1))]
    if rng.random() < 0.3:
        gens[0] = f"({gens[0]})^2"
    return f"ideal({', '.join(gens)})"


def random_case(rng: random.Random, number: int, char: int | None = None, hard: bool = False) -> Case:
    """A random case; ``hard``: more variables, generators and degree."""
    char = char if char is not None else rng.choice([0, P])
    n = rng.choice([3, 4, 4, 5]) if hard else rng.choice([2, 2, 3, 3, 3, 4])
    names = NAMES[:n]
    kind = rng.choices(list(KINDS), weights=list(KINDS.values()))[0]
    if kind in ("minass", "primdec"):
        n = min(n, 3)
        names = NAMES[:n]
        ordering = random_ordering(rng, n, rng.choice(["dp", "lp", "dp-blocks", "Dp"]))
        return Case(number, kind, char, names, ordering, [random_piece(rng, names, char)
                                                          for _ in range(rng.randint(1, 3))])
    if kind == "tangentcone":
        gens = [random_poly(rng, names, char, 3, 0.0) for _ in range(rng.randint(1, n - 1))]
        return Case(number, kind, char, names, "dp", gens)
    ordering = random_ordering(rng, n, rng.choice(LOCAL if kind == "local" else GLOBAL))
    max_deg = {2: 4, 3: 3, 4: 2, 5: 2}[n] + hard
    constant = 0.0 if kind == "local" else 0.1  # in a local ring, a constant term makes a unit
    count = rng.randint(2, 5) if hard else rng.randint(1, 4 if n <= 3 else 3)
    gens = [random_poly(rng, names, char, max_deg, constant) for _ in range(count)]
    elim = "*".join(rng.sample(names, rng.randint(1, n - 1))) if kind == "eliminate" else ""
    return Case(number, kind, char, names, ordering, gens, elim)


# ---------------------------------------------------------------- parsing printed ideals
_TERM = re.compile(r"([+-]?)(\d*)(?:/(\d+))?((?:[a-z]\d*)*)")


def parse_poly(text: str, names: str, char: int) -> dict[tuple[int, ...], Fraction]:
    """A polynomial printed in Singular's short form (``-3x2y+1/2z-7``) as {exponents: coefficient}."""
    poly: dict[tuple[int, ...], Fraction] = {}
    text = text.strip()
    if text == "0":
        return poly
    pos = 0
    while pos < len(text):
        m = _TERM.match(text, pos)
        if not m or m.end() == pos:
            raise ValueError(f"cannot parse {text!r} at {pos}")
        sign, num, den, mono = m.groups()
        c = Fraction(int(num) if num else 1, int(den) if den else 1) * (-1 if sign == "-" else 1)
        exp = [0] * len(names)
        for v, e in re.findall(r"([a-z])(\d*)", mono):
            exp[names.index(v)] += int(e) if e else 1
        key = tuple(exp)
        poly[key] = poly.get(key, Fraction(0)) + c
        pos = m.end()
    if char:
        poly = {e: Fraction(int(c.numerator * pow(c.denominator, -1, char)) % char) for e, c in poly.items()}
    return {e: c for e, c in poly.items() if c}


def monic(poly: dict, char: int, key) -> frozenset:
    """The polynomial divided by its leading coefficient (leading by ``key``), as a hashable set."""
    if not poly:
        return frozenset()
    lead = max(poly, key=key)
    c = poly[lead]
    if char:
        inv = pow(int(c), -1, char)
        return frozenset((e, Fraction(int(v) * inv % char)) for e, v in poly.items())
    return frozenset((e, v / c) for e, v in poly.items())


def ideal_lines(text: str) -> list[str]:
    """The generators of the ideal printed as ``_[i]=...`` lines."""
    return [m.group(1) for m in re.finditer(r"^_\[\d+\]=(.*)$", text, re.M)]


def minimal_monomials(monos: list[tuple[int, ...]]) -> set[tuple[int, ...]]:
    def divides(a, b):
        return all(x <= y for x, y in zip(a, b))
    return {m for m in monos if not any(o != m and divides(o, m) for o in monos)}


# ---------------------------------------------------------------- running both systems
def singular_outputs(cases: list[Case], timeout: float = 30) -> dict[int, str]:
    """Singular's output of each case (one Singular process for a batch; when a batch takes longer
    than ``timeout`` seconds, case by case, leaving out those that still do)."""
    out: dict[int, str] = {}
    for start in range(0, len(cases), 100):
        batch = cases[start:start + 100]
        try:
            out.update(_singular(batch, timeout))
        except subprocess.TimeoutExpired:
            for case in batch:
                try:
                    out.update(_singular([case], timeout))
                except subprocess.TimeoutExpired:
                    pass
    return out


def _singular(cases: list[Case], timeout: float) -> dict[int, str]:
    script = 'option(redSB); LIB "primdec.lib"; LIB "sing.lib";\n' + "".join(f'"@@case {c.number}";\n{c.script()}kill r;\n' for c in cases)
    res = subprocess.run([SINGULAR, "-q", "--no-warn"], input=script + "quit;\n", text=True, capture_output=True,
                         timeout=timeout)
    out: dict[int, str] = {}
    for chunk in res.stdout.split("@@case ")[1:]:
        head, _, body = chunk.partition("\n")
        out[int(head)] = body
    return out


def mech_output(case: Case, timeout: float) -> str | None:
    """mech's output of a case (None when it exceeded the time limit)."""
    from mech import MechError, Session
    from mech.dsl.limits import MechLimitError
    s = Session(timeout=timeout)
    s.execute('option(redSB); LIB "primdec.lib"; LIB "sing.lib";')
    try:
        return s.execute(case.script(), f"<case {case.number}>")
    except MechLimitError:
        return None
    except MechError as e:
        return "error: " + e.format()


def order_key(case: Case):
    """A sort key of exponent tuples for the case's ordering (from mech's kernel)."""
    from mech import Session
    s = Session()
    s.execute(case.ring())
    return s.ring.poly.order.key


def components(case: Case, text: str, key) -> list[tuple[frozenset, frozenset]]:
    """The (primary, prime) pairs of a decomposition's output, each a set of monic polynomials
    (for ``minAssGTZ`` the primary is the prime)."""
    out = []
    for chunk in text.split("@@comp")[1:]:
        q, _, p = chunk.partition("@@prime")
        q_set = frozenset(monic(parse_poly(x, case.names, case.char), case.char, key) for x in ideal_lines(q))
        p_set = frozenset(monic(parse_poly(x, case.names, case.char), case.char, key)
                          for x in ideal_lines(p)) if p else q_set
        out.append((q_set, p_set))
    return out


def compare_decompositions(case: Case, mine: str, theirs: str, key) -> str:
    a, b = components(case, mine, key), components(case, theirs, key)
    if {p for _, p in a} != {p for _, p in b}:
        return f"primes differ: mech {len(a)}, Singular {len(b)} components"
    if case.kind == "primdec":
        # isolated primary components are unique: compare those of the primes that are certainly
        # minimal (listed once, and no other prime's leading ideal inside theirs)
        primes = [p for _, p in b]
        lead = {p: [max(dict(f), key=key) for f in p if f] for p in primes}
        ours = {p: q for q, p in a}
        for q, p in b:
            if primes.count(p) == 1 and _minimal(p, primes, lead) and ours.get(p) != q:
                return "isolated primary components differ"
    return ""


def _minimal(p: frozenset, primes: list[frozenset], lead: dict) -> bool:
    """Whether no other prime's leading ideal lies in ``p``'s (necessary for ``o ⊂ p``)."""
    from mech.kernel.poly import divides
    return not any(o != p and all(any(divides(n, m) for n in lead[p]) for m in lead[o]) for o in primes)


def compare(case: Case, mine: str, theirs: str) -> str:
    """'' when the results agree, else what differs."""
    if mine.startswith("error:"):
        return f"mech failed: {mine}"
    if case.kind in ("minass", "primdec"):
        if "@@comp" not in theirs and "_[" not in theirs and theirs.strip():
            return f"no decomposition in Singular's output: {theirs!r}"
        return compare_decompositions(case, mine, theirs, order_key(case))
    a, b = ideal_lines(mine), ideal_lines(theirs)
    if not b:
        return f"no ideal in Singular's output: {theirs!r}"
    key = order_key(case)
    pa = [parse_poly(x, case.names, case.char) for x in a]
    pb = [parse_poly(x, case.names, case.char) for x in b]
    if case.kind == "local":
        la = minimal_monomials([max(p, key=key) for p in pa if p])
        lb = minimal_monomials([max(p, key=key) for p in pb if p])
        return "" if la == lb else f"leading ideals differ: mech {sorted(la)} Singular {sorted(lb)}"
    if {monic(p, case.char, key) for p in pa} != {monic(p, case.char, key) for p in pb}:
        return "bases differ"
    if a != b:
        return "same basis, printed differently"
    return ""


@dataclass
class Report:
    seed: int
    cases: int = 0
    compared: int = 0
    timeouts: int = 0
    singular_timeouts: int = 0
    by_kind: dict[str, int] = field(default_factory=dict)
    mismatches: list[tuple[Case, str, str, str]] = field(default_factory=list)  # case, problem, mech, Singular
    seconds: float = 0.0

    def summary(self) -> str:
        kinds = ", ".join(f"{k} {v}" for k, v in sorted(self.by_kind.items()))
        return (f"seed {self.seed}: {self.compared} of {self.cases} cases compared ({kinds}), {self.timeouts} over "
                f"mech's time limit, {self.singular_timeouts} over Singular's, {len(self.mismatches)} mismatches, "
                f"{self.seconds:.0f} s")


def run(seed: int, count: int, char: int | None = None, timeout: float = 20, hard: bool = False) -> Report:
    rng = random.Random(seed)
    cases = [random_case(rng, i, char, hard) for i in range(count)]
    report = Report(seed, cases=count)
    t0 = time.monotonic()
    theirs = singular_outputs(cases)
    for case in cases:
        if case.number not in theirs:
            report.singular_timeouts += 1
            continue
        mine = mech_output(case, timeout)
        if mine is None:
            report.timeouts += 1
            continue
        problem = compare(case, mine, theirs.get(case.number, ""))
        report.compared += 1
        report.by_kind[case.kind] = report.by_kind.get(case.kind, 0) + 1
        if problem:
            report.mismatches.append((case, problem, mine, theirs.get(case.number, "")))
    report.seconds = time.monotonic() - t0
    return report


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description="Compare mech's std and eliminate with Singular's on random ideals.")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--count", type=int, default=100)
    p.add_argument("--char", type=int, choices=[0, P], help="only this characteristic (default: both)")
    p.add_argument("--timeout", type=float, default=20, help="mech's time limit per case, in seconds")
    p.add_argument("--show", type=int, default=5, help="mismatches to print")
    p.add_argument("--hard", action="store_true", help="bigger cases: 3 to 5 variables, higher degrees")
    args = p.parse_args(argv)
    if not SINGULAR:
        print("Singular is not installed", file=sys.stderr)
        return 2
    report = run(args.seed, args.count, args.char, args.timeout, args.hard)
    for case, problem, mine, theirs in report.mismatches[:args.show]:
        print(f"--- case {case.number} ({case.kind}): {problem}\n{case.script()}mech:\n{mine}Singular:\n{theirs}")
    print(report.summary())
    return 1 if report.mismatches else 0


if __name__ == "__main__":
    sys.exit(main())
