"""Real roots of univariate polynomials over QQ, exactly.

Squarefree decomposition (flint), isolation of the real roots in disjoint rational intervals by
the Vincent–Collins–Akritas bisection with Descartes' rule of signs (Collins and Akritas 1976;
Rouillier and Zimmermann, "Efficient isolation of polynomial's real roots", 2004), refinement to
any width by bisection, Sturm sequences and counts (the independent check), and the sign of a
polynomial at a root: zero is decided exactly (a gcd with the root's squarefree polynomial),
a nonzero sign by refining until the polynomial has no root in the interval.

Polynomials are python-flint ``fmpz_poly`` / ``fmpq_poly`` (coefficient lists, constant first,
are accepted too).  A :class:`RealRoot` is a simple root of a squarefree primitive integer
polynomial together with an isolating interval ``(lo, hi)``: ``lo < hi``, neither is a root,
the polynomial changes sign across the interval and has exactly one root in it; a rational
root is also kept exactly (``exact``).
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any, Sequence

import flint
from flint import arb, fmpq, fmpq_poly, fmpz, fmpz_poly

from . import offload_exact
from .errors import KernelError

Univariate = Any  # fmpz_poly | fmpq_poly | a coefficient list (constant first)


class RealSolvingError(KernelError):
    """An input the real-solving algorithms do not accept (not univariate, not
    zero-dimensional, not a curve, a point not on the variety) or a limit they reached."""


# --- conversions --------------------------------------------------------------------------

def as_fmpq_poly(f: Univariate) -> fmpq_poly:
    """``f`` as an ``fmpq_poly``."""
    if isinstance(f, fmpq_poly):
        return f
    if isinstance(f, fmpz_poly):
        return fmpq_poly(f)
    return fmpq_poly([fmpq(c) if not isinstance(c, fmpq) else c for c in f])


def primitive(f: Univariate) -> fmpz_poly:
    """The integer primitive multiple of ``f`` with a positive leading coefficient."""
    q = as_fmpq_poly(f)
    if q.is_zero():
        return fmpz_poly([])
    p = q.numer()
    c = p.content()
    p = fmpz_poly([a // c for a in p.coeffs()])
    return -p if p.leading_coefficient() < 0 else p


def sign(x: Any) -> int:
    return (x > 0) - (x < 0)


def squarefree_decomposition(f: Univariate) -> list[tuple[fmpz_poly, int]]:
    """``[(g, m), ...]`` with ``f = c * prod g^m``, the ``g`` squarefree, pairwise coprime,
    primitive with positive leading coefficient (constants omitted)."""
    p = primitive(f)
    if p.degree() <= 0:
        return []
    _, facs = offload_exact.factor_squarefree(p)
    return [(primitive(g), int(m)) for g, m in facs if g.degree() > 0]


def squarefree_part(f: Univariate) -> fmpz_poly:
    """The product of the distinct irreducible factors of ``f`` (primitive)."""
    out = fmpz_poly([1])
    for g, _ in squarefree_decomposition(f):
        out *= g
    return out


# --- Descartes' rule and the Vincent–Collins–Akritas bisection ---------------------------

def variations(coeffs: Sequence[Any]) -> int:
    """Sign variations of a sequence (zeros skipped)."""
    count, last = 0, 0
    for c in coeffs:
        s = sign(c)
        if s:
            if last and s != last:
                count += 1
            last = s
    return count


_X_PLUS_1 = fmpz_poly([1, 1])


def _unit_variations(p: fmpz_poly) -> int:
    """Descartes' bound for the roots of ``p`` in the open interval (0, 1): the variations of
    ``(x+1)^n p(1/(x+1))``; exact when 0 or 1."""
    rev = fmpz_poly(p.coeffs()[::-1])
    return variations(rev(_X_PLUS_1).coeffs())


def _half(p: fmpz_poly) -> fmpz_poly:
    """``2^n p(x/2)``: the left half of (0, 1) blown up to (0, 1)."""
    n = p.degree()
    return fmpz_poly([c * (fmpz(1) << (n - i)) for i, c in enumerate(p.coeffs())])


def _isolate_unit(p: fmpz_poly) -> list[tuple[int, int, bool]]:
    """The roots of the squarefree ``p`` in the open interval (0, 1), as dyadic nodes
    ``(c, d, exact)``: the root ``c/2^d`` when ``exact``, else the only root in
    ``(c/2^d, (c+1)/2^d)``."""
    out: list[tuple[int, int, bool]] = []
    stack = [(p, 0, 0)]
    while stack:
        q, c, d = stack.pop()
        v = _unit_variations(q)
        if v == 0:
            continue
        if v == 1:
            out.append((c, d, False))
            continue
        left = _half(q)
        right = left(_X_PLUS_1)
        if right.coeffs() and right.coeffs()[0] == 0:  # the midpoint is a root
            out.append((2 * c + 1, d + 1, True))
            right = fmpz_poly(right.coeffs()[1:])
        stack.append((right, 2 * c + 1, d + 1))
        stack.append((left, 2 * c, d + 1))
    return out


def _bound_exponent(p: fmpz_poly) -> int:
    """``k >= 0`` with every complex root of ``p`` of absolute value below ``2^k``
    (Fujiwara's bound ``2 max |a_{n-i}/a_n|^(1/i)``)."""
    a = p.coeffs()
    n = len(a) - 1
    top = abs(int(a[n])).bit_length()
    k = 0
    for i in range(1, n + 1):
        c = abs(int(a[n - i]))
        if c:
            k = max(k, -(-(c.bit_length() - top + 1) // i))
    return k + 1


def _scaled(f: fmpq_poly, lo: fmpq, width: fmpq) -> fmpz_poly:
    """``f(lo + width x)`` as a primitive integer polynomial."""
    return primitive(f(fmpq_poly([lo, width])))


def _from_nodes(f: fmpz_poly, nodes: list[tuple[int, int, bool]], lo: fmpq, width: fmpq
                ) -> list[tuple[fmpq, fmpq] | fmpq]:
    out: list[tuple[fmpq, fmpq] | fmpq] = []
    for c, d, exact in nodes:
        a = lo + width * fmpq(c, 2 ** d)
        out.append(a if exact else (a, a + width * fmpq(1, 2 ** d)))
    return out


def _isolate_squarefree(f: fmpz_poly, lo: fmpq | None = None, hi: fmpq | None = None
                        ) -> list[tuple[fmpq, fmpq] | fmpq]:
    """The real roots of the squarefree ``f`` (in the open interval ``(lo, hi)`` if given),
    increasing: exact rationals or open intervals holding exactly one root."""
    q = fmpq_poly(f)
    if lo is not None and hi is not None:
        return _from_nodes(f, _isolate_unit(_scaled(q, lo, hi - lo)), lo, hi - lo)
    if lo is not None or hi is not None:
        raise ValueError("give both ends of the interval or neither")
    b = fmpq(2 ** _bound_exponent(f))
    roots: list[tuple[fmpq, fmpq] | fmpq] = []
    neg = _from_nodes(f, _isolate_unit(_scaled(q, fmpq(0), -b)), fmpq(0), -b)
    for r in neg:
        roots.append(r if isinstance(r, fmpq) else (r[1], r[0]))
    if q(fmpq(0)) == 0:
        roots.append(fmpq(0))
    roots += _from_nodes(f, _isolate_unit(_scaled(q, fmpq(0), b)), fmpq(0), b)
    return sorted(roots, key=lambda r: r if isinstance(r, fmpq) else r[0])


# --- real roots --------------------------------------------------------------------------

@dataclass(frozen=True)
class RealRoot:
    """A real root of ``poly`` (squarefree, primitive): the only root in the open interval
    ``(lo, hi)``, whose ends are not roots; ``exact`` is the root when it is rational;
    ``multiplicity`` its multiplicity in the polynomial it was isolated from."""

    poly: fmpz_poly
    lo: fmpq
    hi: fmpq
    exact: fmpq | None = None
    multiplicity: int = 1

    def refined(self, width: fmpq) -> "RealRoot":
        """The same root with an isolating interval of width at most ``width``."""
        width = fmpq(width)
        lo, hi, f = self.lo, self.hi, self.poly
        if self.exact is not None:
            if hi - lo > width:
                lo, hi = max(lo, self.exact - width / 2), min(hi, self.exact + width / 2)
            return replace(self, lo=lo, hi=hi)
        s_lo = sign(f(lo))
        while hi - lo > width:
            mid = (lo + hi) / 2
            v = sign(f(mid))
            if v == 0:
                return _exact_root(f, mid, self.multiplicity, lo, hi)
            if v == s_lo:
                lo = mid
            else:
                hi = mid
        return replace(self, lo=lo, hi=hi)

    def ball(self, prec: int = 64) -> arb:
        """An ``arb`` enclosing the root, at working precision ``prec`` bits."""
        if self.exact is not None:
            with flint.ctx.workprec(prec):
                return arb(self.exact)
        with flint.ctx.workprec(prec):
            return arb((self.lo + self.hi) / 2, (self.hi - self.lo) / 2)

    def approx(self, digits: int) -> fmpq:
        """A rational within ``10^-digits`` of the root."""
        if self.exact is not None:
            return self.exact
        r = self.refined(fmpq(1, 10 ** digits))
        return (r.lo + r.hi) / 2

    def __float__(self) -> float:
        return float(self.approx(17))

    def sign_of(self, g: Univariate) -> int:
        """The sign of ``g`` at this root (0 exactly when it vanishes there)."""
        return sign_at(g, self)

    def __repr__(self) -> str:
        where = f"= {self.exact}" if self.exact is not None else f"in ({self.lo}, {self.hi})"
        return f"RealRoot({self.poly} {where})"


def _exact_root(f: fmpz_poly, r: fmpq, mult: int, lo: fmpq | None = None, hi: fmpq | None = None) -> RealRoot:
    """The rational root ``r`` of ``f`` with an isolating interval inside ``(lo, hi)``."""
    delta = fmpq(1, 2) if lo is None else min(r - lo, hi - r)
    while True:
        a, b = r - delta, r + delta
        if f(a) != 0 and f(b) != 0 and len(_isolate_squarefree(f, a, b)) == 1:
            return RealRoot(f, a, b, r, mult)
        delta /= 2


def _tightened(f: fmpz_poly, lo: fmpq, hi: fmpq, mult: int) -> RealRoot:
    """The root of ``f`` in ``(lo, hi)`` (the only one) with ends that are not roots."""
    s_lo = sign(f(lo)) or sign(f.derivative()(lo))
    while f(lo) == 0 or f(hi) == 0:
        mid = (lo + hi) / 2
        v = sign(f(mid))
        if v == 0:
            return _exact_root(f, mid, mult, lo, hi)
        if v == s_lo:
            lo = mid
        else:
            hi = mid
    return RealRoot(f, lo, hi, None, mult)


def isolate_real_roots(f: Univariate, lo: fmpq | None = None, hi: fmpq | None = None) -> list[RealRoot]:
    """The distinct real roots of ``f`` (in the open interval ``(lo, hi)`` if given), in
    increasing order, each with its multiplicity in ``f``.  ``f`` must not be zero."""
    if as_fmpq_poly(f).is_zero():
        raise RealSolvingError("the zero polynomial has every number as a root")
    out: list[RealRoot] = []
    for g, m in squarefree_decomposition(f):
        if g.degree() == 1:
            r = fmpq(-g.coeffs()[0], g.coeffs()[1])
            if (lo is None or lo < r) and (hi is None or r < hi):
                out.append(_exact_root(g, r, m))
            continue
        for r in _isolate_squarefree(g, lo, hi):
            out.append(_exact_root(g, r, m) if isinstance(r, fmpq) else _tightened(g, r[0], r[1], m))
    return separate(out)


def count_real_roots(f: Univariate, lo: fmpq | None = None, hi: fmpq | None = None) -> int:
    """The number of distinct real roots of ``f`` (in the open interval ``(lo, hi)``)."""
    return sum(len(_isolate_squarefree(g, lo, hi)) for g, _ in squarefree_decomposition(f))


def separate(roots: Sequence[RealRoot]) -> list[RealRoot]:
    """Distinct roots refined until their intervals are pairwise disjoint, in increasing order."""
    out = sorted(roots, key=lambda r: r.lo)
    while True:
        clash = next((i for i in range(len(out) - 1) if out[i].hi > out[i + 1].lo), None)
        if clash is None:
            return out
        a, b = out[clash], out[clash + 1]
        if a.exact is not None and a.exact == b.exact:
            raise ValueError("the roots are equal")
        out[clash], out[clash + 1] = a.refined((a.hi - a.lo) / 2), b.refined((b.hi - b.lo) / 2)
        out.sort(key=lambda r: r.lo)


# --- Sturm sequences -------------------------------------------------------------------------

def sturm_sequence(f: Univariate) -> list[fmpq_poly]:
    """The Sturm sequence ``f, f', -rem(f, f'), ...`` down to the last nonzero remainder."""
    p = as_fmpq_poly(f)
    seq = [p, p.derivative()]
    while not seq[-1].is_zero():
        seq.append(-(seq[-2] % seq[-1]))
    return seq[:-1] if len(seq) > 1 else seq


def _sign_changes_at(seq: Sequence[fmpq_poly], x: fmpq | None, side: int) -> int:
    """Sign changes of the sequence at ``x`` (``None``: at ``side * infinity``)."""
    if x is None:
        vals = [sign(p.leading_coefficient()) * (side if p.degree() % 2 else 1) for p in seq if not p.is_zero()]
    else:
        vals = [p(x) for p in seq]
    return variations(vals)


def sturm_count(f: Univariate, lo: fmpq | None = None, hi: fmpq | None = None) -> int:
    """Sturm's theorem: the number of distinct real roots of ``f`` in ``(lo, hi]`` (all real
    roots when the ends are omitted); an independent check of :func:`count_real_roots`."""
    seq = sturm_sequence(f)
    if seq[0].degree() <= 0:
        return 0
    return _sign_changes_at(seq, lo, -1) - _sign_changes_at(seq, hi, 1)


# --- signs at roots ---------------------------------------------------------------------------

def vanishes_at(g: Univariate, root: RealRoot) -> bool:
    """Whether ``g`` vanishes at ``root``: exactly when ``gcd(g, poly)`` has a root in its
    interval (exact, no refinement)."""
    q = as_fmpq_poly(g)
    if q.is_zero():
        return True
    if root.exact is not None:
        return q(root.exact) == 0
    h = q.numer().gcd(root.poly)  # over Z: no reduction modulo poly in rationals (large, slow)
    return h.degree() > 0 and sign(h(root.lo)) * sign(h(root.hi)) < 0


def sign_at(g: Univariate, root: RealRoot) -> int:
    """The sign of ``g`` at ``root``: 0 exactly when ``gcd(g, poly)`` vanishes there
    (:func:`vanishes_at`), otherwise found by refining the root until ``g`` has no root in its
    interval."""
    q = as_fmpq_poly(g)
    if q.is_zero():
        return 0
    if root.exact is not None:
        return sign(q(root.exact))
    if vanishes_at(q, root):
        return 0
    q = q % fmpq_poly(root.poly)
    r = root
    orig = as_fmpq_poly(g)
    for bits in (32, 64, 128):  # g does not vanish at the root: a ball of its value excluding 0 decides
        r = r.refined(fmpq(1, 2 ** bits))
        with flint.ctx.workprec(2 * bits + 64):
            v = flint.arb_poly([arb(c) for c in orig.coeffs()])(r.ball(2 * bits + 64))
        if v > 0 or v < 0:
            return 1 if v > 0 else -1
    while True:
        if q(r.lo) != 0 and _unit_variations(_scaled(q, r.lo, r.hi - r.lo)) == 0:
            return sign(q(r.lo))
        r = r.refined((r.hi - r.lo) / 4)
