"""Commands of Singular's ring.lib: new rings from strings (``defring``, ``defrings``, ``defringp``),
renamed variables (``changevar``), the kind of an ordering (``ord_test``), the variables' weights
(``ringweights``), ``isQuotientRing``, submodules (``isSubModule``), ``hasCommutativeVars``, the primitive roots of unity as a
minimal polynomial of a parameter (``rootofUnity``) and tensor products of rings (``ringtensor``).
``export`` puts a procedure's result variables into the ring it returns."""
from __future__ import annotations

import flint
from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.qrings import make_qring, quotient_ideal
from ..dsl.registry import command
from ..dsl.rings import make_ring, parse_ordering
from ..dsl.scopes import Var
from ..dsl.convert_modules import to_module
from ..dsl.values import Ideal, IntVec, Number, OrderBlock, Ring
from ..dsl.values_modules import Module
from ..kernel import Poly
from .general_lib import _letters

LIB = "ring.lib"


def export(ring: Ring, name: str, typ: str, value: Any) -> None:
    """Make ``value`` the variable ``name`` of the ring (what a library procedure exports into a ring
    it returns: seen after ``setring``)."""
    ring.objects[name] = Var(name, typ, value, ring, 0)


def parse_characteristic(text: str) -> tuple[int, tuple[str, ...]]:
    """``"0"`` or ``"(2,A,B)"``: the characteristic and the parameters."""
    parts = [p.strip() for p in text.strip().strip("()").split(",") if p.strip()]
    if not parts or not parts[0].isdigit():
        raise MechRuntimeError(f"not a characteristic: \"{text}\" (e.g. \"0\" or \"(32003,a)\")")
    return int(parts[0]), tuple(parts[1:])


def _indexed_or_letters(start: str, n: int) -> list[str]:
    if start.endswith("("):
        return [f"{start}{i})" for i in range(1, n + 1)]
    if n > 26:
        return [f"{start}({i})" for i in range(1, n + 1)]
    return _letters(start, n)


@command("defring", lib=LIB)
def defring(ch: str, n: int, start: str, order: str) -> Ring:
    """defring(ch, n, v, o): the ring of characteristic (and parameters) ch, n variables named from
    the letter v on (or v(1), ..., v(n) for v = "v(" or n > 26) and the ordering o.

    Example:
      LIB "ring.lib";
      def r = defring("(0,a)", 3, "x", "(dp(1),ds)");
      r;
      → // coefficients: QQ(a)
      → // number of vars : 3
      → //        block   1 : ordering dp
      → //                  : names    x
      → //        block   2 : ordering ds
      → //                  : names    y z
      → //        block   3 : ordering C
    """
    char, params = parse_characteristic(ch)
    names = _indexed_or_letters(start, n)
    return make_ring(char, params, names, parse_ordering(order, len(names)))


def _standard_ring(n: int, p: int, kind: str) -> Ring:
    names = [f"x({i})" for i in range(1, n + 1)] if n > 26 else _letters("x", n)
    return make_ring(p, (), names, [OrderBlock(kind, n), OrderBlock("C")])


@command("defrings", lib=LIB)
def defrings(n: int, p: int = 32003) -> Ring:
    """defrings(n[, p]): the ring of characteristic p (default 32003) in x, y, z, a, b, ... (x(1), ...,
    x(n) for n > 26) with the local ordering ds.

    Example:
      LIB "ring.lib";
      def S = defrings(2, 0);
      S;
      → // coefficients: QQ
      → // number of vars : 2
      → //        block   1 : ordering ds
      → //                  : names    x y
      → //        block   2 : ordering C
    """
    return _standard_ring(n, p, "ds")


@command("defringp", lib=LIB)
def defringp(n: int, p: int = 32003) -> Ring:
    """defringp(n[, p]): as defrings, with the global ordering dp.

    Example:
      LIB "ring.lib";
      def S = defringp(2, 0);
      S;
      → // coefficients: QQ
      → // number of vars : 2
      → //        block   1 : ordering dp
      → //                  : names    x y
      → //        block   2 : ordering C
    """
    return _standard_ring(n, p, "dp")


