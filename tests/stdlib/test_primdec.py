"""primdec.lib in the language: minAssGTZ, minAssChar, primdecGTZ, primdecSY, equidim,
equiRadical.  Lists of components are compared as sets of ideals (each ideal canonicalized by
mech's reduced ``std``), against Singular's output of the paper's scripts (stored below) and
against live Singular on random ideals."""
import random

import pytest
from tests.util import SINGULAR, ideal_blocks, run_singular

from mech import Session
from mech.dsl.errors import MechError

SLIDER2 = """ring r = 0, (c1,s1,c2,s2,l1,l2), (dp(4),dp(2));
ideal J = l1*s1+l2*s2, c1^2+s1^2-1, c2^2+s2^2-1;
matrix D[3][4]; int i; int j; list v = c1,s1,c2,s2;
for (i=1; i<=3; i++) { for (j=1; j<=4; j++) { D[i,j] = diff(J[i], v[j]); } }
ideal F = minor(D,3);
"""
SLIDER3 = """ring r = 0, (c1,s1,c2,s2,c3,s3,l1,l2,l3), (dp(6),dp(3));
ideal J = l1*s1+l2*s2+l3*s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1;
matrix D[4][6]; int i; int j; list v = c1,s1,c2,s2,c3,s3;
for (i=1; i<=4; i++) { for (j=1; j<=6; j++) { D[i,j] = diff(J[i], v[j]); } }
ideal F = minor(D,4);
"""
FOURBAR = """ring r = 0, (c1,s1,c2,s2,c3,s3,l1,l2,l3), (dp(6),dp(3));
ideal J = l1*c1+l2*c2+l3*c3-1, l1*s1+l2*s2+l3*s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1;
matrix D[5][6]; int i; int j; list v = c1,s1,c2,s2,c3,s3;
for (i=1; i<=5; i++) { for (j=1; j<=6; j++) { D[i,j] = diff(J[i], v[j]); } }
ideal F = minor(D,5);
"""
SLIDER2_L1 = """ring r1 = 0, (c1,s1,c2,s2), dp;
ideal J = s1+s2, c1^2+s1^2-1, c2^2+s2^2-1;
"""
FOURBAR_L1 = """ring r1 = 0, (c1,s1,c2,s2,c3,s3), dp;
ideal J = c1+c2+c3-1, s1+s2+s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1;
"""
SLIDER3_L = """ring r1 = 0, (c1,s1,c2,s2,c3,s3), dp;
ideal J = 2*s1+s2+s3, c1^2+s1^2-1, c2^2+s2^2-1, c3^2+s3^2-1;
"""

# Singular 4.3.1's output of the paper's scripts (../shared/reference/paper/*.out), one string
# per component.
SLIDER2_PRIMES = ["l2, l1", "l2, c1", "l1, c2", "s2, c2", "c2, c1", "s1, c1"]
SLIDER3_PRIMES = ["l3, l2, l1", "l3, l2, c1", "l3, l1, c2", "l3, c2, c1", "l2, l1, c3", "l2, c3, c1",
                  "s3, c3", "l1, c3, c2", "c3, c2, c1", "s2, c2", "s1, c1"]
FOURBAR_PRIMES = ["l3, l2", "l3, l1", "-s1*c2+c1*s2, l3", "l2, l1", "-s1*c3+c1*s3, l2",
                  "-s2*c3+c2*s3, l1", "s3, c3", "-s2*c3+c2*s3, -s1*c3+c1*s3, -s1*c2+c1*s2",
                  "s2, c2", "s1, c1"]
SLIDER2_MODES = ["c2^2+s2^2-1, c1-c2, s1+s2", "c2^2+s2^2-1, c1+c2, s1+s2"]
SLIDER2_POINTS = ["s2-1, c2, s1+s2, c1", "s2+1, c2, s1+s2, c1"]
FOURBAR_MODES = ["s3, c3-1, c2^2+s2^2-1, s1+s2+s3, c1+c2+c3-1",
                 "c3^2+s3^2-1, s2+s3, c2+c3, s1+s2+s3, c1+c2+c3-1",
                 "c3^2+s3^2-1, s2, c2-1, s1+s2+s3, c1+c2+c3-1"]
