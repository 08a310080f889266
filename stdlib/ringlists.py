"""Rings as lists: Singular's ``ringlist(r)`` (the coefficients, the variables' names, the ordering's
blocks as [name, intvec] and the quotient ideal) and ``ring(L)`` (the ring a list describes), with the
library procedures built on them: standard.lib's ``ring_list``, ``create_ring`` and ``quotientList``,
ring.lib's ``changechar``, ``changeord`` and ``extendring``."""
from __future__ import annotations

import re
from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.minpoly import extended, get_minpoly
from ..dsl.qrings import make_qring, quotient_ideal
from ..dsl.registry import command
from ..dsl.rings import make_ring, ordering_items, parse_ordering
from ..dsl.values import NONE, Ideal, IntVec, List, OrderBlock, Ring
from ..kernel import Poly
from ..kernel.algext import AlgebraicField
from ..kernel.maps import fetch
from ..dsl.printing import ordstr
from .general_lib import _letters
from .standard import standard_basis

_SIZED = ("lp", "dp", "Dp", "ls", "ds", "Ds", "rp")


def _block_list(b: OrderBlock) -> List:
    if b.kind in ("c", "C"):
        return List([b.kind, IntVec([0])])
    if b.weights:
        return List([b.kind, IntVec(b.weights)])
    return List([b.kind, IntVec([1] * b.size)])


def _coefficients(r: Ring) -> Any:
    if not r.params:
        return r.characteristic
    ideal = Ideal(r.poly, [r.poly.zero()])
    if isinstance(r.poly.field, AlgebraicField):  # over the transcendental field: not reduced to 0
        m = get_minpoly(r)
        ideal = Ideal(m.ring, [m.ring.const(m.c)])
    return List([r.characteristic, List(list(r.params)),
                 List([List(["lp", IntVec([1] * len(r.params))])]), ideal])


@command("ringlist")
def ringlist(r: Ring) -> List:
    """ringlist(r): the list describing the ring r: [1] the characteristic (with parameters the list of
    the characteristic, their names, their ordering and the ideal of the minimal polynomial), [2] the
    variables' names, [3] the ordering's blocks as lists [name, intvec of weights], [4] the quotient
    ideal.

    Example:
      ring r = 0,(x,y),(dp(1),wp(2));
      ringlist(r)[3];
      → [1]:
      →    [1]:
      →       dp
      →    [2]:
      →       1
      → [2]:
      →    [1]:
      →       wp
      →    [2]:
      →       2
      → [3]:
      →    [1]:
      →       C
      →    [2]:
      →       0
    """
    q = quotient_ideal(r.poly)
    quotient = [p for p in q if not p.is_zero()] if q else []
    return List([_coefficients(r), List(list(r.names)), List([_block_list(b) for b in r.blocks]),
                 Ideal(r.poly, quotient or [r.poly.zero()])])


def _blocks(L: Any, nvars: int) -> list[OrderBlock]:
    if isinstance(L, str):
        return parse_ordering(L, nvars)
    blocks = []
    for item in L.items if isinstance(L, List) else []:
        if not isinstance(item, List) or len(item) < 2 or not isinstance(item.items[0], str):
            raise MechRuntimeError("ring(L): L[3] must be a list of orderings [name, intvec]")
        kind, v = item.items[0], item.items[1]
        # as Singular: an int n for a block of n variables (weights 1)
        vals = list(v.values) if isinstance(v, IntVec) else [1] * v if isinstance(v, int) and v > 0 else []
        if kind in ("c", "C"):
            blocks.append(OrderBlock(kind))
        elif kind in _SIZED:
            blocks.append(OrderBlock(kind, len(vals)))
        elif kind == "M":
            blocks.append(OrderBlock("M", int(round(len(vals) ** 0.5)), tuple(vals)))
        else:
            blocks.append(OrderBlock(kind, len(vals), tuple(vals)))
    if not any(b.kind in ("c", "C") for b in blocks):
        blocks.append(OrderBlock("C"))
    return blocks


class CoeffRing:
    """ring_list's first entry: the coefficient field (Singular's cring), printed ``QQ`` or ``ZZ/p``, with
    parameters "char,parameters" (not indented in a list), minimal polynomial included."""

    unindented = True
    type_name = "cring"

    def __init__(self, ring: Ring) -> None:
        self.ring = ring

    def __str__(self) -> str:
        char = self.ring.characteristic
        if not self.ring.params:
            return f"ZZ/{char}" if char else "QQ"
        return ",".join([str(char)] + list(self.ring.params))


