"""The binary operators of the Macaulay2 dialect on its values: arithmetic with the promotion of
elements between rings (an element of ``R`` meets one of ``R/I`` or of ``R[x]`` in the larger
ring; results in a quotient ring are normal forms), strict equality ``===``, ``//``, ``|`` and
``||`` (lists, strings, matrices), ``..<``, ``n : x`` (``n`` copies), quotient rings ``R / I``,
``ZZ/p`` and ``f \\ L`` / ``f @@ g`` on functions."""
from __future__ import annotations

from fractions import Fraction
from typing import Any, Callable, Optional

from ..kernel import Poly
from .errors import MechNameError, MechRuntimeError, MechTypeError
from .m2_local import LocalFraction, local_arith, localized_at, to_local
from .m2_modules import FreeModule, Map, quotient_module, rows, scaled, source_degrees
from .m2_submodules import Module, divide
from .m2_subquotients import ANY_MODULE, module_arith
from .m2_vectors import Vector, vector_arith
from .m2_rings import (M2Ring, cached_quotient, common_ring, integers, is_integral, normal, owner, promote, promotes,
                       quotient_ring)
from .m2_values import FUNCTIONS, Array, CoeffRing, Composed, M2Set, Opt, RingMap, Symbol
from .values import ExprList, Ideal, List, Matrix, Number, Ring, to_int, typeof

#: Macaulay2 symbols mech knows (option names and monomial orders)
SYMBOLS = {"MonomialOrder", "Lex", "GRevLex", "GLex", "RevLex", "Weights", "Eliminate", "ProductOrder", "GroupLex", "GroupRevLex", "Global", "Degrees",
           "Variables", "Position", "Up", "Down", "MonomialSize", "Strategy", "Verbose", "Limit", "DegreeLimit",
           "Inhomogeneous", "SubringLimit", "BasisElementLimit", "PairLimit", "Reverse"}


def ring_of(v: Any) -> Optional[M2Ring]:
    """The Macaulay2 ring of a polynomial, number, ideal or matrix (None for others)."""
    if isinstance(v, Poly):
        return owner(v)
    if isinstance(v, LocalFraction):
        return owner(v.num)
    if isinstance(v, (Number, Ideal, Matrix)):
        return getattr(v.ring, "owner", None) if not isinstance(v, Number) else getattr(v.ring, "owner", None)
    return None


def lift_to(v: Any, target: M2Ring) -> Any:
    """A polynomial or number as an element of ``target``."""
    if isinstance(v, Number):
        v = v.to_poly()
    if isinstance(v, Poly):
        return promote(v, target)
    return v


def unknown(v: Any) -> None:
    """The error for a symbol without a value used in arithmetic."""
    if isinstance(v, Symbol) and v.name not in SYMBOLS:
        raise MechNameError(f"unknown identifier '{v.name}' (a symbol without a value: not a variable of "
                            f"the current ring)")


def _tensor(a: Matrix, b: Matrix) -> Matrix:
    """``a ** b``: the tensor (Kronecker) product, entry (i r + k, j s + l) = a_ij b_kl."""
    if a.ring is not b.ring:
        b = Matrix(a.ring, b.nrows, b.ncols, [lift_to(p, a.ring.owner) for p in b.entries]) \
            if isinstance(getattr(a.ring, "owner", None), M2Ring) else b
    if a.ring is not b.ring:
        raise MechTypeError("a ** b: the matrices are over different rings")
    r, s = b.nrows, b.ncols
    entries = [a.entries[i * a.ncols + j] * b.entries[k * s + m]
               for i in range(a.nrows) for k in range(r) for j in range(a.ncols) for m in range(s)]
    if isinstance(a, Map) and isinstance(b, Map):  # degrees: sums (target, source and the maps')
        return Map(_tensor_free(a.target, b.target), _tensor_free(a.source, b.source), entries, a.degree + b.degree)
    return Matrix(a.ring, a.nrows * r, a.ncols * s, entries)


def _one_by_one(p: Poly) -> Map:
    """A ring element as a 1 x 1 matrix of degree 0 (its source of p's degree), for ``p ** f``."""
    ring = owner(p)
    if ring is None:
        raise MechTypeError("p ** f takes an element of a ring")
    return Map(FreeModule(ring, (0,)), FreeModule(ring, source_degrees(Matrix(p.ring, 1, 1, [p]), (0,))), [p], 0)


