"""Property tests (hypothesis) of the kernel: orderings, Gröbner bases, elimination and primary
decomposition."""
from hypothesis import given, settings
from hypothesis import strategies as st

from mech.kernel import GF, QQ, Block, MonomialOrder, PolyRing, normal_form
from mech.kernel.groebner import groebner
from mech.kernel.ideals import eliminate, intersect
from mech.kernel.poly import lcm_exp
from mech.kernel.primdec import is_prime, primdec_gtz, radical

N = 3
exps = st.tuples(*[st.integers(0, 4)] * N)
weights = st.tuples(*[st.integers(1, 3)] * N)


@st.composite
def orders(draw):
    kind = draw(st.sampled_from(["lp", "dp", "Dp", "wp", "Wp", "ls", "ds", "Ds", "ws", "Ws", "blocks"]))
    if kind == "blocks":
        k = draw(st.integers(1, N - 1))
        a, b = draw(st.sampled_from(["lp", "dp", "ds", "ls", "Dp"])), draw(st.sampled_from(["lp", "dp", "ds"]))
        return MonomialOrder([Block(a, k), Block(b, N - k)])
    w = draw(weights) if kind in ("wp", "Wp", "ws", "Ws") else ()
    return MonomialOrder.simple(kind, N, w)


@settings(max_examples=200, deadline=None)
@given(orders(), exps, exps, exps)
def test_ordering_is_total_and_multiplicative(order, a, b, c):
    assert (order.compare(a, b) == 0) == (a == b)
    assert order.compare(a, b) == -order.compare(b, a)
    ac = tuple(x + z for x, z in zip(a, c))
    bc = tuple(y + z for y, z in zip(b, c))
    assert order.compare(ac, bc) == order.compare(a, b)


@settings(max_examples=100, deadline=None)
@given(orders(), exps, exps, exps)
def test_ordering_is_transitive(order, a, b, c):
    if order.compare(a, b) < 0 and order.compare(b, c) < 0:
        assert order.compare(a, c) < 0


@st.composite
def small_ideals(draw):
    field = draw(st.sampled_from([QQ, GF(32003), GF(7)]))
    kind = draw(st.sampled_from(["dp", "lp", "Dp", "blocks"]))
    order = (MonomialOrder([Block("dp", 1), Block("dp", 2)]) if kind == "blocks"
             else MonomialOrder.simple(kind, N))
    R = PolyRing(field, ["x", "y", "z"], order)
    polys = []
    for _ in range(draw(st.integers(1, 3))):
        terms = draw(st.dictionaries(st.tuples(*[st.integers(0, 2)] * N), st.integers(-5, 5),
                                     min_size=1, max_size=4))
        polys.append(R.from_dict(terms))
    return R, polys


def spoly(f, g):
    lc = lcm_exp(f.lm(), g.lm())
    mf = tuple(x - y for x, y in zip(lc, f.lm()))
    mg = tuple(x - y for x, y in zip(lc, g.lm()))
    return f.mul_term(mf, 1 / f.lc()) - g.mul_term(mg, 1 / g.lc())


@settings(max_examples=60, deadline=None)
@given(small_ideals())
def test_groebner_basis_reduces_generators_and_spolys(data):
    R, polys = data
    G = groebner(polys)
    for f in polys:
        assert normal_form(f, G).is_zero()
    for i, f in enumerate(G):
        assert f.lc() == R.field.one
        for g in G[i + 1:]:
            assert normal_form(spoly(f, g), G).is_zero()
    # reduced: no term of an element is divisible by another element's leading monomial
    for f in G:
        for g in G:
            if f is not g:
                assert not any(all(a <= b for a, b in zip(g.lm(), e)) for e in f.terms)


@settings(max_examples=40, deadline=None)
@given(small_ideals(), st.sets(st.integers(0, N - 1), min_size=1, max_size=N - 1))
def test_elimination_is_free_of_the_variables_and_in_the_ideal(data, drop):
    R, polys = data
    E = eliminate(polys, sorted(drop))
    G = groebner(polys)
    for f in E:
        assert all(e[i] == 0 for e in f.terms for i in drop)
        assert normal_form(f, G).is_zero()


@st.composite
def decomposable_ideals(draw):
    """Intersections and products of small ideals, so that components of several dimensions,
    embedded and non-reduced ones occur; in two or three variables to keep examples quick."""
    field = draw(st.sampled_from([QQ, GF(32003)]))
    R = PolyRing(field, ["x", "y", "z"], MonomialOrder.simple("dp", N))
    x, y, z = R.gens()
    atoms = [x, y, z, x - 1, y + 1, x - y, x + y - z, x ** 2 - y, y ** 2 - z]
    pieces = []
    for _ in range(draw(st.integers(1, 3))):
        gens = draw(st.lists(st.sampled_from(atoms), min_size=1, max_size=2, unique=True))
        power = draw(st.integers(1, 2))
        pieces.append([g ** power if k == 0 else g for k, g in enumerate(gens)])
    return R, pieces


@settings(max_examples=25, deadline=None)
@given(decomposable_ideals())
def test_primary_components_intersect_to_the_ideal(data):
    R, pieces = data
    I = intersect(*pieces, ring=R)
    comps = primdec_gtz(I, R)
    assert intersect(*[q for q, _ in comps], ring=R) == groebner(I, R)
    for q, p in comps:
        assert radical(q, R) == p and is_prime(p, R)


@settings(max_examples=80, deadline=None)
@given(small_ideals(), st.tuples(*[st.integers(0, 3)] * N), st.integers(1, 6), st.tuples(*[st.integers(0, 3)] * N))
def test_a_term_times_a_polynomial_is_the_general_product(data, e, c, e2):
    R, polys = data
    f = polys[0]
    m, n = R.from_dict({e: c}), R.from_dict({e2: -1})  # c is not 0 in any of the fields
    assert f * m == m * f == f.mul_term(e, R.field(c))
    if e != e2:  # m + n has two terms: the general product
        assert f * m + f * n == f * (m + n)
