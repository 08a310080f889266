"""Zero-dimensional systems over QQ: their complex and real solutions, exactly.

The quotient ``A = Q[x]/I`` is a finite-dimensional vector space with the standard monomials of
a ``dp`` Gröbner basis as basis (``kbase``); multiplication by ``x_i`` is a matrix ``M_i``
(normal forms).  From these:

* Hermite's quadratic form ``(a, b) -> Tr(M_ab)`` has rank the number of distinct complex
  solutions and signature the number of distinct real ones (Hermite 1856; Pedersen, Roy and
  Szpirglas 1993) - the signature is read off the characteristic polynomial of the symmetric
  matrix with Descartes' rule, exact since its roots are all real.
* A rational univariate representation (Rouillier, "Solving zero-dimensional systems through
  the rational univariate representation", 1999): a linear form ``u`` separates the solutions when
  the squarefree part ``f`` of the characteristic polynomial ``chi`` of ``M_u`` has as many roots as
  there are distinct solutions (the rank of Hermite's form); then ``x_i = g_{x_i}(t)/g_1(t)`` at
  the roots ``t`` of ``f``, with ``g_v = sum_j Tr(v u^j) H_{d-1-j}`` (``H_j`` the Horner polynomials
  of ``f``), traces read off the multiplication matrices - no radical is computed.  The
  multiplicity of a solution is that of ``u``'s value as a root of ``chi``.
* Real solutions are the real roots of ``f`` (``u`` has rational coefficients and separates),
  isolated exactly (:mod:`.real_roots`); their coordinates are enclosed by ball arithmetic
  (arb) and refined to any number of digits.
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field
from typing import Iterator, Sequence

import flint
from flint import arb, arb_poly, fmpq, fmpq_mat, fmpq_poly, fmpz_poly

from . import offload_exact
from .coeffs import RationalField
from .dimension import krull_dim
from .groebner import groebner, normal_form
from .hilbert import kbase
from .powering import power
from .ideals import dp_ring, move
from .order import Exp
from .poly import Poly, PolyRing
from .real_roots import (RealRoot, RealSolvingError, isolate_real_roots, primitive, sign_at, squarefree_part,
                         variations)


class NotSeparatingError(RealSolvingError):
    """The linear form asked for does not separate the solutions."""


def _ring_of(gens: Sequence[Poly], ring: PolyRing | None) -> PolyRing:
    if ring is None:
        if not gens:
            raise RealSolvingError("an empty list of generators needs its ring")
        ring = gens[0].ring
    if not isinstance(ring.field, RationalField):
        raise RealSolvingError("real solutions need rational coefficients (the field QQ)")
    return ring


def to_fmpq_poly(p: Poly, var: int) -> fmpq_poly:
    """A polynomial in the one variable ``var`` as an ``fmpq_poly``."""
    coeffs: dict[int, fmpq] = {}
    for e, c in p.terms.items():
        if any(v for j, v in enumerate(e) if j != var):
            raise RealSolvingError("the polynomial involves more than one variable")
        coeffs[e[var]] = c
    return fmpq_poly([coeffs.get(k, fmpq(0)) for k in range(max(coeffs, default=-1) + 1)])


def from_fmpq_poly(q: fmpq_poly | fmpz_poly, ring: PolyRing, var: int) -> Poly:
    """The univariate ``q`` as a polynomial of ``ring`` in the variable ``var``."""
    terms = {}
    for k, c in enumerate(q.coeffs()):
        if c != 0:
            e = [0] * ring.nvars
            e[var] = k
            terms[tuple(e)] = fmpq(c)
    return Poly(ring, terms)


def _shift(e: Exp, i: int, k: int = 1) -> Exp:
    """The exponent of ``x^e * x_i^k``."""
    return e[:i] + (e[i] + k,) + e[i + 1:]


def _mat(columns: list[list[fmpq]], size: int) -> fmpq_mat:
    """The matrix with the given columns."""
    return fmpq_mat(size, len(columns), [columns[j][i] for i in range(size) for j in range(len(columns))])


class QuotientAlgebra:
    """``Q[x]/I`` for a zero-dimensional ``I``: the ``dp`` Gröbner basis, the standard
    monomials (``monomials``, a basis) and multiplication matrices in that basis."""

    def __init__(self, gens: Sequence[Poly], ring: PolyRing | None = None) -> None:
        source = _ring_of(gens, ring)
        self.source = source
        self.ring = dp_ring(source)
        self.basis = groebner(move(gens, self.ring), self.ring)
        n = self.ring.nvars
        lms = [g.lm() for g in self.basis]
        if any(sum(e) == 0 for e in lms):
            self.monomials: list[Exp] = []
        elif krull_dim(lms, n) != 0:
            raise RealSolvingError("the ideal is not zero-dimensional")
        else:
            self.monomials = kbase(lms, n)
        self.index = {e: i for i, e in enumerate(self.monomials)}
        self._vars: dict[int, fmpq_mat] = {}
        self._monomial_mats: dict[Exp, fmpq_mat] | None = None

    @property
    def dim(self) -> int:
        """``dim_Q A``: the number of solutions counted with multiplicity."""
        return len(self.monomials)

    def coords(self, p: Poly) -> list[fmpq]:
        """The coordinates of ``p`` (a polynomial of the source ring) in the basis."""
        out = [fmpq(0)] * self.dim
        for e, c in normal_form(Poly(self.ring, p.terms), self.basis).terms.items():
            out[self.index[e]] = c
        return out

    def var_matrix(self, i: int) -> fmpq_mat:
        """The matrix of multiplication by the ``i``-th variable."""
        if not self._vars:
            self._build_matrices()
        return self._vars[i]

    def _build_matrices(self) -> None:
        """All variables' matrices from the normal forms of the border monomials ``x_i b`` not
        in the basis, in increasing order (Faugère, Gianni, Lazard and Mora 1993): the leading
        monomial of a basis element reduces to minus its (reduced) tail; any other border monomial
        is ``x_j t`` for a smaller border monomial ``t``, so its normal form combines known ones."""
        n, D = self.ring.nvars, self.dim
        lead = {g.lm(): g.monic() for g in self.basis}
        border = sorted({_shift(b, i) for b in self.monomials for i in range(n)} - set(self.index),
                        key=self.ring.order.key)
        nf: dict[Exp, dict[int, fmpq]] = {}

        def vector(t: Exp) -> dict[int, fmpq]:
            j = self.index.get(t)
            return {j: fmpq(1)} if j is not None else nf[t]
        for t in border:
            g = lead.get(t)
            if g is not None:
                nf[t] = {self.index[e]: -c for e, c in g.terms.items() if e != t}
                continue
            j = next(j for j in range(n) if t[j] and _shift(t, j, -1) in nf)
            acc: dict[int, fmpq] = {}
            for k, c in nf[_shift(t, j, -1)].items():
                for l, d in vector(_shift(self.monomials[k], j)).items():
                    acc[l] = acc.get(l, fmpq(0)) + c * d
            nf[t] = {l: c for l, c in acc.items() if c != 0}
        for i in range(n):
            m = fmpq_mat(D, D)
            for k, b in enumerate(self.monomials):
                for l, c in vector(_shift(b, i)).items():
                    m[l, k] = c
            self._vars[i] = m

    def linear_matrix(self, form: Sequence[fmpq]) -> fmpq_mat:
        """The matrix of multiplication by ``sum form[i] x_i``."""
        out = fmpq_mat(self.dim, self.dim)
        for i, c in enumerate(form):
            if c != 0:
                out += self.var_matrix(i) * fmpq(c)
        return out

    def monomial_matrix(self, e: Exp) -> fmpq_mat:
        """The matrix of multiplication by the standard monomial ``x^e``."""
        if self._monomial_mats is None:
            mats: dict[Exp, fmpq_mat] = {}
            ident = fmpq_mat(self.dim, self.dim)
            for i in range(self.dim):
                ident[i, i] = 1
            for b in sorted(self.monomials, key=sum):
                if sum(b) == 0:
                    mats[b] = ident
                    continue
                v = next(v for v in range(len(b)) if b[v] and tuple(x - (j == v) for j, x in enumerate(b)) in mats)
                mats[b] = self.var_matrix(v) * mats[tuple(x - (j == v) for j, x in enumerate(b))]
            self._monomial_mats = mats
        return self._monomial_mats[e]

    def poly_matrix(self, p: Poly) -> fmpq_mat:
        """The matrix of multiplication by ``p``: ``p(M_x1, ..., M_xn)`` for a polynomial of few
        low-degree terms (the matrices commute), else ``sum coords(p)_k M_{b_k}``."""
        if self._monomial_mats is None and sum(max(sum(e) - 1, 0) for e in p.terms) < self.dim // 2:
            return self._evaluated(p)
        out = fmpq_mat(self.dim, self.dim)
        for k, c in enumerate(self.coords(p)):
            if c != 0:
                out += self.monomial_matrix(self.monomials[k]) * c
        return out


    def _evaluated(self, p: Poly) -> fmpq_mat:
        """``p`` at the variables' matrices, the power products shared."""
        D = self.dim
        known: dict[Exp, fmpq_mat] = {}

        def power(e: Exp) -> fmpq_mat:
            if e not in known:
                v = next(v for v, k in enumerate(e) if k)
                rest = _shift(e, v, -1)
                known[e] = self.var_matrix(v) if sum(rest) == 0 else self.var_matrix(v) * power(rest)
            return known[e]
        out = fmpq_mat(D, D)
        for e, c in p.terms.items():
            if sum(e) == 0:
                for i in range(D):
                    out[i, i] += c
            else:
                out += power(tuple(e)) * fmpq(c)
        return out


