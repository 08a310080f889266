"""Standard-basis engines and the one entry point, :func:`standard_basis`, for global and local
orderings alike.

An :class:`Engine` is a function ``run(gens, ring)`` with what it accepts: global and/or
local orderings (``"local"`` stands for every non-global ordering, local or mixed) and the
coefficient fields (``"QQ"``, ``"Z/p"``; ``None``: every field, parameters included).  It gets
nonzero, non-constant generators and returns ``{exponent: coefficient}`` dicts: for a global
ordering a Gröbner basis (with ``returns_reduced`` the reduced one, sorted by increasing leading
monomial, each leading exponent first in its dict), for a local one a standard basis.
:func:`register` adds an engine; :func:`standard_basis` then reaches it by name.

``"auto"``, the default, is the policy, not an engine.  Global orderings: F4 for degree
orderings (``is_graded``) over Z/p, and over QQ modular F4, except for systems too small for
its overhead to pay off (:data:`SMALL_WORK`: the compiled Buchberger, lifted) and when the modular
method cannot verify a basis (then Buchberger).  Block and lex orderings over QQ and Z/p: Buchberger within a budget
(:data:`SMALL_BUCHBERGER`; the mechanisms' many small eliminations; lex orderings, every ordering
over Z/p, and ideals with at least as many generators as variables compute the ``dp`` basis first
and skip it for zero-dimensional ideals; over Z/p there is no attempt when the compiled
Hilbert-driven algorithm is built), then a ``dp`` basis (kept in the
cache) and from it FGLM for zero-dimensional ideals (over QQ in a block ordering with at least
:data:`FGLM_STAIRS` standard monomials the Hilbert-driven F4 instead); for the others, over Z/p and
a lex ordering F4 on that ordering within :data:`F4_BUDGET` (its matrices can grow far past
the Hilbert-driven algorithm's work), then the Hilbert-driven algorithm (compiled modulo p and
lifted over QQ, :mod:`.hilbert_compiled`, its homogenized ``dp`` basis by the compiled Buchberger;
in Python without a compiler); Buchberger over other fields.  Local orderings: :mod:`.local_policy`
(Mora or Lazard's homogenization through F4).

:func:`using_engine` sets the default for a dynamic extent (a context variable); it applies to
the computations its engine accepts, the others use ``"auto"``.  An engine named in a call must
accept the ring (:class:`~.errors.EngineError` otherwise).

The last 256 bases for global orderings are kept by (ring, engine, set of generators):
dimension, containment and decomposition ask for the same bases many times (:func:`clear_cache`
for benchmarks).
"""
from __future__ import annotations

from collections import OrderedDict
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass
from typing import Any, Callable, Iterator, Sequence

from .buchberger import TooLong, buchberger, reduce_basis
from .collector import paused
from .coeffs import Field, PrimeField, RationalField
from .errors import EngineError
from .f4 import f4_modp, reduce_modp
from .flint_reduce import FLINT_TERMS, reduce_basis_qq
from .fglm import NotZeroDimensional, fglm_qq, fglm_zp, staircase
from .hilbert_compiled import buchberger_modp, buchberger_qq, hilbert_modp, hilbert_qq, usable as compiled_hilbert
from .hilbert_driven import degree_leads, hilbert_driven, hilbert_f4
from .lazard import lazard
from .local_policy import auto_local
from .modular import ModularFailure, SmallSystem, f4_qq
from .mora import finished, mora
from .order import Exp, MonomialOrder
from .poly import Poly, PolyRing

Terms = dict[Exp, Any]
Run = Callable[[list[Poly], PolyRing], list[Terms]]

AUTO = "auto"
AUTO_SUMMARY = ("the default: F4 for degree orderings over QQ (modular) and Z/p; block and lex orderings: "
                "Buchberger if small (QQ), else from a dp basis FGLM or Hilbert-driven F4 (zero-dimensional ideals), "
                "F4 (lex over Z/p) or Hilbert-driven (compiled mod p, lifted over QQ); "
                "local orderings: Mora, then Lazard")

