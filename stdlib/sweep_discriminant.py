"""The discriminant curves of a mechanism of mobility 0 with two design parameters: the curves in
the plane of the parameters ``(a, b)`` off which the number of real assembly modes cannot change.

The generic analysis over ``Q(a, b)`` is often out of reach (the 3-RPR's), so the curves are
computed from specializations modulo primes. For a linear form ``t`` of the configuration
variables, multiplication by ``t`` in ``Q(a, b)[x]/J`` has a matrix ``N(a, b) / Q(a, b)`` in the
generic fibre's standard monomials, of low degree in ``(a, b)``. Modulo a prime ``p``:

* the fibre at a point of ``F_p^2`` and its matrix come from one replay of an F4 trace
  (:mod:`mech.stdlib.sweep_fibres`); the degrees of ``N`` and ``Q`` from a univariate probe along
  a random line (rational reconstruction);
* ``N`` and ``Q`` are interpolated densely from as many points as ``N`` has monomials, plus a few
  (``Q`` from the left kernel of the numerators' evaluation matrix, then the numerators);
* ``P(t, a, b) = det(t Q - N)`` (Faddeev-LeVerrier, content removed) is, up to a constant, the
  primitive characteristic polynomial of ``t``; where the real count changes two solutions meet
  (its discriminant in ``t`` vanishes) or one goes to infinity (its leading coefficient does);
* of the irreducible factors of discriminant times leading coefficient, those kept are the curves
  along which the fibre is not ``D`` distinct points (tested at points of the curve over ``F_p``
  by a fresh Gröbner basis and a random form's characteristic polynomial): the discriminant of
  one form also vanishes where two distinct solutions share ``t``'s value.

The product of the kept factors, made monic, is lifted over the primes (Chinese remainders,
rational reconstruction) until one more prime leaves it unchanged, and factored over ``Q``.

The designs are grouped by the cells of these curves in :mod:`mech.stdlib.sweep_cells`.
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Sequence

from flint import fmpq, fmpz_mpoly_ctx, nmod_mat, nmod_mpoly_ctx, nmod_poly

from mech.kernel.modular import primes, ratrec
from mech.kernel.poly import Poly, PolyRing
from mech.kernel.real_roots import RealSolvingError
from mech.stdlib.sweep_fibres import ModFibres, Unlucky

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


def _config_ring(R: PolyRing, n: int) -> PolyRing:
    from mech.kernel.order import MonomialOrder
    return PolyRing(R.field, R.names[:n], MonomialOrder.simple("dp", n))


def _integer_terms(fam: _Family) -> list[dict[tuple[int, ...], list[tuple[int, int, int]]]]:
    """The family's generators with integer coefficients (each times its denominators' lcm)."""
    out = []
    for terms in fam.gens:
        den = 1
        for parts in terms.values():
            for _, _, c in parts:
                den = math.lcm(den, int(fmpq(c).q))
        out.append({e: [(i, j, int(fmpq(c).p) * (den // int(fmpq(c).q))) for i, j, c in parts]
                    for e, parts in terms.items()})
    return out


def _forms(n: int, rnd: random.Random) -> list[list[int]]:
    return [[rnd.randint(-3, 3) or 1 for _ in range(n)]]


# ---------------------------------------------------------------- one prime
def _flat(M: list[list[list[int]]]) -> list[int]:
    return [x for col in M[0] for x in col]


def _line_degrees(fib: ModFibres, rnd: random.Random) -> tuple[int, int]:
    """(numerator degree, denominator degree) of the multiplication matrix's entries over
    ``F_p(a, b)``: those of a random combination of them along a random line, by rational
    reconstruction (the largest quotient of the Euclidean remainders, with a margin)."""
    p = fib.p
    a0, b0, u, v = (rnd.randrange(1, p) for _ in range(4))
    xs: list[int] = []
    ys: list[int] = []
    weights: list[int] = []
    s, K = 0, 16
    while K <= 4 * MAX_DEGREE:
        while len(xs) < K:
            s += 1
            M = fib.matrices(a0 + s * u, b0 + s * v)
            if M is None:
                continue
            flat = _flat(M)
            weights = weights or [rnd.randrange(1, p) for _ in flat]
            xs.append(s)
            ys.append(sum(w * x for w, x in zip(weights, flat)) % p)
        got = _rational_degrees(xs, ys, p)
        if got is not None:
            return got
        K *= 2
    raise RealSolvingError(f"the fibres' matrices have degree above {MAX_DEGREE} in the parameters")


def _rational_degrees(xs: list[int], ys: list[int], p: int, margin: int = 3) -> tuple[int, int] | None:
    """The degrees of the rational function through the points, when the points determine it."""
    coeffs = list(ys)  # Newton's divided differences
    for k in range(1, len(xs)):
        for i in range(len(xs) - 1, k - 1, -1):
            coeffs[i] = (coeffs[i] - coeffs[i - 1]) * pow(xs[i] - xs[i - k], -1, p) % p
    f = nmod_poly([coeffs[-1]], p)
    m = nmod_poly([1], p)
    for x, c in zip(reversed(xs[:-1]), reversed(coeffs[:-1])):
        f = f * nmod_poly([-x, 1], p) + c
    for x in xs:
        m *= nmod_poly([-x, 1], p)
    r0, r1, t0, t1 = m, f, nmod_poly([0], p), nmod_poly([1], p)
    best, where = -1, None
    while not r1.is_zero():
        q, r = divmod(r0, r1)
        if q.degree() > best:
            best, where = q.degree(), (max(r1.degree(), 0), t1.degree())
        r0, r1, t0, t1 = r1, r, t1, t0 - q * t1
    if f.is_zero():
        return 0, 0
    return where if best >= margin else None


def _dense(d: int) -> list[tuple[int, int]]:
    return [(i, k - i) for k in range(d + 1) for i in range(k + 1)]


def _monomial_rows(points: list[tuple[int, int]], support: list[tuple[int, int]], p: int) -> list[list[int]]:
    rows = []
    top = max((max(i, j) for i, j in support), default=0)
    for a, b in points:
        pa, pb = [1], [1]
        for _ in range(top):
            pa.append(pa[-1] * a % p)
            pb.append(pb[-1] * b % p)
        rows.append([pa[i] * pb[j] % p for i, j in support])
    return rows


def _matrix_mod(fib: ModFibres, dn: int, dq: int, rnd: random.Random) -> tuple[list[dict], dict, int] | None:
    """The multiplication matrix over ``F_p[a, b]``: its entries ``N_e`` (numerators, total
    degree ``dn``) and their common denominator ``Q`` (degree ``dq``), as exponent -> coefficient
    dicts, and the number of points sampled; None when the samples do not agree (start again).

    With ``V`` the values of the numerators' monomials at the points and ``L`` a basis of its left
    kernel, ``L diag(m) W q = 0`` for every entry (or combination) ``m`` of the matrix, ``W`` the
    values of the denominator's monomials: ``q``, ``Q``'s coefficients, is that system's kernel;
    then the numerators solve ``V n_e = diag(m_e) W q`` (Zippel's dense interpolation)."""
    p = fib.p
    SN, SQ = _dense(dn), _dense(dq)
    E = fib.dim * fib.dim
    combos = 4
    extra = max(3, -(-len(SQ) // combos) + 3)
    points, values = [], []
    while len(points) < len(SN) + extra:
        a, b = rnd.randrange(1, p), rnd.randrange(1, p)
        M = fib.matrices(a, b)
        if M is not None:
            points.append((a, b))
            values.append(_flat(M))
    Ns = len(points)
    V = _monomial_rows(points, SN, p)
    W = _monomial_rows(points, SQ, p)
    X, k = nmod_mat(len(SN), Ns, [V[i][c] for c in range(len(SN)) for i in range(Ns)], p).nullspace()
    L = nmod_mat(k, Ns, [int(X[i, c]) for c in range(k) for i in range(Ns)], p)
    blocks = []
    for _ in range(combos):
        w = [rnd.randrange(1, p) for _ in range(E)]
        m = [sum(x * y for x, y in zip(w, vals)) % p for vals in values]
        blocks.append(L * nmod_mat(Ns, len(SQ), [m[i] * W[i][c] % p for i in range(Ns) for c in range(len(SQ))], p))
    stacked = nmod_mat(k * combos, len(SQ), [int(B[i, c]) for B in blocks for i in range(k) for c in range(len(SQ))], p)
    Y, nullity = stacked.nullspace()
    if nullity != 1:
        return None
    q = [int(Y[c, 0]) for c in range(len(SQ))]
    qv = [sum(x * y for x, y in zip(row, q)) % p for row in W]
    rhs = nmod_mat(Ns, E, [values[i][e] * qv[i] % p for i in range(Ns) for e in range(E)], p)
    Vm = nmod_mat(Ns, len(SN), [x for row in V for x in row], p)
    head = nmod_mat(len(SN), len(SN), [x for row in V[:len(SN)] for x in row], p)
    try:
        num = head.solve(nmod_mat(len(SN), E, [int(rhs[i, e]) for i in range(len(SN)) for e in range(E)], p))
    except ZeroDivisionError:
        return None
    if Vm * num != rhs:  # the extra points: the interpolant must hold there too
        return None
    entries = [{SN[i]: int(num[i, e]) for i in range(len(SN)) if int(num[i, e])} for e in range(E)]
    return entries, {SQ[i]: c for i, c in enumerate(q) if c}, Ns


def _charpoly(N: list[list[Any]], one: Any) -> list[Any]:
    """The characteristic polynomial's coefficients (constant first) of a square matrix over a
    commutative ring where ``1..n`` are invertible (Faddeev and LeVerrier)."""
    n = len(N)
    c = [one * 0] * n + [one]
    Mk = [[one * 0] * n for _ in range(n)]
    for k in range(1, n + 1):
        Mk = [[sum((N[i][l] * Mk[l][j] for l in range(n)), one * 0) + (c[n - k + 1] if i == j else 0)
               for j in range(n)] for i in range(n)]
        tr = sum((sum((N[i][l] * Mk[l][i] for l in range(n)), one * 0) for i in range(n)), one * 0)
        c[n - k] = tr * (-pow(k, -1, one.context().modulus()))
    return c


def _true_part(fib: ModFibres, entries: list[dict], Q: dict, rnd: random.Random,
               known: dict[tuple, bool]) -> Any:
    """The product of the irreducible factors over ``F_p`` of the discriminant and leading
    coefficient of ``P(t, a, b) = det(t Q - N)`` (content removed) along which the fibre is not
    ``D`` distinct points, made monic (an nmod_mpoly in (a, b)). ``known``: the verdicts by
    (degrees, multiplicity) of a first prime, used when this prime's factors have the same keys
    (else the factors are tested and ``known`` filled)."""
    p, D = fib.p, fib.dim
    ctx2 = nmod_mpoly_ctx.get(("a", "b"), ordering="deglex", modulus=p)
    ctx3 = nmod_mpoly_ctx.get(("t", "a", "b"), ordering="lex", modulus=p)
    N = [[ctx2.from_dict(entries[k * D + l]) for k in range(D)] for l in range(D)]  # rows l, columns k
    q = ctx2.from_dict(Q)
    c = _charpoly(N, ctx2.from_dict({(0, 0): 1}))
    coeffs = [c[k] * q ** k for k in range(D + 1)]
    g = coeffs[D]
    for x in coeffs:
        g = g.gcd(x)
    coeffs = [x // g for x in coeffs]
    P = ctx3.from_dict({(k,) + e: v for k, x in enumerate(coeffs) for e, v in x.to_dict().items()})
    disc = ctx2.from_dict({e[1:]: v for e, v in P.discriminant("t").to_dict().items()})
    if disc.is_zero():
        raise RealSolvingError("the solutions are not distinct for generic parameters")
    factors = [(f, (tuple(f.degrees()), m)) for f, m in (disc * coeffs[D]).factor()[1] if not f.is_constant()]
    keys = [k for _, k in factors]
    reuse = len(set(keys)) == len(keys) and set(keys) == set(known)
    if not reuse:
        known.clear()
    T = ctx2.from_dict({(0, 0): 1})
    for f, k in factors:
        if not reuse:
            known[k] = _on_curve(fib, f, rnd)
        if known[k]:
            T *= f
    return T * pow(int(T.leading_coefficient()), -1, p)


def _irregular(fib: ModFibres, f: Any, rnd: random.Random, points: int) -> list[bool]:
    """At up to ``points`` points of ``f = 0`` over ``F_p`` (on random lines): whether the fibre
    there is not ``D`` distinct points."""
    p = fib.p
    solve_in_a = f.degrees()[0] > 0
    out: list[bool] = []
    for _ in range(12 * points):
        v = rnd.randrange(1, p)
        u = f.subs({"b": v} if solve_in_a else {"a": v})
        terms = {e[0] if solve_in_a else e[1]: int(c) for e, c in u.to_dict().items()}
        line = nmod_poly([terms.get(i, 0) for i in range(max(terms, default=0) + 1)], p)
        roots = line.roots() if line.degree() > 0 else []
        if roots:
            r = int(roots[0][0])
            out.append(not fib.regular_at(*((r, v) if solve_in_a else (v, r)), fib.dim))
            if len(out) == points:
                break
    return out


def _on_curve(fib: ModFibres, f: Any, rnd: random.Random, points: int = 2) -> bool:
    """Whether ``f = 0`` is a discriminant curve (True also when no point of it is found)."""
    seen = _irregular(fib, f, rnd, points)
    return any(seen) or not seen


# ---------------------------------------------------------------- over Q
def _lift(acc: dict, modulus: int, part: dict, q: int) -> dict:
    """The Chinese remainders of the coefficients (by monomial) with one more prime's."""
    if not acc:
        return dict(part)
    inv = pow(modulus, -1, q)
    return {e: (x + modulus * ((part.get(e, 0) - x) * inv % q)) for e in set(acc) | set(part)
            for x in [acc.get(e, 0)]}


def _reconstruct(acc: dict, modulus: int) -> dict | None:
    """The primitive integer polynomial whose monic image the residues are, by rational
    reconstruction; None when the modulus is too small yet."""
    bound = math.isqrt(modulus // 2)
    fracs = {}
    for e, x in acc.items():
        got = ratrec(x % modulus, modulus, bound)
        if got is None:
            return None
        if got[0]:
            fracs[e] = got
    den = 1
    for _, d in fracs.values():
        den = math.lcm(den, d)
    ints = {e: n * (den // d) for e, (n, d) in fracs.items()}
    g = 0
    for v in ints.values():
        g = math.gcd(g, v)
    return {e: v // g for e, v in ints.items()}


def discriminant_curves(R: PolyRing, gens: Sequence[Poly], n: int, params: Sequence[str],
                        max_primes: int = 40) -> Curves:
    """The discriminant curves of the system ``gens`` (configuration variables the first ``n`` of
    ``R``, the two ``params`` the others) in the plane of ``params``. Raises
    :class:`NotApplicable` when the system is not zero-dimensional and nonempty."""
    fam = _Family(R, gens, n, params)
    terms = _integer_terms(fam)
    rnd = random.Random(SEED)
    forms = _forms(n, rnd)
    acc: dict = {}
    known: dict[tuple, bool] = {}
    modulus, last, key, D, samples, degrees = 1, None, None, 0, 0, None
    stream = primes(SEED)
    for used, p in enumerate(stream):
        if used >= max_primes:
            break
        fib = ModFibres(fam.ring, terms, p, forms, rnd.randrange(2 ** 30))
        try:
            got = fib.learn(D or None)
            if not D and got == 0:
                raise NotApplicable("the configuration space is not finite and nonempty (mobility is not 0)")
            degrees = degrees or _line_degrees(fib, rnd)
            D = got
            found = _matrix_mod(fib, *degrees, rnd)
        except Unlucky:
            continue
        if found is None:
            continue
        entries, Q, count = found
        samples += count
        T = _true_part(fib, entries, Q, rnd, known)
        image = {e: int(c) for e, c in T.to_dict().items()}
        shape = (T.total_degree(), max(image, key=lambda e: (sum(e), e)))
        if key is None or shape != key:
            if key is not None and shape[0] < key[0]:
                continue  # an unlucky prime (a factor lost): skip it
            key, acc, modulus, last = shape, {}, 1, None
        acc = _lift(acc, modulus, image, p)
        modulus *= p
        poly = _reconstruct(acc, modulus)
        if poly is not None and (poly == last or _confirmed(poly, fam, terms, forms, D, next(stream), rnd)):
            return _curves(poly, params, D, samples)
        last = poly
    raise RealSolvingError("the discriminant curves could not be lifted")


def _confirmed(poly: dict, fam: _Family, terms: list, forms: list, D: int, q: int, rnd: random.Random) -> bool:
    """Whether at a fresh prime ``q`` every point found on each irreducible factor of the lifted
    ``poly`` (two per factor) has a fibre that is not ``D`` distinct points (a wrong lift has
    regular fibres on its zeros)."""
    fib = ModFibres(fam.ring, terms, q, forms, rnd.randrange(2 ** 30))
    try:
        fib.learn(D)
    except Unlucky:
        return False
    ctx = fmpz_mpoly_ctx.get(("a", "b"), "lex")
    ctxq = nmod_mpoly_ctx.get(("a", "b"), ordering="deglex", modulus=q)
    for f, _ in ctx.from_dict(poly).factor()[1]:
        if f.is_constant():
            continue
        seen = _irregular(fib, ctxq.from_dict({e: int(c) % q for e, c in f.to_dict().items()}), rnd, 2)
        if not seen or not all(seen):
            return False
    return True


def _curves(poly: dict, params: Sequence[str], D: int, samples: int) -> Curves:
    """The irreducible factors over Q of the lifted product, as :class:`Curves`."""
    ctx2 = fmpz_mpoly_ctx.get((params[0], params[1]), "lex")
    factors = []
    for f, _ in ctx2.from_dict(poly).factor()[1]:
        if not f.is_constant():
            factors.append(f if f.leading_coefficient() > 0 else -f)
    factors.sort(key=lambda f: (f.total_degree(), str(f)))
    return Curves(tuple(params), [{(int(e[0]), int(e[1])): Fraction(int(c)) for e, c in f.to_dict().items()} for f in factors],
                  [str(f).replace(" ", "") for f in factors], D, samples)


_CACHE: dict[tuple, Curves] = {}


def mechanism_curves(m: Any, params: Sequence[str], limit: float | None) -> Curves:
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
            ok, got = within(limit, discriminant_curves, R, gens, n, params)
        except (NotApplicable, RealSolvingError) as e:
            got, ok = Curves(tuple(params), note=f"no discriminant curves ({e})"), True
        if not ok:
            return Curves(tuple(params), note=f"no discriminant curves (not found in {limit:g} s)")
        _CACHE[key] = got
    return _CACHE[key]


def curve_label(name: str, index: int) -> str:
    """A short name of a curve: its polynomial when short, else ``D<index + 1>``."""
    return name if len(name) <= 40 else f"D{index + 1}"
