"""The functions of Macaulay2's PrimaryDecomposition and MinimalPrimes packages beyond those of
``stdlib/m2.py`` (``dialect="m2"``): ``minprimes``, ``ass``, ``topComponents``,
``removeLowestDimension``, ``primaryComponent``, ``localize`` and ``irreducibleDecomposition``, from
the primary decomposition of the kernel."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.m2_values import MonomialIdeal
from ..dsl.m2_rings import in_quotients
from ..dsl.registry import command
from ..dsl.values import NONE, Ideal, List
from ..kernel import Poly
from ..kernel import ideals as K
from .m2 import _global, _lift, _minimal, _primdec, _quotient_of, _reduced, _trim, minimal_primes


@command("minprimes", dialect="m2")
@in_quotients
def minprimes(ctx, I: Ideal) -> List:
    """minprimes I: the minimal primes of I (as minimalPrimes)."""
    return minimal_primes(ctx, I)


minprimes.m2_options = ("CodimensionLimit",)


@command("ass", dialect="m2")
@in_quotients
def ass(I: Ideal) -> List:
    """ass I: the associated primes of I (as associatedPrimes)."""
    return associated_primes(I)


def _components(I: Ideal) -> list[tuple[Ideal, Ideal, int]]:
    """(primary component, its prime, dimension) for a primary decomposition of I."""
    _global(I, "a primary decomposition")
    return [(_reduced(I, q), _reduced(I, p), K.dimension(p, ring=I.ring)) for q, p in _primdec(I)]


def _intersection(I: Ideal, parts: list[Ideal]) -> Ideal:
    if not parts:
        return Ideal(I.ring, [I.ring.one()])
    polys = K.intersect(*[_lift(J) for J in parts], ring=I.ring)
    if _quotient_of(I.ring) is not None:  # computed on the preimages in R: back in R/Q, trimmed
        return _trim(_reduced(I, K.std(polys, ring=I.ring)))
    return _minimal(I, sorted(polys, key=lambda p: I.ring.order.key(p.lm())))


@command("topComponents", dialect="m2")
@in_quotients
def top_components(I: Ideal) -> Ideal:
    """topComponents I: the intersection of I's primary components of the largest dimension."""
    comps = _components(I)
    if not comps:
        return I
    top = max(d for _, _, d in comps)
    return _intersection(I, [q for q, _, d in comps if d == top])


@command("isPrimary", dialect="m2")
@in_quotients
def is_primary_over(Q: Ideal, P: Ideal) -> bool:
    """isPrimary(Q, P), P the radical of Q: as Macaulay2 defines it, whether P is prime and Q has no
    components of lower dimension (Q == topComponents Q)."""
    from .m2 import _gb, is_prime
    return is_prime(P) and _gb(Q).gens == _gb(top_components(Q)).gens


@command("removeLowestDimension", dialect="m2")
@in_quotients
def remove_lowest_dimension(I: Ideal) -> Ideal:
    """removeLowestDimension I: the intersection of I's primary components above the lowest
    dimension (the unit ideal when all have one dimension)."""
    comps = _components(I)
    if not comps:
        return I
    low = min(d for _, _, d in comps)
    return _intersection(I, [q for q, _, d in comps if d > low])


def _contains(big: Ideal, small: Ideal) -> bool:
    return K.is_subset(small.nonzero(), big.nonzero(), ring=big.ring)


@command("primaryComponent", dialect="m2")
@in_quotients
def primary_component(I: Ideal, P: Ideal) -> Ideal:
    """primaryComponent(I, P): the P-primary component of I that Eisenbud, Huneke and Vasconcelos'
    construction gives (P an associated prime of I): for m = 1, 2, ... the top component Q of
    I + P^m, until Q meets (I localized at P) : P^infinity inside I localized at P."""
    _global(I, "primaryComponent")
    ring, I0, P0 = I.ring, _lift(I), _lift(P)
    at_p = [q for q, p in _primdec_of(I0, ring) if K.is_subset(p, P0, ring=ring)]
    if not at_p:
        raise MechRuntimeError("primaryComponent(I, P): P contains no associated prime of I")
    local = K.intersect(*at_p, ring=ring)
    colon = K.saturate(local, P0, ring=ring)[0]
    m = 1
    while True:
        Q = _top(K.ideal_sum(I0, K.ideal_power(P0, m, ring=ring), ring=ring), ring)
        if K.is_subset(K.intersect(Q, colon, ring=ring), local, ring=ring):
            return _trim(_reduced(I, K.std(Q, ring=ring)))
        m += 1


def _primdec_of(polys: list[Poly], ring) -> list[tuple[list[Poly], list[Poly]]]:
    from ..kernel.primdec import primdec_gtz
    return primdec_gtz(polys, ring)


def _top(polys: list[Poly], ring) -> list[Poly]:
    """The intersection of the primary components of largest dimension."""
    comps = [(q, K.dimension(p, ring=ring)) for q, p in _primdec_of(polys, ring)]
    top = max(d for _, d in comps)
    return K.intersect(*[q for q, d in comps if d == top], ring=ring)


@command("localize", dialect="m2")
def localize(I: Ideal, P: Ideal) -> Ideal:
    """localize(I, P): the intersection of I's primary components whose primes lie in P (I
    localized at the prime P, contracted back)."""
    return _intersection(I, [q for q, p, _ in _components(I) if _contains(P, p)])


