"""Mora's algorithm with the highest corner (kernel/mora.py): the degree cut from a
zero-dimensional leading ideal and the trial cuts justified by Nakayama's lemma must give the
same local ideal, leading ideal and vdim as the computation without a cut (Lazard's method)
and as Singular."""
import subprocess

import pytest
from tests.util import SINGULAR, parse_poly

from mech.kernel import GF, QQ, Block, MonomialOrder, PolyRing
from mech.kernel.engines import standard_basis
from mech.kernel.hilbert import hilbert_numerators, minimal_monomials, vdim
from mech.kernel.mora import Corner, _mora, _separate, mora


def ds_ring(names, field=GF(32003), kind="ds"):
    return PolyRing(field, list(names), MonomialOrder([Block(kind, len(names))]))


def jacobian_and(f):
    return [f.diff(i) for i in range(f.ring.nvars)] + [f]


def example(R, a):
    """An isolated singularity with a cubic tangent cone (our example, not Singular's)."""
    return jacobian_and(parse_poly(R, f"x^2*y^2*(x+2*y+z)+(x+y-z)^3+x^{a}+y^{a}+z^{a}"))


def lms(basis, R):
    key = R.order.key
    return sorted(max(b, key=key) for b in basis)


def test_corner_needs_all_pure_powers_and_only_goes_down():
    R = ds_ring("xy")
    c = Corner(R)
    assert c.enabled and c.cut is None
    assert not c.update((1, 1), lambda: [(1, 1)])
    assert not c.update((3, 0), lambda: [(1, 1), (3, 0)])
    assert c.update((0, 2), lambda: [(1, 1), (3, 0), (0, 2)]) and c.found
    assert c.cut == 2  # x^2 is the standard monomial of largest degree
    assert c.update((2, 0), lambda: [(1, 1), (2, 0), (0, 2)]) and c.cut == 1
    assert not Corner(ds_ring("xy", kind="ls")).enabled


@pytest.mark.parametrize("a, field", [(5, GF(32003)), (9, GF(32003)), (5, QQ), (7, QQ)])
def test_cut_bases_agree_with_lazard(a, field):
    R = ds_ring("xyz", field)
    gens = example(R, a)
    ours = standard_basis(gens, R, "mora")
    theirs = standard_basis(gens, R, "lazard")
    assert sorted(g.lm() for g in ours) == sorted(g.lm() for g in theirs)
    assert vdim([g.lm() for g in ours], 3) == vdim([g.lm() for g in theirs], 3) > 0
    # the same ideal of the local ring: the union has the same leading ideal
    both = standard_basis(list(ours) + list(theirs), R, "mora")
    assert sorted(g.lm() for g in both) == sorted(g.lm() for g in ours)


def test_trial_cut_is_used_only_when_it_is_proved():
    R = ds_ring("xyz")
    gens = example(R, 7)
    top = max(g.total_degree() for g in gens)
    basis, corner = _mora(gens, R, None, 2 * top)
    assert corner.found and corner.cut < 2 * top  # Nakayama: m^cut+1 lies in the ideal
    assert lms(basis, R) == lms(mora(gens, R), R)
    _, low = _mora(gens, R, None, 2)  # a cut too low proves nothing
    assert not (low.found and low.cut < 2)
    # no corner for a curve germ: the trials fail and the uncut computation answers
    C = ds_ring("xyz")
    curve = [parse_poly(C, "x^2-y^3+z^5"), parse_poly(C, "x*y-z^4")]
    _, _, d = hilbert_numerators(lms(mora(curve, C), C), 3)
    assert d == 1


