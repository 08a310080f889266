"""Minimal associated primes, primary decomposition, radicals and equidimensional parts.

Ideals are lists of :class:`Poly` of one ring with a global ordering; results are reduced
Gröbner bases in that ring (see :mod:`.ideals`).  The algorithms (Greuel–Pfister, *A Singular
Introduction to Commutative Algebra*, ch. 4):

* **Reduction to dimension zero** (Gianni–Trager–Zacharias).  For a maximal independent set
  ``u`` of ``I`` and the other variables ``x``, a Gröbner basis for the product ordering
  ``(dp(x), dp(u))`` is one of ``I K(u)[x]``, which is zero-dimensional; with ``h`` the
  product of the leading coefficients in ``K[u]`` of the elements with minimal leading
  ``x``-monomials (a Gröbner basis over ``K(u)``), ``I K(u)[x] ∩ K[x,u] = I : h^∞`` and
  ``I = (I : h^∞) ∩ (I + h^m)`` for the saturation exponent ``m``.
* **Zero-dimensional primes over K(u)**: factor the minimal polynomial of each variable
  (an elimination basis) and split; add the squarefree parts (Seidenberg's lemma makes the
  ideal radical); an ideal whose vector-space dimension equals the degree of an irreducible
  minimal polynomial is maximal.  Otherwise a random linear form plays the variable
  (generic coordinates).  The primes of ``K[x,u]`` are the contractions ``P : h_P^∞``.
* **Minimal primes**: first a factorizing Gröbner basis splits ``V(I)`` along factors of
  basis elements; each piece goes through the reduction above; non-minimal primes are
  dropped.
* **Primary components**: GTZ splits the zero-dimensional ideal over ``K(u)`` by the
  prime-power factors of minimal polynomials, separates the primaries of what remains with
  saturations ``I : s^∞`` by elements ``s`` lying in all other primes and recurses on
  ``I + h^m``; Shimoyama–Yokoyama saturates ``I`` by such separators of its minimal primes
  (pseudo-primary components), extracts their isolated primaries the same way and recurses
  on the remainders.  Both finish by merging components of equal radical and removing
  redundant (embedded) ones, so the decomposition is irredundant.

* **Parameters** (``K(a)[x]``, Singular's ``ring r = (0,a),(x),dp;``): the decompositions
  of ``I K(a)[x] ∩ K[x,a]`` (parameters as variables) extended to ``K(a)[x]``.

Correct in characteristic 0 and for Z/p with p large enough that random linear forms are
primitive elements; over Z/p with parameters, an inseparable minimal polynomial (a p-th power
in ``x`` over ``K(u)``) is not made radical and raises ``RuntimeError``.  The coefficient
field enters only through field operations, factorization (:mod:`.factor`) and ``groebner``.
"""
from __future__ import annotations

import math
import random
from typing import Callable, Sequence

from .factor import factorize, normalize, to_flint
from .groebner import groebner, normal_form
from .ideals import (Ideal, dimension, independent_set, intersect, is_unit, move,
                     product_order, quotient, ring_of, saturate_poly, saturation_exponent, std,
                     with_order)
from .order import Block, Exp, MonomialOrder
from .coeffs import GF, QQ
from .poly import Poly, PolyRing

Component = tuple[list[Poly], list[Poly]]

_ATTEMPTS = 40


# --- small helpers ----------------------------------------------------------------------

def _irreducible(f: Poly, cache: dict | None = None) -> list[Poly]:
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
        for g in _irreducible(p):
            seen.setdefault(g)
    result = ring.one()
    for g in seen:
        result = result * g
    return result


def _is_linear(basis: Sequence[Poly]) -> bool:
    return all(p.total_degree() <= 1 for p in basis)


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
            raise ValueError("the ideal is not zero-dimensional over K(u)")
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


# --- zero-dimensional decomposition over K(u) --------------------------------------------

