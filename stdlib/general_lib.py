"""Commands of Singular's general.lib: letters (``A_Z``, ``A_Z_L``, ``ASCII``), integers
(``absValue``, ``factorial``, ``fibonacci``, ``primes``, ``number_e``), ``product`` and ``sum`` of the
entries of an ideal, matrix or intvec, ``deleteSublist``, and prime factors (``primefactors``, built in, and
``primecoeffs``).  (``binomial`` is in :mod:`mech.stdlib.crt`.)"""
from __future__ import annotations

from fractions import Fraction
from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.intmat import IntMat
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, List, Matrix, Number
from ..kernel import Poly
from ..kernel.coeffs import RationalField
from .polyops import prime

LIB = "general.lib"
_LOWER = "abcdefghijklmnopqrstuvwxyz"


def _letters(s: str, n: int) -> list[str]:
    alphabet = _LOWER if s in _LOWER else _LOWER.upper()
    if len(s) != 1 or s not in alphabet or not (-26 <= n <= 26 and n != 0):
        raise MechRuntimeError(f'A_Z("a", n) needs one letter and 0 < |n| <= 26, not ("{s}", {n})')
    k = alphabet.index(s)
    step = 1 if n > 0 else -1
    return [alphabet[(k + step * i) % 26] for i in range(abs(n))]


@command("A_Z", lib=LIB)
def a_z(s: str, n: int) -> str:
    """A_Z("a", n): n letters from a on, comma separated (backwards for n < 0), wrapping round the
    alphabet; capitals for a capital letter.

    Example:
      LIB "general.lib";
      A_Z("x", 4);
      → x,y,z,a
      A_Z("C", -3);
      → C,B,A
    """
    return ",".join(_letters(s, n))


@command("A_Z_L", lib=LIB)
def a_z_l(s: str, n: int) -> List:
    """A_Z_L("a", n): the list of the letters A_Z("a", n) gives.

    Example:
      LIB "general.lib";
      A_Z_L("c", 2);
      → [1]:
      →    c
      → [2]:
      →    d
    """
    return List(_letters(s, n))


#: The printable ASCII characters, 32 to 126.
_PRINTABLE = "".join(chr(k) for k in range(32, 127))


def _ascii_table() -> str:
    """The characters 32..126 in rows of 15 above their codes, each after the first right-aligned in
    five places.  Singular's table shows the code 106 as ``10`` (its text cuts it): kept, for equal
    output."""
    lines = []
    for start in range(32, 127, 15):
        codes = list(range(start, min(start + 15, 127)))
        lines.append("".join(chr(c) if i == 0 else f"{chr(c):>5}" for i, c in enumerate(codes)))
        nums = "".join(str(c) if i == 0 else f"{c:>5}" for i, c in enumerate(codes))
        lines.append(nums.replace("  106", "  10"))
    return "\n".join(lines) + " "


@command("ASCII", lib=LIB)
def ascii_(*nm: int) -> str:
    """ASCII(): the table of the printable ASCII characters and their codes; ASCII(n): the character
    of code n; ASCII(n, m): the characters of codes n to m (32 <= n <= m <= 126).

    Example:
      LIB "general.lib";
      ASCII(65);
      → A
      ASCII(97, 102);
      → abcdef
    """
    if not nm:
        return _ascii_table()
    if len(nm) > 2 or not all(32 <= k <= 126 for k in nm):
        raise MechRuntimeError("ASCII(n[, m]) takes codes of printable characters, 32 <= n <= m <= 126")
    lo, hi = nm[0], nm[-1]
    return _PRINTABLE[lo - 32:hi - 31]


def _sign(c: Any) -> int:
    """The sign Singular's comparison with 0 gives: of an integer or of a rational number; other
    values (polynomials, elements of Z/p and of parameter fields) count as positive."""
    if isinstance(c, Poly) and c.is_constant():
        c = Number(c.ring, c.coeff_of(c.ring.zero_exp))
    if isinstance(c, Number) and isinstance(c.ring.field, RationalField):
        c = Fraction(c.to_fraction())
    if isinstance(c, (int, Fraction)):
        return (c > 0) - (c < 0)
    return 1


@command("absValue", lib=LIB)
def abs_value(c: int | Number | Poly) -> Any:
    """absValue(c): the absolute value of the int, number or constant polynomial c (c itself when
    c >= 0, else -c).

    Example:
      LIB "general.lib";
      absValue(-7);
      → 7
      ring r = 0,x,dp;
      absValue(-3/4);
      → 3/4
    """
    if _sign(c) >= 0:
        return c
    if isinstance(c, Number):
        return Number(c.ring, -c.c)
    return -c