@command("changevar", lib=LIB)
def changevar(ctx, names: str, r: Ring | None = None) -> Ring:
    """changevar(vars[, r]): the ring r (default the basering) with its variables renamed: vars lists
    the new names ("a,b,c") or is "t()" for t(1), ..., t(n); a quotient ring keeps its ideal.

    Example:
      LIB "ring.lib";
      ring r = 0,(x,y),dp;
      def R = changevar("t()");
      R;
      → // coefficients: QQ
      → // number of vars : 2
      → //        block   1 : ordering dp
      → //                  : names    t(1) t(2)
      → //        block   2 : ordering C
    """
    old = r if r is not None else ctx.basering()
    n = len(old.names)
    if names.endswith("()"):
        new = [f"{names[:-2]}({i})" for i in range(1, n + 1)]
    else:
        new = [v.strip() for v in names.split(",") if v.strip()]
    if len(new) != n:
        raise MechRuntimeError(f"changevar: {len(new)} names for the {n} variables of the ring")
    ring = make_ring(old.characteristic, old.params, new, list(old.blocks))
    quotient = quotient_ideal(old.poly)
    if quotient is None:
        return ring
    return make_qring(ring, Ideal(ring.poly, [Poly(ring.poly, g.terms) for g in quotient], is_std=True))


def _local_var(ring, i: int) -> bool:
    e = tuple(int(j == i) for j in range(ring.nvars))
    return ring.order.compare(e, ring.zero_exp) < 0


@command("ord_test", lib=LIB)
def ord_test(r: Ring) -> int:
    """ord_test(r): 1 if the ordering of r is global (every variable > 1), -1 if it is local (every
    variable < 1), 0 if it is mixed.

    Example:
      LIB "ring.lib";
      ring r = 0,(x,y),(dp(1),ls(1));
      ord_test(r);
      → 0
    """
    ring = r.poly
    local = [_local_var(ring, i) for i in range(ring.nvars)]
    return 1 if not any(local) else -1 if all(local) else 0


@command("ringweights", lib=LIB)
def ringweights(r: Ring) -> IntVec:
    """ringweights(r): the weights of the variables in the ordering of r (1 where it gives none).

    Example:
      LIB "ring.lib";
      ring r = 0,(x,y,z),(wp(2,3),dp);
      ringweights(r);
      → 2,3,1
    """
    from .polynomials import _ring_weights  # imported late: polynomials' size(x) must follow intmats' size
    ws = _ring_weights(r.poly)
    return IntVec(ws if ws is not None else [1] * r.poly.nvars)


@command("isQuotientRing", lib=LIB)
def is_quotient_ring(r: Ring) -> int:
    """isQuotientRing(r): 1 if r is a quotient ring (a qring of a nonzero ideal), else 0.

    Example:
      LIB "ring.lib";
      ring r = 0,x,dp;
      isQuotientRing(r);
      → 0
      qring q = ideal(x);
      isQuotientRing(q);
      → 1
    """
    gens = quotient_ideal(r.poly)
    return int(bool(gens) and any(not g.is_zero() for g in gens))


@command("rootofUnity", lib=LIB)
def root_of_unity(ctx, n: int) -> Number:
    """rootofUnity(n): the minimal polynomial over QQ of the primitive n-th roots of unity (the n-th
    cyclotomic polynomial) in the parameter of the basering, to be set as its minpoly.

    Example:
      LIB "ring.lib";
      ring r = (0,q),x,dp;
      rootofUnity(6);
      → (q2-q+1)
    """
    ring = ctx.basering()
    field = ring.poly.field
    if len(ring.params) != 1:
        raise MechRuntimeError("rootofUnity: the procedure works only with one ring parameter variable")
    if n < 0:
        raise MechRuntimeError(f"rootofUnity: cannot compute ({n})-th primitive root of unity")
    if n == 0:
        return Number(ring.poly, field(0))
    q = field.gen(0)
    if ring.characteristic and n > 2:
        return Number(ring.poly, _root_of_unity_p(ctx, ring, n, q))
    value = field(0)
    for k, c in enumerate(flint.fmpz_poly.cyclotomic(n).coeffs()):
        if c:
            value = value + q ** k * int(c)
    return Number(ring.poly, value)