SMALL_WORK = 600
"""Below this much work (matrix entries) in the first modular run, ``auto`` leaves a system over
QQ to Buchberger (compiled and lifted where built), whose smaller overhead wins there (measured
on random systems in three variables: the crossover is near 1000 for Buchberger in Python).
The block system of benchmarks/cases.py in ``dp`` (576 entries): 0.59 ms with the compiled
Buchberger after the first modular run, 1.28 ms with Buchberger in Python, 0.59 ms by modular
F4 alone; cyclic-5 and hcyclic-5 (about 5000 entries) stay faster by modular F4 (1.9 and 2.3 ms
against the compiled Buchberger's 2.5)."""


SMALL_BUCHBERGER = 3000
"""For block and lexicographic orderings ``auto`` first tries Buchberger within a budget, in
Python without the compiled extension: this many terms of reducers used (about 2.5 ms).  The
mechanisms' many small eliminations finish there; larger computations go to FGLM
(zero-dimensional ideals) or the Hilbert-driven algorithm.  Measured on benchmarks/cases.py
(session 13): the four-bar coupler curve finishes within 3000 and the budget's failure costs
2.4 ms on the block (dp(3),dp(2)) and the five-bar projection (5000: 4 ms).  Earlier: 20000
wasted 20-40 ms on katsura-4/5 and cyclic-5 in ``lp`` and katsura-5 in (dp(3),dp(3))."""


ATTEMPT_PRIMES = 4
"""The compiled attempt gives up after this many primes of 50 bits (coefficients of about 95 bits): larger
coefficients are left to the Hilbert-driven algorithm or FGLM."""


COMPILED_BUDGET = 20000
"""The same attempt with the compiled Buchberger over QQ (:func:`.hilbert_compiled.buchberger_qq`):
terms summed in its reductions modulo a prime.  The four-bar coupler curve needs fewer than
5000 (2.8 ms with the lift, the Python attempt 3.2 ms); failing at 20000 costs 1.3 ms on the
block (dp(3),dp(2)) and the five-bar projection.  Over Z/p there is no attempt: the compiled
Hilbert-driven algorithm is faster even on the four-bar curve (0.8 against 2.5 ms)."""


HOMOGENEOUS_BUDGET = 5000
"""The ``dp`` basis of the homogenized generators (the Hilbert series of the Hilbert-driven
algorithms) by the compiled Buchberger within this many terms summed modulo the first prime,
past them by ``auto`` (modular F4 over QQ): the block (dp(3),dp(2)) of benchmarks/cases.py needs
a few thousand (0.1 ms a prime, modular F4 0.4 ms more), the five-bar projection 69000 (two
primes of 3.5 ms against modular F4's 4.4 ms in all; session 14)."""


F4_BUDGET = 4_000_000
"""Over Z/p, ``auto`` computes a positive-dimensional ideal's basis for a lexicographic ordering by
F4 on that ordering while its matrices stay within this many entries and their dense reduction
within 1250 times as many operations (about a second; :data:`.f4.DENSE_PER_ENTRY`), then by the
Hilbert-driven algorithm.  F4 took Singular's rcyclic-13 in lp (13 variables, 200k
entries) in 0.1 s where the Hilbert-driven Buchberger took more than 30 s; on zero-dimensional
ideals FGLM goes first (F4 in lp needed minutes for katsura-5).  Block orderings stay with the
Hilbert-driven algorithm (faster on benchmarks/cases.py's elimination)."""


