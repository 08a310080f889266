"""Minimal associated primes, primary decomposition, radicals and equidimensional parts.

Ideals are lists of :class:`Poly` of one ring with a global ordering; results are reduced
Gröbner bases in that ring (see :mod:`.ideals`).  The algorithms (Greuel–Pfister, *A Singular
Introduction to Commutative Algebra*, ch. 4):

* **Reduction to dimension zero** (Gianni–Trager–Zacharias; :mod:`.zerodim`).  For a
  maximal independent set ``u`` of ``I`` and the other variables ``x``, a Gröbner basis for
  the product ordering ``(dp(x), dp(u))`` is one of ``I K(u)[x]``, which is zero-dimensional;
  with ``h`` the product of the leading coefficients in ``K[u]`` of the elements with minimal
  leading ``x``-monomials (a Gröbner basis over ``K(u)``), ``I K(u)[x] ∩ K[x,u] = I : h^∞``
  and ``I = (I : h^∞) ∩ (I + h^m)`` for the saturation exponent ``m``.
* **Zero-dimensional primes over K(u)**: factor the minimal polynomial of each variable
  (:mod:`.minpoly`) and split; add the squarefree parts (Seidenberg's lemma makes the
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
from typing import Callable, Sequence

from .coeffs import GF, QQ
from .factor import normalize
from .groebner import contains_all, groebner, normal_form
from .ideals import (Ideal, dimension, independent_set, intersect, is_unit, move,
                     product_order, quotient, ring_of, saturate_poly, saturation_exponent, std,
                     with_order)
from .order import Block, Exp, MonomialOrder
from .poly import Poly, PolyRing
from .zerodim import Component, Reduction, contract, irreducible, separator


def _is_linear(basis: Sequence[Poly]) -> bool:
    return all(p.total_degree() <= 1 for p in basis)


# --- minimal associated primes ----------------------------------------------------------

def _contained(polys: Sequence[Poly], basis: Sequence[Poly]) -> bool:
    """Whether the polynomials lie in the ideal of the Gröbner basis ``basis``."""
    return contains_all(basis, polys)


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
            facs = [f for f in irreducible(p, cache) if f not in nonzero]
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
        red = Reduction(piece, ring)
        found = red.primes()
        primes.extend(found)
        h = red.h
        # nothing outside V(h)'s complement when the piece is itself one of its primes, or I : h = I
        if h.is_constant() or any(_contained(P, piece) for P in found) or \
                _contained(quotient(piece, [h], ring), piece):
            continue
        for f in irreducible(h, cache):
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
        gens = [self._lift(p) for p in ideal if not p.is_zero()]
        if hasattr(self.field, "modulus"):  # K[a]/(m) (kernel/algext.py): K[x, a]/(I, m(a)), nothing to saturate
            m = self.field.modulus
            cs = m.numer().coeffs() if not self.field.characteristic else m.coeffs()
            gens.append(Poly(self.big, {(0,) * self.n + (e,): self.big.field(int(c)) for e, c in enumerate(cs) if int(c)}))
            return groebner(gens, self.big)
        basis = groebner(gens, self.big)
        return contract(basis, self.big, range(self.n))[0]

    def generic(self, prime: list[Poly]) -> bool:
        """Whether a prime, a reduced basis for the elimination ordering, meets ``K[a]`` in 0."""
        return hasattr(self.field, "modulus") or all(any(e[:self.n]) for e in (p.lm() for p in prime))

    def back(self, basis: list[Poly]) -> list[Poly]:
        """The extension to ``K(a)[x]``, a reduced basis."""
        field, polys = self.field, []
        for p in basis:
            if not field.characteristic:
                p = p * math.lcm(*(int(c.q) for c in p.terms.values()))
            coeffs: dict[Exp, dict] = {}
            for e, c in p.terms.items():
                coeffs.setdefault(e[:self.n], {})[e[self.n:]] = int(c.p) if not field.characteristic else int(c)
            image = {e: field.from_polys(field.ctx.from_dict(d)) for e, d in coeffs.items()}
            polys.append(Poly(self.ring, {e: c for e, c in image.items() if c}))  # K[a]/(m): m(a) goes to 0
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
        red = Reduction(rest, ring)
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
        s = separator(primes, i, ring)
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
    red = Reduction(pseudo, ring, independent_set(prime, ring.nvars))
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
