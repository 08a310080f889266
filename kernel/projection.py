"""Minimal primes of a radical equidimensional ideal by a certified birational projection.

Let ``J ⊂ K[x1..xn]`` be radical and equidimensional of dimension ``d`` and ``V = V(J)`` of
degree ``deg V`` (the degree of the Hilbert polynomial of a degree-ordering basis: the sum of
the degrees of the components).  A linear projection ``π = (L_1..L_{d+1})`` to ``A^{d+1}``
maps ``V`` into a hypersurface when ``J ∩ K[y] = (g)`` with ``y_j = L_j(x)`` (elimination);
``g`` is squarefree because ``J`` is radical.  For a linear projection
``deg π(C) · deg(π|C) <= deg C`` for every component ``C`` (over K its conjugate geometric
components may share images), and every irreducible factor of ``g`` is the image of some
component.  So when the degrees of the distinct irreducible factors ``g_1..g_k`` add up to
``deg V``, each factor is the image of exactly one component, distinct components have distinct
images and every component maps birationally onto its factor: ``J`` has exactly ``k`` minimal
primes, and ``P_i = (J + g_i(L)) : (∏_{j≠i} g_j(L))^∞`` (the product lies in every other prime
but not in ``P_i``, and ``J`` is the intersection of the primes).

This is a certificate, not a probabilistic answer: a projection either passes the degree test,
and then the result is proved, or it is rejected (another one is tried; :func:`project_primes`
returns ``None`` when none passes).  The radical and equidimensional hypotheses are the
caller's (a radical complete intersection satisfies both).

Parameters: with the last ``params`` variables ``u`` taken as parameters the field is
``K = QQ(u)`` (the ring's ordering must eliminate the other variables first, e.g.
``(dp(n), dp(k))``: a basis there is one over ``QQ(u)``).  The eliminant is ``J ∩ QQ[u, y]``,
degrees are degrees in ``x`` resp. ``y``, factors free of ``y`` are units of ``K``, and each
prime over ``QQ(u)`` is returned contracted to ``QQ[x, u]`` (saturated by the leading
coefficients in ``u`` of its basis): the components of ``V`` that dominate the parameter space.
"""
from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Iterator, Sequence

from .dimension import krull_dim
from .errors import OrderingError
from .factor import factorize, normalize
from .hilbert import degree
from .ideals import dp_ring, eliminate, move, product_order, saturate_poly, std
from .order import Block, MonomialOrder
from .poly import Poly, PolyRing
from .progress import report

_COEFFS = [c for c in range(-9, 10) if c]


@dataclass
class Projection:
    """A certified decomposition: ``forms`` (the ``L_j``, polynomials of the ring), ``degree``
    (``deg V`` over ``K``), the irreducible factors of the eliminant in ``image_ring``
    (parameters, then ``y1..``) and as polynomials of the ring (``g_i(u, L(x))``), and
    ``primes[i]``, the prime mapping onto ``V(image[i])`` (reduced basis in the ring's order;
    sorted by leading monomials as :func:`~.primdec.min_ass_gtz` sorts primes of one dimension)."""

    forms: list[Poly]
    degree: int
    image_ring: PolyRing
    image: list[Poly]
    factors: list[Poly]
    primes: list[list[Poly]]


def _check_params(ring: PolyRing, params: int) -> int:
    n = ring.nvars - params
    if params and not ring.order.is_elimination_for(list(range(n))):
        raise OrderingError("projection: the ordering must eliminate the non-parameters first")
    return n


def variety_degree(ideal: Sequence[Poly], ring: PolyRing, params: int = 0) -> int:
    """``deg V(I)`` over ``QQ(last params variables)``: the degree of the Hilbert polynomial of
    a ``dp`` basis (Singular's ``degree(std(I))`` in a ``dp`` ring); with parameters, of the
    leading monomials in the other variables of a basis in the ring's (eliminating) ordering."""
    n = _check_params(ring, params)
    if params:
        return degree([g.lm()[:n] for g in std(ideal, ring)], n).degree
    dp = dp_ring(ring)
    return degree([g.lm() for g in std(move(ideal, dp), dp)], n).degree


def candidate_forms(ring: PolyRing, count: int, params: int = 0,
                    seed: int = 1) -> Iterator[list[Poly]]:
    """Linear forms in the non-parameters, ``count`` at a time, sparse first: sums of
    consecutive pairs of variables from the start and from the end (``c_j + s_j`` for a
    mechanism), then forms using each variable once (in a random form) with small random
    coefficients, then dense small random forms."""
    gens, n = ring.gens(), ring.nvars - params
    if 2 * count <= n:
        yield [gens[2 * j] + gens[2 * j + 1] for j in range(count)]
        if n - 2 * count >= 2:
            yield [gens[n - 2 * j - 2] + gens[n - 2 * j - 1] for j in range(count)]
    rnd = random.Random(seed)
    for dense in (False, False, True):
        forms = [ring.zero() for _ in range(count)]
        for k, i in enumerate(rnd.sample(range(n), n)):
            for j in range(count) if dense else [k % count]:
                forms[j] = forms[j] + gens[i] * rnd.choice(_COEFFS)
        yield forms


