"""FGLM: the reduced Gröbner basis of a zero-dimensional ideal in any global ordering from its
basis in another one (Faugère, Gianni, Lazard, Mora, J. Symb. Comput. 16, 1993).

``K[x]/I`` has the standard monomials ``B`` of the known basis ``G`` as a ``K``-basis
(``D = |B|``).  The normal forms of the *border* ``{x_i b : b in B} \\ B`` give the
multiplication matrices.  Then the monomials are visited in increasing target order, each one
``x_i m`` with ``m`` a new standard monomial: its normal form is ``M_i NF(m)`` (or read off
directly for ``B`` and the border), and it is reduced against the normal forms of the new
standard monomials so far.  A dependent monomial gives an element of the new basis (tail: the
dependency, on new standard monomials only, so the basis comes out reduced); an independent one
is a new standard monomial.  Whether a visited monomial lies in the new leading ideal is read
off its quotients by the variables (visited before it), not tested against every leading
monomial.

With the compiled module ``_fglm`` (kernel/_fglm.c) and a reduced ``G``, the border's
:class:`Border` plan -- which monomial each column ``x_a B[j]`` is; the normal form of each
border monomial, in increasing order, as minus a basis element's tail or as ``x_i`` times an
earlier border monomial's form -- is found once and depends on the monomials only; C fills the
matrices from it at each prime and walks the whole new staircase (:func:`_walked`), and at
further primes repeats the first walk's steps without the walk (:func:`replay`).  Otherwise
the border normal forms come out of one F4 matrix (:meth:`.f4.F4._matrix`: each border
monomial's row ``u g`` reduced by back substitution, its reduced tail minus its normal form) and
the walk runs in Python, its steps in C on dense arrays (:class:`_Compiled`) or on vectors
packed modulo ``p`` as in :mod:`.f4_vectors` (:class:`_Packed`: slot ``j < D`` holds the
coefficient of ``B[j]``; slot ``D + k`` records how a row combines the normal forms of the new
standard monomials, so a dependency is read off when the low slots vanish).

Over QQ the conversion runs modulo primes.  From a source basis of small coefficients
(:data:`LIFT_HEIGHT`) the conversions are lifted by Chinese remaindering and rational
reconstruction and the lift is proved (:func:`_proved`: its elements reduce to 0 by the source
basis exactly -- in C on 64-bit integers while they fit, kernel/_fglm_proof.c -- so they lie in
``I``, and its leading monomials leave ``D`` standard monomials, so they generate ``lt(I)``).
Otherwise, or when that fails, the conversion found modulo a prime is redone over QQ
(:func:`_exact`): the border normal forms exactly, the normal forms of the new standard and
leading monomials by the multiplication matrices, one linear solve for the tails.
"""
from __future__ import annotations

import heapq
from array import array
from dataclasses import dataclass
from itertools import chain
from operator import mul
from typing import Any, Sequence

import flint

from .errors import NotSupported
from .f4 import F4, PackingOverflow
from .f4_rows import compiled
from .f4_vectors import Vectors, support
from .fglm_solve import solve_qq
from .monomials import Packing, nonnegative_matrix
from .order import Exp, MonomialOrder

try:
    from ._fglm import fglm_matrices as MATRICES, fglm_plan as PLAN, fglm_reduces as REDUCES, fglm_replay as REPLAY
    from ._fglm import fglm_step as STEP, fglm_walk as WALK
except ImportError:  # no compiler at install (or a module built before these): the packed Python integers
    MATRICES = PLAN = REDUCES = REPLAY = STEP = WALK = None


@dataclass
class Conversion:
    """An FGLM result: element ``i`` of the new basis is ``lms[i] + sum tails[i][k] stairs[k]``
    (``stairs``: the new standard monomials).  ``stair_from[k]`` and ``lm_from[i]`` say how
    the monomial was reached: ``(j, k)`` for ``x_j stairs[k]`` (``(-1, -1)`` for 1)."""

    lms: list[Exp]
    tails: list[list[Any]]
    stairs: list[Exp]
    stair_from: list[tuple[int, int]]
    lm_from: list[tuple[int, int]]
    steps: array | None = None
    """With the compiled steps: ``(mode, a, b, leading)`` of each visit, for :func:`replay`."""


class NotZeroDimensional(NotSupported):
    """FGLM needs a zero-dimensional ideal."""


class Unlucky(Exception):
    """The basis modulo this prime does not behave as over QQ (drop the prime)."""


