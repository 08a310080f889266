"""Macaulay2's list library in the Macaulay2 dialect (``dialect="m2"``): ``sum``, ``product``,
``select``, ``scan``, ``any``, ``all``, ``sort``, ``max``, ``min``, ``set``, ``tally``, ``flatten``,
``toList``, ``toSequence``, ``apply`` (on lists, numbers and pairs of lists), ``applyTable``,
``same``, ``isSubset``, ``unique``, ``reverse``, ``take``, ``drop``, ``position(s)``, ``member``,
``delete``, ``prepend``, ``number``, ``subsets``, and ``assert``, ``error``, ``needsPackage``.

Elements are told apart as Macaulay2's hash tables do (``===``): by their type, ring and text."""
from __future__ import annotations

import re
from fractions import Fraction
from functools import cmp_to_key
from itertools import combinations
from typing import Any

from ..dsl.errors import MechRuntimeError, MechTypeError
from ..dsl.m2_local import in_local_rings, local_ideal_subset, localized_at
from ..dsl.m2_printing import to_string
from ..dsl.m2_rings import in_group_rings, in_quotients, is_integral
from ..dsl.m2_values import FUNCTIONS, Array, Iterator, M2Set, Symbol, Tally
from ..dsl.registry import command
from ..dsl.values import NONE, ExprList, Ideal, List, Matrix, Number, typeof
from .m2_regex import regex_select
from ..kernel import Poly

#: the packages whose functions the dialect has (needsPackage accepts them)
PACKAGES = {"PrimaryDecomposition", "MinimalPrimes", "Saturation", "Elimination", "LocalRings", "Core"}

Seq = List | ExprList | str | Iterator


def key(x: Any) -> Any:
    """What tells elements apart in sets, tallies, unique and member (Macaulay2's strict equality)."""
    ring = getattr(x, "ring", None)
    return (type(x).__name__, id(ring) if ring is not None else None, to_string(x))


def _items(L: Any) -> list:
    if isinstance(L, (List, ExprList, M2Set)):
        return list(L.items)
    if isinstance(L, str):  # a string as the sequence of its characters
        return list(L)
    if isinstance(L, Iterator):  # what is left of it
        return list(L.source)
    raise MechTypeError(f"expected a list, not a {typeof(L)}")


def _same_kind(L: Any, items: list) -> Any:
    """``items`` as the kind of list ``L`` is (list, array or sequence; a string: a sequence)."""
    if isinstance(L, (ExprList, str)):
        return ExprList(items)
    return Array(items) if isinstance(L, Array) else List(items)


def _fn(f: Any) -> None:
    if not isinstance(f, FUNCTIONS):
        raise MechTypeError(f"expected a function, not a {typeof(f)}")


def _truth(v: Any, what: str) -> bool:
    if not isinstance(v, bool):
        raise MechTypeError(f"{what}: the function must return true or false, not a {typeof(v)}")
    return v


# ---------------------------------------------------------------- sums and products
def _fold(ctx, values: list, op: str, unit: int) -> Any:
    if not values:
        return unit
    acc = values[0]
    for v in values[1:]:
        acc = ctx._binary(op, acc, v)
    return acc


@command("sum", dialect="m2")
@in_quotients
def sum_(ctx, L: Seq | int, f: Any = None) -> Any:
    """sum L: the sum of the entries; sum(L, f) / sum(n, f): the sum of f(x) for x in L (or 0..n-1)."""
    items = list(range(L)) if type(L) is int else _items(L)
    if f is not None:
        _fn(f)
        items = [ctx.apply(f, [x]) for x in items]
    return _fold(ctx, items, "+", 0)


@command("product", dialect="m2")
@in_quotients
def product(ctx, L: Seq | int, f: Any = None) -> Any:
    """product L: the product of the entries; product(L, f) / product(n, f): of f(x)."""
    items = list(range(L)) if type(L) is int else _items(L)
    if f is not None:
        _fn(f)
        items = [ctx.apply(f, [x]) for x in items]
    return _fold(ctx, items, "*", 1)


