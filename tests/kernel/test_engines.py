"""The engine conformance suite: every registered standard-basis engine (kernel/engines.py), and
``auto``, on one shared list of ideals and orderings, for every case the engine accepts.

The cases are parametrized over the registry itself, so an engine registered in the kernel is
tested here without editing this file.  Global orderings: the reduced basis equals the reference
engine's (Buchberger).  Local and mixed orderings (standard bases are not unique): the same
leading monomials as the reference's (Mora) -- a minimal standard basis has the minimal
generators of the leading ideal -- and each element lies in the ideal (weak normal form 0 by the
reference), so both generate the same ideal of the localization; and the generators reduce to 0
by it (a standard basis).  A sample is checked against real Singular."""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import pytest
from tests.util import ideal_blocks, parse_poly, run_singular

from mech.kernel import GF, QQ, Block, KernelError, MonomialOrder, PolyRing
from mech.kernel import engines as E
from mech.kernel.buchberger import buchberger
from mech.kernel.dimension import krull_dim
from mech.kernel.engines import (ENGINES, check_engine, default_engine, list_engines, register, standard_basis,
                                 using_engine)
from mech.kernel.errors import EngineError, OrderingError
from mech.kernel.groebner import groebner
from mech.kernel.localnf import weak_normal_form


@dataclass(frozen=True)
class Case:
    name: str
    names: str
    singular_order: str        # the ordering as Singular writes it
    blocks: tuple[Block, ...]  # the same ordering for the kernel
    gens: tuple[str, ...]      # Singular's long form

    def ring(self, char: int) -> PolyRing:
        return PolyRing(QQ if char == 0 else GF(char), list(self.names), MonomialOrder(list(self.blocks)))


def _b(kind: str, n: int, weights: tuple[int, ...] = ()) -> Block:
    return Block(kind, n, weights)


XYZ = ("7*x*y*z+z^5", "x^2+y^3+z^7", "5*z^5+y^5")
WEIGHTED = ("x^2-y*z", "y^3+x-z", "x*z-y^2+1")
CASES = [
    # global orderings: positive-dimensional, zero-dimensional, unit, zero ideals; dp lp blocks weights
    Case("twisted cubic, dp", "xyz", "dp", (_b("dp", 3),), ("x^2-y", "x^3-z")),
    Case("katsura-3, dp", "abcd", "dp", (_b("dp", 4),),
         ("a+2*b+2*c+2*d-1", "a^2+2*b^2+2*c^2+2*d^2-a", "2*a*b+2*b*c+2*c*d-b", "b^2+2*a*c+2*b*d-c")),
    Case("unit ideal, dp", "xy", "dp", (_b("dp", 2),), ("x*y-1", "x^2-y", "y^3")),
    Case("zero ideal, dp", "xy", "dp", (_b("dp", 2),), ("0",)),
    Case("sphere and parabolas, lp", "xyz", "lp", (_b("lp", 3),), ("x^2+y^2+z^2-1", "x-y^2", "y*z-x")),
    Case("elimination, (dp(4),dp(2))", "abcdxy", "(dp(4),dp(2))", (_b("dp", 4), _b("dp", 2)),
         ("x-a*b", "y-c*d", "a^2+b^2-1", "c^2+d^2-1")),
    Case("weights, wp(3,1,2)", "xyz", "wp(3,1,2)", (_b("wp", 3, (3, 1, 2)),), WEIGHTED),
    Case("weight prefix, (a(0,1,1),lp)", "xyz", "(a(0,1,1),lp)", (_b("a", 3, (0, 1, 1)), _b("lp", 3)), WEIGHTED),
    # local and mixed orderings
    Case("space curve singularity, ds", "xyz", "ds", (_b("ds", 3),), XYZ),
    Case("space curve singularity, ls", "xyz", "ls", (_b("ls", 3),), XYZ),
    Case("space curve singularity, ws(2,3,1)", "xyz", "ws(2,3,1)", (_b("ws", 3, (2, 3, 1)),), XYZ),
    Case("surface germ (positive-dimensional), ds", "xyz", "ds", (_b("ds", 3),), ("x*y-z^2", "x^3+y^3-x*z")),
    Case("unit factors, ds", "xy", "ds", (_b("ds", 2),), ("x-x^2", "y^2-y^3+x*y")),
    Case("mixed, (dp(1),ds(2))", "xyz", "(dp(1),ds(2))", (_b("dp", 1), _b("ds", 2)), XYZ),
    Case("mixed, (ds(1),dp(2))", "xyz", "(ds(1),dp(2))", (_b("ds", 1), _b("dp", 2)), XYZ),
    Case("unit ideal of the local ring, ds", "xy", "ds", (_b("ds", 2),), ("x", "y-1")),
    Case("zero ideal, ds", "xy", "ds", (_b("ds", 2),), ("0",)),
    # zero-dimensional ideals in lex and block orderings (FGLM's conversions)
    Case("katsura-3, lp", "abcd", "lp", (_b("lp", 4),),
         ("a+2*b+2*c+2*d-1", "a^2+2*b^2+2*c^2+2*d^2-a", "2*a*b+2*b*c+2*c*d-b", "b^2+2*a*c+2*b*d-c")),
    Case("katsura-3, (dp(2),dp(2))", "abcd", "(dp(2),dp(2))", (_b("dp", 2), _b("dp", 2)),
         ("a+2*b+2*c+2*d-1", "a^2+2*b^2+2*c^2+2*d^2-a", "2*a*b+2*b*c+2*c*d-b", "b^2+2*a*c+2*b*d-c")),
]
CHARS = (0, 32003)


