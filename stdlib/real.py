"""Real solutions, exactly (:mod:`mech.kernel.real_roots`, ``real_solve``, ``real_curve``,
``real_branches``; docs/real.md): Singular's rootsur.lib (``nrroots``, ``sturm``, ``sturmseq``)
and rootsmr.lib (``nrRootsDeterm``, ``nrRootsProbab``), and mech's own commands for real roots
and solutions, the circuits of a real curve and the real branches at a point.

Decimal numbers are returned as strings with the requested number of digits after the point: the
exact value correctly rounded (its enclosure is refined until both ends round alike)."""
from __future__ import annotations

from fractions import Fraction
from typing import Any, Callable

from ..dsl.errors import MechRuntimeError
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, List, Number
from ..kernel import Poly, PolyRing

_DIGITS_LIMIT = 1000


def _kernel(cmd: str, func: Callable, *args: Any) -> Any:
    """Call a kernel function; its refusals become errors of the command."""
    from ..kernel.real_roots import RealSolvingError
    try:
        return func(*args)
    except RealSolvingError as e:
        raise MechRuntimeError(f"{cmd}: {e}") from None


def _rational(cmd: str, ring: PolyRing) -> None:
    from ..kernel.coeffs import RationalField
    if not isinstance(ring.field, RationalField):
        raise MechRuntimeError(f"{cmd}: only over the rationals (ring r = 0, ...)")


def _digits(cmd: str, digits: int) -> int:
    if not 0 <= digits <= _DIGITS_LIMIT:
        raise MechRuntimeError(f"{cmd}: the number of digits must be between 0 and {_DIGITS_LIMIT}")
    return digits


def _univariate(cmd: str, p: Poly) -> tuple[Any, int]:
    """``p`` as an fmpq_poly and its variable's index (0 for a constant)."""
    from ..kernel.real_solve import to_fmpq_poly
    _rational(cmd, p.ring)
    used = p.variables()
    if len(used) > 1:
        raise MechRuntimeError(f"{cmd}: the polynomial must be univariate")
    var = next(iter(used), 0)
    return to_fmpq_poly(p, var), var


def _rounded(boxes: Callable[[int], list], d: int) -> list[list[str]]:
    """Each box (a list of intervals, ``boxes(k)`` computes them of width ``10^-k``) as its
    coordinates correctly rounded to ``d`` digits: refined until both ends of every interval round
    alike (a value exactly halfway between two roundings is given by its midpoint)."""
    from ..kernel.real_solve import decimal
    for extra in (2, 8, 24, 64):
        found = boxes(d + extra)
        if all(decimal(lo, d) == decimal(hi, d) for box in found for lo, hi in box):
            break
    return [[decimal((lo + hi) / 2, d) for lo, hi in box] for box in found]


def _number(cmd: str, ring: PolyRing, v: Any) -> Any:
    from flint import fmpq
    if isinstance(v, int):
        return fmpq(v)
    if isinstance(v, Number):
        return fmpq(v.c)
    if isinstance(v, Poly) and v.is_constant():
        return fmpq(v.coeff_of(ring.zero_exp))
    raise MechRuntimeError(f"{cmd}: expected a number")


# --- rootsur.lib ---------------------------------------------------------------------------

@command("nrroots", lib="rootsur.lib")
def nrroots(p: Poly) -> int:
    """nrroots(p): the number of distinct real roots of the univariate polynomial p (isolated
    exactly by the Vincent-Collins-Akritas bisection; Singular counts with Sturm-Habicht
    sequences).

    Example:
      LIB "rootsur.lib";
      ring r = 0,x,dp;
      nrroots((x+2)*(x-1)*(x-5)*(x2+1));
      → 3
    """
    from ..kernel.real_roots import count_real_roots
    f, _ = _univariate("nrroots", p)
    if f.is_zero():
        raise MechRuntimeError("nrroots: the zero polynomial has every number as a root")
    return count_real_roots(f) if f.degree() > 0 else 0


