"""The prime ideals of the components of a curve, interpolated modulo a prime and proved over QQ.

Setting (:func:`.slices.curve_image`): ``J ⊂ QQ[x1..xn]`` radical, equidimensional of dimension
1, and a projection ``y = (L1, L2)`` to the plane whose eliminant factors into irreducible
``g_1..g_k`` of degrees adding up to ``deg V(J)``: ``J`` has exactly ``k`` minimal primes
``Q_i``, ``Q_i`` the one over ``g_i`` (``V(J + g_i(L))`` is ``C_i = V(Q_i)`` and finitely
many points).

1. Points of ``C_i`` over ``F_p``: for random ``a``, each simple root ``b`` of ``g_i(a, y)`` that
   is a root of no other factor has a single point of ``V(J)`` over it (the projection is
   birational on ``C_i``): the left eigenvector for ``b`` of multiplication by ``L2`` on
   ``F_p[x]/(J + (L1 - a))`` is the evaluation at that point.
2. ``Q_i`` up to degree ``d`` is the kernel of the evaluation of the monomials of degree ``<= d``
   at enough points (more than the Hilbert function of ``Q_i`` at ``d``); its echelon form with
   the monomials in decreasing ``dp`` order gives the reduced Gröbner basis of ``Q_i`` truncated
   at degree ``d``, canonical, so its coefficients are lifted to QQ by rational reconstruction.
   ``d`` grows until the truncation has dimension 1 and degree ``deg g_i`` modulo ``p``.
3. Proof over QQ (:func:`_proved`) that the lifted candidates ``P_1..P_k`` are the ``Q_i``:
   each ``G_i`` a Gröbner basis (its S-pairs reduce to 0 over QQ) with (a) ``J ⊆ P_i`` and
   (c) ``dim P_i = 1``; then the one-dimensional part of ``V(P_i)`` is a nonempty union of
   components ``C_l``, ``l ∈ S_i``, each ``Q_l`` an associated prime of ``P_i``.  (d)
   ``h_i = ∏_{j≠i} u_j`` (``u_j ∈ G_j``, reduced modulo ``G_i``) is a nonzerodivisor modulo
   ``P_i``.  As ``h_i`` lies in every ``Q_l``, ``l ∈ S_j``, ``j ≠ i`` (up to ``P_i``), and in
   no associated prime of ``P_i``, the ``S_i`` are disjoint: ``k`` nonempty disjoint sets of
   ``k`` components are singletons ``{σ(i)}``.  Then for ``u ∈ Q_σ(i)``, ``u·h_i`` lies in
   ``⋂_l Q_l + P_i = J + P_i = P_i``, so ``u ∈ P_i : h_i = P_i``; and ``P_i ⊆ rad P_i = Q_σ(i)``:
   ``P_i = Q_σ(i)``.
   (d) is decided modulo a prime ``q`` on the homogenizations (``P*`` from the homogenized
   ``G_i``, a Gröbner basis): ``P* ⊆ P* : h*`` gives ``HF(S/(P* + h*)) >= HF(S/P*)(1 - t^e)``
   coefficientwise over QQ (``e = deg h*``), and reducing integer generators modulo ``q`` can
   only raise the Hilbert function; so equality modulo ``q`` forces equality over QQ, that is
   ``P* : h* = P*``, and dehomogenizing, ``P_i : h_i = P_i``.

Every step either proves the primes or gives up (None): the caller falls back to saturation.
"""
from __future__ import annotations

import random
from math import gcd, isqrt
from typing import Sequence

import flint

from .dimension import krull_dim
from .groebner import normal_form
from .fglm import border_forms
from .hilbert import degree, hilbert_numerators, kbase
from .coeffs import GF
from .ideals import dp_ring, move, std
from .modular import ExactReducer, primes, ratrec
from .order import MonomialOrder
from .poly import Poly, PolyRing
from .progress import report

#: Give up after this many evaluation points per component and prime (a curve of degree ``e``
#: needs about ``e·d`` at degree ``d``).
MAX_POINTS = 400
#: The largest degree of the truncated bases tried.
MAX_DEGREE = 6


def _monomials(n: int, d: int, order: MonomialOrder) -> list[tuple[int, ...]]:
    """The monomials of degree ``<= d`` in ``n`` variables, decreasing in ``order``."""
    out: list[tuple[int, ...]] = []

    def grow(prefix: list[int], left: int) -> None:
        if len(prefix) == n - 1:
            for k in range(left + 1):
                out.append(tuple(prefix + [k]))
            return
        for k in range(left + 1):
            grow(prefix + [k], left - k)
    grow([], d)
    return sorted(out, key=order.key, reverse=True)


