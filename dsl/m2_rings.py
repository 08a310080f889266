"""Macaulay2's rings: polynomial rings over QQ and ZZ/p (``QQ[x,y]``), towers (``QQ[t][x,y]``),
quotient rings (``R/I``) and the promotion of elements between them.

Every ring is an :class:`M2Ring` on a kernel ring of its own (:class:`FlatRing`: equal only to
itself, so elements remember their ring): a tower ``A[x]`` is flattened to the polynomial ring in
its variables and the coefficient ring's (``QQ[t][x]`` is ``QQ[x,t]`` with the product order, ``x``
first), a quotient ``R/I`` has ``R``'s variables and a :class:`~mech.kernel.quotient.Quotient`
reducing every element to its normal form, as Macaulay2 does on every operation.  An element of a
ring promotes to the rings built on it (towers over it, its quotients) by its variables."""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any, Optional, Sequence

from ..kernel import Block, MonomialOrder, Poly, PolyRing
from ..kernel.quotient import Quotient
from .errors import MechRuntimeError, MechTypeError
from .m2_values import QQ_RING, CoeffRing
from .values import OrderBlock, Ring


class FlatRing(PolyRing):
    """The kernel ring of one Macaulay2 ring: equal only to itself (``owner``: that ring)."""

    owner: "M2Ring"

    def __eq__(self, other: object) -> bool:
        return self is other

    def __hash__(self) -> int:
        return id(self)


#: how values print (``value``: Macaulay2's ``toString``), set by :mod:`mech.dsl.m2_printing`
TEXT: dict[str, Any] = {"value": str}


@dataclass(eq=False)
class M2Ring(Ring):
    """A Macaulay2 ring on its kernel ring ``poly`` (see the module's docstring)."""

    coeffs: CoeffRing = QQ_RING              #: the coefficient field at the bottom of a tower
    base: Any = None                         #: the coefficient ring: a CoeffRing or an M2Ring
    own: tuple[str, ...] = ()                #: the ring's own variables (a tower's outer ones)
    parent: Optional["M2Ring"] = None        #: R, for R/I
    relations: tuple[Poly, ...] = ()         #: I's generators as given, for R/I
    quotient: Optional[Quotient] = None      #: all relations (a tower's coefficient ring's too)
    degrees: tuple[int, ...] = ()            #: the degree of each (flattened) variable
    max_exponent: Optional[int] = None       #: MonomialSize => n: exponents below 2^(n-1)
    info: dict = field(default_factory=dict)  #: what other libraries keep about the ring

    def describe(self) -> str:
        """The ring as Macaulay2 writes an unnamed one: ``QQ[x..z]``, ``(ZZ/101)[a, c]``,
        ``(QQ[t])[x]``, ``R/(x^2,y)``."""
        P = self.info.get("localized_at")
        if P is not None:
            return f"localRing({ring_name(self.info['over'], paren=False)},{TEXT['value'](P)})"
        if self.parent is not None:
            rel = [TEXT["value"](g) for g in self.relations] or ["0"]
            text = rel[0] if len(rel) == 1 and _atomic(rel[0]) else f"({','.join(rel)})"
            return f"{ring_name(self.parent, paren=False)}/{text}"
        return f"{ring_name(self.base, paren=True)}[{', '.join(variable_runs(self.own))}]"

    @property
    def is_quotient(self) -> bool:
        return self.quotient is not None

    @property
    def m2_fields(self) -> dict[str, Any]:
        """A local ring R_P's ``maxIdeal`` (P) and ``residueMap`` (R_P -> frac(R/P), the variables to
        their normal forms modulo P); no fields for other rings."""
        P = self.info.get("localized_at")
        if P is None and "legacy_max" in self.info:  # setMaxIdeal m (the LocalRings package's legacy)
            m, residue = self.info["legacy_max"]
            return {"maxIdeal": m, "residueMap": residue}
        if P is None:
            return {}
        from .m2_values import RingMap
        R = self.info["over"]
        field_ = fraction_field(cached_quotient(R, P))
        images = tuple(normal(Poly(field_.ring.poly, dict(R.poly.gen(i).terms))) for i in range(R.poly.nvars))
        return {"maxIdeal": P, "residueMap": RingMap(field_, self, images)}

    def ambient(self) -> "M2Ring":
        """The polynomial ring of a quotient (the ring itself when it is none)."""
        r = self
        while r.parent is not None:
            r = r.parent
        return r


