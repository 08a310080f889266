"""Strong Gröbner bases over the integers, and the ideal operations of ``ZZ[x]`` built on them.

The polynomials are :class:`~.poly.Poly` over QQ with integral coefficients.  A strong Gröbner
basis G of an ideal I of ZZ[x] has, for every lead term ``c*m`` of an element of I, an element of
G whose lead term divides it (monomial and coefficient).  It is computed by Buchberger's algorithm
over a Euclidean domain (Kandri-Rody and Kapur 1988; Becker and Weispfenning, *Gröbner Bases*,
§10.1): the pairs give S-polynomials ``(c/a) u f - (c/b) v g`` (``c = lcm(a, b)``) and, when no
lead coefficient divides the other, G-polynomials ``s u f + t v g`` with ``s a + t b = gcd(a, b)``;
a term is reducible by g when g's lead term divides it.  f lies in I exactly when it reduces to 0.
Elimination, intersections (``t I + (1 - t) J``), quotients and saturations follow as over a field."""
from __future__ import annotations

import heapq
from math import gcd
from typing import Sequence

from .order import Block, MonomialOrder
from .poly import Poly, PolyRing, divides, lcm_exp


def _int(c: object) -> int:
    p, q = (c.p, c.q) if hasattr(c, "p") else (c, 1)
    if q != 1:
        raise ValueError("a polynomial over ZZ has integral coefficients")
    return int(p)


def _times(p: Poly, e: tuple[int, ...], c: int) -> Poly:
    """``c * x^e * p``."""
    f = p.ring.field
    return Poly(p.ring, {tuple(a + b for a, b in zip(k, e)): v * f(c) for k, v in p.terms.items()}) if c else p.ring.zero()


def _ext_gcd(a: int, b: int) -> tuple[int, int, int]:
    """(d, s, t) with d = gcd(a, b) = s a + t b."""
    s0, s1, t0, t1 = 1, 0, 0, 1
    while b:
        q = a // b
        a, b = b, a - q * b
        s0, s1 = s1, s0 - q * s1
        t0, t1 = t1, t0 - q * t1
    return (a, s0, t0) if a >= 0 else (-a, -s0, -t0)


def reduce(f: Poly, G: Sequence[Poly]) -> Poly:
    """The remainder of f by G: every term reducible by an element of G is reduced away (the
    terms taken largest first from a heap, the coefficients as Python integers)."""
    if not G or f.is_zero():
        return f
    return _reduce(f, [_divisor(g) for g in G])


def _divisor(g: Poly) -> tuple:
    """(lead monomial, lead coefficient, the other terms) of g, with Python integers."""
    return g.lm(), _int(g.lc()), [(e, _int(c)) for e, c in g.terms.items() if e != g.lm()]


def _reduce(f: Poly, divisors: Sequence[tuple]) -> Poly:
    ring = f.ring
    key = ring.order.key
    rest = {e: _int(c) for e, c in f.terms.items()}
    heap = [(tuple(-k for k in key(e)), e) for e in rest]
    heapq.heapify(heap)
    out = {}
    while heap:
        e = heapq.heappop(heap)[1]
        c = rest.pop(e, 0)
        if not c:
            continue  # a term cancelled meanwhile
        for lm, a, tail in divisors:
            if c % a == 0 and divides(lm, e):
                q = c // a
                u = tuple(x - y for x, y in zip(e, lm))
                for t, d in tail:
                    m = tuple(x + y for x, y in zip(t, u))
                    v = rest.get(m)
                    if v is None:
                        rest[m] = -q * d
                        heapq.heappush(heap, (tuple(-k for k in key(m)), m))
                    elif v == q * d:
                        del rest[m]
                    else:
                        rest[m] = v - q * d
                break
        else:
            out[e] = c
    field = ring.field
    return Poly(ring, {e: field(c) for e, c in out.items()})


def _positive(p: Poly) -> Poly:
    return -p if _int(p.lc()) < 0 else p


