"""A lower bound for the rank of a Jacobian at algebraic points, modulo a prime.

The points ``x = phi(t)``, ``m(t) = 0`` (``m`` irreducible over Q, ``K = Q[t]/m``) are sent to
``F_p`` by ``t -> r`` for a root ``r`` of ``m`` modulo a prime ``p`` that divides no denominator
(nor the leading coefficient of ``m``): ``Z_(p)[t]/m -> F_p`` is a ring map, so a minor of the
Jacobian that vanishes over K vanishes modulo ``p`` and the rank modulo ``p`` is at most the rank
over K.  With the upper bound every point of a ``d``-dimensional variety gives (rank at most
``n - d``), a rank ``n - d`` modulo ``p`` proves the rank over K: the Zariski tangent space has
dimension ``d`` exactly, without linear algebra over K (its Gröbner basis over ``Q[x, t]`` took
seconds for a six-bar's points of degree 16).
"""
from __future__ import annotations

from typing import Sequence

from flint import fmpz, nmod_mat, nmod_poly

from .poly import Poly

#: Primes tried (a root of ``m`` modulo ``p`` exists for a positive density of primes,
#: at least ``1 / deg m`` by Chebotarev's theorem).
TRIES = 60
_START = (1 << 31) - 1


def _primes(count: int) -> list[int]:
    out, q = [], _START
    while len(out) < count:
        if fmpz(q).is_prime():
            out.append(q)
        q -= 2
    return out


def _mod(c: object, p: int) -> int | None:
    """A rational coefficient modulo ``p`` (None when its denominator vanishes there)."""
    num, den = (int(c.p), int(c.q)) if hasattr(c, "q") else (int(c), 1)
    return None if den % p == 0 else num * pow(den, -1, p) % p


def _values(p: Poly, prime: int) -> dict[tuple, int] | None:
    out = {}
    for e, c in p.terms.items():
        v = _mod(c, prime)
        if v is None:
            return None
        out[e] = v
    return out


def _eval(terms: dict[tuple, int], powers: list[list[int]], prime: int, skip: int = -1) -> int:
    """The terms at the point (their ``skip``-th partial derivative's value when ``skip >= 0``)."""
    total = 0
    for e, c in terms.items():
        if skip >= 0:
            k = e[skip]
            if not k:
                continue
            c = c * k
        v = c
        for j, k in enumerate(e):
            if j == skip:
                k -= 1
            if k:
                v = v * powers[j][k] % prime
        total += v
    return total % prime


def jacobian_rank_mod(gens: Sequence[Poly], at: Sequence[Poly], minpoly: Poly) -> int | None:
    """The rank modulo a prime of the Jacobian (in the first ``n`` variables) of ``gens``
    (polynomials of ``Q[x_1..x_n, t]``) at ``x = at(t)``, ``t`` a root of ``minpoly(t)`` modulo
    the prime: a lower bound for its rank over ``Q[t]/minpoly``; None when no prime of
    :data:`TRIES` gives a root."""
    n = len(at)
    m_terms = {e[n]: c for e, c in minpoly.terms.items()}
    for prime in _primes(TRIES):
        coeffs = [0] * (max(m_terms) + 1)
        ok = True
        for k, c in m_terms.items():
            v = _mod(c, prime)
            if v is None:
                ok = False
                break
            coeffs[k] = v
        if not ok or coeffs[-1] == 0:
            continue
        roots = nmod_poly(coeffs, prime).roots()
        if not roots:
            continue
        r = int(roots[0][0])
        point = []
        for a in at:
            terms = _values(a, prime)
            if terms is None:
                break
            point.append(sum(c * pow(r, e[n], prime) for e, c in terms.items()) % prime)
        else:
            table = [_values(g, prime) for g in gens]
            if any(t is None for t in table):
                continue
            top = max((max(e) for g in gens for e in g.terms), default=0) + 1
            powers = [[pow(v, k, prime) for k in range(top)] for v in point + [r]]
            rows = [[_eval(t, powers, prime, i) for i in range(n)] for t in table]
            return nmod_mat(rows, prime).rank() if rows else 0
    return None