@command("factorial", lib=LIB)
def factorial(n: int) -> int:
    """factorial(n): n! (an integer of any size).

    Example:
      LIB "general.lib";
      factorial(20);
      → 2432902008176640000
    """
    import math
    if n < 0:
        raise MechRuntimeError("factorial(n) needs n >= 0")
    return math.factorial(n)


@command("fibonacci", lib=LIB)
def fibonacci(n: int) -> int:
    """fibonacci(n): the n-th Fibonacci number (0, 1, 1, 2, 3, 5... from n = 0).

    Example:
      LIB "general.lib";
      fibonacci(10);
      → 55
    """
    a, b = 0, 1
    for _ in range(max(n, 0)):
        a, b = b, a + b
    return a


@command("primes", lib=LIB)
def primes(n: int, m: int) -> IntVec:
    """primes(n, m): the primes p with prime(n) <= p <= m, increasing; for m < n the primes from
    prime(m) to n, decreasing (prime(k): the largest prime <= k, 2 for k < 2).

    Example:
      LIB "general.lib";
      primes(10, 20);
      → 7,11,13,17,19
      primes(7, 1);
      → 7,5,3,2
    """
    lo, hi = min(n, m), max(n, m)
    p, q = prime(lo), prime(hi)
    out = []
    while q >= p:
        out.append(q)
        if q == 2:
            break
        q = prime(q - 1)
    return IntVec(out if m < n else out[::-1])


def _entries(x: Any) -> list[Any]:
    if isinstance(x, Ideal):
        return list(x.gens)
    if isinstance(x, Matrix):
        return list(x.entries)
    if isinstance(x, IntMat):
        return list(x.values)
    if isinstance(x, IntVec):
        return list(x.values)
    if isinstance(x, List):
        return list(x.items)
    if getattr(type(x), "type_name", "") == "vector":  # a vector's entries
        return list(x.entries)
    return [x]


def _selected(args: tuple[Any, ...], cmd: str) -> list[Any]:
    """The entries product and sum combine: of the one argument x (an ideal, matrix row by row, intvec,
    intmat or list) or of the arguments, those at the positions of a last intvec argument
    (None when one is outside)."""
    args = list(args)
    v = args.pop() if len(args) > 1 and isinstance(args[-1], (IntVec, int)) else None
    if not args:
        raise MechRuntimeError(f"{cmd} needs something to combine")
    ents = _entries(args[0]) if len(args) == 1 else args
    if v is not None:
        pos = list(v) if isinstance(v, IntVec) else [v]
        if any(not 1 <= k <= len(ents) for k in pos):
            return None
        ents = [ents[k - 1] for k in pos]
    return ents


@command("product", lib=LIB)
def product(*args: Any) -> Any:
    """product(x[, v]): the product of the entries of the ideal, matrix (row by row), intvec, intmat or
    list x, or of those at the positions in the intvec v (1 when a position is outside x); product(a,
    b, ...[, v]): of the arguments.

    Example:
      LIB "general.lib";
      ring r = 0,(x,y,z),dp;
      product(maxideal(1));
      → xyz
      product(intvec(2,3,4), 2..3);
      → 12
    """
    ents = _selected(args, "product")
    if ents is None:
        return 1
    out = ents[0]
    for e in ents[1:]:
        out = out * e
    return out


@command("sum", lib=LIB)
def sum_(*args: Any) -> Any:
    """sum(x[, v]): the sum of the entries of the ideal, matrix (row by row), intvec, intmat or list x,
    or of those at the positions in the intvec v (0 when a position is outside x); sum(a, b, ...[, v]):
    of the arguments.

    Example:
      LIB "general.lib";
      ring r = 0,(x,y,z),dp;
      sum(maxideal(1));
      → x+y+z
      sum(intvec(1..100));
      → 5050
    """
    ents = _selected(args, "sum")
    if ents is None:
        return 0
    out = ents[0]
    for e in ents[1:]:
        out = out + e
    return out


@command("deleteSublist", lib=LIB)
def delete_sublist(v: IntVec, L: List) -> List:
    """deleteSublist(v, L): the list L without the entries at the positions in the intvec v.

    Example:
      LIB "general.lib";
      deleteSublist(intvec(1,3), list(1,2,3,4));
      → [1]:
      →    2
      → [2]:
      →    4
    """
    drop = set(v)
    return List([x for i, x in enumerate(L.items, 1) if i not in drop])


