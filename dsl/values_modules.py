"""Singular's ``vector`` and ``module`` values: elements and submodules of a free module R^n.

A :class:`Vector` holds its entries (component i is entry i-1; trailing zeros dropped: a Singular
vector has no fixed rank, ``nrows(v)`` is its highest nonzero component).  A :class:`Module` holds its
generators and its rank (the free module it lies in: at least every generator's highest component).
The terms of a vector are ordered by the ring's *module ordering*: the ordering's ``c``/``C`` block
says where the component is compared (first, between two blocks or last) and how (``C``: gen(2) >
gen(1); ``c``: gen(1) > gen(2)); a ring whose ordering begins with ``c`` prints vectors as ``[f1,f2,..]``
(Singular's VectorOut), others as ``f1*gen(1)+...`` by decreasing term.
"""
from __future__ import annotations

from typing import Any, Callable, Iterable, Optional, Sequence

from ..kernel import Poly, PolyRing
from ..kernel.order import MonomialOrder

Exp = tuple[int, ...]
Term = tuple[Exp, int]  # (exponent, component from 0): the kernel's vector terms (kernel.modules)


class Vector:
    """An element of R^n given by its entries (component 1 first)."""

    __slots__ = ("ring", "entries")
    type_name = "vector"

    def __init__(self, ring: PolyRing, entries: Iterable[Poly]) -> None:
        ents = list(entries)
        while ents and ents[-1].is_zero():
            ents.pop()
        self.ring = ring
        self.entries: tuple[Poly, ...] = tuple(ents)

    @property
    def nrows(self) -> int:
        return len(self.entries)

    def get(self, i: int) -> Poly:
        """Entry ``i`` (1-based; 0 beyond the last component)."""
        return self.entries[i - 1] if 1 <= i <= len(self.entries) else self.ring.zero()

    def is_zero(self) -> bool:
        return not self.entries

    def terms(self) -> dict[Term, Any]:
        """The kernel's form ``{(exp, comp): coeff}`` (components from 0)."""
        return {(e, i): c for i, p in enumerate(self.entries) for e, c in p.terms.items()}

    @classmethod
    def from_terms(cls, ring: PolyRing, terms: dict[Term, Any], rank: int = 0) -> "Vector":
        n = max([i + 1 for _, i in terms] + [rank])
        parts: list[dict[Exp, Any]] = [{} for _ in range(n)]
        for (e, i), c in terms.items():
            parts[i][e] = c
        return cls(ring, [Poly(ring, d) for d in parts])

    def padded(self, n: int) -> list[Poly]:
        """The first ``n`` entries (zeros beyond the last component)."""
        return [self.get(i) for i in range(1, n + 1)]

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Vector) and other.entries == self.entries

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return f"Vector({', '.join(p.to_str() for p in self.entries)})"


class Module:
    """A submodule of R^rank given by generators (at least one, possibly zero); ``is_std`` marks a
    standard basis, ``weights`` the components' degrees Singular's syz gives a homogeneous input's syzygies
    (its attribute isHomog; None: none)."""

    __slots__ = ("ring", "gens", "rank", "is_std", "weights")
    type_name = "module"

    def __init__(self, ring: PolyRing, gens: Iterable[Vector], rank: int = 0, is_std: bool = False,
                 weights: Optional[tuple[int, ...]] = None) -> None:
        self.ring = ring
        self.gens: tuple[Vector, ...] = tuple(gens) or (Vector(ring, ()),)
        self.rank = max([rank, 1] + [g.nrows for g in self.gens])
        self.is_std = is_std
        self.weights = weights

    def nonzero(self) -> list[Vector]:
        return [g for g in self.gens if not g.is_zero()]

    def __len__(self) -> int:
        return len(self.gens)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Module) and other.gens == self.gens and other.rank == self.rank

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return f"Module(rank {self.rank}, {len(self.gens)} generators)"


