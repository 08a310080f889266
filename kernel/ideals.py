"""Operations on ideals: elimination, sums, products, powers, intersections, quotients,
saturations, containment and equality (radicals: :mod:`.primdec`).

An ideal is a list of :class:`Poly` of one ring with a global ordering (pass ``ring=`` when
the list may be empty).  Unless said otherwise a result is the reduced Gröbner basis in the
input ring's ordering (``[]`` for the zero ideal, ``[1]`` for the unit ideal).  Auxiliary
orderings and variables are built as new rings; polynomials move by remapping exponents.
Everything is computed through :func:`groebner`, so a faster engine speeds all of it up.
"""
from __future__ import annotations

from typing import Callable, Sequence

from .dimension import independent_sets, krull_dim
from .engines import cached_standard_basis
from .errors import DomainError
from .groebner import contains_all, groebner, normal_form
from .order import Block, Exp, MonomialOrder
from .poly import Poly, PolyRing
from .powering import power

Ideal = Sequence[Poly]


def ring_of(*ideals: Ideal, ring: PolyRing | None = None) -> PolyRing:
    """The ring the ideals live in (``ring`` if given)."""
    if ring is not None:
        return ring
    for ideal in ideals:
        for p in ideal:
            return p.ring
    raise DomainError("the ring of an empty ideal must be given (ring=...)")


def std(ideal: Ideal, ring: PolyRing | None = None) -> list[Poly]:
    """The reduced Gröbner basis of ``ideal``."""
    return groebner([p for p in ideal if not p.is_zero()], ring_of(ideal, ring=ring))


def is_unit(basis: Ideal) -> bool:
    """Whether a Gröbner basis generates the unit ideal."""
    return any(p.is_constant() and not p.is_zero() for p in basis)


# --- auxiliary rings --------------------------------------------------------------------

def with_order(ring: PolyRing, order: MonomialOrder) -> PolyRing:
    """The ring's variables and field with another ordering."""
    return PolyRing(ring.field, ring.names, order)


def dp_ring(ring: PolyRing) -> PolyRing:
    """The ring's variables and field ordered by ``dp``."""
    return with_order(ring, MonomialOrder.simple("dp", ring.nvars))


def move(polys: Ideal, ring: PolyRing) -> list[Poly]:
    """The same polynomials (same variables) as elements of ``ring``."""
    return [Poly(ring, p.terms) for p in polys if not p.is_zero()]


def product_order(nvars: int, blocks: Sequence[Sequence[int]]) -> MonomialOrder:
    """The product ordering ``(dp(blocks[0]), dp(blocks[1]), ...)`` on variables given by
    index (a block need not be contiguous), as one matrix block with a fast sort key (one
    shared ordering per shape: building and checking one costs milliseconds)."""
    parts = tuple(tuple(sorted(b)) for b in blocks if b)
    order = _PRODUCT_ORDERS.get((nvars, parts))
    if order is None:
        if len(_PRODUCT_ORDERS) > 256:
            _PRODUCT_ORDERS.clear()
        order = _PRODUCT_ORDERS[nvars, parts] = _product_order(nvars, [list(b) for b in parts])
    return order


_PRODUCT_ORDERS: dict[tuple[int, tuple[tuple[int, ...], ...]], MonomialOrder] = {}


def _product_order(nvars: int, parts: list[list[int]]) -> MonomialOrder:
    rows: list[list[int]] = []
    for block in parts:
        rows.append([1 if j in block else 0 for j in range(nvars)])
        for v in reversed(block[1:]):
            rows.append([-1 if j == v else 0 for j in range(nvars)])
    order = MonomialOrder([Block("M", nvars, tuple(v for r in rows for v in r))])
    order.key = _product_key(parts)
    order.product_blocks = parts  # type: ignore[attr-defined]
    return order


def _product_key(parts: list[list[int]]) -> Callable[[Exp], tuple]:
    """The sort key of the product of ``dp`` blocks (equal to the matrix ordering's)."""
    tails = [tuple(reversed(b[1:])) for b in parts]

    def key(e: Exp) -> tuple:
        out: list[int] = []
        for block, tail in zip(parts, tails):
            out.append(sum([e[i] for i in block]))
            out.extend([-e[i] for i in tail])
        return tuple(out)
    return key


def _prefixed(ring: PolyRing, extra: Sequence[str]) -> PolyRing:
    """``ring`` with new variables in front, in a ``dp`` block before the ring's ordering
    (an elimination ordering for them)."""
    names = list(extra) + list(ring.names)
    while len(set(names)) < len(names):
        names = ["_" + n if i < len(extra) else n for i, n in enumerate(names)]
    k, n = len(extra), len(names)
    parts = getattr(ring.order, "product_blocks", None)
    if parts is None and ring.order == MonomialOrder([Block("dp", ring.nvars)]):
        parts = [range(ring.nvars)]
    if parts is not None:
        order = product_order(n, [range(k)] + [[i + k for i in p] for p in parts])
    else:
        order = MonomialOrder([Block("dp", k)] + list(ring.order.blocks), n)
    return PolyRing(ring.field, names, order)