def _tensor_free(F: FreeModule, G: FreeModule) -> FreeModule:
    """``F ** G`` of free modules: the degrees' sums, F's index outer."""
    if F.ring is not G.ring:
        raise MechTypeError("F ** G: the free modules are over different rings")
    return FreeModule(F.ring, tuple(d + e for d in F.degrees for e in G.degrees))


def _frobenius(I: Ideal, e: Array) -> Ideal:
    """``I^[e1, ..., en]``: the ideal of I's generators with each own variable x_i of the ring
    replaced by x_i^e_i (``I^[e]``: the same e for all)."""
    R = getattr(I.ring, "owner", None)
    n = len(R.own) if R is not None and R.own else I.ring.nvars
    exps = [to_int(k) for k in e.items]
    if any(k < 0 for k in exps) or len(exps) not in (1, n):
        raise MechRuntimeError(f"I^[...] takes one exponent >= 0 or one per variable ({n})")
    exps = exps * n if len(exps) == 1 else exps
    scale = exps + [1] * (I.ring.nvars - n)
    gens = [normal(Poly(I.ring, {tuple(k * s for k, s in zip(t, scale)): c for t, c in g.terms.items()}))
            for g in I.gens]
    return Ideal(I.ring, [g for g in gens if not g.is_zero()])


def strictly_equal(a: Any, b: Any) -> bool:
    """``a === b``: the same value of the same type (rings: the same ring; ideals: the same generators)."""
    if isinstance(a, bool) or isinstance(b, bool):
        return a is b
    if type(a) is not type(b):
        return False
    if isinstance(a, (Ring, CoeffRing)):
        return a is b or (isinstance(a, CoeffRing) and a.characteristic == b.characteristic)
    if isinstance(a, Poly):
        return a.ring is b.ring and a == b
    if isinstance(a, Ideal):
        return a.ring is b.ring and tuple(a.gens) == tuple(b.gens)
    if isinstance(a, Matrix):
        return a.ring is b.ring and (a.nrows, a.ncols) == (b.nrows, b.ncols) and list(a.entries) == list(b.entries)
    if isinstance(a, (List, ExprList)):
        return len(a.items) == len(b.items) and all(strictly_equal(x, y) for x, y in zip(a.items, b.items))
    if isinstance(a, Opt):
        return strictly_equal(a.key, b.key) and strictly_equal(a.value, b.value)
    if isinstance(a, M2Set):
        return set(a.keys) == set(b.keys)
    if isinstance(a, RingMap):
        return a.target is b.target and a.source is b.source and a.images == b.images
    try:
        return bool(a == b)
    except Exception:
        return a is b


