"""Submodules of free modules R^n over a polynomial ring with field coefficients: Gröbner bases
(Buchberger's algorithm for modules, with the chain criterion), normal forms, membership,
syzygies and minimal generators of graded submodules.

A vector of R^n is a dict ``{(exp, comp): coeff}`` (``comp`` from 0).  Terms are compared by a
*module order*: ``term over position`` (Macaulay2's default, ``Position => Up``: the monomial
first, then the larger component), or, with ``elim = m``, every term in a component ``< m`` above
every term in a component ``>= m`` (used for syzygies: Schreyer's elimination of the components).
Literature: Greuel–Pfister, *A Singular Introduction to Commutative Algebra*, 2.3 (standard bases
of modules) and 2.5 (syzygies by elimination of components); Eisenbud, *Commutative Algebra*, 15.5.
"""
from __future__ import annotations

import heapq
from typing import Any, Callable, Iterable, Optional, Sequence

from .poly import Poly, PolyRing, divides, lcm_exp, sub_exp, support_mask

Exp = tuple[int, ...]
Term = tuple[Exp, int]
Vector = dict[Term, Any]


def vector(columns: Sequence[Poly]) -> Vector:
    """The vector with these entries (entry i in component i)."""
    return {(e, i): c for i, p in enumerate(columns) for e, c in p.terms.items()}


def entries(v: Vector, ring: PolyRing, rank: int) -> list[Poly]:
    """The entries of a vector, one polynomial per component."""
    parts: list[dict[Exp, Any]] = [{} for _ in range(rank)]
    for (e, i), c in v.items():
        parts[i][e] = c
    return [Poly(ring, d) for d in parts]


class ModuleOrder:
    """A term order on R^n: term over position (components ascending), optionally with the
    components below ``elim`` eliminated (above all others) and, with ``shifts``, terms compared
    first by their degree plus their component's shift (a degree order whatever the ring's).
    ``key`` grows with the term, ``neg_key`` shrinks (for heaps)."""

    def __init__(self, ring: PolyRing, elim: int = 0, shifts: Optional[Sequence[int]] = None) -> None:
        base = ring.order.key
        if shifts is not None:
            sh = tuple(shifts)

            def okey(e: Exp, i: int = 0) -> tuple:
                return (sum(e) + sh[i],) + base(e)
        else:
            def okey(e: Exp, i: int = 0) -> tuple:
                return base(e)

        def nkey(e: Exp, i: int = 0) -> tuple:
            return tuple(-v for v in okey(e, i))
        if elim:
            self.key: Callable[[Term], tuple] = lambda t: (t[1] < elim, okey(*t), t[1])
            self.neg_key: Callable[[Term], tuple] = lambda t: (t[1] >= elim, nkey(*t), -t[1])
        else:
            self.key = lambda t: (okey(*t), t[1])
            self.neg_key = lambda t: (nkey(*t), -t[1])


class _Descending:
    """A sort key in reverse (the heap's order for a module order given by its key)."""

    __slots__ = ("k",)

    def __init__(self, k: tuple) -> None:
        self.k = k

    def __lt__(self, other: "_Descending") -> bool:
        return other.k < self.k


def _lead(v: Vector, key: Callable[[Term], tuple]) -> Term:
    return max(v, key=key)


def _add_multiple(f: Vector, g: Vector, shift: Exp, c: Any) -> None:
    """f += c * x^shift * g, in place."""
    for (e, i), d in g.items():
        t = (tuple(a + b for a, b in zip(e, shift)), i)
        s = f.get(t)
        if s is None:
            f[t] = c * d
        else:
            s = s + c * d
            if s == 0:
                del f[t]
            else:
                f[t] = s


