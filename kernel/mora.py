"""Standard bases for arbitrary monomial orderings (local, mixed, global).

For a non-global ordering ``>`` the ring of interest is the localization
``K[x]_> = S^-1 K[x]`` with ``S = {u : LM(u) = 1}`` (for local orderings such as ``ds``:
the local ring at the origin).  A standard basis of ``I`` is a finite ``G`` in ``I`` whose
leading monomials generate the leading ideal ``L(I)``.

Two engines (Greuel–Pfister, *A Singular Introduction to Commutative Algebra*, 1.6–1.7):

* ``"mora"``: Buchberger's algorithm with Mora's normal form, which bounds the reduction by
  the *ecart* ``deg f - deg LM(f)`` and keeps reduced intermediate polynomials as reducers
  (GP Alg. 1.7.6).  Strategy as in Singular: ecarts follow the sugar (the degree of the
  homogenized polynomial), one queue holds generators, pairs and postponed polynomials by
  sugar, a polynomial whose reduction would raise its sugar waits while other work comes
  first, the reducers (basis elements and intermediate polynomials) persist, leading
  unit factors ``x^a u`` are cancelled.  Its bases are usually the ones Singular prints.
* ``"lazard"``: homogenize with a new variable ``t``, compute a Gröbner basis for the global
  ordering "degree, then ``>`` on the ``x``-part" with the global engine, set ``t = 1``
  (Lazard's method; every ``f`` in ``I`` has ``t^ecart f^h`` in the homogenized ideal, whose
  leading monomial is ``t^e LM(f)``).  It computes a global object, so it suffers from
  components away from the origin, but never from Mora's long detours.

``"auto"`` (the default) runs Mora within a :class:`Budget` and falls back to Lazard: Mora's
normal form terminates, but on some ideals only after reductions into degree 50 with
coefficients of thousands of digits (Singular's own ``reduce`` hangs on some of them).

Pair criteria: the Gebauer–Möller chain criteria (statements about syzygies of the leading
terms, valid for every ordering, GP 2.5.9) and the product criterion only when it really
gives a standard representation ``spoly(f, g) = f'g - g'f``: for a local ordering
``LM(f')LM(g)`` may equal ``LM(g')LM(f)``, and then the pair must be reduced.
"""
from __future__ import annotations

import heapq
from fractions import Fraction
from functools import lru_cache
from typing import Any, Callable, Sequence

from .groebner import groebner, normal_form
from .order import Block, Exp, MonomialOrder
from .poly import Poly, PolyRing, add_exp, divides, lcm_exp

Terms = dict[Exp, Any]


def _mask(e: Exp) -> int:
    m = 0
    for i, v in enumerate(e):
        if v:
            m |= 1 << i
    return m


class _Elem:
    """A polynomial with its leading data: leading monomial, mask, length and ecart.

    ``ecart`` is ``D - deg LM`` for the degree ``D`` of the homogenized polynomial the
    element stands for (its sugar); by default ``D`` is the polynomial's own degree."""

    __slots__ = ("p", "lm", "mask", "ecart", "tail_lm")

    def __init__(self, p: Terms, key: Callable, ecart: int | None = None) -> None:
        self.p = p
        ranked = sorted(p, key=key, reverse=True)[:2]
        self.lm = ranked[0]
        self.tail_lm = ranked[1] if len(ranked) > 1 else None
        self.mask = _mask(self.lm)
        self.ecart = max(sum(e) for e in p) - sum(self.lm) if ecart is None else ecart

    @property
    def sugar(self) -> int:
        return self.ecart + sum(self.lm)


class BudgetExceeded(Exception):
    """Mora's normal form ran past its budget (see :class:`Budget`)."""


class Budget:
    """A bound on the work of Mora's normal forms: reduction steps and the size (bits) of
    rational coefficients.  Successful runs on random ideals (3 variables, degree 5) stay
    below 600 steps and 400 bits; runaway ones pass 512 bits within a second."""

    def __init__(self, steps: int = 2000, bits: int = 512) -> None:
        self.steps, self.bits = steps, bits

    def charge(self, c: Any) -> None:
        """Account for one reduction step of a polynomial with leading coefficient ``c``."""
        self.steps -= 1
        if self.steps < 0 or (hasattr(c, "height_bits") and c.height_bits() > self.bits):
            raise BudgetExceeded