# ---------------------------------------------------------------- functions over lists
@command("apply", dialect="m2")
@in_quotients
@in_local_rings
def apply(ctx, L: Seq | int, f: Any, g: Any = None) -> Any:
    """apply(L, f): f(x) for x in L (the same kind of list); apply(n, f): for x in 0..n-1;
    apply(L1, L2, f): f(x, y) for the pairs of entries."""
    if g is not None:
        if not isinstance(f, (List, ExprList, str)) or len(_items(f)) != len(_items(L)):
            raise MechRuntimeError("apply(L1, L2, f): the lists need the same length")
        _fn(g)
        return _same_kind(f if isinstance(f, str) else L, [ctx.apply(g, [x, y]) for x, y in zip(_items(L), _items(f))])
    _fn(f)
    if type(L) is int:
        return List([ctx.apply(f, [i]) for i in range(L)])
    if isinstance(L, Iterator):
        return Iterator(ctx.apply(f, [x]) for x in L.source)
    return _same_kind(L, [ctx.apply(f, [x]) for x in _items(L)])


@command("applyTable", dialect="m2")
@in_quotients
def apply_table(ctx, T: List, f: Any) -> List:
    """applyTable(T, f): f applied to every entry of the table (list of lists) T."""
    _fn(f)
    return List([List([ctx.apply(f, [x]) for x in _items(row)]) for row in T.items])


@command("scan", dialect="m2")
@in_quotients
@in_local_rings
def scan(ctx, L: Seq | int, f: Any) -> None:
    """scan(L, f): apply f to every entry (or to 0..n-1), for its effects."""
    _fn(f)
    for x in (range(L) if type(L) is int else _items(L)):
        ctx.apply(f, [x])
    return NONE


@command("select", dialect="m2")
@in_quotients
@in_local_rings
def select(ctx, L: Seq | int, f: Any, g: Any = None) -> Any:
    """select(L, f): the entries x with f(x) true; select(n, L, f): the first n of them;
    select(n, f): the integers 0 <= i < n with f(i) true; select(re, s) and select(re, t, s) on
    strings: the matches of a regular expression (:func:`mech.stdlib.m2_regex.regex_select`)."""
    if isinstance(L, str) and isinstance(f, str):
        return regex_select(L, g, f) if g is not None else regex_select(L, f)
    if type(L) is int and g is None:
        _fn(f)
        return List([i for i in range(L) if _truth(ctx.apply(f, [i]), "select")])
    if g is not None:
        n, L, f = L, f, g
    else:
        n = None
    _fn(f)
    if n is None and isinstance(L, (str, Iterator)):  # Macaulay2 1.21: an iterator
        source = iter(L) if isinstance(L, str) else L.source
        return Iterator(x for x in source if _truth(ctx.apply(f, [x]), "select"))
    out = []
    for x in _items(L):
        if n is not None and len(out) >= n:
            break
        if _truth(ctx.apply(f, [x]), "select"):
            out.append(x)
    return _same_kind(L, out)


@command("any", dialect="m2")
@in_quotients
@in_local_rings
def any_(ctx, L: Seq | int, f: Any) -> bool:
    """any(L, f): whether f(x) is true for some entry x (or x in 0..n-1)."""
    _fn(f)
    return any(_truth(ctx.apply(f, [x]), "any") for x in (range(L) if type(L) is int else _items(L)))


@command("all", dialect="m2")
@in_quotients
@in_local_rings
def all_(ctx, L: Seq | int, f: Any) -> bool:
    """all(L, f): whether f(x) is true for every entry x (or x in 0..n-1)."""
    _fn(f)
    return all(_truth(ctx.apply(f, [x]), "all") for x in (range(L) if type(L) is int else _items(L)))