def staircase(lms: Sequence[Exp], nvars: int) -> list[Exp]:
    """The standard monomials of a zero-dimensional leading ideal (:class:`NotZeroDimensional`
    otherwise; ``[]`` for the unit ideal), in no particular order.  Grown from 1 by the
    variables: a monomial is in the leading ideal ``L`` iff it is a leading monomial or one of
    its quotients by a variable is in ``L``, so ``t`` is standard iff it is no leading
    monomial and all its quotients ``t / x_j`` are standard (already found)."""
    lmset = set(lms)
    if (0,) * nvars in lmset:
        return []
    pure = {next(i for i, a in enumerate(e) if a) for e in lmset if sum(1 for a in e if a) == 1}
    if len(pure) < nvars:
        raise NotZeroDimensional("FGLM needs a zero-dimensional ideal")
    one = (0,) * nvars
    w, unit = _digits(lms, nvars, 2)
    leads = {_packed(e, unit) for e in lmset}
    out, packs = [one], [0]
    std = {0}
    for b, x in zip(out, packs):  # both grow while they are read
        lower = [x - unit[j] for j in range(nvars) if b[j]]  # b / x_j: t / x_j = x_i (b / x_j)
        for i in range(nvars):
            ui = unit[i]
            t = x + ui
            if t in std or t in leads:
                continue
            for y in lower:
                if y + ui not in std:
                    break
            else:
                std.add(t)
                packs.append(t)
                out.append(b[:i] + (b[i] + 1,) + b[i + 1:])
    return out


def _digits(monomials: Sequence[Exp], nvars: int, room: int) -> tuple[int, list[int]]:
    """Exponents as the base ``2^w`` digits of an integer (:func:`_packed`), with room for
    exponents up to ``room`` above those of ``monomials``: ``w`` and the variables' units."""
    w = (max(max(e) for e in monomials) + room + 1).bit_length()
    return w, [1 << (w * i) for i in range(nvars)]


def _packed(e: Exp, unit: list[int]) -> int:
    return sum(map(mul, e, unit))


def border_forms(basis: Sequence[dict[Exp, int]], order: MonomialOrder, B: list[Exp], p: int) -> dict[Exp, list[int]]:
    """``{t: NF(t) as a list over B}`` modulo ``p`` for the border ``t`` of the staircase
    ``B`` of a monic Gröbner basis (coefficients as ints mod p) for ``order``."""
    n = order.nvars
    Bset = set(B)
    border = {t for b in B for t in _multiples(b, n) if t not in Bset}
    key = order.key
    lms = [max(g, key=key) for g in basis]
    top = max(sum(e) for g in basis for e in g)
    maxdeg = 63
    while maxdeg < 4 * top + 2:
        maxdeg = 2 * maxdeg + 1
    while True:
        P = Packing(order, maxdeg)
        try:
            return _border(basis, lms, P, border, B, p)
        except PackingOverflow:
            maxdeg = 2 * maxdeg + 1


def _multiples(b: Exp, n: int):
    for i in range(n):
        t = list(b)
        t[i] += 1
        yield tuple(t)


def _border_pivots(P: Packing, packed_lms: list[int], border) -> dict[int, tuple[int, int]]:
    """Each border monomial (packed) as a multiple of a basis element's leading monomial:
    ``(index of the element, packed cofactor)``."""
    g = P.guard
    pivots = {}
    for t in border:
        x = P.pack(t)
        xg = x | g
        k = next(k for k, lm in enumerate(packed_lms) if (xg - lm) & g == g)
        pivots[x] = (k, x - packed_lms[k])
    return pivots


def _border(basis, lms, P: Packing, border, B, p) -> dict[Exp, list[int]]:
    eng = F4([], P, p)
    packed_lms = []
    for g in basis:
        items = sorted(((P.pack(e), c) for e, c in g.items()), reverse=True)
        eng._add([m for m, _ in items], [c for _, c in items], True)
        packed_lms.append(items[0][0])
    pivots = _border_pivots(P, packed_lms, border)
    border = list(border)
    want = [P.pack(t) for t in border]
    if compiled(p):
        _, nonpivot, (_, _, tails), _ = eng._matrix_compiled([], pivots, want)
    else:
        T, pivcols, nonpivot, *_ = eng._matrix([], pivots)
        where = {c: j for j, c in enumerate(pivcols)}
        tails = [support(eng.vec, T[where[x]], len(nonpivot)) for x in want]
    index = {P.pack(b): j for j, b in enumerate(B)}
    slot_to_b = [index[x] for x in nonpivot]  # non-pivot monomials are standard
    D = len(B)
    out = {}
    for t, (slots, vals) in zip(border, tails):
        nf = [0] * D
        for s, v in zip(slots, vals):
            nf[slot_to_b[s]] = p - v
        out[t] = nf
    return out