def _reduce_by(h: Terms, hlm: Exp, g: _Elem) -> Terms:
    """``h - (LT(h)/LT(g)) g`` for ``LM(g) | LM(h)``."""
    shift = tuple([a - b for a, b in zip(hlm, g.lm)])
    factor = h[hlm] / g.p[g.lm]
    out = dict(h)
    for e, c in g.p.items():
        te = tuple([a + b for a, b in zip(e, shift)])
        v = out.get(te)
        if v is None:
            out[te] = -factor * c
        else:
            v = v - factor * c
            if v == 0:
                del out[te]
            else:
                out[te] = v
    return out


def _choose(reducers: Sequence[_Elem], lm: Exp, ecart: int) -> _Elem | None:
    """A reducer whose leading monomial divides ``lm``: the first (reducers are kept by
    increasing sugar) unless its ecart exceeds ``ecart``; then one of least ecart, shorter
    ones first, stopping at the first whose ecart is at most ``ecart``."""
    mask = _mask(lm)
    best = None
    for g in reducers:
        if g.mask & ~mask or not divides(g.lm, lm):
            continue
        if best is None or g.ecart < best.ecart or (g.ecart == best.ecart and len(g.p) < len(best.p)):
            best = g
        if best.ecart <= ecart:
            break
    return best


def mora_normal_form(f: Terms, reducers: Sequence[_Elem], key: Callable,
                     budget: Budget | None = None) -> Terms:
    """Mora's weak normal form (GP Alg. 1.7.6 with sugar ecarts): ``h`` with ``u f - h`` in
    the ideal of the reducers for a unit ``u`` (``LM(u) = 1``), and ``h = 0`` or ``LM(h)``
    divisible by no leading monomial of a reducer.  Only leading terms are reduced.
    Raises :class:`BudgetExceeded` when a ``budget`` is given and runs out."""
    pool = sorted(reducers, key=lambda g: g.sugar)
    h, sugar = f, max(sum(e) for e in f) if f else 0
    while h:
        h = cancel_unit(h, key)
        lm = max(h, key=key)
        ecart = sugar - sum(lm)
        g = _choose(pool, lm, ecart)
        if g is None:
            return h
        if budget is not None:
            budget.charge(h[lm])
        if g.ecart > ecart:
            _insert(pool, _Elem(h, key, ecart))
            sugar += g.ecart - ecart
        h = _reduce_by(h, lm, g)
    return h


def _insert(pool: list[_Elem], g: _Elem) -> None:
    """Insert keeping ``pool`` sorted by sugar (after the elements of equal sugar)."""
    s = g.sugar
    i = len(pool)
    while i and pool[i - 1].sugar > s:
        i -= 1
    pool.insert(i, g)


def cancel_unit(h: Terms, key: Callable) -> Terms:
    """``lc(h) x^a`` when ``h = x^a u`` with ``x^a = LM(h)`` and ``u`` a unit of ``K[x]_>``
    (every term of ``h`` divisible by its leading monomial); ``h`` otherwise."""
    if len(h) > 1:
        lm = max(h, key=key)
        if all(divides(lm, e) for e in h):
            return {lm: h[lm]}
    return h


def _monic(h: Terms, key: Callable) -> Terms:
    lm = max(h, key=key)
    inv = 1 / h[lm]
    return {e: c * inv for e, c in h.items()}


def _lifts(f: _Elem, g: _Elem) -> bool:
    """Whether the pair (f, g) satisfies the product criterion with a standard
    representation: coprime leading monomials and ``LM(f')LM(g) != LM(g')LM(f)``."""
    if f.mask & g.mask:
        return False
    if f.tail_lm is None or g.tail_lm is None:
        return True
    return add_exp(f.tail_lm, g.lm) != add_exp(g.tail_lm, f.lm)