class _Quotient:
    """Linear algebra in ``K(u)[x]/I`` without rational functions: elements are vectors over
    ``K[u]`` (flint polynomials) on the standard ``x``-monomials with a common denominator;
    normal forms by fraction-free (pseudo-) reduction modulo a Gröbner basis for the product
    ordering ``x >> u``, minimal polynomials by fraction-free Krylov iteration."""

    def __init__(self, basis: Sequence[Poly], ring: PolyRing, xs: Sequence[int]) -> None:
        self.ctx = to_flint(ring.one()).context()
        self.xs = list(xs)
        xset = set(xs)
        self.key = _product_x_key(len(xs))
        self.reducers = []
        for p in basis:
            vec = self._vector(p, xset)
            lead = max(vec, key=self.key)
            self.reducers.append((lead, vec[lead], vec))

    def _vector(self, p: Poly, xset: set) -> dict:
        parts: dict[Exp, dict] = {}
        for e, c in p.terms.items():
            xe = tuple(e[i] for i in self.xs)
            ue = tuple(0 if i in xset else v for i, v in enumerate(e))
            parts.setdefault(xe, {})[ue] = c
        return {xe: self.ctx.from_dict(d) for xe, d in parts.items()}

    def normal_form(self, f: dict) -> tuple[dict, object]:
        """``(r, D)`` with ``f = r / D`` in ``K(u)[x]/I``, ``r`` reduced."""
        f = dict(f)
        done: dict = {}
        scale = self.ctx.from_dict({(0,) * self.ctx.nvars(): 1})
        while f:
            m = max(f, key=self.key)
            c = f.pop(m)
            hit = next((r for r in self.reducers if all(a >= b for a, b in zip(m, r[0]))), None)
            if hit is None:
                done[m] = c
                continue
            lead, lc, vec = hit
            shift = tuple(a - b for a, b in zip(m, lead))
            g = c.gcd(lc)
            mul, fac = lc / g, c / g
            if not mul.is_one():
                f = {k: v * mul for k, v in f.items()}
                done = {k: v * mul for k, v in done.items()}
                scale = scale * mul
            for e, v in vec.items():
                if e == lead:
                    continue
                t = tuple(a + b for a, b in zip(e, shift))
                w = f.get(t)
                w = -fac * v if w is None else w - fac * v
                if w.is_zero():
                    f.pop(t, None)
                else:
                    f[t] = w
        return self._reduce_content(done, scale)

    def _reduce_content(self, vec: dict, scale):
        g = scale
        for v in vec.values():
            if g.is_one():
                break
            g = g.gcd(v)
        if not g.is_one() and not g.is_zero():
            vec = {k: v / g for k, v in vec.items()}
            scale = scale / g
        return vec, scale

    def times_form(self, vec: dict, form: dict) -> dict:
        out: dict = {}
        for e, v in vec.items():
            for pos, c in form.items():
                t = e[:pos] + (e[pos] + 1,) + e[pos + 1:]
                w = out.get(t)
                w = v * c if w is None else w + v * c
                if w.is_zero():
                    out.pop(t, None)
                else:
                    out[t] = w
        return out

    def minimal_poly(self, form: dict) -> list:
        """The coefficients (in ``K[u]``, content removed) of the minimal polynomial over
        ``K(u)`` of multiplication by the linear form ``{position in xs: coefficient}``."""
        one = self.ctx.from_dict({(0,) * self.ctx.nvars(): 1})
        vec, denom = self.normal_form({(0,) * len(self.xs): one})
        rows: list[tuple[Exp, dict, dict]] = []
        denoms = []
        k = 0
        while True:
            denoms.append(denom)
            v, combo = dict(vec), {k: one}
            for piv, row, rc in rows:
                a = v.get(piv)
                if a is None:
                    continue
                b = row[piv]
                g = a.gcd(b)
                a, b = a / g, b / g
                v = _axpy(b, v, -a, row)
                combo = _axpy(b, combo, -a, rc)
            if not v:
                coeffs = [combo.get(j, one * 0) * denoms[j] for j in range(k + 1)]
                content = coeffs[-1]
                for c in coeffs:
                    content = content.gcd(c)
                return [c / content for c in coeffs]
            v, combo = _primitive_pair(v, combo)
            rows.append((max(v, key=self.key), v, combo))
            k += 1
            vec, d = self.normal_form(self.times_form(vec, form))
            denom = denom * d