def m2_binary(op: str, a: Any, b: Any, current: Optional[Ring], apply: Callable[[Any, list], Any],
              fallback: Callable[[str, Any, Any, Any], Any]) -> Any:
    """``a op b`` for the operators only Macaulay2 has or gives another meaning (None when the
    ordinary arithmetic of ``fallback(op, a, b, ring)`` applies); ``apply(f, args)`` calls a function."""
    if op == "===":
        return strictly_equal(a, b)
    if op == "=!=":
        return not strictly_equal(a, b)
    if isinstance(a, Vector) or isinstance(b, Vector):
        v = vector_arith(op, a, b)
        if v is not NotImplemented:
            return v
    if isinstance(b, ANY_MODULE) and isinstance(a, ANY_MODULE) or op in ("*", "++") and isinstance(b, (*ANY_MODULE, FreeModule)):
        v = module_arith(op, a, b)
        if v is not NotImplemented:
            return v
    if op == ":" and type(a) is int:  # n copies of anything, a symbol too
        if a < 0:
            raise MechRuntimeError("n : x takes n >= 0")
        return ExprList([b] * a)
    unknown(a)
    unknown(b)
    if op == "..<":
        return ExprList(list(range(to_int(a), to_int(b))))
    if op == "|":
        return _bar(a, b)
    if op == "||":
        return _vbar(a, b)
    if op == "&" and type(a) is int and type(b) is int:
        return a & b
    if op == "\\" and isinstance(a, FUNCTIONS):
        if not isinstance(b, (List, ExprList)):
            raise MechTypeError(f"f \\ L takes a list, not a {typeof(b)}")
        return type(b)([apply(a, [x]) for x in b.items])
    if op == "//" and isinstance(b, FUNCTIONS):  # x // f: f x
        return apply(b, [a])
    if op == "/" and isinstance(a, (List, ExprList)) and isinstance(b, FUNCTIONS):  # L / f: apply(L, f)
        return type(a)([apply(b, [x]) for x in a.items])
    if op == "@@" and isinstance(a, FUNCTIONS) and isinstance(b, FUNCTIONS):
        return Composed(a, b)
    if op == "/" and isinstance(a, CoeffRing) and a.characteristic is None and type(b) is int:
        if b < 2 or any(b % d == 0 for d in range(2, int(b ** 0.5) + 1)):
            raise MechRuntimeError(f"ZZ/{b}: mech's coefficient rings ZZ/p need a prime p")
        return CoeffRing(b, f"ZZ/{b}")
    if op == "/" and isinstance(a, M2Ring) and isinstance(b, Ideal) and b.ring is a.poly:
        return cached_quotient(a, b)
    if op == "/" and isinstance(a, M2Ring):
        return quotient_ring(a, _relations(a, b))
    if op == "^" and isinstance(a, M2Ring) and (type(b) is int or isinstance(b, List)):
        return free_module(a, b)
    if op == "^" and isinstance(a, CoeffRing) and a.name == "ZZ" and type(b) is int:  # ZZ^n
        return free_module(integers(), b)
    if op == "^" and isinstance(a, Ideal) and isinstance(b, Array):
        return _frobenius(a, b)
    if op == "^" and isinstance(a, Matrix) and isinstance(b, List):  # M^{i, ...}: rows
        return rows(a, [to_int(i) for i in b.items])
    if op == "/" and isinstance(a, FreeModule) and isinstance(b, Module) and b.kind == "image" and b.ambient == a:
        return Module("cokernel", b.matrix)  # F / (a submodule of F)
    if op == "/" and isinstance(a, FreeModule):
        return quotient_module(a, b)
    if op in ("==", "!=") and isinstance(a, M2Ring) and b == 0 and type(b) is int:  # R == 0: the zero ring
        return normal(a.poly.one()).is_zero() == (op == "==")
    if op in ("==", "!=") and isinstance(a, FreeModule) and isinstance(b, FreeModule):
        return (a == b) == (op == "==")
    if op in ("==", "!=") and isinstance(a, Module) and isinstance(b, Module):
        return a.same(b) == (op == "==")
    if op == "*" and isinstance(b, List) and type(a) is int and all(type(x) is int for x in b.items):
        return List([a * x for x in b.items])  # 2 * {1, 2}: each entry (a degree)
    if op == "**" and isinstance(a, RingMap) and isinstance(b, FreeModule):  # f ** M: M over f's target
        return apply(a, [b])
    if op == "**" and isinstance(a, Matrix) and isinstance(b, Matrix):
        return _tensor(a, b)
    if op == "**" and isinstance(a, FreeModule) and isinstance(b, FreeModule):
        return _tensor_free(a, b)
    if op == "**" and (isinstance(a, Poly) and isinstance(b, Map) or isinstance(a, Map) and isinstance(b, Poly)):
        return _tensor(*(_one_by_one(x) if isinstance(x, Poly) else x for x in (a, b)))
    if op == "**" and isinstance(b, M2Ring) and isinstance(a, (Poly, Ideal, Matrix)):
        return _base_change(a, b)
    if op in ("//", "%") and any(is_integral(getattr(v, "ring", None)) for v in (a, b)):
        raise MechRuntimeError(f"{op} on elements of a polynomial ring over ZZ is not supported by mech")
    if op == "//":
        return _floor_div(a, b)
    if op == "%" and type(a) is int and type(b) is int:
        if b == 0:
            raise MechRuntimeError("division by 0")
        return a % b
    return _arith(op, a, b, current, fallback)