class ModuleGB:
    """A Gröbner basis of a submodule of R^n, completed as generators are added (:meth:`add`)."""

    def __init__(self, ring: PolyRing, rank: int, elim: int = 0, shifts: Optional[Sequence[int]] = None,
                 collect: bool = False, key: Optional[Callable[[Term], tuple]] = None) -> None:
        self.ring, self.rank, self.elim = ring, rank, elim
        self.collect = collect and elim > 0
        self.syzygies: list[Vector] = []  # with collect: the reduced vectors with no term below elim
        self._pairs: list[tuple[int, int, int]] = []  # (degree, i, j), a heap
        self._pending: set[tuple[int, int]] = set()
        self.shifts = tuple(shifts) if shifts is not None else (0,) * rank
        if key is None:
            order = ModuleOrder(ring, elim, shifts)
            self.key, self.neg_key = order.key, order.neg_key
        else:  # another module order (a global one: Singular's position over term, c or C), below elim's
            self.key = (lambda t: (t[1] < elim, key(t))) if elim else key
            self.neg_key = lambda t: _Descending(self.key(t))
        self.basis: list[Vector] = []
        self.leads: list[Term] = []
        self._by_comp: dict[int, list[tuple[Exp, int, int]]] = {}  # component -> (lead exp, mask, index)
        self._treated: set[tuple[int, int]] = set()

    def _set_basis(self, basis: list[Vector], leads: list[Term]) -> None:
        self.basis, self.leads = basis, leads
        self._by_comp = {}
        for k, (e, i) in enumerate(leads):
            self._by_comp.setdefault(i, []).append((e, support_mask(e), k))

    # ---------------------------------------------------------------- reduction
    def _divisor(self, t: Term, skip: int = -1) -> Optional[int]:
        e, i = t
        cands = self._by_comp.get(i)
        if not cands:
            return None
        m = support_mask(e)
        for le, lm, k in cands:
            if k != skip and not lm & ~m and divides(le, e):
                return k
        return None

    def reduce(self, f: Vector, full: bool = True, skip: int = -1) -> Vector:
        """The normal form of f (full: every term reduced; otherwise only the lead term; ``skip``:
        a basis element not to use)."""
        f = dict(f)
        out: Vector = {}
        nkey = self.neg_key
        heap = [(nkey(t), t) for t in f]
        heapq.heapify(heap)
        while heap:
            t = heapq.heappop(heap)[1]
            c = f.get(t)
            if c is None:
                continue
            k = self._divisor(t, skip)
            if k is None:
                if not full:
                    out.update(f)
                    return out
                out[t] = f.pop(t)
                continue
            g, lt = self.basis[k], self.leads[k]
            shift, coef = sub_exp(t[0], lt[0]), -c / g[lt]
            for (e, i), d in g.items():
                u = (tuple(a + b for a, b in zip(e, shift)), i)
                s = f.get(u)
                if s is None:
                    f[u] = coef * d
                    heapq.heappush(heap, (nkey(u), u))
                else:
                    s = s + coef * d
                    if s == 0:
                        del f[u]
                    else:
                        f[u] = s
        return out

    def contains(self, f: Vector) -> bool:
        return not self.reduce(f, full=False)

    # ---------------------------------------------------------------- completion
    def add(self, gens: Iterable[Vector], reduced: bool = True, up_to: Optional[int] = None) -> None:
        """Add generators and complete the basis (Buchberger's algorithm, pairs by degree of
        their lcm plus their component's shift, Buchberger's chain criterion); ``up_to``: only the
        pairs up to that degree (the rest wait for a later call: for homogeneous vectors and
        shifts, a basis complete up to degree d decides membership in degrees <= d);
        ``reduced``: then interreduce the basis."""
        pairs, pending = self._pairs, self._pending
        for g in gens:
            self._insert(g)
        while pairs and (up_to is None or pairs[0][0] <= up_to):
            _, i, j = heapq.heappop(pairs)
            pending.discard((i, j))
            if not self._chain(i, j, pending):
                self._insert(self._spoly(i, j))
        if reduced:
            self._interreduce()

    def _insert(self, g: Vector) -> None:
        g = self.reduce(g)
        if not g:
            return
        t = _lead(g, self.key)
        if self.collect and t[1] >= self.elim:
            self.syzygies.append(g)
            return
        c = g[t]
        g = {k: v / c for k, v in g.items()}
        n = len(self.basis)
        self.basis.append(g)
        self.leads.append(t)
        for le, _, k in self._by_comp.get(t[1], ()):
            heapq.heappush(self._pairs, (sum(lcm_exp(le, t[0])) + self.shifts[t[1]], k, n))
            self._pending.add((k, n))
        self._by_comp.setdefault(t[1], []).append((t[0], support_mask(t[0]), n))

    def _chain(self, i: int, j: int, pending: set[tuple[int, int]]) -> bool:
        """Buchberger's chain criterion: some lead k (same component) divides lcm(lead i, lead j)
        and the pairs (i, k), (j, k) are already treated."""
        L = lcm_exp(self.leads[i][0], self.leads[j][0])
        m = support_mask(L)
        for le, lm, k in self._by_comp[self.leads[i][1]]:
            if k in (i, j) or lm & ~m or not divides(le, L):
                continue
            if (min(i, k), max(i, k)) not in pending and (min(j, k), max(j, k)) not in pending:
                return True
        return False

    def _spoly(self, i: int, j: int) -> Vector:
        (ei, _), (ej, _) = self.leads[i], self.leads[j]
        L = lcm_exp(ei, ej)
        f: Vector = {}
        _add_multiple(f, self.basis[i], sub_exp(L, ei), self.ring.field.one)
        _add_multiple(f, self.basis[j], sub_exp(L, ej), -self.ring.field.one)
        return f

    def _interreduce(self) -> None:
        """Keep a minimal basis (no lead divides another's) with reduced tails (a complete basis:
        no pair waits)."""
        if self._pairs:
            raise ValueError("interreducing a basis with pairs left")
        order = sorted(range(len(self.basis)), key=lambda k: self.key(self.leads[k]))
        keep: list[int] = []
        for k in order:
            e, i = self.leads[k]
            if not any(self.leads[m][1] == i and divides(self.leads[m][0], e) for m in keep):
                keep.append(k)
        self._set_basis([self.basis[k] for k in keep], [self.leads[k] for k in keep])
        for n, g in enumerate(self.basis):
            lt = self.leads[n]
            tail = self.reduce({t: c for t, c in g.items() if t != lt}, skip=n)
            tail[lt] = g[lt]
            self.basis[n] = tail