class _Sampler:
    """Points of the components modulo ``p`` (step 1)."""

    def __init__(self, ideal: Sequence[Poly], ring: PolyRing, forms: Sequence[Poly],
                 factors: Sequence[Poly], p: int, seed: int) -> None:
        self.p, self.rnd = p, random.Random(seed)
        self.R = PolyRing(GF(p), list(ring.names), MonomialOrder.simple("dp", ring.nvars))
        field = self.R.field
        self.J = [Poly(self.R, {e: field(c) for e, c in g.terms.items()}) for g in ideal]
        self.L = [Poly(self.R, {e: field(c) for e, c in f.terms.items()}) for f in forms]
        self.g = [{e: int(field(c)) for e, c in f.terms.items()} for f in factors]
        self.points: list[list[list[int]]] = [[] for _ in factors]
        self.staircases: dict[tuple, list[tuple]] = {}

    def _univariate(self, k: int, a: int) -> flint.nmod_poly:
        coeffs: dict[int, int] = {}
        for (i, j), c in self.g[k].items():
            coeffs[j] = (coeffs.get(j, 0) + c * pow(a, i, self.p)) % self.p
        return flint.nmod_poly([coeffs.get(j, 0) for j in range(max(coeffs) + 1)], self.p)

    def sample(self, want: Sequence[int]) -> None:
        """Add points until component ``i`` has ``want[i]`` of them (or too many slices failed)."""
        for _ in range(4 * max(want) + 40):
            if all(len(pts) >= w for pts, w in zip(self.points, want)):
                return
            a = self.rnd.randrange(self.p)
            unis = [self._univariate(k, a) for k in range(len(self.g))]
            whole = unis[0]
            for u in unis[1:]:
                whole = whole * u
            if whole.degree() <= 0 or whole.gcd(whole.derivative()).degree() != 0:
                continue  # a point at infinity or a multiple root: another slice
            roots = [[int(b) for b, _ in u.roots()] if len(self.points[k]) < want[k] else []
                     for k, u in enumerate(unis)]
            if any(roots):
                for k, pt in self._slice_points(a, roots):
                    self.points[k].append(pt)

    def _slice_points(self, a: int, roots: list[list[int]]) -> list[tuple[int, list[int]]]:
        """The points of ``V(J)`` on ``L1 = a`` over the roots ``b`` (``L2 = b``): left eigenvectors
        of multiplication by ``L2`` on ``F_p[x]/(J + (L1 - a))`` are the evaluations there."""
        p, R, n = self.p, self.R, self.R.nvars
        basis = std(self.J + [self.L[0] - R.const(a)], R)
        lms = tuple(g.lm() for g in basis)
        if lms not in self.staircases:  # the same for almost every slice
            self.staircases[lms] = kbase(list(lms), n)
        B = self.staircases[lms]
        if (0,) * n not in B:
            return []
        D, index = len(B), {b: i for i, b in enumerate(B)}
        forms = border_forms([{e: int(c) for e, c in g.terms.items()} for g in basis], R.order, B, p)

        def nf(t: tuple) -> list[int]:
            if t in index:
                v = [0] * D
                v[index[t]] = 1
                return v
            return forms[t]
        one = index[(0,) * n]
        cols = []  # NF(L2 * b_j)
        L2 = {e: int(c) for e, c in self.L[1].terms.items()}
        for b in B:
            col = [0] * D
            for e, c in L2.items():
                for i, v in enumerate(nf(tuple(x + y for x, y in zip(b, e)))):
                    if v:
                        col[i] = (col[i] + c * v) % p
            cols.append(col)
        coords = [nf(tuple(int(i == k) for i in range(n))) for k in range(n)]
        out = []
        for k, bs in enumerate(roots):
            for b in bs:
                A = flint.nmod_mat([[(cols[j][i] - (b if i == j else 0)) % p for i in range(D)]
                                    for j in range(D)], p)  # (M - b)^T: rows j, columns i
                K, nullity = A.nullspace()
                if nullity != 1 or int(K[one, 0]) == 0:
                    continue
                v = [int(K[i, 0]) for i in range(D)]
                s = pow(v[one], -1, p)
                out.append((k, [sum(x * y for x, y in zip(v, c)) * s % p for c in coords]))
        return out


