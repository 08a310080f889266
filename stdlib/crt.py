"""Chinese remaindering and rational reconstruction, coefficient by coefficient (Singular's
``chinrem`` and ``farey``): the lifting steps of modular methods; and ``binomial`` (general.lib)."""
from __future__ import annotations

from math import gcd as int_gcd
from typing import Any, Callable

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import BigInt, Ideal, IntVec, List, Matrix, Number
from ..kernel import Poly


def _crt(residues: list[int], moduli: list[int]) -> tuple[int, int]:
    """(x, m): the least non-negative x with x = residues[i] mod moduli[i], m the product."""
    x, m = 0, 1
    for v, n in zip(residues, moduli):
        if int_gcd(m, n) != 1:
            raise MechRuntimeError("chinrem: the moduli must be pairwise coprime")
        x += m * ((v - x) * pow(m, -1, n) % n)
        m *= n
    return x % m, m


def _symmetric(x: int, m: int) -> int:
    return x - m if 2 * x > m else x


def _integer(c: Any) -> int:
    """A coefficient of QQ that is an integer, as a Python int."""
    if int(c.q) != 1:
        raise MechRuntimeError(f"chinrem: the coefficients must be integers, not {c}")
    return int(c.p)


def _entries(x: Any) -> tuple[str, list[Any], Any]:
    """(kind, entries, shape) of one residue: an int, a poly (a number is a constant poly), an ideal's
    generators or a matrix's entries."""
    if type(x) is int:
        return "int", [x], None
    if isinstance(x, Poly):
        return "poly", [x], None
    if isinstance(x, Number):
        return "poly", [x.to_poly()], None
    if isinstance(x, Ideal):
        return "ideal", list(x.gens), x.ring
    if isinstance(x, Matrix):
        return "matrix", list(x.entries), (x.ring, x.nrows, x.ncols)
    raise MechRuntimeError(f"chinrem: cannot lift a {type(x).__name__}")


def _lift_polys(polys: list[Poly], moduli: list[int], m: int) -> Poly:
    ring = polys[0].ring
    if ring.field.characteristic:
        raise MechRuntimeError("chinrem of polynomials needs a ring of characteristic 0")
    monomials = {e for p in polys for e in p.terms}
    terms = {}
    for e in monomials:
        x, _ = _crt([_integer(p.terms[e]) if e in p.terms else 0 for p in polys], moduli)
        if x:
            terms[e] = ring.field(_symmetric(x, m))
    return Poly(ring, terms)


@command("chinrem")
def chinrem(values: IntVec | List, moduli: IntVec | List) -> Any:
    """chinrem(v, m): the solution of x = v[i] mod m[i] (pairwise coprime moduli): for an intvec v the
    least non-negative int; for a list v of ints, polynomials, ideals or matrices (all of the same
    kind) the coefficient-wise solution in the symmetric range (-M/2, M/2], M the product of the m[i]
    (ideals are padded with zeros to the longest).

    Example:
      chinrem(intvec(4,3), intvec(5,7));
      → 24
      chinrem(list(4,3), list(5,7));
      → -11
      ring r = 0,x,dp;
      chinrem(list(ideal(x2+4), ideal(3x)), list(5,7));
      → _[1]=-14x2+10x+14
    """
    if isinstance(values, IntVec) and not isinstance(moduli, IntVec):
        raise MechRuntimeError("chinrem(intvec, list) is not defined (Singular: chinrem(intvec, intvec), chinrem(list, intvec|list))")
    vs, ms = list(values), [int(n) if isinstance(n, int) else n for n in moduli]
    if len(vs) != len(ms) or not vs or not all(isinstance(n, int) and not isinstance(n, bool) and n > 0 for n in ms):
        raise MechRuntimeError("chinrem(v, m): v and m of the same length, m of positive ints")
    if isinstance(values, IntVec):
        return _crt(vs, ms)[0]
    kinds = [_entries(v) for v in vs]
    kind = kinds[0][0] if all(k[0] == kinds[0][0] for k in kinds) else "mixed"
    _, m = _crt([0] * len(ms), ms)
    if kind == "int":
        return _symmetric(_crt(vs, ms)[0], m)
    if kind == "mixed" and all(k[0] in ("int", "poly") for k in kinds):  # ints among polynomials
        ring = next(k[1][0].ring for k in kinds if k[0] == "poly")
        kind, kinds = "poly", [("poly", [ring.const(ring.field(v)) if type(v) is int else v], None) for v in vs]
    if kind == "mixed" or (kind == "matrix" and len({k[2][1:] for k in kinds}) > 1):
        raise MechRuntimeError("chinrem: the residues must be all ints, polys, ideals or matrices of one size")
    size = max(len(k[1]) for k in kinds)
    columns = []
    for i in range(size):
        polys = [k[1][i] if i < len(k[1]) else k[1][0].ring.zero() for k in kinds]
        columns.append(_lift_polys(polys, ms, m))
    if kind == "poly":
        return columns[0]
    if kind == "ideal":
        return Ideal(kinds[0][2], columns)
    ring, nrows, ncols = kinds[0][2]
    return Matrix(ring, nrows, ncols, columns)