# --- Hermite's quadratic form ------------------------------------------------------------------

def hermite_matrix(A: QuotientAlgebra, weight: Poly | None = None) -> fmpq_mat:
    """The matrix ``Tr(h b_i b_j)`` of Hermite's form (weighted by ``h``, default 1)."""
    D = A.dim
    tau = _trace_vector(A)
    if weight is not None:
        tau = tau * A.poly_matrix(weight)
    rows = [tau * A.monomial_matrix(b) for b in A.monomials]
    return fmpq_mat(D, D, [r[0, j] for r in rows for j in range(D)])


def signature(S: fmpq_mat) -> tuple[int, int]:
    """``(rank, signature)`` of a symmetric rational matrix, from its characteristic polynomial
    (real-rooted, so Descartes' rule counts the positive and the negative eigenvalues)."""
    chi = offload_exact.charpoly(S)
    coeffs = chi.coeffs()
    zeros = next((k for k, c in enumerate(coeffs) if c != 0), len(coeffs))
    pos = variations(coeffs)
    neg = variations([c if k % 2 == 0 else -c for k, c in enumerate(coeffs)])
    return S.nrows() - zeros, pos - neg


def hermite_counts(gens: Sequence[Poly], ring: PolyRing | None = None) -> tuple[int, int]:
    """``(distinct complex solutions, distinct real solutions)`` of a zero-dimensional system:
    the rank and the signature of Hermite's quadratic form."""
    A = QuotientAlgebra(gens, ring)
    if A.dim == 0:
        return 0, 0
    return signature(hermite_matrix(A))