def _params() -> list:
    """(engine, case, characteristic) for every registered engine (and auto) and every case it accepts."""
    out = []
    for name in ["auto"] + list(ENGINES):
        for case in CASES:
            for char in CHARS:
                if name == "auto" or ENGINES[name].refusal(case.ring(char)) is None:
                    out.append(pytest.param(name, case, char, id=f"{name}-{case.name}-{char or 'QQ'}"))
    return out


@lru_cache(maxsize=None)
def gens_of(case: Case, char: int) -> tuple:
    R = case.ring(char)
    return R, tuple(parse_poly(R, t) for t in case.gens)


@lru_cache(maxsize=None)
def reference(case: Case, char: int) -> tuple:
    R, gens = gens_of(case, char)
    return tuple(standard_basis(list(gens), R, "buchberger" if R.order.is_global else "mora"))


def leading(basis) -> list:
    return sorted(p.lm() for p in basis)


def assert_same_local_basis(ours, ref, gens) -> None:
    """``ours`` is a minimal standard basis of the ideal whose standard basis is ``ref``."""
    assert leading(ours) == leading(ref)
    assert all(p.lc() == p.ring.field.one for p in ours)
    assert all(weak_normal_form(p, list(ref)).is_zero() for p in ours)
    assert all(weak_normal_form(g, ours).is_zero() for g in gens)


@pytest.mark.parametrize("engine, case, char", _params())
def test_engine_conforms(engine, case, char):
    R, gens = gens_of(case, char)
    ref = list(reference(case, char))
    if engine != "auto" and ENGINES[engine].zero_dimensional and ref and krull_dim([p.lm() for p in ref], R.nvars) > 0:
        with pytest.raises(EngineError, match="needs a zero-dimensional ideal"):
            standard_basis(list(gens), R, engine)
        return
    ours = standard_basis(list(gens), R, engine)
    key = R.order.key
    if R.order.is_global:
        assert ours == ref
        assert [key(p.lm()) for p in ours] == sorted(key(p.lm()) for p in ours)
    else:
        assert_same_local_basis(ours, ref, gens)
        assert [key(p.lm()) for p in ours] == sorted((key(p.lm()) for p in ours), reverse=True)
    if "unit ideal" in case.name:
        assert ours == [R.one()]
    if "zero ideal" in case.name:
        assert ours == []


@pytest.mark.singular
def test_reference_matches_singular():
    """The reference bases (hence every engine's) against Singular: ``option(redSB)`` reduced
    bases for global orderings; for local ones the leading monomials and the ideal."""
    sample = [(case, char) for case in CASES for char in CHARS]
    script = "option(redSB);\n" + "".join(
        f"ring r = {char}, ({','.join(case.names)}), {case.singular_order}; short = 0; "
        f"ideal i = {', '.join(case.gens)}; std(i); kill r;\n" for case, char in sample)
    blocks = ideal_blocks(run_singular(script))
    assert len(blocks) == len(sample)
    for (case, char), block in zip(sample, blocks):
        R, gens = gens_of(case, char)
        theirs = [p for p in (parse_poly(R, t) for t in block) if not p.is_zero()]
        ref = list(reference(case, char))
        if R.order.is_global:
            assert ref == [p.monic() for p in theirs], (case.name, char)
        else:
            assert_same_local_basis(ref, theirs, gens)


