"""``char_series(I)``: an irreducible characteristic series of I (Wu-Ritt), as Singular computes it.

Each row of the result is an irreducible ascending set (a triangular set: increasing main variables,
the last variable of the ring the largest) and V(I) is the union of the sets V(row) \\ V(initials).
The method (Wang's version of Wu's algorithm, as described in Greuel-Pfister's book and Wang's
"On the parallelization of characteristic-set-based algorithms"):

* a *basic set* of a polynomial set takes the polynomial of lowest rank and then, repeatedly, the one
  of lowest rank among those reduced with respect to the ones taken; a *characteristic set* (medial
  form) adds the non-zero pseudo-remainders to the set until none remains, dropping factors that were
  seen as initials before and variables dividing the remainders (they become branches of their own);
* each characteristic set found is tested for irreducibility: a polynomial that factors over the ground
  field splits the set; a polynomial above a non-linear one is factored over the extension they define
  when that is a finite field Z/p[v]/(A) (:mod:`.charset_ext`), else tested by whether the set's
  saturation is prime; splitting over other extensions (Singular's factory uses Trager's method with its
  own representation of the factors) is refused as not supported;
* every factor of an initial and every dropped factor starts a new branch ``qs + [factor]``; branches are
  processed longest first, and sets implied by other sets are removed at the end.

The order of the branches, of the sets and of the polynomials follows the same fixed rules as Singular
(its factory library), so the printed matrix is the same.
"""
from __future__ import annotations

from dataclasses import dataclass, field as dfield
from typing import Sequence

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Ideal, Matrix
from ..kernel import Poly
from ..kernel.coeffs import PrimeField, RationalField
from ..kernel.errors import NotSupported
from ..kernel.ideals import saturate_poly
from ..kernel.primdec import is_prime
from .charset_ext import finite_field_factors
from .charset_ops import (LC, degree, difference, divides, factor_set, factors, factors_of_initials,
                          is_const, is_subset, level, lowest_rank, normalize, premb, prem_list, size,
                          sqrfree_part, uni_gcd, union, content)

Set = list[Poly]


@dataclass
class _Stored:
    """Factors removed from remainders (fs1) and candidates for removal (fs2)."""
    fs1: Set = dfield(default_factory=list)
    fs2: Set = dfield(default_factory=list)

    def copy(self) -> "_Stored":
        return _Stored(list(self.fs1), list(self.fs2))


def basic_set(PS: Set) -> Set:
    if len(PS) < 2:
        return list(PS)
    QS, BS = list(PS), []
    while QS:
        b = lowest_rank(QS)
        cb = level(b)
        BS = union([b], BS)
        if cb <= 0:
            return []
        degb = degree(b)
        RS: Set = []
        for f in QS:
            if degree(f, cb) < degb:
                RS = union([f], RS)
        QS = RS
    return BS


def char_set_n(PS: Set) -> Set:
    """The medial set: add pseudo-remainders until they all vanish."""
    QS, RS, CSet = list(PS), list(PS), []
    while RS:
        QS = uni_gcd(QS)
        CSet = basic_set(QS)
        RS = []
        if CSet and level(CSet[0]) > 0:
            for f in difference(QS, CSet):
                r = prem_list(f, CSet)
                if not r.is_zero():
                    RS = union(RS, [r])
            QS = union(CSet, RS)
    return CSet


def _sqrfree_set(PS: Set) -> Set:
    L: Set = []
    for f in PS:
        L = union(L, [sqrfree_part(f)])
    return L


def char_set_via_char_set_n(PS: Set) -> Set:
    L = _sqrfree_set(PS)
    result = char_set_n(L)
    if not result or is_const(result[0]):
        return [PS[0].ring.one()]
    RS: Set = []
    for f in difference(L, result):
        r = premb(f, result)
        if not r.is_zero():
            RS = union(RS, [r])
    if not RS:
        return result
    return char_set_via_char_set_n(union(L, union(RS, result)))


def _remove_factors(r: Poly, stored: _Stored) -> tuple[Poly, Set]:
    """r without the stored factors and without variable factors; the factors removed."""
    removed: Set = []
    n = level(r)
    for g in stored.fs1:
        while (q := divides(g, r)) is not None and not r.is_zero():
            r = q
    for g in stored.fs2:
        if g != r:
            hit = False
            while (q := divides(g, r)) is not None:
                hit, r = True, q
            if hit:
                removed = union(removed, [g])
    r = normalize(r)
    for v in range(1, n + 1):
        if r == r.ring.one():
            break
        x = r.ring.gen(v - 1)
        if x != r:
            hit = False
            while (q := divides(x, r)) is not None:
                hit, r = True, q
            if hit:
                removed = union(removed, [x])
    return normalize(r), removed


