"""The structure of polynomials and ideals: ``size``, leading terms (``lead``, ``leadcoef``,
``leadmonom``), ``deg``, derivatives (``diff``, ``jacob``), ``subst`` and ``maxideal``."""
from __future__ import annotations

from typing import Any, Optional

from ..dsl.errors import MechRuntimeError, MechTypeError
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, List, Map, Matrix, Number, Ring, to_poly
from ..dsl.values import typeof as _typeof
from ..kernel import Poly
from ..kernel.algext import AlgebraicField
from ..kernel.matrix import apply_operator


@command("size")
def size(x: Any) -> int:
    """size(x): terms of a poly, nonzero generators of an ideal, entries of a list, intvec or
    matrix, characters of a string.

    Example:
      ring r = 0,(x,y),dp;
      size(x2+2xy-1);
      → 3
      size(ideal(x, 0, y));
      → 2
      size("mech");
      → 4
    """
    if isinstance(x, int):
        return 0 if x == 0 else 1
    if isinstance(x, Number):
        return 0 if x.is_zero() else 1
    if isinstance(x, Poly):
        return len(x.terms)
    if isinstance(x, Ideal):
        return len(x.nonzero())
    if isinstance(x, Matrix):
        return x.nrows * x.ncols
    if isinstance(x, (List, str, IntVec)):
        return len(x)
    if isinstance(x, Map):
        return len(x.images)
    if isinstance(x, Ring):
        return _field_size(x.poly.field)
    raise MechTypeError(f"size is not defined for {_typeof(x)}")


@command("lead")
def lead(f: Poly | Ideal) -> Any:
    """lead(f): the leading term of a poly, or the ideal of leading terms.

    Example:
      ring r = 0,(x,y),dp;
      lead(3x2y-x3+y);
      → -x3
      lead(ideal(x+y2, 2x-1));
      → _[1]=y2
      → _[2]=2x
    """
    if isinstance(f, Poly):
        return f.ring.zero() if f.is_zero() else f.lt()
    return Ideal(f.ring, [g if g.is_zero() else g.lt() for g in f.gens])


@command("leadcoef")
def leadcoef(f: Poly) -> Number:
    """leadcoef(f): the leading coefficient of f (a number).

    Example:
      ring r = 0,(x,y),dp;
      leadcoef(-3x2y+x3+y);
      → 1
    """
    return Number(f.ring, f.ring.field.zero if f.is_zero() else f.lc())


@command("leadmonom")
def leadmonom(f: Poly) -> Poly:
    """leadmonom(f): the leading monomial of f (coefficient 1).

    Example:
      ring r = 0,(x,y),dp;
      leadmonom(-3x2y+x3+y);
      → x3
    """
    return f.ring.zero() if f.is_zero() else f.ring.monomial(f.lm())


def _ring_weights(ring: Any) -> Optional[list[int]]:
    """The variables' weights deg uses without a weight vector, as Singular: those of the first weighted
    block (a, wp, ws, Wp, Ws) covering a variable, else 1 (None: all 1)."""
    weights: list[Optional[int]] = [None] * ring.nvars
    pos = 0
    for b in ring.order.blocks:
        if b.kind == "a" or b.kind in ("wp", "Wp", "ws", "Ws"):
            for j, v in enumerate(b.weights[:ring.nvars - pos]):
                if weights[pos + j] is None:
                    weights[pos + j] = abs(v)
        if b.kind != "a":
            pos += b.size
    if all(x is None for x in weights):
        return None
    return [1 if x is None else x for x in weights]