# --- the rational univariate representation --------------------------------------------------

def _candidate_forms(n: int, tries: int = 60) -> Iterator[list[fmpq]]:
    """Separating-form candidates: the variables (last first), then small integer forms of
    growing size (a fixed pseudo-random sequence: results are reproducible)."""
    for i in reversed(range(n)):
        yield [fmpq(int(j == i)) for j in range(n)]
    rnd = random.Random(20240519)
    for k in range(tries):
        size = 2 + k // 6
        yield [fmpq(rnd.randint(-size, size)) for _ in range(n)]


@dataclass
class RUR:
    """A rational univariate representation: the solutions are ``x_i = shape[i](t)
    = numerators[i](t) / denominator(t)`` at the roots ``t`` of ``poly`` (squarefree, primitive),
    ``t`` the value of the separating form ``sum form[i] x_i``; ``charpoly`` is the
    characteristic polynomial of that form on ``Q[x]/I`` (its roots' multiplicities are the
    solutions')."""

    ring: PolyRing | None
    form: list[fmpq]
    poly: fmpz_poly
    shape: list[fmpq_poly]
    numerators: list[fmpq_poly]
    denominator: fmpq_poly
    charpoly: fmpq_poly

    @property
    def count(self) -> int:
        """The number of distinct complex solutions."""
        return max(self.poly.degree(), 0)

    def real_roots(self) -> list[RealRoot]:
        """The real roots of ``poly`` (one per real solution), with the solutions' multiplicities."""
        if self.count == 0:
            return []
        return isolate_real_roots(self.charpoly)

    def value(self, p: Poly) -> fmpq_poly:
        """``p`` at the solutions as a polynomial in ``t``: ``p(shape(t)) mod poly``."""
        f = fmpq_poly(self.poly)
        out = fmpq_poly([])
        powers: dict[tuple[int, int], fmpq_poly] = {}
        for e, c in p.terms.items():
            t = fmpq_poly([c])
            for i, k in enumerate(e):
                if k:
                    key = (i, k)
                    if key not in powers:
                        powers[key] = _powmod(self.shape[i], k, f)
                    t = (t * powers[key]) % f
            out += t
        return out % f

    def sign(self, p: Poly, root: RealRoot) -> int:
        """The sign of ``p`` at the real solution of ``root`` (exact)."""
        return sign_at(self.value(p), root)

    def enclosure(self, root: RealRoot, prec: int) -> list[arb]:
        """Balls around the coordinates of the solution at ``root`` (its interval as is)."""
        with flint.ctx.workprec(prec):
            t = root.ball(prec)
            d = ball_eval(self.denominator, t)
            return [ball_eval(g, t) / d for g in self.numerators]