def groebner_basis(ring: PolyRing, rank: int, gens: Sequence[Vector]) -> list[Vector]:
    """The reduced Gröbner basis (monic) of the submodule generated by gens, in term over position
    order, sorted by increasing lead term (as Macaulay2's ``gens gb`` lists it)."""
    gb = ModuleGB(ring, rank)
    gb.add(gens)
    return gb.basis


def vector_degree(v: Vector, degrees: Sequence[int]) -> Optional[int]:
    """The degree of a vector: the largest of its terms' degrees plus their components' degrees
    (the degree of a homogeneous vector; None for 0)."""
    if not v:
        return None
    return max(sum(e) + degrees[i] for e, i in v)


def syzygies(ring: PolyRing, rank: int, gens: Sequence[Vector],
             degrees: Optional[Sequence[int]] = None) -> list[Vector]:
    """Generators of the syzygies of gens (vectors of R^len(gens)): Buchberger's algorithm on
    ``gens[j] + e_(rank+j)`` with the first ``rank`` components eliminated, the S-polynomials
    and generators whose first part reduces to 0 giving syzygies (they generate them: Schreyer's
    theorem, Eisenbud 15.10; Greuel–Pfister 2.5).  The terms are compared by degree first,
    e_(rank+j) of the degree of gens[j] (with ``degrees``, the components' degrees; else 0):
    homogeneous gens make homogeneous vectors, treated degree by degree."""
    k = len(gens)
    degrees = list(degrees) if degrees is not None else [0] * rank
    shifts = degrees + [vector_degree(g, degrees) or 0 for g in gens]
    gb = ModuleGB(ring, rank + k, elim=rank, shifts=shifts, collect=True)
    gb.add([{**g, **{(ring_zero_exp(ring), rank + j): ring.field.one}} for j, g in enumerate(gens)], reduced=False)
    return [{(e, i - rank): c for (e, i), c in g.items()} for g in gb.syzygies]


def ring_zero_exp(ring: PolyRing) -> Exp:
    return (0,) * ring.nvars


def minimal_generators(ring: PolyRing, rank: int, gens: Sequence[Vector],
                       degrees: Optional[Sequence[int]] = None) -> list[Vector]:
    """Generators of the submodule generated by gens, taken by increasing degree (component
    degrees ``degrees``; None: by lead term only) and lead term, each kept unless it lies in the
    span of those kept before it: a minimal generating set when gens are homogeneous."""
    key = ModuleOrder(ring).key

    def rank_of(g: Vector) -> tuple:
        lead = key(max(g, key=key))
        return (vector_degree(g, degrees), lead) if degrees is not None else (lead,)

    gb = ModuleGB(ring, rank, shifts=degrees)
    kept: list[Vector] = []
    for g in sorted((g for g in gens if g), key=rank_of):
        d = vector_degree(g, degrees) if degrees is not None else None
        gb.add([], reduced=False, up_to=d)  # complete up to g's degree
        if gb.contains(g):
            continue
        kept.append(g)
        gb.add([g], reduced=False, up_to=d)
    return kept


def is_homogeneous(v: Vector, degrees: Sequence[int]) -> bool:
    return len({sum(e) + degrees[i] for e, i in v}) <= 1