FGLM_STAIRS = 100
"""Over QQ, a zero-dimensional ideal with at least this many standard monomials gets its basis
for a block ordering by the Hilbert-driven F4 (:func:`.hilbert_driven.hilbert_f4`) instead of
FGLM, whose exact linear algebra grows with the cube of that number.  Measured on
benchmarks/cases.py (session 10, alternating, load ~8): cyclic-6 in (dp(3),dp(3)), 156
monomials, 200-240 ms against FGLM's 310-360; katsura-6 in (dp(3),dp(4)), 64 monomials,
FGLM 193-199 ms against 201-225; katsura-5 (32) 42-48 against 48-52.  Lex orderings stay with
FGLM (the Hilbert-driven F4 took 2 s on katsura-5 in lp, FGLM 50 ms), and over Z/p FGLM
was as fast or faster on all three."""


def field_kind(field: Field) -> str | None:
    """``"QQ"``, ``"Z/p"``, or None for other fields (rational functions in parameters)."""
    if isinstance(field, RationalField):
        return "QQ"
    if isinstance(field, PrimeField):
        return "Z/p"
    return None


def ordering_kind(ring: PolyRing) -> str:
    """``"global"``, or ``"local"`` for every other ordering (local or mixed)."""
    return "global" if ring.order.is_global else "local"


@dataclass(frozen=True)
class Engine:
    """A standard-basis algorithm and the rings it accepts (see the module docstring)."""

    name: str
    run: Run
    summary: str
    orderings: frozenset[str]
    fields: frozenset[str] | None
    returns_reduced: bool = False
    zero_dimensional: bool = False

    def refusal(self, ring: PolyRing) -> str | None:
        """Why the engine does not accept ``ring``; None when it does."""
        if ordering_kind(ring) not in self.orderings:
            wanted = "a global" if self.orderings == {"global"} else "a local or mixed"
            return f"the engine '{self.name}' needs {wanted} ordering"
        if self.fields is not None and field_kind(ring.field) not in self.fields:
            return (f"the engine '{self.name}' needs coefficients in {' or '.join(sorted(self.fields))}, "
                    f"not {ring.field!r}")
        return None


ENGINES: dict[str, Engine] = {}
"""The registered engines by name (see :func:`register`)."""


def register(name: str, run: Run, summary: str, *, orderings: Sequence[str] = ("global",),
             fields: Sequence[str] | None = None, returns_reduced: bool = False,
             zero_dimensional: bool = False) -> Engine:
    """Register (or replace) the engine ``name``: ``run(gens, ring)`` as in the module docstring,
    a one-line ``summary``, the kinds of ``orderings`` (``"global"``, ``"local"``) and ``fields``
    (``"QQ"``, ``"Z/p"``; None: every field) it accepts; ``zero_dimensional``: it raises
    :class:`~.fglm.NotZeroDimensional` for other ideals (an :class:`~.errors.EngineError` when
    the call names it; as the default engine it leaves them to ``auto``)."""
    if name == AUTO:
        raise EngineError(f"'{AUTO}' names the default policy, not an engine")
    unknown = set(orderings) - {"global", "local"} | set(fields or ()) - {"QQ", "Z/p"}
    if unknown:
        raise EngineError(f"unknown capabilities for the engine '{name}': {', '.join(sorted(unknown))}")
    engine = Engine(name, run, summary, frozenset(orderings), None if fields is None else frozenset(fields),
                    returns_reduced, zero_dimensional)
    ENGINES[name] = engine
    clear_cache()  # bases cached under a replaced engine's name
    return engine


def list_engines() -> list[tuple[str, str]]:
    """``(name, one-line description)`` of ``"auto"`` and every registered engine."""
    return [(AUTO, AUTO_SUMMARY)] + [(e.name, e.summary) for e in ENGINES.values()]


def suitable_engines(ring: PolyRing) -> list[str]:
    """The names usable for ``ring``: ``"auto"`` and the engines accepting it."""
    return [AUTO] + [e.name for e in ENGINES.values() if e.refusal(ring) is None]