FOURBAR_POINTS = ["s3, c3-1, s2, c2-1, s1+s2+s3, c1+c2+c3-1", "s3, c3-1, s2, c2+1, s1+s2+s3, c1+c2+c3-1",
                  "s3, c3+1, s2, c2-1, s1+s2+s3, c1+c2+c3-1"]
SLIDER3_POINTS = ["s3-1, c3, s2-1, c2, s1+1/2*s2+1/2*s3, c1", "s3+1, c3, s2+1, c2, s1+1/2*s2+1/2*s3, c1"]


def mech(script: str) -> str:
    return Session().execute('LIB "primdec.lib";\n' + script)


def canonical(ring: str, ideals: list[list[str]]) -> list[tuple[str, ...]]:
    """Each ideal (generators as text) as the lines of its reduced standard basis in mech."""
    if not ideals:
        return []
    out = Session().execute(ring + "".join(f"std(ideal({', '.join(g)}));\n" for g in ideals))
    blocks = ideal_blocks(out)
    assert len(blocks) == len(ideals)
    return [tuple(b) for b in blocks]


def as_set(ring: str, ideals: list[list[str]]) -> set[tuple[str, ...]]:
    found = canonical(ring, ideals)
    assert len(set(found)) == len(found), "a component occurs twice"
    return set(found)


def texts(components: list[str]) -> list[list[str]]:
    return [c.split(", ") for c in components]


def pairs(output: str) -> list[tuple[list[str], list[str]]]:
    """(primary, prime) pairs from the output of primdecGTZ/primdecSY."""
    blocks = ideal_blocks(output)
    assert len(blocks) % 2 == 0
    return list(zip(blocks[::2], blocks[1::2]))


def header(setup: str) -> str:
    """The ring declaration of a setup script (its first line)."""
    return setup.splitlines()[0] + "\n"


# --- the paper ---------------------------------------------------------------------------

@pytest.mark.parametrize("setup, expected, cmd", [
    (SLIDER2, SLIDER2_PRIMES, "minAssGTZ"), (SLIDER3, SLIDER3_PRIMES, "minAssGTZ"),
    (FOURBAR, FOURBAR_PRIMES, "minAssGTZ"), (SLIDER2, SLIDER2_PRIMES, "minAssChar")])
def test_fitting_ideal_primes(setup, expected, cmd):
    """The minimal primes of the Fitting ideals: 6, 11 and 10 components, as in the paper."""
    out = mech(setup + f"list L = {cmd}(F); size(L); L;")
    assert out.splitlines()[0] == str(len(expected))
    ring = header(setup)
    assert as_set(ring, ideal_blocks(out)) == as_set(ring, texts(expected))


def test_fitting_ideal_radical():
    """radical(F) is the intersection of the minimal primes."""
    out = mech(SLIDER2 + "radical(F); intersect(" + ", ".join(f"ideal({c})" for c in SLIDER2_PRIMES) + ");")
    first, second = ideal_blocks(out)
    ring = header(SLIDER2)
    assert canonical(ring, [first]) == canonical(ring, [second])


@pytest.mark.parametrize("setup, modes", [(SLIDER2_L1, SLIDER2_MODES), (FOURBAR_L1, FOURBAR_MODES)])
@pytest.mark.parametrize("cmd", ["primdecGTZ", "primdecSY"])
def test_motion_modes(setup, modes, cmd):
    """The motion modes at l = 1: prime components, each its own primary."""
    comps = pairs(mech(setup + f"{cmd}(J);"))
    ring = header(setup)
    assert as_set(ring, [q for q, _ in comps]) == as_set(ring, texts(modes))
    assert canonical(ring, [q for q, _ in comps]) == canonical(ring, [p for _, p in comps])