def shape_representation(poly: fmpz_poly, shape: Sequence[fmpq_poly]) -> RUR:
    """The representation ``x_i = shape[i](t)`` at the roots of ``poly`` (squarefree)."""
    f = fmpq_poly(poly)
    df = f.derivative()
    return RUR(None, [], poly, list(shape), [(h * df) % f for h in shape], df, f)


def _powmod(p: fmpq_poly, k: int, f: fmpq_poly) -> fmpq_poly:
    return power(p % f, k, fmpq_poly([1]), lambda a, b: (a * b) % f)


def ball_eval(p: fmpq_poly, t: arb) -> arb:
    """A ball around ``p(t)`` (at the current precision)."""
    return arb_poly([arb(c) for c in p.coeffs()])(t) if p.coeffs() else arb(0)


def _inverse_mod(a: fmpq_poly, f: fmpq_poly) -> fmpq_poly:
    g, s, _ = a.xgcd(f)
    return s / g.coeffs()[0]


def rur(gens: Sequence[Poly], ring: PolyRing | None = None, form: Sequence[fmpq] | None = None) -> RUR:
    """A rational univariate representation of the solutions of a zero-dimensional system.
    With ``form`` that linear form must separate them (else :class:`NotSeparatingError`)."""
    return rur_of(QuotientAlgebra(gens, ring), form)


def rur_of(A: QuotientAlgebra, form: Sequence[fmpq] | None = None) -> RUR:
    """:func:`rur` for a known quotient algebra."""
    n = A.ring.nvars
    if A.dim == 0:
        return RUR(A.source, [fmpq(0)] * n, fmpz_poly([1]), [], [], fmpq_poly([1]), fmpq_poly([1]))
    distinct: int | None = None
    forms = [list(map(fmpq, form))] if form is not None else _candidate_forms(n)
    for lam in forms:
        chi = offload_exact.charpoly(A.linear_matrix(lam))
        f = squarefree_part(chi)
        if f.degree() < A.dim:
            if distinct is None:
                distinct = signature(hermite_matrix(A))[0]
            if f.degree() < distinct:
                continue
        return _representation(A, lam, f, chi)
    if form is not None:
        raise NotSeparatingError("the linear form does not separate the solutions")
    raise RealSolvingError("no separating linear form found")


def _representation(A: QuotientAlgebra, lam: list[fmpq], f: fmpz_poly, chi: fmpq_poly) -> RUR:
    """Rouillier's ``g_v = sum_j Tr(v u^j) H_{d-1-j}`` for ``v = 1, x_1, ..., x_n``."""
    D, d = A.dim, f.degree()
    M = A.linear_matrix(lam)
    tau = _trace_vector(A)
    rows = [tau] + [tau * A.var_matrix(i) for i in range(A.ring.nvars)]
    w = _mat([A.coords(A.source.one())], D)
    traces = [[] for _ in rows]
    for _ in range(d):
        for k, r in enumerate(rows):
            traces[k].append((r * w)[0, 0])
        w = M * w
    a = fmpq_poly(f).coeffs()
    horner = [fmpq_poly([a[d]])]
    for j in range(1, d):
        horner.append(horner[-1] * fmpq_poly([0, 1]) + a[d - j])
    g = [sum((horner[d - 1 - j] * t[j] for j in range(d)), fmpq_poly([])) for t in traces]
    fq = fmpq_poly(f)
    inv = _inverse_mod(g[0], fq)
    shape = [(gi * inv) % fq for gi in g[1:]]
    return RUR(A.source, lam, primitive(f), shape, g[1:], g[0], chi)


