"""Small built-in commands of Singular that its manual shows: ``numerator`` and ``denominator`` of a
number, the ``variables`` a polynomial or ideal involves, ``univariate``, ``sortvec``, the Kronecker
product ``tensor`` of two matrices, the exterior power ``wedge`` of a matrix, ``jacob`` of a matrix,
``intvec`` of an intmat, interpolation at the powers of a point (``vandermonde``) and the highest
corner of a zero-dimensional standard basis (``highcorner``), the ideal of the polynomials vanishing
to given orders at given points (``interpolation``), the ``kernel`` of a map, the Groebner basis from
another ring (``frwalk``) and the matrices of the Koszul complex (``koszul``)."""
from __future__ import annotations

from functools import cmp_to_key
from typing import Any
from itertools import combinations, product

from ..dsl.errors import MechRuntimeError
from ..dsl.intmat import IntMat
from ..dsl.registry import command
from ..dsl.values import Ideal, IntVec, List, Map, Matrix, Number, Ring
from ..kernel import Poly
from ..kernel import hilbert as H
from ..kernel import matrix as KM
from ..kernel.coeffs import RationalField
from .matrix_lib import outer


def _rational(n: Number, cmd: str):
    if not isinstance(n.ring.field, RationalField):
        raise MechRuntimeError(f"{cmd} of a number is supported over QQ")
    return n.to_fraction()


@command("numerator")
def numerator(n: Number) -> Number:
    """numerator(n): the numerator of the rational number n.

    Example:
      ring r = 0,x,dp;
      numerator(-3/2);
      → -3
    """
    return Number(n.ring, n.ring.field(_rational(n, "numerator").numerator))


@command("denominator")
def denominator(n: Number) -> Number:
    """denominator(n): the (positive) denominator of the rational number n.

    Example:
      ring r = 0,x,dp;
      denominator(-3/2);
      → 2
    """
    return Number(n.ring, n.ring.field(_rational(n, "denominator").denominator))


@command("variables")
def variables(ctx, f: Poly | Ideal | int) -> Ideal:
    """variables(f): the ideal of the ring variables the polynomial or ideal f involves, in the ring's
    order (the zero ideal for a constant).

    Example:
      ring r = 0,(x,y,z),dp;
      variables(ideal(z2, x+1));
      → _[1]=x
      → _[2]=z
    """
    ring = ctx.basering().poly
    polys = [] if isinstance(f, int) else [f] if isinstance(f, Poly) else list(f.gens)
    used = sorted({i for p in polys for e in p.terms for i, k in enumerate(e) if k})
    return Ideal(ring, [ring.gen(i) for i in used] or [ring.zero()])


@command("univariate")
def univariate(f: Poly) -> int:
    """univariate(f): i if the polynomial f involves only the i-th variable, -1 if it is constant,
    else 0.

    Example:
      ring r = 0,(x,y),dp;
      univariate(y3+1);
      → 2
      univariate(xy);
      → 0
    """
    used = {i for e in f.terms for i, k in enumerate(e) if k}
    if not used:
        return -1
    return used.pop() + 1 if len(used) == 1 else 0


@command("sortvec")
def sortvec(I: Ideal) -> IntVec:
    """sortvec(I): the permutation that sorts the nonzero generators of I increasingly by their leading
    monomials (the positions of the smallest first; a 0 for each zero generator, at the end).

    Example:
      ring r = 0,(x,y,z),dp;
      sortvec(ideal(y, z, x3, x));
      → 2,1,4,3
    """
    order = I.ring.order
    nonzero = [i for i, g in enumerate(I.gens) if not g.is_zero()]
    nonzero.sort(key=cmp_to_key(lambda i, j: order.compare(I.gens[i].lm(), I.gens[j].lm())))
    return IntVec([i + 1 for i in nonzero] + [0] * (len(I.gens) - len(nonzero)))


@command("tensor")
def tensor(A: Matrix, B: Matrix) -> Matrix:
    """tensor(A, B): the tensor (Kronecker) product of the matrices: the blocks A[i,j]*B.

    Example:
      ring r = 0,(x,y),dp;
      matrix A[1][2] = 1,2;
      matrix B[2][1] = x,y;
      print(tensor(A, B));
      → x,2x,
      → y,2y
    """
    return outer(A, B)