def ring_name(r: Any, paren: bool) -> str:
    """A ring as part of another's description: its name, else its description (in parentheses
    when ``paren`` and it is not a plain word)."""
    text = r.name or r.describe()
    return f"({text})" if paren and not re.fullmatch(r"\w+", text) else text


def _atomic(s: str) -> bool:
    return all(ch.isalnum() or ch in "_^" for ch in s)


def variable_runs(names: Sequence[str]) -> list[str]:
    """Variables as Macaulay2 lists them: runs of consecutive ones as ``a..c`` or ``x_1..x_4``."""
    out: list[str] = []
    k = 0
    while k < len(names):
        j = k
        while j + 1 < len(names) and _next(names[j]) == names[j + 1]:
            j += 1
        out.append(names[k] if j == k else f"{names[k]}..{names[j]}")
        k = j + 1
    return out


def _next(name: str) -> Optional[str]:
    """The name after ``name`` in a run (``b`` after ``a``, ``x_2`` after ``x_1``, ``x_(1,3)`` after ``x_(1,2)``)."""
    if len(name) == 1 and name.isalpha() and name not in "zZ":
        return chr(ord(name) + 1)
    m = re.fullmatch(r"(.+_\(?(?:-?\d+,)*)(-?\d+)(\)?)", name)
    if m:
        return f"{m.group(1)}{int(m.group(2)) + 1}{m.group(3)}"
    return None


# ---------------------------------------------------------------- making rings
def _flat(field: Any, names: Sequence[str], blocks: Sequence[Block]) -> FlatRing:
    return FlatRing(field, list(names), MonomialOrder(list(blocks), len(names)))


def kernel_blocks(blocks: Sequence[OrderBlock]) -> list[Block]:
    return [Block(b.kind, b.size, b.weights) for b in blocks if b.kind not in ("c", "C")]


def polynomial_ring(base: Any, names: Sequence[str], blocks: Sequence[OrderBlock],
                    degrees: Sequence[int] = (), max_exponent: Optional[int] = None) -> M2Ring:
    """``base[names]`` with the order ``blocks`` on the new variables (a tower: then the base's)."""
    if isinstance(base, CoeffRing):  # over ZZ: QQ's arithmetic on integral polynomials (is_integral)
        coeffs, field, below, below_blocks = base, base.field or QQ_RING.field, (), []
    elif isinstance(base, M2Ring):
        if base.info.get("local") is not None:
            raise MechRuntimeError("polynomial rings over local rings are not supported")
        coeffs, field, below = base.coeffs, base.poly.field, base.poly.names
        below_blocks = list(base.poly.order.blocks)
    else:
        raise MechTypeError("a polynomial ring is built over a ring")
    clash = sorted(set(names) & set(below))
    if clash:
        raise MechRuntimeError(f"the variable {clash[0]} is a variable of the coefficient ring too")
    flat = _flat(field, list(names) + list(below), kernel_blocks(blocks) + below_blocks)
    degs = tuple(degrees) or (1,) * len(names)
    ring = M2Ring(flat, (), tuple(blocks) + (OrderBlock("C"),), coeffs=coeffs, base=base, own=tuple(names),
                  degrees=degs + (base.degrees if isinstance(base, M2Ring) else ()), max_exponent=max_exponent)
    flat.owner = ring
    if isinstance(base, M2Ring) and base.quotient is not None:
        ring.quotient = Quotient.of([promote(g, ring, check=False) for g in base.quotient.basis], flat)
    return ring


def is_integral(ring: Any) -> bool:
    """Whether a ring (or a value's kernel ring) is built over ZZ (its elements have integral coefficients)."""
    owner = getattr(ring, "owner", ring)
    return isinstance(owner, M2Ring) and owner.coeffs.characteristic is None