def check_engine(name: str, ring: PolyRing | None = None) -> None:
    """Raise :class:`~.errors.EngineError` unless ``name`` is ``"auto"`` or a registered engine
    that accepts ``ring`` (when given)."""
    if name == AUTO:
        return
    engine = ENGINES.get(name)
    if engine is None:
        raise EngineError(f"unknown engine '{name}' (known: {', '.join(n for n, _ in list_engines())})")
    why = engine.refusal(ring) if ring is not None else None
    if why:
        raise EngineError(f"{why} (engines for this ring: {', '.join(suitable_engines(ring))})")


_DEFAULT: ContextVar[str] = ContextVar("mech_kernel_engine", default=AUTO)


def default_engine() -> str:
    """The engine used when a call names none (``"auto"`` unless :func:`using_engine` is active)."""
    return _DEFAULT.get()


@contextmanager
def using_engine(name: str) -> Iterator[None]:
    """Within the ``with`` block, ``name`` is the default engine (for the rings it accepts)."""
    check_engine(name)
    token = _DEFAULT.set(name)
    try:
        yield
    finally:
        _DEFAULT.reset(token)


def _resolve(ring: PolyRing, engine: str | None) -> str:
    """The engine to run: the one named (checked), else the default if it accepts ``ring``."""
    if engine is not None:
        check_engine(engine, ring)
        return engine
    name = _DEFAULT.get()
    chosen = ENGINES.get(name)
    return name if chosen is not None and chosen.refusal(ring) is None else AUTO


def standard_basis(gens: Sequence[Poly], ring: PolyRing | None = None, engine: str | None = None) -> list[Poly]:
    """A standard basis of the ideal generated by ``gens`` in ``K[x]_>`` for the ring's ordering.

    Global orderings: the reduced Gröbner basis, sorted by increasing leading monomial.
    Otherwise a minimal standard basis, monic, with reduced leading terms but unreduced tails
    (tail reduction need not terminate for local orderings), sorted from the largest leading
    monomial down as Singular's ``std`` prints it.  ``[1]`` for the unit ideal (the whole ring
    ``K[x]_>``), ``[]`` for the zero ideal.  ``engine``: ``"auto"`` or a registered name (see
    :func:`list_engines`); None: the default (:func:`using_engine`)."""
    ring = ring or (gens[0].ring if gens else None)
    if ring is None:
        return []
    name = _resolve(ring, engine)
    gens = [g for g in gens if not g.is_zero()]
    if not gens:
        return []
    if not ring.order.is_global:
        return _compute(gens, ring, name, engine is not None)
    key = _key(gens, ring, name)
    out = _CACHE.get(key)
    if out is None:
        out = _compute(gens, ring, name, engine is not None)
        _remember(key, out)
    else:
        _CACHE.move_to_end(key)
    return list(out)


def cached_standard_basis(gens: Sequence[Poly], ring: PolyRing, engine: str | None = None) -> list[Poly] | None:
    """The basis :func:`standard_basis` would return for a global ordering, if it is known
    already; else None."""
    out = _CACHE.get(_key(gens, ring, _resolve(ring, engine)))
    return None if out is None else list(out)


def clear_cache() -> None:
    """Forget the recent bases (benchmarks time computations, not look-ups)."""
    _CACHE.clear()


def _key(gens: Sequence[Poly], ring: PolyRing, name: str) -> tuple:
    return ring, name, frozenset(g for g in gens if not g.is_zero())


def _remember(key: tuple, basis: list[Poly]) -> None:
    _CACHE[key] = basis
    if len(_CACHE) > _CACHE_SIZE:
        _CACHE.popitem(last=False)


_CACHE: OrderedDict[tuple, list[Poly]] = OrderedDict()
_CACHE_SIZE = 256


def _compute(gens: list[Poly], ring: PolyRing, name: str, named: bool = True) -> list[Poly]:
    """The basis by the engine ``name`` (with the cycle collector paused); a default engine
    (not ``named`` in the call) that needs a zero-dimensional ideal leaves the others to
    ``auto``."""
    with paused():
        return _compute_basis(gens, ring, name, named)