@command("sturm", lib="rootsur.lib")
def sturm(p: Poly, a: Any, b: Any) -> int:
    """sturm(p, a, b): the number of distinct real roots of the univariate polynomial p in the
    interval (a, b] (Sturm's theorem); a < b, and neither may be a root.

    Example:
      LIB "rootsur.lib";
      ring r = 0,x,dp;
      sturm((x+2)*(x-1)*(x-5), -3, 6);
      → 3
    """
    from ..kernel.real_roots import sturm_count
    f, _ = _univariate("sturm", p)
    lo, hi = _number("sturm", p.ring, a), _number("sturm", p.ring, b)
    if lo >= hi:
        raise MechRuntimeError("sturm: a must be lower than b")
    if f(lo) == 0 or f(hi) == 0:
        raise MechRuntimeError("sturm: neither a nor b can be roots of p")
    return sturm_count(f, lo, hi)


@command("sturmseq", lib="rootsur.lib")
def sturmseq(p: Poly) -> List:
    """sturmseq(p): the Sturm sequence of the univariate polynomial p (p, p', then the negated
    remainders), divided by the gcd of p and p' (the last one) and scaled to leading
    coefficients 1 or -1, the last replaced by its sign, as rootsur.lib does.

    Example:
      LIB "rootsur.lib";
      ring r = 0,x,dp;
      sturmseq(x3-x);
      → [1]:
      →    x3-x
      → [2]:
      →    x2-1/3
      → [3]:
      →    x
      → [4]:
      →    1
    """
    from flint import fmpq_poly
    from ..kernel.real_roots import sign, sturm_sequence
    from ..kernel.real_solve import from_fmpq_poly
    f, var = _univariate("sturmseq", p)
    if f.degree() < 1:
        raise MechRuntimeError("sturmseq: the polynomial must have a positive degree")
    seq = sturm_sequence(f)
    last = seq[-1]
    s = sign(last.leading_coefficient())
    out = []
    for q in seq[:-1]:
        q = q // (last * s) if last.degree() > 0 else q / (last.leading_coefficient() * s)
        out.append(q / abs(q.leading_coefficient()))
    out.append(fmpq_poly([s]))
    return List([from_fmpq_poly(q, p.ring, var) for q in out])


# --- rootsmr.lib ---------------------------------------------------------------------------

def _zero_dim(cmd: str, I: Ideal) -> list[Poly]:
    from ..kernel.ideals import dimension
    _rational(cmd, I.ring)
    if not I.ring.order.is_global:
        raise MechRuntimeError(f"{cmd} needs a global ordering (dp, lp, ...)")
    gens = I.nonzero()
    if not gens or dimension(gens, I.ring) != 0:
        raise MechRuntimeError(f"{cmd}: the ideal is not zero-dimensional")
    return gens


@command("nrRootsDeterm", lib="rootsmr.lib")
def nr_roots_determ(I: Ideal) -> int:
    """nrRootsDeterm(I): the number of distinct real solutions of the zero-dimensional ideal I:
    the signature of Hermite's quadratic form Tr(b_i b_j) on Q[x]/I (deterministic).

    Example:
      LIB "rootsmr.lib";
      ring r = 0,(x,y),dp;
      nrRootsDeterm(ideal(x2+y2-4, xy-1));
      → 4
    """
    from ..kernel.real_solve import hermite_counts
    return _kernel("nrRootsDeterm", hermite_counts, _zero_dim("nrRootsDeterm", I), I.ring)[1]


@command("nrRootsProbab", lib="rootsmr.lib")
def nr_roots_probab(I: Ideal) -> int:
    """nrRootsProbab(I): the number of distinct real solutions of the zero-dimensional ideal I,
    from a rational univariate representation (a random separating form, checked, so the count is
    exact - Singular's is probabilistic).

    Example:
      LIB "rootsmr.lib";
      ring r = 0,(x,y),dp;
      nrRootsProbab(ideal(x2+y2-4, xy-1));
      → 4
    """
    from ..kernel.real_solve import count_solutions
    return _kernel("nrRootsProbab", count_solutions, _zero_dim("nrRootsProbab", I), I.ring)[1]