def fglm_modp(basis: Sequence[dict[Exp, int]], source: MonomialOrder, target: MonomialOrder, p: int,
              B: list[Exp] | None = None, structure: Border | None = None) -> Conversion:
    """The reduced basis for ``target`` of the ideal with the monic Gröbner basis ``basis``
    (for ``source``, coefficients as ints mod ``p``; ``B``: its standard monomials in increasing
    ``source`` order and ``structure`` its :class:`Border`, if known already)."""
    n = source.nvars
    key = source.key
    if B is None:
        B = sorted(staircase([max(g, key=key) for g in basis], n), key=key)
    D = len(B)
    if not D:
        return Conversion([(0,) * n], [[]], [], [], [])
    index = {b: j for j, b in enumerate(B)}
    if STEP is not None and p < LIMIT and (n + 3) * D * D <= COMPILED_ENTRIES:
        if structure is None:
            structure = Border.of(basis, source, B)
        if structure is not None:
            M = structure.matrices(basis, p)
            if WALK is not None and n * structure.w <= 64 and _small_weights(target, D):
                return _walked(structure, M, target, p)
            lin = _Compiled(p, index, structure.where, M)
        else:  # a basis that is not reduced
            border = border_forms(basis, source, B, p)
            lin = _Compiled(p, index, _where(border, B, n), _dense(border, B, index, n))
    else:
        lin = _Packed(p, B, index, border_forms(basis, source, B, p), n)
    tkey = target.key
    one = (0,) * n
    w, unit = _digits([(D,) * n], n, 0)  # a visited monomial has no exponent above D
    out = Conversion([], [], [], [], [], getattr(lin, "steps", None))
    heap = [(tkey(one), 0, one, -1, -1)]  # (key, packed monomial, monomial, i, k): x_i * stairs[k]
    seen = {0}
    # monomials visited and found in the new leading ideal; each visited t = x_i s (s standard)
    # has its other quotients t / x_j = x_i (s / x_j) visited before it (smaller, pushed when
    # the standard s / x_j was found), so t is in the ideal iff one of them is
    inside: set[int] = set()
    while heap:
        _, x, t, i, k = heapq.heappop(heap)
        if any(t[j] and x - unit[j] in inside for j in range(n) if j != i):
            inside.add(x)
            continue
        K = len(out.stairs)
        tail = lin.visit(t, i, k, K)
        if tail is not None:
            inside.add(x)
            out.lms.append(t)
            out.lm_from.append((i, k))
            out.tails.append(tail + [0] * (D - K))
            continue
        out.stairs.append(t)
        out.stair_from.append((i, k))
        for j in range(n):
            y = x + unit[j]
            if y not in seen:
                seen.add(y)
                u = t[:j] + (t[j] + 1,) + t[j + 1:]
                heapq.heappush(heap, (tkey(u), y, u, j, K))
    if len(out.stairs) != D:
        raise Unlucky("the new staircase has the wrong size")
    return out


def replay(first: Conversion, basis: Sequence[dict[Exp, int]], structure: Border, p: int) -> Conversion | None:
    """The conversion ``first`` (made with the compiled steps) at another prime ``p``: the same
    visits in the same order, only the linear algebra redone (``fglm_replay`` of
    kernel/_fglm.c); None if a visit turns out otherwise (one of the two primes is unlucky)."""
    D = len(structure.B)
    tails = array("I", bytes(4 * D * len(first.lms)))
    if not REPLAY(p, D, structure.matrices(basis, p), first.steps, tails):
        return None
    return Conversion(first.lms, [tails[D * i:D * (i + 1)].tolist() for i in range(len(first.lms))],
                      first.stairs, first.stair_from, first.lm_from, first.steps)


def _walked(structure: Border, M: array, target: MonomialOrder, p: int) -> Conversion:
    """:func:`fglm_modp`'s visits all in C (``fglm_walk`` of kernel/_fglm.c, the same steps in
    the same order) on monomials packed as :attr:`Border.w`-bit digits, the target ordering as
    its nonnegative weight matrix."""
    B, n, w = structure.B, structure.n, structure.w
    D = len(B)
    steps = array("i", bytes(16 * (n * (D + 1) + 1)))  # 4 entries a visit
    W = array("q", [v for row in nonnegative_matrix(target) for v in row])
    got = WALK(p, D, n, w, W, M, structure.code_keys, structure.code_values, steps)
    if got is None or len(got[0]) != D:
        raise Unlucky("the new staircase has the wrong size")
    stairs, stair_from, lms, lm_from, tails, visits = got
    tails = array("I", tails)
    mask = (1 << w) - 1
    shifts = [w * i for i in range(n)]
    return Conversion([tuple((x >> s) & mask for s in shifts) for x in lms],
                      [tails[D * r:D * (r + 1)].tolist() for r in range(len(lms))],
                      [tuple((x >> s) & mask for s in shifts) for x in stairs],
                      list(zip(stair_from[::2], stair_from[1::2])), list(zip(lm_from[::2], lm_from[1::2])),
                      steps[:4 * visits])


