"""Standard bases for arbitrary monomial orderings (local, mixed, global).

For a non-global ordering ``>`` the ring of interest is the localization
``K[x]_> = S^-1 K[x]`` with ``S = {u : LM(u) = 1}`` (for local orderings such as ``ds``:
the local ring at the origin).  A standard basis of ``I`` is a finite ``G`` in ``I`` whose
leading monomials generate the leading ideal ``L(I)``.

Two engines (Greuel–Pfister, *A Singular Introduction to Commutative Algebra*, 1.6–1.7):

* ``"mora"`` (default): Buchberger's algorithm with Mora's normal form, which bounds the
  reduction by the *ecart* ``deg f - deg LM(f)`` and keeps reduced intermediate
  polynomials as reducers (GP Alg. 1.7.6).  It processes the generators and pairs the way
  Singular's ``std`` does, so its bases are usually the ones Singular prints.
* ``"lazard"``: homogenize with a new variable ``t``, compute a Gröbner basis for the global
  ordering "degree, then ``>`` on the ``x``-part" with the global engine, set ``t = 1``
  (GP Lemma 1.7.9).  Independent of the code here, so the tests use it as a cross-check.

Pair criteria: the Gebauer–Möller chain criteria (statements about syzygies of the leading
terms, valid for every ordering, GP 2.5.9) and the product criterion only when it really
gives a standard representation ``spoly(f, g) = f'g - g'f``: for a local ordering
``LM(f')LM(g)`` may equal ``LM(g')LM(f)``, and then the pair must be reduced.
"""
from __future__ import annotations

from typing import Any, Callable, Sequence

from .groebner import groebner
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
    """A polynomial with its leading data: leading monomial, mask, degree, ecart."""

    __slots__ = ("p", "lm", "mask", "deg", "ecart", "tail_lm")

    def __init__(self, p: Terms, key: Callable) -> None:
        self.p = p
        ranked = sorted(p, key=key, reverse=True)[:2]
        self.lm = ranked[0]
        self.tail_lm = ranked[1] if len(ranked) > 1 else None
        self.mask = _mask(self.lm)
        self.deg = max(sum(e) for e in p)
        self.ecart = self.deg - sum(self.lm)


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


def mora_normal_form(f: Terms, reducers: Sequence[_Elem], key: Callable) -> Terms:
    """Mora's weak normal form (GP Alg. 1.7.6): ``h`` with ``u f - h`` in the ideal of the
    reducers for a unit ``u`` (``LM(u) = 1``), and ``h = 0`` or ``LM(h)`` not divisible by any
    leading monomial of a reducer.  Only leading terms are reduced."""
    h = f
    extra: list[_Elem] = []
    while h:
        h = cancel_unit(h, key)
        lm = max(h, key=key)
        mask = _mask(lm)
        best = None
        for pool in (reducers, extra):
            for g in pool:
                if g.mask & ~mask == 0 and divides(g.lm, lm) and (best is None or g.ecart < best.ecart):
                    best = g
                    if g.ecart == 0:
                        break
            if best is not None and best.ecart == 0:
                break
        if best is None:
            return h
        if best.ecart > max(sum(e) for e in h) - sum(lm):
            extra.append(_Elem(h, key))
        h = _reduce_by(h, lm, best)
    return h


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