def _truncated_basis(points: list[list[int]], n: int, d: int, order: MonomialOrder,
                     p: int) -> tuple[list[tuple], list[dict[tuple, int]]] | None:
    """The reduced basis modulo ``p`` of the ideal of the points truncated at degree ``d``:
    (its leading monomials, its elements), or None when the points are too few to tell."""
    mons = _monomials(n, d, order)
    if len(points) <= 0:
        return None
    rows = []
    for pt in points:
        powers = [[pow(v, k, p) for k in range(d + 1)] for v in pt]
        row = []
        for m in mons:
            v = 1
            for i, k in enumerate(m):
                if k:
                    v = v * powers[i][k] % p
            row.append(v)
        rows.append(row)
    E = flint.nmod_mat(rows, p)
    if E.rank() >= len(points):
        return None  # the points may not pin the Hilbert function down: more are needed
    K, nullity = E.nullspace()
    if nullity == 0:
        return [], []
    vecs = flint.nmod_mat([[int(K[i, j]) for i in range(len(mons))] for j in range(nullity)], p).rref()[0]
    rows_ = []
    for r in range(nullity):
        terms = {mons[c]: int(vecs[r, c]) for c in range(len(mons)) if int(vecs[r, c])}
        rows_.append((mons[min(c for c in range(len(mons)) if int(vecs[r, c]))], terms))
    keep = [(lm, t) for lm, t in rows_
            if not any(m != lm and all(a <= b for a, b in zip(m, lm)) for m, _ in rows_)]
    return [lm for lm, _ in keep], [t for _, t in keep]


def _candidate(points: list[list[int]], ring: PolyRing, e: int, p: int) -> list[dict[tuple, int]] | None:
    """The reduced ``dp`` basis modulo ``p`` of the ideal of the points of a component of
    degree ``e`` (step 2): the linear part first, the rest in the variables it leaves free."""
    n = ring.nvars
    order = MonomialOrder.simple("dp", n)
    first = _truncated_basis(points, n, 1, order, p)
    if first is None:
        return None
    lms, linear = first
    bound = {lm.index(1) for lm in lms}
    free = [i for i in range(n) if i not in bound]
    sub = MonomialOrder.simple("dp", len(free))
    for d in range(2, MAX_DEGREE + 1):
        got = _truncated_basis([[pt[i] for i in free] for pt in points], len(free), d, sub, p)
        if got is None:
            return None
        slms, polys = got
        line = not slms and len(free) == 1 and e == 1  # the points span a line
        if line or slms and krull_dim(slms, len(free)) == 1 and degree(slms, len(free)).degree == e:
            def lift(m: tuple) -> tuple:
                out = [0] * n
                for i, k in zip(free, m):
                    out[i] = k
                return tuple(out)
            return linear + [{lift(m): c for m, c in t.items()} for t in polys]
    return None


