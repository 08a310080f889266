"""Procedures of Singular's algebra.lib on maps of affine algebras: ``alg_kernel``, ``is_injective``,
``is_surjective``, ``is_bijective``.  As algebra.lib: in the ring of x(1..n) (the basering's
variables) and y(1..m) (the source's) ordered (dp(n), dp(m)), a standard basis of the f_i - y(i)
(f_i the images) and of the basering's quotient ideal; its elements free of x generate the kernel,
and phi is onto when every x(i) reduces to a polynomial in the y alone.  The orderings of the
rings do not matter (algebra.lib computes in dp); a quotient source ring R/I: the kernel is taken
modulo I."""
from __future__ import annotations

from typing import Any

from ..dsl.printing import poly_str, set_short
from ..dsl.qrings import quotient_of
from ..dsl.registry import command
from ..dsl.values import Ideal, List, Map, OrderBlock, Ring
from ..kernel import MonomialOrder, Poly, PolyRing
from .algebra_subrings import dependent_comment, _relation_ring, _relations, _x_free
from .ring_lib import export
from .sing_lib import comment
from .standard import _nf, normalize, standard_basis

LIB = "algebra.lib"


def _images(ctx, phi: Map | Ideal, m: int) -> list[Poly]:
    ring = ctx.basering().poly
    given = list(phi.images) if isinstance(phi, Map) else list(phi.gens)
    given = [Poly(ring, g.terms) for g in given]
    return (given + [ring.zero()] * m)[:m]


def _graph(ctx, images: list[Poly]) -> tuple[Ring, list[Poly]]:
    """The ring x(1..n), y(1..m) with (dp(n), dp(m)) and a standard basis of the graph of the map."""
    base = ctx.basering()
    n, m = len(base.names), len(images)
    R = _relation_ring(base, n, list(range(1, m + 1)), [OrderBlock("dp", n), OrderBlock("dp", m)])
    return R, standard_basis(Ideal(R.poly, _relations(base, images, R.poly, n)))


def _kernel(ctx, images: list[Poly]) -> tuple[Ring, list[Poly]]:
    """The ring x(1..n), y(1..m) in dp and the generators of the kernel of y(i) -> images[i]."""
    base = ctx.basering()
    n, m = len(base.names), len(images)
    R3, basis = _graph(ctx, images)
    R2 = _relation_ring(base, n, list(range(1, m + 1)), [OrderBlock("dp", n + m)])
    return R2, [normalize(Poly(R2.poly, g.terms)) for g in basis if _x_free(g, n)]


def _in_source(ker: list[Poly], n: int, pr: Ring) -> list[Poly]:
    """The kernel's generators (in y(1..m)) as polynomials of the source ring pr."""
    return [Poly(pr.poly, {e[n:]: c for e, c in g.terms.items()}) for g in ker]


def _zero_mod_source(ker: list[Poly], n: int, pr: Ring) -> bool:
    """Whether the kernel lies in the quotient ideal of the source ring (always, when it is empty)."""
    polys = [g for g in _in_source(ker, n, pr) if not g.is_zero()]
    if not polys:
        return True
    quotient = quotient_of(pr.poly)
    if quotient is None:
        return False
    basis = [Poly(pr.poly, g.terms) for g in quotient.basis]
    basis.sort(key=lambda g: pr.poly.order.key(g.lm()))
    return all(_nf(g, basis).is_zero() for g in polys)


def _onto(ctx, images: list[Poly]) -> int:
    n = len(ctx.basering().names)
    R, basis = _graph(ctx, images)
    big = R.poly
    basis.sort(key=lambda g: big.order.key(g.lm()))
    for i in range(n):
        check = _nf(big.gen(i), basis)
        if not check.is_zero() and any(check.lm()[:n]):
            return 0
    return 1