def eliminant(ideal: Sequence[Poly], ring: PolyRing, forms: Sequence[Poly],
              params: int = 0) -> tuple[PolyRing, list[Poly]]:
    """``J ∩ QQ[u, y]`` with ``y_j = forms[j]`` (``u`` the parameters): the ring ``QQ[u, y]``
    (``dp``) and the elimination ideal's reduced basis there."""
    N, m = ring.nvars, len(forms)
    n = N - params
    names = list(ring.names) + [f"_y{j + 1}" for j in range(m)]
    big = PolyRing(ring.field, names, product_order(N + m, [range(n), range(n, N + m)]))
    xs = big.gens()
    lifted = [g.compose(xs[:N], big) for g in ideal]
    lifted += [xs[N + j] - f.compose(xs[:N], big) for j, f in enumerate(forms)]
    elim = eliminate(lifted, range(n), big)
    image = PolyRing(ring.field, list(ring.names[n:]) + [f"y{j + 1}" for j in range(m)],
                     MonomialOrder([Block("dp", params + m)]))
    return image, [Poly(image, {e[n:]: c for e, c in g.terms.items()}) for g in elim]


def _contract(basis: list[Poly], ring: PolyRing, n: int) -> list[Poly]:
    """``I·QQ(u)[x] ∩ QQ[x, u]`` from a basis of ``I`` in an ordering eliminating ``x``: ``I``
    saturated by the product of the leading coefficients in ``u``."""
    leading = {normalize(Poly(ring, {(0,) * n + e[n:]: c for e, c in g.terms.items()
                                     if e[:n] == g.lm()[:n]})) for g in basis}
    h = ring.one()
    for lc in leading:
        h = h * lc
    return basis if h.is_constant() else saturate_poly(basis, h, ring, is_basis=True)


def certify(ideal: Sequence[Poly], ring: PolyRing, forms: Sequence[Poly], params: int = 0,
            deg: int | None = None) -> Projection | None:
    """The certified decomposition by the projection ``(u, forms)``, or ``None`` when the image
    is not a hypersurface or the factor degrees do not add up to ``deg V``.  ``ideal`` must be
    radical and equidimensional (over ``QQ(u)``), ``len(forms)`` its dimension over ``QQ(u)``
    plus one."""
    _check_params(ring, params)
    deg = variety_degree(ideal, ring, params) if deg is None else deg
    image, elim = eliminant(ideal, ring, forms, params)
    if len(elim) != 1 or elim[0].is_constant():
        return None

    def y_degree(g: Poly) -> int:
        return max(sum(e[params:]) for e in g.terms)
    facs = [(g, k) for g, k in factorize(elim[0])[1] if y_degree(g) > 0]
    if any(k > 1 for _, k in facs) or sum(y_degree(g) for g, _ in facs) != deg:
        return None
    return split_by_factors(ideal, ring, forms, deg, image, [g for g, _ in facs], params)


def split_by_factors(ideal: Sequence[Poly], ring: PolyRing, forms: Sequence[Poly], deg: int,
           image: PolyRing, facs: list[Poly], params: int = 0) -> Projection:
    """The certified primes from the eliminant's factors ``facs`` (polynomials of ``image``)."""
    n = ring.nvars - params
    images = list(ring.gens()[n:]) + list(forms)
    factors = [g.compose(images, ring) for g in facs]
    found: dict[int, list[Poly]] = {}

    def split(basis: list[Poly], part: list[int]) -> None:
        """``basis``: the intersection of the primes over the factors ``part`` (J is radical:
        saturating by ``g_j(L)`` drops exactly the prime over ``g_j``)."""
        if len(part) == 1:
            found[part[0]] = _contract(basis, ring, n) if params else basis
            report("projection", len(found), len(factors), "the primes over the eliminant's factors")
            return
        for half, other in ((part[:len(part) // 2], part[len(part) // 2:]),
                            (part[len(part) // 2:], part[:len(part) // 2])):
            rest = basis
            for j in other:
                rest = saturate_poly(rest, factors[j], ring, is_basis=True)
            split(rest, half)
    split(std(ideal, ring), list(range(len(factors))))
    primes = [found[i] for i in range(len(factors))]
    key = ring.order.key  # the order of min_ass_gtz for primes of one dimension
    order = sorted(range(len(primes)), key=lambda i: [key(g.lm()) for g in primes[i]])
    return Projection(list(forms), deg, image, [facs[i] for i in order],
                      [factors[i] for i in order], [primes[i] for i in order])


def project_primes(ideal: Sequence[Poly], ring: PolyRing, params: int = 0,
                   attempts: int = 4) -> Projection | None:
    """The minimal primes of the radical equidimensional ``ideal`` (over ``QQ(u)``, ``u`` the
    last ``params`` variables), certified by the first of ``attempts`` projections
    (:func:`candidate_forms`) that passes the degree test, else ``None`` (the caller falls
    back to another method)."""
    n = _check_params(ring, params)
    basis = std(ideal, ring)
    count = krull_dim([g.lm()[:n] for g in basis], n) + 1  # the dimension over QQ(u), plus one
    if count < 1:
        return None
    deg = variety_degree(basis, ring, params)
    for k, forms in enumerate(candidate_forms(ring, count, params)):
        if k == attempts:
            break
        found = certify(ideal, ring, forms, params, deg)
        if found is not None:
            return found
    return None
