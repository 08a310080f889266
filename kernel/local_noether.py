"""Singular's ``noether``: a monomial ``N`` declared the highest corner of the standard bases of a
local degree ordering (``ds``, ``Ds``, ``ws``, ...: the first criterion is the lower degree).
Every monomial smaller than ``N`` is taken to lie in the ideal, so standard bases live in
``K[x]_> / M`` with ``M`` the ideal of the monomials below ``N``: the terms below ``N`` are dropped
(Singular's ``std`` and ``reduce`` with ``noether`` set; checked in Singular 4.3.1:
``noether = x11; std(ideal(z+x11+y11, y12, x12))`` gives ``z+x11``).  The user vouches for the
claim; it is not checked."""
from __future__ import annotations

from itertools import combinations_with_replacement
from typing import Callable, Sequence

from .errors import NotSupported
from .order import Exp
from .poly import Poly, PolyRing


def supports_noether(ring: PolyRing) -> bool:
    """Whether ``ring``'s ordering starts with the lower total degree (then the monomials below
    ``N`` are the smaller ones of ``N``'s degree and all of higher degree)."""
    first = ring.order.first_row()
    return len(set(first)) == 1 and first[0] < 0


def below(noether: Exp, ring: PolyRing) -> list[Exp]:
    """Generators of the ideal of the monomials smaller than ``noether``."""
    if not supports_noether(ring):
        raise NotSupported("noether other than 0 needs a local degree ordering (ds, Ds)")
    key, n, d = ring.order.key, ring.nvars, sum(noether)
    bound = key(noether)
    out = []
    for degree in (d, d + 1):
        for c in combinations_with_replacement(range(n), degree):
            e = [0] * n
            for i in c:
                e[i] += 1
            if degree > d or key(tuple(e)) < bound:
                out.append(tuple(e))
    return out


def truncate(p: Poly, noether: Exp) -> Poly:
    """``p`` without its terms smaller than ``noether``."""
    key = p.ring.order.key
    bound = key(noether)
    return Poly(p.ring, {e: c for e, c in p.terms.items() if key(e) >= bound})


def noether_basis(gens: Sequence[Poly], ring: PolyRing, noether: Exp,
                  basis: Callable[[list[Poly]], list[Poly]]) -> list[Poly]:
    """A standard basis of ``(gens) + M`` by ``basis``, without the terms below ``noether`` (and
    without the elements that lie in ``M``)."""
    one = ring.field.one
    extra = [Poly(ring, {e: one}) for e in below(noether, ring)]
    cut = [q for q in (truncate(g, noether) for g in gens) if not q.is_zero()]
    out = [truncate(b, noether) for b in basis(cut + extra)]
    return [b for b in out if not b.is_zero()]