def _axpy(a, x: dict, b, y: dict) -> dict:
    """``a*x + b*y`` for sparse vectors with flint entries."""
    out = {k: a * v for k, v in x.items()}
    for k, v in y.items():
        w = out.get(k)
        w = b * v if w is None else w + b * v
        if w.is_zero():
            out.pop(k, None)
        else:
            out[k] = w
    return out


def _primitive_pair(v: dict, combo: dict) -> tuple[dict, dict]:
    g = None
    for w in list(v.values()) + list(combo.values()):
        g = w if g is None else g.gcd(w)
        if g.is_one():
            return v, combo
    return {k: w / g for k, w in v.items()}, {k: w / g for k, w in combo.items()}


def _product_x_key(n: int) -> Callable[[Exp], tuple]:
    """The ``dp`` key on ``x``-exponents (the ``x`` block of :func:`product_order`)."""
    return lambda e: (sum(e), *[-v for v in reversed(e[1:])])


class _ZeroDim:
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
            f = _Quotient(g, self.ring, self.xs).minimal_poly({pos: self.ring.field.one})
            self.minpolys[key] = self._as_poly(f, self.ring, target)
        return self.minpolys[key]

    def form_minimal_poly(self, g: list[Poly], ell: Poly) -> Poly:
        """The minimal polynomial of the linear form ``ell`` as a polynomial in the extra
        variable ``t`` of ``self.big``."""
        form = {self.xs.index(e.index(1)): c for e, c in ell.terms.items()}
        f = _Quotient(g, self.ring, self.xs).minimal_poly(form)
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
        ell = self.ring.zero()
        for i in self.xs:
            ell = ell + self.ring.gen(i) * self.rng.randint(1, span)
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
                raise RuntimeError("no primitive element found (inseparable extension or a too small field)")
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
        contracted = [_contract(p, self.ring, self.xs)[0] for p in primes]
        return [(saturate_poly(g, _separator(contracted, i, self.ring), self.ring, is_basis=True), p)
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


def _contract(basis: list[Poly], ring: PolyRing, xs: Sequence[int]) -> tuple[list[Poly], Poly]:
    """``(I K(u)[x] ∩ K[x,u], h)``: the contraction ``I : h^∞`` of an ideal given by a Gröbner
    basis for the product ordering, and ``h`` (the squarefree product of the leading
    coefficients)."""
    h = _sqfree_product(_leading_coefficients(basis, xs), ring)
    if h.is_constant():
        return basis, h
    return saturate_poly(basis, h, ring, is_basis=True), h


# --- the reduction to dimension zero ---------------------------------------------------

class _Reduction:
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
        return groebner(move(_contract(basis, self.bring, self.xs)[0], self.ring), self.ring)

    def primes(self) -> list[list[Poly]]:
        """The contracted primes (reduced bases in the input ring)."""
        zd = _ZeroDim(self.bring, self.xs, self.us)
        return [self._contracted(p) for p in zd.primes(self.bbasis)]

    def primaries(self) -> list[Component]:
        """The contracted primary components of ``I K(u)[x]`` with their primes."""
        zd = _ZeroDim(self.bring, self.xs, self.us)
        return [(self._contracted(q), self._contracted(p)) for q, p in zd.primaries(self.bbasis)]


# --- minimal associated primes ----------------------------------------------------------

def _contained(polys: Sequence[Poly], basis: Sequence[Poly]) -> bool:
    """Whether the polynomials lie in the ideal of the Gröbner basis ``basis``."""
    return all(normal_form(p, basis).is_zero() for p in polys)


def _facstd(basis: list[Poly], ring: PolyRing, cache: dict) -> list[list[Poly]]:
    """Factorizing Gröbner bases: ideals without reducible or non-squarefree basis elements
    such that every minimal prime of ``I`` is a minimal prime of one of them.  A branch
    ``I + f_i`` for a basis element ``f_1 ··· f_k`` only looks for primes avoiding
    ``f_1, ..., f_(i-1)``: those factors are dropped from later splits, and a branch whose
    ideal contains one of them is abandoned."""
    out: list[list[Poly]] = []
    todo: list[tuple[list[Poly], list[Poly]]] = [(basis, [])]
    while todo:
        gens, nonzero = todo.pop()
        g = groebner(gens, ring)
        if is_unit(g) or any(normal_form(f, g).is_zero() for f in nonzero):
            continue
        for p in g:
            facs = [f for f in _irreducible(p, cache) if f not in nonzero]
            if not facs:
                break
            if len(facs) > 1 or facs[0] != normalize(p):
                todo.extend((g + [f], nonzero + facs[:i]) for i, f in enumerate(facs))
                break
        else:
            out.append(g)
    return _minimal_ideals(out)


def _minimal_ideals(ideals: list[list[Poly]]) -> list[list[Poly]]:
    """Distinct ideals (reduced bases) not containing another one."""
    uniq: list[list[Poly]] = []
    for i in sorted(ideals, key=lambda b: (len(b), sum(len(p) for p in b))):
        if not any(_contained(j, i) for j in uniq):
            uniq = [j for j in uniq if not _contained(i, j)] + [i]
    return uniq


def _min_ass(basis: list[Poly], ring: PolyRing, cache: dict, split: bool = True) -> list[list[Poly]]:
    """Primes whose varieties cover ``V(I)`` (all minimal primes among them)."""
    primes: list[list[Poly]] = []
    for piece in (_facstd(basis, ring, cache) if split else [basis]):
        if _is_linear(piece):
            primes.append(piece)
            continue
        red = _Reduction(piece, ring)
        primes.extend(red.primes())
        h = red.h
        if h.is_constant() or _contained(quotient(piece, [h], ring), piece):
            continue
        for f in _irreducible(h, cache):
            primes.extend(_min_ass(groebner(piece + [f], ring), ring, cache))
    return _minimal_ideals(primes)


class _Parameters:
    """A ring ``K(a)[x]`` with parameters seen as ``K[x, a]`` (the parameters as the last
    variables, ordering ``(dp(x), dp(a))``): the primary components of ``I K(a)[x]`` are the
    extensions of those of ``J = I K(a)[x] ∩ K[x, a]`` whose primes meet ``K[a]`` in 0 (all
    of them; the localization at ``K[a] \\ 0`` keeps exactly those)."""

    def __init__(self, ring: PolyRing) -> None:
        field = ring.field
        self.ring, self.field, self.n = ring, field, ring.nvars
        base = GF(field.characteristic) if field.characteristic else QQ
        names = list(ring.names) + [a if a not in ring.names else f"_{a}" for a in field.params]
        m = len(field.params)
        self.big = PolyRing(base, names, product_order(self.n + m, [range(self.n), range(self.n, self.n + m)]))

    @staticmethod
    def of(ring: PolyRing) -> bool:
        """Whether the ring's coefficients have parameters."""
        return bool(getattr(ring.field, "params", ()))

    def _lift(self, p: Poly) -> Poly:
        """``p`` times the lcm of its denominators, in ``K[x, a]``."""
        den = self.field.ctx.constant(1)
        for c in p.terms.values():
            den = den * (c.den // den.gcd(c.den))
        terms = {}
        for e, c in p.terms.items():
            for ea, k in (c.num * (den // c.den)).to_dict().items():
                terms[e + tuple(ea)] = self.big.field(int(k))
        return Poly(self.big, terms)

    def ideal(self, ideal: Ideal) -> list[Poly]:
        """``J = I K(a)[x] ∩ K[x, a]``: the lifted generators saturated by the product of the
        leading coefficients (in ``K[a]``) of their Gröbner basis, eliminating ``x``."""
        basis = groebner([self._lift(p) for p in ideal if not p.is_zero()], self.big)
        return _contract(basis, self.big, range(self.n))[0]

    def generic(self, prime: list[Poly]) -> bool:
        """Whether a prime, a reduced basis for the elimination ordering, meets ``K[a]`` in 0."""
        return all(any(e[:self.n]) for e in (p.lm() for p in prime))

    def back(self, basis: list[Poly]) -> list[Poly]:
        """The extension to ``K(a)[x]``, a reduced basis."""
        field, polys = self.field, []
        for p in basis:
            if not field.characteristic:
                p = p * math.lcm(*(int(c.q) for c in p.terms.values()))
            coeffs: dict[Exp, dict] = {}
            for e, c in p.terms.items():
                coeffs.setdefault(e[:self.n], {})[e[self.n:]] = int(c.p) if not field.characteristic else int(c)
            polys.append(Poly(self.ring, {e: field.from_polys(field.ctx.from_dict(d)) for e, d in coeffs.items()}))
        return groebner(polys, self.ring)


def _work(ideal: Ideal, ring: PolyRing | None) -> tuple[PolyRing, PolyRing, list[Poly]]:
    """``(ring, work, basis)``: the input ring, the same ring ordered by ``dp`` (where the
    decompositions run, as they do not depend on the ordering) and the ideal's reduced
    basis there."""
    ring = ring_of(ideal, ring=ring)
    dp = MonomialOrder([Block("dp", ring.nvars)])
    work = ring if ring.order == dp else with_order(ring, dp)
    return ring, work, std(move(ideal, work), work)


def _back(basis: list[Poly], ring: PolyRing) -> list[Poly]:
    return groebner(move(basis, ring), ring)


def _sort_key(ring: PolyRing) -> Callable[[list[Poly]], tuple]:
    """A deterministic order of ideals: decreasing dimension, then leading monomials."""
    key = ring.order.key
    return lambda b: (-dimension(b, ring), [key(p.lm()) for p in b])


def _min_ass_public(ideal: Ideal, ring: PolyRing | None, split: bool) -> list[list[Poly]]:
    ring = ring_of(ideal, ring=ring)
    if _Parameters.of(ring):
        pr = _Parameters(ring)
        return sorted([pr.back(p) for p in _min_ass_public(pr.ideal(ideal), pr.big, split)
                       if pr.generic(p)], key=_sort_key(ring))
    ring, work, basis = _work(ideal, ring)
    if is_unit(basis):
        return []
    primes = [_back(p, ring) for p in _min_ass(basis, work, {}, split)]
    return sorted(primes, key=_sort_key(ring))


def min_ass_gtz(ideal: Ideal, ring: PolyRing | None = None) -> list[list[Poly]]:
    """The minimal associated primes of ``I`` (Singular's ``minAssGTZ``), as reduced bases;
    ``[]`` for the unit ideal."""
    return _min_ass_public(ideal, ring, True)


def min_ass_char(ideal: Ideal, ring: PolyRing | None = None) -> list[list[Poly]]:
    """The minimal associated primes (Singular's ``minAssChar``).  Computed like
    :func:`min_ass_gtz` but without the factorizing pre-split: each ideal is reduced to
    dimension zero directly and split by factoring minimal polynomials (triangular
    splitting in place of characteristic sets); the result is the same set of primes."""
    return _min_ass_public(ideal, ring, False)


def radical(ideal: Ideal, ring: PolyRing | None = None) -> list[Poly]:
    """The radical of ``I``: the intersection of its minimal primes."""
    ring = ring_of(ideal, ring=ring)
    primes = min_ass_gtz(ideal, ring)
    return intersect(*primes, ring=ring) if primes else [ring.one()]


def equi_radical(ideal: Ideal, ring: PolyRing | None = None) -> list[Poly]:
    """Singular's ``equiRadical``: the intersection of the minimal primes of maximal
    dimension (the radical of the top-dimensional part)."""
    ring = ring_of(ideal, ring=ring)
    primes = min_ass_gtz(ideal, ring)
    if not primes:
        return [ring.one()]
    top = max(dimension(p, ring) for p in primes)
    return intersect(*[p for p in primes if dimension(p, ring) == top], ring=ring)


def is_prime(ideal: Ideal, ring: PolyRing | None = None) -> bool:
    """Whether ``I`` is a prime ideal (the unit ideal is not)."""
    _, work, basis = _work(ideal, ring)
    primes = [] if is_unit(basis) else _min_ass(basis, work, {})
    return len(primes) == 1 and primes[0] == basis


def is_primary(ideal: Ideal, ring: PolyRing | None = None) -> bool:
    """Whether ``I`` is a primary ideal (the unit ideal is not)."""
    _, work, basis = _work(ideal, ring)
    if is_unit(basis):
        return False
    primes = _min_ass(basis, work, {})
    return len(primes) == 1 and len(_clean(_primdec_sy(basis, work, {}), work)) == 1


# --- primary decomposition ---------------------------------------------------------------

def _separator(primes: list[list[Poly]], i: int, ring: PolyRing) -> Poly:
    """An element of every prime but the ``i``-th, not in the ``i``-th."""
    s = ring.one()
    for j, p in enumerate(primes):
        if j == i:
            continue
        outside = [g for g in p if not normal_form(g, primes[i]).is_zero()]
        s = s * min(outside, key=lambda g: (g.total_degree(), len(g)))
    return s


def _split_off(basis: list[Poly], h: Poly, ring: PolyRing,
               saturated: list[Poly] | None = None) -> list[Poly] | None:
    """``I + h^m`` with ``m`` the saturation exponent of ``h``, or None when ``I : h == I``."""
    if h.is_constant():
        return None
    sat = saturated if saturated is not None else saturate_poly(basis, h, ring, is_basis=True)
    m = saturation_exponent(basis, sat, [h], ring, is_basis=True)
    if m == 0:
        return None
    return groebner(basis + [h ** m], ring)


def _primdec_gtz(basis: list[Poly], ring: PolyRing) -> list[Component]:
    """Primary components of ``I`` (possibly redundant): the components of ``I : h^∞`` from
    dimension zero over ``K(u)``, then the same for ``I + h^m``, until the components found
    intersect to ``I``."""
    comps: list[Component] = []
    found = [ring.one()]
    rest: list[Poly] | None = basis
    while rest is not None and not is_unit(rest):
        red = _Reduction(rest, ring)
        new = red.primaries()
        comps += new
        found = intersect(found, *[q for q, _ in new], ring=ring)
        if _contained(found, basis):
            break
        rest = _split_off(rest, red.h, ring)
    return comps


def _primdec_sy(basis: list[Poly], ring: PolyRing, cache: dict) -> list[Component]:
    if is_unit(basis):
        return []
    primes = _min_ass(basis, ring, cache)
    comps: list[Component] = []
    if len(primes) == 1:
        return _extract(basis, primes[0], ring, cache)
    rest = basis
    for i, p in enumerate(primes):
        s = _separator(primes, i, ring)
        sat = saturate_poly(rest, s, ring, is_basis=True)
        comps += _extract(sat, p, ring, cache)
        m = saturation_exponent(rest, sat, [s], ring, is_basis=True)
        rest = groebner(rest + [s ** m], ring) if m else sat
    if not is_unit(rest):
        comps += _primdec_sy(rest, ring, cache)
    return comps


def _extract(pseudo: list[Poly], prime: list[Poly], ring: PolyRing, cache: dict) -> list[Component]:
    """The isolated primary component of a pseudo-primary ideal (radical ``prime``) and the
    decomposition of what remains."""
    red = _Reduction(pseudo, ring, independent_set(prime, ring.nvars))
    h = red.h
    primary = pseudo if h.is_constant() else saturate_poly(pseudo, h, ring, is_basis=True)
    comps = [(primary, prime)]
    rest = _split_off(pseudo, h, ring, primary)
    if rest is not None:
        comps += _primdec_sy(rest, ring, cache)
    return comps


def _clean(comps: list[Component], ring: PolyRing) -> list[Component]:
    """Merge components with equal radicals and drop redundant ones (most embedded first)."""
    merged: dict[tuple[Poly, ...], list[list[Poly]]] = {}
    for q, p in comps:
        merged.setdefault(tuple(p), []).append(q)
    items = [(intersect(*qs, ring=ring) if len(qs) > 1 else qs[0], list(p))
             for p, qs in merged.items()]
    dims = [dimension(p, ring) for _, p in items]
    keep = list(range(len(items)))
    for k in sorted(range(len(items)), key=lambda k: dims[k]):
        q, p = items[k]
        below = [items[j][0] for j in keep if j != k and _contained(items[j][1], p)]
        if below and _contained(intersect(*below, ring=ring), q):
            keep.remove(k)
    return [items[k] for k in keep]


def _primdec_public(ideal: Ideal, ring: PolyRing | None, method: str) -> list[Component]:
    ring = ring_of(ideal, ring=ring)
    key = _sort_key(ring)
    if _Parameters.of(ring):
        pr = _Parameters(ring)
        comps = [(pr.back(q), pr.back(p)) for q, p in _primdec_public(pr.ideal(ideal), pr.big, method)
                 if pr.generic(p)]
        return sorted(comps, key=lambda c: (key(c[1]), key(c[0])))
    ring, work, basis = _work(ideal, ring)
    comps = _primdec_gtz(basis, work) if method == "gtz" else _primdec_sy(basis, work, {})
    out = [(_back(q, ring), _back(p, ring)) for q, p in _clean(comps, work)]
    return sorted(out, key=lambda c: (key(c[1]), key(c[0])))


def primdec_gtz(ideal: Ideal, ring: PolyRing | None = None) -> list[Component]:
    """An irredundant primary decomposition (Singular's ``primdecGTZ``): a list of
    ``(primary, prime)`` pairs of reduced bases, embedded components included; ``[]`` for
    the unit ideal."""
    return _primdec_public(ideal, ring, "gtz")


def primdec_sy(ideal: Ideal, ring: PolyRing | None = None) -> list[Component]:
    """An irredundant primary decomposition by Shimoyama–Yokoyama (Singular's
    ``primdecSY``); same format as :func:`primdec_gtz`."""
    return _primdec_public(ideal, ring, "sy")


# --- equidimensional parts --------------------------------------------------------------

def equidim(ideal: Ideal, ring: PolyRing | None = None) -> list[list[Poly]]:
    """Singular's ``equidim``: equidimensional ideals ``a[1..s]`` with intersection ``I``,
    by increasing dimension; ``a[s]`` is the top-dimensional part (the intersection of the
    primary components of dimension ``dim I``), ``a[k]`` the intersection of the components
    of the k-th smaller dimension occurring.  Embedded components are not unique, so the
    lower parts may differ from Singular's (their radicals agree).  ``[[1]]`` for the unit
    ideal."""
    ring = ring_of(ideal, ring=ring)
    comps = primdec_gtz(ideal, ring)
    if not comps:
        return [[ring.one()]]
    by_dim: dict[int, list[list[Poly]]] = {}
    for q, p in comps:
        by_dim.setdefault(dimension(p, ring), []).append(q)
    return [intersect(*by_dim[d], ring=ring) for d in sorted(by_dim)]


def equidim_max(ideal: Ideal, ring: PolyRing | None = None) -> list[Poly]:
    """Singular's ``equidimMax``: the top-dimensional part of ``I``."""
    return equidim(ideal, ring)[-1]
