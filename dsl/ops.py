"""Operators of the language on values, with Singular's semantics.

``int`` arithmetic truncates like C (``-7 div 2 == -3``, ``-7 mod 3 == -1``); ``/`` between ints is
integer division (Singular warns); mixed int/number/poly operands are promoted to the larger type
in the basering; ideals add (generators joined, zeros and repeated multiples dropped) and multiply
(pairwise products); matrices add and multiply as matrices.
"""
from __future__ import annotations

from typing import Any, Callable, Optional

from ..kernel import Poly, PolyRing
from .errors import MechRuntimeError, MechTypeError
from .intmat import IntMat, euclid_div, intmat_op
from .minpoly import compare_params
from .convert_modules import to_module, to_vector
from .values_modules import Module, Vector, matrix_entries
from .values import (BigInt, ExprList, Ideal, IntVec, List, Matrix, Number, Ring, same_value, to_ideal, to_number,
                     to_poly, typeof)

Warn = Callable[[str], None]


def trunc_div(a: int, b: int) -> int:
    if b == 0:
        raise MechRuntimeError("division by 0")
    q = abs(a) // abs(b)
    return q if (a >= 0) == (b >= 0) else -q


def trunc_mod(a: int, b: int) -> int:
    return a - b * trunc_div(a, b)


_INTS = (int, BigInt)


def _rank(v: Any) -> int:
    if isinstance(v, int):
        return 0
    if isinstance(v, Number):
        return 1
    if isinstance(v, Poly):
        return 2
    return -1


def _bad(op: str, a: Any, b: Any) -> MechTypeError:
    return MechTypeError(f"operator {op} is not defined for {typeof(a)} and {typeof(b)}")


def _ring(a: Any, b: Any, ring: Optional[PolyRing]) -> Optional[PolyRing]:
    for v in (a, b):
        r = getattr(v, "ring", None)
        if isinstance(r, PolyRing):
            return r
    return ring


def _scalar(op: str, a: Any, b: Any, ring: Optional[PolyRing]) -> Any:
    """``a op b`` for int/number/poly operands (at least one not an int)."""
    ring = _ring(a, b, ring)
    rank = max(_rank(a), _rank(b))
    if rank == 1:
        x, y = to_number(a, ring).c, to_number(b, ring).c
        if op == "+":
            return Number(ring, x + y)
        if op == "-":
            return Number(ring, x - y)
        if op == "*":
            return Number(ring, x * y)
        if op == "/":
            if y == 0:
                raise MechRuntimeError("division by 0")
            return Number(ring, x / y)
        raise _bad(op, a, b)
    x, y = to_poly(a, ring), to_poly(b, ring)
    if op == "+":
        return x + y
    if op == "-":
        return x - y
    if op == "*":
        return x * y
    if op in ("/", "div"):
        return poly_quotient(x, y)
    raise _bad(op, a, b)


def poly_quotient(f: Poly, g: Poly) -> Poly:
    """Singular's ``f / g``: the quotient of dividing ``f`` by ``g`` (a remainder is dropped)."""
    if g.is_zero():
        raise MechRuntimeError("division by 0")
    if g.is_constant():
        return f / g.lc()
    ring = f.ring
    glm, glc = g.lm(), g.lc()
    q, r = ring.zero(), f
    while not r.is_zero():
        e = r.lm()
        if all(a >= b for a, b in zip(e, glm)):
            t = ring.monomial(tuple(a - b for a, b in zip(e, glm)), r.terms[e] / glc)
            q, r = q + t, r - t * g
        else:
            r = r - r.lt()
    return q


def _simplify(gens: list[Poly], multiples: bool) -> list[Poly]:
    """Drop zero generators and repeated ones (with ``multiples``: constant multiples of earlier ones)."""
    out: list[Poly] = []
    seen_monic: set = set()
    for g in gens:
        if g.is_zero():
            continue
        k = g.monic() if multiples else g
        sig = frozenset(k.terms.items())
        if sig in seen_monic:
            continue
        seen_monic.add(sig)
        out.append(g)
    return out


