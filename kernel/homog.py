"""Homogeneity and homogenization with respect to the ring's variable weights (Singular's
``homog``): weights come from the first block covering a variable (``wp``/``Wp``/``ws``/``Ws``
weights, 1 for the other kinds, matrix orderings included), or from a leading ``a(...)``
weight vector."""
from __future__ import annotations

from typing import Sequence

from .errors import DomainError
from .poly import Poly, PolyRing


def variable_weights(ring: PolyRing) -> tuple[int, ...]:
    """The degree weights of the variables, as Singular's ``deg`` and ``homog`` use them."""
    blocks = ring.order.blocks
    if blocks and blocks[0].kind == "a":
        w = list(blocks[0].weights) + [1] * ring.nvars
        return tuple(abs(v) for v in w[:ring.nvars])
    out: list[int] = []
    for b in blocks:
        if b.kind == "a":
            continue
        if b.kind in ("wp", "Wp", "ws", "Ws"):
            out += [abs(v) for v in b.weights]
        else:
            out += [1] * b.size
    return tuple(out)


def weighted_degree(exp: Sequence[int], weights: Sequence[int]) -> int:
    return sum(e * w for e, w in zip(exp, weights))


def is_homogeneous(polys: Sequence[Poly] | Poly) -> bool:
    """Singular's ``homog(I)``: every generator is homogeneous for the ring's weights (zero
    and constants are)."""
    polys = [polys] if isinstance(polys, Poly) else list(polys)
    for f in polys:
        w = variable_weights(f.ring)
        if len({weighted_degree(e, w) for e in f.terms}) > 1:
            return False
    return True


def homogenize(polys: Sequence[Poly] | Poly, var_index: int) -> list[Poly] | Poly:
    """Singular's ``homog(I, h)``: each term of each generator is multiplied by the power of
    the variable ``h`` (weight 1 required) that brings it to the generator's largest weighted
    degree.  A single polynomial gives a polynomial."""
    single = isinstance(polys, Poly)
    items = [polys] if single else list(polys)
    out = []
    for f in items:
        ring = f.ring
        if not 0 <= var_index < ring.nvars:
            raise DomainError(f"no variable {var_index + 1} in a ring with {ring.nvars} variables")
        w = variable_weights(ring)
        if w[var_index] != 1:
            raise DomainError("variable must have weight 1")
        top = max((weighted_degree(e, w) for e in f.terms), default=0)
        terms: dict = {}
        for e, c in f.terms.items():
            e2 = list(e)
            e2[var_index] += top - weighted_degree(e, w)
            key = tuple(e2)
            v = terms.get(key)
            terms[key] = c if v is None else v + c
        out.append(Poly(ring, {e: c for e, c in terms.items() if c != 0}))
    return out[0] if single else out