def _compute_basis(gens: list[Poly], ring: PolyRing, name: str, named: bool) -> list[Poly]:
    if any(g.is_constant() for g in gens):
        return [ring.one()]
    if name == AUTO:
        return _auto_global(gens, ring) if ring.order.is_global else _auto_local(gens, ring)
    engine = ENGINES[name]
    try:
        return _finish(engine.run(gens, ring), ring, engine.returns_reduced)
    except NotZeroDimensional:
        if not engine.zero_dimensional:
            raise
        if named:
            raise EngineError(f"the engine '{name}' needs a zero-dimensional ideal") from None
        return _compute(gens, ring, AUTO)


def _auto_global(gens: list[Poly], ring: PolyRing) -> list[Poly]:
    kind = field_kind(ring.field)
    if ring.order.is_graded:
        if kind == "Z/p":
            return _finish(f4_modp(gens, ring), ring, True)
        if kind == "QQ":
            try:
                return _finish(f4_qq(gens, ring, small_work=SMALL_WORK), ring, True)
            except SmallSystem:
                return _finish(_buchberger_compiled(gens, ring), ring, True)
            except ModularFailure:
                pass
    elif kind is not None:
        dp = _dp_ring(ring)
        lex = all(b.kind == "lp" for b in ring.order.blocks)
        basis = cached_standard_basis([Poly(dp, g.terms) for g in gens], dp, AUTO)
        # the dp basis first (FGLM without Buchberger's attempt) where it is cheap or likely to be
        # needed: fewer generators than variables make the ideal positive-dimensional (Krull)
        first = lex or kind == "Z/p" or len(gens) >= ring.nvars
        if basis is None and first:
            basis = _degree_basis(gens, ring)
        if basis is None or first and not _zero_dimensional(basis):
            try:
                return _attempt(gens, ring)
            except TooLong:
                # positive-dimensional ideals need the dp basis of the homogenized generators (the
                # Hilbert series), which tells the dimension too: the ideal's own dp basis is
                # computed only for FGLM
                if basis is None and _finite_quotient(degree_leads(gens, ring, _dp_homogeneous), ring.nvars):
                    basis = _degree_basis(gens, ring)
        try:
            if basis is None:
                raise NotZeroDimensional("known from the homogenized ideal")
            if kind == "QQ" and not lex and len(staircase([b.lm() for b in basis], ring.nvars)) >= FGLM_STAIRS:
                return _finish(hilbert_f4(gens, ring, _dp_auto), ring, False)
            return _finish(_convert(basis, ring), ring, True)
        except NotZeroDimensional:
            if kind == "Z/p" and lex:
                try:
                    return _finish(f4_modp(gens, ring, F4_BUDGET), ring, True)
                except TooLong:
                    pass
            return _finish(_hilbert_reduced(gens, ring), ring, True)
        except ModularFailure:
            pass
    return _finish(buchberger(gens, ring), ring, False)


def _attempt(gens: list[Poly], ring: PolyRing) -> list[Poly]:
    """Buchberger's algorithm within a budget (:class:`~.buchberger.TooLong` past it): compiled
    and lifted over QQ (:data:`COMPILED_BUDGET`), none over Z/p where the compiled Hilbert-driven
    algorithm beats it even on small systems, else in Python (:data:`SMALL_BUCHBERGER`)."""
    if compiled_hilbert(ring):
        if isinstance(ring.field, PrimeField):
            raise TooLong
        try:
            return _finish(buchberger_qq(gens, ring, COMPILED_BUDGET, ATTEMPT_PRIMES), ring, True)
        except ModularFailure:
            raise TooLong from None
    return _finish(buchberger(gens, ring, SMALL_BUCHBERGER), ring, False)


