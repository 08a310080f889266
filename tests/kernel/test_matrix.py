"""Matrices, determinants, minors and Jacobians against Singular 4.3.1 (hard-coded truths from
real runs, live differential runs when Singular is installed)."""
import random
from fractions import Fraction

import pytest
from tests.util import SINGULAR, ideal_blocks, parse_poly, run_singular

from mech.kernel import GF, QQ, Block, MonomialOrder, PolyRing
from mech.kernel.errors import DivisionError, DomainError
from mech.kernel.groebner import groebner
from mech.kernel.matrix import Matrix, det, exact_divide, gradient, jacobian, minors

singular = pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")


def ring(names, blocks=None, field=QQ):
    names = names.split(",") if "," in names else list(names)
    return PolyRing(field, names, MonomialOrder(blocks or [Block("dp", len(names))]))


# the paper's Jacobians (reference/paper/*.sing) and Singular's minor(D, k) of them
SLIDER2_MINORS = """-4*c1*c2*l1, -4*c1*s2*l1, 4*c1*c2*l2, 4*s1*c2*l2"""
SLIDER3_MINORS = """-8*c1*c2*c3*l1, -8*c1*s2*c3*l1, 8*c1*c2*c3*l2, 8*s1*c2*c3*l2, -8*c1*c2*s3*l1,
-8*c1*s2*s3*l1, 8*c1*c2*s3*l2, 8*s1*c2*s3*l2, -8*c1*c2*c3*l3, -8*s1*c2*c3*l3, -8*c1*s2*c3*l3,
-8*s1*s2*c3*l3"""
FOURBAR_MINORS = """8*s1*c2*c3*l1*l2-8*c1*s2*c3*l1*l2, 8*s1*c2*s3*l1*l2-8*c1*s2*s3*l1*l2,
-8*s1*c2*c3*l1*l3+8*c1*c2*s3*l1*l3, -8*s1*s2*c3*l1*l3+8*c1*s2*s3*l1*l3,
8*c1*s2*c3*l2*l3-8*c1*c2*s3*l2*l3, 8*s1*s2*c3*l2*l3-8*s1*c2*s3*l2*l3"""


def paper_jacobian(name):
    if name == "slider2":
        R = ring("c1,s1,c2,s2,l1,l2", [Block("dp", 4), Block("dp", 2)])
        c1, s1, c2, s2, l1, l2 = R.gens()
        J = [l1 * s1 + l2 * s2, c1**2 + s1**2 - 1, c2**2 + s2**2 - 1]
        angles = 4
    else:
        R = ring("c1,s1,c2,s2,c3,s3,l1,l2,l3", [Block("dp", 6), Block("dp", 3)])
        c1, s1, c2, s2, c3, s3, l1, l2, l3 = R.gens()
        J = [l1 * s1 + l2 * s2 + l3 * s3, c1**2 + s1**2 - 1, c2**2 + s2**2 - 1, c3**2 + s3**2 - 1]
        if name == "fourbar":
            J = [l1 * c1 + l2 * c2 + l3 * c3 - 1] + J[:1] + J[1:]
        angles = 6
    D = Matrix(R, len(J), angles, [f.diff(j) for f in J for j in range(angles)])
    return R, D


@pytest.mark.parametrize("name,k,truth", [("slider2", 3, SLIDER2_MINORS), ("slider3", 4, SLIDER3_MINORS),
                                          ("fourbar", 5, FOURBAR_MINORS)])
def test_paper_fitting_ideals(name, k, truth):
    R, D = paper_jacobian(name)
    expected = [parse_poly(R, t.strip()) for t in truth.split(",")]
    F = minors(D, k)
    assert F == expected  # Singular's order, signs, zero minors dropped
    assert groebner(F) == groebner(expected)


def test_jacobian_is_singular_jacob():
    R = ring("xyz")
    x, y, z = R.gens()
    J = jacobian([x**2 * y, y + z**3])
    assert (J.nrows, J.ncols) == (2, 3)
    assert J.rows == [[2 * x * y, x**2, R.zero()], [R.zero(), R.one(), 3 * z**2]]
    assert gradient(x**2 * y + z) == [2 * x * y, x**2, R.one()]


