"""Linear algebra in ``K(u)[x]/I`` without rational functions, for the reduction to dimension
zero (:mod:`.zerodim`): elements are vectors over ``K[u]`` (flint polynomials) on the standard
``x``-monomials with a common denominator; normal forms by fraction-free (pseudo-) reduction
modulo a Gröbner basis for the product ordering ``x >> u``, minimal polynomials of linear forms
by fraction-free Krylov iteration."""
from __future__ import annotations

from typing import Callable, Sequence

from .factor import to_flint
from .order import Exp
from .poly import Poly, PolyRing


class Quotient:
    """``K(u)[x]/I`` for a Gröbner basis of ``I`` for the product ordering ``x >> u``."""

    def __init__(self, basis: Sequence[Poly], ring: PolyRing, xs: Sequence[int]) -> None:
        self.ctx = to_flint(ring.one()).context()
        self.xs = list(xs)
        xset = set(xs)
        self.key = product_x_key(len(xs))
        self.reducers = []
        for p in basis:
            vec = self._vector(p, xset)
            lead = max(vec, key=self.key)
            self.reducers.append((lead, vec[lead], vec))

    def _vector(self, p: Poly, xset: set) -> dict:
        parts: dict[Exp, dict] = {}
        for e, c in p.terms.items():
            xe = tuple(e[i] for i in self.xs)
            ue = tuple(0 if i in xset else v for i, v in enumerate(e))
            parts.setdefault(xe, {})[ue] = c
        return {xe: self.ctx.from_dict(d) for xe, d in parts.items()}

    def normal_form(self, f: dict) -> tuple[dict, object]:
        """``(r, D)`` with ``f = r / D`` in ``K(u)[x]/I``, ``r`` reduced."""
        f = dict(f)
        done: dict = {}
        scale = self.ctx.from_dict({(0,) * self.ctx.nvars(): 1})
        while f:
            m = max(f, key=self.key)
            c = f.pop(m)
            hit = next((r for r in self.reducers if all(a >= b for a, b in zip(m, r[0]))), None)
            if hit is None:
                done[m] = c
                continue
            lead, lc, vec = hit
            shift = tuple(a - b for a, b in zip(m, lead))
            g = c.gcd(lc)
            mul, fac = lc / g, c / g
            if not mul.is_one():
                f = {k: v * mul for k, v in f.items()}
                done = {k: v * mul for k, v in done.items()}
                scale = scale * mul
            for e, v in vec.items():
                if e == lead:
                    continue
                t = tuple(a + b for a, b in zip(e, shift))
                w = f.get(t)
                w = -fac * v if w is None else w - fac * v
                if w.is_zero():
                    f.pop(t, None)
                else:
                    f[t] = w
        return self._reduce_content(done, scale)

    def _reduce_content(self, vec: dict, scale):
        g = scale
        for v in vec.values():
            if g.is_one():
                break
            g = g.gcd(v)
        if not g.is_one() and not g.is_zero():
            vec = {k: v / g for k, v in vec.items()}
            scale = scale / g
        return vec, scale

    def times_form(self, vec: dict, form: dict) -> dict:
        out: dict = {}
        for e, v in vec.items():
            for pos, c in form.items():
                t = e[:pos] + (e[pos] + 1,) + e[pos + 1:]
                w = out.get(t)
                w = v * c if w is None else w + v * c
                if w.is_zero():
                    out.pop(t, None)
                else:
                    out[t] = w
        return out

    def minimal_poly(self, form: dict) -> list:
        """The coefficients (in ``K[u]``, content removed) of the minimal polynomial over
        ``K(u)`` of multiplication by the linear form ``{position in xs: coefficient}``."""
        one = self.ctx.from_dict({(0,) * self.ctx.nvars(): 1})
        vec, denom = self.normal_form({(0,) * len(self.xs): one})
        rows: list[tuple[Exp, dict, dict]] = []
        denoms = []
        k = 0
        while True:
            denoms.append(denom)
            v, combo = dict(vec), {k: one}
            for piv, row, rc in rows:
                a = v.get(piv)
                if a is None:
                    continue
                b = row[piv]
                g = a.gcd(b)
                a, b = a / g, b / g
                v = _axpy(b, v, -a, row)
                combo = _axpy(b, combo, -a, rc)
            if not v:
                coeffs = [combo.get(j, one * 0) * denoms[j] for j in range(k + 1)]
                content = coeffs[-1]
                for c in coeffs:
                    content = content.gcd(c)
                return [c / content for c in coeffs]
            v, combo = _primitive_pair(v, combo)
            rows.append((max(v, key=self.key), v, combo))
            k += 1
            vec, d = self.normal_form(self.times_form(vec, form))
            denom = denom * d


def _axpy(a, x: dict, b, y: dict) -> dict:
    """``a*x + b*y`` for sparse vectors with flint entries."""
    out = {k: a * v for k, v in x.items()}
    for k, v in y.items():
        w = out.get(k)
        w = b * v if w is None else w + b * v
        if w.is_zero():
            out.pop(k, None)
        else:
            out[k] = w
    return out


def _primitive_pair(v: dict, combo: dict) -> tuple[dict, dict]:
    g = None
    for w in list(v.values()) + list(combo.values()):
        g = w if g is None else g.gcd(w)
        if g.is_one():
            return v, combo
    return {k: w / g for k, w in v.items()}, {k: w / g for k, w in combo.items()}


def product_x_key(n: int) -> Callable[[Exp], tuple]:
    """The ``dp`` key on ``x``-exponents (the ``x`` block of :func:`product_order`)."""
    return lambda e: (sum(e), *[-v for v in reversed(e[1:])])