@pytest.mark.parametrize("setup, extra, points", [
    (SLIDER2_L1, "c1,c2", SLIDER2_POINTS), (FOURBAR_L1, "-s2*c3+c2*s3, -s1*c3+c1*s3, -s1*c2+c1*s2", FOURBAR_POINTS),
    (SLIDER3_L, "c1,c2,c3", SLIDER3_POINTS)])
def test_singular_points(setup, extra, points):
    out = mech(setup + f"minAssGTZ(J + ideal({extra}));")
    ring = header(setup)
    assert as_set(ring, ideal_blocks(out)) == as_set(ring, texts(points))


def test_local_ring_dispatch():
    """With a local ordering: the components through the origin (two at q1 of the four-bar)."""
    out = mech(FOURBAR_L1 + """map toq1 = r1, c1-1, s1, c2+1, s2, c3+1, s3;
ideal Jq = toq1(J);
ring rl = 0, (c1,s1,c2,s2,c3,s3), ds;
ideal Jl = imap(r1, Jq);
minAssGTZ(Jl);""")
    assert len(ideal_blocks(out)) == 2


# --- small examples ----------------------------------------------------------------------

def test_embedded_component_output():
    """<x^2, xy> = <x> ∩ <x^2, y> in Singular's format (Singular lists the embedded prime's
    generators as x, y: its generator order after primdec.lib's ring changes is not kept)."""
    out = mech("ring r = 0, (x,y), dp;\nideal I = x2, xy;\nprimdecGTZ(I); primdecSY(I);")
    block = ("[1]:\n   [1]:\n      _[1]=x\n   [2]:\n      _[1]=x\n"
             "[2]:\n   [1]:\n      _[1]=y\n      _[2]=x2\n   [2]:\n      _[1]=y\n      _[2]=x\n")
    assert out == block + block


def test_non_reduced_and_mixed_dimensions():
    """A non-reduced primary line, a plane and an embedded point (the origin, on the plane)."""
    ring = "ring r = 0, (x,y,z), dp;\n"
    script = ring + "ideal I = intersect(ideal((x-1)^2, y), ideal(z), ideal(x,y,z)^3);\n"
    comps = pairs(mech(script + "primdecGTZ(I);"))
    assert as_set(ring, [p for _, p in comps]) == as_set(ring, [["x-1", "y"], ["z"], ["x", "y", "z"]])
    isolated = [q for q, p in comps if p != ["z", "y", "x"]]
    assert as_set(ring, isolated) == as_set(ring, [["(x-1)^2", "y"], ["z"]])
    blocks = ideal_blocks(mech(script + "equidim(I); equiRadical(I); minAssChar(I);"))
    assert canonical(ring, blocks[1:3]) == canonical(ring, [["(x-1)^2", "y"], ["z"]])
    assert canonical(ring, blocks[3:4]) == canonical(ring, [["z"]])
    assert as_set(ring, blocks[4:]) == as_set(ring, [["x-1", "y"], ["z"]])
    meet = "intersect(" + ", ".join(f"ideal({', '.join(b)})" for b in blocks[:3]) + ")"
    assert canonical(ring, [[meet]]) == canonical(ring, [["intersect(ideal((x-1)^2, y), ideal(z), ideal(x,y,z)^3)"]])


def test_embedded_primary_is_kept():
    """An embedded point: <x*y, y^2> = <y> ∩ <x, y^2>."""
    ring = "ring r = 0, (x,y), dp;\n"
    comps = pairs(mech(ring + "primdecGTZ(ideal(xy, y2));"))
    assert as_set(ring, [p for _, p in comps]) == as_set(ring, [["y"], ["x", "y"]])


def test_unit_and_zero_ideal():
    """As Singular: the unit ideal gives list(ideal(1)) globally, the empty list locally."""
    out = mech("ring r = 0, (x,y), dp;\nminAssGTZ(ideal(1)); primdecSY(ideal(1)); minAssChar(ideal(0));\n"
               "ring s = 0, (x,y), ds;\nminAssGTZ(ideal(x-1)); primdecGTZ(ideal(x-1));")
    assert out == ("[1]:\n   _[1]=1\n[1]:\n   [1]:\n      _[1]=1\n   [2]:\n      _[1]=1\n[1]:\n   _[1]=0\n"
                   "empty list\nempty list\n")