def _small_weights(order: MonomialOrder, D: int) -> bool:
    """Whether the keys ``W e`` of monomials of degree at most ``n D`` fit 63 bits."""
    return max(max(row) for row in nonnegative_matrix(order)) * order.nvars * (D + 1) < 1 << 62


class Border:
    """The part of the multiplication matrices of ``K[x]/I`` that is the same at every prime, from
    a reduced Gröbner basis of ``I`` with the standard monomials ``B``: which monomial each
    column ``x_a B[j]`` is, and how the normal form of each border monomial (in increasing
    order) follows from earlier ones -- minus a basis element's tail for its leading monomial,
    else ``x_i`` times an earlier border monomial's form (see ``fglm_matrices`` in
    kernel/_fglm.c).  :meth:`matrices` fills in the numbers at a prime.  Monomials are packed as
    digits of :attr:`w` bits (room for the exponents up to ``D`` a conversion visits);
    :attr:`code_keys` and :attr:`code_values` say which packed monomial is ``B[j]`` (``j``) or
    ``x_a B[j]`` on the border (``D + a D + j``)."""

    def __init__(self, B: list[Exp], n: int, w: int, cols: array, plan: array, tidx: array,
                 terms: list[tuple[int, Exp]], code_keys: array, code_values: array) -> None:
        self.B, self.n, self.w, self.cols, self.plan, self.tidx, self.terms = B, n, w, cols, plan, tidx, terms
        self.code_keys, self.code_values = code_keys, code_values

    @property
    def where(self) -> dict[Exp, tuple[int, int]]:
        """Each border monomial as ``x_a B[j]`` (the first reached)."""
        D = len(self.B)
        pairs = [divmod(c - D, D) for c in self.code_values[D:]]
        return {_times(self.B[j], a): (a, j) for a, j in pairs}

    @classmethod
    def of(cls, basis: Sequence[dict[Exp, Any]], order: MonomialOrder, B: list[Exp]) -> Border | None:
        """The structure for ``basis`` (``fglm_plan`` of kernel/_fglm.c; None if the basis is not
        reduced or its monomials do not pack into 64 bits)."""
        n, D = order.nvars, len(B)
        w = (D + 1).bit_length()  # a conversion visits exponents up to D
        if n * w > 64:
            return None
        W = array("q", [v for row in nonnegative_matrix(order) for v in row])
        offsets = array("q", [0])
        for g in basis:
            offsets.append(offsets[-1] + len(g))
        got = PLAN(n, w, W, array("i", [a for b in B for a in b]), array("i", [a for g in basis for e in g for a in e]),
                   offsets)
        if got is None:
            return None
        cols, plan, tidx, tsrc, code_keys, code_values = got
        flat = [(k, e) for k, g in enumerate(basis) for e in g]
        tsrc = array("i", tsrc)
        return cls(B, n, w, array("i", cols), array("i", plan), array("i", tidx), [flat[t] for t in tsrc],
                   array("Q", code_keys), array("q", code_values))

    def matrices(self, basis: Sequence[dict[Exp, int]], p: int) -> array:
        """The multiplication matrices modulo ``p`` (the layout of :class:`_Compiled`) for this
        structure's basis with coefficients ``basis`` (monic, ints mod ``p``, same elements in
        the same positions, terms missing counted as 0)."""
        vals = array("I", [(p - basis[k].get(e, 0)) % p for k, e in self.terms])
        D, n = len(self.B), self.n
        M = array("I", bytes(4 * n * D * D))
        MATRICES(p, D, n, self.cols, self.plan, self.tidx, vals, M)
        return M


def _where(border: dict[Exp, list[int]], B: list[Exp], n: int) -> dict[Exp, tuple[int, int]]:
    """Each border monomial as ``x_a B[j]`` (the first reached)."""
    where: dict[Exp, tuple[int, int]] = {}
    for a in range(n):
        for j, b in enumerate(B):
            u = _times(b, a)
            if u in border:
                where.setdefault(u, (a, j))
    return where


def _dense(border: dict[Exp, list[int]], B: list[Exp], index: dict[Exp, int], n: int) -> array:
    """The multiplication matrices in :class:`_Compiled`'s layout from the border normal forms."""
    D = len(B)
    M = array("I")
    unit = [0] * D
    for a in range(n):
        for b in B:
            u = _times(b, a)
            r = index.get(u)
            if r is None:
                M.extend(border[u])
            else:
                unit[r] = 1
                M.extend(unit)
                unit[r] = 0
    return M


LIMIT = 1 << 31
"""Primes below this go to the compiled steps (products of two entries fit 62 bits)."""

COMPILED_ENTRIES = 1 << 23
"""FGLM modulo ``p`` runs its linear algebra in the compiled kernel (kernel/_fglm.c) when its
dense arrays (the ``n`` multiplication matrices and the rows, ``(n + 3) D^2`` entries of 4
bytes) stay within this many entries; otherwise on packed Python integers."""