@pytest.mark.singular
@pytest.mark.parametrize("a", [6, 11])
def test_cut_bases_match_singular(a):
    R = ds_ring("xyz")
    gens = example(R, a)
    ours = ",".join(g.to_str() for g in standard_basis(gens, R))
    given = ",".join(g.to_str() for g in gens)
    script = (f"ring r=32003,(x,y,z),ds; ideal i={given}; ideal j=std(i); ideal m={ours};"
              "ideal sm=std(m); print(size(reduce(m,j))); print(size(reduce(i,sm)));"
              "print(vdim(j)-vdim(sm)); print(size(reduce(lead(j),lead(sm))));"
              "print(size(reduce(lead(sm),lead(j)))); print(vdim(j)); quit;")
    out = subprocess.run([SINGULAR, "-q"], input=script, text=True, capture_output=True, timeout=120).stdout.split()
    assert out[:5] == ["0"] * 5 and int(out[5]) > 0, out


@pytest.mark.parametrize("kind", ["ds", "ls", "Ds"])
def test_generators_in_disjoint_variables_are_split(kind):
    """Bases of the groups of generators sharing no variable, together, have the leading ideal of
    the whole computation (kernel/mora.py's _separate)."""
    R = PolyRing(GF(32003), ["x", "y", "z", "w"], MonomialOrder([Block(kind, 4)]))
    gens = [parse_poly(R, p) for p in ["x^3+y^2+x^4*y", "x*y^3+y^5", "z^2*w+w^4+z^5", "z^3-w^3+z*w^4"]]
    assert [(used, len(p)) for used, p in _separate(gens, 4)] == [([0, 1], 2), ([2, 3], 2)]
    key = R.order.key
    split = mora(gens, R)
    whole = _mora(gens, R)[0]
    assert sorted(minimal_monomials([max(b, key=key) for b in split])) == \
        sorted(minimal_monomials([max(b, key=key) for b in whole]))
    assert len(split) == len(minimal_monomials([max(b, key=key) for b in split]))


@pytest.mark.parametrize("kind", ["ds", "ls"])
def test_copies_of_a_group_are_computed_once(kind, monkeypatch):
    """Groups equal up to renaming their variables in order are computed once, in the ring of
    their own variables (kernel/mora.py's _part_basis), with the leading ideal of the whole."""
    from mech.kernel import mora as mora_module
    R = PolyRing(GF(32003), ["x", "y", "z", "w"], MonomialOrder([Block(kind, 4)]))
    gens = [parse_poly(R, p) for p in ["x^3+y^2+x^4*y", "x*y^3+y^5", "z^3+w^2+z^4*w", "z*w^3+w^5"]]
    calls = []
    real = mora_module.mora_group

    def spy(gens, ring, *args):
        calls.append(ring.nvars)
        return real(gens, ring, *args)
    monkeypatch.setattr(mora_module, "mora_group", spy)
    split = mora(gens, R)
    assert calls == [2]
    key = R.order.key
    lms = sorted(max(b, key=key) for b in split)
    assert lms == sorted(minimal_monomials([max(b, key=key) for b in _mora(gens, R)[0]]))
    assert sorted((e[2], e[3]) for e in lms if e[2] or e[3]) == sorted((e[0], e[1]) for e in lms if e[0] or e[1])


@pytest.mark.parametrize("kind", ["ds", "ls"])
def test_groups_in_unevenly_spaced_variables(kind):
    """Groups whose variables are not evenly spaced in the ring (a, b, d and c, e, f) are placed
    back term by term (kernel/mora.py's _part_basis), with the leading ideal of the whole."""
    R = PolyRing(GF(32003), list("abcdef"), MonomialOrder([Block(kind, 6)]))
    gens = [parse_poly(R, p) for p in ["a^3+b^2+d^4*a", "a*b^3+d^5", "d^3-b*a^2", "c^3+e^2+f^4*c", "c*e^3+f^5", "f^3-e*c^2"]]
    assert [used for used, _ in _separate(gens, 6)] == [[0, 1, 3], [2, 4, 5]]
    key = R.order.key
    split = mora(gens, R)
    whole = _mora(gens, R)[0]
    assert sorted(max(b, key=key) for b in split) == sorted(minimal_monomials([max(b, key=key) for b in whole]))
