"""The ``auto`` policy for local orderings (kernel/local_policy.py): every route (Mora first,
Lazard's method through F4 within a budget, the homogeneous shortcut) gives a standard basis
with the leading ideal Mora alone finds, and Lazard's dehomogenization keeps one element per
minimal leading monomial."""
import pytest
from tests.util import SINGULAR, ideal_blocks, parse_poly, run_singular

from mech.kernel import GF, QQ, Block, MonomialOrder, PolyRing
from mech.kernel import local_policy
from mech.kernel.engines import clear_cache, standard_basis
from mech.kernel.hilbert import minimal_monomials
from mech.kernel import mora as mora_module
from mech.kernel.mora import contains_axis, mora

SYSTEMS = [
    ("x,y,z", "ds", ["x^2*y+z^3+x^5", "y^3+x*z^2+y^6", "z^4+x*y*z+x^7"]),
    ("x,y,z", "ds", ["x^2+y^2+z^2", "x*y*z", "x^3+y^3"]),  # homogeneous
    ("x,y", "ls", ["x^3+y^2+x^4*y", "x*y^3+y^5"]),
    ("w,x,y,z", "Ds", ["w*x+y^2+z^5", "x^2+w^3+y*z^2", "y*z+w^4", "z^3+x^3*y"]),
]


def _ring(names, kind, field):
    names = names.split(",")
    return PolyRing(field, names, MonomialOrder([Block(kind, len(names))]))



@pytest.mark.parametrize("field", [GF(32003), QQ])
@pytest.mark.parametrize("names,kind,polys", SYSTEMS)
@pytest.mark.parametrize("mora_first", [0, local_policy.MORA_FIRST])
def test_every_route_gives_the_leading_ideal_of_mora(names, kind, polys, field, mora_first, monkeypatch):
    monkeypatch.setattr(local_policy, "MORA_FIRST", mora_first)
    monkeypatch.setattr(local_policy, "MORA_COMPILED", mora_first or local_policy.MORA_COMPILED)
    monkeypatch.setattr(local_policy, "MORA_QUICK", mora_first and local_policy.MORA_QUICK)
    monkeypatch.setattr(local_policy, "MORA_UNCUT", mora_first and local_policy.MORA_UNCUT)
    R = _ring(names, kind, field)
    gens = [parse_poly(R, p) for p in polys]
    key = R.order.key
    expected = sorted(minimal_monomials([max(b, key=key) for b in mora(gens, R)]))
    got = standard_basis(gens, R)
    assert sorted(minimal_monomials([g.lm() for g in got])) == expected
    assert len(got) == len(expected)  # minimal


def test_lazard_route_is_taken_and_agrees(monkeypatch):
    calls = []
    run = local_policy._f4_within

    def spy(budget):
        calls.append(budget)
        return run(budget)
    monkeypatch.setattr(local_policy, "MORA_FIRST", 0)
    monkeypatch.setattr(local_policy, "MORA_COMPILED", 0)
    monkeypatch.setattr(local_policy, "MORA_QUICK", 0)
    monkeypatch.setattr(local_policy, "MORA_UNCUT", 0)
    monkeypatch.setattr(local_policy, "_f4_within", spy)
    R = _ring("x,y,z", "ds", GF(32003))
    gens = [parse_poly(R, p) for p in SYSTEMS[0][2]]
    got = standard_basis(gens, R)
    compiled = local_policy.CompiledMora.usable(R)
    assert calls == [local_policy.LAZARD_SMALL if compiled else local_policy.LAZARD_BUDGET]
    key = R.order.key
    assert sorted(g.lm() for g in got) == sorted(minimal_monomials([max(b, key=key) for b in mora(gens, R)]))


def test_compiled_routes_after_the_first_mora_agree(monkeypatch):
    """Over Z/p with the compiled loop: Lazard within the small budget, then Mora without trial
    cuts, then the large Lazard; each gives the leading ideal of Mora alone."""
    R = _ring("x,y,z", "ds", GF(32003))
    if not local_policy.CompiledMora.usable(R):
        pytest.skip("the C extension _mora is not built")
    gens = [parse_poly(R, p) for p in SYSTEMS[0][2]]
    key = R.order.key
    expected = sorted(minimal_monomials([max(b, key=key) for b in mora(gens, R)]))
    monkeypatch.setattr(local_policy, "MORA_COMPILED", 0)
    for small, uncut in [(0, local_policy.MORA_UNCUT), (0, 0)]:
        monkeypatch.setattr(local_policy, "LAZARD_SMALL", small)
        monkeypatch.setattr(local_policy, "MORA_UNCUT", uncut)
        clear_cache()
        got = standard_basis(gens, R)
        assert sorted(minimal_monomials([g.lm() for g in got])) == expected
        assert len(got) == len(expected)


AXIS = ["x^2+y*z+x*z^3", "y^3+x*z^2", "x*y*z+y^2*z^2+x^4"]  # no pure power of z: the z-axis is a zero


def test_contains_axis():
    R = _ring("x,y,z", "ds", GF(32003))
    assert contains_axis([parse_poly(R, p) for p in AXIS])
    assert not contains_axis([parse_poly(R, p) for p in SYSTEMS[0][2]])  # x^5, y^3, z^4 are terms
    assert not contains_axis([parse_poly(R, p) for p in ["x^2+y^3", "y^2*x"]])  # z occurs in none
    assert contains_axis([parse_poly(R, p) for p in ["x^2+y*z", "y^2*x"]])


@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
def test_an_axis_skips_the_trial_cuts_and_matches_singular(monkeypatch):
    """With a coordinate axis in the zero set no trial cut can succeed: the first run is Mora
    without cuts, whose leading ideal is Singular's."""
    R = _ring("x,y,z", "ds", GF(32003))
    if not local_policy.CompiledMora.usable(R):
        pytest.skip("the C extension _mora is not built")
    calls = []
    run = mora_module._mora

    def spy(gens, ring, budget=None, cut=None):
        calls.append(cut)
        return run(gens, ring, budget, cut)
    monkeypatch.setattr(mora_module, "_mora", spy)
    gens = [parse_poly(R, p) for p in AXIS]
    clear_cache()
    got = standard_basis(gens, R)
    assert calls == [None]
    script = f"ring r = 32003, (x,y,z), ds; short = 0;\nideal I = {','.join(AXIS)};\nlead(std(I));\n"
    singular = sorted(parse_poly(R, m).lm() for m in ideal_blocks(run_singular(script))[0])
    assert sorted(g.lm() for g in got) == singular


def test_the_policy_runs_once_per_group_of_copies(monkeypatch):
    """Generators in disjoint variables: the policy runs on each group in the ring of its own
    variables, copies equal up to renaming once (kernel/mora.py's in_groups), and the bases
    together have the leading ideal of Mora on the whole."""
    R = _ring("x,y,z,w", "ds", GF(32003))
    gens = [parse_poly(R, p) for p in ["x^3+y^2+x^4*y", "x*y^3+y^5", "z^3+w^2+z^4*w", "z*w^3+w^5"]]
    calls = []
    real = local_policy._auto_group

    def spy(part, ring, global_basis):
        calls.append(ring.names)
        return real(part, ring, global_basis)
    monkeypatch.setattr(local_policy, "_auto_group", spy)
    clear_cache()
    got = standard_basis(gens, R)
    assert calls == [("x", "y")]
    key = R.order.key
    whole = mora_module._mora(gens, R)[0]
    assert sorted(g.lm() for g in got) == sorted(minimal_monomials([max(b, key=key) for b in whole]))
