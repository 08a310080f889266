"""Ideal-style operations on modules (Singular dialect): ``intersect``, ``quotient``, ``interred``,
``dim``, ``homog``, ``eliminate``.

Intersections and quotients come from syzygies (Greuel–Pfister, *A Singular Introduction to Commutative
Algebra*, 2.8): M ∩ N is the image under M of the first parts of the syzygies of [M | N]; M : N (an
ideal) intersects over N's generators n the first entries of the syzygies of [n | M]; M : p (a module)
is the first part of the syzygies of [p*e_1, ..., p*e_r | M].
"""
from __future__ import annotations

from typing import Callable, Optional

from ..dsl.registry import command
from ..dsl.values import Ideal
from ..dsl.values_modules import Module, Vector, lead_term
from ..kernel import Poly, PolyRing
from ..kernel import modules as km
from .module_commands import _basis, _global, _module, _vecs, global_twin, q_columns


def _first_parts(ring: PolyRing, rank: int, gens: list[dict], k: int) -> list[dict]:
    """The first k entries of the syzygies of gens (over a qring R/Q: of gens and the q*e_i)."""
    return [{t: c for t, c in s.items() if t[1] < k}
            for s in km.syzygies(global_twin(ring), rank, gens + q_columns(ring, rank))]


@command("intersect")
def intersect_one(M: Module) -> Module:
    """intersect(M) of one module: M as a standard basis."""
    return _module(M.ring, _basis(M.ring, M.rank, _vecs(M)), M.rank, True)


@command("intersect")
def intersect(M: Module, N: Module, *more: Module) -> Module:
    """intersect(M, N, ...): the intersection of submodules of a free module (a standard basis).

    Example:
      ring r = 0,(x,y),dp;
      intersect(module([x,y]), module([x2,0],[0,y]));
      → _[1]=x2*gen(1)+xy*gen(2)
    """
    ring = M.ring
    out = M
    for N2 in (N,) + more:
        rank, k = max(out.rank, N2.rank), len(out.gens)
        parts = _first_parts(ring, rank, _vecs(out) + _vecs(N2), k)
        images = []
        for a in parts:
            img: dict = {}
            for (e, j), c in a.items():
                km._add_multiple(img, out.gens[j].terms(), e, c)
            images.append({t: c for t, c in img.items() if c != 0})
        out = _module(ring, _basis(ring, rank, images), rank, True)
    return out


@command("quotient")
def quotient(M: Module, N: Module | Poly | Ideal) -> Module | Ideal:
    """quotient(M, N): the ideal {f : f*N inside M}; quotient(M, p): the module {v : p*v inside M}.

    Example:
      ring r = 0,(x,y),dp;
      quotient(module([x,y],[y,x2]), module([x2,0],[0,y]));
      → _[1]=x3-y2
    """
    ring = M.ring
    rank = M.rank
    if isinstance(N, Ideal):  # {v : I*v inside M}: the intersection over I's generators
        parts = [quotient(M, f) for f in N.gens if not f.is_zero()]
        return intersect(*parts) if len(parts) > 1 else parts[0] if parts else Module(ring, [], rank)
    if isinstance(N, Poly):
        scaled = [{(e, i): c for e, c in N.terms.items()} for i in range(rank)]
        parts = _first_parts(ring, rank, scaled + _vecs(M), rank)  # coefficient j of p*e_j: entry j
        return _module(ring, _basis(ring, rank, parts), rank, True)
    from ..kernel.ideals import intersect as intersect_ideals
    from .standard import normalize, standard_basis
    pieces = []
    for n in N.nonzero():
        parts = _first_parts(ring, max(rank, n.nrows), [n.terms()] + _vecs(M), 1)
        pieces.append([Poly(ring, {e: c for (e, _), c in a.items()}) for a in parts] or [ring.zero()])
    if not pieces:
        return Ideal(ring, [ring.one()], is_std=True)
    gens = intersect_ideals(*pieces, ring=ring) if len(pieces) > 1 else pieces[0]
    return Ideal(ring, standard_basis(Ideal(ring, [normalize(g) for g in gens])), is_std=True)