def _char(c: Any) -> tuple[int, tuple[str, ...], Any]:
    """(characteristic, parameters, minimal polynomial ideal or None) of ringlist's first entry."""
    if isinstance(c, CoeffRing):
        return c.ring.characteristic, c.ring.params, _coefficients(c.ring).items[3] if c.ring.params else None
    if isinstance(c, int):
        return c, (), None
    if isinstance(c, str):
        parts = [p.strip() for p in c.strip().strip("()").split(",") if p.strip()]
        if not parts or not re.fullmatch(r"\d+", parts[0]):
            raise MechRuntimeError(f'ring(L): cannot read the coefficients "{c}"')
        return int(parts[0]), tuple(parts[1:]), None
    if isinstance(c, List) and c.items and isinstance(c.items[0], int):
        names = tuple(c.items[1].items) if len(c) > 1 and isinstance(c.items[1], List) else ()
        minpoly = c.items[3] if len(c) > 3 and isinstance(c.items[3], Ideal) else None
        return c.items[0], names, minpoly
    raise MechRuntimeError("ring(L): L[1] must be the characteristic or a list [char, parameters, ordering, minpoly]")


def list_ring(L: List, minpoly: bool = True) -> Ring:
    """The ring the list L describes (as ringlist gives it); the quotient ideal and the minimal
    polynomial are carried over by position."""
    if not isinstance(L, List) or len(L) < 3:
        raise MechRuntimeError("ring(L): L must be a list of at least 3 entries (ringlist's form)")
    char, params, mp = _char(L.items[0])
    names = L.items[1]
    if isinstance(names, str):
        names = [n.strip() for n in names.strip().strip("()").split(",") if n.strip()]
    else:
        names = [str(n) for n in names.items]
    new = make_ring(char, params, names, _blocks(L.items[2], len(names)))
    if (minpoly or isinstance(L.items[0], CoeffRing)) and mp is not None:
        gens = [g for g in mp.gens if not g.is_zero()]
        if gens:
            if not gens[0].is_constant():
                raise MechRuntimeError("ring(L): the minimal polynomial must be a number (a polynomial in the parameter)")
            new.poly = extended(new.poly, new.poly.field(gens[0].lc()))
    q = L.items[3] if len(L) > 3 and L.items[3] is not NONE else None
    if isinstance(q, Ideal) and q.nonzero():
        polys = fetch(q.nonzero(), q.ring, new.poly)
        new = make_qring(new, Ideal(new.poly, polys))
    return new


@command("ring")
def ring_of_list(L: List) -> Ring:
    """ring(L): the ring described by the list L in ringlist's form (the quotient ideal is taken as a
    standard basis, as Singular does).

    Example:
      ring r = 0,(x,y),dp;
      list l = ringlist(r);
      l[2][2] = "z";
      def s = ring(l);
      s;
      → // coefficients: QQ
      → // number of vars : 2
      → //        block   1 : ordering dp
      → //                  : names    x z
      → //        block   2 : ordering C
    """
    return list_ring(L)


@command("ring_list")
def ring_list(r: Ring) -> List:
    """ring_list(r): ringlist(r), with the coefficients as a coefficient ring (a cring, printed QQ, ZZ/p
    or "char,parameters"; create_ring keeps its minimal polynomial).

    Example:
      LIB "standard.lib";
      ring r = (0,a),x,dp;
      ring_list(r)[1];
      → 0,a
      ring s = 7,x,dp;
      ring_list(s)[1];
      → ZZ/7
    """
    return List([CoeffRing(r)] + list(ringlist(r).items[1:]))


def _lenient_ordering(text: str, nvars: int) -> list[OrderBlock]:
    """The blocks of an ordering string; as Singular, the last block of a size is extended when the
    blocks cover fewer than nvars variables."""
    covered = _covered(text)
    if covered >= nvars:
        return parse_ordering(text, nvars)
    blocks = parse_ordering(text, covered)
    last = max((k for k, b in enumerate(blocks) if b.kind in _SIZED), default=None)
    if last is not None:
        blocks[last] = OrderBlock(blocks[last].kind, blocks[last].size + nvars - covered)
    return blocks


