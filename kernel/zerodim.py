"""The reduction to dimension zero and the decomposition there (Gianni–Trager–Zacharias;
Greuel–Pfister, *A Singular Introduction to Commutative Algebra*, ch. 4), for :mod:`.primdec`.

For a maximal independent set ``u`` of ``I`` and the other variables ``x``, a Gröbner basis for
the product ordering ``(dp(x), dp(u))`` is one of ``I K(u)[x]``, which is zero-dimensional
(:class:`Reduction`).  Its primes and primary components over ``K(u)`` come from factoring
minimal polynomials of the variables (an elimination basis) and splitting, Seidenberg's lemma
(adding squarefree parts makes the ideal radical), and random linear forms as primitive
elements (:class:`ZeroDim`); they are contracted to ``K[x,u]`` by saturation
(:func:`contract`)."""
from __future__ import annotations

import random
from typing import Sequence

from .errors import NotSupported
from .factor import factorize
from .groebner import groebner, normal_form
from .ideals import independent_set, move, product_order, saturate_poly, with_order
from .minpoly import Quotient
from .order import Exp
from .poly import Poly, PolyRing


Component = tuple[list[Poly], list[Poly]]

_ATTEMPTS = 40


# --- small helpers ----------------------------------------------------------------------

def irreducible(f: Poly, cache: dict | None = None) -> list[Poly]:
    """Distinct irreducible non-constant factors of ``f``."""
    if cache is not None and f in cache:
        return cache[f]
    facs = [] if f.is_constant() else [g for g, _ in factorize(f)[1]]
    if cache is not None:
        cache[f] = facs
    return facs


def _sqfree_product(polys: Sequence[Poly], ring: PolyRing) -> Poly:
    """The product of the distinct irreducible factors of the polynomials."""
    seen: dict[Poly, None] = {}
    for p in polys:
        for g in irreducible(p):
            seen.setdefault(g)
    result = ring.one()
    for g in seen:
        result = result * g
    return result


def _x_part(e: Exp, xs: Sequence[int]) -> Exp:
    return tuple(e[i] for i in xs)


def _lc_x(p: Poly, xs: Sequence[int]) -> Poly:
    """The coefficient in ``K[u]`` of the leading ``x``-monomial (product ordering)."""
    lead = _x_part(p.lm(), xs)
    xset = set(xs)
    return Poly(p.ring, {tuple(0 if i in xset else v for i, v in enumerate(e)): c
                         for e, c in p.terms.items() if _x_part(e, xs) == lead})


def _leading_coefficients(basis: Sequence[Poly], xs: Sequence[int]) -> list[Poly]:
    """The leading coefficients in ``K[u]`` of a Gröbner basis of ``I K(u)[x]`` taken from
    a basis for a product ordering ``x >> u``: one element (the one with the smallest
    coefficient) for each minimal ``x``-leading monomial suffices."""
    best: dict[Exp, Poly] = {}
    for p in basis:
        lead, c = _x_part(p.lm(), xs), _lc_x(p, xs)
        if lead not in best or (c.total_degree(), len(c)) < (best[lead].total_degree(), len(best[lead])):
            best[lead] = c

    def divides(a: Exp, b: Exp) -> bool:
        return a != b and all(i <= j for i, j in zip(a, b))
    return [c for lead, c in best.items() if not any(divides(o, lead) for o in best)]


def _unit_over_ku(basis: Sequence[Poly], xs: Sequence[int]) -> bool:
    """Whether a basis for a product ordering ``x >> u`` generates 1 over ``K(u)``."""
    return any(not any(p.lm()[i] for i in xs) for p in basis)


def _vdim(basis: Sequence[Poly], xs: Sequence[int]) -> int:
    """``dim_K(u) K(u)[x]/I`` from a zero-dimensional basis for a product ordering."""
    lms = [_x_part(p.lm(), xs) for p in basis]
    n = len(xs)
    bounds = []
    for i in range(n):
        pure = [e[i] for e in lms if e[i] and not any(e[j] for j in range(n) if j != i)]
        if not pure:
            raise AssertionError("the ideal is not zero-dimensional over K(u)")  # u is a maximal independent set
        bounds.append(min(pure))
    count = 0

    def walk(prefix: list[int]) -> None:
        nonlocal count
        k = len(prefix)
        if k == n:
            count += 1
            return
        for v in range(bounds[k]):
            cand = prefix + [v]
            if any(all(e[j] <= cand[j] for j in range(k + 1)) and not any(e[k + 1:]) for e in lms):
                break
            walk(cand)

    walk([])
    return count


def _in_target(f: Poly, target: int) -> list[tuple[Poly, int]]:
    """Irreducible factors of ``f`` (with multiplicity) involving the variable ``target``."""
    return [(g, m) for g, m in factorize(f)[1] if g.degree_in(target) > 0]


