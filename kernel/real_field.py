"""Exact arithmetic in a real number field ``Q(c) = Q[T]/(p)`` with a chosen real root ``c`` of the
irreducible ``p``: elements are polynomials in ``T`` reduced modulo ``p`` (``fmpq_poly``); zero
tests are exact, values at ``c`` enclosed in balls.  Polynomials over the field (lists of
elements, constant first) can be divided by ``Y - y``, matrices have ranks and kernels (Gaussian
elimination), polynomials are evaluated at points - what the curve sweep and the branch analysis
need at an algebraic point."""
from __future__ import annotations

from typing import Sequence

import flint
from flint import arb, fmpq, fmpq_poly

from .real_roots import RealRoot

Elt = fmpq_poly
UPoly = list[fmpq_poly]  # a polynomial over the field, constant coefficient first


class RealAlgebraicField:
    """``Q(c)``: ``root.poly`` must be irreducible over Q (its roots are ``c`` and conjugates)."""

    def __init__(self, root: RealRoot) -> None:
        self.root = root
        self.p = fmpq_poly(root.poly)
        self.zero = fmpq_poly([])
        self.one = fmpq_poly([1])

    def __call__(self, a: fmpq_poly | fmpq | int) -> Elt:
        if isinstance(a, fmpq_poly):
            return a % self.p
        return fmpq_poly([a])

    def mul(self, a: Elt, b: Elt) -> Elt:
        return (a * b) % self.p

    def inv(self, a: Elt) -> Elt:
        g, s, _ = (a % self.p).xgcd(self.p)
        if g.degree() != 0:
            raise ZeroDivisionError("division by zero in a number field")
        return s / g.coeffs()[0]

    def is_zero(self, a: Elt) -> bool:
        return (a % self.p).is_zero()

    def ball(self, a: Elt, prec: int = 128) -> arb:
        """A ball around the value of ``a`` at ``c`` (at ``prec`` bits)."""
        with flint.ctx.workprec(prec):
            coeffs = (a % self.p).coeffs()
            return flint.arb_poly([arb(c) for c in coeffs])(self.root.ball(prec)) if coeffs else arb(0)

    def refine(self, width: fmpq) -> None:
        """Narrow the interval of ``c`` (later balls are tighter)."""
        self.root = self.root.refined(width)

    # --- polynomials over the field -----------------------------------------------------------

    def strip(self, f: UPoly) -> UPoly:
        out = [self(c) for c in f]
        while out and out[-1].is_zero():
            out.pop()
        return out

    def divide_linear(self, f: UPoly, y: Elt) -> UPoly:
        """``f / (Y - y)``; ValueError unless ``y`` is a root of ``f``."""
        f = self.strip(f)
        out: UPoly = [self.zero] * (len(f) - 1)
        carry = self.zero
        for k in range(len(f) - 1, 0, -1):
            carry = self(f[k] + self.mul(carry, y)) if k < len(f) - 1 else f[k]
            out[k - 1] = carry
        if not self.is_zero(f[0] + self.mul(out[0] if out else self.zero, y)):
            raise ValueError("not a root")
        return out

    def evaluate(self, terms: dict[tuple[int, ...], fmpq], point: Sequence[Elt]) -> Elt:
        """The polynomial with these terms (exponent: coefficient) at the point."""
        out = self.zero
        for e, c in terms.items():
            t = fmpq_poly([c])
            for x, k in zip(point, e):
                if k:
                    t = self.mul(t, x ** k)
            out += t
        return self(out)

    def kernel(self, rows: Sequence[Sequence[Elt]]) -> list[list[Elt]]:
        """A basis of the right kernel of a matrix over the field (reduced row echelon form)."""
        m = [[self(a) for a in row] for row in rows]
        ncols = len(m[0]) if m else 0
        pivots: list[int] = []
        for col in range(ncols):
            piv = next((i for i in range(len(pivots), len(m)) if not self.is_zero(m[i][col])), None)
            if piv is None:
                continue
            r = len(pivots)
            m[r], m[piv] = m[piv], m[r]
            inv = self.inv(m[r][col])
            m[r] = [self.mul(a, inv) for a in m[r]]
            for i in range(len(m)):
                if i != r and not self.is_zero(m[i][col]):
                    q = m[i][col]
                    m[i] = [self(a - self.mul(q, b)) for a, b in zip(m[i], m[r])]
            pivots.append(col)
        basis = []
        for free in (c for c in range(ncols) if c not in pivots):
            v = [self.zero] * ncols
            v[free] = self.one
            for i, col in enumerate(pivots):
                v[col] = self(-m[i][free])
            basis.append(v)
        return basis

    def rank(self, rows: Sequence[Sequence[Elt]]) -> int:
        """The rank of a matrix over the field (Gaussian elimination, exact)."""
        m = [[self(a) for a in row] for row in rows]
        rank, ncols = 0, len(m[0]) if m else 0
        for col in range(ncols):
            pivot = next((i for i in range(rank, len(m)) if not self.is_zero(m[i][col])), None)
            if pivot is None:
                continue
            m[rank], m[pivot] = m[pivot], m[rank]
            inv = self.inv(m[rank][col])
            for i in range(rank + 1, len(m)):
                if not self.is_zero(m[i][col]):
                    q = self.mul(m[i][col], inv)
                    m[i] = [self(a - q * b) for a, b in zip(m[i], m[rank])]
            rank += 1
        return rank