@command("interred")
def interred(M: Module) -> Module:
    """interred(M): generators of M with no leading term dividing another's and reduced tails."""
    ring = M.ring
    _global(ring, "interred")
    return _module(ring, interreduce(ring, M.rank, _vecs(M), _key(ring)), M.rank)


def interreduce(ring: PolyRing, rank: int, vecs: list[dict], key: Callable[[tuple], tuple]) -> list[dict]:
    """Vectors generating the same module as ``vecs`` for the global module order ``key``, none with a
    leading term dividing another's, tails reduced, scaled as Singular's std and sorted by leading term."""
    gens = [g for g in vecs if g]
    changed = True
    while changed:
        changed = False
        for i in range(len(gens)):
            others = [g for j, g in enumerate(gens) if j != i and g]
            gb = km.ModuleGB(ring, rank, key=key)
            gb._set_basis(others, [max(g, key=key) for g in others])
            red = gb.reduce(gens[i])
            if red != gens[i]:
                gens[i], changed = red, True
        gens = [g for g in gens if g]
    from .module_commands import _normalized
    out = [_normalized(ring, g, max(g, key=key)) for g in gens]
    out.sort(key=lambda g: key(max(g, key=key)))
    return out


@command("eliminate")
def eliminate(M: Module, m: Poly) -> Module:
    """eliminate(M, m): the submodule of the vectors of M free of the variables of the monomial m (M
    intersected with the free module over the other variables), a standard basis: the vectors free
    of them in a basis for the ordering a(1 on them), then the ring's (term over position).

    Example:
      ring r = 0,(t,x,y),dp;
      eliminate(module([x-t2, 0], [y-t3, 0], [0, x-t]), t);
      → _[1]=x3*gen(1)-y2*gen(1)
    """
    from ..kernel.ideals import with_order
    from ..kernel.order import Block, MonomialOrder
    ring = M.ring
    _global(ring, "eliminate")
    elim = {i for i, k in enumerate(m.lm()) if k} if not m.is_constant() else set()
    weights = tuple(1 if i in elim else 0 for i in range(ring.nvars))
    aux = with_order(ring, MonomialOrder([Block("a", ring.nvars, weights)] + list(ring.order.blocks), ring.nvars))
    gb = km.ModuleGB(aux, M.rank)
    gb.add([v for v in _vecs(M) if v])
    kept = [v for v in gb.basis if not any(e[i] for (e, _), c in v.items() if c != 0 for i in elim)]
    return _module(ring, _basis(ring, M.rank, kept), M.rank, True)


def _key(ring: PolyRing):
    from ..dsl.values_modules import kernel_key
    return kernel_key(ring)


def _component_leads(M: Module) -> dict[int, list[tuple]]:
    leads: dict[int, list[tuple]] = {}
    for g in M.nonzero():
        e, i = lead_term(g)
        leads.setdefault(i, []).append(e)
    return leads


def _component_lead_sets(ctx, M: Module) -> list[list[tuple]]:
    """For each component i of R^r/M (M taken as a standard basis), the leading exponents of M's
    vectors there and of the qring's relations: R/L_i's leading ideal."""
    from ..dsl.qrings import quotient_of
    if not M.is_std:
        ctx.assume_std(M, 0)  # type: ignore[arg-type]
    leads = _component_leads(M)
    q = quotient_of(M.ring)
    qleads = [g.lm() for g in q.basis] if q is not None else []
    return [leads.get(i, []) + qleads for i in range(M.rank)]


@command("dim")
def dim(ctx, M: Module) -> int:
    """dim(M): the Krull dimension of R^r/M for a standard basis M (-1 when M is the free module; over
    a qring R/Q of (R/Q)^r/M)."""
    from ..kernel.dimension import krull_dim
    n = M.ring.nvars
    dims = [krull_dim(es, n) if es else n
            for es in _component_lead_sets(ctx, M) if not any(not any(e) for e in es)]
    return max(dims) if dims else -1