# --- mech's commands --------------------------------------------------------------------------

@command("realRoots")
def real_roots(p: Poly, digits: int = 10) -> List:
    """realRoots(p[, digits]): the distinct real roots of the univariate polynomial p, increasing,
    as decimal strings with the given number of digits after the point (default 10).

    Example:
      ring r = 0,x,dp;
      realRoots((x2-2)*(x+1)^2, 6);
      → [1]:
      →    -1.414214
      → [2]:
      →    -1.000000
      → [3]:
      →    1.414214
    """
    from flint import fmpq
    from ..kernel.real_roots import isolate_real_roots
    f, _ = _univariate("realRoots", p)
    d = _digits("realRoots", digits)
    if f.is_zero():
        raise MechRuntimeError("realRoots: the zero polynomial has every number as a root")
    roots = isolate_real_roots(f) if f.degree() > 0 else []

    def boxes(k: int) -> list:
        narrow = [r.refined(fmpq(1, 10 ** k)) for r in roots]
        return [[(r.exact, r.exact) if r.exact is not None else (r.lo, r.hi)] for r in narrow]
    return List([v for v, in _rounded(boxes, d)])


@command("realSolutions")
def real_solutions(I: Ideal, digits: int = 10) -> List:
    """realSolutions(I[, digits]): the distinct real solutions of the zero-dimensional ideal I,
    each a list of its coordinates as decimal strings with the given number of digits after the
    point (default 10); certified (a rational univariate representation, exact root isolation and
    ball arithmetic).

    Example:
      ring r = 0,(x,y),dp;
      realSolutions(ideal(x2+y2-4, x-y), 6);
      → [1]:
      →    [1]:
      →       -1.414214
      →    [2]:
      →       -1.414214
      → [2]:
      →    [1]:
      →       1.414214
      →    [2]:
      →       1.414214
    """
    from ..kernel.real_solve import real_solutions as solve
    d = _digits("realSolutions", digits)
    gens = _zero_dim("realSolutions", I)

    def boxes(k: int) -> list:
        return [s.box for s in _kernel("realSolutions", solve, gens, I.ring, k).real]
    return List([List(pt) for pt in sorted(_rounded(boxes, d), key=lambda pt: [Fraction(v) for v in pt])])


@command("countRealSolutions")
def count_real_solutions(I: Ideal) -> IntVec:
    """countRealSolutions(I): the numbers of distinct complex and of distinct real solutions of the
    zero-dimensional ideal I (a rational univariate representation; vdim(std(I)) counts with
    multiplicity).

    Example:
      ring r = 0,(x,y),dp;
      countRealSolutions(ideal(x2+y2-4, xy-1));
      → 4,4
    """
    from ..kernel.real_solve import count_solutions
    return IntVec(_kernel("countRealSolutions", count_solutions, _zero_dim("countRealSolutions", I), I.ring))


def _curve(cmd: str, I: Ideal) -> list[Poly]:
    _rational(cmd, I.ring)
    if not I.ring.order.is_global:
        raise MechRuntimeError(f"{cmd} needs a global ordering (dp, lp, ...)")
    return I.nonzero() or [I.ring.zero()]


@command("realCircuits")
def real_circuits(I: Ideal) -> int:
    """realCircuits(I): the number of circuits (connected components of the real points, isolated
    real points not counted) of the curve V(I) over the rationals, exactly (a certified sweep of a
    generic plane projection).

    Example:
      ring r = 0,(x,y),dp;
      realCircuits(ideal((x2+y2-1)*((x-3)^2+y2-1)));
      → 2
    """
    from ..kernel.real_curve import curve_topology
    return _kernel("realCircuits", curve_topology, _curve("realCircuits", I), I.ring, None).count