def mora(gens: Sequence[Poly], ring: PolyRing) -> list[Terms]:
    """A minimal standard basis (as dicts, leading-term reduced, monic) by Buchberger's
    algorithm with Mora's normal form, the Gebauer–Möller criteria and pair selection by
    sugar (the degree of the homogenized S-polynomial)."""
    key = ring.order.key
    sign = 1 if ring.order.is_global else -1
    basis: list[_Elem] = []
    active: list[bool] = []
    pairs: list[tuple[int, int, Exp, int]] = []

    def update(h: _Elem) -> None:
        nonlocal pairs
        k = len(basis)
        basis.append(h)
        active.append(True)
        new = []
        for i in range(k):
            if active[i]:
                g = basis[i]
                lc = lcm_exp(g.lm, h.lm)
                sugar = max(g.deg + sum(lc) - sum(g.lm), h.deg + sum(lc) - sum(h.lm))
                new.append((i, k, lc, sugar))
        kept = [a for a in new if not any(b[2] != a[2] and divides(b[2], a[2]) for b in new)]
        by_lcm: dict[Exp, tuple[tuple, bool]] = {}
        for a in kept:
            lifts = _lifts(basis[a[0]], h)
            prev = by_lcm.get(a[2])
            if prev is None or (lifts and not prev[1]):
                by_lcm[a[2]] = (a, lifts)
        final = [a for a, lifts in by_lcm.values() if not lifts]
        old = [(i, j, lc, s) for (i, j, lc, s) in pairs
               if not (divides(h.lm, lc) and lcm_exp(basis[i].lm, h.lm) != lc
                       and lcm_exp(basis[j].lm, h.lm) != lc)]
        pairs = old + final
        for i in range(k):
            if active[i] and divides(h.lm, basis[i].lm):
                active[i] = False

    def add(h: Terms) -> bool:
        """Enter a reduced nonzero polynomial; True when it is a unit."""
        h = _monic(cancel_unit(h, key), key)
        if max(h, key=key) == ring.zero_exp:
            return True
        update(_Elem(h, key))
        return False

    def rank(e: Exp) -> tuple:  # smallest first for global orderings, largest first otherwise
        return tuple(sign * v for v in key(e))

    todo = sorted((g for g in gens if not g.is_zero()), key=lambda g: (g.total_degree(), rank(g.lm())))
    while todo or pairs:
        # the next generator or pair of least sugar (generators first on ties)
        best_pair = min(range(len(pairs)), default=None,
                        key=lambda t: (pairs[t][3], rank(pairs[t][2])))
        if todo and (best_pair is None or todo[0].total_degree() <= pairs[best_pair][3]):
            h = mora_normal_form(dict(todo.pop(0).terms), basis, key)
        else:
            i, j, lc, _ = pairs.pop(best_pair)
            h = mora_normal_form(_spoly(basis[i], basis[j], lc), basis, key)
        if h and add(h):
            return [{ring.zero_exp: ring.field.one}]
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
    from fractions import Fraction
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


def lazard(gens: Sequence[Poly], ring: PolyRing) -> list[Terms]:
    """A minimal standard basis by Lazard's method: a homogeneous Gröbner basis of the
    homogenized ideal for :func:`homogenized_order`, dehomogenized."""
    key = ring.order.key
    hring = PolyRing(ring.field, ring.names + ("@t",), homogenized_order(ring.order))
    hgens = []
    for g in gens:
        if g.is_zero():
            continue
        d = g.total_degree()
        hgens.append(Poly(hring, {e + (d - sum(e),): c for e, c in g.terms.items()}))
    out: list[Terms] = []
    for hg in groebner(hgens, hring):
        p: Terms = {}
        for e, c in hg.terms.items():
            p[e[:-1]] = p.get(e[:-1], 0) + c
        p = {e: c for e, c in p.items() if c != 0}
        if p:
            out.append(_monic(cancel_unit(p, key), key))
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
    and ``[]`` for the zero ideal.  ``engine`` is ``"mora"`` (default) or ``"lazard"``."""
    ring = ring or (gens[0].ring if gens else None)
    if ring is None:
        return []
    gens = [g for g in gens if not g.is_zero()]
    if ring.order.is_global and engine == "auto":
        return groebner(gens, ring)
    if not gens:
        return []
    run = ENGINES["mora" if engine == "auto" else engine]
    key = ring.order.key
    basis = sorted(run(gens, ring), key=lambda p: key(max(p, key=key)), reverse=not ring.order.is_global)
    return [Poly(ring, b) for b in basis]


def elems(basis: Sequence[Poly]) -> list[_Elem]:
    """Reducers for :func:`mora_normal_form` from polynomials."""
    return [_Elem(dict(b.terms), b.ring.order.key) for b in basis if not b.is_zero()]


def weak_normal_form(f: Poly, basis: Sequence[Poly]) -> Poly:
    """Singular's ``reduce``/``NF`` for a local or mixed ordering: Mora's weak normal form of
    ``f`` (``u f - h`` in the ideal for a unit ``u``, and ``LM(h)`` not in ``L(basis)``) with a
    leading-monomial unit factor cancelled (``x^a u -> x^a``).  Zero iff ``f`` lies in the
    ideal of ``K[x]_>`` generated by ``basis`` when ``basis`` is a standard basis.  Tails are
    not reduced, so the result is determined up to a unit and modulo the ideal."""
    if f.is_zero():
        return f
    key = f.ring.order.key
    h = mora_normal_form(dict(f.terms), elems(basis), key)
    return Poly(f.ring, cancel_unit(h, key) if h else h)