def mod_char_set(L: Set, stored: _Stored) -> tuple[Set, _Stored]:
    """The modified medial set (remainders freed of known factors); the updated stored factors."""
    QS, RS, CSet = uni_gcd(L), list(L), []
    stored2 = _Stored()
    while RS:
        CSet = basic_set(QS)
        initial = factors_of_initials(CSet)
        stored2.fs1 = list(stored.fs1)
        stored2.fs2 = union(stored2.fs2, initial)
        RS = []
        if CSet and level(CSet[0]) > 0:
            for f in difference(QS, CSet):
                r = prem_list(f, CSet)
                if not r.is_zero():
                    r, removed = _remove_factors(r, stored2)
                    stored2.fs1 = union(stored2.fs1, removed)
                    stored2.fs2 = difference(stored2.fs2, removed)
                    RS = union(RS, [r])
            QS = union(CSet, RS)
        stored = stored2.copy()
    return CSet, stored


def _remove_content(PS: Set, stored: _Stored) -> Set:
    if not PS or level(PS[0]) == 0:
        return PS
    out: Set = []
    for f in PS:
        cc = content(f)
        if level(cc) > 0:
            out.append(normalize(_exact(f, cc)))
            stored.fs1 = union([normalize(cc)], stored.fs1)
        else:
            out.append(normalize(f))
    return out


def _exact(f: Poly, g: Poly) -> Poly:
    q = divides(g, f)
    assert q is not None
    return q


def _quasilinear(AS: Set) -> bool:
    return sum(1 for f in AS if degree(f) > 1) <= 1


def _irred_as(AS: Set) -> tuple[int, Poly | None, Set]:
    """(index of the first reducible element (1-based, 0: irreducible), that element, its factors)."""
    qs: list = []
    for nr, f in enumerate(AS, 1):
        qs = factors(f)
        if len(qs) >= 2 or qs[0][1] > 1:
            return nr, f, [normalize(g) for g, _ in qs]
    if not _quasilinear(AS):
        for nr in range(1, len(AS)):
            f = AS[nr]
            if degree(f) <= 1 or not any(degree(g) > 1 for g in AS[:nr]):
                continue
            split = finite_field_factors(f, AS[:nr])
            if split is None:
                if not _irreducible_set(AS[:nr + 1]):
                    raise MechRuntimeError("char_series: splitting an ascending set whose polynomial is reducible "
                                           "over the algebraic extension given by the ones below (factoring over "
                                           "algebraic function fields) is not supported")
                split = [(f, 1)]
            qs = split
            if len(qs) > 1 or qs[0][1] > 1:
                return nr + 1, f, [normalize(g) for g, _ in qs]
    return 0, None, [normalize(g) for g, _ in qs]


def _irreducible_set(AS: Set) -> bool:
    """Whether the ascending set is irreducible: its saturation by the initials is a prime ideal (the
    last polynomial, irreducible over the rationals, stays irreducible over the extension below it)."""
    ring = AS[0].ring
    h = ring.one()
    for g in AS:
        h = h * LC(g)
    try:
        return is_prime(saturate_poly(AS, h, ring), ring)
    except NotSupported as e:
        raise MechRuntimeError(f"char_series: testing an ascending set for irreducibility over this field is not "
                               f"supported ({e})") from None


def _adjoin(is_: Set, qs: Set, qh: list[Set], cs: Set | None = None) -> list[Set]:
    iscopy: Set = []
    for f in is_:
        if level(f) > 0:
            iscopy = union([f], iscopy)
    if not iscopy:
        return []
    qhi = [q for q in qh if q != qs]
    out: list[Set] = []
    for f in iscopy:
        itt = union(qs, [f])
        if cs is not None:
            itt = union(itt, cs)
        if not any(is_subset(j, itt) for j in qhi):
            out.append(itt)
    return out


def _inplace_union(a: list[Set], b: list[Set]) -> list[Set]:
    if not a:
        return b
    if not b:
        return list(a)
    for s in a:
        if s and s not in b:
            b = [s] + b
    return b


def _sort_sets(sets: list[Set]) -> None:
    """Bubble sort: longer sets first, then fewer terms in the first polynomial."""
    def first_size(s: Set) -> int:
        return size(s[0]) if s else 0
    n = len(sets)
    for l in range(1, n + 1):
        for k in range(n - l):
            a, b = sets[k], sets[k + 1]
            if len(a) < len(b) or (len(a) == len(b) and first_size(a) > first_size(b)):
                sets[k], sets[k + 1] = b, a