def _box_mid(box: list, d: int) -> List:
    from ..kernel.real_solve import decimal
    return List([decimal((lo + hi) / 2, d) for lo, hi in box])


@command("realTopology")
def real_topology(I: Ideal, digits: int = 6) -> List:
    """realTopology(I[, digits]): the real points of the curve V(I): a list of [1] the number of
    circuits, [2] the circuits, each a list (bounded 1 or 0, a point on it, the lower and the upper
    corner of its bounding box - certified for a bounded circuit, rounded outwards), [3] the
    isolated real points; numbers as decimal strings with the given digits.

    Example:
      ring r = 0,(x,y),dp;
      list T = realTopology(ideal(y2+x2-x3), 3);
      T[1];
      → 1
      T[2][1][1];
      → 0
      T[3];
      → [1]:
      →    [1]:
      →       0.000
      →    [2]:
      →       0.000
    """
    from ..kernel.real_curve import curve_topology
    from ..kernel.real_solve import decimal
    d = _digits("realTopology", digits)
    topo = _kernel("realTopology", curve_topology, _curve("realTopology", I), I.ring, d + 2)
    circuits = []
    for c in topo.circuits:
        circuits.append(List([int(c.bounded), _box_mid(c.samples[0], d),
                              List([decimal(lo, d, -1) for lo, _ in c.box]), List([decimal(hi, d, 1) for _, hi in c.box])]))
    return List([topo.count, List(circuits), List([_box_mid(b, d) for b in topo.isolated])])


@command("realBranches")
def real_branches(I: Ideal, p: Any) -> List:
    """realBranches(I, p): the real branches of the curve V(I) at the point p (a list of rational
    coordinates, or a zero-dimensional ideal: then one answer per real point of it): a list of the
    number of real half-branches (points on a small certified sphere around p), of branches (half
    of them), the kind ("regular", "node", "cusp", "tacnode", "isolated", or "singular" for one
    branch through a singular point that is not a cusp) and the real tangent directions.

    Example:
      ring r = 0,(x,y),dp;
      realBranches(ideal(y2-x2-x3), list(0,0));
      → [1]:
      →    4
      → [2]:
      →    2
      → [3]:
      →    node
      → [4]:
      →    [1]:
      →       [1]:
      →          1.0000
      →       [2]:
      →          -1.0000
      →    [2]:
      →       [1]:
      →          1.0000
      →       [2]:
      →          1.0000
    """
    from ..kernel.real_branches import real_branches as branches
    gens = _curve("realBranches", I)
    point = _point("realBranches", I.ring, p)
    found = _kernel("realBranches", branches, gens, I.ring, point)

    def one(b: Any) -> List:
        return List([b.half_branches, b.branches, b.kind, List([_box_mid(t, 4) for t in b.tangents])])
    if isinstance(p, Ideal) and not all(g.is_constant() for g in p.gens):
        return List([List([_box_mid(b.point, 6)] + list(one(b).items)) for b in found])
    return one(found[0])


def _point(cmd: str, ring: PolyRing, p: Any) -> list:
    """A rational point (list, intvec or ideal of numbers) or the generators of a 0-dimensional ideal."""
    if isinstance(p, Ideal) and not all(g.is_constant() for g in p.gens):
        return p.nonzero()
    items = list(p.values) if isinstance(p, IntVec) else list(p.items) if isinstance(p, List) else \
        list(p.gens) if isinstance(p, Ideal) else None
    if items is None:
        raise MechRuntimeError(f"{cmd}: give the point as a list of coordinates or a zero-dimensional ideal")
    if len(items) != ring.nvars:
        raise MechRuntimeError(f"{cmd}: the point has {len(items)} coordinates, the ring {ring.nvars} variables")
    return [_number(cmd, ring, v) for v in items]