def _lift(residues: list[list[dict[tuple, int]]], moduli: list[int]) -> list[Poly] | None:
    """Rational reconstruction of bases of one shape modulo several primes (Chinese remainders)."""
    shape = [sorted(t) for t in residues[0]]
    if any([sorted(t) for t in r] != shape for r in residues):
        return None
    m = 1
    for q in moduli:
        m *= q
    bound = isqrt(m // 2)
    out = []
    for k, mons in enumerate(shape):
        terms = {}
        for mon in mons:
            a, mm = 0, 1
            for r, q in zip(residues, moduli):
                a = a + mm * ((r[k][mon] - a) * pow(mm, -1, q) % q)
                mm *= q
            rec = ratrec(a, m, bound)
            if rec is None:
                return None
            terms[mon] = flint.fmpq(*rec)
        out.append(terms)
    return out


def ideal_of_components(ideal: Sequence[Poly], ring: PolyRing, forms: Sequence[Poly], factors: Sequence[Poly],
                        max_primes: int = 3, seed: int = 3) -> list[list[Poly]] | None:
    """The minimal primes of ``ideal`` (radical, equidimensional of dimension 1) over the
    eliminant's factors ``factors`` (polynomials of ``QQ[y1, y2]``, ``y = forms``, certified by
    :func:`.slices.curve_image`), proved (see the module docstring), as reduced bases in
    ``ring``'s order; None when a step gives up (too few points, a failed lift or proof within
    ``max_primes`` primes)."""
    dp = dp_ring(ring)
    J = move(list(ideal), dp)
    degs = [g.total_degree() for g in factors]
    stream = _large_primes(seed)
    residues: list[list[list[dict]]] = []
    moduli: list[int] = []
    for attempt in range(max_primes):
        p = next(stream)
        sampler = _Sampler(J, dp, move(list(forms), dp), factors, p, seed + attempt)
        want = [2 * e + 8 for e in degs]
        cands: list[list[dict]] = []
        while True:
            sampler.sample(want)
            cands = []
            for k, e in enumerate(degs):
                c = _candidate(sampler.points[k], dp, e, p) if len(sampler.points[k]) >= want[k] else None
                if c is None:
                    break
                cands.append(c)
            if len(cands) == len(degs):
                break
            k = len(cands)
            if len(sampler.points[k]) < want[k] or want[k] >= MAX_POINTS:
                return None
            want[k] = 2 * want[k]
        report("mode ideals", attempt + 1, max_primes, "interpolated modulo a prime")
        residues.append(cands)
        moduli.append(p)
        lifted = [_lift([r[k] for r in residues], moduli) for k in range(len(degs))]
        if any(x is None for x in lifted):
            continue
        primes_ = [[Poly(dp, t) for t in basis] for basis in lifted]
        if _proved(J, dp, primes_):
            return [std(move(P, ring), ring) for P in primes_]
    return None


def _large_primes(seed: int):
    """Distinct pseudo-random primes below ``2^31`` (the compiled F4's limit): fewer for the lift."""
    rnd, seen = random.Random(seed), set()
    while True:
        q = _prime_below(rnd.randrange(1 << 30, 1 << 31))
        if q not in seen:
            seen.add(q)
            yield q


def _prime_below(n: int) -> int:
    while not flint.fmpz(n).is_prime():
        n -= 1
    return n


def _integral(p: Poly) -> dict[tuple, int]:
    den = 1
    for c in p.terms.values():
        den = den * int(c.q) // gcd(den, int(c.q))
    return {e: int(c.p) * (den // int(c.q)) for e, c in p.terms.items()}


def _nonzerodivisor(basis: list[Poly], h: Poly, q: int) -> bool:
    """Whether ``h`` is proved a nonzerodivisor modulo the ideal of the ``dp`` Gröbner basis
    ``basis`` over QQ, by the Hilbert series of the homogenizations modulo ``q`` (see the module
    docstring; False also when ``q`` cannot tell)."""
    n = basis[0].ring.nvars
    target = hilbert_numerators([g.lm() for g in basis], n)[0]
    e = h.total_degree()
    target = _trim([a - (target[k - e] if k >= e else 0) for k, a in enumerate(target + [0] * e)])
    S = PolyRing(GF(q), list(basis[0].ring.names) + ["_h"], MonomialOrder.simple("dp", n + 1))
    gens = []
    for g in list(basis) + [h]:
        top = g.total_degree()
        gens.append(Poly(S, {e_ + (top - sum(e_),): S.field(c) for e_, c in _integral(g).items()}))
    got = hilbert_numerators([g.lm() for g in std([g for g in gens if not g.is_zero()], S)], n + 1)[0]
    return got == target


def _trim(a: list[int]) -> list[int]:
    while len(a) > 1 and a[-1] == 0:
        a = a[:-1]
    return a


def _proved(J: list[Poly], ring: PolyRing, candidates: list[list[Poly]]) -> bool:
    """Steps (a), (c), (d) of the module docstring over QQ for the candidates (``dp`` ring)."""
    n = ring.nvars
    bases = []
    for k, P in enumerate(candidates):
        G = std(P, ring)
        terms = [{e: c for e, c in b.terms.items()} for b in G]
        if not ExactReducer(terms, ring.order).is_groebner():  # the basis property, exactly
            return False
        if any(not normal_form(f, G).is_zero() for f in J) or krull_dim([b.lm() for b in G], n) != 1:
            return False  # (a), (c)
        bases.append(G)
        report("mode ideals", k + 1, len(candidates), "proved to contain J, of dimension 1")
    stream = primes(7)
    for i, G in enumerate(bases):
        h = ring.one()
        for j, other in enumerate(bases):
            if j == i:
                continue
            u = next((r for r in (normal_form(b, G) for b in sorted(other, key=lambda b: b.total_degree()))
                      if not r.is_zero()), None)
            if u is None:
                return False
            h = normal_form(h * u, G)
        if not any(_nonzerodivisor(G, h, next(stream)) for _ in range(2)):
            return False  # (d)
    return True
