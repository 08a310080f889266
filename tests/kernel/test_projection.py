"""Minimal primes by a certified birational projection (mech.kernel.projection), checked against
primdecGTZ (mech's and Singular's) and, for the five-bar, against an independent argument."""
from __future__ import annotations

import random

import pytest

from mech.dsl.printing import poly_str
from mech.kernel import QQ, Block, MonomialOrder, PolyRing
from mech.kernel.ideals import dimension, ideals_equal, intersect, is_subset
from mech.kernel.primdec import min_ass_gtz
from mech.kernel.projection import certify, eliminant, project_primes, variety_degree
from mech.stdlib.mechanism import parse_mechanism
from tests.util import SINGULAR, ideal_blocks, parse_poly, run_singular

FIVEBAR = "ground O A 2; bar O B 1; bar B C 1; bar C D 1; bar D A 1"
NUMERIC = {"fourbar": "ground O A 1; bar O B 1; bar B C 1; bar C A 1",
           "kite": "ground O A 1; bar O B 1; bar B C 2; bar C A 2",
           "slider": "fix O; bar O A 1; bar A B 1; slider B",
           "slider3": "fix O; bar O A 2; bar A B 1; bar B C 1; slider C"}


def same_sets(a, b, ring):
    return len(a) == len(b) and all(any(ideals_equal(p, q, ring) for q in b) for p in a)


def singular_min_ass(ring, ideal, params=()):
    """Singular's minAssGTZ (over QQ(params) when given) as lists of polynomial strings."""
    names = [n for n in ring.names if n not in params]
    field = f"(0,{','.join(params)})" if params else "0"
    out = run_singular(f'LIB "primdec.lib";\nring r = {field}, ({",".join(names)}), dp;\n'
                       f'ideal J = {", ".join(poly_str(g) for g in ideal)};\nlist L = minAssGTZ(J);\n'
                       'int i; for (i = 1; i <= size(L); i++) { print("---"); L[i]; }')
    return ideal_blocks(out)


def test_fivebar_is_prime():
    """J of the five-bar (8 variables, dim 2): the eliminant for y_j = c_j + s_j is irreducible of
    degree 14 = deg V(J), so J is prime (primdecGTZ does not finish here)."""
    R, J = parse_mechanism(FIVEBAR).constraints()
    assert variety_degree(J, R) == 14
    found = project_primes(J, R)
    assert [f.to_str() for f in found.forms] == ["c1+s1", "c2+s2", "c3+s3"]
    assert [g.total_degree() for g in found.image] == [14] and found.degree == 14
    assert len(found.primes) == 1 and ideals_equal(found.primes[0], J, R)


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular not installed")
def test_fivebar_certificate_against_singular():
    """Singular's mult(std(J)), eliminant and factorization: the same certificate."""
    R, J = parse_mechanism(FIVEBAR).constraints()
    found = project_primes(J, R)
    names = ",".join(R.names)
    out = run_singular(
        f"ring r0 = 0, ({names}), dp;\nideal J = {', '.join(poly_str(g) for g in J)};\n"
        f"mult(std(J));\nring r = 0, ({names},y1,y2,y3), (dp(8),dp(3));\nideal J = imap(r0, J);\n"
        "ideal E = eliminate(J + ideal(y1-c1-s1, y2-c2-s2, y3-c3-s3), c1*s1*c2*s2*c3*s3*c4*s4);\n"
        "size(E); list F = factorize(E[1], 2); size(F[1]); F[2]; E[1];")
    lines = out.split()
    assert lines[:4] == ["14", "1", "1", "1"]
    g = parse_poly(found.image_ring, lines[4])
    assert (g * found.image[0].lc() - found.image[0] * g.lc()).is_zero()


def test_fivebar_prime_independently():
    """In complex coordinates z = c + i*s the five-bar is {sum z_i = 2, sum 1/z_i = 2} in the torus;
    with z4 = 2 - z1 - z2 - z3 one polynomial, irreducible over Q(i): V(J) is irreducible."""
    import sympy
    z1, z2, z3 = sympy.symbols("z1 z2 z3")
    F = sympy.numer(sympy.together(1 / z1 + 1 / z2 + 1 / z3 + 1 / (2 - z1 - z2 - z3) - 2))
    _, factors = sympy.factor_list(sympy.expand(F), extension=sympy.I)
    assert len(factors) == 1 and factors[0][1] == 1
    assert all(sympy.rem(factors[0][0], z, z) != 0 for z in (z1, z2, z3))  # not a coordinate