@command("alg_kernel", lib=LIB)
def alg_kernel(ctx, phi: Map, pr: Ring, *opts: Any) -> str:
    """alg_kernel(phi, pr[, s][, c]): the kernel of the map phi from the ring pr to the basering, as a
    string in pr's variables (long form, as algebra.lib returns it); with a string s, also the
    ideal of that name in pr.

    Example:
      LIB "algebra.lib";
      ring A = 0,(x,y),dp;
      ring B = 0,(s,t),dp;
      map psi = A, s2, s3;
      alg_kernel(psi, A);
      → x^3-y^2
    """
    m = len(pr.names)
    R2, ker = _kernel(ctx, _images(ctx, phi, m))
    dependent_comment(ctx, depth=1)  # algebra.lib computes the kernel by algDependent
    n = len(R2.names) - m
    polys = _in_source(ker, n, pr)
    dp = PolyRing(pr.poly.field, pr.poly.names, MonomialOrder.simple("dp", m))  # algebra.lib prints from dp
    set_short(dp, False)
    text = ",".join(poly_str(Poly(dp, g.terms)) for g in polys) if polys else "0"
    name = next((o for o in opts if isinstance(o, str)), None)
    if name is not None:
        export(pr, name, "ideal", Ideal(pr.poly, polys or [pr.poly.zero()]))
    return text


@command("is_injective", lib=LIB)
def is_injective(ctx, phi: Map, pr: Ring, *opts: Any) -> Any:
    """is_injective(phi, pr[, s]): 1 if the map phi from the ring pr to the basering is injective,
    else 0; with a string s, the list of that answer and a ring with the ideal ``ker`` of phi.

    Example:
      LIB "algebra.lib";
      ring A = 0,(x,y),dp;
      ring B = 0,(s,t),dp;
      map psi = A, s2, s3;
      is_injective(psi, A);
      → 0
    """
    m = len(pr.names)
    R2, ker = _kernel(ctx, _images(ctx, phi, m))
    dependent_comment(ctx, depth=1)
    injective = int(_zero_mod_source(ker, len(R2.names) - m, pr))
    if not any(isinstance(o, str) for o in opts):
        return injective
    export(R2, "ker", "ideal", Ideal(R2.poly, ker or [R2.poly.zero()]))
    comment(ctx, "\n// The 2nd element of the list is a ring with variables x(1),...,x(n),\n"
            "// y(1),...,y(m) if the basering has n variables and the map is\n// F[1],...,F[m].\n"
            "// It contains the ideal ker, the kernel of the given map y(i) --> F[i].\n"
            "// To access to the ring and see ker you must give the ring a name,\n// e.g.:\n"
            "     def S = l[2]; setring S; ker;\n        ")
    return List([injective, R2])


@command("is_surjective", lib=LIB)
def is_surjective(ctx, phi: Map, pr: Ring | None = None) -> int:
    """is_surjective(phi): 1 if the map phi to the basering is surjective (every variable of the
    basering is a polynomial in the images, modulo the basering's quotient ideal), else 0.

    Example:
      LIB "algebra.lib";
      ring A = 0,(x,y),dp;
      ring B = 0,(s,t),dp;
      map psi = A, s2, s3;
      is_surjective(psi);
      → 0
    """
    images = list(phi.images) if pr is None else _images(ctx, phi, len(pr.names))
    return _onto(ctx, [Poly(ctx.basering().poly, g.terms) for g in images])


@command("is_bijective", lib=LIB)
def is_bijective(ctx, phi: Map | Ideal, pr: Ring) -> int:
    """is_bijective(phi, pr): 1 if the map phi (or the map given by the ideal of images) from the ring
    pr to the basering is bijective, else 0 (with algebra.lib's comment which property fails).

    Example:
      LIB "algebra.lib";
      ring A = 0,(x,y),dp;
      ring B = 0,(s),dp;
      map psi = A, s, s2;
      is_bijective(psi, A);
      → // map not injective
      → 0
    """
    m = len(pr.names)
    images = _images(ctx, phi, m)
    R2, ker = _kernel(ctx, images)
    if not _zero_mod_source(ker, len(R2.names) - m, pr):
        comment(ctx, "// map not injective")
        return 0
    if not _onto(ctx, images):
        comment(ctx, "// map injective, but not surjective")
        return 0
    return 1

