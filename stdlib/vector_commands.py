"""Polynomial commands on vectors and modules (Singular dialect): ``lead``, ``leadcoef``, ``leadexp``,
``leadmonom``, ``ord``, ``deg``, ``jet``, ``diff``, ``subst``, ``simplify(v, 1)``, ``cleardenom``, and
``kbase``/``vdim`` of a module's standard basis.  Entrywise commands reuse the polynomial ones on the
vector's entries; leading terms follow the ring's module ordering.
"""
from __future__ import annotations

from typing import Any, Callable

from ..dsl.convert_modules import to_module
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, Matrix, Number
from ..dsl.values_modules import Module, Vector, lead_term
from ..kernel import Poly
from ..kernel.poly import divides
from . import monomials, polynomials, polyops
from .idealops import simplify_generators
from .hilbert import kbase as kbase_ideal, vdim as vdim_ideal
from .module_commands import _normalized


def _each(m: Vector | Module, f: Callable[[Poly], Poly]) -> Vector | Module:
    if isinstance(m, Vector):
        return Vector(m.ring, [f(p) for p in m.entries])
    return Module(m.ring, [Vector(m.ring, [f(p) for p in g.entries]) for g in m.gens], m.rank)


def _lead(v: Vector) -> Vector:
    t = lead_term(v)
    if t is None:
        return v
    return Vector.from_terms(v.ring, {t: v.terms()[t]})


@command("lead")
def lead(m: Vector | Module) -> Vector | Module:
    """lead(v): the leading term of v (of each generator of a module) in the module ordering."""
    return _lead(m) if isinstance(m, Vector) else Module(m.ring, [_lead(g) for g in m.gens], m.rank)


@command("leadcoef")
def leadcoef(v: Vector) -> Number:
    """leadcoef(v): the coefficient of v's leading term."""
    t = lead_term(v)
    return Number(v.ring, v.terms()[t] if t is not None else v.ring.field.zero)


@command("leadexp")
def leadexp(v: Vector) -> IntVec:
    """leadexp(v): the exponents of v's leading term followed by its component."""
    t = lead_term(v)
    return IntVec(list(t[0]) + [t[1] + 1] if t is not None else [0] * (v.ring.nvars + 1))


@command("leadmonom")
def leadmonom(v: Vector) -> Vector:
    """leadmonom(v): the leading monomial of v times its generator (coefficient 1)."""
    t = lead_term(v)
    return Vector.from_terms(v.ring, {t: v.ring.field.one}) if t is not None else v


@command("ord")
def ord_(v: Vector) -> int:
    """ord(v): the (weighted) degree of v's leading monomial (-1 for 0)."""
    t = lead_term(v)
    return monomials.ord_(v.ring.monomial(t[0])) if t is not None else -1


@command("deg")
def deg(v: Vector | Module, w: IntVec | None = None) -> int:
    """deg(v): the largest (weighted) degree of v's entries (-1 for 0)."""
    vs = [v] if isinstance(v, Vector) else v.nonzero()
    degs = [polynomials.deg(p, w) if w is not None else polynomials.deg(p) for g in vs for p in g.entries
            if not p.is_zero()]
    return max(degs) if degs else -1


@command("jet")
def jet(m: Vector | Module, d: int) -> Vector | Module:
    """jet(v, d): the terms of v of total degree at most d."""
    return _each(m, lambda p: polyops.jet(p, d))


@command("diff")
def diff(m: Vector | Module, x: Poly) -> Vector | Module:
    """diff(v, x): the derivative of each entry by the variable x."""
    return _each(m, lambda p: polynomials.diff(p, x))


@command("subst")
def subst(m: Vector | Module, *pairs: Any) -> Vector | Module:
    """subst(v, x, p, ...): x replaced by p in each entry."""
    return _each(m, lambda p: polynomials.subst(p, *pairs))


@command("cleardenom")
def cleardenom(v: Vector) -> Vector:
    """cleardenom(v): v times a constant with coprime integer coefficients, a positive leading one."""
    t = lead_term(v)
    if t is None or v.ring.field.characteristic:
        return v
    return Vector.from_terms(v.ring, _normalized(v.ring, v.terms(), t))


@command("simplify")
def simplify(v: Vector, flag: int) -> Vector:
    """simplify(v, 1): v divided by its leading coefficient (other flags leave a vector as it is)."""
    t = lead_term(v)
    if not flag & 1 or t is None:
        return v
    c = v.terms()[t]
    return Vector.from_terms(v.ring, {s: a / c for s, a in v.terms().items()})


@command("simplify")
def simplify_module(M: Module, flag: int) -> Module:
    """simplify(M, n) of a module: the clean-ups of simplify(I, n) on its generators, leading terms
    (monomial and component) in the module ordering."""
    ring = M.ring
    out = simplify_generators(list(M.gens), flag, lead_term,
                              lambda a, b: a[1] == b[1] and divides(a[0], b[0]), lambda v: simplify(v, 1))
    zero = Vector(ring, [])
    return Module(ring, [zero if v is None else v for v in out] or [zero], M.rank)


@command("simplify")
def simplify_matrix(m: Matrix, flag: int) -> Module:
    """simplify(M, n) of a matrix: as Singular, M converted to the module of its columns, then simplified."""
    return simplify_module(to_module(m, m.ring), flag)


def _component_ideals(M: Module) -> list[Ideal]:
    ring = M.ring
    leads: list[list[Poly]] = [[] for _ in range(M.rank)]
    for g in M.nonzero():
        e, i = lead_term(g)
        leads[i].append(ring.monomial(e))
    return [Ideal(ring, ls or [ring.zero()], is_std=True) for ls in leads]


@command("vdim")
def vdim(ctx, M: Module) -> int:
    """vdim(M): the vector space dimension of R^r/M for a standard basis M (-1 if infinite)."""
    dims = [vdim_ideal(ctx, I) for I in _component_ideals(M)]
    return -1 if any(d < 0 for d in dims) else sum(dims)


@command("kbase")
def kbase(ctx, M: Module) -> Module:
    """kbase(M): the monomials times generators outside the leading module of the standard basis M
    (a vector space basis of R^r/M; 0 if it is infinite-dimensional), component by component."""
    ring = M.ring
    parts = _component_ideals(M)
    if any(vdim_ideal(ctx, I) < 0 for I in parts):
        return Module(ring, [])
    gens = [Vector(ring, [ring.zero()] * i + [p]) for i, I in enumerate(parts)
            for p in kbase_ideal(ctx, I).gens if not p.is_zero()]
    return Module(ring, gens, M.rank)