def _covered(text: str) -> int:
    """The variables an ordering string's blocks cover by their explicit sizes and weights (a block
    without a size: all, as many as can be)."""
    total = 0
    for kind, nums in ordering_items(text):
        if kind in ("c", "C", "a"):
            continue
        if kind in _SIZED and not nums:
            return 1 << 30
        total += nums[0] if kind in _SIZED else len(nums or [])
    return total


@command("create_ring")
def create_ring(l1: Any, l2: Any, l3: Any, *rest: Any) -> Ring:
    """create_ring(l1, l2, l3[, l4][, "no_minpoly"]): ring(list(l1, l2, l3, l4)), where l1 may be a
    string such as "0", "(32003)" or "(0,a,b)", l2 a string such as "(x,y,z)" and l3 an ordering string
    such as "dp" or "(lp(3),ds(2))"; "no_minpoly" drops the minimal polynomial.

    Example:
      LIB "standard.lib";
      ring R = create_ring("(0,a)", "(x,y)", "(lp(1),dp(1))");
      R;
      → // coefficients: QQ(a)
      → // number of vars : 2
      → //        block   1 : ordering lp
      → //                  : names    x
      → //        block   2 : ordering dp
      → //                  : names    y
      → //        block   3 : ordering C
    """
    ideal = next((x for x in rest if isinstance(x, Ideal)), NONE)
    keep = "no_minpoly" not in [x for x in rest if isinstance(x, str)]
    if isinstance(l3, str):
        names = l2 if isinstance(l2, List) else List([n.strip() for n in l2.strip().strip("()").split(",") if n.strip()])
        l3 = List([List([b.kind, IntVec(b.weights or ([0] if b.kind in "cC" else [1] * b.size))])
                   for b in _lenient_ordering(l3, len(names))])
        l2 = names
    return list_ring(List([l1, l2, l3, ideal]), minpoly=keep)


@command("quotientList")
def quotient_list(RL: List, *flag: str) -> List:
    """quotientList(RL[, "isSB"]): the ringlist RL of a quotient ring with RL[4] replaced by a standard
    basis for the ordering RL[3] (RL itself with "isSB" or when RL[4] has at most one generator).

    Example:
      LIB "standard.lib";
      ring P = 0,(y,z,u),lp;
      qring Q = std(ideal(y+u2, z+u));
      list L = ringlist(Q);
      L[3][1][1] = "dp";
      quotientList(L)[4];
      → _[1]=z+u
      → _[2]=y+u2
    """
    q = RL.items[3] if len(RL) > 3 else None
    if flag and flag[0] == "isSB" or not isinstance(q, Ideal) or len(q.nonzero()) <= 1:
        return RL
    target = list_ring(List(list(RL.items[:3]) + [NONE]))
    basis = standard_basis(Ideal(target.poly, fetch(q.nonzero(), q.ring, target.poly)))
    back = [Poly(q.ring, p.terms) for p in basis]  # an ideal of the basering, as Singular's
    return List(list(RL.items[:3]) + [Ideal(q.ring, back)])


def _ring_arg(ctx, rest: tuple) -> Ring:
    return rest[0] if rest and isinstance(rest[0], Ring) else ctx.basering()


@command("changechar", lib="ring.lib")
def changechar(ctx, c: Any, *r: Ring) -> Ring:
    """changechar(c[, r]): the ring r (default the basering) with ringlist's first entry replaced by c
    (a characteristic, or a ringlist whose first entry is taken).

    Example:
      LIB "ring.lib";
      ring r = 0,(x,y),(dp(1),ds(1));
      def R = changechar(32003);
      R;
      → // coefficients: ZZ/32003
      → // number of vars : 2
      → //        block   1 : ordering dp
      → //                  : names    x
      → //        block   2 : ordering ds
      → //                  : names    y
      → //        block   3 : ordering C
    """
    base = _ring_arg(ctx, r)
    rl = ringlist(base)
    first = c.items[0] if isinstance(c, List) and len(c) == 1 else c
    return list_ring(List([first] + list(rl.items[1:])))


@command("changeord", lib="ring.lib")
def changeord(ctx, o: List, *r: Ring) -> Ring:
    """changeord(o[, r]): the ring r (default the basering) with the ordering o (ringlist's form: a
    list of [name, intvec]); a quotient ring keeps its ideal (as a standard basis for the new ordering).

    Example:
      LIB "ring.lib";
      ring r = 0,(x,y,z),dp;
      def R = changeord(list(list("lp", 1:3)));
      R;
      → // coefficients: QQ
      → // number of vars : 3
      → //        block   1 : ordering lp
      → //                  : names    x y z
      → //        block   2 : ordering C
    """
    base = _ring_arg(ctx, r)
    rl = ringlist(base)
    return list_ring(List([rl.items[0], rl.items[1], o, rl.items[3]]))