def _root_of_unity_p(ctx, ring: Ring, n: int, q: Any) -> Any:
    """ring.lib's choice in characteristic p: the first factor of t^n - 1 of the largest degree (in
    factorize's order) whose root a has a^(n div 2) != 1 (when the parameter already has a minimal
    polynomial, ring.lib cannot set another one: it warns and tests the parameter itself)."""
    from ..kernel import PolyRing
    from ..kernel.coeffs import PrimeField
    from ..kernel.order import MonomialOrder
    from .factorize import factory_factors
    p = ring.characteristic
    R = PolyRing(PrimeField(p), ["t"], MonomialOrder.simple("dp", 1))
    t = R.gen(0)
    factors = [g for g, _ in factory_factors(t ** n - R.one())]
    d = max(g.total_degree() for g in factors)
    top = [g for g in factors if g.total_degree() == d]

    def value(g: Poly) -> Any:
        out = ring.poly.field(0)
        for e, c in g.terms.items():
            out = out + q ** e[0] * int(c)
        return out
    if len(top) == 1:
        return value(top[0])
    if n % 2:
        raise MechRuntimeError("rootofUnity: ASSUME failed: n%2 == 0 (several factors of t^n-1 of the largest "
                               "degree for an odd n)")
    algebraic = hasattr(ring.poly.field, "modulus")
    x = flint.nmod_poly([0, 1], p)
    for g in top:
        if algebraic:
            ctx.warn("Trying to set minpoly over non-transcendental ground field...")
            root_power_is_one = q ** (n // 2) == ring.poly.field.one
        else:
            m = flint.nmod_poly([int(g.coeff_of((k,))) for k in range(d + 1)], p)
            root_power_is_one = (x ** (n // 2)) % m == 1
        if not root_power_is_one:
            return value(g)
    raise MechRuntimeError(f"rootofUnity: no primitive {n}-th root of unity found")


@command("hasCommutativeVars", lib=LIB)
def has_commutative_vars(r: Ring) -> int:
    """hasCommutativeVars(r): 1 if r is a commutative polynomial ring (always, in mech).

    Example:
      LIB "ring.lib";
      ring r = 0,(x,y),dp;
      hasCommutativeVars(r);
      → 1
    """
    return 1


@command("ringtensor", lib=LIB)
def ringtensor(*rings: Ring) -> Ring:
    """ringtensor(r1, r2, ...): the tensor product of the rings: their variables side by side, their
    ordering blocks one after the other (the module component last), the characteristic of the one
    that has one, and the quotient ideals of the quotient rings together.

    Example:
      LIB "ring.lib";
      ring r = 32003,(x,y),dp;
      ring s = 0,(a,b),ls;
      def R = ringtensor(r, s);
      R;
      → // coefficients: ZZ/32003
      → // number of vars : 4
      → //        block   1 : ordering dp
      → //                  : names    x y
      → //        block   2 : ordering ls
      → //                  : names    a b
      → //        block   3 : ordering C
    """
    if len(rings) < 2:
        raise MechRuntimeError("ringtensor needs at least two rings")
    chars = {r.characteristic for r in rings if r.characteristic}
    if len(chars) > 1:
        raise MechRuntimeError(f"ringtensor: the characteristics {sorted(chars)} differ")
    names = [n for r in rings for n in r.names]
    params = tuple(p for r in rings for p in r.params)
    blocks = [b for r in rings for b in r.blocks if b.kind not in ("c", "C")] + [OrderBlock("C")]
    ring = make_ring(chars.pop() if chars else 0, params, names, blocks)
    big, quotient, offset = ring.poly, [], 0
    for r in rings:
        n = len(r.names)
        for g in quotient_ideal(r.poly) or []:
            quotient.append(Poly(big, {(0,) * offset + e + (0,) * (big.nvars - offset - n): c
                                       for e, c in g.terms.items()}))
        offset += n
    return make_qring(ring, Ideal(big, quotient)) if quotient else ring


@command("preimageLoc", lib=LIB)
def preimage_loc(ctx, ring_name: str, map_name: str, ideal_name: str) -> Ideal:
    """preimageLoc("R", "phi", "J"): the preimage in the basering of the ideal J of the ring R under the
    map phi into R, the three given by name, for any orderings: when R is a quotient ring with a local
    ordering, only the primary components of its ideal through the origin are kept (the quotient of the
    local ring), then the preimage is taken as for global orderings.

    Example:
      LIB "ring.lib";
      ring S = 0,(x,y),dp;
      ring R0 = 0,(x,y),ds;
      qring R = std(x2+x);
      map psi = S,x,y;
      ideal null;
      setring S;
      preimageLoc("R","psi","null");
      → _[1]=x
    """
    from ..kernel.ideals import intersect, move, with_order
    from ..kernel.primdec import primdec_gtz
    from ..kernel.order import Block, MonomialOrder
    from .idealops import preimage_polys
    source = ctx.basering().poly
    var = ctx.lookup(ring_name)
    if var is None or not isinstance(var.value, Ring):
        raise MechRuntimeError(f"preimageLoc: {ring_name} is not a ring")
    target = var.value
    phi, J = ctx.lookup_in_ring(target, map_name), ctx.lookup_in_ring(target, ideal_name)
    if phi is None or J is None:
        raise MechRuntimeError(f"preimageLoc: {map_name} or {ideal_name} is not defined in {ring_name}")
    ring = target.poly
    glob = with_order(ring, MonomialOrder([Block("dp", ring.nvars)], ring.nvars))
    gens = list(J.value.nonzero()) if isinstance(J.value, Ideal) else [J.value]
    q = quotient_ideal(ring)
    extra = move([p for p in q if not p.is_zero()], glob) if q is not None else []
    if extra and not ring.order.is_global:
        through = [move(c[0], glob) for c in primdec_gtz(extra, glob)
                   if all(p.terms.get(glob.zero_exp) is None for p in c[1])]
        extra = intersect(*through, ring=glob) if through else [glob.one()]
    images = [Poly(glob, p.terms) for p in phi.value.images]
    images += [glob.zero()] * (source.nvars - len(images))
    out = preimage_polys(source, glob, images[:source.nvars], move(gens, glob) + extra)
    return Ideal(source, out or [source.zero()])


@command("optionIsSet", lib=LIB)
def option_is_set(ctx, name: str) -> int:
    """optionIsSet(name): 1 if the option name is active (as ring.lib finds it: the name occurs in the
    list option() prints), else 0; an unknown option is an error.

    Example:
      LIB "ring.lib";
      optionIsSet("redSB");
      → 0
      option(redSB);
      optionIsSet("redSB");
      → 1
    """
    from ..dsl.errors import MechNameError
    from ..dsl.options import OPTION_ORDER, shown_options
    base = name[2:] if name.startswith("no") and name[2:] in OPTION_ORDER else name
    if base not in OPTION_ORDER:
        raise MechNameError(f"unknown option '{name}'")
    shown = shown_options(ctx.options, ctx.explicit_options, ctx.ring)
    return int(name in " ".join(shown))



@command("isSubModule", lib=LIB)
def is_sub_module(ctx, i: Ideal | Module, j: Ideal | Module) -> int:
    """isSubModule(I, J): 1 if the module generated by I lies in the one J generates, else 0 (ideals
    as submodules of R^1; in a local ordering, of the localization, as Singular's reduce).

    Example:
      LIB "ring.lib";
      ring r = 0,x,dp;
      isSubModule(ideal(x3), ideal(x2));
      → 1
      isSubModule(ideal(x2), ideal(x3));
      → 0
    """
    from .module_commands import reduce, std
    ring = ctx.basering().poly
    sub, mod = to_module(i, ring), to_module(j, ring)
    basis = mod if mod.is_std else std(mod)
    return int(all(not g.terms() for g in reduce(ctx, sub, basis).gens))