# Lazy reduction (as in Singular): a polynomial whose reduction would raise its sugar
# goes back to the queue when other work comes first, and so does one whose sugar rose
# LAZY_DEGREE above its start or that took more than LAZY_PASS reductions.
LAZY_DEGREE = 1
LAZY_PASS = 2


class _Pair:
    __slots__ = ("i", "j", "lcm", "alive")

    def __init__(self, i: int, j: int, lcm: Exp) -> None:
        self.i, self.j, self.lcm, self.alive = i, j, lcm, True


def mora(gens: Sequence[Poly], ring: PolyRing, budget: Budget | None = None) -> list[Terms]:
    """A minimal standard basis (as dicts, leading-term reduced, monic) by Buchberger's
    algorithm with Mora's normal form: the Gebauer–Möller criteria, a queue of generators,
    pairs and postponed polynomials ordered by sugar, and one growing set of reducers
    (basis elements and the intermediate polynomials Mora's normal form keeps).
    Raises :class:`BudgetExceeded` when a ``budget`` is given and runs out."""
    key = ring.order.key
    sign = 1 if ring.order.is_global else -1
    basis: list[_Elem] = []
    active: list[bool] = []
    pairs: list[_Pair] = []
    pool: list[_Elem] = []  # reducers, sorted by sugar
    queue: list[tuple] = []  # (sugar, rank of LM, counter, pair or (h, sugar))
    counter = 0

    def rank(e: Exp) -> tuple:  # smallest first for global orderings, largest first otherwise
        return tuple(sign * v for v in key(e))

    def push(sugar: int, lm: Exp, item: Any) -> None:
        nonlocal counter
        counter += 1
        heapq.heappush(queue, (sugar, rank(lm), counter, item))

    def first_in_queue(sugar: int, lm: Exp) -> bool:
        """Whether work of this sugar and leading monomial would be taken before the rest."""
        while queue and isinstance(queue[0][3], _Pair) and not queue[0][3].alive:
            heapq.heappop(queue)
        return not queue or (sugar, rank(lm)) <= queue[0][:2]

    def update(h: _Elem) -> None:
        k = len(basis)
        basis.append(h)
        active.append(True)
        new = []
        for i in range(k):
            if active[i]:
                new.append(_Pair(i, k, lcm_exp(basis[i].lm, h.lm)))
        kept = [a for a in new if not any(b.lcm != a.lcm and divides(b.lcm, a.lcm) for b in new)]
        by_lcm: dict[Exp, tuple[_Pair, bool]] = {}
        for a in kept:
            lifts = _lifts(basis[a.i], h)
            prev = by_lcm.get(a.lcm)
            if prev is None or (lifts and not prev[1]):
                by_lcm[a.lcm] = (a, lifts)
        for p in pairs:
            if p.alive and divides(h.lm, p.lcm) and lcm_exp(basis[p.i].lm, h.lm) != p.lcm \
                    and lcm_exp(basis[p.j].lm, h.lm) != p.lcm:
                p.alive = False
        pairs[:] = [p for p in pairs if p.alive]
        for a, lifts in by_lcm.values():
            if not lifts:
                pairs.append(a)
                push(sum(a.lcm) + max(basis[a.i].ecart, h.ecart), a.lcm, a)
        for i in range(k):
            if active[i] and divides(h.lm, basis[i].lm):
                active[i] = False

    def reduce(h: Terms, sugar: int) -> tuple[Terms, int] | None:
        """Reduce until irreducible (returned with its sugar; {} for zero) or postponed
        (None)."""
        limit, passes = sugar + LAZY_DEGREE, 0
        while True:
            h = cancel_unit(h, key)
            lm = max(h, key=key)
            ecart = sugar - sum(lm)
            g = _choose(pool, lm, ecart)
            if g is None:
                return h, sugar
            if budget is not None:
                budget.charge(h[lm])
            if g.ecart > ecart:
                if not first_in_queue(sugar, lm):
                    push(sugar, lm, (h, sugar))
                    return None
                _insert(pool, _Elem(h, key, ecart))
                sugar += g.ecart - ecart
            h = _reduce_by(h, lm, g)
            if not h:
                return h, sugar
            passes += 1
            if sugar >= limit or passes > LAZY_PASS:
                lm = max(h, key=key)
                if not first_in_queue(sugar, lm):
                    if _choose(pool, lm, sugar - sum(lm)) is None:
                        return h, sugar
                    push(sugar, lm, (h, sugar))
                    return None

    for g in gens:
        if not g.is_zero():
            push(g.total_degree(), g.lm(), (dict(g.terms), g.total_degree()))
    while queue:
        sugar, _, _, item = heapq.heappop(queue)
        if isinstance(item, _Pair):
            if not item.alive:
                continue
            item.alive = False
            pairs.remove(item)
            h = _spoly(basis[item.i], basis[item.j], item.lcm)
        else:
            h, sugar = item
        if not h:
            continue
        done = reduce(h, sugar)
        if done is None or not done[0]:
            continue
        h, sugar = done
        h = _monic(cancel_unit(h, key), key)
        lm = max(h, key=key)
        if lm == ring.zero_exp:
            return [{ring.zero_exp: ring.field.one}]
        elem = _Elem(h, key, min(sugar - sum(lm), max(sum(e) for e in h) - sum(lm)))
        _insert(pool, elem)
        update(elem)
    return [b.p for b, a in zip(basis, active) if a]