class _Packed:
    """FGLM's linear algebra on vectors packed into Python integers (:mod:`.f4_vectors`):
    :meth:`visit` forms the normal form of a monomial and reduces it by the rows so far."""

    def __init__(self, p: int, B: list[Exp], index: dict[Exp, int], border: dict[Exp, list[int]], n: int) -> None:
        self.p, self.B, self.index, self.D = p, B, index, len(B)
        self.vec = vec = Vectors(p)
        self.w = vec.slot
        self.mask = (1 << self.w) - 1
        self.low = (1 << (self.w * self.D)) - 1
        self.norm = vec.normalizer(2 * self.D + 1)
        self.border = {t: _pack(vec, nf) for t, nf in border.items()}
        self.nfs: list[int] = []  # NF of each new standard monomial (low slots)
        self.piv: list[tuple[int, int]] = []  # (pivot slot, row) semi-echelon rows with their combinations

    def column(self, t: Exp) -> int:
        j = self.index.get(t)
        return 1 << (self.w * j) if j is not None else self.border[t]

    def visit(self, t: Exp, i: int, k: int, K: int) -> list[int] | None:
        """``t = x_i * stairs[k]`` (``k < 0``: ``t = 1``), ``K`` new standard monomials so far:
        the tail over them if ``t`` is a new leading monomial, else None (``t`` is standard)."""
        p, w, mask, D, norm = self.p, self.w, self.mask, self.D, self.norm
        if k < 0 or t in self.index or t in self.border:
            v = self.column(t)
        else:
            src = self.nfs[k]
            terms = []
            for j in range(D):
                c = (src >> (w * j)) & mask
                if c:
                    terms.append((c, self.column(_times(self.B[j], i))))
            v = self.vec.add_multiples(0, terms, D)
        x = v | (1 << (w * (D + K)))
        count, hmax = 0, self.vec.hmax
        for s, y in self.piv:
            c = ((x >> (w * s)) & mask) % p
            if c:
                x += (p - c) * y
                count += 1
                if count == hmax:
                    x, count = norm(x), 0
        x = norm(x)
        if not x & self.low:
            return [(x >> (w * (D + j))) & mask for j in range(K)]
        s0 = ((x & self.low).bit_length() - 1) // w
        c = (x >> (w * s0)) & mask
        if c != 1:
            x = norm(x * pow(c, -1, p))
        self.piv.append((s0, x))
        self.nfs.append(v)
        return None


class _Compiled:
    """:class:`_Packed`'s operations in the compiled kernel (``fglm_step`` of kernel/_fglm.c) on
    dense arrays: the multiplication matrices ``M``, the new standard monomials' normal forms,
    the rows and their pivots; each visit is recorded in :attr:`steps`."""

    def __init__(self, p: int, index: dict[Exp, int], where: dict[Exp, tuple[int, int]], M: array) -> None:
        D = self.D = len(index)
        self.p, self.index, self.where, self.M = p, index, where, M
        self.nfs = array("I", bytes(4 * D * (D + 1)))
        self.piv = array("I", bytes(4 * (2 * D + 1) * (D + 1)))
        self.slot = array("i", bytes(4 * (D + 1)))
        self.steps = array("i")

    def visit(self, t: Exp, i: int, k: int, K: int) -> list[int] | None:
        """As :meth:`_Packed.visit`."""
        j = self.index.get(t)
        if j is not None:
            mode, a, b = 0, j, 0
        elif t in self.where:
            mode, (a, b) = 1, self.where[t]
        else:
            mode, a, b = 2, i, k
        tail = STEP(self.p, self.D, K, self.M, self.nfs, self.piv, self.slot, mode, a, b)
        self.steps.extend((mode, a, b, tail is not None))
        return tail


def _times(e: Exp, i: int) -> Exp:
    t = list(e)
    t[i] += 1
    return tuple(t)


def _pack(vec: Vectors, vals: list[int]) -> int:
    w = vec.slot
    return sum(v << (w * j) for j, v in enumerate(vals) if v)


def as_dicts(conv: Conversion, one: Any) -> list[dict[Exp, Any]]:
    """The basis elements as ``{exponent: coefficient}`` dicts, leading monomial first."""
    out = []
    for lm, tail in zip(conv.lms, conv.tails):
        d = {lm: one}
        for s, c in zip(conv.stairs, tail):
            if c:
                d[s] = c
        out.append(d)
    return out


