"""Mora's normal form of a vector of R^n for a module order that need not be a well-order (local or
mixed orderings): Greuel–Pfister, *A Singular Introduction to Commutative Algebra*, algorithm 2.3.12
(NFMora, for modules as in 2.3): reduce the leading term by the divisor of least ecart, keeping the
intermediate vector as a further divisor when its ecart is the smaller one; then the terms after the
leading one are reduced as Singular's ``reduce`` does in local orderings (by a divisor whose ecart is
at most that of the tail from the term on, which ends)."""
from __future__ import annotations

from typing import Any, Callable, Sequence

from .modules import Term, Vector, _add_multiple
from .poly import divides, sub_exp


def ecart(v: Vector, lead: Term) -> int:
    """The largest total degree of v's terms minus that of its leading term."""
    return max(sum(e) for e, _ in v) - sum(lead[0])


def mora_normal_form(f: Vector, gens: Sequence[Vector], key: Callable[[Term], tuple]) -> Vector:
    """A normal form of f by gens: no term of gens' leading terms divides its leading term, and f minus
    it is u*f' with f' in the module's span, u a unit of the localization (u = 1 for a well-order)."""
    divisors: list[tuple[Vector, Term, int]] = []
    for g in gens:
        if g:
            lead = max(g, key=key)
            divisors.append((g, lead, ecart(g, lead)))
    divisors.sort(key=lambda d: key(d[1]))  # the smallest leading term first
    given = list(divisors)
    h = dict(f)
    while h:
        lead = max(h, key=key)
        best = None
        for g, lg, eg in divisors:
            if lg[1] == lead[1] and divides(lg[0], lead[0]) and (best is None or eg < best[2]):
                best = (g, lg, eg)
        if best is None:
            break
        g, lg, eg = best
        eh = ecart(h, lead)
        if eg > eh:
            divisors.append((dict(h), lead, eh))
        _reduce_term(h, lead, g, lg)
    return _tail_reduce(h, given, key) if h else h


def _reduce_term(h: Vector, t: Term, g: Vector, lg: Term) -> None:
    coef: Any = -h[t] / g[lg]
    _add_multiple(h, g, sub_exp(t[0], lg[0]), coef)


def _tail_reduce(h: Vector, divisors: list[tuple[Vector, Term, int]], key: Callable[[Term], tuple]) -> Vector:
    done = {max(h, key=key)}
    while True:
        rest = [t for t in h if t not in done]
        if not rest:
            return h
        t = max(rest, key=key)
        kt = key(t)
        tail_ecart = max(sum(u[0]) for u in h if key(u) <= kt) - sum(t[0])
        best = next(((g, lg) for g, lg, eg in divisors
                     if lg[1] == t[1] and divides(lg[0], t[0]) and eg <= tail_ecart), None)
        if best is None:
            done.add(t)
        else:
            _reduce_term(h, t, *best)