def test_arithmetic_and_access():
    R = ring("xyz")
    x, y, z = R.gens()
    A = Matrix(R, 2, 2, [x, y, z, 1])
    B = Matrix(R, 2, 2, [1, 2, 3, 4])
    assert (A * B).entries() == [x + 3 * y, 2 * x + 4 * y, z + 3, 2 * z + 4]
    assert (A + B).entries() == [x + 1, y + 2, z + 3, R.const(5)]
    assert (A - A).is_zero() and (-A + A).is_zero()
    assert A.transpose().entries() == [x, z, y, R.one()]
    assert (2 * A).entries() == [2 * x, 2 * y, 2 * z, R.const(2)]
    assert (A * x).entries() == [x**2, x * y, x * z, x]
    assert A**2 == A * A and A**0 == Matrix.identity(R, 2)
    assert A.get(2, 1) == z and A[1, 0] == z
    A.set(2, 1, y)
    assert A.get(2, 1) == y
    assert Matrix(R, 2, 3).entries() == [R.zero()] * 6
    with pytest.raises(IndexError):
        A.get(3, 1)
    with pytest.raises(DomainError):
        A * Matrix(R, 3, 1)
    with pytest.raises(DomainError):
        A + Matrix(R, 2, 3)


def test_det_small_and_symbolic():
    R = ring("xyz")
    x, y, z = R.gens()
    assert det(Matrix(R, 2, 2, [x, y, z, 1])) == x - y * z
    C = Matrix(R, 3, 3, [x, y, z, 1, 2, 3, x**2, y**2, z**2])
    # Singular: det(C) = 3x2y-3xy2-2x2z+y2z+2xz2-yz2
    assert C.det() == 3 * x**2 * y - 3 * x * y**2 - 2 * x**2 * z + y**2 * z + 2 * x * z**2 - y * z**2
    assert det(Matrix(R, 0, 0)) == R.one()
    with pytest.raises(DomainError):
        det(Matrix(R, 2, 3))


def test_vandermonde_and_bareiss_agree_with_laplace():
    n = 6
    R = ring([f"x{i}" for i in range(n)])
    X = R.gens()
    V = Matrix(R, n, n, [X[i] ** j for i in range(n) for j in range(n)])
    expected = R.one()
    for i in range(n):
        for j in range(i + 1, n):
            expected = expected * (X[j] - X[i])
    assert det(V) == expected  # Bareiss (n > 4) with exact division
    # a zero pivot forces a row swap
    W = Matrix(R, 5, 5, [0 if i == j == 0 else X[(i + 2 * j) % n] + i - j for i in range(5) for j in range(5)])
    from mech.kernel.matrix import _laplace
    assert det(W) == _laplace(W.rows, list(range(5)), list(range(5)), {})


def test_exact_divide():
    R = ring("xy")
    x, y = R.gens()
    a, b = x**3 - y**3 + x * y + 1, x**2 + x * y - 2
    assert exact_divide(a * b, b) == a
    assert exact_divide(6 * x**2 * y, 3 * x) == 2 * x * y
    with pytest.raises(DivisionError):
        exact_divide(a * b + 1, b)
    with pytest.raises(ZeroDivisionError):
        exact_divide(a, R.zero())


def test_minor_conventions():
    """Facts from Singular 4.3.1 runs."""
    R = ring("xyz")
    x, y, z = R.gens()
    M = Matrix(R, 3, 4, R.gens() * 4)
    assert minors(M, 0) == [R.one()]
    assert minors(M, 4) == [R.zero()]
    # k = 1: rows and columns from the last, zeros moved to the end
    A = Matrix(R, 2, 3, [x, 0, y, 0, 0, z])
    assert minors(A, 1) == [z, y, x] + [R.zero()] * 3
    # k = 2 keeps zeros (at the end); pivoting may flip signs: minor([0,x;y,0], 2) = xy
    assert minors(Matrix(R, 2, 2, [0, x, y, 0]), 2) == [x * y]
    N = Matrix(R, 3, 3, [x, 0, 0, 0, y, 0, 0, 0, z])
    assert minors(N, 2) == [y * z, x * z, x * y] + [R.zero()] * 6
    # k = 2 on [x,y,z; 1,2,3; ...]: Singular prints z-w-like rows in pivot order
    B = Matrix(R, 2, 3, [x, y, z, 2, 3, 5])
    assert minors(B, 2) == [5 * y - 3 * z, 5 * x - 2 * z, -3 * x + 2 * y]
    # k >= 3 in three variables over QQ: colex order, zero minors dropped
    C = Matrix(R, 4, 4, [x, 0, 0, 0, 0, y, 0, 0, 0, 0, z, 0, 0, 0, 0, 0])
    assert minors(C, 3) == [x * y * z]
    assert minors(Matrix(R, 3, 3), 3) == [R.zero()]