def _compactify(ring: PolyRing, gens: list[Poly]) -> list[Poly]:
    """Singular's id_Compactify: the unit ideal ``1`` if a generator is a unit (its leading monomial
    is 1 in the ring's ordering), else without zeros and constant multiples of earlier generators."""
    if any(not g.is_zero() and not any(g.lm()) for g in gens):
        return [ring.one()]
    return _simplify(gens, True)


def _ideal_op(op: str, a: Any, b: Any, ring: Optional[PolyRing]) -> Any:
    ring = _ring(a, b, ring)
    if op == "+":
        ia, ib = to_ideal(a, ring), to_ideal(b, ring)
        return Ideal(ring, _compactify(ring, list(ia.gens) + list(ib.gens)))
    if op == "*":
        if isinstance(a, Ideal) and isinstance(b, Ideal):
            return Ideal(ring, _compactify(ring, [f * g for f in a.gens for g in b.gens]))
        if isinstance(a, Ideal):
            p = to_poly(b, ring)
            return Ideal(ring, [g * p for g in a.gens])
        p = to_poly(a, ring)
        return Ideal(ring, [p * g for g in b.gens])
    raise _bad(op, a, b)


def _matrix_op(op: str, a: Any, b: Any, ring: Optional[PolyRing]) -> Matrix:
    ring = _ring(a, b, ring)
    if isinstance(a, Matrix) and isinstance(b, Matrix):
        if op in ("+", "-"):
            if (a.nrows, a.ncols) != (b.nrows, b.ncols):
                raise MechRuntimeError(f"matrix sizes do not match ({a.nrows}x{a.ncols}, {b.nrows}x{b.ncols}) in {op}")
            f = (lambda x, y: x + y) if op == "+" else (lambda x, y: x - y)
            return Matrix(ring, a.nrows, a.ncols, [f(x, y) for x, y in zip(a.entries, b.entries)])
        if op == "*":
            if a.ncols != b.nrows:
                raise MechRuntimeError(f"matrix sizes not compatible ({a.nrows}x{a.ncols}, {b.nrows}x{b.ncols}) in *")
            out = []
            for i in range(1, a.nrows + 1):
                for j in range(1, b.ncols + 1):
                    s = ring.zero()
                    for k in range(1, a.ncols + 1):
                        s = s + a.get(i, k) * b.get(k, j)
                    out.append(s)
            return Matrix(ring, a.nrows, b.ncols, out)
        raise _bad(op, a, b)
    if op in ("+", "-", "*") and isinstance(a, Matrix) and isinstance(b, Ideal):  # the ideal as a 1 x n matrix
        return _matrix_op(op, a, Matrix(ring, 1, len(b.gens), list(b.gens)), ring)
    if op in ("+", "-") and isinstance(a, Matrix) and _rank(b) >= 0:  # Singular: b times the unit matrix
        p = to_poly(b, ring)
        ents = list(a.entries)
        for i in range(min(a.nrows, a.ncols)):
            ents[i * a.ncols + i] = ents[i * a.ncols + i] + p if op == "+" else ents[i * a.ncols + i] - p
        return Matrix(ring, a.nrows, a.ncols, ents)
    if op == "+" and isinstance(b, Matrix) and _rank(a) >= 0:
        return _matrix_op(op, b, a, ring)
    if op == "-" and isinstance(b, Matrix) and _rank(a) >= 0:  # as Singular: a as a 1 x 1 matrix
        return _matrix_op(op, Matrix(ring, 1, 1, [to_poly(a, ring)]), b, ring)
    if op == "*" and _rank(b) >= 0 and isinstance(a, Matrix):
        p = to_poly(b, ring)
        return Matrix(ring, a.nrows, a.ncols, [x * p for x in a.entries])
    if op == "*" and _rank(a) >= 0 and isinstance(b, Matrix):
        p = to_poly(a, ring)
        return Matrix(ring, b.nrows, b.ncols, [p * x for x in b.entries])
    raise _bad(op, a, b)