def quotient_ring(R: M2Ring, gens: Sequence[Poly]) -> M2Ring:
    """``R/I`` for the ideal ``I`` of ``R`` generated by ``gens``."""
    if R.info.get("local") is not None:
        raise MechRuntimeError("quotients of local rings are not supported")
    if is_integral(R):
        raise MechRuntimeError("quotient rings of polynomial rings over ZZ are not supported by mech")
    old = R.poly
    flat = FlatRing(old.field, old.names, old.order)
    S = M2Ring(flat, (), R.blocks, coeffs=R.coeffs, base=R.base, own=R.own, parent=R,
               relations=tuple(Poly(flat, dict(g.terms)) for g in gens), degrees=R.degrees,
               max_exponent=R.max_exponent)
    flat.owner = S
    below = list(R.quotient.basis) if R.quotient is not None else []
    S.quotient = Quotient.of([Poly(flat, dict(g.terms)) for g in below + list(gens) if not g.is_zero()], flat)
    return S


def cached_quotient(R: M2Ring, I: Any) -> M2Ring:
    """``R/I`` for an ideal I of R: the same ring again for the same ideal (as Macaulay2 keeps it)."""
    cache = R.info.setdefault("quotients_by", {})
    if id(I) not in cache:
        cache[id(I)] = (I, quotient_ring(R, list(I.gens)))
    return cache[id(I)][1]


@dataclass(eq=False)
class FractionField:
    """``frac R`` of a domain R (a name and the target of a local ring's residue map: mech does not
    compute in it)."""
    ring: M2Ring
    name: str = ""

    def describe(self) -> str:
        name = ring_name(self.ring, paren=False)
        return f"frac {name}" if name.isidentifier() else f"frac({name})"


def fraction_field(R: M2Ring) -> FractionField:
    """``frac R``, the same value again for the same ring."""
    if "frac" not in R.info:
        R.info["frac"] = FractionField(R)
    return R.info["frac"]


def exact_over_zz(fn: Any) -> Any:
    """Mark a command of the dialect as exact on elements of rings over ZZ (it neither divides nor
    computes a Gröbner basis over QQ; the interpreter refuses the others there)."""
    fn.zz_ok = True
    return fn


def in_group_rings(fn: Any) -> Any:
    """Mark a command of the dialect as exact on elements of rings with invertible variables
    (``GroupLex``): it only prints or reads the ring (the interpreter refuses the others there)."""
    fn.group_ok = True
    return fn


def in_quotients(fn: Any) -> Any:
    """Mark a command of the dialect as correct on elements of quotient rings (the interpreter
    refuses the others there)."""
    fn.quotient_ok = True
    return fn


# ---------------------------------------------------------------- elements
def owner(p: Poly) -> Optional[M2Ring]:
    """The Macaulay2 ring of a kernel polynomial (None for rings not made here)."""
    return getattr(p.ring, "owner", None)


def _below(ring: M2Ring) -> list[M2Ring]:
    """The rings whose elements promote to ``ring``: its quotient parents and coefficient rings."""
    out: list[M2Ring] = []
    todo = [ring]
    while todo:
        r = todo.pop()
        for s in (r.parent, r.base):
            if isinstance(s, M2Ring) and s not in out:
                out.append(s)
                todo.append(s)
    return out


def promotes(source: M2Ring, target: M2Ring) -> bool:
    """Whether elements of ``source`` promote to ``target``."""
    return source is target or source in _below(target)


def promote(p: Poly, target: M2Ring, check: bool = True) -> Poly:
    """``p`` as an element of ``target`` (a ring built on ``p``'s ring), in normal form."""
    if p.ring is target.poly:
        return p
    source = owner(p)
    if check and (source is None or not promotes(source, target)):
        raise MechTypeError("the element's ring does not promote to this ring")
    pad = target.poly.nvars - p.ring.nvars
    terms = {(0,) * pad + e: c for e, c in p.terms.items()} if pad else dict(p.terms)
    return normal(Poly(target.poly, terms))