class ZeroDim:
    """Decompositions of ideals ``I`` of ``K[x,u]`` with ``I K(u)[x]`` zero-dimensional;
    ``ring`` has the product ordering ``x >> u`` and ideals are Gröbner bases there.
    Components are ideals of ``K[x,u]`` whose extensions to ``K(u)[x]`` are the primes and
    primaries (contract them with :func:`_contract`)."""

    def __init__(self, ring: PolyRing, xs: Sequence[int], us: Sequence[int]) -> None:
        self.ring, self.xs, self.us = ring, list(xs), list(us)
        self.rng = random.Random(20240613)
        self.minpolys: dict[tuple, Poly] = {}
        n = ring.nvars
        name = "t"
        while name in ring.names:
            name = "_" + name
        # ring plus a last variable t for linear forms, ordered (dp(x), dp(t), dp(u))
        self.big = PolyRing(ring.field, list(ring.names) + [name],
                            product_order(n + 1, [self.xs, [n], self.us]))

    def minimal_poly(self, g: list[Poly], target: int) -> Poly:
        """The minimal polynomial over ``K(u)`` of the variable ``target`` modulo ``g``,
        as a polynomial of ``K[u][target]``."""
        key = (tuple(g), target)
        if key not in self.minpolys:
            pos = self.xs.index(target)
            f = Quotient(g, self.ring, self.xs).minimal_poly({pos: self.ring.field.one})
            self.minpolys[key] = self._as_poly(f, self.ring, target)
        return self.minpolys[key]

    def form_minimal_poly(self, g: list[Poly], ell: Poly) -> Poly:
        """The minimal polynomial of the linear form ``ell`` as a polynomial in the extra
        variable ``t`` of ``self.big``."""
        form = {self.xs.index(e.index(1)): c for e, c in ell.terms.items()}
        f = Quotient(g, self.ring, self.xs).minimal_poly(form)
        return self._as_poly(f, self.big, self.ring.nvars)

    def _as_poly(self, coeffs: list, ring: PolyRing, var: int) -> Poly:
        """``sum(coeffs[j] * var^j)`` with flint coefficients in ``K[u]``."""
        conv = self.ring.field
        terms = {}
        for j, c in enumerate(coeffs):
            for e, v in c.to_dict().items():
                exp = [int(k) for k in e] + [0] * (ring.nvars - self.ring.nvars)
                exp[var] = j
                terms[tuple(exp)] = v if not conv.characteristic else conv(int(v))
        return Poly(ring, terms)

    def random_form(self, attempt: int) -> Poly:
        p = self.ring.field.characteristic
        span = 30 + 10 * attempt if not p else min(p - 1, 1000)
        low = 0 if 0 < p < 5 else 1  # over Z/2, Z/3 the forms with zero coefficients are needed too
        ell = self.ring.zero()
        while ell.is_zero():
            for i in self.xs:
                ell = ell + self.ring.gen(i) * self.rng.randint(low, span)
        return ell

    def by_form(self, g: list[Poly], d: int) -> tuple[list[Component], bool] | None:
        """Random linear forms ``ell`` until one is cyclic (its minimal polynomial ``f`` has
        degree ``d = vdim(g)``, so ``K(u)[x]/g ≅ K(u)[t]/(f)``) or ``f`` has several
        irreducible factors ``p^m``.  Returns the pieces ``(g + p(ell)^m, g + p(ell))`` and
        whether ``ell`` was cyclic (then they are the primary components and their primes);
        None after ``_ATTEMPTS`` failures."""
        n = self.ring.nvars
        for attempt in range(_ATTEMPTS):
            ell = self.random_form(attempt)
            f = self.form_minimal_poly(g, ell)
            facs = _in_target(f, n)
            cyclic = f.degree_in(n) == d
            if cyclic or len(facs) > 1:
                images = [self.ring.gen(i) for i in range(n)] + [ell]

                def back(p: Poly) -> Poly:
                    return Poly(self.big, p.terms).compose(images, self.ring)
                return [(groebner(g + [back(p ** m)], self.ring), groebner(g + [back(p)], self.ring))
                        for p, m in facs], cyclic
        return None

    def primes(self, basis: list[Poly]) -> list[list[Poly]]:
        """The primes containing ``I`` over ``K(u)``: split by factors of minimal polynomials
        of the variables, make radical by adding their squarefree parts (Seidenberg), then a
        cyclic linear form of the radical ideal gives its primes."""
        out: list[list[Poly]] = []
        todo = [basis]
        while todo:
            g = todo.pop()
            if _unit_over_ku(g, self.xs):
                continue
            d = _vdim(g, self.xs)
            if d == 1:
                out.append(g)
                continue
            status, extra = "radical", []
            for i in reversed(self.xs):
                facs = _in_target(self.minimal_poly(g, i), i)
                if len(facs) > 1:
                    todo.extend(groebner(g + [p], self.ring) for p, _ in facs)
                    status = "split"
                    break
                p, m = facs[0]
                if p.degree_in(i) == d:
                    out.append(g)
                    status = "prime"
                    break
                if m > 1:
                    extra.append(p)
            if status != "radical":
                continue
            if extra:
                todo.append(groebner(g + extra, self.ring))
                continue
            found = self.by_form(g, d)
            if found is None:
                raise NotSupported("no primitive element found (inseparable extension or a too small field)")
            pieces, cyclic = found
            if cyclic:
                out.extend(p for _, p in pieces)
            else:
                todo.extend(p for _, p in pieces)
        return out

    def separated(self, g: list[Poly]) -> list[Component]:
        """The primary components of ``g`` over ``K(u)`` from its primes: ``g : s^∞`` for an
        element ``s`` of all primes but one (all primes are maximal over ``K(u)``)."""
        primes = self.primes(g)
        if len(primes) == 1:
            return [(g, primes[0])]
        contracted = [contract(p, self.ring, self.xs)[0] for p in primes]
        return [(saturate_poly(g, separator(contracted, i, self.ring), self.ring, is_basis=True), p)
                for i, p in enumerate(primes)]

    def primaries(self, basis: list[Poly]) -> list[Component]:
        """The primary components over ``K(u)`` with their primes: a cyclic variable gives
        them at once; the prime-power factors of a variable's minimal polynomial split the
        ideal into coprime pieces; a piece without either is separated by its primes."""
        out: list[Component] = []
        todo = [basis]
        while todo:
            g = todo.pop()
            if _unit_over_ku(g, self.xs):
                continue
            d = _vdim(g, self.xs)
            found = None
            for i in reversed(self.xs):
                f = self.minimal_poly(g, i)
                facs = _in_target(f, i)
                if f.degree_in(i) == d or len(facs) > 1:
                    found = ([(groebner(g + [p ** m], self.ring), groebner(g + [p], self.ring))
                              for p, m in facs], f.degree_in(i) == d)
                    break
            if found is None:
                out.extend(self.separated(g))
                continue
            pieces, cyclic = found
            if cyclic:
                out.extend(pieces)
            else:
                todo.extend(q for q, _ in pieces)
        return out