def _lift(p: Poly, big: PolyRing, k: int) -> Poly:
    pad = (0,) * k
    return Poly(big, {pad + e: c for e, c in p.terms.items()})


def _drop(p: Poly, ring: PolyRing, k: int) -> Poly:
    return Poly(ring, {e[k:]: c for e, c in p.terms.items()})


def _free_of_prefix(basis: Sequence[Poly], ring: PolyRing, k: int) -> list[Poly]:
    return [_drop(p, ring, k) for p in basis if all(not any(e[:k]) for e in p.terms)]


# --- elimination and the ideal arithmetic -----------------------------------------------

def eliminate(ideal: Ideal, var_indices: Sequence[int], ring: PolyRing | None = None) -> list[Poly]:
    """The elimination ideal ``I ∩ K[other variables]`` (Singular's ``eliminate(I, x*y)``
    with ``var_indices`` the positions of x, y), as a reduced basis in the ring's ordering."""
    ring = ring_of(ideal, ring=ring)
    elim = set(var_indices)
    if not elim:
        return std(ideal, ring)
    if ring.order.is_elimination_for(sorted(elim)):
        aux = ring
    else:
        weights = tuple(1 if i in elim else 0 for i in range(ring.nvars))
        aux = with_order(ring, MonomialOrder([Block("a", ring.nvars, weights)] + list(ring.order.blocks),
                                             ring.nvars))
    basis = groebner(move(ideal, aux), aux)
    kept = [p for p in basis if not any(e[i] for e in p.terms for i in elim)]
    return move(kept, ring) if aux is ring else groebner(move(kept, ring), ring)


def ideal_sum(*ideals: Ideal, ring: PolyRing | None = None) -> list[Poly]:
    """``I1 + I2 + ...``."""
    ring = ring_of(*ideals, ring=ring)
    return groebner([p for i in ideals for p in i if not p.is_zero()], ring)


def ideal_product(*ideals: Ideal, ring: PolyRing | None = None) -> list[Poly]:
    """``I1 * I2 * ...`` (generated by the products of generators)."""
    ring = ring_of(*ideals, ring=ring)
    gens = [ring.one()]
    for ideal in ideals:
        basis = std(ideal, ring)
        gens = [a * b for a in gens for b in basis]
        gens = groebner(gens, ring) if gens else []
    return gens


def ideal_power(ideal: Ideal, k: int, ring: PolyRing | None = None) -> list[Poly]:
    """``I^k`` (``I^0`` is the unit ideal)."""
    ring = ring_of(ideal, ring=ring)
    if k < 0:
        raise DomainError("the exponent of an ideal power must be nonnegative")
    return power(std(ideal, ring), k, [ring.one()], lambda a, b: ideal_product(a, b, ring=ring))


def intersect(*ideals: Ideal, ring: PolyRing | None = None) -> list[Poly]:
    """``I1 ∩ I2 ∩ ...`` (by eliminating t from ``t*I + (1-t)*J``, pairwise)."""
    ring = ring_of(*ideals, ring=ring)
    if not ideals:
        return [ring.one()]
    bases = sorted((std(i, ring) for i in ideals), key=len)
    result = bases[0]
    for other in bases[1:]:
        result = _intersect2(result, other, ring)
    return result


def _intersect2(a: list[Poly], b: list[Poly], ring: PolyRing) -> list[Poly]:
    if not a or not b:
        return []
    if is_unit(a):
        return b
    if is_unit(b):
        return a
    if is_subset(a, b):
        return a
    if is_subset(b, a):
        return b
    big = _prefixed(ring, ["t"])
    t = big.gen(0)
    gens = [t * _lift(p, big, 1) for p in a] + [(1 - t) * _lift(p, big, 1) for p in b]
    return _free_of_prefix(groebner(gens, big), ring, 1)


def intersect_local(*ideals: Ideal, ring: PolyRing | None = None) -> list[Poly]:
    """``I1 ∩ I2 ∩ ...`` in the localization of a local or mixed ordering: ``t`` eliminated from
    ``t*I + (1-t)*J`` by a standard basis for ``(dp(t), ordering)`` (``t`` global, so the elements free
    of ``t`` generate the intersection), pairwise; a standard basis."""
    from .engines import standard_basis
    ring = ring_of(*ideals, ring=ring)
    big = PolyRing(ring.field, ["t"] + list(ring.names), MonomialOrder([Block("dp", 1)] + list(ring.order.blocks),
                                                                      ring.nvars + 1))
    t = big.gen(0)
    result = standard_basis([p for p in ideals[0] if not p.is_zero()], ring) if ideals else [ring.one()]
    for other in ideals[1:]:
        gens = [t * _lift(p, big, 1) for p in result] + [(1 - t) * _lift(p, big, 1) for p in other if not p.is_zero()]
        result = standard_basis(_free_of_prefix(standard_basis(gens, big), ring, 1), ring)
    return result