# --- the driver's API --------------------------------------------------------------------

def test_a_registered_engine_is_reached_by_name(monkeypatch):
    monkeypatch.setattr(E, "ENGINES", dict(ENGINES))
    calls = []

    def toy(gens, ring):
        calls.append(len(gens))
        return buchberger(gens, ring)
    register("toy", toy, "Buchberger, counted")
    assert ("toy", "Buchberger, counted") in list_engines()
    case = CASES[1]
    R, gens = gens_of(case, 0)
    assert standard_basis(list(gens), R, "toy") == list(reference(case, 0)) and calls == [4]
    with using_engine("toy"):
        assert default_engine() == "toy"
        assert groebner(list(gens[:3]), R) == standard_basis(list(gens[:3]), R, "buchberger")
        assert calls == [4, 3]
        local = CASES[12]
        L, lgens = gens_of(local, 0)  # a local ring: the default does not apply, auto does
        assert_same_local_basis(standard_basis(list(lgens), L), reference(local, 0), lgens)
        assert calls == [4, 3]
    assert default_engine() == "auto"


def test_a_bad_engine_name_lists_the_known_engines():
    R, gens = gens_of(CASES[0], 0)
    with pytest.raises(EngineError) as info:
        standard_basis(list(gens), R, "nonesuch")
    assert str(info.value) == f"unknown engine 'nonesuch' (known: {', '.join(n for n, _ in list_engines())})"
    assert all(name in str(info.value) for name in ["auto"] + list(ENGINES))
    with pytest.raises(EngineError, match="unknown engine 'nonesuch'"):
        with using_engine("nonesuch"):
            pass
    assert isinstance(info.value, KernelError) and not isinstance(info.value, ValueError)


def test_an_engine_refuses_a_ring_it_does_not_accept():
    L, gens = gens_of(CASES[8], 0)  # ds
    with pytest.raises(EngineError, match=r"^the engine 'buchberger' needs a global ordering "
                                          r"\(engines for this ring: auto, mora, lazard\)$"):
        standard_basis(list(gens), L, "buchberger")
    R, gens = gens_of(CASES[0], 0)  # QQ
    with pytest.raises(EngineError, match=r"^the engine 'f4' needs coefficients in Z/p, not QQ"):
        standard_basis(list(gens), R, "f4")
    R, gens = gens_of(CASES[0], 32003)
    with pytest.raises(EngineError, match=r"needs coefficients in QQ, not GF\(32003\)"):
        check_engine("modular", R)
    with pytest.raises(OrderingError, match="Gröbner bases need a global ordering"):
        groebner(list(gens_of(CASES[8], 0)[1]))


def test_engines_are_listed_with_one_line_descriptions():
    listed = list_engines()
    assert listed[0][0] == "auto"
    assert [n for n, _ in listed[1:]] == list(ENGINES)
    assert {"buchberger", "f4", "modular", "mora", "lazard"} <= set(ENGINES)
    assert all(summary and "\n" not in summary for _, summary in listed)


def test_auto_is_not_an_engine_name():
    with pytest.raises(EngineError):
        register("auto", buchberger, "no")


def test_auto_leaves_a_small_system_over_qq_to_the_compiled_buchberger(monkeypatch):
    # the block system of benchmarks/cases.py in dp: its first modular F4 run stays below SMALL_WORK
    ring = PolyRing(QQ, list("xyzuv"), MonomialOrder.simple("dp", 5))
    gens = [parse_poly(ring, s) for s in ("x^2+y*u-1", "y^2-x*v", "z^3-u^2*v", "x*y*z-u-v")]
    calls = []
    compiled = E._buchberger_compiled
    monkeypatch.setattr(E, "_buchberger_compiled", lambda g, r: calls.append(r) or compiled(g, r))
    E.clear_cache()
    basis = standard_basis(gens, ring)
    assert calls == [ring]
    assert [p.terms for p in basis] == [p.terms for p in standard_basis(gens, ring, "buchberger")]
    assert len(basis) > len(gens)