@command("position", dialect="m2")
@in_quotients
def position(ctx, L: Seq, f: Any, g: Any = None) -> Any:
    """position(L, f): the index of the first entry with f true (null if none); position(A, B, f):
    the first index i with f(A_i, B_i) true; with Reverse => true the last."""
    if g is not None:
        rows = list(zip(_items(L), _items(f)))
        if len(_items(L)) != len(_items(f)):
            raise MechRuntimeError("position(A, B, f): the lists need the same length")
        f = g
    else:
        rows = [(x,) for x in _items(L)]
    _fn(f)
    order = range(len(rows) - 1, -1, -1) if ctx.m2_options.get("Reverse") is True else range(len(rows))
    return next((i for i in order if _truth(ctx.apply(f, list(rows[i])), "position")), NONE)


position.m2_options = ("Reverse",)


@command("positions", dialect="m2")
@in_quotients
def positions(ctx, L: Seq, f: Any) -> List:
    """positions(L, f): the indices of the entries with f true."""
    _fn(f)
    return List([i for i, x in enumerate(_items(L)) if _truth(ctx.apply(f, [x]), "positions")])


@command("number", dialect="m2")
@in_quotients
def number(ctx, L: Seq, f: Any) -> int:
    """number(L, f): how many entries have f true."""
    _fn(f)
    return sum(1 for x in _items(L) if _truth(ctx.apply(f, [x]), "number"))


# ---------------------------------------------------------------- reshaping
@command("toList", dialect="m2")
@in_quotients
@in_local_rings
def to_list(L: Any) -> List:
    """toList L: the entries of a sequence, set or list as a list."""
    return List(_items(L))


@command("toSequence", dialect="m2")
@in_quotients
def to_sequence(L: Seq) -> ExprList:
    """toSequence L: the entries as a sequence."""
    return ExprList(_items(L))


@command("sequence", dialect="m2")
@in_quotients
def sequence(*xs: Any) -> ExprList:
    """sequence x: x as a sequence of one entry (a sequence stays itself)."""
    if len(xs) == 1 and isinstance(xs[0], ExprList):
        return xs[0]
    return ExprList(list(xs))


@command("flatten", dialect="m2")
@in_quotients
def flatten(L: Seq | Matrix) -> Any:
    """flatten L: the entries of L's lists spliced into L (one level); flatten M: the entries of a
    matrix, column by column, as a one-row matrix."""
    if isinstance(L, Matrix):
        return Matrix(L.ring, 1, L.nrows * L.ncols, [L.get(i, j) for j in range(1, L.ncols + 1)
                                                     for i in range(1, L.nrows + 1)])
    out = []
    for x in _items(L):
        out.extend(x.items if isinstance(x, List) else [x])
    return _same_kind(L, out)


@command("splice", dialect="m2")
@in_quotients
def splice(L: Seq) -> Any:
    """splice L: the entries of L's sequences spliced into L (one level)."""
    out = []
    for x in _items(L):
        out.extend(x.items if isinstance(x, ExprList) else [x])
    return _same_kind(L, out)


@command("reverse", dialect="m2")
@in_quotients
def reverse(L: Seq) -> Any:
    """reverse L: the entries in the opposite order (a string reversed)."""
    return L[::-1] if isinstance(L, str) else _same_kind(L, _items(L)[::-1])


def _span(n: Any, length: int, what: str) -> tuple[int, int]:
    if type(n) is int:
        return (0, n) if n >= 0 else (length + n, length)
    if isinstance(n, List) and len(n.items) == 2 and all(type(k) is int for k in n.items):
        return n.items[0], n.items[1] + 1
    raise MechTypeError(f"{what}(L, n) takes a number or a pair {{i, j}}")


@command("take", dialect="m2")
@in_quotients
def take(L: Seq, n: int | List) -> Any:
    """take(L, n): the first n entries (the last -n for n < 0); take(L, {i, j}): entries i..j."""
    items = _items(L)
    a, b = _span(n, len(items), "take")
    part = items[max(a, 0):max(b, 0)]
    return List(part) if isinstance(L, str) else _same_kind(L, part)