def _split(gens: list[tuple[int, ...]]) -> list[list[tuple[int, ...]]]:
    """The irreducible components (lists of pure powers) of the monomial ideal of ``gens``."""
    for m in gens:
        support = [i for i, k in enumerate(m) if k]
        if len(support) > 1:
            i = support[0]
            power = tuple(m[i] if j == i else 0 for j in range(len(m)))
            rest = tuple(0 if j == i else k for j, k in enumerate(m))
            others = [g for g in gens if g != m]
            return _split(_mingens(others + [power])) + _split(_mingens(others + [rest]))
    return [gens]


def _irreducible(monos: list[tuple[int, ...]]) -> list[list[tuple[int, ...]]]:
    """The irredundant irreducible components (lists of pure powers) of a monomial ideal."""
    comps = [sorted(c, reverse=True) for c in _split(_mingens(monos))]
    unique: list[list[tuple[int, ...]]] = []
    for c in comps:
        if c not in unique:
            unique.append(c)

    def contains(a: list, b: list) -> bool:  # (a) ⊇ (b)
        return all(any(all(x <= y for x, y in zip(g, m)) for g in a) for m in b)
    return [c for c in unique if not any(o != c and contains(c, o) for o in unique)]


def _mingens(monos: list[tuple[int, ...]]) -> list[tuple[int, ...]]:
    monos = list(dict.fromkeys(monos))
    return [m for m in monos if not any(o != m and all(a <= b for a, b in zip(o, m)) for o in monos)]


@command("irreducibleDecomposition", dialect="m2")
def irreducible_decomposition(I: MonomialIdeal) -> List:
    """irreducibleDecomposition I: the irreducible monomial ideals (generated by powers of
    variables) whose irredundant intersection is the monomial ideal I."""
    keep = _irreducible([g.lm() for g in I.nonzero()])
    ring = I.ring
    return List([MonomialIdeal(ring, [Poly(ring, {m: ring.field.one}) for m in c]) for c in sorted(keep)])


def monomial_primdec(I: Ideal) -> list[tuple[Ideal, Ideal]] | None:
    """Macaulay2's Monomial strategy for an ideal of monic monomials in a polynomial ring:
    the irreducible components grouped by their support and intersected, the groups by size
    and then by their variables (as index lists); each prime's variables from the last. None
    for other ideals (the zero and unit ideals too)."""
    ring = I.ring
    gens = I.nonzero()
    if (not gens or getattr(getattr(ring, "owner", None), "quotient", None) is not None
            or not ring.order.is_global or any(len(g.terms) != 1 or g.lc() != ring.field.one for g in gens)
            or any(not any(g.lm()) for g in gens)):
        return None
    groups: dict[tuple[int, ...], list[tuple[int, ...]]] = {}
    for comp in _irreducible([g.lm() for g in gens]):
        support = tuple(sorted(next(i for i, k in enumerate(m) if k) for m in comp))
        old = groups.get(support)
        if old is None:
            groups[support] = comp
        else:   # the intersection of two monomial ideals: the lcms of their generators
            groups[support] = _mingens([tuple(max(a, b) for a, b in zip(u, v)) for u in old for v in comp])
    cast = MonomialIdeal if isinstance(I, MonomialIdeal) else Ideal
    out = []
    for support in sorted(groups, key=lambda s: (len(s), s)):
        monos = sorted(groups[support], key=ring.order.key)
        comp = cast(ring, [Poly(ring, {m: ring.field.one}) for m in monos])
        prime = cast(ring, [ring.gen(i) for i in reversed(support)])
        out.append((comp, prime))
    return out


@command("radicalContainment", dialect="m2")
@in_quotients
def radical_containment(g: Poly | Ideal, I: Ideal) -> Any:
    """radicalContainment(g, I): whether g is in the radical of I (Rabinowitsch: I : g^infinity is
    the unit ideal); for an ideal G: null when G lies in it, else the index of G's first generator
    that does not."""
    _global(I, "radicalContainment")
    basis = K.std(_lift(I), ring=I.ring)

    def inside(f: Poly) -> bool:
        return K.is_unit(K.saturate_poly(basis, f, ring=I.ring, is_basis=True))
    if isinstance(g, Ideal):
        return next((i for i, f in enumerate(g.gens) if not inside(f)), NONE)
    return inside(g)


#: an element's answer is a Boolean (the registry gives 0 or 1), an ideal's an index or null
radical_containment.m2_result = lambda args, v: v if isinstance(args[0], Ideal) else bool(v)


@command("primaryDecomposition", dialect="m2")
@in_quotients
def primary_decomposition(ctx, I: Ideal) -> List:
    """primaryDecomposition I: primary ideals whose intersection is I (with Strategy =>
    EisenbudHunekeVasconcelos: primaryComponent(I, P) for each associated prime P)."""
    strategy = ctx.m2_options.get("Strategy")
    if getattr(strategy, "name", None) == "EisenbudHunekeVasconcelos":
        return List([primary_component(I, P) for P in associated_primes(I).items])
    mono = monomial_primdec(I)
    if mono is not None:
        return List([q for q, _ in mono])
    return List([_reduced(I, q) for q, _ in _primdec(I)])


primary_decomposition.m2_options = ("Strategy",)


@command("associatedPrimes", dialect="m2")
@in_quotients
def associated_primes(I: Ideal) -> List:
    """associatedPrimes I: the associated primes of I."""
    mono = monomial_primdec(I)
    if mono is not None:
        return List([p for _, p in mono])
    out: list[Ideal] = []
    for _, p in _primdec(I):
        P = _reduced(I, p)
        if P not in out:
            out.append(P)
    return List(out)