@pytest.mark.parametrize("name", sorted(NUMERIC))
def test_mechanisms_against_gtz(name):
    R, J = parse_mechanism(NUMERIC[name]).constraints()
    found = project_primes(J, R)
    assert found is not None and sum(g.total_degree() for g in found.image) == found.degree
    assert same_sets(found.primes, min_ass_gtz(J, R), R)


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular not installed")
@pytest.mark.parametrize("name", sorted(NUMERIC))
def test_mechanisms_against_singular(name):
    R, J = parse_mechanism(NUMERIC[name]).constraints()
    got = [[parse_poly(R, t) for t in b] for b in singular_min_ass(R, J)]
    assert same_sets(project_primes(J, R).primes, got, R)


def test_rejected_projection():
    """The four-bar (1,1,1) with y = (c1+s1, c2+s2): two of its three circles project 2:1 onto
    lines, the factor degrees add up to 3 < 6: not a certificate."""
    R, J = parse_mechanism(NUMERIC["fourbar"]).constraints()
    c1, s1, c2, s2 = R.gens()[:4]
    _, elim = eliminant(J, R, [c1 + s1, c2 + s2])
    assert len(elim) == 1 and elim[0].total_degree() == 3
    assert certify(J, R, [c1 + s1, c2 + s2]) is None


def random_prime(R, rnd, d):
    """A prime of dimension d: linear equations for all but d + 1 variables and one irreducible
    hypersurface (quadric or cubic with a random linear term) in the rest."""
    xs = R.gens()
    n = R.nvars
    r = lambda: R.const(rnd.randint(-3, 3))  # noqa: E731
    gens = [xs[i] - sum((r() * xs[j] for j in range(n - d - 1, n)), r()) for i in range(n - d - 1)]
    tail = xs[n - d - 1:]
    f = tail[0] ** rnd.choice([2, 3]) + sum((r() * x for x in tail[1:]), R.zero()) + \
        R.const(rnd.randint(1, 3)) * tail[-1] ** 2 + r()
    return gens + [f]


@pytest.mark.parametrize("seed", range(6))
def test_random_intersections_of_primes(seed):
    rnd = random.Random(seed)
    R = PolyRing(QQ, ["x", "y", "z", "w"], MonomialOrder([Block("dp", 4)]))
    d = rnd.choice([1, 2])
    primes = [random_prime(R, rnd, d) for _ in range(rnd.randint(1, 3))]
    J = intersect(*primes, ring=R)
    want = min_ass_gtz(J, R)  # distinct primes only (a random prime may repeat)
    found = project_primes(J, R, attempts=5)
    assert found is not None and same_sets(found.primes, want, R)


# ---------------------------------------------------------------- symbolic lengths: over QQ(l)
SLIDER2 = "fix O; bar O A l1; bar A B l2; slider B"
SLIDER3 = "fix O; bar O A l1; bar A B l2; bar B C l3; slider C"
FOURBAR = "ground O A 1; bar O B l1; bar B C l2; bar C A l3"


@pytest.mark.parametrize("text", [SLIDER2, SLIDER3, FOURBAR], ids=["slider2", "slider3", "fourbar"])
def test_symbolic_lengths_one_generic_mode(text):
    m = parse_mechanism(text)
    R, J = m.constraints()
    k = len(m.symbols())
    found = project_primes(J, R, k)
    assert found is not None and len(found.primes) == 1
    assert all(any(sum(e[k:]) for e in g.terms) for g in found.image)  # involves the y's
    P = found.primes[0]
    assert is_subset(J, P, R) and dimension(P, R) == dimension(J, R)  # a component of J
    # the specialisation at generic lengths is prime too (a consistency check)
    n = R.nvars - k
    values = [2, 3, 4][:k]
    S = PolyRing(QQ, R.names[:n], MonomialOrder([Block("dp", n)]))
    images = S.gens() + [S.const(v) for v in values]
    Js = [g.compose(images, S) for g in J]
    assert len(min_ass_gtz(Js, S)) == 1


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular not installed")
@pytest.mark.parametrize("text", [SLIDER2, SLIDER3], ids=["slider2", "slider3"])
def test_symbolic_lengths_against_singular(text):
    """Singular's minAssGTZ over QQ(lengths) finds one component too (for the four-bar it does not
    finish within minutes)."""
    m = parse_mechanism(text)
    R, J = m.constraints()
    assert len(singular_min_ass(R, J, m.symbols())) == len(project_primes(J, R, len(m.symbols())).primes)