@command("drop", dialect="m2")
@in_quotients
def drop(L: Seq, n: int | List) -> Any:
    """drop(L, n): without the first n entries (the last -n for n < 0); drop(L, {i, j}): without i..j."""
    items = _items(L)
    if isinstance(n, List) and not (0 <= n.items[0] <= n.items[1] if all(type(k) is int for k in n.items) else False):
        return _same_kind(L, items)  # Macaulay2: drop(L, {j,k}) with k < j or a negative index drops nothing
    a, b = _span(n, len(items), "drop")
    a, b = max(a, 0), max(b, 0)
    return _same_kind(L, items[:a] + items[b:])


@command("prepend", dialect="m2")
@in_quotients
def prepend(x: Any, L: Seq) -> Any:
    """prepend(x, L): L with x added at the front."""
    return _same_kind(L, [x, *_items(L)])


@command("delete", dialect="m2")
@in_quotients
def delete(x: Any, L: Seq) -> Any:
    """delete(x, L): L without the entries equal to x."""
    k = key(x)
    return _same_kind(L, [y for y in _items(L) if key(y) != k])


@command("unique", dialect="m2")
@in_quotients
def unique(L: Seq) -> List:
    """unique L: the entries without repetitions, in the order first met."""
    return List(M2Set(_items(L), key).items)


@command("member", dialect="m2")
@in_quotients
def member(x: Any, L: Any) -> bool:
    """member(x, L): whether x is an entry of the list or set L."""
    k = key(x)
    return any(key(y) == k for y in _items(L))


@command("subsets", dialect="m2")
@in_quotients
def subsets(L: Seq | int, k: int | None = None) -> List:
    """subsets(L, k): the k-element subsets (as lists); subsets L: all of them; subsets(n, k): of 0..n-1."""
    items = list(range(L)) if type(L) is int else _items(L)
    sizes = [k] if k is not None else range(len(items) + 1)
    return List([List(list(c)) for s in sizes for c in combinations(items, s)])


@command("same", dialect="m2")
@in_quotients
def same(L: Seq) -> bool:
    """same L: whether all entries are equal."""
    keys = {key(x) for x in _items(L)}
    return len(keys) <= 1


# ---------------------------------------------------------------- sets and tallies
@command("set", dialect="m2")
@in_quotients
def set_(L: Seq) -> M2Set:
    """set L: the set of the entries."""
    return M2Set(_items(L), key)


@command("tally", dialect="m2")
@in_quotients
def tally(L: Seq) -> Tally:
    """tally L: how often each entry occurs."""
    return Tally(_items(L), key)


@command("isSubset", dialect="m2")
@in_quotients
@in_local_rings
def is_subset(a: Any, b: Any) -> bool:
    """isSubset(A, B): whether every element of A is one of B (lists, sets), or the ideal A lies in B."""
    if isinstance(a, Ideal) and isinstance(b, Ideal) and localized_at(b.ring) is not None:
        return local_ideal_subset(a, b)
    if isinstance(a, Ideal) and isinstance(b, Ideal):
        from .m2 import _gb, _quotient_of, zz_subset
        if is_integral(b.ring):
            return zz_subset(a, b)
        from ..kernel.groebner import normal_form
        q = _quotient_of(b.ring)
        basis = list(_gb(b).gens) + (list(q.basis) if q is not None else [])
        return all(normal_form(g, basis).is_zero() for g in a.nonzero())
    keys = {key(y) for y in _items(b)}
    return all(key(x) in keys for x in _items(a))


# ---------------------------------------------------------------- order
def _string_key(text: str) -> tuple:
    """Macaulay2's order of strings: other characters before digits before letters, runs of
    digits by their value, letters regardless of case (then capitals first)."""
    primary, case = [], []
    for run in re.findall(r"\d+|\D", text):
        if run.isdigit():
            primary.append((1, int(run), ""))
        elif run.isalpha():
            primary.append((2, 0, run.lower()))
            case.append(0 if run.isupper() else 1)
        else:
            primary.append((0, 0, run))
    return tuple(primary), tuple(case)