@command("wedge")
def wedge(M: Matrix, k: int) -> Matrix:
    """wedge(M, k): the k-th exterior power of the matrix M as Singular gives it: the k x k minors of M,
    rows and columns indexed by the k-subsets in lexicographic order, the minor of rows I and
    columns J taken with the sign (-1)^(sum(I) + sum(J)).

    Example:
      ring r = 0,(x,y,z),dp;
      matrix m[2][3] = x,y,y,z,z,x;
      print(wedge(m, 2));
      → xz-yz,-x2+yz,xy-yz
    """
    if not 0 < k <= min(M.nrows, M.ncols):
        raise MechRuntimeError(f"wedge(M, {k}): k must be between 1 and the size of M")
    rows = list(combinations(range(1, M.nrows + 1), k))
    cols = list(combinations(range(1, M.ncols + 1), k))
    out = []
    for I in rows:
        for J in cols:
            minor = KM.det(KM.Matrix(M.ring, k, k, [M.get(i, j) for i in I for j in J]))
            out.append(-minor if (sum(I) + sum(J)) % 2 else minor)
    return Matrix(M.ring, len(rows), len(cols), out)


@command("jacob")
def jacob_matrix(M: Matrix) -> Matrix:
    # jacob(M) of a matrix (as Singular, of the module of its columns): one row for each column i of M,
    # entry (i, (k-1)*nrows(M)+j) the derivative of M[j,i] by the k-th variable.  No docstring: the
    # command's help is polynomials.jacob's (this module registers first).
    n, m = M.ring.nvars, M.nrows
    return Matrix(M.ring, M.ncols, m * n, [M.get(j, i).diff(k) for i in range(1, M.ncols + 1)
                                           for k in range(n) for j in range(1, m + 1)])


@command("intvec")
def intvec_of_intmat(m: IntMat) -> IntVec:
    # intvec(m) of an intmat: its entries row by row (the help is conversions.intvec's)
    return IntVec(m.values)


@command("vandermonde")
def vandermonde(p: Ideal, v: Ideal, d: int) -> Poly:
    """vandermonde(p, v, d): the polynomial f with each exponent at most d (in n variables) whose value
    at the point p^i = (p_1^i, ..., p_n^i) is v[i+1] for i = 0, ..., (d+1)^n - 1 (the entries of p
    and v numbers; the monomials' values at p must be distinct).

    Example:
      ring r = 0,(x,y),dp;
      vandermonde(ideal(2,3), ideal(1,2,3,4), 1);
      → 1/30xy+5/2x-5/6y-7/10
    """
    ring = p.ring
    n = ring.nvars
    if len(p.gens) != n or not all(g.is_constant() for g in list(p.gens) + list(v.gens)):
        raise MechRuntimeError("vandermonde(p, v, d): p must hold a number for each variable, v numbers")
    field = ring.field
    point = [g.coeff_of(ring.zero_exp) if not g.is_zero() else field(0) for g in p.gens]
    mons = list(product(range(d + 1), repeat=n))
    values = [g.coeff_of(ring.zero_exp) if not g.is_zero() else field(0) for g in v.gens]
    if len(values) < len(mons):
        raise MechRuntimeError(f"vandermonde: {len(mons)} values needed, {len(values)} given")
    nodes = []
    for e in mons:
        w = field(1)
        for c, k in zip(point, e):
            w = w * c ** k
        nodes.append(w)
    if len(set(nodes)) != len(nodes):
        raise MechRuntimeError("vandermonde: the monomials take equal values at the point")
    # solve sum_m c_m * nodes[m]^i = values[i], i = 0..N-1, by Gaussian elimination
    N = len(mons)
    rows, power = [], [field(1)] * N
    for i in range(N):
        rows.append(list(power) + [values[i]])
        power = [a * b for a, b in zip(power, nodes)]
    for c in range(N):
        k = next(r for r in range(c, N) if rows[r][c] != 0)
        rows[c], rows[k] = rows[k], rows[c]
        inv = field(1) / rows[c][c]
        rows[c] = [x * inv for x in rows[c]]
        for r in range(N):
            if r != c and rows[r][c] != 0:
                f = rows[r][c]
                rows[r] = [a - f * b for a, b in zip(rows[r], rows[c])]
    return Poly(ring, {e: rows[m][N] for m, e in enumerate(mons) if rows[m][N] != 0})


@command("highcorner")
def highcorner(I: Ideal) -> Poly:
    """highcorner(I): for a standard basis I of a zero-dimensional ideal, the highest corner: the
    smallest monomial (in the ring's ordering) outside the leading ideal; 0 if there is none (the
    unit ideal, or R/I infinite-dimensional).

    Example:
      ring r = 0,(x,y),ds;
      highcorner(std(ideal(x3, x2y, y3)));
      → xy2
    """
    ring = I.ring
    lms = [g.lm() for g in I.nonzero()]
    if not lms or H.vdim(lms, ring.nvars) <= 0:
        return ring.zero()
    mons = H.kbase(lms, ring.nvars)
    return ring.monomial(min(mons, key=ring.order.key))