def _intvec_op(op: str, a: Any, b: Any) -> Any:
    if isinstance(a, IntVec) and isinstance(b, IntVec):
        if op in ("+", "-"):
            n = max(len(a), len(b))
            x = list(a.values) + [0] * (n - len(a))
            y = list(b.values) + [0] * (n - len(b))
            return IntVec([u + v if op == "+" else u - v for u, v in zip(x, y)])
        raise _bad(op, a, b)
    if isinstance(a, IntVec) and isinstance(b, int):
        fn = {"+": lambda u: u + b, "-": lambda u: u - b, "*": lambda u: u * b,
              "/": lambda u: euclid_div(u, b), "div": lambda u: euclid_div(u, b),
              "mod": lambda u: u - b * euclid_div(u, b)}.get(op)
    elif isinstance(a, int) and isinstance(b, IntVec) and op in ("+", "*"):
        return _intvec_op(op, b, a)
    else:
        fn = None
    if fn is None:
        raise _bad(op, a, b)
    return IntVec([fn(u) for u in a.values])


def binary(op: str, a: Any, b: Any, ring: Optional[PolyRing], warn: Warn) -> Any:
    """``a op b`` for the arithmetic operators ``+ - * / div mod ^ :``."""
    if (type(a) is BigInt or type(b) is BigInt) and type(a) in _INTS and type(b) in _INTS:
        return _bigint_op(op, a, b)
    if type(a) is int and type(b) is int:
        if op == "+":
            return a + b
        if op == "-":
            return a - b
        if op == "*":
            return a * b
        if op == "/":
            warn("int division with `/`: use `div` instead")
            return trunc_div(a, b)
        if op == "div":
            return trunc_div(a, b)
        if op == "mod":
            if b == 0:
                raise MechRuntimeError("division by 0")
            return trunc_mod(a, b)
        if op == "^":
            if b < 0:
                raise MechRuntimeError("negative exponent for an int")
            _check_power(abs(a).bit_length(), b, MAX_INT_BITS, "int")
            return a ** b
        if op == ":":
            if b < 0:
                raise MechRuntimeError("negative repetition count")
            return IntVec([a] * b)
    if op == "^":
        return power(a, b)
    if isinstance(a, (Vector, Module)) or isinstance(b, (Vector, Module)):
        return module_binary(op, a, b, ring)
    if isinstance(a, IntMat) or isinstance(b, IntMat):
        return intmat_op(op, a, b)
    if isinstance(a, (IntVec,)) or isinstance(b, IntVec):
        return _intvec_op(op, a, b)
    if op == "+" and any(isinstance(x, Ideal) for x in (a, b)) and \
            any(isinstance(x, Matrix) and x.nrows == 1 for x in (a, b)):  # a rank-1 module: the ideal's sum
        return _ideal_op(op, *(Ideal(x.ring, x.entries) if isinstance(x, Matrix) else x for x in (a, b)), ring)
    if isinstance(a, Matrix) or isinstance(b, Matrix):
        return _matrix_op(op, a, b, ring)
    if isinstance(a, Ideal) or isinstance(b, Ideal):
        return _ideal_op(op, a, b, ring)
    if op == "+":
        if isinstance(a, str) and isinstance(b, str):
            return a + b
        if isinstance(a, Ring) and isinstance(b, Ring):
            from .rings import ring_sum
            return ring_sum(a, b)
        if isinstance(a, List) and isinstance(b, List):
            return List(a.items + b.items)
    if _rank(a) >= 0 and _rank(b) >= 0:
        if op == "mod" and isinstance(a, Poly):
            raise _bad(op, a, b)
        return _scalar(op, a, b, ring)
    raise _bad(op, a, b)


MAX_INT_BITS = 1 << 20     # powers beyond these sizes are refused: computed in one C call, they would
MAX_COEFF_BITS = 1 << 26   # take minutes that no time limit can interrupt (3^99999999)


def _check_power(bits: int, k: int, limit: int, what: str) -> None:
    if bits > 1 and k > 1 and bits * k > limit:
        raise MechRuntimeError(f"{what} too large: the power would have about {bits * k} bits (at most {limit})")


def _coeff_bits(c: Any) -> int:
    """The size of a rational coefficient in bits (0 for others: modular ones stay small)."""
    num, den = getattr(c, "p", None), getattr(c, "q", None)
    if hasattr(num, "bit_length") and hasattr(den, "bit_length"):
        return max(int(num.bit_length()), int(den.bit_length()))
    return 0