def _spoly(f: _Elem, g: _Elem, lc: Exp) -> Terms:
    sf = tuple([a - b for a, b in zip(lc, f.lm)])
    sg = tuple([a - b for a, b in zip(lc, g.lm)])
    cf, cg = f.p[f.lm], g.p[g.lm]
    out: Terms = {}
    for e, c in f.p.items():
        out[tuple([a + b for a, b in zip(e, sf)])] = c * cg
    for e, c in g.p.items():
        te = tuple([a + b for a, b in zip(e, sg)])
        v = out.get(te)
        v = -c * cf if v is None else v - c * cf
        if v == 0:
            out.pop(te, None)
        else:
            out[te] = v
    return out


def homogenized_order(order: MonomialOrder) -> MonomialOrder:
    """The global ordering on ``(x, t)``: total degree first, then ``order`` on the x-part."""
    n = order.nvars
    blocks = [Block("a", 0, (1,) * (n + 1))]
    rows = [list(r) for r in order.matrix]
    blocks.append(Block("M", n, tuple(v for r in _square(rows, n) for v in r)))
    blocks.append(Block("lp", 1))
    return MonomialOrder(blocks)


def _square(rows: list[list[int]], n: int) -> list[list[int]]:
    """``n`` linearly independent rows of ``rows`` defining the same ordering (the first
    rows that raise the rank; later rows never matter once the rank is full)."""
    chosen: list[list[int]] = []
    echelon: list[list[Fraction]] = []
    for r in rows:
        v = [Fraction(x) for x in r]
        for e in echelon:
            piv = next(i for i, x in enumerate(e) if x)
            if v[piv]:
                f = v[piv] / e[piv]
                v = [a - f * b for a, b in zip(v, e)]
        if any(v):
            echelon.append(v)
            chosen.append(r)
        if len(chosen) == n:
            break
    return chosen


def _homogenized_ring(ring: PolyRing) -> PolyRing:
    return PolyRing(ring.field, ring.names + ("@t",), homogenized_order(ring.order))


def _homogenize(p: Poly, hring: PolyRing) -> Poly:
    d = p.total_degree()
    return Poly(hring, {e + (d - sum(e),): c for e, c in p.terms.items()})


def _dehomogenize(p: Poly) -> Terms:
    out: Terms = {}
    for e, c in p.terms.items():
        out[e[:-1]] = out[e[:-1]] + c if e[:-1] in out else c
    return {e: c for e, c in out.items() if c != 0}