# ---------------------------------------------------------------- the module ordering
_COMPONENT: dict[int, tuple[PolyRing, Callable[[Term], tuple], bool]] = {}


_BLOCKS: dict[int, tuple[PolyRing, tuple]] = {}


def note_blocks(ring: PolyRing, blocks: tuple) -> None:
    """Record the ordering blocks as written of a kernel ring (mech.dsl.rings and qrings do)."""
    _BLOCKS[id(ring)] = (ring, tuple(blocks))


def _blocks_of(ring: PolyRing) -> tuple:
    """The ordering blocks as written (with c/C) of a ring the language made (() if unknown)."""
    hit = _BLOCKS.get(id(ring))
    return hit[1] if hit is not None and hit[0] is ring else ()


def module_order(ring: PolyRing) -> tuple[Callable[[Term], tuple], bool]:
    """(key, vector_out): a sort key of the terms ``(exp, comp)`` growing with the ring's module
    ordering, and whether vectors print as ``[...]`` (the ordering starts with ``c``)."""
    hit = _COMPONENT.get(id(ring))
    if hit is not None and hit[0] is ring:
        return hit[1], hit[2]
    blocks = _blocks_of(ring)
    pos = next((k for k, b in enumerate(blocks) if b.kind in ("c", "C")), len(blocks))
    sign = -1 if pos < len(blocks) and blocks[pos].kind == "c" else 1
    mono = ring.order.key
    key: Callable[[Term], tuple]
    if pos >= len(blocks) - 1:
        key = lambda t: (mono(t[0]), sign * t[1])  # noqa: E731
    elif pos == 0:
        key = lambda t: (sign * t[1], mono(t[0]))  # noqa: E731
    else:  # between blocks: the blocks before it decide first
        from ..kernel.order import Block
        before = [Block(b.kind, b.size, b.weights) for b in blocks[:pos]]
        n = sum(b.size for b in before if b.kind != "a")
        pre = MonomialOrder(before, n).key
        key = lambda t: (pre(t[0][:n]), sign * t[1], mono(t[0]))  # noqa: E731
    out = pos == 0 and sign < 0
    _COMPONENT[id(ring)] = (ring, key, out)
    return key, out


def kernel_key(ring: PolyRing) -> Callable[[Term], tuple]:
    """The module ordering on the kernel's terms (components from 0)."""
    return module_order(ring)[0]


def sorted_terms(v: Vector) -> list[tuple[Term, Any]]:
    """The terms of v from the largest down (components from 0)."""
    key = kernel_key(v.ring)
    return sorted(v.terms().items(), key=lambda tc: key(tc[0]), reverse=True)


def lead_term(v: Vector) -> Optional[Term]:
    t = v.terms()
    return max(t, key=kernel_key(v.ring)) if t else None


# ---------------------------------------------------------------- conversions
def gen(ring: PolyRing, i: int) -> Vector:
    """The i-th canonical generator of the free module."""
    if i < 0:
        raise ValueError(f"gen({i}): the index must be positive")
    return Vector(ring, [ring.zero()] * (i - 1) + [ring.one()] if i > 0 else [])


def from_poly(p: Poly) -> Vector:
    """Singular's poly -> vector: p * gen(1)."""
    return Vector(p.ring, [p])


def module_from_columns(ring: PolyRing, nrows: int, columns: Sequence[Sequence[Poly]]) -> Module:
    return Module(ring, [Vector(ring, c) for c in columns], nrows)


def module_columns(m: Module, nrows: Optional[int] = None) -> list[list[Poly]]:
    n = m.rank if nrows is None else nrows
    return [g.padded(n) for g in m.gens]



def matrix_entries(m: "Module | Vector") -> tuple[int, int, list[Poly]]:
    """(rows, columns, entries row by row) of matrix(m): the generators as columns."""
    if isinstance(m, Vector):
        m = Module(m.ring, [m])
    cols = module_columns(m)
    return m.rank, len(cols), [cols[j][i] for i in range(m.rank) for j in range(len(cols))]