def power(a: Any, k: Any) -> Any:
    if not isinstance(k, int):
        raise MechTypeError(f"operator ^ needs an int exponent, not {typeof(k)}")
    if isinstance(a, Number) or (isinstance(a, Poly) and len(a.terms) == 1):
        _check_power(_coeff_bits(a.c if isinstance(a, Number) else a.lc()), abs(k), MAX_COEFF_BITS, "number")
    try:  # flint refuses sizes it cannot represent (rational functions of parameters)
        if isinstance(a, Number):
            if k < 0:
                if a.c == 0:
                    raise MechRuntimeError("division by 0")
                return Number(a.ring, (a.ring.field.one / a.c) ** (-k))
            return Number(a.ring, a.c ** k)
        if isinstance(a, Poly):
            if k < 0:
                raise MechRuntimeError("negative exponent for a poly")
            return a ** k
    except (ValueError, OverflowError) as e:
        if "large" not in str(e) and not isinstance(e, OverflowError):
            raise
        raise MechRuntimeError(f"{typeof(a)} too large: the power {k} cannot be represented") from None
    if isinstance(a, Ideal):
        if k < 0:
            raise MechRuntimeError("negative exponent for an ideal")
        gens = [a.ring.one()]  # all k-fold products, without zeros and repetitions (Singular's id_Power)
        for _ in range(k):
            gens = [f * g for f in gens for g in a.gens]
        return Ideal(a.ring, _simplify(gens, False) or [a.ring.zero()])
    if isinstance(a, Matrix) and a.nrows == a.ncols and k >= 0:
        result = Matrix(a.ring, a.nrows, a.ncols, [a.ring.one() if i == j else a.ring.zero()
                                                   for i in range(a.nrows) for j in range(a.ncols)])
        for _ in range(k):
            result = _matrix_op("*", result, a, a.ring)
        return result
    raise MechTypeError(f"operator ^ is not defined for {typeof(a)} and int")


def _bigint_op(op: str, a: int, b: int) -> Any:
    """``a op b`` with a bigint operand: a bigint; div, / and mod Euclidean as Singular's bigint."""
    if op in ("div", "/", "mod", "%") and b == 0:
        raise MechRuntimeError("division by 0")
    if op == "+":
        return BigInt(a + b)
    if op == "-":
        return BigInt(a - b)
    if op == "*":
        return BigInt(a * b)
    if op in ("div", "/"):
        return BigInt(euclid_div(a, b))
    if op in ("mod", "%"):
        return BigInt(a % abs(b))
    if op == "^":
        if b < 0:
            raise MechRuntimeError("negative exponent for a bigint")
        _check_power(abs(a).bit_length(), b, MAX_INT_BITS, "bigint")
        return BigInt(a ** b)
    raise _bad(op, a, b)


def negate(a: Any) -> Any:
    if isinstance(a, int):
        return -a
    if isinstance(a, Number):
        return Number(a.ring, -a.c)
    if isinstance(a, Poly):
        return -a
    if isinstance(a, Matrix):
        return Matrix(a.ring, a.nrows, a.ncols, [-x for x in a.entries])
    if isinstance(a, IntVec):
        return IntVec([-x for x in a.values])
    if isinstance(a, (Vector, Module)):
        return module_negate(a)
    if isinstance(a, IntMat):
        return IntMat(a.nrows, a.ncols, [-x for x in a.values])
    raise MechTypeError(f"unary minus is not defined for {typeof(a)}")


def truth(v: Any) -> bool:
    """An int used as a condition."""
    if isinstance(v, int):
        return v != 0
    if isinstance(v, Number):
        return v.c != 0
    if isinstance(v, Poly) and v.is_constant():
        return not v.is_zero()
    raise MechTypeError(f"a condition must be an int, not {typeof(v)}")


def _sort_number(n: Number) -> Any:
    if n.ring.field.characteristic:
        return int(n.c)  # Singular compares Z/p elements by their representatives in [0, p)
    return n.c