def _e_digits(n: int) -> list[int]:
    """The first n+1 decimal digits of e - 2 (truncated), by Sale's mixed-radix algorithm: e - 2 is
    0.111... in the radix 2, 3, 4, ...; times 10 with carries from the right gives each next digit."""
    frac = [1] * (n + 1)  # the digits of e - 2 in the radix 2, 3, ..., n + 2
    out = []
    for _ in range(n + 1):
        carry = 0
        for m in range(n, -1, -1):
            s = frac[m] * 10 + carry
            carry, frac[m] = divmod(s, m + 2)
        out.append(carry)
    return out


@command("number_e", lib=LIB)
def number_e(ctx, n: int) -> Any:
    """number_e(n): Euler's number e to n decimal places by Sale's algorithm with n+1 places (as
    Singular: the last places are not exact): a string without a basering of characteristic 0, else
    the rational number of n+1 decimals.

    Example:
      LIB "general.lib";
      number_e(5);
      → 2.7182
      ring r = 0,t,dp;
      number_e(5);
      → 2718253/1000000
    """
    digits = _e_digits(n)
    ring = ctx.ring
    if ring is not None and ring.poly.field.characteristic == 0:
        value = 2 + Fraction(int("".join(map(str, digits))), 10 ** len(digits))
        poly = ring.poly
        return Number(poly, poly.field(value.numerator) / poly.field(value.denominator))
    return ("2." + "".join(map(str, digits)))[:n + 1]


@command("primefactors")
def primefactors(n: int | Number, bound: int | None = None) -> List:
    """primefactors(n[, p]): the list of the prime factors of the integer n (with bound p: those up
    to p, by trial division), their multiplicities, and the factor left (the sign, 0 for n = 0, or
    the cofactor without prime factors up to p).

    Example:
      primefactors(-360);
      → [1]:
      →    [1]:
      →       2
      →    [2]:
      →       3
      →    [3]:
      →       5
      → [2]:
      →    [1]:
      →       3
      →    [2]:
      →       2
      →    [3]:
      →       1
      → [3]:
      →    -1
    """
    import flint
    n = int(n)
    if n == 0:
        return List([List(), List(), 0])
    sign, rest = (-1 if n < 0 else 1), abs(n)
    if bound is None:
        pairs = [(int(p), int(e)) for p, e in flint.fmpz(rest).factor()] if rest > 1 else []
        return List([List([p for p, _ in pairs]), List([e for _, e in pairs]), sign])
    pairs, p = [], 2
    while p <= bound and rest > 1:
        e = 0
        while rest % p == 0:
            rest //= p
            e += 1
        if e:
            pairs.append((p, e))
        p += 1
        while not flint.fmpz(p).is_prime():
            p += 1
    if 1 < rest < (bound + 1) ** 2:  # no prime factor up to the bound: a prime itself
        pairs.append((rest, 1))
        rest = 1
    return List([List([p for p, _ in pairs]), List([e for _, e in pairs]), sign * rest])


def _coefficients(x: Any) -> list[int]:
    if isinstance(x, (int, IntVec, IntMat)):
        return [int(v) for v in _entries(x)]
    polys = _entries(x)
    out = []
    for p in polys:
        for c in (p.terms.values() if isinstance(p, Poly) else [p.c]):
            out.append(int(Number(p.ring, c)))
    return out


@command("primecoeffs", lib=LIB)
def primecoeffs(ctx, J: Any, bound: int = 32003) -> List:
    """primecoeffs(J[, p]): the list of the intvec of the prime factors up to p (default 32003) of
    the coefficients of J (a poly, ideal, matrix, int or intvec) and the factors left of them (an
    intvec without a basering, else an ideal), each once.

    Example:
      LIB "general.lib";
      primecoeffs(intvec(12, 45));
      → [1]:
      →    2,3,5
      → [2]:
      →    1
    """
    bound = min(bound, 32003)
    primes: set[int] = set()
    rests: list[int] = []
    for c in dict.fromkeys(c for c in _coefficients(J) if c):
        found = primefactors(c, bound)
        primes.update(found.items[0].items)
        if found.items[2] not in rests:
            rests.append(found.items[2])
    ring = ctx.ring
    if ring is None:
        return List([IntVec(sorted(primes)), IntVec(rests)])
    poly = ring.poly
    return List([IntVec(sorted(primes)), Ideal(poly, [poly.const(r) for r in rests] or [poly.zero()])])