def free_module(R: M2Ring, b: int | List) -> FreeModule:
    """``R^n`` (generators of degree 0) or ``R^{d1, ...}`` (generators of degrees -d1, ...)."""
    if type(b) is int:
        if b < 0:
            raise MechRuntimeError("R^n takes n >= 0")
        return FreeModule(R, (0,) * b)
    degs = [d.items[0] if isinstance(d, List) and len(d.items) == 1 else d for d in b.items]
    return FreeModule(R, tuple(-to_int(d) for d in degs))


def _base_change(v: Poly | Ideal | Matrix, S: M2Ring) -> Any:
    """``v ** S``: a polynomial, ideal or matrix of R in a ring S built on R (R/I, a tower, R_P)."""
    R = ring_of(v)
    P = localized_at(S)
    if P is not None and R is S.info["over"]:
        move = lambda p: to_local(p, S)  # noqa: E731
    elif R is not None and promotes(R, S):
        move = lambda p: promote(p, S)  # noqa: E731
    else:
        raise MechTypeError("v ** S: S is not a ring built on v's ring")
    if isinstance(v, Poly):
        return move(v)
    if isinstance(v, Ideal):
        return Ideal(S.poly, [move(g) for g in v.gens])
    return Matrix(S.poly, v.nrows, v.ncols, [move(g) for g in v.entries])


def _relations(R: M2Ring, b: Any) -> list[Poly]:
    items = b.gens if isinstance(b, Ideal) else b.items if isinstance(b, (List, ExprList)) else [b]
    out = []
    for g in items:
        if type(g) is int:
            g = R.poly.const(R.poly.field(g))
        elif isinstance(g, (Poly, Number)):
            g = lift_to(g, R)
        else:
            raise MechTypeError(f"R / I takes an ideal or elements of R, not a {typeof(g)}")
        out.append(g)
    return out


def _bar(a: Any, b: Any) -> Any:
    if isinstance(a, (List, ExprList)) and isinstance(b, (List, ExprList)) and type(a) is type(b):
        return type(a)(list(a.items) + list(b.items))
    if isinstance(a, str) and isinstance(b, (str, int)) or isinstance(b, str) and type(a) is int:
        return f"{a}{b}"
    if type(a) is int and type(b) is int:
        return a | b
    if isinstance(a, Matrix) and isinstance(b, Matrix):
        if a.nrows != b.nrows:
            raise MechRuntimeError("A | B: the matrices need as many rows")
        a, b = _one_ring(a, b)
        rows = [list(r) + list(s) for r, s in zip(a.rows(), b.rows())]
        return Matrix(a.ring, a.nrows, a.ncols + b.ncols, [p for r in rows for p in r])
    raise MechTypeError(f"no operator | for a {typeof(a)} and a {typeof(b)}")


def _one_ring(a: Matrix, b: Matrix) -> tuple[Matrix, Matrix]:
    """Two matrices over one ring: the entries of one promoted to the other's ring (a matrix of
    integers over ZZ: its numbers), as Macaulay2 joins them."""
    if a.ring is b.ring:
        return a, b
    ra, rb = getattr(a.ring, "owner", None), getattr(b.ring, "owner", None)
    for x, rx, ry in ((b, rb, ra), (a, ra, rb)):
        if ry is None:
            continue
        if rx is not None and promotes(rx, ry):
            moved = [promote(p, ry) for p in x.entries]
        elif rx is not None and rx is integers():
            moved = [_from_integers(p, ry) for p in x.entries]
        else:
            continue
        y = Matrix(ry.poly, x.nrows, x.ncols, moved)
        return (a, y) if x is b else (y, b)
    raise MechTypeError("the matrices are over different rings")


def _vbar(a: Any, b: Any) -> Any:
    if isinstance(a, Matrix) and isinstance(b, Matrix):
        if a.ncols != b.ncols:
            raise MechRuntimeError("A || B: the matrices need as many columns")
        a, b = _one_ring(a, b)
        return Matrix(a.ring, a.nrows + b.nrows, a.ncols, list(a.entries) + list(b.entries))
    raise MechTypeError(f"no operator || for a {typeof(a)} and a {typeof(b)}")