def strong_basis(F: Sequence[Poly], ring: PolyRing) -> list[Poly]:
    """A minimal strong Gröbner basis of the ideal F generates (lead coefficients positive,
    tails reduced), sorted by increasing lead monomial, then lead coefficient.

    Pairs are taken smallest lcm first (the normal strategy) and skipped by Buchberger's two
    criteria in their form over ZZ (Lichtblau, *Effective Gröbner bases over Euclidean domains*,
    2012): coprime lead monomials with coprime lead coefficients; a third element h whose lead
    term divides the pair's lcm term (monomial and coefficient) with both pairs (f, h), (h, g) done."""
    G: list[Poly] = []
    lts: list[tuple[tuple[int, ...], int]] = []  # (lead monomial, lead coefficient) of G's elements
    pairs: list[tuple] = []                       # heap of (order key of the lcm, i, j)
    waiting: set[tuple[int, int]] = set()
    key = ring.order.key

    divisors: list[tuple] = []

    def add(h: Poly) -> None:
        h = _reduce(h, divisors) if divisors and not h.is_zero() else h
        if h.is_zero():
            return
        h = _positive(h)
        k = len(G)
        G.append(h)
        divisors.append(_divisor(h))
        lts.append((h.lm(), _int(h.lc())))
        for i in range(k):
            heapq.heappush(pairs, (key(lcm_exp(lts[i][0], lts[k][0])), i, k))
            waiting.add((i, k))

    def useless(i: int, j: int) -> bool:
        (ei, a), (ej, b) = lts[i], lts[j]
        if gcd(a, b) == 1 and all(x == 0 or y == 0 for x, y in zip(ei, ej)):
            return True
        m, c = lcm_exp(ei, ej), a * b // gcd(a, b)
        for h, (eh, d) in enumerate(lts):
            if h in (i, j) or not divides(eh, m) or c % d:
                continue
            if (min(i, h), max(i, h)) not in waiting and (min(j, h), max(j, h)) not in waiting:
                return True
        return False

    for f in F:
        if not f.is_zero():
            add(Poly(ring, dict(f.terms)))
    while pairs:
        _, i, j = heapq.heappop(pairs)
        f, g = G[i], G[j]
        a, b = lts[i][1], lts[j][1]
        m = lcm_exp(lts[i][0], lts[j][0])
        u = tuple(x - y for x, y in zip(m, lts[i][0]))
        v = tuple(x - y for x, y in zip(m, lts[j][0]))
        if a % b and b % a:  # the G-polynomial: lead term gcd(a, b) x^m
            _, s, t = _ext_gcd(a, b)
            add(_times(f, u, s) + _times(g, v, t))
        skip = useless(i, j)
        waiting.discard((i, j))
        if not skip:
            c = a * b // gcd(a, b)
            add(_times(f, u, c // a) - _times(g, v, c // b))
    minimal: list[Poly] = []
    for g in sorted(G, key=lambda p: (ring.order.key(p.lm()), _int(p.lc()))):
        if not any(divides(h.lm(), g.lm()) and _int(g.lc()) % _int(h.lc()) == 0 for h in minimal):
            minimal.append(g)
    out = [_positive(g.lt() + reduce(g - g.lt(), [h for h in minimal if h is not g])) for g in minimal]
    return sorted(out, key=lambda p: (ring.order.key(p.lm()), _int(p.lc())))


def contains(basis: Sequence[Poly], f: Poly) -> bool:
    """Whether f lies in the ideal of a strong Gröbner basis."""
    return reduce(f, basis).is_zero()


def eliminate(F: Sequence[Poly], indices: Sequence[int], ring: PolyRing) -> list[Poly]:
    """A strong Gröbner basis of the ideal of F intersected with ZZ[the other variables] (of two
    polynomials, one monic in the one variable eliminated: its generator, :mod:`.zz_elimination`)."""
    F = [f for f in F if not f.is_zero()]
    if len(F) == 2 and len(set(indices)) == 1:
        from .zz_elimination import eliminate_pair
        pair = eliminate_pair(F[0], F[1], list(indices)[0], ring)
        if pair is not None:
            return pair
    n = ring.nvars
    gone = sorted(set(indices))
    keep = [i for i in range(n) if i not in gone]
    perm = gone + keep
    big = PolyRing(ring.field, [ring.names[i] for i in perm],
                   MonomialOrder([Block("dp", len(gone)), Block("dp", len(keep))] if keep else [Block("dp", n)], n))
    moved = [Poly(big, {tuple(e[i] for i in perm): c for e, c in f.terms.items()}) for f in F]
    pos = [perm.index(i) for i in range(n)]
    out = []
    for g in strong_basis(moved, big):
        if all(e[j] == 0 for e in g.terms for j in range(len(gone))):
            out.append(Poly(ring, {tuple(e[pos[i]] for i in range(n)): c for e, c in g.terms.items()}))
    return strong_basis(out, ring)


def _with_t(F: Sequence[Poly], ring: PolyRing, big: PolyRing, power: int) -> list[Poly]:
    return [Poly(big, {(power,) + e: c for e, c in f.terms.items()}) for f in F]


def intersect(A: Sequence[Poly], B: Sequence[Poly], ring: PolyRing) -> list[Poly]:
    """A strong Gröbner basis of the intersection of two ideals (t A + (1 - t) B, t eliminated)."""
    n = ring.nvars
    big = PolyRing(ring.field, ["_t"] + list(ring.names), MonomialOrder([Block("dp", 1), Block("dp", n)], n + 1))
    tA = _with_t(A, ring, big, 1)
    B0, B1 = _with_t(B, ring, big, 0), _with_t(B, ring, big, 1)
    out = [g for g in strong_basis(tA + [p - q for p, q in zip(B0, B1)], big) if all(e[0] == 0 for e in g.terms)]
    return strong_basis([Poly(ring, {e[1:]: c for e, c in g.terms.items()}) for g in out], ring)


def quotient(A: Sequence[Poly], B: Sequence[Poly], ring: PolyRing) -> list[Poly]:
    """A strong Gröbner basis of A : B (the intersection of the quotients by B's generators)."""
    from .factor import divide_exact
    result: list[Poly] | None = None
    for f in B:
        if f.is_zero():
            continue
        part = [divide_exact(g, f) for g in intersect(A, [f], ring)]
        result = part if result is None else intersect(result, part, ring)
    return strong_basis(result if result is not None else [ring.one()], ring)


def saturate(A: Sequence[Poly], B: Sequence[Poly], ring: PolyRing) -> list[Poly]:
    """A strong Gröbner basis of A : B^infinity."""
    current = strong_basis(A, ring)
    while True:
        nxt = quotient(current, B, ring)
        if all(contains(current, g) for g in nxt):
            return current
        current = nxt