def fglm_zp(basis: Sequence[dict[Exp, Any]], source: MonomialOrder, target: MonomialOrder, p: int,
            leads: Sequence[Exp] | None = None) -> list[dict]:
    """The reduced basis for ``target`` over Z/p (``nmod`` coefficients), increasing leading
    monomials, from a reduced basis for ``source`` (``leads``: its leading exponents, if known)."""
    key = source.key
    B = sorted(staircase(leads if leads is not None else [max(g, key=key) for g in basis], source.nvars), key=key)
    conv = fglm_modp([{e: int(c) for e, c in g.items()} for g in basis], source, target, p, B)
    one = flint.nmod(1, p)
    return [{lm: one, **{s: flint.nmod(c, p) for s, c in zip(conv.stairs, tail) if c}}
            for lm, tail in zip(conv.lms, conv.tails)]


# --- over QQ -------------------------------------------------------------------------------

def _mod(basis: Sequence[dict[Exp, Any]], p: int) -> list[dict[Exp, int]] | None:
    """A basis over QQ modulo ``p`` (None if ``p`` divides a denominator)."""
    out = []
    for g in basis:
        h = {}
        for e, c in g.items():
            d = int(c.q) % p
            if not d:
                return None
            h[e] = int(c.p) * pow(d, -1, p) % p if d != 1 else int(c.p) % p
        out.append(h)
    return out


LIFT_HEIGHT = 16
"""Over QQ, when the source basis has coefficients of at most this many bits, the conversions
modulo primes are first lifted by rational reconstruction (from at most :data:`LIFT_PRIMES`
primes) and proved (:func:`_proved`); otherwise, past those primes, or when a lift fails its
proof, the exact conversion (:func:`_exact`) takes over.  Measured (session 13): cyclic-5 in
``lp``, a source of 8 bits, 70 standard monomials, a target of 18 bits: two conversions modulo p
2.7 ms each and the proof 2 ms, against the exact conversion's 11 ms more (its border normal
forms 5 ms, its linear algebra 6 ms): 15.8 -> 10.9 ms (session 14, compiled: the first
conversion 0.3 ms, the replay 0.2, the proof 0.75; the lifted path 3 ms).  katsura-4/5 (sources of 32 and 61
bits, targets of 251 and 1411 bits) and katsura-6 in (dp(3),dp(4)) (115 bits) lost 4-40 ms
to four primes that did not lift."""

LIFT_PRIMES = 3
"""See :data:`LIFT_HEIGHT`."""


def fglm_qq(basis: Sequence[dict[Exp, Any]], source: MonomialOrder, target: MonomialOrder,
            leads: Sequence[Exp] | None = None) -> list[dict]:
    """The reduced basis for ``target`` over QQ (``fmpq`` coefficients), increasing leading
    monomials, of the zero-dimensional ideal with the reduced basis ``basis`` for ``source``
    (``leads``: its leading exponents, if known; see the module docstring): lifted from primes
    and proved, else converted exactly."""
    from .modular import ModularFailure
    n = source.nvars
    key = source.key
    if leads is None:
        leads = [max(g, key=key) for g in basis]
    basis = [{lm: g[lm], **g} for lm, g in zip(leads, basis)]  # leading exponent first
    B = sorted(staircase([next(iter(g)) for g in basis], n), key=key)
    if not B:
        return [{(0,) * n: flint.fmpq(1)}]
    runs = _conversions(basis, source, target, B)
    done: list[Conversion] = []
    if max(c.height_bits() for g in basis for c in g.values()) <= LIFT_HEIGHT:
        out = _lifted(runs, done, basis, source, target, B)
        if out is not None:
            return out
    border = border_forms_qq(basis, source, B)
    for conv in chain(done, (c for _, c in runs)):  # the lift's conversions, then further primes
        out = _exact(conv, border, B, target)
        if out is not None:
            return out
    raise ModularFailure("FGLM: five unlucky primes in a row")


def _conversions(basis: Sequence[dict[Exp, Any]], source: MonomialOrder, target: MonomialOrder, B: list[Exp]):
    """``(p, conversion modulo p)`` at successive primes, the unlucky ones skipped, within five
    primes that divide no denominator.  The border's structure is found once; after the first
    conversion with the compiled steps the others replay its visits (:func:`replay`), in full
    again where a visit turns out otherwise."""
    from .modular import primes
    structure = Border.of(basis, source, B) if STEP is not None else None
    first = None
    tried = 0
    for p in primes(20240917):
        mod = _mod(basis, p)
        if mod is None:
            continue
        tried += 1
        if tried > 5:
            return
        conv = replay(first, mod, structure, p) if first is not None and p < LIMIT else None
        if conv is None:
            try:
                conv = fglm_modp(mod, source, target, p, B, structure)
            except Unlucky:
                continue
        if first is None and conv.steps is not None and structure is not None:
            first = conv
        yield p, conv