def _new_names(va: str, n: int) -> list[str]:
    """extendring's new variables: T(1..n) for "T(", n letters from a single letter (n <= 26), else va(1..n)."""
    if va.endswith("("):
        return [f"{va}{i})" for i in range(1, n + 1)]
    if len(va) == 1 and va.isalpha() and n <= 26:
        return _letters(va, n)
    return [f"{va}({i})" for i in range(1, n + 1)]


def _sized_blocks(o: str, iv: list[int], n: int) -> str:
    """ring.lib's use of an intvec in extendring: the sizes of the blocks of o in turn; a weighted block
    (w or W) takes iv[1] weights iv[2..iv[1]+1] first; the rest of the n variables go to the last block."""
    left = n
    weighted = ""
    w = max(o.find("w"), o.find("W"))
    if w >= 0:
        k = iv[0]
        weighted = o[w:w + 2] + "(" + ",".join(str(v) for v in iv[1:k + 1]) + ")"
        o = o[:w] + "@" + o[w + 2:]
        left -= k
        iv = iv[k + 1:]
    parts = o.split(",")
    sizes = iter(iv)
    for j, part in enumerate(parts[:-1]):
        if part != "@":
            size = next(sizes, None)
            if size is None:
                break
            parts[j] = f"{part}({size})"
            left -= size
    o = ",".join(parts).replace("@", weighted)
    if left > 0 and not o.endswith(")"):
        o += f"({left})"
    return o


@command("extendring", lib="ring.lib")
def extendring(ctx, n: int, va: str, o: str, *rest: Any) -> Ring:
    """extendring(n, va, o[, iv, i, r]): the ring r (default the basering) with n new variables named
    from va ("T" gives T, U, ... (T(1..n) beyond 26), "x(" gives x(1..n)), in front (i = 0, default) or
    after the old ones (i != 0), ordered by o (dp gets the size n) followed (preceded) by r's ordering;
    a c or C at either end of o is the module ordering of the whole; a nonzero intvec iv gives the
    blocks' sizes (and the weights of a weighted block).

    Example:
      LIB "ring.lib";
      ring r = 0,(x,y),ds;
      def R = extendring(2, "t(", "dp");
      R;
      → // coefficients: QQ
      → // number of vars : 4
      → //        block   1 : ordering dp
      → //                  : names    t(1) t(2)
      → //        block   2 : ordering ds
      → //                  : names    x y
      → //        block   3 : ordering C
    """
    from .sing_lib import comment
    o1 = o2 = ""
    has_c = any(c in o for c in "cC")
    if has_c:
        if o[0] in "cC":
            o1, o = o[:2], o[2:]
        else:
            o2, o = o[-2:], o[:-2]
    rest = rest or (0,)
    iv: list[int] = []
    if isinstance(rest[0], IntVec):
        iv = list(rest[0].values)
        i = rest[1] if len(rest) > 1 else 0
        r = rest[2] if len(rest) > 2 else ctx.basering()
        if not any(iv) and not o.endswith(")") and "," not in o:
            o += f"({n})"
    else:
        i = rest[0]
        r = rest[1] if len(rest) > 1 else ctx.basering()
        if not o.endswith(")") and "," not in o:
            o += f"({n})"
    ro = ordstr(r)
    v = w = ""
    if ro[0] in "cC":
        v, ro = ro[:2], ro[2:]
    else:
        w, ro = ro[-2:], ro[:-2]
    if not has_c:
        o1, o2 = v, w
    if any(iv):
        o = _sized_blocks(o, iv, n)
    old = list(r.names)
    if i == 0:
        names, o = _new_names(va, n) + old, o1 + o + "," + ro + o2
    else:
        names, o = old + _new_names(va, n), o1 + ro + "," + o + o2
    comment(ctx, "\n// 'extendring' created a new ring.\n// To see the ring, type (if the name 'R' was "
            "assigned to the return value):\n     show(R);\n", depth=1)
    return create_ring(ring_list(r).items[0], List(names), "(" + o.replace(" ", "") + ")")
