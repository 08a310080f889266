"""The affine chart of a variety's linear equations: a reduced ``dp`` basis with elements
``x_j - a_j(free)`` identifies the variety with its image in the free variables (an affine
isomorphism), where the real curve algorithms work with fewer variables."""
from __future__ import annotations

from flint import fmpq

from .coeffs import QQ
from .order import Block, MonomialOrder
from .poly import Poly, PolyRing

Box = list[tuple[fmpq, fmpq]]


class Chart:
    """The affine subspace of the linear elements ``x_j - a_j(free)`` of a reduced ``dp`` basis:
    the curve is given in the free variables by the other generators restricted to it."""

    def __init__(self, gens: list[Poly], basis: list[Poly], ring: PolyRing) -> None:
        n = ring.nvars
        linear = {g.lm().index(1): g.monic() for g in basis if g.total_degree() == 1}
        self.free = [i for i in range(n) if i not in linear]
        self.ring = PolyRing(QQ, [ring.names[i] for i in self.free], MonomialOrder([Block("dp", len(self.free))]))
        xs = self.ring.gens()
        self.maps: list[tuple[fmpq, list[fmpq]]] = []
        images = []
        for i in range(n):
            if i in linear:
                g = linear[i]
                const = -g.coeff_of(ring.zero_exp)
                lin = [-g.coeff_of(tuple(int(k == j) for k in range(n))) for j in self.free]
            else:
                const, lin = fmpq(0), [fmpq(int(j == i)) for j in self.free]
            self.maps.append((const, lin))
            images.append(sum((x * c for x, c in zip(xs, lin) if c != 0), self.ring.const(const)))
        self.gens = [h for h in (g.compose(images, self.ring) for g in gens) if not h.is_zero()]

    def directions(self) -> list[list[fmpq]]:
        """The original coordinates as linear forms in the free variables (distinct, nonzero)."""
        out: list[list[fmpq]] = []
        for _, lin in self.maps:
            if any(lin) and lin not in out:
                out.append(lin)
        return out

    def lift(self, box: Box) -> Box:
        """The box of a point of the chart in all coordinates (exact interval arithmetic)."""
        out = []
        for const, lin in self.maps:
            lo = hi = const
            for c, (a, b) in zip(lin, box):
                lo, hi = (lo + c * a, hi + c * b) if c >= 0 else (lo + c * b, hi + c * a)
            out.append((lo, hi))
        return out

    def lift_direction(self, box: Box) -> Box:
        """The box of a direction (a tangent vector) of the chart in all coordinates."""
        out = []
        for _, lin in self.maps:
            lo = hi = fmpq(0)
            for c, (a, b) in zip(lin, box):
                lo, hi = (lo + c * a, hi + c * b) if c >= 0 else (lo + c * b, hi + c * a)
            out.append((lo, hi))
        return out

