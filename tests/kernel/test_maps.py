"""Ring maps (map, imap, fetch, subst) against Singular 4.3.1."""
import random
from fractions import Fraction

import pytest
from tests.util import SINGULAR, ideal_blocks, parse_poly, run_singular

from mech.kernel import GF, QQ, Block, MonomialOrder, PolyRing
from mech.kernel.errors import DomainError
from mech.kernel.maps import fetch, imap, map_polys, subst
from mech.kernel.ratfunc import RationalFunctionField

singular = pytest.mark.skipif(SINGULAR is None, reason="Singular is not installed")


def ring(names, field=QQ, kind="dp"):
    names = names.split(",") if "," in names else list(names)
    return PolyRing(field, names, MonomialOrder([Block(kind, len(names))]))


def source():
    r = ring("xyz")
    x, y, z = r.gens()
    return r, x**2 + Fraction(1, 3) * y - z + Fraction(2, 5)


def test_imap_and_fetch_between_characteristics():
    r, f = source()
    x, y, z = r.gens()
    s = ring("yxw", GF(7))
    Y, X, W = s.gens()
    # Singular: imap(r,f) = x2-2y-1, imap(r, ideal(x-y, z2)) = -y+x, 0; fetch(r,f) = y2-2x-w-1
    assert imap([f], r, s) == [X**2 - 2 * Y - 1]
    assert imap([x - y, z**2], r, s) == [X - Y, s.zero()]
    assert fetch([f], r, s) == [Y**2 - 2 * X - W - 1]
    t = ring("ab")
    a, b = t.gens()
    assert fetch([f], r, t) == [a**2 + Fraction(1, 3) * b + Fraction(2, 5)]
    u = ring("abcd")
    a, b, c, d = u.gens()
    assert fetch([f], r, u) == [a**2 + Fraction(1, 3) * b - c + Fraction(2, 5)]


def test_prime_field_to_rationals_uses_symmetric_representatives():
    p5 = ring("xyz", GF(5))
    x, y, z = p5.gens()
    g = 3 * x + 4 * y + 2 * z
    q = ring("xyz")
    X, Y, Z = q.gens()
    assert fetch([g], p5, q) == imap([g], p5, q) == [-2 * X - Y + 2 * Z]
    p7 = ring("xyz", GF(7))
    X, Y, Z = p7.gens()
    assert fetch([g], p5, p7) == [-2 * X - Y + 2 * Z]


def test_denominator_divisible_by_p():
    r = ring("xy")
    x, y = r.gens()
    with pytest.raises(DomainError, match="divisible by 7"):
        imap([x / 7 + y], r, ring("xy", GF(7)))


def test_map_images():
    r, f = source()
    q = ring("xyz")
    x, y, z = q.gens()
    # Singular: map phi = r, x+y, z; phi(f) = x2+2xy+y2+1/3z+2/5 (missing images are 0)
    assert map_polys([f], [x + y, z], q) == [x**2 + 2 * x * y + y**2 + Fraction(1, 3) * z + Fraction(2, 5)]
    # map m = r, x+1, y, z2 in the same ring
    assert map_polys([f], [x + 1, y, z**2], r) == [x**2 - z**2 + 2 * x + Fraction(1, 3) * y + Fraction(7, 5)]
    s = ring("yxw", GF(7))
    Y, X, W = s.gens()
    assert map_polys([f], [X, Y, W], s) == [X**2 - 2 * Y - W - 1]
    with pytest.raises(DomainError, match="4 images"):
        map_polys([f], [x, y, z, x], q)
    with pytest.raises(DomainError, match="target ring"):
        map_polys([f], [x, y, s.gen(0)], q)
    with pytest.raises(DomainError, match="source ring"):
        map_polys([s.gen(0)], [x, y, z], q, source=r)


def test_subst():
    r, f = source()
    x, y, z = r.gens()
    assert subst(f, 0, y + 1) == (y + 1) ** 2 + Fraction(1, 3) * y - z + Fraction(2, 5)
    assert subst(f, 2, 3) == x**2 + Fraction(1, 3) * y - 3 + Fraction(2, 5)
    assert subst(x * y, 1, x) == x**2
    with pytest.raises(DomainError):
        subst(f, 3, x)