GENERIC_3x4 = {  # Singular's minor(M,2) of the generic 3x4 matrix: (rows, cols, sign), 1-based
    2: "23|34+ 23|24+ 23|14+ 13|34+ 13|24+ 13|14+ 23|23- 23|13- 13|23- 13|13- 23|12+ 13|12+ "
       "12|34+ 12|24+ 12|14+ 12|23- 12|13- 12|12+",
    3: "123|123+ 123|124+ 123|134+ 123|234+",
}


@pytest.mark.parametrize("k", [2, 3])
def test_generic_matrix_minor_order(k):
    R = ring([f"a{i}" for i in range(12)])
    M = Matrix(R, 3, 4, R.gens())
    expected = []
    for item in GENERIC_3x4[k].split():
        rows, cols = item[:-1].split("|")
        sub = M.submatrix([int(r) - 1 for r in rows], [int(c) - 1 for c in cols]).det()
        expected.append(sub if item[-1] == "+" else -sub)
    assert minors(M, k) == expected


def _random_matrix(R, r, c, rng):
    x, y, z = (R.gens() * 3)[:3]
    pool = [x, y, z, x + 1, y * z, x - z, 2 * x * y, x**2 + y + z]

    def entry():
        t = rng.random()
        if t < 0.3:
            return R.zero()
        if t < 0.5:
            return R.const(rng.randint(-3, 3))
        return rng.choice(pool)
    return Matrix(R, r, c, [entry() for _ in range(r * c)])


def _singular_minors(R, M, k):
    char = R.field.characteristic
    script = (f"ring R={char},({','.join(R.names)}),dp; short=0; matrix M[{M.nrows}][{M.ncols}]="
              f"{','.join(e.to_str() for e in M.entries())}; minor(M,{k});")
    return [parse_poly(R, t) for t in ideal_blocks(run_singular(script))[0]]


@singular
@pytest.mark.parametrize("char,names", [(0, "xyz"), (0, "xy"), (32003, "xyz"), (7, "xyzu"), (5, "x")])
def test_minors_match_singular_exactly(char, names):
    """Order, signs and zeros of minor(M,k) for random sparse matrices, each algorithm
    Singular's heuristic picks (integer coefficients: see minors' docstring)."""
    R = ring(names, field=QQ if char == 0 else GF(char))
    rng = random.Random(char * 100 + len(names))
    for _ in range(12):
        k = rng.randint(1, 4)
        M = _random_matrix(R, rng.randint(k, 5), rng.randint(k, 5), rng)
        assert minors(M, k) == _singular_minors(R, M, k), (M, k)


@singular
@pytest.mark.parametrize("name,k", [("slider2", 3), ("slider3", 4), ("fourbar", 5)])
def test_paper_minors_live(name, k):
    R, D = paper_jacobian(name)
    order = "(dp(4),dp(2))" if name == "slider2" else "(dp(6),dp(3))"
    script = (f"ring R=0,({','.join(R.names)}),{order}; short=0; matrix D[{D.nrows}][{D.ncols}]="
              f"{','.join(e.to_str() for e in D.entries())}; minor(D,{k});")
    expected = [parse_poly(R, t) for t in ideal_blocks(run_singular(script))[0]]
    assert minors(D, k) == expected


@singular
def test_det_matches_singular():
    R = ring("xyz")
    rng = random.Random(5)
    for n in (3, 5, 6):
        M = _random_matrix(R, n, n, rng)
        script = (f"ring R=0,(x,y,z),dp; short=0; matrix M[{n}][{n}]="
                  f"{','.join(e.to_str() for e in M.entries())}; ideal d=det(M); d;")
        assert det(M) == parse_poly(R, ideal_blocks(run_singular(script))[0][0])


def test_fractions_in_entries():
    R = ring("xy")
    x, y = R.gens()
    M = Matrix(R, 2, 2, [Fraction(1, 2) * x, y, 1, Fraction(2, 3)])
    assert det(M) == Fraction(1, 3) * x - y