def _trace_vector(A: QuotientAlgebra) -> fmpq_mat:
    """The row ``(Tr M_b)_b`` over the standard monomials ``b``."""
    D = A.dim
    return fmpq_mat(1, D, [sum((A.monomial_matrix(b)[k, k] for k in range(D)), fmpq(0)) for b in A.monomials])


# --- real solutions ---------------------------------------------------------------------------

def arb_bounds(b: arb) -> tuple[fmpq, fmpq]:
    """The ends of an arb ball as exact rationals."""
    m, e = b.mid().man_exp()
    r, s = b.rad().man_exp()
    mid = fmpq(m) * fmpq(2) ** int(e) if e >= 0 else fmpq(m, 2 ** int(-e))
    rad = fmpq(r) * fmpq(2) ** int(s) if s >= 0 else fmpq(r, 2 ** int(-s))
    return mid - rad, mid + rad


def decimal(value: fmpq, digits: int, direction: int = 0) -> str:
    """``value`` with ``digits`` decimals: rounded to nearest (half away from zero), or down
    (``direction`` -1) or up (+1)."""
    scaled = value * 10 ** digits
    if direction:
        k = scaled.floor() if direction < 0 else -((-scaled).floor())
        n, negative = abs(int(k)), k < 0
    else:
        n, negative = (abs(scaled.p) * 2 + scaled.q) // (2 * scaled.q), scaled < 0
    s = str(n).rjust(digits + 1, "0")
    body = s[:-digits] + "." + s[-digits:] if digits else s
    return ("-" if negative and n else "") + body


@dataclass
class RealSolution:
    """A real solution: a box ``[(lo, hi), ...]`` holding it and no other solution, its
    multiplicity, and the root of the representation it comes from."""

    box: list[tuple[fmpq, fmpq]]
    multiplicity: int
    root: RealRoot = field(repr=False)

    def midpoint(self) -> list[fmpq]:
        return [(lo + hi) / 2 for lo, hi in self.box]

    def decimals(self, digits: int) -> list[str]:
        return [decimal(v, digits) for v in self.midpoint()]


@dataclass
class Solutions:
    """The solutions of a zero-dimensional system: ``total`` counted with multiplicity
    (``vdim``), ``complex_count`` distinct complex ones, the ``real`` ones as certified boxes."""

    total: int
    complex_count: int
    real: list[RealSolution]
    representation: RUR = field(repr=False)

    @property
    def real_count(self) -> int:
        return len(self.real)


def solution_boxes(rep: RUR, roots: list[RealRoot], width: fmpq) -> list[tuple[RealRoot, list[tuple[fmpq, fmpq]]]]:
    """Boxes of width at most ``width`` around the real solutions, pairwise disjoint."""
    out = []
    for root in roots:
        k = 64
        r = root
        while True:
            r = r.refined(fmpq(1, 2 ** k) if r.exact is None else width)
            balls = rep.enclosure(r, k + 64)
            if all(b.is_finite() for b in balls):
                box = [arb_bounds(b) for b in balls]
                if all(hi - lo <= width for lo, hi in box):
                    break
            k += 32
        out.append((r, box))
    for i in range(len(out)):
        for j in range(i + 1, len(out)):
            if all(a[0] <= b[1] and b[0] <= a[1] for a, b in zip(out[i][1], out[j][1])):
                return solution_boxes(rep, roots, width / 2 ** 16)
    return out


def real_solutions(gens: Sequence[Poly], ring: PolyRing | None = None, digits: int = 10) -> Solutions:
    """The distinct complex and real solutions of a zero-dimensional system over QQ; each real
    solution in a box of width at most ``10^-digits`` containing no other solution."""
    A = QuotientAlgebra(gens, ring)
    rep = rur_of(A)
    roots = rep.real_roots()
    boxes = solution_boxes(rep, roots, fmpq(1, 10 ** digits))
    return Solutions(A.dim, rep.count, [RealSolution(b, r.multiplicity, r) for r, b in boxes], rep)


def count_solutions(gens: Sequence[Poly], ring: PolyRing | None = None) -> tuple[int, int]:
    """``(distinct complex solutions, distinct real solutions)`` from the representation."""
    rep = rur(gens, ring)
    return rep.count, len(rep.real_roots())