def quotient_local(ideal: Ideal, other: Ideal, ring: PolyRing | None = None) -> list[Poly]:
    """``I : J`` in the localization of a local or mixed ordering: localization commutes with ideal
    quotients, so the quotient of the polynomial ideals (computed for ``dp``) generates it; a standard
    basis."""
    from .engines import standard_basis
    ring = ring_of(ideal, other, ring=ring)
    dp = with_order(ring, MonomialOrder([Block("dp", ring.nvars)]))
    found = quotient(move(ideal, dp), move(other, dp), ring=dp)
    return standard_basis(move(found, ring), ring)


def quotient(ideal: Ideal, other: Ideal, ring: PolyRing | None = None) -> list[Poly]:
    """The ideal quotient ``I : J = {f : f*J ⊆ I}``."""
    from .factor import divide_exact
    ring = ring_of(ideal, other, ring=ring)
    basis = std(ideal, ring)
    result: list[Poly] | None = None
    for f in std(other, ring):
        if normal_form(f, basis).is_zero():
            continue
        inter = _intersect2(basis, [f], ring)
        q = groebner([divide_exact(p, f) for p in inter], ring)
        result = q if result is None else _intersect2(result, q, ring)
    return [ring.one()] if result is None else result


def saturate_poly(ideal: Ideal, f: Poly, ring: PolyRing | None = None,
                  is_basis: bool = False) -> list[Poly]:
    """``I : f^∞`` by eliminating t from ``I + (1 - t*f)`` (``is_basis``: the ideal is
    given by its reduced Gröbner basis)."""
    ring = ring_of(ideal, [f], ring=ring)
    if f.is_zero():
        return [ring.one()]
    basis = list(ideal) if is_basis else std(ideal, ring)
    if f.is_constant():
        return basis
    if is_unit(basis):
        return basis
    big = _prefixed(ring, ["t"])
    t = big.gen(0)
    gens = [_lift(p, big, 1) for p in basis] + [big.one() - t * _lift(f, big, 1)]
    return _free_of_prefix(groebner(gens, big), ring, 1)


def saturation_exponent(ideal: Ideal, saturated: Ideal, other: Ideal,
                        ring: PolyRing | None = None, is_basis: bool = False) -> int:
    """The least ``k`` with ``I : J^k == I : J^∞`` given ``saturated = I : J^∞``: the least
    ``k`` with ``saturated * J^k ⊆ I``, found by multiplying normal forms modulo ``I``
    (``is_basis``: ``I`` is given by its reduced Gröbner basis)."""
    ring = ring_of(ideal, saturated, other, ring=ring)
    basis = list(ideal) if is_basis else std(ideal, ring)
    gens = [g for g in std(other, ring)]
    current = _echelon([normal_form(p, basis) for p in saturated], ring)
    k = 0
    while current:
        k += 1
        current = _echelon([normal_form(p * g, basis) for p in current for g in gens], ring)
    return k


def _echelon(polys: list[Poly], ring: PolyRing) -> list[Poly]:
    """A basis of the K-span of ``polys`` (distinct leading monomials)."""
    rows: dict[Exp, Poly] = {}
    for p in polys:
        while not p.is_zero():
            lm = p.lm()
            r = rows.get(lm)
            if r is None:
                rows[lm] = p.monic()
                break
            p = p - r * p.lc()
    return list(rows.values())


def saturate(ideal: Ideal, other: Ideal, ring: PolyRing | None = None) -> tuple[list[Poly], int]:
    """Singular's ``sat(I, J)``: ``(I : J^∞, k)`` with ``k`` the least exponent such that
    ``I : J^k == I : J^(k+1)`` (0 when ``I : J == I``)."""
    ring = ring_of(ideal, other, ring=ring)
    basis = std(ideal, ring)
    gens = std(other, ring)
    result = [ring.one()]
    for f in gens:
        result = intersect(result, saturate_poly(basis, f, ring), ring=ring)
    return result, saturation_exponent(basis, result, gens, ring)


# --- comparison ------------------------------------------------------------------------

def is_subset(a: Ideal, b: Ideal, ring: PolyRing | None = None) -> bool:
    """Whether ``I ⊆ J``."""
    ring = ring_of(a, b, ring=ring)
    return contains_all(std(b, ring), [p for p in a if not p.is_zero()])


def ideals_equal(a: Ideal, b: Ideal, ring: PolyRing | None = None) -> bool:
    """Whether the two ideals are equal (equal reduced Gröbner bases)."""
    ring = ring_of(a, b, ring=ring)
    return std(a, ring) == std(b, ring)


def dimension(ideal: Ideal, ring: PolyRing | None = None) -> int:
    """The Krull dimension of ``K[x]/I`` (-1 for the unit ideal)."""
    ring = ring_of(ideal, ring=ring)
    basis = cached_standard_basis(ideal, ring)
    if basis is None:
        if not ring.order.is_graded:  # any ordering gives the dimension, a degree ordering fastest
            ring = dp_ring(ring)
            ideal = move(ideal, ring)
        basis = std(ideal, ring)
    return krull_dim([p.lm() for p in basis], ring.nvars)


def independent_set(basis: Sequence[Poly], nvars: int) -> list[int]:
    """A maximal (largest) independent set of variables modulo a Gröbner basis."""
    sets = independent_sets([p.lm() for p in basis], nvars)
    return sorted(sets[0]) if sets else []

