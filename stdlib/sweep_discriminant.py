"""The discriminant curves of a mechanism of mobility 0 with two design parameters: the curves in
the plane of the parameters ``(a, b)`` off which the number of real assembly modes cannot change.

The generic analysis over ``Q(a, b)`` is often out of reach (the 3-RPR's), so the curves are
computed from specializations. For a separating linear form ``t`` of the configuration variables,
the characteristic polynomial of multiplication by ``t`` in ``Q[x]/J(a, b)`` is, for generic
``(a, b)``, ``P(t, a, b) / P_D(a, b)`` with ``P`` primitive in ``Z[a, b][t]`` of degree ``D`` (the
number of complex solutions). ``P`` is found by evaluation and exact interpolation: at rational
points ``(a0, b0)`` the characteristic polynomial is computed exactly (:class:`QuotientAlgebra`);
the degrees of ``P``'s coefficients are read along a generic line, and the exponents of ``a`` and
``b`` that occur along lines through the axes (small univariate systems modulo a prime); then the
coefficients on that support solve the linear equations ``P_k(a0, b0) = c_k(a0, b0) P_D(a0, b0)``,
whose one-dimensional kernel is found modulo primes and lifted (Chinese remainders, rational
reconstruction), checked on every equation and at fresh points. Where the real count changes,
two solutions meet (the discriminant of ``P`` in ``t`` vanishes) or one goes to infinity (``P_D``
vanishes). The discriminant of one form also vanishes where two distinct solutions share ``t``'s value (a
conjugate pair with a real ``t``): only the irreducible factors common to two forms are kept.

The designs of a grid are grouped by the cells of these curves in :mod:`mech.stdlib.sweep_cells`.
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Sequence

from flint import fmpq, fmpz_mpoly_ctx, nmod_mat

from mech.kernel.real_roots import RealSolvingError
from mech.kernel.real_solve import QuotientAlgebra
from mech.kernel.poly import Poly, PolyRing

PRIME = 4611686018427387847  # < 2^62: the degrees along lines are found modulo it
SEED = 20261124
MAX_DEGREE = 40

Terms = dict[tuple[int, int], Fraction]


@dataclass
class Curves:
    """The discriminant curves in the plane of ``params``: each an irreducible polynomial in
    (a, b) as exponent -> coefficient; ``D`` the generic number of complex solutions."""

    params: tuple[str, str]
    factors: list[Terms] = field(default_factory=list)
    names: list[str] = field(default_factory=list)
    D: int = 0
    samples: int = 0
    note: str = ""


class NotApplicable(Exception):
    """The family is not zero-dimensional with two parameters (nothing to compute)."""


class _Family:
    """The constraints of a mechanism with two symbolic parameters, ready to specialize."""

    def __init__(self, R: PolyRing, gens: Sequence[Poly], n: int, params: Sequence[str]) -> None:
        if R.nvars != n + 2 or sorted(R.names[n:]) != sorted(params):
            raise NotApplicable("not a family in exactly two parameters")
        self.ring = _config_ring(R, n)
        ia, ib = R.names.index(params[0]), R.names.index(params[1])
        self.gens: list[dict[tuple[int, ...], list[tuple[int, int, Any]]]] = []
        for g in gens:
            terms: dict[tuple[int, ...], list[tuple[int, int, Any]]] = {}
            for e, c in g.terms.items():
                terms.setdefault(e[:n], []).append((e[ia], e[ib], c))
            self.gens.append(terms)

    def at(self, a: Fraction, b: Fraction) -> list[Poly]:
        fa, fb = fmpq(a.numerator, a.denominator), fmpq(b.numerator, b.denominator)
        out = []
        for terms in self.gens:
            p = {}
            for e, parts in terms.items():
                v = sum((c * fa ** i * fb ** j for i, j, c in parts), fmpq(0))
                if v != 0:
                    p[e] = v
            if p:
                out.append(Poly(self.ring, p))
        return out


def _config_ring(R: PolyRing, n: int) -> PolyRing:
    from mech.kernel.order import MonomialOrder
    return PolyRing(R.field, R.names[:n], MonomialOrder.simple("dp", n))


def _charpolys(fam: _Family, a: Fraction, b: Fraction, forms: list[list[fmpq]]) -> tuple[int, list[list[fmpq]]] | None:
    """(vdim, the monic characteristic polynomials' coefficients, constant first) at (a, b);
    None when the fiber is not zero-dimensional."""
    try:
        A = QuotientAlgebra(fam.at(a, b), fam.ring)
    except RealSolvingError:
        return None
    return A.dim, [[fmpq(c) for c in A.linear_matrix(f).charpoly().coeffs()] for f in forms]


class _Search:
    """Samples of the family: points, the number of solutions there and the characteristic
    polynomials of the forms; points whose fiber is special (another count, not finite) skipped."""

    def __init__(self, fam: _Family, forms: list[list[fmpq]], box: tuple[Fraction, Fraction, Fraction, Fraction]) -> None:
        self.fam, self.forms, self.box = fam, forms, box
        self.rnd = random.Random(SEED)
        self.D = 0
        self.count = 0
        self.memo: dict[tuple[Fraction, Fraction], list[list[fmpq]] | None] = {}
        self.pool: list = []  # random points with the generic count, and their polynomials

    def random_point(self) -> tuple[Fraction, Fraction]:
        lo_a, hi_a, lo_b, hi_b = self.box
        den = 7
        return (Fraction(self.rnd.randint(int(lo_a * den), int(hi_a * den)), den),
                Fraction(self.rnd.randint(int(lo_b * den), int(hi_b * den)), den))

    def sample(self, a: Fraction, b: Fraction) -> list[list[fmpq]] | None:
        """The forms' characteristic polynomials at (a, b), when it has the generic count."""
        if a == 0 or b == 0:
            return None
        if (a, b) not in self.memo:
            self.count += 1
            got = _charpolys(self.fam, a, b, self.forms)
            self.memo[(a, b)] = got[1] if got is not None and got[0] == self.D else None
        return self.memo[(a, b)]

    def random_samples(self, count: int) -> list:
        """``count`` random points with the generic count, and their polynomials."""
        while len(self.pool) < count:
            pt = self.random_point()
            got = self.sample(*pt)
            if got is not None:
                self.pool.append((pt, got))
        return self.pool[:count]

    def start(self) -> None:
        """The generic number of solutions: the most frequent among a few random points."""
        seen: dict[int, int] = {}
        for _ in range(5):
            got = _charpolys(self.fam, *self.random_point(), self.forms[:1])
            if got is None:
                raise NotApplicable("the configuration space is not finite (mobility is not 0)")
            seen[got[0]] = seen.get(got[0], 0) + 1
        self.D = max(seen, key=lambda k: (seen[k], k))
        if self.D == 0:
            raise NotApplicable("no configuration")
        a0, b0 = self.random_point()
        r = self.rnd
        # a generic line (total degrees), and lines through the axes (the exponents of a and b)
        self.lines = [(a0, b0, Fraction(r.randint(1, 4), 3), Fraction(r.randint(1, 4), 5)),
                      (Fraction(0), b0, Fraction(1, 3), Fraction(0)), (a0, Fraction(0), Fraction(0), Fraction(1, 3))]


def _nullvector_mod(rows: list[list[int]], ncols: int, p: int) -> list[int] | None:
    """The kernel vector of ``rows`` modulo ``p`` when the kernel has dimension 1."""
    if not rows:
        return None
    X, nullity = nmod_mat(len(rows), ncols, [v % p for r in rows for v in r], p).nullspace()
    if nullity != 1:
        return None
    return [int(X[i, 0]) for i in range(ncols)]


def _rows(samples: list, which: int, D: int, supports: list[list[tuple[int, int]]],
          value: Any) -> list[list[int]]:
    """The equations ``P_k(s) den_k - num_k P_D(s) = 0`` (k < D) at the samples, the unknowns the
    coefficients of ``P_0 .. P_D`` on their supports; ``value(point, (i, j))`` a monomial's value
    times a factor common to the row (integers)."""
    offsets = [0]
    for sup in supports:
        offsets.append(offsets[-1] + len(sup))
    rows = []
    for n, (point, coeffs) in enumerate(samples):
        c = coeffs[which]
        lead = [value(point, m) for m in supports[D]]
        for k in range(D):
            if n >= len(supports[k]) + len(supports[D]) + 3:
                continue  # enough equations for P_k
            num, den = int(c[k].p), int(c[k].q)
            row = [0] * offsets[-1]
            row[offsets[k]:offsets[k + 1]] = [den * value(point, m) for m in supports[k]]
            row[offsets[D]:] = [-num * v for v in lead]
            rows.append(row)
    return rows


def _solve(samples: list, which: int, D: int, supports: list[list[tuple[int, int]]], value: Any) -> list[int] | None:
    """The primitive integer kernel vector of the equations (1-dimensional kernel), from its images
    modulo primes (Chinese remainders, rational reconstruction), checked on every equation."""
    from mech.kernel.modular import primes, ratrec
    rows = _rows(samples, which, D, supports, value)
    ncols = len(rows[0]) if rows else 0
    modulus, acc, pivot, last = 1, None, None, None
    for q in primes(SEED):
        v = _nullvector_mod(rows, ncols, q)
        if v is None:
            if acc is None:
                return None  # the kernel is not 1-dimensional
            continue
        if pivot is None:
            pivot = next(i for i, x in enumerate(v) if x)
        if v[pivot] == 0:
            continue
        inv = pow(v[pivot], -1, q)
        v = [x * inv % q for x in v]
        if acc is None:
            acc, modulus = v, q
        else:
            m2 = modulus * q
            acc = [(a + modulus * ((x - a) * pow(modulus, -1, q) % q)) % m2 for a, x in zip(acc, v)]
            modulus = m2
        bound = math.isqrt(modulus // 2)
        fracs = [ratrec(a, modulus, bound) for a in acc]
        if any(f is None for f in fracs):
            continue
        if fracs != last:
            last = fracs
            continue
        den = 1
        for _, d in fracs:
            den = den * d // math.gcd(den, d)
        ints = [n * (den // d) for n, d in fracs]
        if all(sum(r * x for r, x in zip(row, ints) if x) == 0 for row in rows):
            return ints
        last = None
    return None


def _line_exponents(search: _Search, which: int, line: tuple[Fraction, ...], max_degree: int) -> list[set[int]]:
    """The exponents of ``s`` in each ``P_k(a0 + s u, b0 + s v)`` (sampled at s = 1, 2, ...)."""
    a0, b0, u, v = line
    D, samples, s = search.D, [], 0
    p = PRIME
    for e in range(max_degree + 1):
        supports = [[(i, 0) for i in range(e + 1)]] * (D + 1)
        while len(samples) * D < (D + 1) * (e + 1) + 2 * D:
            s += 1
            got = search.sample(a0 + s * u, b0 + s * v)
            if got is not None:
                samples.append((Fraction(s), got))
        rows = _rows(samples, which, D, supports, lambda pt, m: int(pt.numerator) ** m[0])
        vec = _nullvector_mod(rows, (D + 1) * (e + 1), p)
        if vec is not None:
            return [{i for i in range(e + 1) if vec[k * (e + 1) + i]} for k in range(D + 1)]
    raise RealSolvingError(f"no family polynomial of degree at most {max_degree} in the parameters")


def _family_poly(search: _Search, which: int, ctx: Any) -> Any:
    """``P(t, a, b)`` for form ``which``, as an fmpz_mpoly of ``ctx`` (t, a, b): the degrees of its
    coefficients along a generic line and along the two axes' directions, then the coefficients."""
    D = search.D
    total = [max(e, default=-1) for e in _line_exponents(search, which, search.lines[0], MAX_DEGREE)]
    in_a = _line_exponents(search, which, search.lines[1], max(total))
    in_b = _line_exponents(search, which, search.lines[2], max(total))
    supports = [[(i, j) for i in sorted(ea) for j in sorted(eb) if i + j <= dt]
                for dt, ea, eb in zip(total, in_a, in_b)]
    ncols = sum(len(sup) for sup in supports)
    need = max(max(len(sup) for sup in supports), -(-ncols // D))

    def value(pt: tuple[Fraction, Fraction], m: tuple[int, int]) -> int:
        (a, b), (i, j) = pt, m
        return a.numerator ** i * a.denominator ** (da_max - i) * b.numerator ** j * b.denominator ** (db_max - j)
    da_max, db_max = max(max(e) for e in in_a), max(max(e) for e in in_b)
    for extra in (2, 6, 12):
        samples = search.random_samples(need + extra)
        vec = _solve(samples, which, D, supports, value)
        if vec is not None:
            terms: dict[tuple[int, int, int], int] = {}
            pos = 0
            for k, sup in enumerate(supports):
                for i, j in sup:
                    if vec[pos]:
                        terms[(k, i, j)] = vec[pos]
                    pos += 1
            P = ctx.from_dict(terms)
            if _check(P, search, which):
                return P
    raise RealSolvingError("the family polynomial could not be interpolated")


def _check(P: Any, search: _Search, which: int, fresh: int = 2) -> bool:
    """``P(t, a0, b0)`` proportional to the characteristic polynomial at fresh points."""
    done = 0
    while done < fresh:
        a, b = search.random_point()
        cps = search.sample(a, b)
        if cps is None:
            continue
        done += 1
        coeffs = _at(P, a, b, search.D)
        lead = coeffs[search.D]
        if lead == 0 or any(coeffs[k] != lead * cps[which][k] for k in range(search.D)):
            return False
    return True


def _at(P: Any, a: Fraction, b: Fraction, D: int) -> list[fmpq]:
    """The coefficients in t of ``P(t, a, b)``."""
    out = [fmpq(0)] * (D + 1)
    fa, fb = fmpq(a.numerator, a.denominator), fmpq(b.numerator, b.denominator)
    for (k, i, j), c in P.to_dict().items():
        out[k] += fmpq(c) * fa ** i * fb ** j
    return out


def _forms(n: int, count: int) -> list[list[fmpq]]:
    rnd = random.Random(SEED + 1)
    return [[fmpq(rnd.randint(-3, 3) or 1) for _ in range(n)] for _ in range(count)]


def _factors(P: Any, ctx2: Any, D: int) -> dict[str, Any]:
    """The irreducible factors in (a, b) of P's discriminant and leading coefficient in t,
    each with a positive leading coefficient."""
    out = {}
    lead = ctx2.from_dict({(i, j): c for (k, i, j), c in P.to_dict().items() if k == D})
    disc = P.discriminant("t")
    disc = ctx2.from_dict({(i, j): c for (k, i, j), c in disc.to_dict().items()})
    for q in (lead, disc):
        if q.is_zero():
            raise RealSolvingError("the solutions are not distinct for generic parameters")
        for f, _ in q.factor()[1]:
            if f.is_constant():
                continue
            f = f if f.leading_coefficient() > 0 else -f
            out[str(f)] = f
    return out


def _divides_disc(f: Any, P: Any, D: int, rnd: random.Random, names: tuple[str, str]) -> bool:
    """Whether the curve ``f`` (a polynomial of P's ring free of t) lies in ``P``'s discriminant
    or leading-coefficient curve: checked on two random lines ``b = b0`` (``a = a0`` when ``f``
    does not involve ``a``)."""
    var = names[1] if f.degrees()[1] > 0 else names[0]
    for _ in range(2):
        v = rnd.randint(2, 10 ** 6)
        fv, Pv = f.subs({var: v}), P.subs({var: v})
        lead = Pv.context().from_dict({(0,) + e[1:]: c for e, c in Pv.to_dict().items() if e[0] == D})
        h = Pv.discriminant("t") * lead
        if fv.is_constant() or max(fv.gcd(h).degrees()) < max(fv.degrees()):
            return False
    return True


def discriminant_curves(R: PolyRing, gens: Sequence[Poly], n: int, params: Sequence[str],
                        box: tuple[Fraction, Fraction, Fraction, Fraction]) -> Curves:
    """The discriminant curves of the system ``gens`` (configuration variables the first ``n`` of
    ``R``, the two ``params`` the others) in the plane of ``params``; samples are drawn in ``box``
    (lo_a, hi_a, lo_b, hi_b). Raises :class:`NotApplicable` when the system is not zero-dimensional."""
    fam = _Family(R, gens, n, params)
    search = _Search(fam, _forms(n, 2), box)
    search.start()
    ctx = fmpz_mpoly_ctx.get(("t", params[0], params[1]), "lex")
    ctx2 = fmpz_mpoly_ctx.get((params[0], params[1]), "lex")
    found = _factors(_family_poly(search, 0, ctx), ctx2, search.D)
    P2 = _family_poly(search, 1, ctx)
    rnd = random.Random(SEED + 2)
    factors = [f for f in found.values()
               if _divides_disc(ctx.from_dict({(0,) + e: c for e, c in f.to_dict().items()}), P2, search.D, rnd, tuple(params))]
    factors.sort(key=lambda f: (f.total_degree(), str(f)))
    return Curves(tuple(params), [{(int(e[0]), int(e[1])): Fraction(int(c)) for e, c in f.to_dict().items()} for f in factors],
                  [str(f).replace(" ", "") for f in factors], search.D, search.count)


_CACHE: dict[tuple, Curves] = {}


def mechanism_curves(m: Any, params: Sequence[str], box: tuple[Fraction, Fraction, Fraction, Fraction],
                     limit: float | None) -> Curves:
    """The discriminant curves of mechanism ``m`` (its symbolic lengths exactly ``params``), within
    ``limit`` seconds; a :class:`Curves` with only a ``note`` when they do not apply or finish.
    Remembered for the process (a sweep and its map compute them once)."""
    from mech.dsl.limits import within
    try:
        R, gens = m.constraints()
    except Exception as e:  # noqa: BLE001 - no curves: the sweep analyses every design
        return Curves(tuple(params), note=f"no discriminant curves ({e})")
    key = (tuple(R.names), tuple(str(g) for g in gens), tuple(params))
    if key not in _CACHE:
        n = len(m.variables())
        try:
            ok, got = within(limit, discriminant_curves, R, gens, n, params, box)
        except (NotApplicable, RealSolvingError) as e:
            return Curves(tuple(params), note=f"no discriminant curves ({e})")
        if not ok:
            return Curves(tuple(params), note=f"no discriminant curves (not found in {limit:g} s)")
        _CACHE[key] = got
    return _CACHE[key]


def curve_label(name: str, index: int) -> str:
    """A short name of a curve: its polynomial when short, else ``D<index + 1>``."""
    return name if len(name) <= 40 else f"D{index + 1}"