def normal(p: Poly) -> Poly:
    """``p`` reduced modulo its ring's relations (itself in a polynomial ring)."""
    ring = owner(p)
    if ring is None or ring.quotient is None or p.is_zero():
        return p
    return ring.quotient.reduce(p)


def common_ring(a: M2Ring, b: M2Ring) -> Optional[M2Ring]:
    """The ring both promote to (one of the two), if any."""
    if promotes(a, b):
        return b
    if promotes(b, a):
        return a
    return None


def lift_gens(ring: M2Ring, gens: Sequence[Poly]) -> list[Poly]:
    """Generators of the preimage in the flattened polynomial ring of the ideal ``gens`` of
    ``ring``: ``gens`` and the ring's relations (computations in R/Q happen on I + Q)."""
    out = [g for g in gens if not g.is_zero()]
    if ring.quotient is not None:
        out += list(ring.quotient.basis)
    return out


def reduce_all(ring: M2Ring, polys: Sequence[Poly]) -> list[Poly]:
    """Polynomials of the flattened ring as elements of ``ring``: normal forms, zeros dropped."""
    out = []
    for p in polys:
        q = normal(p) if ring.quotient is not None else p
        if not q.is_zero() and q not in out:
            out.append(q)
    return out


# ---------------------------------------------------------------- towers
def degree_vectors(ring: M2Ring) -> list[tuple[int, ...]]:
    """The degree of each flattened variable as Macaulay2 grades a tower: ``A[x]`` gives its own
    variables ``{d, 0, ...}`` and ``A``'s ``{0, degree in A}`` (one component in a plain ring)."""
    if isinstance(ring.base, M2Ring):
        below = degree_vectors(ring.base)
        width = 1 + (len(below[0]) if below else 1)
        own = [(d,) + (0,) * (width - 1) for d in ring.degrees[:len(ring.own)]]
        return own + [(0,) + v for v in below]
    if "multidegrees" in ring.ambient().info:  # R/I: R's
        return list(ring.ambient().info["multidegrees"])
    return [(d,) for d in (ring.degrees or (1,) * ring.poly.nvars)]


def term_degree(e: tuple[int, ...], vecs: Sequence[tuple[int, ...]]) -> tuple[int, ...]:
    """The degree vector of the monomial with exponent ``e`` (``vecs``: :func:`degree_vectors`)."""
    return tuple(sum(k * v[j] for k, v in zip(e, vecs)) for j in range(len(vecs[0]) if vecs else 1))


def multidegree(p: Poly) -> tuple[int, ...]:
    """``degree p`` in Macaulay2: the componentwise largest degree vector of p's terms."""
    ring = owner(p)
    vecs = degree_vectors(ring) if ring is not None else [(1,)] * p.ring.nvars
    degs = [term_degree(e, vecs) for e in p.terms]
    return tuple(max(d[j] for d in degs) for j in range(len(degs[0])))


def tower_terms(p: Poly) -> Optional[list[tuple[tuple[int, ...], Poly]]]:
    """The terms of ``p`` in a tower ``A[x]`` as (exponent of the own variables, coefficient in
    ``A``), from the largest down; None when ``p``'s ring is no tower."""
    ring = owner(p)
    if ring is None or not isinstance(ring.base, M2Ring):
        return None
    own = len(ring.own)
    groups: dict[tuple[int, ...], dict] = {}
    for e, c in p.sorted_terms():
        groups.setdefault(e[:own], {})[e[own:]] = c
    return [(e, Poly(ring.base.poly, sub)) for e, sub in groups.items()]


_INTEGERS: list[M2Ring] = []


def integers() -> M2Ring:
    """ZZ as a ring with no variables, for integers Macaulay2 puts in matrices and ideals with no
    ring in use (``matrix {{1, 2}}``, ``ideal 7``): one ring, named ``ZZ``."""
    if not _INTEGERS:
        from .m2_values import ZZ_RING
        ring = polynomial_ring(ZZ_RING, [], [OrderBlock("dp", 0, ())])
        ring.name = "ZZ"
        _INTEGERS.append(ring)
    return _INTEGERS[0]