def _contractsub(cs1: Set, cs2: Set) -> bool:
    """Whether the zero set of cs1 (off its initials) lies in that of cs2 by pseudo-division."""
    if any(not prem_list(f, cs2).is_zero() for f in cs1):
        return False
    return all(not prem_list(f, cs2).is_zero() for f in factors_of_initials(cs1))


def _contract(cs: list[Set]) -> list[Set]:
    if len(cs) < 2:
        return cs
    mem: list[Set] = []
    ts: list[Set] = []
    for ii, a in enumerate(cs[:-1]):
        if a in mem:
            continue
        for b in cs[ii + 1:]:
            if b in mem:
                continue
            if _contractsub(a, b):
                ts.append(b)
                mem.append(b)
            elif _contractsub(b, a):
                ts.append(a)
    return difference(cs, ts)


def irr_char_series(PS: Sequence[Poly]) -> list[Set]:
    """The rows of the irreducible characteristic series of the polynomials PS (none zero)."""
    one = PS[0].ring.one()
    L: Set = []
    for f in PS:
        L = union([sqrfree_part(f)], L)
    highest = max(level(f) for f in PS)
    pi: list[Set] = []
    ppi: list[Set] = []
    qqi: list[Set] = []
    qsi: list[Set] = []
    iss: list[Set] = []
    qhi: list[Set] = [L]
    first = True
    while qhi:
        _sort_sets(qhi)
        qs = qhi[0]
        ppi1 = [s for s in ppi if s and len(qs) > len(s)]
        ppi2 = [s for s in ppi if s and len(qs) <= len(s)]
        qqi = _inplace_union(ppi2, qqi)
        ppi = [] if first else union(ppi1, [qs])
        first = False
        stored = _Stored()
        if len(qs) - 3 < highest:
            cs, stored = mod_char_set(qs, stored)
        else:
            cs = char_set_n(qs)
        cs = _remove_content(cs, stored)
        factorset = stored.fs1
        index_red = 0
        if cs and level(cs[0]) > 0:
            index_red, reducible, ts = _irred_as(cs)
            if index_red <= 0:
                if not is_subset(cs, qs):
                    cs = char_set_via_char_set_n(union(qs, cs))
                if cs not in pi:
                    pi = union([cs], pi)
                    if level(cs[0]) > 0:
                        index_red, reducible, ts = _irred_as(cs)
                        if index_red <= 0:
                            qsi = union([cs], qsi)
                            if len(cs) == highest:
                                is_ = factor_set(factorset)
                            else:
                                is_ = union(factors_of_initials(cs), factor_set(factorset))
                            iss = _adjoin(is_, qs, qqi)
                    else:
                        iss = _adjoin(factor_set(factorset), qs, qqi)
                else:
                    iss = _adjoin(factor_set(factorset), qs, qqi)
            if index_red > 0:
                is_ = factor_set(factorset)
                if index_red > 1:
                    cst = cs[:cs.index(reducible)]
                    is_ = union(factors_of_initials(union(cst, [reducible])), is_)
                    iss = union(_adjoin(ts, qs, qqi, cst), _adjoin(is_, qs, qqi))
                else:
                    iss = _adjoin(union(is_, ts), qs, qqi)
        else:
            iss = _adjoin(factor_set(factorset), qs, qqi)
        qhi = union(iss, qhi[1:]) if len(qhi) > 1 else iss
    return _contract(qsi) if qsi else [[one]]


@command("char_series")
def char_series(I: Ideal) -> Matrix:
    """char_series(I): an irreducible characteristic series of I as a matrix, one ascending set a row
    (the variables ranked by their position in the ring, the last one highest), as Singular prints it.

    Example:
      ring r = 32003,(x,y,z),dp;
      print(char_series(ideal(xyz, xz, y)));
      → y,z,
      → x,y
    """
    ring = I.ring
    field = ring.field
    if not isinstance(field, (RationalField, PrimeField)):
        raise MechRuntimeError(f"char_series is not available over the coefficient field {field!r}")
    gens = [normalize(g) for g in I.gens if not g.is_zero()]
    if not gens:
        return Matrix(ring, 1, 1)
    rows = irr_char_series(gens)
    ncols = max(len(r) for r in rows)
    return Matrix(ring, len(rows), ncols, [p for r in rows for p in r + [ring.zero()] * (ncols - len(r))])