@command("mult")
def mult(ctx, M: Module) -> int:
    """mult(M): the degree (multiplicity for a local ordering) of R^r/M for a standard basis M: the sum
    of those of the R/L_i of the components' leading ideals L_i of the largest dimension.

    Example:
      ring r = 0,(x,y),dp;
      mult(std(module([x2,0],[0,y3])));
      → 5
    """
    from ..kernel import hilbert as H
    from ..kernel.dimension import krull_dim
    n = M.ring.nvars
    parts = [(krull_dim(es, n) if es else n, H.mult(es, n))
             for es in _component_lead_sets(ctx, M) if not any(not any(e) for e in es)]
    top = max((d for d, _ in parts), default=-1)
    return sum(m for d, m in parts if d == top)


def _register_multiplicity() -> None:
    """Singular's ``multiplicity``: another name of ``mult`` (ideals first, as the registry tries them in turn)."""
    from .hilbert import mult as mult_ideal
    command("multiplicity")(mult_ideal)
    command("multiplicity")(mult)


_register_multiplicity()


@command("homog")
def homog(ctx, M: Module | Vector) -> int:
    """homog(M): 1 if M is homogeneous for some degrees of the components (each generator's terms of
    one degree, counting its component's degree), else 0; a module variable M gets those degrees as its
    attribute isHomog (the least ones: 0 for a component no other one's degree fixes)."""
    from .ideals import mark_homogeneous
    from .polynomials import _ring_weights
    ws = _ring_weights(M.ring) or [1] * M.ring.nvars

    def wdeg(e: tuple) -> int:
        return sum(a * w for a, w in zip(e, ws))
    vecs = [{(wdeg(e), i): c for (e, i), c in v.items()} for v in
            ([M.terms()] if isinstance(M, Vector) else [g.terms() for g in M.nonzero()])]
    shift: dict[int, int] = {}
    group: dict[int, int] = {}  # component -> the first component of its connected set
    todo = [v for v in vecs if v]
    while todo:
        v = next((w for w in todo if any(i in shift for _, i in w)), todo[0])
        todo.remove(v)
        known: Optional[int] = next((e + shift[i] for e, i in v if i in shift), None)
        root = next((group[i] for _, i in v if i in shift), None)
        if known is None:
            e, i = next(iter(v))
            shift[i], group[i], root = 0, i, i
            known = e
        for e, i in v:
            if i not in shift:
                shift[i], group[i] = known - e, root
            elif e + shift[i] != known:
                return 0
    if isinstance(M, Module):
        least = {r: min(s for i, s in shift.items() if group[i] == r) for r in set(group.values())}
        mark_homogeneous(ctx, [shift[i] - least[group[i]] if i in shift else 0 for i in range(M.rank)])
    return 1


@command("transpose")
def transpose(M: Module) -> Module:
    """transpose(M): the module of the columns of the transposed matrix of M.

    Example:
      ring r = 0,(x,y),dp;
      print(transpose(module([x,y],[1,0])));
      → x,y,
      → 1,0
    """
    cols = [g.padded(M.rank) for g in M.gens]
    return Module(M.ring, [Vector(M.ring, [c[i] for c in cols]) for i in range(M.rank)], len(cols))


@command("highcorner")
def highcorner(M: Module) -> Vector:
    """highcorner(M): for a standard basis M, the smallest of the highest corners of the components whose
    leading ideal is zero-dimensional, in the ring's monomial ordering, in the largest component (in the
    module ordering) where it is one (as Singular; 0 if there is none).

    Example:
      ring r = 32003,(x,y),(c,ds);
      module m = maxideal(3)*gen(1), maxideal(2)*gen(2);
      highcorner(std(m));
      → [y2]
    """
    from ..kernel import hilbert as H
    ring = M.ring
    corners = []
    for i, es in _component_leads(M).items():
        if H.vdim(es, ring.nvars) <= 0:
            continue
        corners.append((min(H.kbase(es, ring.nvars), key=ring.order.key), i))
    if not corners:
        return Vector(ring, [])
    low = min(ring.order.key(e) for e, _ in corners)
    e, i = max((c for c in corners if ring.order.key(c[0]) == low), key=_key(ring))
    return Vector(ring, [ring.zero()] * i + [ring.monomial(e)])
