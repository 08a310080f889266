"""The fibres of a two-parameter zero-dimensional family modulo a prime, fast: characteristic
polynomials of linear forms at many parameter points ``(a, b)`` in ``F_p``.

The fibre's Gröbner basis (``dp``) is computed once by F4 at a random point with a trace
(:mod:`mech.kernel.f4_trace`, Traverso's Gröbner trace), and at every other point the trace is
replayed: only the linear algebra that mattered, with the point's coefficients. A point whose
computation does not follow the trace (a special fibre) is skipped. The reduced basis gives the
multiplication matrices by the normal forms of the border monomials, in increasing order
(Faugère, Gianni, Lazard and Mora 1993): a leading monomial reduces to minus its tail, any other
border monomial is ``x_j t`` for a smaller border monomial ``t``. The recipe of that recursion
depends only on the leading monomials, so it is made once; a point costs one replay and a few
small vector sums.
"""
from __future__ import annotations

import random
from typing import Any, Sequence

from flint import nmod_mat, nmod_poly

from mech.kernel.f4 import F4, PackingOverflow, initial_degree
from mech.kernel.f4_trace import TraceMismatch, replay
from mech.kernel.hilbert import kbase
from mech.kernel.dimension import krull_dim
from mech.kernel.monomials import Packing
from mech.kernel.poly import PolyRing

Exp = tuple[int, ...]


class Unlucky(Exception):
    """No generic fibre found modulo this prime (take another)."""