def resolution(ring: PolyRing, rank: int, gens: Sequence[Vector], degrees: Sequence[int],
               max_length: Optional[int] = None) -> list[tuple[list[Vector], list[int]]]:
    """A minimal graded free resolution of the quotient R^rank / <gens> (homogeneous gens):
    the differentials d_1, d_2, ... as (columns, their source degrees); d_1's columns are a minimal
    generating set of the submodule, d_(i+1)'s a minimal one of d_i's syzygies (Eisenbud, 19.1)."""
    maps: list[tuple[list[Vector], list[int]]] = []
    cols = minimal_generators(ring, rank, gens, degrees)
    tdeg = list(degrees)
    limit = ring.nvars + 1 if max_length is None else max_length
    while cols and len(maps) < limit:
        sdeg = [vector_degree(c, tdeg) for c in cols]
        maps.append((cols, sdeg))
        cols = minimal_generators(ring, len(cols), syzygies(ring, len(tdeg), cols, tdeg), sdeg)
        tdeg = sdeg
    return maps


def lift(ring: PolyRing, rank: int, gens: Sequence[Vector], f: Vector) -> Optional[list[Poly]]:
    """Coefficients a_j with f = sum a_j gens[j], or None when f is not in the submodule."""
    k = len(gens)
    gb = ModuleGB(ring, rank + k, elim=rank)
    gb.add([{**g, **{(ring_zero_exp(ring), rank + j): ring.field.one}} for j, g in enumerate(gens)])
    r = gb.reduce(f)
    if any(i < rank for _, i in r):
        return None
    return [-p for p in entries({(e, i - rank): c for (e, i), c in r.items()}, ring, k)]


def drop_unit_relations(ring: PolyRing, cols: Sequence[Vector], degrees: Sequence[int]) -> tuple[list[Vector], list[int]]:
    """The relations of R^n / <cols> after removing each generator that a relation with a nonzero
    constant entry expresses by the others (that entry's component is deleted); returns the
    remaining relations and component degrees."""
    cols, degrees = [dict(c) for c in cols], list(degrees)
    zero = (0,) * ring.nvars

    def unit_entry(c: Vector) -> Optional[int]:
        comps = [i for (e, i) in c if e == zero]
        return next((i for i in comps if sum(1 for (_, k) in c if k == i) == 1), None)

    while True:
        unit = next(((j, i) for j, c in enumerate(cols) if (i := unit_entry(c)) is not None), None)
        if unit is None:
            return cols, degrees
        j, i = unit
        r = cols.pop(j)
        c0 = r[(zero, i)]
        out = []
        for c in cols:
            for (e, k), v in [(t, v) for t, v in c.items() if t[1] == i]:
                _add_multiple(c, r, e, -v / c0)
            out.append({(e, k - (k > i)): v for (e, k), v in c.items() if k != i})
        cols = out
        del degrees[i]


def annihilator(ring: PolyRing, rank: int, relations: Sequence[Vector]) -> list[Poly]:
    """Generators of the annihilator of R^rank / <relations>: the intersection over the
    components i of (relations : e_i), each the first entries of the syzygies of e_i and the
    relations."""
    from .ideals import intersect
    zero = ring_zero_exp(ring)
    parts = []
    for i in range(rank):
        syz = syzygies(ring, rank, [{(zero, i): ring.field.one}, *relations])
        parts.append([Poly(ring, {e: c for (e, k), c in s.items() if k == 0}) for s in syz] or [ring.zero()])
    return intersect(*parts, ring=ring) if parts else [ring.one()]


def local_standard_basis(ring: PolyRing, rank: int, gens: Sequence[Vector],
                         key: Callable[[Term], tuple]) -> list[Vector]:
    """A standard basis of the submodule generated by gens for a module order ``key`` that need not be
    a well-order (local or mixed): Lazard's method (Greuel–Pfister 1.7.3, for modules 2.3): a Gröbner
    basis of the homogenized generators (a new variable t) for the order comparing total degree first,
    then ``key`` (a well-order), dehomogenized (t = 1) and kept minimal by leading terms, sorted by
    increasing leading term."""
    from .order import MonomialOrder
    hring = PolyRing(ring.field, tuple(ring.names) + ("@t",), MonomialOrder.simple("dp", ring.nvars + 1))

    def hom(v: Vector) -> Vector:
        d = max(sum(e) for e, _ in v)
        return {(e + (d - sum(e),), i): c for (e, i), c in v.items()}

    gb = ModuleGB(hring, rank, key=lambda t: (sum(t[0]), key((t[0][:-1], t[1]))))
    gb.add([hom(v) for v in gens if v])
    out = [{(e[:-1], i): c for (e, i), c in g.items()} for g in gb.basis]
    leads = [max(v, key=key) for v in out]
    keep: list[int] = []
    for k in sorted(range(len(out)), key=lambda k: (sum(leads[k][0]), key(leads[k]))):  # divisors first
        e, i = leads[k]
        if not any(leads[m][1] == i and divides(leads[m][0], e) for m in keep):
            keep.append(k)
    return [out[k] for k in sorted(keep, key=lambda k: key(leads[k]))]