def test_finite_field():
    """Over Z/7: x^7 - x splits into seven points, y^2 + 1 is irreducible; an embedded point."""
    ring = "ring r = 7, (x,y), dp;\n"
    out = mech(ring + "minAssGTZ(ideal(x7-x, y2+1));")
    assert as_set(ring, ideal_blocks(out)) == as_set(ring, [[f"x-{a}", "y2+1"] for a in range(7)])
    comps = pairs(mech(ring + "primdecGTZ(ideal((x-1)^7*y, y^2));"))   # (x-1)^7 = x^7-1
    assert as_set(ring, [p for _, p in comps]) == as_set(ring, [["y"], ["x-1", "y"]])
    assert [["y"], ["y"]] in [[q, p] for q, p in comps]


def test_parameters():
    """Over Q(a,b): x^2 - a is irreducible, rational coefficients come back, components in the
    parameters alone (a = 0) are not components."""
    ring = "ring r = (0,a,b), (x,y), dp;\n"
    out = mech(ring + "minAssGTZ(ideal((x2-a)*(y-b), x*(y2-a*b)));")
    assert as_set(ring, ideal_blocks(out)) == as_set(ring, [["x", "y-b"], ["x2-a", "y2-ab"]])
    out = mech(ring + "minAssGTZ(ideal((2*x-a)*(3*y-b), x*y));")
    assert as_set(ring, ideal_blocks(out)) == as_set(ring, [["x", "3*y-b"], ["y", "2*x-a"]])
    out = mech(ring + "minAssGTZ(ideal(a*x^2-b^2*y^2));")   # a prime over Q(a,b)
    assert len(ideal_blocks(out)) == 1
    zp = "ring s = (7,a), (x,y), dp;\n"
    out = mech(zp + "minAssGTZ(ideal((2*x-a)*(3*y-a), x*y));")
    assert as_set(zp, ideal_blocks(out)) == as_set(zp, [["x", "3*y-a"], ["y", "2*x-a"]])
    comps = pairs(mech(ring + "primdecGTZ(ideal(x2-a*y, b*x*y));"))
    assert as_set(ring, [p for _, p in comps]) == as_set(ring, [["x", "y"]])
    assert as_set(ring, [q for q, _ in comps]) == as_set(ring, [["x2-ay", "xy"]])


def test_sat_after_primdec_lib():
    """LIB "primdec.lib" loads elim.lib, as in Singular."""
    out = Session().execute('LIB "primdec.lib";\nring r = 0, (x,y), dp;\nsat(ideal(x2, xy), ideal(x))[2];')
    assert out == "2\n"


def test_errors():
    with pytest.raises(MechError, match="unknown command 'minAssGTZ'"):
        Session().execute("ring r = 0, (x,y), dp;\nminAssGTZ(ideal(x));")
    with pytest.raises(MechError, match="equidim needs a global ordering"):
        mech("ring r = 0, (x,y), ds;\nequidim(ideal(x));")


# --- against Singular ---------------------------------------------------------------------

@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
def test_parameters_against_singular():
    """Over Q(a,b) Singular's components (its bases need not be reduced) equal ours."""
    ring = "ring r = (0,a,b), (x,y,z), dp;\n"
    ideals = ["(x2-a)*(y-b), x*(y2-a*b)*z", "a*x^2-b*y^2, z^2-a*b", "(x-a*y)^2, x*z-b",
              "(2*x-a)^2*(3*y-b), x*y*z"]
    script = ring + 'LIB "primdec.lib";\n' + "".join(f'minAssGTZ(ideal({i})); "--"; primdecGTZ(ideal({i})); "--";\n'
                                                      for i in ideals)
    theirs, ours = run_singular(script).split("--\n"), mech(script).split("--\n")
    assert len(theirs) == len(ours) == 2 * len(ideals) + 1
    for t, o in zip(theirs[0::2], ours[0::2]):
        assert as_set(ring, ideal_blocks(t)) == as_set(ring, ideal_blocks(o))
    for t, o in zip(theirs[1::2], ours[1::2]):
        for part in (0, 1):
            assert as_set(ring, [c[part] for c in pairs(t)]) == as_set(ring, [c[part] for c in pairs(o)])