def compare(op: str, a: Any, b: Any, ring: Optional[PolyRing]) -> int:
    """``a op b`` for ``== != < <= > >=`` (1 or 0)."""
    if isinstance(a, ExprList) or isinstance(b, ExprList):
        raise MechTypeError("cannot compare expression lists")
    for m, other in ((a, b), (b, a)):  # a 1 x 1 matrix against a polynomial: its entry (as Singular)
        if isinstance(m, Matrix) and m.nrows == m.ncols == 1 and op in ("==", "!=") and _rank(other) >= 0:
            return compare(op, m.entries[0], other, ring)
    if type(a) in _INTS and type(b) in _INTS or (isinstance(a, str) and isinstance(b, str)):
        x, y = a, b
    elif _rank(a) >= 0 and _rank(b) >= 0:
        ring = _ring(a, b, ring)
        if max(_rank(a), _rank(b)) == 1:
            if getattr(ring.field, "params", ()):
                x, y = to_number(a, ring).c, to_number(b, ring).c
                if op not in ("==", "!="):
                    return compare_params(op, x, y)
            else:
                x, y = _sort_number(to_number(a, ring)), _sort_number(to_number(b, ring))
        else:
            p, q = to_poly(a, ring), to_poly(b, ring)
            if op in ("==", "!="):
                return int((p == q) == (op == "=="))
            x, y = _poly_cmp(p, q), 0
    elif op in ("==", "!=") and isinstance(a, IntMat) and isinstance(b, IntMat):
        return int((a == b) == (op == "=="))
    elif op in ("==", "!=") and type(a) is type(b) and isinstance(a, (Ideal, Matrix, IntVec, List, Vector, Module)):
        return int(same_value(a, b) == (op == "=="))
    elif isinstance(a, IntVec) and isinstance(b, IntVec):
        x, y = a.values, b.values
    else:
        raise MechTypeError(f"cannot compare {typeof(a)} and {typeof(b)}")
    if op == "==":
        return int(x == y)
    if op == "!=":
        return int(x != y)
    if op == "<":
        return int(x < y)
    if op == "<=":
        return int(x <= y)
    if op == ">":
        return int(x > y)
    return int(x >= y)


def _poly_cmp(p: Poly, q: Poly) -> int:
    """Singular's order of polynomials: constants as numbers; else by leading monomial (0 below every
    monomial), then by the sign
    of the difference of the leading coefficients (over Z/p its symmetric representative: ``6x > x`` is
    0 in Z/7); the other terms do not count (``x+2 > x+1`` is 0)."""
    field = p.ring.field
    if p.is_constant() and q.is_constant():  # as numbers: a constant's sign counts, 0 is no monomial
        x, y = p.coeff_of(p.ring.zero_exp), q.coeff_of(q.ring.zero_exp)
        if getattr(field, "params", ()):  # as Singular orders numbers with parameters
            return 1 if compare_params(">", x, y) else -1 if compare_params(">", y, x) else 0
        d = x - y
    elif p.is_zero() or q.is_zero():
        return int(not p.is_zero()) - int(not q.is_zero())
    else:
        a, b = p.ring.order.key(p.lm()), p.ring.order.key(q.lm())
        if a != b:
            return 1 if a > b else -1
        d = p.lc() - q.lc()  # Singular asks whether the difference is positive
    if not d:
        return 0
    if getattr(field, "params", ()):
        return 1 if compare_params(">", d, field.zero) else -1
    if field.characteristic:
        return 1 if field.symmetric(d) > 0 else -1
    return 1 if d > 0 else -1


# ---------------------------------------------------------------- vectors and modules
def _is_scalar(v: Any) -> bool:
    return isinstance(v, (int, Number, Poly)) and not isinstance(v, bool)


def _add(v: Vector, w: Vector, sign: int) -> Vector:
    n = max(v.nrows, w.nrows)
    return Vector(v.ring, [a + b if sign > 0 else a - b for a, b in zip(v.padded(n), w.padded(n))])


