"""Standard bases and normal forms: ``std``, ``groebner``, Singular's other Groebner commands
(``slimgb``, ``stdfglm``, ``stdhilb``, ``modStd``: each through its engine), ``reduce``, ``NF``,
``dim``, and the helpers
the other command modules share: :func:`normalize` (a basis element as Singular's std returns it) and
:func:`standard_basis` (the global/local dispatch)."""
from __future__ import annotations

from math import gcd
from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.noether import active_noether
from ..dsl.qrings import quotient_of, with_quotient
from ..dsl.registry import command
from ..dsl.values import Ideal, Matrix
from ..dsl.convert_modules import to_module
from ..dsl.values_modules import Module
from ..kernel import Poly
from ..kernel.dimension import krull_dim
from ..kernel.engines import AUTO, ENGINES, check_engine, list_engines
from ..kernel.errors import EngineError
from ..kernel.engines import standard_basis as kernel_standard_basis
from ..kernel.groebner import normal_form
from ..kernel.local_noether import noether_basis, truncate


def normalize(p: Poly) -> Poly:
    """A basis element as Singular's std returns it: over QQ (and QQ(a,..)) the primitive multiple
    without denominators and with positive leading coefficient; over Z/p monic (Z/p(a,..): the
    leading coefficient's leading term 1)."""
    if p.is_zero():
        return p
    field = p.ring.field
    if getattr(field, "params", ()):
        return _normalize_params(p)
    if field.characteristic:
        return p.monic()
    import flint
    den = 1
    for c in p.terms.values():
        q = int(c.q)
        den = den * q // gcd(den, q)
    g = 0
    for c in p.terms.values():
        g = gcd(g, int(c.p) * (den // int(c.q)))
    scale = flint.fmpq(den, g)
    return p * (-scale if p.lc() < 0 else scale)


def primitive_numerators(p: Poly) -> dict:
    """Over a field of rational functions in parameters: p's coefficients times the lcm of their
    denominators, divided by the gcd of the numerators (polynomials in the parameters), by monomial."""
    lcm = None
    for c in p.terms.values():
        lcm = c.den if lcm is None else lcm * c.den // lcm.gcd(c.den)
    nums = {e: c.num * (lcm // c.den) for e, c in p.terms.items()}
    content = None
    for n in nums.values():
        content = n if content is None else content.gcd(n)
    return {e: n // content for e, n in nums.items()}


def _normalize_params(p: Poly) -> Poly:
    field = p.ring.field
    nums = primitive_numerators(p)
    lead = int(nums[p.lm()].leading_coefficient())
    if field.characteristic:
        inv = pow(lead, -1, field.characteristic)
        nums = {e: n * inv for e, n in nums.items()}
    elif lead < 0:
        nums = {e: -n for e, n in nums.items()}
    return Poly(p.ring, {e: field.from_polys(n) for e, n in nums.items()})


def standard_basis(ideal: Ideal) -> list[Poly]:
    """A standard basis of ``ideal`` (reduced for global orderings), normalized as Singular's std;
    in a qring R/Q the elements of a standard basis of ideal + Q outside Q's leading ideal."""
    q = quotient_of(ideal.ring)
    if q is not None:
        return [normalize(p) for p in q.std(ideal.nonzero())]
    corner = active_noether(ideal.ring)
    if corner is not None:
        return [normalize(p) for p in noether_basis(ideal.nonzero(), ideal.ring, corner,
                                                    lambda gens: kernel_standard_basis(gens, ideal.ring))]
    return [normalize(p) for p in kernel_standard_basis(ideal.nonzero(), ideal.ring)]


def _engine_list() -> str:
    return "\n".join(f"      {name:<11}{summary}" for name, summary in list_engines())


def engine(ctx, name: str = "") -> Any:
    """engine(): the name of the session's Groebner engine; engine("NAME"): use NAME from now on for
    std and every command built on it (elimination, decomposition, ...), wherever it accepts the
    ring (elsewhere "auto" chooses).  The same as mech --engine NAME and Session(engine="NAME").
    The engines:
{engines}

    Example:
      engine();
      → auto
      engine("buchberger");
      ring r = 0,(x,y),dp;
      std(ideal(x2-y, xy-1));
      → _[1]=y2-x
      → _[2]=xy-1
      → _[3]=x2-y
      engine("auto");
    """
    if not name:
        return ctx.settings.get("engine", AUTO)
    check_engine(name)
    ctx.settings["engine"] = name
    return None


engine.__doc__ = engine.__doc__.replace("{engines}", _engine_list())
command("engine")(engine)


@command("std")
def std(I: Ideal) -> Ideal:
    """std(I): a standard basis of the ideal I for the ring's ordering (for a global ordering the
    reduced Groebner basis, each element a primitive integer polynomial over QQ, monic over Z/p),
    sorted by increasing leading monomial.

    Example:
      ring r = 0,(x,y,z),dp;
      ideal I = x2-y, xy-z;
      std(I);
      → _[1]=y2-xz
      → _[2]=xy-z
      → _[3]=x2-y
    """
    return Ideal(I.ring, standard_basis(I), is_std=True)


@command("groebner")
def groebner(I: Ideal) -> Ideal:
    """groebner(I): a Groebner basis of I (the same as std(I)).

    Example:
      ring r = 0,(x,y),lp;
      groebner(ideal(x2+y2-1, x-y));
      → _[1]=2y2-1
      → _[2]=x-y
    """
    return Ideal(I.ring, standard_basis(I), is_std=True)


def _global(name: str, I: Ideal) -> None:
    if not I.ring.order.is_global:
        raise MechRuntimeError(f"{name} needs a global ordering (dp, lp, ...), not a local one")


def _by_engine(name: str, I: Ideal, engine: str) -> list[Poly]:
    """The reduced basis by ``engine`` where it accepts the ring, else by ``auto``."""
    _global(name, I)
    ring = I.ring
    use = engine if ENGINES[engine].refusal(ring) is None else AUTO
    return kernel_standard_basis(I.nonzero(), ring, use)


@command("slimgb")
def slimgb(I: Ideal) -> Ideal:
    """slimgb(I): a Groebner basis of I for a global ordering.  mech returns the reduced basis, as
    std does (Singular's slimgb may leave tails unreduced and list the elements in another
    order).

    Example:
      ring r = 32003,(x,y),dp;
      slimgb(ideal(x2+y2-1, x-y));
      → _[1]=x-y
      → _[2]=y2+16001
    """
    _global("slimgb", I)
    return Ideal(I.ring, standard_basis(I), is_std=True)


@command("stdfglm")
def stdfglm(I: Ideal) -> Ideal:
    """stdfglm(I): the reduced Groebner basis of a zero-dimensional ideal I, computed for dp and
    converted to the ring's ordering by the FGLM algorithm (the engine "fglm"; over other fields
    than QQ and Z/p as std).

    Example:
      ring r = 0,(x,y,z),lp;
      stdfglm(ideal(x2+y2+z2-1, x-y2, yz-x));
      → _[1]=z6+z4-3z2+1
      → _[2]=2y+z5+2z3-3z
      → _[3]=2x+z4-1
    """
    try:
        basis = _by_engine("stdfglm", I, "fglm")
    except EngineError:
        raise MechRuntimeError("stdfglm: the ideal has to be zero-dimensional") from None
    return Ideal(I.ring, [normalize(p) for p in basis], is_std=True)


@command("stdhilb")
def stdhilb(I: Ideal) -> Ideal:
    """stdhilb(I): a Groebner basis of I by the Hilbert-driven algorithm (the engine "hilbert"):
    the ideal is homogenized, its Hilbert series read off a dp basis, and the basis for the
    ring's ordering computed degree by degree, stopping each degree once the series says it is
    complete.  mech returns the reduced basis.

    Example:
      ring r = 0,(x,y,z),lp;
      stdhilb(ideal(x2+y, xy-z));
      → _[1]=y3+z2
      → _[2]=xz+y2
      → _[3]=xy-z
      → _[4]=x2+y
    """
    return Ideal(I.ring, [normalize(p) for p in _by_engine("stdhilb", I, "hilbert")], is_std=True)


@command("modStd", lib="modstd.lib")
def modStd(I: Ideal) -> Ideal:
    """modStd(I): the reduced Groebner basis of I over QQ by modular methods (the engine
    "modular": F4 modulo primes, lifted by rational reconstruction and verified), monic as
    Singular's modStd returns it; over Z/p as std.

    Example:
      LIB "modstd.lib";
      ring r = 0,(x,y,z),dp;
      modStd(ideal(3x2-y, 2xy-z, z3-x));
      → _[1]=y2-3/2xz
      → _[2]=xy-1/2z
      → _[3]=x2-1/3y
      → _[4]=z3-x
    """
    return Ideal(I.ring, _by_engine("modStd", I, "modular"), is_std=True)


def _nf(f: Poly, basis: list[Poly], bad_ecart: bool = False) -> Poly:
    if f.ring.order.is_global:
        return normal_form(f, basis)
    from ..kernel.localnf import weak_normal_form
    h = weak_normal_form(f, basis, bad_ecart)
    corner = active_noether(f.ring)
    return h if corner is None else truncate(h, corner)


def _reduce(ctx: Any, f: Any, I: Ideal, bad_ecart: bool = False) -> Any:
    """reduce(f, I); ``bad_ecart``: Singular's option 2 (local orderings: the tail is reduced also
    by elements of bad ecart)."""
    if len(I.gens) > 1:  # as Singular: an ideal of one generator is a standard basis
        ctx.assume_std(I, 1)
    key = I.ring.order.key
    basis = sorted(with_quotient(I.nonzero(), I.ring), key=lambda g: key(g.lm()))  # from the smallest
    if isinstance(f, Poly):
        return _nf(f, basis, bad_ecart)
    if isinstance(f, Ideal):
        return Ideal(f.ring, [_nf(g, basis, bad_ecart) for g in f.gens])
    return Matrix(f.ring, f.nrows, f.ncols, [_nf(g, basis, bad_ecart) for g in f.entries])


@command("reduce")
def reduce(ctx, f: Poly | Ideal | Matrix, I: Ideal) -> Any:
    """reduce(f, I): the normal form of f (a poly, ideal or matrix) with respect to the standard
    basis I; the remainder is returned as it is (not normalized).

    Example:
      ring r = 0,(x,y),dp;
      ideal G = std(ideal(x2-y, y2-1));
      reduce(x3+y3, G);
      → xy+y
    """
    return _reduce(ctx, f, I)


@command("NF")
def NF(ctx, f: Poly | Ideal | Matrix, I: Ideal) -> Any:
    """NF(f, I): the normal form of f with respect to the standard basis I (the same as reduce).

    Example:
      ring r = 0,(x,y),dp;
      ideal G = std(ideal(x2-y, y2-1));
      NF(x4+xy, G);
      → xy+1
    """
    return _reduce(ctx, f, I)


@command("dim")
def dim(ctx, I: Ideal) -> int:
    """dim(I): the Krull dimension of R/I for a standard basis I (-1 for the unit ideal).

    Example:
      ring r = 0,(x,y,z),dp;
      dim(std(ideal(xy, xz)));
      → 2
    """
    ctx.assume_std(I, 0)
    order = I.ring.order
    if not order.is_global and not order.is_local:
        ctx.warn(f"dim({ctx.argnames[0]}) may be wrong because the mixed monomial ordering")
    lms = [g.lm() for g in with_quotient(I.nonzero(), I.ring)]
    return krull_dim(lms, I.ring.nvars)


@command("std")
def std_row(m: Matrix) -> Matrix | Module:
    """std(m) of a one-row matrix (a module of rank 1: the ideal of its entries), as a one-row matrix."""
    if m.nrows != 1:  # a module: Singular's std(matrix) is the module's standard basis
        from .module_commands import std as std_module
        return std_module(to_module(m, m.ring))
    basis = std(Ideal(m.ring, m.entries))
    return Matrix(m.ring, 1, len(basis.gens), list(basis.gens))