def random_prime(rng: random.Random, names: list[str]) -> list[str]:
    """A prime ideal as generator texts: a linear space, the graph of a polynomial map or a
    point (prime by construction)."""
    order = names[:]
    rng.shuffle(order)
    kind = rng.choice(["linear", "graph", "point"])

    def form(variables: list[str], deg: int) -> str:
        terms = [str(rng.randint(-3, 3))]
        for _ in range(rng.randint(1, 2)):
            mono = "*".join(rng.choice(variables) for _ in range(rng.randint(1, deg)))
            terms.append(f"{rng.randint(-3, 3)}*{mono}")
        return "+".join(terms)

    if kind == "point":
        return [f"{v}-({rng.randint(-2, 2)})" for v in names]
    k = rng.randint(1, len(names) - 1)
    return [f"{order[i]}-({form(order[i + 1:] if kind == 'linear' else order[k:], 1 if kind == 'linear' else 2)})"
            for i in range(k)]


def random_ideals(seed: int, count: int) -> list[tuple[str, str]]:
    """(ring declaration, ideal expression) pairs: intersections, products and a squared prime
    intersected with others, over QQ and Z/32003."""
    rng = random.Random(seed)
    cases = []
    for i in range(count):
        names = ["x", "y", "z", "w"][:3 + i % 2]
        ring = f"ring r = {32003 if i % 3 == 2 else 0}, ({','.join(names)}), dp;\n"
        primes = [f"ideal({', '.join(random_prime(rng, names))})" for _ in range(rng.randint(2, 3))]
        how = rng.choice(["intersect", "product", "power"])
        if how == "intersect":
            expr = f"intersect({', '.join(primes)})"
        elif how == "product":
            expr = f"{primes[0]}*{primes[1]}"
        else:
            expr = f"intersect({primes[0]}^2, {', '.join(primes[1:])})"
        cases.append((ring, expr))
    return cases


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
def test_random_against_singular():
    """minAssGTZ and primdecGTZ through the language, against Singular: the same minimal primes,
    the same associated primes, the same isolated primaries; ours intersect to the ideal."""
    cases = random_ideals(seed=5, count=30)
    for ring, expr in cases:
        script = ring + f'LIB "primdec.lib";\nideal I = {expr};\nminAssGTZ(I);\n"--";\nprimdecGTZ(I);\n'
        theirs, ours = run_singular(script), mech(script)
        (t_min, t_dec), (o_min, o_dec) = theirs.split("--\n"), ours.split("--\n")
        primes = as_set(ring, ideal_blocks(o_min))
        assert primes == as_set(ring, ideal_blocks(t_min)), expr
        t_pairs, o_pairs = pairs(t_dec), pairs(o_dec)
        assert as_set(ring, [p for _, p in o_pairs]) == as_set(ring, [p for _, p in t_pairs]), expr
        isolated = {p: q for q, p in zip(canonical(ring, [q for q, _ in t_pairs]),
                                         canonical(ring, [p for _, p in t_pairs])) if p in primes}
        for q, p in zip(canonical(ring, [q for q, _ in o_pairs]), canonical(ring, [p for _, p in o_pairs])):
            if p in primes:
                assert q == isolated[p], expr
        meet = f"intersect({', '.join('ideal(' + ', '.join(q) + ')' for q, _ in o_pairs)})"
        assert _same(ring, expr, meet), expr


def _same(ring: str, expr: str, meet: str) -> bool:
    out = Session().execute(ring + f"ideal I = {expr};\nideal M = {meet};\n"
                            "size(reduce(I, std(M))) + size(reduce(M, std(I)));")
    return out == "0\n"