def _floor_div(a: Any, b: Any) -> Any:
    if type(a) is int and type(b) is int:
        if b == 0:
            raise MechRuntimeError("division by 0")
        return a // b
    if isinstance(a, Poly) and isinstance(b, (Poly, Number, int)):
        R = owner(a)
        if isinstance(b, Poly) and owner(b) is not R:
            raise MechTypeError("f // g: the polynomials are in different rings")
        if R is not None and R.quotient is not None:
            raise MechRuntimeError("f // g in a quotient ring is not supported")
        g = b if isinstance(b, Poly) else a.ring.const(b.c if isinstance(b, Number) else a.ring.field(b))
        if g.is_zero():
            raise MechRuntimeError("division by 0")
        return _quotient(a, g)
    if isinstance(a, Matrix) and isinstance(b, Matrix):
        return divide(a, b)
    raise MechTypeError(f"no operator // for a {typeof(a)} and a {typeof(b)}")


def _quotient(f: Poly, g: Poly) -> Poly:
    """The quotient of the division of ``f`` by ``g`` (terms not divisible by ``lt(g)`` go to the remainder)."""
    from ..kernel.poly import divides
    q, rest = f.ring.zero(), f
    lm, lc = g.lm(), g.lc()
    while not rest.is_zero():
        hit = next(((e, c) for e, c in rest.sorted_terms() if divides(lm, e)), None)
        if hit is None:
            break
        e, c = hit
        t = f.ring.monomial(tuple(x - y for x, y in zip(e, lm)), c / lc)
        q, rest = q + t, rest - t * g
    return q


def _group_power(op: str, a: Any, b: Any, ring: M2Ring) -> Optional[Poly]:
    """In a ring whose first variables are invertible (``GroupLex => n``): a negative power of a
    unit (a coefficient unit times a monomial in those variables: Laurent monomials); None for sums,
    products, equality and other powers, the only other operations allowed there."""
    if op not in ("+", "-", "*", "^", "==", "!=") or not isinstance(a, (Poly, Number, int)) \
            or not isinstance(b, (Poly, Number, int)) or ring_of(a) not in (ring, None) or ring_of(b) not in (ring, None):
        raise MechRuntimeError(f"operator {op} in a ring with invertible variables (GroupLex) is not supported by mech")
    if op == "^" and type(b) is int and b < 0:
        f = lift_to(a, ring) if not isinstance(a, Poly) else a
        n = ring.info["group"]
        if len(f.terms) != 1:
            raise MechRuntimeError("negative power of an element that is not a unit")
        (e, c), = f.terms.items()
        if any(e[n:]) or (is_integral(ring) and abs(c) != 1):
            raise MechRuntimeError("negative power of an element that is not a unit")
        return Poly(f.ring, {tuple(-k * -b for k in e): (f.ring.field.one / c) ** -b})
    return None