def lazard(gens: Sequence[Poly], ring: PolyRing) -> list[Terms]:
    """A minimal standard basis by Lazard's method: a homogeneous Gröbner basis of the
    homogenized ideal for :func:`homogenized_order`, dehomogenized.  Unit factors
    ``x^a u`` of the generators are cancelled first (they only enlarge the global problem)."""
    key = ring.order.key
    hring = _homogenized_ring(ring)
    hgens = [_homogenize(Poly(ring, cancel_unit(g.terms, key)), hring) for g in gens if not g.is_zero()]
    out = [_monic(cancel_unit(p, key), key) for p in (_dehomogenize(h) for h in groebner(hgens, hring)) if p]
    return _minimal(out, key)


def _minimal(basis: list[Terms], key: Callable) -> list[Terms]:
    """Drop elements whose leading monomial is divisible by another's (keep the first)."""
    lms = [max(b, key=key) for b in basis]
    keep = []
    for i, (b, m) in enumerate(zip(basis, lms)):
        if not any(divides(lms[j], m) and (lms[j] != m or j < i) for j in range(len(basis)) if j != i):
            keep.append(b)
    return keep


ENGINES: dict[str, Callable[[Sequence[Poly], PolyRing], list[Terms]]] = {"mora": mora, "lazard": lazard}


def standard_basis(gens: Sequence[Poly], ring: PolyRing | None = None, engine: str = "auto") -> list[Poly]:
    """A standard basis of the ideal generated by ``gens`` in ``K[x]_>`` for the ring's
    ordering ``>``.

    Global orderings: the reduced Gröbner basis (:func:`groebner`).  Otherwise a minimal
    standard basis, monic, with reduced leading terms but unreduced tails (tail reduction
    need not terminate for local orderings), sorted from the largest leading monomial down
    as Singular's ``std`` prints it; ``[1]`` when the ideal is the whole ring ``K[x]_>``
    and ``[]`` for the zero ideal.

    ``engine``: ``"mora"``, ``"lazard"`` or ``"auto"`` (Mora within a :class:`Budget`,
    which gives Singular's generators in the common cases, then Lazard)."""
    ring = ring or (gens[0].ring if gens else None)
    if ring is None:
        return []
    gens = [g for g in gens if not g.is_zero()]
    if ring.order.is_global and engine == "auto":
        return groebner(gens, ring)
    if not gens:
        return []
    if engine == "auto":
        try:
            basis = mora(gens, ring, Budget())
        except BudgetExceeded:
            basis = lazard(gens, ring)
    else:
        basis = ENGINES[engine](gens, ring)
    key = ring.order.key
    basis.sort(key=lambda p: key(max(p, key=key)), reverse=not ring.order.is_global)
    return [Poly(ring, b) for b in basis]


def elems(basis: Sequence[Poly]) -> list[_Elem]:
    """Reducers for :func:`mora_normal_form` from polynomials."""
    return [_Elem(dict(b.terms), b.ring.order.key) for b in basis if not b.is_zero()]


def weak_normal_form(f: Poly, basis: Sequence[Poly]) -> Poly:
    """Singular's ``reduce``/``NF`` for a local or mixed ordering: a weak normal form ``h`` of
    ``f`` (``u f - h`` in the ideal for a unit ``u``, and ``h = 0`` or ``LM(h)`` not in
    ``L(basis)``), so zero iff ``f`` lies in the ideal of ``K[x]_>`` when ``basis`` is a
    standard basis.  Mora's normal form (leading terms, then a leading-monomial unit factor
    cancelled: ``x^a u -> x^a``, then :func:`tail_reduce`), as Singular computes it; for a local degree
    ordering (``ds Ds ws Ws``) past its :class:`Budget` the exact normal form of
    :func:`homogenized_normal_form`.  The result is determined up to a unit and modulo the
    ideal, not term by term."""
    if f.is_zero():
        return f
    key = f.ring.order.key
    degree_first = all(v < 0 for v in f.ring.order.matrix[0])
    try:
        h = mora_normal_form(dict(f.terms), elems(basis), key, Budget() if degree_first else None)
    except BudgetExceeded:
        return homogenized_normal_form(f, basis)
    if not h:
        return Poly(f.ring, h)
    return Poly(f.ring, tail_reduce(cancel_unit(h, key), basis))