@command("deg")
def deg(f: Poly | Ideal, w: IntVec | None = None) -> int:
    """deg(f) or deg(f, w): the (weighted) total degree of f, -1 for 0; for an ideal the maximum.  Without w
    the weights are the ordering's (of wp, ws and a blocks; 1 for the other variables), as in Singular.

    Example:
      ring r = 0,(x,y),dp;
      deg(x2y+y5);
      → 5
      deg(x2y+y5, intvec(3,1));
      → 7
      deg(0);
      → -1
    """
    def one(p: Poly) -> int:
        if p.is_zero():
            return -1
        ws = _ring_weights(p.ring) if w is None else list(w.values) + [0] * (p.ring.nvars - len(w))
        if ws is None:
            return p.total_degree()
        return max(sum(a * b for a, b in zip(e, ws)) for e in p.terms)
    if isinstance(f, Poly):
        return one(f)
    return max((one(g) for g in f.gens), default=-1)


@command("diff")
def diff(f: Poly | Ideal | Matrix, x: Poly) -> Any:
    """diff(f, x): the partial derivative of f (poly, ideal or matrix) by the ring variable x.

    Example:
      ring r = 0,(x,y),dp;
      diff(x3y2+xy, x);
      → 3x2y2+y
      diff(ideal(x2, xy), y);
      → _[1]=0
      → _[2]=x
    """
    i = _var_index(x, "diff")
    if isinstance(f, Poly):
        return f.diff(i)
    if isinstance(f, Ideal):
        return Ideal(f.ring, [g.diff(i) for g in f.gens])
    return Matrix(f.ring, f.nrows, f.ncols, [g.diff(i) for g in f.entries])


@command("diff")
def diff_operators(H: Ideal, I: Ideal) -> Matrix:
    """diff(H, I): the matrix of the H[i] applied to the I[j] as differential operators (x^a acts as
    the a-th partial derivative).

    Example:
      ring r = 0,(x,y),dp;
      print(diff(ideal(x, y2), ideal(x2, xy2)));
      → 2x,y2,
      → 0, 2x
    """
    return Matrix(I.ring, len(H.gens), len(I.gens), [apply_operator(h, f) for h in H.gens for f in I.gens])



def _var_index(x: Poly, cmd: str) -> int:
    if len(x.terms) == 1:
        (e, c), = x.terms.items()
        if c == 1 and sum(e) == 1:
            return e.index(1)
    raise MechRuntimeError(f"{cmd}: the second argument must be a ring variable")


def _param_index(x: Poly) -> Optional[int]:
    """j if x is the j-th parameter of its ring's coefficient field, else None."""
    params = getattr(x.ring.field, "params", ())
    if not params or not x.is_constant() or x.is_zero():
        return None
    c = x.lc()
    return next((j for j in range(len(params)) if c == x.ring.field.gen(j)), None)


def _subst_param(f: Poly, j: int, g: Poly) -> Poly:
    """f with g for the j-th parameter in its coefficients (polynomials in the parameters of QQ(a,..), or
    the parameter of an algebraic extension, its coefficients read as polynomials of degree < deg m)."""
    ring, field = g.ring, f.ring.field  # g's ring: f may be minpoly, a number of QQ(a)
    out = ring.zero()
    for e, c in f.terms.items():
        if isinstance(field, AlgebraicField):
            value = sum((field(v) * g ** k for k, v in enumerate(c.u.coeffs()) if v), ring.zero())
        else:
            if c.den != 1:  # Singular then drops the denominators (with a warning)
                raise MechRuntimeError("subst: substituting a parameter in coefficients with denominators is not "
                                       "supported")
            value = ring.zero()
            for m, v in zip(c.num.monoms(), c.num.coeffs()):
                rest = ring.field(int(v))
                for k, mk in enumerate(m):
                    if k != j and mk:
                        rest = rest * ring.field.gen(k) ** int(mk)
                value = value + g ** int(m[j]) * rest
        out = out + ring.monomial(e, ring.field.one) * value
    return out