def module_binary(op: str, a: Any, b: Any, ring: Optional[PolyRing]) -> Any:
    """``a op b`` where a or b is a vector or a module."""
    ring = getattr(a, "ring", None) or getattr(b, "ring", None) or ring
    if op == "+" and (isinstance(a, Ideal) and isinstance(b, Vector) or isinstance(a, Vector) and isinstance(b, Ideal)):
        return _sum(to_module(a, ring), to_module(b, ring))  # as modules (Singular)
    if op == "*" and isinstance(a, Ideal) and isinstance(b, Vector):  # I*v: the module of the g*v
        return Module(ring, [Vector(ring, [g * x for x in b.entries]) for g in a.gens])
    if op == "*" and isinstance(a, Vector) and isinstance(b, Ideal):
        return module_binary(op, b, a, ring)
    if op in ("+", "-") and isinstance(a, Matrix):  # as matrices (Singular; M + A is a module sum)
        a2, b2 = (Matrix(ring, *matrix_entries(x)) if isinstance(x, (Module, Vector)) else x for x in (a, b))
        return binary(op, a2, b2, ring, lambda _m: None)
    if op == "*" and isinstance(a, Ideal) and isinstance(b, Module):  # I*M: f*m for f in I, m in M
        return Module(ring, [Vector(ring, [f * x for x in m.entries]) for f in a.gens for m in b.gens], b.rank)
    if op == "*" and isinstance(a, Module) and isinstance(b, Ideal):  # M*I: m*f for m in M, f in I
        return Module(ring, [Vector(ring, [x * f for x in m.entries]) for m in a.gens for f in b.gens], a.rank)
    if op == "*" and isinstance(a, Module) and isinstance(b, Module):
        raise MechTypeError("module * module: Singular has no product of two submodules of a free module")
    if op == "*" and isinstance(a, (Module, Vector)) and isinstance(b, (Module, Vector)):  # as matrices
        mats = [Matrix(ring, *matrix_entries(x if isinstance(x, Module) else Module(ring, [x]))) for x in (a, b)]
        return binary("*", mats[0], mats[1], ring, lambda _m: None)
    if isinstance(a, Module) or isinstance(b, Module):
        if op == "+" and all(isinstance(x, (Module, Vector, Ideal, Matrix)) for x in (a, b)):
            return _sum(to_module(a, ring), to_module(b, ring))
        if op == "*" and isinstance(a, Module) and _is_scalar(b):
            p = to_poly(b, ring)
            return Module(ring, [Vector(ring, [x * p for x in g.entries]) for g in a.gens], a.rank)
        if op == "*" and isinstance(b, Module) and _is_scalar(a):
            return module_binary("*", b, a, ring)
        if op == "*" and isinstance(a, Matrix) and isinstance(b, Module):
                return binary("*", a, Matrix(ring, *matrix_entries(b)), ring, lambda _m: None)
        if op == "*" and isinstance(a, Module) and isinstance(b, Matrix):  # the module as its matrix
            return binary("*", Matrix(ring, *matrix_entries(a)), b, ring, lambda _m: None)
        raise _bad(op, a, b)
    if op in ("+", "-") and (isinstance(a, Vector) or _is_scalar(a)) and (isinstance(b, Vector) or _is_scalar(b)):
        return _add(to_vector(a, ring), to_vector(b, ring), 1 if op == "+" else -1)
    if op == "*" and _is_scalar(a) and isinstance(b, Vector):
        p = to_poly(a, ring)
        return Vector(ring, [p * x for x in b.entries])
    if op == "*" and isinstance(a, Vector) and _is_scalar(b):
        return module_binary("*", b, a, ring)
    if op in ("/", "div") and isinstance(a, Vector) and _is_scalar(b):
        p = to_poly(b, ring)
        return Vector(ring, [poly_quotient(x, p) for x in a.entries])
    if op == "*" and isinstance(a, Matrix) and isinstance(b, Vector):
        return binary("*", a, Matrix(ring, *matrix_entries(Module(ring, [b], a.ncols))), ring, lambda _m: None)
    raise _bad(op, a, b)


def _sum(a: Module, b: Module) -> Module:
    """M + N: the generators of both, without zeros and repeated generators (as Singular)."""
    gens: list[Vector] = []
    for g in a.gens + b.gens:
        if not g.is_zero() and g not in gens:
            gens.append(g)
    return Module(a.ring, gens, max(a.rank, b.rank))


def module_negate(a: Vector | Module) -> Vector | Module:
    if isinstance(a, Vector):
        return Vector(a.ring, [-x for x in a.entries])
    return Module(a.ring, [Vector(a.ring, [-x for x in g.entries]) for g in a.gens], a.rank)
