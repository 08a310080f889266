"""F4's critical pairs with the Gebauer–Möller update (Becker–Weispfenning's UPDATE).

A pair is ``(key, lcm, i, j)``: the key orders the selection (the weighted degree of the lcm
for graded orderings, else the sugar), the lcm is a packed monomial, ``i < j`` index basis
elements (``j = -1``: the input row ``i``, its lcm its leading monomial).  :func:`pair_set`
gives the compiled set (``kernel/_f4pairs.c``) when the extension is built, else
:class:`PairSet`; both do the same steps in the same order.
"""
from __future__ import annotations

from .monomials import Packing

try:
    from ._f4rows import Pairs as _Compiled
except ImportError:  # no compiler at install (or an extension built before the pairs): pure Python
    _Compiled = None


def pair_set(P: Packing, by_weight: bool):
    """An empty pair set for packing ``P``; ``by_weight``: keys are weighted degrees of lcms
    (else sugars)."""
    if _Compiled is not None and P.ebits <= 31:
        return _Compiled(P.nvars, P.ebits, tuple(P.units), P.first_weights, by_weight, P.maxdeg)
    return PairSet(P, by_weight)


class PairSet:
    """The pairs in pure Python, on the packed monomials' exponent fields (word-parallel)."""

    def __init__(self, P: Packing, by_weight: bool) -> None:
        self.P = P
        self.by_weight = by_weight
        self.leads: list[int] = []
        self.sugar: list[int] = []
        self.pairs: list[tuple[int, int, int, int]] = []

    def __len__(self) -> int:
        return len(self.pairs)

    def add(self, lead: int, sugar: int) -> None:
        """A new element (numbered in the order added) with its leading monomial and sugar."""
        self.leads.append(lead)
        self.sugar.append(sugar)

    def push(self, key: int, k: int) -> None:
        """The pair of input row ``k``."""
        self.pairs.append((key, self.leads[k], k, -1))

    def update(self, h: int, active: list[bool]) -> bool:
        """Add element ``h``: new pairs and pruned old ones; ``active`` (usable as reducers and
        in new pairs) updated.  False, with nothing changed, when an lcm exceeds the packing.
        The criteria compare lcms by their exponent fields only (no repacking)."""
        P = self.P
        g, eg, eall = P.guard, P.eguard, P.eall
        lcm_e = P.lcm_e
        leads = self.leads
        H = leads[h]
        He = H & eall
        Hg, shift, fill = He | eg, P.ebits - 1, (1 << P.ebits) - 1
        cands = []
        for i in range(h):
            if active[i]:
                ei = leads[i] & eall
                sel = (((Hg - ei) & eg) >> shift) * fill  # lcm_e inline: the fields where H >= l_i
                Le = (He & sel) | (ei & ~sel)
                cands.append((Le, i, Le == ei + He))
        # criterion M: drop (i,h) if another new pair's lcm properly divides its lcm;
        # criterion F: among equal lcms keep one, a coprime one if there is one.  In increasing
        # order of the exponent fields (lexicographic, so divisors come first) it suffices to
        # test the lcms kept so far.
        cands.sort()
        kept: dict[int, tuple] = {}
        for c in cands:
            Le = c[0]
            prev = kept.get(Le)
            if prev is not None:
                if c[2] and not prev[2]:
                    kept[Le] = c
                continue
            Lg = Le | eg
            for d in kept:
                if (Lg - d) & eg == eg:
                    break
            else:
                kept[Le] = c
        degree, sugar = P.degree, self.sugar
        dH, sh = degree(H), sugar[h]
        new = []
        for Le, i, coprime in kept.values():
            if coprime:
                continue
            li = leads[i]
            L = P.lcm(li, H)
            dL = degree(L)
            if dL > P.maxdeg:
                return False
            key = P.weighted_degree(L) if self.by_weight else max(sugar[i] + dL - degree(li), sh + dL - dH)
            new.append((key, L, i, h))
        # criterion B on the old pairs
        old = []
        for pr in self.pairs:
            s, L, i, j = pr
            if j >= 0 and ((L | g) - H) & g == g:
                Le = L & eall
                if lcm_e(leads[i], H) != Le and lcm_e(leads[j], H) != Le:
                    continue
            old.append(pr)
        self.pairs = old + new
        for i in range(h):
            if active[i] and ((leads[i] | g) - H) & g == g:
                active[i] = False
        active[h] = True
        return True

    def minimal(self, active: list[bool]) -> list[int]:
        """The active elements whose leading monomial no other active element's divides (of equal
        ones, the first), by increasing index."""
        g, leads = self.P.guard, self.leads
        on = [k for k in range(len(active)) if active[k]]
        out = []
        for k in on:
            xg = leads[k] | g
            if not any((xg - leads[j]) & g == g and (leads[j] != leads[k] or j < k) for j in on if j != k):
                out.append(k)
        return out

    def lowest(self) -> int | None:
        """The lowest key (None without pairs)."""
        return min(pr[0] for pr in self.pairs) if self.pairs else None

    def take(self) -> list[tuple[int, int, int, int]]:
        """The pairs of the lowest key, removed (in their order)."""
        d = self.lowest()
        sel = [pr for pr in self.pairs if pr[0] == d]
        self.pairs = [pr for pr in self.pairs if pr[0] != d]
        return sel

    def take_rows(self) -> tuple[int, dict[int, tuple[int, int]], list[tuple[int, int]]]:
        """The pairs of the lowest key ``d``, removed, as F4's rows: ``(d, pivots, rows)``
        (:func:`pair_rows`)."""
        sel = self.take()
        return (sel[0][0], *pair_rows(sel, self.leads))

    def drop(self, d: int) -> None:
        """Forget the pairs of key ``d``."""
        self.pairs = [pr for pr in self.pairs if pr[0] != d]

    def clear(self) -> None:
        self.pairs = []

    def everything(self) -> list[tuple[int, int, int, int]]:
        """All pairs (in their order)."""
        return list(self.pairs)


def pair_rows(sel: list[tuple[int, int, int, int]], leads: list[int]):
    """F4's rows of the pairs ``sel`` (elements with leading monomials ``leads``): per lcm one
    row becomes its reducer, the others are to be reduced; ``(k, u)`` stands for
    ``x^u * poly[k]``.  Returns ``pivots`` ({lcm: row}) and the rows to reduce, each row once."""
    pivots: dict[int, tuple[int, int]] = {}
    rows: list[tuple[int, int]] = []
    seen: set[tuple[int, int]] = set()
    for s, L, i, j in sel:
        for k in ((i,) if j < 0 else (i, j)):
            spec = (k, L - leads[k])
            if spec in seen:
                continue
            seen.add(spec)
            if j >= 0 and L not in pivots:
                pivots[L] = spec
            else:
                rows.append(spec)
    return pivots, rows