@command("jacob")
def jacob(f: Poly | Ideal) -> Any:
    """jacob(f): the ideal of partial derivatives of a poly; for an ideal the Jacobian matrix
    (one row per generator).

    Example:
      ring r = 0,(x,y),dp;
      jacob(x3+xy2);
      → _[1]=3x2+y2
      → _[2]=2xy
      print(jacob(ideal(x2+y2-1, x-y)));
      → 2x,2y,
      → 1, -1
    """
    n = f.ring.nvars
    if isinstance(f, Poly):
        return Ideal(f.ring, [f.diff(i) for i in range(n)])
    return Matrix(f.ring, len(f.gens), n, [g.diff(i) for g in f.gens for i in range(n)])


@command("subst")
def subst(f: Poly | Ideal | Matrix | Number, *pairs: Any) -> Any:
    """subst(f, x, g, ...): substitute g for the ring variable (or parameter) x in f (several pairs in
    turn).

    Example:
      ring r = 0,(x,y,z),dp;
      subst(x2+yz, x, y+1);
      → y2+yz+2y+1
      subst(x2+yz, y, 2, z, x);
      → x2+2x
    """
    if not pairs or len(pairs) % 2:
        raise MechTypeError("subst(f, x, g): give a variable and its substitute")
    if isinstance(f, Number):
        f = to_poly(f, f.ring)
        if len(pairs) == 2 and isinstance(pairs[1], Poly) and pairs[1].ring is not f.ring:
            # minpoly (a number of QQ(a)) as a polynomial in a: evaluated at a polynomial of the basering
            j = _param_index(to_poly(pairs[0], pairs[1].ring))
            if j is not None and not isinstance(f.ring.field, AlgebraicField):
                return _subst_param(f, j, pairs[1])
    ring = f.ring
    for k in range(0, len(pairs), 2):
        x = to_poly(pairs[k], ring)
        g = to_poly(pairs[k + 1], ring)
        j = _param_index(x)
        if j is not None:  # a parameter: in every coefficient
            if isinstance(f, Poly):
                f = _subst_param(f, j, g)
            elif isinstance(f, Ideal):
                f = Ideal(ring, [_subst_param(p, j, g) for p in f.gens])
            else:
                f = Matrix(ring, f.nrows, f.ncols, [_subst_param(p, j, g) for p in f.entries])
            continue
        i = _var_index(x, "subst")
        images = ring.gens()
        images[i] = g
        if isinstance(f, Poly):
            f = f.compose(images)
        elif isinstance(f, Ideal):
            f = Ideal(ring, [p.compose(images) for p in f.gens])
        else:
            f = Matrix(ring, f.nrows, f.ncols, [p.compose(images) for p in f.entries])
    return f


@command("maxideal")
def maxideal(ctx, k: int) -> Ideal:
    """maxideal(k): the ideal of all monomials of degree k.

    Example:
      ring r = 0,(x,y),dp;
      maxideal(2);
      → _[1]=y2
      → _[2]=xy
      → _[3]=x2
    """
    ring = ctx.basering().poly
    if k <= 0:
        return Ideal(ring, [ring.one()], is_std=True)
    if k == 1:  # Singular: the variables in their order
        return Ideal(ring, ring.gens(), is_std=True)
    exps: list[tuple[int, ...]] = []

    def rec(i: int, left: int, cur: list[int]) -> None:
        if i == ring.nvars - 1:
            exps.append(tuple(cur + [left]))
            return
        for a in range(left, -1, -1):
            rec(i + 1, left - a, cur + [a])
    rec(0, k, [])
    # Singular lists them in increasing lex order and marks them as a standard basis
    return Ideal(ring, [ring.monomial(e) for e in sorted(exps)], is_std=True)


def _field_size(field: Any) -> int:
    """size(R) of a ring: the number of elements of its coefficient field, -1 when it is infinite."""
    p = field.characteristic
    if not p or getattr(field, "params", None) and getattr(field, "modulus", None) is None:
        return -1
    modulus = getattr(field, "modulus", None)
    return p ** modulus.degree() if modulus is not None else p