# ---------------------------------------------------------------- order
def _compare(x: Any, y: Any) -> int:
    """Macaulay2's ``?`` for sorting: numbers by value, strings alphabetically, polynomials by
    their leading monomials in the ring's order then coefficients, lists entry by entry."""
    if isinstance(x, (int, Fraction)) and isinstance(y, (int, Fraction)) and not isinstance(x, bool):
        return (x > y) - (x < y)
    if isinstance(x, Symbol) and isinstance(y, Symbol):
        x, y = x.name, y.name
    if isinstance(x, str) and isinstance(y, str):
        kx, ky = _string_key(x), _string_key(y)
        return (kx > ky) - (kx < ky)
    if isinstance(x, Number):
        x = x.to_poly()
    if isinstance(y, Number):
        y = y.to_poly()
    if isinstance(x, Poly) and type(y) is int:
        y = x.ring.const(x.ring.field(y))
    if isinstance(y, Poly) and type(x) is int:
        x = y.ring.const(y.ring.field(x))
    if isinstance(x, Poly) and isinstance(y, Poly) and x.ring is y.ring:
        kx = [x.ring.order.key(e) for e, _ in x.sorted_terms()]
        ky = [y.ring.order.key(e) for e, _ in y.sorted_terms()]
        for a, b in zip(kx, ky):
            if a != b:
                return 1 if a > b else -1
        return (len(kx) > len(ky)) - (len(kx) < len(ky))
    if isinstance(x, (List, ExprList)) and isinstance(y, (List, ExprList)):
        for a, b in zip(x.items, y.items):
            c = _compare(a, b)
            if c:
                return c
        return (len(x.items) > len(y.items)) - (len(x.items) < len(y.items))
    raise MechTypeError(f"cannot compare a {typeof(x)} with a {typeof(y)}")


@command("sort", dialect="m2")
@in_quotients
def sort(L: Seq) -> Any:
    """sort L: the entries in increasing order."""
    return _same_kind(L, sorted(_items(L), key=cmp_to_key(_compare)))


@command("rsort", dialect="m2")
@in_quotients
def rsort(L: Seq) -> Any:
    """rsort L: the entries in decreasing order."""
    return _same_kind(L, sorted(_items(L), key=cmp_to_key(_compare), reverse=True))


def _extreme(xs: tuple, sign: int, what: str) -> Any:
    items = _items(xs[0]) if len(xs) == 1 and isinstance(xs[0], (List, ExprList)) else list(xs)
    if not items:
        raise MechRuntimeError(f"{what} of an empty list")
    best = items[0]
    for x in items[1:]:
        if _compare(x, best) * sign > 0:
            best = x
    return best


@command("max", dialect="m2")
@in_quotients
@in_local_rings
def max_(*xs: Any) -> Any:
    """max L (or max(a, b, ...)): the largest entry; max R_P: the maximal ideal of a local ring."""
    if len(xs) == 1 and localized_at(xs[0]) is not None:
        S = xs[0]
        return Ideal(S.poly, [Poly(S.poly, dict(g.terms)) for g in localized_at(S).nonzero()])
    return _extreme(xs, 1, "max")


@command("min", dialect="m2")
@in_quotients
def min_(*xs: Any) -> Any:
    """min L (or min(a, b, ...)): the smallest entry."""
    return _extreme(xs, -1, "min")


# ---------------------------------------------------------------- entries and output
@command("toString", dialect="m2")
@in_quotients
@in_local_rings
@in_group_rings
def to_string_cmd(x: Any) -> str:
    """toString x: the value as one line of text."""
    return to_string(x)


@command("print", dialect="m2")
@in_quotients
@in_local_rings
@in_group_rings
def print_(ctx, x: Any) -> None:
    """print x: print the value (one line, as toString x)."""
    ctx.write(to_string(x) + "\n")