def _lifted(runs, done: list[Conversion], basis: Sequence[dict[Exp, Any]], source: MonomialOrder,
            target: MonomialOrder, B: list[Exp]) -> list[dict] | None:
    """The basis lifted from the conversions ``runs`` (at most :data:`LIFT_PRIMES`, each kept in
    ``done``) by Chinese remaindering and rational reconstruction, once :func:`_proved`; None
    when the primes run out, a prime gives another shape, or a lift fails its proof.  A lift is
    tried once its coefficients lie far below the reconstruction's bound
    (:meth:`.modular.Reconstructor.confident`: almost every residue has some small fraction, so
    a lift from too few primes would mostly be wrong and cost a failed proof)."""
    from .modular import Lifter, Reconstructor
    lifter = Lifter()
    for p, conv in runs:
        done.append(conv)
        first = done[0]
        if conv.lms != first.lms or conv.stairs != first.stairs:
            return None
        lifter.add(conv.tails, p)
        rec = Reconstructor([len(tail) for tail in conv.tails])  # afresh: no coefficients from fewer primes
        tails = rec.attempt(lifter.values, lifter.m)
        if tails is not None and rec.confident():
            out = as_dicts(Conversion(first.lms, tails, first.stairs, [], []), flint.fmpq(1))
            return out if _proved(out, basis, source, target, B) else None
        if len(done) >= LIFT_PRIMES:
            return None
    return None


def _proved(candidate: list[dict[Exp, Any]], basis: Sequence[dict[Exp, Any]], source: MonomialOrder,
            target: MonomialOrder, B: list[Exp]) -> bool:
    """Whether ``candidate`` (leading exponent first in each dict) is the reduced basis for
    ``target`` of the ideal ``I`` with the Gröbner basis ``basis`` (leading exponent first) for
    ``source`` and the standard monomials ``B``.  A proof: every element reduces to 0 by
    ``basis`` exactly, so ``candidate`` lies in ``I`` and its leading monomials generate an ideal
    inside ``lt(I)``; both have ``|B| = dim K[x]/I`` standard monomials, so they are equal and
    ``candidate`` is a Gröbner basis of ``I``; reduced as its leading monomials are minimal, its
    elements monic and their other monomials standard and below the leading one."""
    from .hilbert_compiled import reduce_to_zero
    n = target.nvars
    tkey = target.key
    lms = [next(iter(g)) for g in candidate]
    try:
        stairs = staircase(lms, n)
    except NotZeroDimensional:
        return False
    if len(stairs) != len(B) or any(len(set(lms)) != len(lms) or
                                    any(a != b and all(x <= y for x, y in zip(a, b)) for a in lms) for b in lms):
        return False
    std = set(stairs)
    for g, lm in zip(candidate, lms):
        top = tkey(lm)
        if g[lm] != 1 or any(e != lm and (e not in std or tkey(e) > top) for e in g):
            return False
    got = _reduces_compiled(basis, candidate, source)
    return reduce_to_zero(list(basis), candidate, source) if got is None else got


def _reduces_compiled(basis: Sequence[dict[Exp, Any]], polys: Sequence[dict[Exp, Any]],
                      order: MonomialOrder) -> bool | None:
    """:func:`.hilbert_compiled.reduce_to_zero` in C on 64-bit integers (``fglm_reduces`` of
    kernel/_fglm_proof.c, the same fraction-free steps); None without the extension or when a
    number leaves 64 bits (then Python's integers decide)."""
    if REDUCES is None:
        return None
    flat = []
    for group in (basis, polys):
        offsets = array("q", [0])
        for f in group:
            offsets.append(offsets[-1] + len(f))
        coefs = [c for f in group for c in f.values()]
        try:
            nums, dens = array("q", [int(c.p) for c in coefs]), array("q", [int(c.q) for c in coefs])
        except OverflowError:
            return None
        flat += [offsets, array("i", [a for f in group for e in f for a in e]), nums, dens]
    W = array("q", [v for row in nonnegative_matrix(order) for v in row])
    got = REDUCES(order.nvars, W, *flat)
    return None if got < 0 else bool(got)


def border_forms_qq(basis: Sequence[dict[Exp, Any]], order: MonomialOrder, B: list[Exp]) -> dict[Exp, list]:
    """:func:`border_forms` over QQ, exactly: the same F4 matrix (its structure from the mod
    p machinery), back substitution with rational vectors."""
    n = order.nvars
    Bset = set(B)
    border = {t for b in B for t in _multiples(b, n) if t not in Bset}
    top = max(sum(e) for g in basis for e in g)
    maxdeg = 63
    while maxdeg < 4 * top + 2:
        maxdeg = 2 * maxdeg + 1
    while True:
        P = Packing(order, maxdeg)
        try:
            return _border_qq(basis, P, border, B)
        except PackingOverflow:
            maxdeg = 2 * maxdeg + 1


