"""Lead terms by the first parts of a monomial order in the Macaulay2 dialect (``dialect="m2"``):
``leadTerm(n, f)`` and ``leadTerm(n, I)``; lead terms of vectors (``leadTerm v``, ``Position =>``)."""
from __future__ import annotations

from typing import Callable

from ..dsl.errors import MechRuntimeError
from ..dsl.m2_rings import in_quotients, tower_terms
from ..dsl.registry import command
from ..dsl.m2_vectors import Vector
from ..dsl.values import Ideal, Matrix
from ..kernel import MonomialOrder, Poly, PolyRing
from .m2 import _gb, _no_zz


Part = Callable[[tuple[int, ...]], object]


def order_parts(ring: PolyRing, n: int) -> list[Part]:
    """The first ``n`` parts of the ring's monomial order as Macaulay2 counts them (each a function
    of an exponent whose values compare as the order does): each ``Weights => w`` one part, then each
    block one part (GLex: the degree, then the block) -- the cases checked against Macaulay2 1.21;
    others are refused."""
    parts: list[Part] = []
    pos, weights = 0, False
    for block in ring.order.blocks:
        if len(parts) >= n:
            break
        if block.kind == "a":
            parts.append(_weigh(dict(block.sparse_rows(pos)[0])))
            weights = True
            continue
        lo, hi = pos, pos + block.size
        if block.kind in ("Dp", "Wp"):
            parts.append(_weigh(dict(block.sparse_rows(lo)[0])))
        elif block.kind not in ("dp", "wp", "ds", "ws") and not (block.kind == "lp" and not weights):
            break
        parts.append(lambda e, lo=lo, hi=hi: e[lo:hi])
        pos = hi
        if weights:  # after weights, Macaulay2 1.21 counts the parts of a second block otherwise
            break
    if len(parts) < n and pos < ring.nvars:
        raise MechRuntimeError(f"leadTerm(n, ...): the first {n} parts of this monomial order are not known to mech")
    return parts[:n]


def _weigh(row: dict[int, int]) -> Part:
    return lambda e: sum(w * e[i] for i, w in row.items())


def lead_part(f: Poly, parts: list[Part]) -> Poly:
    """The sum of f's terms whose values by ``parts`` are those of f's lead monomial."""
    if f.is_zero():
        return f
    top = [p(f.lm()) for p in parts]
    return Poly(f.ring, {e: c for e, c in f.terms.items() if [p(e) for p in parts] == top})


@command("leadTerm", dialect="m2")
@in_quotients
def lead_term_part(n: int, f: Poly | Ideal) -> Poly | Matrix:
    """leadTerm(n, f): the terms of f largest by the first n parts of the monomial order (its weight
    vectors); leadTerm(n, I): the matrix of these of a Gröbner basis of I."""
    if n < 0:
        raise MechRuntimeError("leadTerm(n, ...) takes n >= 0")
    if isinstance(f, Ideal):
        _no_zz(f, "leadTerm")
        gens = _gb(f).gens
    else:
        gens = [f]
    if any(tower_terms(g) is not None for g in gens if not g.is_zero()):
        raise MechRuntimeError("leadTerm(n, ...) in a tower of rings is not supported by mech")
    ring = f.ring
    parts = order_parts(ring, n)
    lead = [lead_part(g, parts) for g in gens]
    return Matrix(ring, 1, len(lead), lead) if isinstance(f, Ideal) else lead[0]


@command("leadTerm", dialect="m2")
@in_quotients
def lead_term_vector(v: Vector) -> Vector:
    """leadTerm v of a vector: its largest term by the order of the free module (the ring's monomial
    order with the basis index where ``Position => Up|Down`` puts it: by default last, Up)."""
    ring = v.ring
    blocks = ring.order.blocks
    count, way = v.module.ring.info.get("position", (len(blocks), "Up"))
    if 0 < count < len(blocks) and any(b.kind == "a" for b in blocks):
        raise MechRuntimeError("leadTerm of a vector: Position between blocks with Weights is not supported by mech")
    m = sum(b.size for b in blocks[:count] if b.kind != "a")
    first = MonomialOrder(blocks[:count], m).key if count else None
    second = MonomialOrder(blocks[count:], ring.nvars - m).key if count < len(blocks) else None

    def key(e: tuple[int, ...], i: int) -> tuple:
        return (first(e[:m]) if first else (), i if way == "Up" else -i, second(e[m:]) if second else ())
    terms = [(key(e, i), i, e, c) for i, p in enumerate(v.entries) for e, c in p.terms.items()]
    if not terms:
        return v
    _, i, e, c = max(terms, key=lambda t: t[0])
    return Vector(v.module, [Poly(ring, {e: c}) if j == i else ring.zero() for j in range(len(v.entries))])


lead_term_vector.zz_ok = True