@command("first", dialect="m2")
@in_quotients
@in_local_rings
def first(L: List | ExprList) -> Any:
    """first L: the first entry."""
    if not L.items:
        raise MechRuntimeError("first: the list is empty")
    return L.items[0]


@command("last", dialect="m2")
@in_quotients
@in_local_rings
def last(L: List | ExprList) -> Any:
    """last L: the last entry."""
    if not L.items:
        raise MechRuntimeError("last: the list is empty")
    return L.items[-1]


@command("append", dialect="m2")
@in_quotients
def append(L: List, x: Any) -> List:
    """append(L, x): L with x added at the end."""
    return List([*L.items, x])


@command("join", dialect="m2")
@in_quotients
def join(*lists: List | ExprList | Iterator) -> List | ExprList:
    """join(L1, L2, ...): the concatenated lists (of the first one's kind; later iterators as
    their entries)."""
    if lists and isinstance(lists[0], Iterator):  # an iterator of the entries of all, in turn
        return Iterator(x for L in lists for x in (L.source if isinstance(L, Iterator) else _items(L)))
    items = [x for L in lists for x in _items(L)]
    return type(lists[0])(items) if lists else List([])


@command("length", dialect="m2")
@in_quotients
@in_local_rings
def length(L: List | ExprList) -> int:
    """length L: the number of entries."""
    return len(L.items)


# ---------------------------------------------------------------- programs
@command("assert", dialect="m2")
@in_quotients
@in_local_rings
def assert_(x: Any) -> None:
    """assert x: stop with an error unless x is true."""
    if x is not True:
        raise MechRuntimeError("assertion failed" if x is False else f"assert: expected true or false, got {to_string(x)}")
    return NONE


@command("error", dialect="m2")
@in_quotients
@in_local_rings
def error(*parts: Any) -> None:
    """error "message": stop with this error."""
    raise MechRuntimeError("".join(p if isinstance(p, str) else to_string(p) for p in parts))


@command("needsPackage", dialect="m2")
def needs_package(name: str, *options: Any) -> Any:
    """needsPackage "Name": the package (its name; nothing to load for the packages whose functions mech has)."""
    if name not in PACKAGES:
        raise MechRuntimeError(f"the package {name} is not available in mech (available: {', '.join(sorted(PACKAGES))})")
    return Symbol(name)


@command("debug", dialect="m2")
def debug(package: Any) -> None:
    """debug P: makes a package's private names visible in Macaulay2; mech has none to show (nothing)."""
    if not isinstance(package, Symbol) or package.name not in PACKAGES:
        raise MechRuntimeError("debug takes a package (needsPackage \"Name\")")


@command("isPrime", dialect="m2")
@in_quotients
def is_prime_number(n: int) -> bool:
    """isPrime n: whether the integer n is a prime number."""
    import flint
    return n > 1 and bool(flint.fmpz(n).is_prime())


@command("identity", dialect="m2")
@in_quotients
def identity(*xs: Any) -> Any:
    """identity x: x (identity(a, b): the sequence (a, b); identity(): the empty one)."""
    return xs[0] if len(xs) == 1 else ExprList(list(xs))


# ---------------------------------------------------------------- numbers
@command("odd", dialect="m2")
def odd(n: int) -> bool:
    """odd n: whether n is odd."""
    return n % 2 == 1


@command("even", dialect="m2")
def even(n: int) -> bool:
    """even n: whether n is even."""
    return n % 2 == 0


@command("binomial", dialect="m2")
def binomial(n: int, k: int) -> int:
    """binomial(n, k): n choose k."""
    from math import comb
    if n < 0 or k < 0:
        raise MechRuntimeError("binomial(n, k) takes n, k >= 0")
    return comb(n, k)


for _name, _f in list(globals().items()):  # the list library: no arithmetic of its own over ZZ (isSubset checks its ideals)
    if callable(_f) and getattr(_f, "__module__", "") == __name__ and hasattr(_f, "quotient_ok"):
        _f.zz_ok = True
