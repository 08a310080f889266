"""The LocalRings package's legacy functions in the Macaulay2 dialect (``dialect="m2"``), for a
polynomial ring R with a maximal ideal set by ``setMaxIdeal m``: ``R.maxIdeal``, ``R.residueMap``
(R -> R, the variables to their normal forms modulo m), ``localComplement f`` (a complement of the
image of f modulo m: ``id // n`` for ``n`` the transposed syzygies of the transposed residue of f),
``localMingens f`` (``f * localComplement syz f``: generators minimal at m) and ``localsyz f``
(``localMingens syz f``), ``localModulo(f, g)`` (``localMingens`` of the first rows of
``syz(f | g)``), ``localPrune M`` -- the package's definitions; their matrices are solutions Macaulay2 and
mech may choose differently when there are several."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.m2_maps import apply_map
from ..dsl.m2_modules import CyclicModule, FreeModule, Map
from ..dsl.m2_rings import M2Ring, normal
from ..dsl.m2_submodules import Module, as_map, divide, module
from ..dsl.m2_values import RingMap
from ..dsl.registry import command
from ..dsl.values import Ideal, Matrix
from ..kernel import ideals as K
from ..kernel.groebner import normal_form
from .m2_modules import identity, transpose
from .m2_resolutions import syz


@command("setMaxIdeal", dialect="m2")
def set_max_ideal(m: Ideal) -> Ideal:
    """setMaxIdeal m: the maximal ideal of m's ring used by the legacy local functions (m itself)."""
    R = getattr(m.ring, "owner", None)
    if not isinstance(R, M2Ring) or R.quotient is not None:
        raise MechRuntimeError("setMaxIdeal takes an ideal of a polynomial ring")
    basis = K.std(m.nonzero(), ring=m.ring)
    images = tuple(normal(normal_form(m.ring.gen(i), basis)) for i in range(m.ring.nvars))
    R.info["legacy_max"] = (m, RingMap(R, R, images))
    return m


def _residue_map(f: Matrix) -> RingMap:
    R = f.ring.owner
    if "legacy_max" not in R.info:
        raise MechRuntimeError("use setMaxIdeal first")
    return R.info["legacy_max"][1]


@command("localComplement", dialect="m2")
def local_complement(f: Matrix) -> Map:
    """localComplement f: a matrix h with n h = id, n the transposed syzygies of the transpose of f
    modulo the maximal ideal (the columns of f's target that complete f's image there)."""
    n = transpose(syz(transpose(as_map(apply_map(_residue_map(f), as_map(f))))))
    return divide(identity(n.target), n)


@command("localMingens", dialect="m2")
def local_mingens(f: Matrix) -> Matrix:
    """localMingens f: generators of f's image, minimal at the maximal ideal (f localComplement syz f)."""
    s = syz(f)
    if s.ncols == 0:
        return as_map(f)
    return _product(as_map(f), local_complement(s))


def _product(f: Map, g: Map) -> Map:
    """The composition f g of maps."""
    from ..kernel.matrix import Matrix as KernelMatrix
    h = KernelMatrix(f.ring, f.nrows, f.ncols, list(f.entries)) * KernelMatrix(g.ring, g.nrows, g.ncols, list(g.entries))
    return Map(f.target, g.source, h.entries(), f.degree + g.degree)


@command("localModulo", dialect="m2")
def local_modulo(f: Matrix, g: Matrix) -> Matrix:
    """localModulo(f, g): generators, minimal at the maximal ideal, of the elements whose image under
    f lies in the image of g (localMingens of the first rows of syz(f | g))."""
    f, g = as_map(f), as_map(g)
    if f.nrows != g.nrows:
        raise MechRuntimeError("localModulo(f, g) takes maps with the same target")
    s = syz(Map(f.target, FreeModule(f.target.ring, f.source.degrees + g.source.degrees),
                [row for i in range(f.nrows) for row in (*f.entries[i * f.ncols:(i + 1) * f.ncols],
                                                         *g.entries[i * g.ncols:(i + 1) * g.ncols])]))
    top = Map(f.source, s.source, list(s.entries[:f.ncols * s.ncols]))
    return local_mingens(top) if top.ncols else top


@command("localPrune", dialect="m2")
def local_prune(M: Module | CyclicModule) -> Any:
    """localPrune M: M presented minimally at the maximal ideal, the cokernel of
    ``localModulo(p1, p)`` for the presentation p of M (a cokernel's relations, the syzygies of an
    image's generators) and ``p1 = localComplement p`` (a free module when it has no relations)."""
    M = module(M)
    p = syz(M.matrix) if M.kind == "image" else M.matrix  # the syzygies of an image's generators
    p1 = local_complement(p)
    p2 = local_modulo(p1, p)
    return p2.target if p2.ncols == 0 else Module("cokernel", p2)


@command("localsyz", dialect="m2")
def local_syz(f: Matrix) -> Matrix:
    """localsyz f: the syzygies of f, minimal at the maximal ideal (localMingens syz f)."""
    s = syz(f)
    return s if s.ncols == 0 else local_mingens(s)