def _zero_dimensional(basis: list[Poly]) -> bool:
    """Whether the ideal with this Gröbner basis is zero-dimensional (a pure power of every
    variable among the leading monomials)."""
    n = basis[0].ring.nvars if basis else 0
    pure = {next(i for i, a in enumerate(e) if a) for e in (b.lm() for b in basis) if sum(1 for a in e if a) == 1}
    return len(pure) == n


def _finite_quotient(leads: list[Exp], nvars: int) -> bool:
    """Whether an ideal whose leading ideal these monomials generate is zero-dimensional or the
    unit ideal (FGLM's cases)."""
    if (0,) * nvars in leads:
        return True
    pure = {next(i for i, a in enumerate(e) if a) for e in leads if sum(1 for a in e if a) == 1}
    return len(pure) == nvars


def _dp_ring(ring: PolyRing) -> PolyRing:
    return PolyRing(ring.field, ring.names, MonomialOrder.simple("dp", ring.nvars))


def _degree_basis(gens: Sequence[Poly], ring: PolyRing) -> list[Poly]:
    """The reduced basis of the ideal for ``dp`` (by ``auto``, kept in the cache)."""
    dp = _dp_ring(ring)
    return standard_basis([Poly(dp, g.terms) for g in gens], dp, AUTO)


def _convert(basis: list[Poly], ring: PolyRing) -> list[Terms]:
    """FGLM from a ``dp`` basis to the ring's ordering."""
    source = basis[0].ring.order if basis else MonomialOrder.simple("dp", ring.nvars)
    terms, leads = [b.terms for b in basis], [b.lm() for b in basis]
    if isinstance(ring.field, PrimeField):
        return fglm_zp(terms, source, ring.order, ring.field.characteristic, leads)
    return fglm_qq(terms, source, ring.order, leads)


def _dp_auto(gens: list[Poly], ring: PolyRing) -> list[Poly]:
    return standard_basis(gens, ring, AUTO)


def _dp_homogeneous(gens: list[Poly], ring: PolyRing) -> list[Poly]:
    """The ``dp`` basis of homogenized generators the Hilbert-driven algorithms start from: by
    the compiled Buchberger within :data:`HOMOGENEOUS_BUDGET` where it is built, else (or past
    the budget) by ``auto``; kept in the cache as ``auto``'s basis (the reduced basis is one)."""
    known = cached_standard_basis(gens, ring, AUTO)
    if known is not None or not compiled_hilbert(ring):
        return known or standard_basis(gens, ring, AUTO)
    try:
        if isinstance(ring.field, PrimeField):
            terms = buchberger_modp(gens, ring, HOMOGENEOUS_BUDGET)
        else:
            terms = buchberger_qq(gens, ring, HOMOGENEOUS_BUDGET)
    except (TooLong, ModularFailure):
        return standard_basis(gens, ring, AUTO)
    basis = _finish(terms, ring, True)
    _remember(_key(gens, ring, AUTO), basis)
    return basis


def _buchberger_compiled(gens: list[Poly], ring: PolyRing) -> list[Terms]:
    """The reduced basis by Buchberger's algorithm in C modulo p, over QQ lifted from primes
    (:mod:`.hilbert_compiled`), else (or when the lift fails) in Python."""
    if compiled_hilbert(ring):
        try:
            if isinstance(ring.field, PrimeField):
                return buchberger_modp(gens, ring)
            return buchberger_qq(gens, ring)
        except ModularFailure:
            pass
    return _lead_first(_finish(buchberger(gens, ring), ring, False))


def _lead_first(basis: list[Poly]) -> list[Terms]:
    return [{p.lm(): p.terms[p.lm()], **p.terms} for p in basis]


def _fglm(gens: list[Poly], ring: PolyRing) -> list[Terms]:
    """The engine ``fglm``: a ``dp`` basis by ``auto``, converted by FGLM."""
    return _convert(_degree_basis(gens, ring), ring)