def _arith(op: str, a: Any, b: Any, current: Optional[Ring], fallback: Callable) -> Any:
    """Arithmetic after promoting both operands to their common ring; quotient rings reduce;
    local rings have fractions."""
    a, b = _integers_promoted(op, a, b)
    ra, rb = ring_of(a), ring_of(b)
    ring = ra or rb
    if ring is not None and ring.info.get("group") and _group_power(op, a, b, ring) is not None:
        return _group_power(op, a, b, ring)
    if ring is not None and localized_at(ring) is not None and op in ("+", "-", "*", "/", "^", "==", "!=") \
            and isinstance(a, (Poly, Number, LocalFraction, int)) and isinstance(b, (Poly, Number, LocalFraction, int)):
        return local_arith(op, a, b, ring)
    if ra is not None and rb is not None and ra is not rb and op in "+-*/%" and not isinstance(a, (Ideal, Matrix)) \
            and not isinstance(b, (Ideal, Matrix)):
        ring = common_ring(ra, rb)
        if ring is None:
            raise MechTypeError(f"no operator {op} for elements of the rings {ra.name or ra.describe()} and "
                                f"{rb.name or rb.describe()}")
        a, b = lift_to(a, ring), lift_to(b, ring)
    if op in ("==", "!=") and ra is not None and rb is not None and ra is not rb:
        ring = common_ring(ra, rb)
        if ring is not None and isinstance(a, (Poly, Number)) and isinstance(b, (Poly, Number)):
            a, b = lift_to(a, ring), lift_to(b, ring)
    if op == "/" and type(a) is int and type(b) is int:
        if b == 0:
            raise MechRuntimeError("division by 0")
        if current is None or is_integral(current):
            return Fraction(a, b)
        r = current.poly
        return Number(r, r.field(a) / r.field(b))
    if Fraction in (type(a), type(b)) and {type(a), type(b)} <= {int, Fraction} and op in "+-*/^":
        return _rational(op, a, b)
    v = fallback(op, a, b, ring.poly if ring is not None else (current.poly if current else None))
    if isinstance(v, Matrix) and op == "*" and (isinstance(a, Map) or isinstance(b, Map)):
        if isinstance(a, Map) and isinstance(b, Map):  # composition
            v = Map(a.target, b.source, v.entries, a.degree + b.degree) if a.source.rank == b.target.rank else v
        elif isinstance(b, Map) and not isinstance(a, Matrix):
            v = scaled(b, a, v)
        elif isinstance(a, Map) and not isinstance(b, Matrix):
            v = scaled(a, b, v)
    if isinstance(v, (Poly, Number)) and is_integral(v.ring) and not _integral(v):
        raise MechRuntimeError(f"the result of {op} has a fractional coefficient: it is not in a ring over ZZ")
    if isinstance(v, Poly) and ring is not None:
        if ring.quotient is not None:
            v = normal(v)
        if ring.max_exponent is not None and any(k >= ring.max_exponent for e in v.terms for k in e):
            raise MechRuntimeError(f"monomial overflow: exponents of this ring are below {ring.max_exponent} "
                                   f"(MonomialSize)")
    return v


def _from_integers(p: Poly, S: M2Ring) -> Poly:
    """An integer (a constant of ZZ's ring of no variables) as an element of S."""
    return S.poly.const(S.poly.field(int(p.terms.get((), 0))))


def _integers_promoted(op: str, a: Any, b: Any) -> tuple[Any, Any]:
    """A matrix of integers (over ZZ) beside a matrix, polynomial or number of another ring, or an
    ideal of ZZ in a sum or quotient with an ideal of another ring: as elements of that
    ring, as Macaulay2 promotes ZZ into every ring (it refuses the product of ideals of two rings:
    so does mech)."""
    ZZ = integers().poly
    for x, y in ((a, b), (b, a)):
        S = getattr(getattr(y, "ring", None), "owner", None)
        if S is None or y.ring is ZZ or getattr(x, "ring", None) is not ZZ:
            continue
        if isinstance(x, Map) and isinstance(y, (Matrix, Poly, Number)):
            moved = Map(FreeModule(S, x.target.degrees), FreeModule(S, x.source.degrees),
                        [_from_integers(p, S) for p in x.entries], x.degree)
        elif isinstance(x, Matrix) and isinstance(y, (Matrix, Poly, Number)):
            moved = Matrix(S.poly, x.nrows, x.ncols, [_from_integers(p, S) for p in x.entries])
        elif isinstance(x, Ideal) and isinstance(y, Ideal) and op in ("+", ":"):
            moved = Ideal(S.poly, [_from_integers(p, S) for p in x.gens])
        else:
            continue
        return (moved, b) if x is a else (a, moved)
    return a, b


def _integral(v: Poly | Number) -> bool:
    coeffs = v.terms.values() if isinstance(v, Poly) else [v.c]
    return all(getattr(c, "denominator", 1) == 1 for c in coeffs)


def _rational(op: str, a: Fraction | int, b: Fraction | int) -> Fraction | int:
    """Arithmetic of rational numbers outside a ring (``1/2 + 1``); integral results are ints."""
    if op == "^" and type(b) is not int:
        raise MechTypeError("a rational number's exponent is an integer")
    if op == "/" and b == 0:
        raise MechRuntimeError("division by 0")
    v = {"+": lambda: a + b, "-": lambda: a - b, "*": lambda: a * b, "/": lambda: Fraction(a) / b,
         "^": lambda: Fraction(a) ** b}[op]()
    return int(v) if v.denominator == 1 else v


__all__ = ["SYMBOLS", "m2_binary", "ring_of", "lift_to", "strictly_equal"]