def highest_corner(basis: Sequence[Poly]) -> Exp | None:
    """The highest corner of a standard basis for a local ordering: the smallest monomial
    outside the leading ideal, when there are finitely many; every smaller monomial lies in
    the ideal of the local ring (its normal form is a combination of smaller standard
    monomials).  None when the quotient is infinite-dimensional or the ordering not local."""
    from .hilbert import kbase
    basis = [b for b in basis if not b.is_zero()]
    if not basis or not basis[0].ring.order.is_local:
        return None
    ring = basis[0].ring
    std = kbase([b.lm() for b in basis], ring.nvars)
    return min(std, key=ring.order.key) if std else None


def tail_reduce(h: Terms, basis: Sequence[Poly]) -> Terms:
    """Reduce the terms after the leading one, from the largest down, as Singular's ``reduce``
    mostly does: drop those below the highest corner (:func:`highest_corner`: they lie in the
    ideal); reduce a term ``t`` by the first basis element (smallest leading monomial first)
    whose leading monomial divides it, any element when there is a highest corner (finitely
    many monomials lie above it), else only an element whose ecart is at most that of the
    tail from ``t`` on (its degree minus ``deg t``: the degrees of the tail never exceed
    their first maximum, so this ends).  The leading term and the class modulo the ideal do
    not change."""
    ring = basis[0].ring if basis else None
    if ring is None or len(h) < 2:
        return h
    key = ring.order.key
    corner = highest_corner(basis)
    pool = [_Elem(dict(b.terms), key) for b in sorted(basis, key=lambda b: key(b.lm())) if not b.is_zero()]
    h = dict(h)
    done = {max(h, key=key)}
    while True:
        if corner is not None:
            bound = key(corner)
            h = {e: c for e, c in h.items() if key(e) >= bound}
        rest = [e for e in h if e not in done]
        if not rest:
            return h
        t = max(rest, key=key)
        kt = key(t)
        ecart = max(sum(e) for e in h if key(e) <= kt) - sum(t)
        g = next((g for g in pool if divides(g.lm, t) and (corner is not None or g.ecart <= ecart)), None)
        if g is None:
            done.add(t)
        else:
            h = _reduce_by(h, t, g)


@lru_cache(maxsize=32)
def _homogenized_basis(basis: tuple[Poly, ...]) -> tuple[PolyRing, list[Poly]]:
    hring = _homogenized_ring(basis[0].ring)
    return hring, groebner([_homogenize(b, hring) for b in basis], hring)


def homogenized_normal_form(f: Poly, basis: Sequence[Poly]) -> Poly:
    """A normal form with ``f - h`` in the ideal (no unit) and ``h = 0`` or ``LM(h)`` not in
    ``L(basis)``: the global normal form of ``t^k f^h`` modulo a Gröbner basis of the
    homogenized generators (ordering :func:`homogenized_order`) with ``t = 1``, for the
    first ``k = 0, 1, 3, 7, ...`` whose result has a leading monomial outside ``L(basis)``.
    Such a ``k`` exists when the ordering is a local degree ordering (its first weight row
    negative): the leading monomials of all ``h`` congruent to ``f`` whose leading monomial
    lies in ``L(basis)`` have bounded degree, and for ``k`` beyond that bound plus the ecarts
    of the basis, ``t^k`` times such a monomial is a leading monomial of the homogenized
    ideal.  For other orderings the loop need not end."""
    basis = [b for b in basis if not b.is_zero()]
    if f.is_zero() or not basis:
        return f
    ring, key = f.ring, f.ring.order.key
    hring, hbasis = _homogenized_basis(tuple(basis))
    lms = [b.lm() for b in basis]
    t = hring.gen(ring.nvars)
    fh, k = _homogenize(f, hring), 0
    while True:
        h = _dehomogenize(normal_form(fh * t ** k, hbasis))
        if not h or not any(divides(m, max(h, key=key)) for m in lms):
            return Poly(ring, h)
        k = 2 * k + 1