def contract(basis: list[Poly], ring: PolyRing, xs: Sequence[int]) -> tuple[list[Poly], Poly]:
    """``(I K(u)[x] ∩ K[x,u], h)``: the contraction ``I : h^∞`` of an ideal given by a Gröbner
    basis for the product ordering, and ``h`` (the squarefree product of the leading
    coefficients)."""
    h = _sqfree_product(_leading_coefficients(basis, xs), ring)
    if h.is_constant():
        return basis, h
    return saturate_poly(basis, h, ring, is_basis=True), h


# --- the reduction to dimension zero ---------------------------------------------------

class Reduction:
    """An ideal seen over ``K(u)``: the independent set, the product-order ring and basis,
    ``h`` and the zero-dimensional primes contracted to ``K[x,u]`` (in the input ring)."""

    def __init__(self, basis: list[Poly], ring: PolyRing, us: Sequence[int] | None = None) -> None:
        n = ring.nvars
        self.ring = ring
        self.us = independent_set(basis, n) if us is None else list(us)
        self.xs = [i for i in range(n) if i not in self.us]
        self.bring = with_order(ring, product_order(n, [self.xs, self.us]))
        self.bbasis = groebner(move(basis, self.bring), self.bring)
        self.h = Poly(ring, _sqfree_product(_leading_coefficients(self.bbasis, self.xs),
                                            self.bring).terms)

    def _contracted(self, basis: list[Poly]) -> list[Poly]:
        return groebner(move(contract(basis, self.bring, self.xs)[0], self.ring), self.ring)

    def primes(self) -> list[list[Poly]]:
        """The contracted primes (reduced bases in the input ring)."""
        zd = ZeroDim(self.bring, self.xs, self.us)
        return [self._contracted(p) for p in zd.primes(self.bbasis)]

    def primaries(self) -> list[Component]:
        """The contracted primary components of ``I K(u)[x]`` with their primes."""
        zd = ZeroDim(self.bring, self.xs, self.us)
        return [(self._contracted(q), self._contracted(p)) for q, p in zd.primaries(self.bbasis)]


def separator(primes: list[list[Poly]], i: int, ring: PolyRing) -> Poly:
    """An element of every prime but the ``i``-th, not in the ``i``-th."""
    s = ring.one()
    for j, p in enumerate(primes):
        if j == i:
            continue
        outside = [g for g in p if not normal_form(g, primes[i]).is_zero()]
        s = s * min(outside, key=lambda g: (g.total_degree(), len(g)))
    return s