def _border_qq(basis, P: Packing, border, B) -> dict[Exp, list]:
    eng = F4([], P, 2)
    coefs, packed_lms = [], []
    for g in basis:
        items = sorted(((P.pack(e), c) for e, c in g.items()), reverse=True)
        eng._add([m for m, _ in items], [0] * len(items), True)
        coefs.append([c for _, c in items])
        packed_lms.append(items[0][0])
    pivots = _border_pivots(P, packed_lms, border)
    rowmons, nonpivot = eng._symbolic([], pivots)
    nonpivot.sort()
    m = len(nonpivot)
    slot = {x: s for s, x in enumerate(nonpivot)}
    zero = flint.fmpq(0)
    T: dict[int, flint.fmpq_mat] = {}
    for col in sorted(pivots):
        k, u = pivots[col]
        rm, cs = rowmons[(k, u)], coefs[k]
        vals = [zero] * m
        acc = None
        for x, c in zip(rm[1:], cs[1:]):
            s = slot.get(x)
            if s is not None:
                vals[s] = c
            else:
                term = T[x] * c
                acc = term if acc is None else acc + term
        row = flint.fmpq_mat(1, m, vals)
        T[col] = row - acc if acc is not None else row
    index = {P.pack(b): j for j, b in enumerate(B)}
    to_b = [index[x] for x in nonpivot]
    D = len(B)
    out = {}
    for t in border:
        nf = [zero] * D
        for s, v in enumerate(T[P.pack(t)].entries()):
            if v:
                nf[to_b[s]] = -v
        out[t] = nf
    return out


def _exact(conv: Conversion, border: dict[Exp, list[Any]], B: list[Exp], target: MonomialOrder) -> list[dict] | None:
    """The conversion ``conv`` (found modulo a prime) redone over QQ with the exact border
    normal forms: the normal forms of the new standard monomials and leading monomials by
    the multiplication matrices, then one linear solve for the tails.  None if the prime was
    unlucky (the new standard monomials are dependent over QQ, or a tail has a monomial above
    its leading one)."""
    D = len(B)
    index = {b: j for j, b in enumerate(B)}
    one = flint.fmpq(1)
    Vec = tuple[flint.fmpz_mat, flint.fmpz]  # a vector over QQ: integer numerators, one denominator
    known: dict[Exp, Vec] = {}

    def column(t: Exp) -> Vec:
        v = known.get(t)
        if v is None:
            j = index.get(t)
            if j is not None:
                u = flint.fmpz_mat(D, 1)
                u[j, 0] = 1
                v = u, flint.fmpz(1)
            else:
                v = flint.fmpq_mat(D, 1, border[t]).numer_denom()
            known[t] = v
        return v

    mats: dict[int, Vec] = {}

    def mult(i: int) -> Vec:
        m = mats.get(i)
        if m is None:  # the columns over their common denominator, as rows, transposed
            cols = [column(_times(b, i)) for b in B]
            d = flint.fmpz(1)
            for _, dc in cols:
                if dc != 1:
                    d = d.lcm(dc)
            flat: list = []
            for v, dc in cols:
                flat.extend((v if dc == d else v * (d // dc)).entries())
            m = mats[i] = flint.fmpz_mat(D, D, flat).transpose(), d
        return m

    def vector(t: Exp, i: int, k: int) -> Vec:
        if k < 0 or t in index or t in border:
            return column(t)
        (M, dm), (v, dv) = mult(i), stairs[k]
        w, d = M * v, dm * dv
        g = d
        for x in w.entries():
            if g == 1:
                break
            g = g.gcd(x)
        return (w, d) if g == 1 else (w / g, d // g)

    stairs: list[Vec] = []
    for t, (i, k) in zip(conv.stairs, conv.stair_from):
        stairs.append(vector(t, i, k))
    rhs = [vector(t, i, k) for t, (i, k) in zip(conv.lms, conv.lm_from)]
    cols = [v.entries() for v, _ in stairs]
    rcols = [v.entries() for v, _ in rhs]
    L = len(rhs)
    # V diag(1/dv) X = N diag(1/dn):  X = diag(dv) Z diag(1/dn) with Vn Z = Nn (integer matrices)
    V = flint.fmpq_mat(flint.fmpz_mat(D, D, [cols[c][r] for r in range(D) for c in range(D)]))
    N = flint.fmpq_mat(flint.fmpz_mat(D, L, [rcols[c][r] for r in range(D) for c in range(L)]))
    try:
        Z = solve_qq(V, N)  # multimodular, in the process
    except ZeroDivisionError:
        return None
    A = [[Z[k, c] * stairs[k][1] / rhs[c][1] for k in range(D)] for c in range(L)]
    tkey = target.key
    conv.tails = []
    for c, lm in enumerate(conv.lms):
        tail = [-a for a in A[c]]
        top = tkey(lm)
        if any(a and tkey(s) > top for a, s in zip(tail, conv.stairs)):
            return None
        conv.tails.append(tail)
    return as_dicts(conv, one)