@command("interpolation")
def interpolation(points: List, v: IntVec) -> Ideal:
    """interpolation(l, v): for a list l of maximal ideals (points, e.g. ideal(x-1, y+2)) and the
    intvec v of orders, the reduced standard basis of the polynomials vanishing to order v[i] at the
    i-th point: the intersection of the powers l[i]^v[i].

    Example:
      ring r = 0,(x,y),dp;
      interpolation(list(ideal(x,y), ideal(x-1,y)), intvec(2,1));
      → _[1]=y2
      → _[2]=xy
      → _[3]=x3-x2
    """
    from .ideals import intersect
    ideals = [p for p in points.items if isinstance(p, Ideal)]
    if len(ideals) != len(points.items) or len(v.values) < len(ideals) or not ideals:
        raise MechRuntimeError("interpolation(l, v): l must be a list of ideals of points, v an order for each")
    ring = ideals[0].ring
    powers = []
    for P, k in zip(ideals, v.values):
        if k < 1:
            raise MechRuntimeError("interpolation: the orders must be positive")
        gens = [ring.one()]
        for _ in range(k):
            gens = [g * h for g in gens for h in P.nonzero()]
        powers.append(Ideal(ring, gens))
    return intersect(*powers)


@command("kernel", raw=True)
def kernel(ctx, ring_node: Any, map_node: Any) -> Ideal:
    """kernel(S, phi): the kernel of the map phi from the basering to the ring S (preimage of 0).

    Example:
      ring r1 = 0,(a,b,c),dp;
      ring r = 0,(x,y),dp;
      map f = r1, x, y, x+y;
      setring r1;
      kernel(r, f);
      → _[1]=a+b-c
    """
    from .idealops import preimage_polys
    from .rings import _in_ring
    source = ctx.basering().poly
    target, phi = _in_ring(ctx, ring_node, map_node, "kernel")
    if not isinstance(target, Ring) or not isinstance(phi, Map):
        raise MechRuntimeError("kernel(S, phi): S a ring, phi a map from the basering into it")
    images = (list(phi.images) + [target.poly.zero()] * source.nvars)[:source.nvars]
    out = preimage_polys(source, target.poly, images, [])
    return Ideal(source, out or [source.zero()])


@command("frwalk", raw=True)
def frwalk(ctx, ring_node: Any, ideal_node: Any) -> Ideal:
    """frwalk(r, I): the reduced Groebner basis, for the basering's ordering, of the ideal I of the ring
    r (its variables mapped by name), as Singular's Groebner walk gives it.

    Example:
      ring r = 0,(x,y),dp;
      ideal i = std(ideal(x2+y, xy-1));
      ring s = 0,(x,y),lp;
      frwalk(r, i);
      → _[1]=y3+1
      → _[2]=x+y2
    """
    from ..kernel.maps import imap as imap_polys
    from .rings import _in_ring
    from .standard import standard_basis
    source, I = _in_ring(ctx, ring_node, ideal_node, "frwalk")
    if not isinstance(I, Ideal):
        raise MechRuntimeError("frwalk(r, I): I must be an ideal of the ring r")
    target = ctx.basering().poly
    mapped = Ideal(target, imap_polys(I.nonzero(), source.poly, target) or [target.zero()])
    return Ideal(target, standard_basis(mapped), is_std=True)


@command("koszul")
def koszul(ctx, d: int, f: int | Ideal) -> Matrix:
    """koszul(d, n) or koszul(d, I): the d-th matrix of the Koszul complex of the first n variables (of
    the generators of I): rows the (d-1)-subsets, columns the d-subsets in lexicographic order, the
    entry for T and T without its j-th element (-1)^(j+1) times the j-th element's generator (the 1 x 1
    zero matrix for d outside 1..n).

    Example:
      ring r = 0,(x,y,z),dp;
      print(koszul(2, 3));
      → -y,-z,0,
      → x, 0, -z,
      → 0, x, y
    """
    ring = ctx.basering().poly
    gens = list(ring.gens()[:f]) if isinstance(f, int) else list(f.gens)
    n = len(gens)
    if not 1 <= d <= n:  # as Singular: the 1 x 1 zero matrix
        return Matrix(ring, 1, 1, [ring.zero()])
    rows = list(combinations(range(n), d - 1))
    cols = list(combinations(range(n), d))
    where = {S: i for i, S in enumerate(rows)}
    entries = [ring.zero()] * (len(rows) * len(cols))
    for c, T in enumerate(cols):
        for j, t in enumerate(T):
            S = T[:j] + T[j + 1:]
            entries[where[S] * len(cols) + c] = gens[t] if j % 2 == 0 else -gens[t]
    return Matrix(ring, len(rows), len(cols), entries)