def _hilbert_reduced(gens: list[Poly], ring: PolyRing) -> list[Terms]:
    """The reduced basis by the Hilbert-driven algorithm: compiled modulo p, over QQ lifted
    from primes (:mod:`.hilbert_compiled`), else (or when the lift fails) in Python."""
    if compiled_hilbert(ring):
        try:
            if isinstance(ring.field, PrimeField):
                return hilbert_modp(gens, ring, _dp_homogeneous)
            return hilbert_qq(gens, ring, _dp_homogeneous)
        except ModularFailure:
            pass
    return _lead_first(_finish(hilbert_driven(gens, ring, _dp_homogeneous), ring, False))


def _auto_local(gens: list[Poly], ring: PolyRing) -> list[Poly]:
    basis = auto_local(gens, ring, lambda hgens, hring: standard_basis(hgens, hring, AUTO))
    return finished(basis, ring, minimal=True)  # the policy's routes (Mora, Lazard) give minimal bases


def _finish(basis: list[Terms], ring: PolyRing, reduced: bool) -> list[Poly]:
    """An engine's basis as the entry point returns it (see :func:`standard_basis`); a global
    basis not ``reduced`` is reduced by F4's back substitution over Z/p, by flint over QQ (from
    :data:`.flint_reduce.FLINT_TERMS` terms), else by Buchberger's reduction."""
    if ring.order.is_global:
        if not reduced:
            if isinstance(ring.field, PrimeField):
                reduce = reduce_modp
            elif isinstance(ring.field, RationalField) and sum(map(len, basis)) >= FLINT_TERMS:
                reduce = reduce_basis_qq
            else:
                reduce = reduce_basis
            return [Poly(ring, b) for b in reduce(basis, ring)]
        out = []
        for b in basis:
            p = Poly(ring, b)
            p._lm = next(iter(b))
            out.append(p)
        return out
    return finished(basis, ring)


def _lazard(gens: list[Poly], ring: PolyRing) -> list[Terms]:
    """Lazard's method, its global basis by ``auto`` (whatever the default engine)."""
    return lazard(gens, ring, lambda hgens, hring: standard_basis(hgens, hring, AUTO))


register("buchberger", buchberger,
         "Buchberger's algorithm (Gebauer–Möller criteria, sugar strategy) on packed monomials; every field")
register("f4", f4_modp, "Faugère's F4 modulo p: symbolic preprocessing, row reduction on packed vectors",
         fields=("Z/p",), returns_reduced=True)
register("modular", f4_qq, "F4 modulo primes with a trace, lifted to QQ by rational reconstruction, verified",
         fields=("QQ",), returns_reduced=True)
register("fglm", _fglm, "a dp basis by auto, converted by FGLM to the ring's ordering (zero-dimensional ideals)",
         fields=("QQ", "Z/p"), returns_reduced=True, zero_dimensional=True)
register("hilbert", lambda gens, ring: hilbert_driven(gens, ring, _dp_auto),
         "Hilbert-driven Buchberger: homogenize, Hilbert series from a dp basis, drop pairs once it is reached")
register("buchberger-compiled", _buchberger_compiled,
         "Buchberger's algorithm in C modulo p (normal strategy), over QQ lifted from primes and verified "
         "(Python without a compiler)", returns_reduced=True)
register("hilbert-compiled", _hilbert_reduced,
         "Hilbert-driven Buchberger in C modulo p, over QQ lifted from primes and verified (Python without a compiler)",
         returns_reduced=True)
register("hilbert-f4", lambda gens, ring: hilbert_f4(gens, ring, _dp_auto),
         "Hilbert-driven F4: homogenize, Hilbert series from a dp basis, F4 (modular over QQ) until it is reached",
         fields=("QQ", "Z/p"))
register("mora", mora, "Mora's normal form with ecart and sugar, the highest corner for ds (Singular's std for local orderings)",
         orderings=("global", "local"))
register("lazard", _lazard, "Lazard's method: homogenize, Gröbner basis by auto, dehomogenize",
         orderings=("global", "local"))
