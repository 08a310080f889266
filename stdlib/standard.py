"""Standard bases and normal forms: ``std``, ``groebner``, ``reduce``, ``NF``, ``dim``, and the helpers
the other command modules share: :func:`normalize` (a basis element as Singular's std returns it) and
:func:`standard_basis` (the global/local dispatch)."""
from __future__ import annotations

from math import gcd
from typing import Any

from ..dsl.registry import command
from ..dsl.values import Ideal, Matrix
from ..kernel import Poly
from ..kernel.dimension import krull_dim
from ..kernel.engines import AUTO, check_engine, list_engines
from ..kernel.engines import standard_basis as kernel_standard_basis
from ..kernel.groebner import normal_form


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


def _normalize_params(p: Poly) -> Poly:
    field = p.ring.field
    lcm = None
    for c in p.terms.values():
        lcm = c.den if lcm is None else lcm * c.den // lcm.gcd(c.den)
    nums = {e: c.num * (lcm // c.den) for e, c in p.terms.items()}
    content = None
    for n in nums.values():
        content = n if content is None else content.gcd(n)
    nums = {e: n // content for e, n in nums.items()}
    lead = int(nums[p.lm()].leading_coefficient())
    if field.characteristic:
        inv = pow(lead, -1, field.characteristic)
        nums = {e: n * inv for e, n in nums.items()}
    elif lead < 0:
        nums = {e: -n for e, n in nums.items()}
    return Poly(p.ring, {e: field.from_polys(n) for e, n in nums.items()})


def standard_basis(ideal: Ideal) -> list[Poly]:
    """A standard basis of ``ideal`` (reduced for global orderings), normalized as Singular's std."""
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


def _nf(f: Poly, basis: list[Poly]) -> Poly:
    if f.ring.order.is_global:
        return normal_form(f, basis)
    from ..kernel.localnf import weak_normal_form
    return weak_normal_form(f, basis)


def _reduce(ctx: Any, f: Any, I: Ideal) -> Any:
    ctx.assume_std(I, 1)
    key = I.ring.order.key
    basis = sorted(I.nonzero(), key=lambda g: key(g.lm()))  # Singular tries reducers from the smallest
    if isinstance(f, Poly):
        return _nf(f, basis)
    if isinstance(f, Ideal):
        return Ideal(f.ring, [_nf(g, basis) for g in f.gens])
    return Matrix(f.ring, f.nrows, f.ncols, [_nf(g, basis) for g in f.entries])


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
    lms = [g.lm() for g in I.nonzero()]
    return krull_dim(lms, I.ring.nvars)