# the paper's shift maps (reference/paper/*.sing) and Singular's images
def test_paper_shift_maps():
    r1 = ring("c1,s1,c2,s2")
    c1, s1, c2, s2 = r1.gens()
    J = [s1 + s2, c1**2 + s1**2 - 1, c2**2 + s2**2 - 1]
    Jq = map_polys(J, [c1, s1 - 1, c2, s2 + 1], r1)  # map toq2 = r1, c1, s1-1, c2, s2+1
    assert Jq == [s1 + s2, c1**2 + s1**2 - 2 * s1, c2**2 + s2**2 + 2 * s2]
    rl = ring("c1,s1,c2,s2", kind="ds")
    C1, S1, C2, S2 = rl.gens()
    assert imap(Jq, r1, rl) == [S1 + S2, -2 * S1 + C1**2 + S1**2, 2 * S2 + C2**2 + S2**2]

    r3 = ring("c1,s1,c2,s2,c3,s3")
    c1, s1, c2, s2, c3, s3 = r3.gens()
    J3 = [2 * s1 + s2 + s3, c1**2 + s1**2 - 1, c2**2 + s2**2 - 1, c3**2 + s3**2 - 1]
    assert map_polys(J3, [c1, s1 - 1, c2, s2 + 1, c3, s3 + 1], r3) == [
        2 * s1 + s2 + s3, c1**2 + s1**2 - 2 * s1, c2**2 + s2**2 + 2 * s2, c3**2 + s3**2 + 2 * s3]
    J4 = [c1 + c2 + c3 - 1, s1 + s2 + s3, c1**2 + s1**2 - 1, c2**2 + s2**2 - 1, c3**2 + s3**2 - 1]
    assert map_polys(J4, [c1 - 1, s1, c2 + 1, s2, c3 + 1, s3], r3) == [  # map toq1
        c1 + c2 + c3, s1 + s2 + s3, c1**2 + s1**2 - 2 * c1, c2**2 + s2**2 + 2 * c2, c3**2 + s3**2 + 2 * c3]


def test_parameters():
    F = RationalFunctionField(0, "ab")
    pa = ring("xy", F)
    a, b = F.gens()
    x, y = pa.gens()
    f = a * x + b**2
    G = RationalFunctionField(0, "ba")
    pb = ring("y", G)
    gb, ga = G.gens()
    (Y,) = pb.gens()
    assert fetch([f], pa, pb) == [gb * Y + ga**2]      # Singular: (b)*y+(a2)
    assert imap([f], pa, pb) == [pb.const(gb**2)]      # x is missing: (b2)
    pc = ring("y", RationalFunctionField(0, "c"))
    assert fetch([f], pa, pc) == [pc.field.gen(0) * pc.gen(0)]  # (c)*y
    pu = ring("xb", RationalFunctionField(0, "a"))
    X, B = pu.gens()
    assert imap([f], pa, pu) == [B**2 + pu.field.gen(0) * X]   # b2+(a)*x
    with pytest.raises(DomainError, match="coefficient field"):
        map_polys([f], [Y], pb)
    with pytest.raises(DomainError, match="non-constant"):
        imap([x / a], pa, ring("xa"))
    # rationals into a parameter field, and Z/7(a)
    q = ring("xy")
    qx, qy = q.gens()
    assert map_polys([qx**2 + qy / 2], [a * x, y], pa) == [a**2 * x**2 + y / 2]
    F7 = RationalFunctionField(7, "a")
    p7 = ring("xy", F7)
    assert map_polys([qx**2 + qy / 2], [F7.gen(0) * p7.gen(0), p7.gen(1)], p7) == [
        F7.gen(0) ** 2 * p7.gen(0) ** 2 - 3 * p7.gen(1)]


def _random_poly(R, rng, terms=4, deg=3, fractions=True):
    f = R.zero()
    for _ in range(terms):
        e = [rng.randint(0, deg) for _ in range(R.nvars)]
        den = rng.choice([1, 1, 2, 3]) if fractions else 1
        f = f + R.monomial(e, Fraction(rng.randint(-9, 9), den))
    return f


@singular
@pytest.mark.parametrize("char", [0, 7, 32003])
def test_random_maps_match_singular(char):
    """map, imap and fetch from QQ[x,y,z,w] to K[w,y,u,z] (QQ: integer coefficients, as the
    test parser reads no fractions)."""
    rng = random.Random(char)
    r = ring("xyzw")
    s = ring("wyuz", QQ if char == 0 else GF(char))
    polys = [_random_poly(r, rng, fractions=char != 0) for _ in range(3)]
    images = [_random_poly(s, rng, 2, 1, fractions=False) for _ in range(4)]
    src = ",".join(f.to_str() for f in polys)
    img = ",".join(g.to_str() for g in images)
    out = run_singular(f"ring r=0,(x,y,z,w),dp; ideal I={src}; ring s={char},(w,y,u,z),dp; short=0;"
                       f"map phi=r,{img}; phi(I); imap(r,I); fetch(r,I);")
    mapped, imapped, fetched = ([parse_poly(s, t) for t in block] for block in ideal_blocks(out))
    assert map_polys(polys, images, s) == mapped
    assert imap(polys, r, s) == imapped
    assert fetch(polys, r, s) == fetched