class ModFibres:
    """The family ``gens`` (``terms``: per generator, config monomial -> [(i, j, integer c)] for
    ``c a^i b^j``) modulo ``p``, in the configuration ring ``ring`` (``dp``)."""

    def __init__(self, ring: PolyRing, terms: Sequence[dict[Exp, list[tuple[int, int, int]]]], p: int,
                 forms: Sequence[Sequence[int]], seed: int) -> None:
        self.ring, self.p, self.n = ring, p, ring.nvars
        self.forms = [[c % p for c in f] for f in forms]
        self.rnd = random.Random(seed)
        self.packing = Packing(ring.order, initial_degree([_Degree(max(sum(e) for e in t)) for t in terms]))
        self.shapes: list[list[int]] = []
        self.parts: list[list[list[tuple[int, int, int]]]] = []
        for t in terms:
            items = sorted(((self.packing.pack(e), parts) for e, parts in t.items()), reverse=True)
            self.shapes.append([m for m, _ in items])
            self.parts.append([[(i, j, c % p) for i, j, c in parts] for _, parts in items])
        self.degrees = (max(i for g in self.parts for ps in g for i, _, _ in ps),
                        max(j for g in self.parts for ps in g for _, j, _ in ps))
        self.trace: Any = None
        self.dim = 0
        self.hits = self.misses = 0  # points that followed the trace, and that did not

    # -- the generators at a point ---------------------------------------------------------
    def coefficients(self, a: int, b: int, strict: bool = True) -> list[list[int]] | None:
        """Each generator's coefficients at (a, b) in its shape; None when a leading one vanishes
        (``strict``)."""
        p = self.p
        pa, pb = [1], [1]
        for _ in range(self.degrees[0]):
            pa.append(pa[-1] * a % p)
        for _ in range(self.degrees[1]):
            pb.append(pb[-1] * b % p)
        out = []
        for g in self.parts:
            cs = [sum(c * pa[i] * pb[j] for i, j, c in ps) % p for ps in g]
            if cs[0] == 0 and strict:
                return None
            out.append(cs)
        return out

    def learn(self, dim: int | None = None, tries: int = 8) -> int:
        """Record the trace at a random point (whose fibre has ``dim`` points, when given); the
        fibre's dimension as a vector space (0: not zero-dimensional or empty)."""
        for _ in range(tries):
            a, b = self.rnd.randrange(1, self.p), self.rnd.randrange(1, self.p)
            cs = self.coefficients(a, b)
            if cs is None:
                continue
            engine = F4(list(zip(self.shapes, cs)), self.packing, self.p, record=True)
            try:
                engine.run()
            except PackingOverflow:
                raise Unlucky("monomials beyond the packing") from None
            self._structure(engine.trace.shape, engine.trace.unit)
            if dim is None or self.dim == dim:
                self.trace = engine.trace
                return self.dim
        raise Unlucky(f"no fibre with {dim} points modulo {self.p}")

    def _structure(self, shape: list[list[int]], unit: bool) -> None:
        """The standard monomials and the recipe of the multiplication matrices of a reduced
        basis with the monomials ``shape`` (packed, leading one first)."""
        unpack, n = self.packing.unpack, self.n
        leads = [unpack(ms[0]) for ms in shape]
        self.dim = 0
        if unit or krull_dim(leads, n) != 0:
            return
        self.monomials = kbase(leads, n)
        self.index = {e: i for i, e in enumerate(self.monomials)}
        self.dim = len(self.monomials)
        lead_of = {e: k for k, e in enumerate(leads)}
        border = sorted({_shift(b, i) for b in self.monomials for i in range(n)} - set(self.index),
                        key=self.ring.order.key)
        ids = dict(self.index)  # standard monomials 0 .. dim-1, then the border in increasing order
        for t in border:
            ids[t] = len(ids)
        self.tails = [[self.index[unpack(m)] for m in ms[1:]] for ms in shape]
        self.recipe: list[tuple[int, list[int] | None]] = []  # (basis element, None) or (x_j t's t, targets)
        for t in border:
            if t in lead_of:
                self.recipe.append((lead_of[t], None))
            else:
                j = next(j for j in range(n) if t[j] and self.dim <= ids.get(_shift(t, j, -1), -1) < ids[t])
                self.recipe.append((ids[_shift(t, j, -1)], [ids[_shift(bm, j)] for bm in self.monomials]))
        self.products = [[ids[_shift(bm, i)] for bm in self.monomials] for i in range(n)]  # x_i b_k

    # -- a point ----------------------------------------------------------------------------
    def matrices(self, a: int, b: int) -> list[list[list[int]]] | None:
        """The forms' multiplication matrices (columns) at (a, b) in the generic fibre's basis, or
        None when the point's computation leaves the trace (a special fibre). Raises
        :class:`Unlucky` when most points leave it (the trace was learnt at a special point)."""
        cs = self.coefficients(a % self.p, b % self.p)
        basis = None
        if cs is not None:
            try:
                basis = replay(self.trace, cs, self.p)
            except TraceMismatch:
                pass
        if basis is None or len(basis) != len(self.tails):
            self.misses += 1
            if self.misses > 20 + self.hits:
                raise Unlucky(f"the trace learnt modulo {self.p} is not the generic fibre's")
            return None
        self.hits += 1
        return self._matrices(basis)

    def regular_at(self, a: int, b: int, D: int) -> bool:
        """Whether the fibre at (a, b) is ``D`` distinct points (a fresh F4, no trace): then the
        real solutions are simple there and none escapes; False on a discriminant curve."""
        point = ModFibres.__new__(ModFibres)
        point.__dict__.update(self.__dict__)
        cs = self.coefficients(a % self.p, b % self.p, strict=False)
        rows = []
        for ms, c in zip(self.shapes, cs):
            kept = [(m, x) for m, x in zip(ms, c) if x]
            if kept:
                rows.append(([m for m, _ in kept], [x for _, x in kept]))
        try:
            basis = F4(rows, self.packing, self.p).run()
        except PackingOverflow:
            return False  # not the generic fibre
        point._structure([ms for ms, _ in basis], len(basis) == 1 and basis[0][0] == [0])
        if point.dim != D:
            return False
        form = [self.rnd.randrange(1, self.p) for _ in range(self.n)]
        point.forms = [form]
        cp = nmod_poly(point._charpoly(point._matrices([cs2 for _, cs2 in basis])[0]), self.p)
        return cp.gcd(cp.derivative()).degree() == 0

    def _matrices(self, basis: list[list[int]]) -> list[list[list[int]]]:
        """The forms' multiplication matrices, as columns."""
        p, D = self.p, self.dim
        vecs = [[int(k == l) for l in range(D)] for k in range(D)]  # by id: standard monomials first
        for src, targets in self.recipe:
            v = [0] * D
            if targets is None:
                for slot, c in zip(self.tails[src], basis[src][1:]):
                    v[slot] = -c % p
            else:
                for c, t in zip(vecs[src], targets):
                    if c:
                        w = vecs[t]
                        v = [x + c * y for x, y in zip(v, w)]
                v = [x % p for x in v]
            vecs.append(v)
        out = []
        for form in self.forms:
            cols = [[0] * D for _ in range(D)]
            for c, targets in zip(form, self.products):
                if c:
                    for k, t in enumerate(targets):
                        cols[k] = [x + c * y for x, y in zip(cols[k], vecs[t])]
            out.append(cols)
        return out

    def _charpoly(self, cols: list[list[int]]) -> list[int]:
        D = self.dim
        m = nmod_mat(D, D, [cols[k][l] % self.p for l in range(D) for k in range(D)], self.p)
        return [int(c) for c in m.charpoly().coeffs()]


class _Degree:
    """A generator's total degree, for :func:`mech.kernel.f4.initial_degree`."""

    def __init__(self, d: int) -> None:
        self.d = d

    def total_degree(self) -> int:
        return self.d


def _shift(e: Exp, i: int, k: int = 1) -> Exp:
    return e[:i] + (e[i] + k,) + e[i + 1:]