def _reconstruct(x: int, n: int) -> tuple[int, int]:
    """(a, b), b > 0, a/b = x mod n with 2a^2 < n, by the extended Euclidean algorithm on (n, x) stopped
    at the first small remainder (Wang's rational reconstruction, as Singular's farey): (0, 1) when
    the remainders reach 0, (x, 1) itself when the small remainder and its cofactor are not coprime."""
    r0, r1, s0, s1 = n, x + n if x < 0 else x, 0, 1
    while r1 != 0:
        if 2 * r1 * r1 < n:
            if s1 < 0:
                r1, s1 = -r1, -s1
            return (r1, s1) if int_gcd(r1, s1) == 1 else (x, 1)
        q, r = divmod(r0, r1)
        r0, r1, s0, s1 = r1, r, s1, s0 - q * s1
    return 0, 1


def _farey_poly(p: Poly, n: int) -> Poly:
    field = p.ring.field
    terms = {}
    for e, c in p.terms.items():
        a, b = _reconstruct(_integer(c), n)
        if a:
            terms[e] = field(a) / field(b)
    return Poly(p.ring, terms)


@command("farey")
def farey(ctx, x: int | Poly | Ideal | Matrix, n: int | BigInt) -> Any:
    """farey(x, N): the rational number a/b with a = b*x mod N and 2a^2 < N found by the extended
    Euclidean algorithm (0 when there is none, x itself when a and b are not coprime), for an integer
    x or each coefficient of a polynomial (giving an ideal, as Singular), ideal or matrix (over QQ).

    Example:
      ring r = 0,x,dp;
      farey(7, 10);
      → 1/3
      farey(7x+3, 10);
      → _[1]=1/3x-1/3
    """
    if n <= 1:
        raise MechRuntimeError("farey: the modulus must be at least 2")
    f: Callable[[Poly], Poly] = lambda p: _farey_poly(p, n)
    if isinstance(x, int):
        ring = ctx.basering().poly
        p = f(ring.const(x))
        return Number(ring, p.terms.get(ring.zero_exp, ring.field(0)))
    if isinstance(x, Poly):  # as Singular: an ideal of one generator
        return Ideal(x.ring, [f(x)])
    if isinstance(x, Ideal):
        return Ideal(x.ring, [f(p) for p in x.gens])
    return Matrix(x.ring, x.nrows, x.ncols, [f(p) for p in x.entries])


@command("binomial", lib="general.lib")
def binomial(n: int, k: int) -> int:
    """binomial(n, k): the binomial coefficient n choose k (0 unless 0 <= k <= n).

    Example:
      LIB "general.lib";
      binomial(10, 3);
      → 120
    """
    from math import comb
    return comb(n, k) if 0 <= k <= n else 0
