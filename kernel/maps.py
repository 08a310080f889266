"""Ring maps: Singular's ``map`` (images of the variables), ``imap`` (by name), ``fetch``
(by position) and ``subst``, with Singular's conversion of coefficients between fields.

Coefficients: QQ -> Z/p reduces (a denominator divisible by p is an error); Z/p -> QQ and
Z/p -> Z/q go through the symmetric representative.  Parameters of a rational function
field map by name (``imap``: to the parameter or variable of that name) or by position
(``fetch``); a parameter or variable without image maps to 0, as in Singular.
"""
from __future__ import annotations

from fractions import Fraction
from typing import Any, Callable, Sequence

from .coeffs import Field
from .errors import DomainError
from .poly import Exp, Poly, PolyRing
from .ratfunc import RatFunc, RationalFunctionField

CoeffMap = Callable[[Any], Poly]


def _scalar(value: Fraction | int, target: Field) -> Any:
    """A rational number (or integer) in ``target`` (its base field for parameter fields)."""
    try:
        return target(value)
    except ZeroDivisionError:
        raise DomainError(f"cannot map {value} to characteristic {target.characteristic}: "
                         f"its denominator is divisible by {target.characteristic}") from None


def _int_image(n: int, source: Field, target: Field) -> Any:
    """The image of an integer coefficient of a source parameter polynomial."""
    if source.characteristic:
        p = source.characteristic
        n %= p
        if n > p // 2:
            n -= p
    return _scalar(n, target)


def coefficient_map(source: PolyRing, target: PolyRing, by_name: bool = True) -> CoeffMap:
    """A function taking a coefficient of ``source`` to a polynomial of ``target`` (a
    constant unless a parameter becomes a variable)."""
    sf, tf = source.field, target.field
    if sf == tf:
        zero = target.zero_exp
        return lambda c: Poly(target, {zero: c}) if c != 0 else target.zero()
    if not isinstance(sf, RationalFunctionField):
        return lambda c: target.const(_scalar(sf.to_fraction(c), tf))
    images: list[Poly] = []
    for i, name in enumerate(sf.params):
        if by_name:
            if isinstance(tf, RationalFunctionField) and name in tf.params:
                images.append(target.const(tf.gen(tf.params.index(name))))
            elif name in target.names:
                images.append(target.gen(target.names.index(name)))
            else:
                images.append(target.zero())
        elif isinstance(tf, RationalFunctionField) and i < len(tf.params):
            images.append(target.const(tf.gen(i)))
        else:
            images.append(target.zero())

    def evaluate(p: Any) -> Poly:
        out = target.zero()
        for exps, c in p.terms():
            t = target.const(_int_image(int(c), sf, tf))
            for img, e in zip(images, exps):
                if e:
                    t = t * img ** int(e)
            out = out + t
        return out

    def convert(c: RatFunc) -> Poly:
        num = evaluate(c.num)
        if c.den.is_one():
            return num
        den = evaluate(c.den)
        if den.is_zero():
            raise DomainError(f"cannot map the coefficient {c}: its denominator maps to 0")
        if not den.is_constant():
            raise DomainError(f"cannot map the coefficient {c}: its denominator maps to a "
                             "non-constant polynomial")
        return num / den
    return convert


def _apply(polys: Sequence[Poly], target: PolyRing, images: Sequence[Poly | None],
           coeff: CoeffMap) -> list[Poly]:
    """Substitute ``images[i]`` (None for 0) for the i-th variable, coefficients by ``coeff``."""
    # fast path: every image is a variable (coefficient 1) or 0 and coefficients are constants
    perm = [_variable_index(img) for img in images]
    if all(j is not False for j in perm):
        return [_permute(f, target, perm, coeff) for f in polys]
    out = []
    for f in polys:
        powers: dict[tuple[int, int], Poly] = {}
        acc = target.zero()
        for e, c in f.terms.items():
            t = coeff(c)
            for i, k in enumerate(e):
                if k and not t.is_zero():
                    img = images[i]
                    if img is None:
                        t = target.zero()
                        break
                    p = powers.get((i, k))
                    if p is None:
                        p = powers[(i, k)] = img ** k
                    t = t * p
            acc = acc + t
        out.append(acc)
    return out


def _variable_index(img: Poly | None) -> int | None | bool:
    """None for a zero image, j for the variable x_j, False for anything else."""
    if img is None or img.is_zero():
        return None
    if len(img.terms) == 1:
        (e, c), = img.terms.items()
        if c == 1 and sum(e) == 1:
            return e.index(1)
    return False


def _permute(f: Poly, target: PolyRing, perm: Sequence[int | None], coeff: CoeffMap) -> Poly:
    acc: dict[Exp, Any] = {}
    n = target.nvars
    pending = []
    for e, c in f.terms.items():
        te = [0] * n
        for i, k in enumerate(e):
            if k:
                j = perm[i]
                if j is None:
                    break
                te[j] += k
        else:
            cp = coeff(c)
            if cp.is_constant():
                if not cp.is_zero():
                    key = tuple(te)
                    v = acc.get(key)
                    acc[key] = cp.lc() if v is None else v + cp.lc()
            else:
                pending.append(cp.mul_term(tuple(te), target.field.one))
    out = Poly(target, {e: c for e, c in acc.items() if c != 0})
    for p in pending:
        out = out + p
    return out


def map_polys(polys: Sequence[Poly], images: Sequence[Poly], target: PolyRing,
              source: PolyRing | None = None) -> list[Poly]:
    """Singular's ``map phi = source, images...; phi(polys)``: the i-th variable of the
    source goes to ``images[i]`` (a polynomial of ``target``); variables without an image go
    to 0.  Coefficients convert between QQ and Z/p (and into parameter fields); a source
    ring with parameters needs the same coefficient field in the target (Singular: "can not
    map from ground field")."""
    source = source or (polys[0].ring if polys else None)
    if source is None:
        return []
    if len(images) > source.nvars:
        raise DomainError(f"{len(images)} images for a ring with {source.nvars} variables")
    for img in images:
        if not isinstance(img, Poly) or (img.ring is not target and img.ring != target):
            raise DomainError("the images must be polynomials of the target ring")
    sf, tf = source.field, target.field
    if isinstance(sf, RationalFunctionField) and sf != tf:
        raise DomainError(f"cannot map from the coefficient field {sf!r} to {tf!r}")
    full = list(images) + [None] * (source.nvars - len(images))
    return _apply(_check(polys, source), target, full, coefficient_map(source, target))


def imap(polys: Sequence[Poly], source: PolyRing, target: PolyRing) -> list[Poly]:
    """Singular's ``imap``: each variable goes to the target variable of the same name (or
    to the target parameter of that name); names missing from the target go to 0;
    parameters likewise by name."""
    images: list[Poly | None] = []
    tf = target.field
    for name in source.names:
        if name in target.names:
            images.append(target.gen(target.names.index(name)))
        elif isinstance(tf, RationalFunctionField) and name in tf.params:
            images.append(target.const(tf.gen(tf.params.index(name))))
        else:
            images.append(None)
    return _apply(_check(polys, source), target, images, coefficient_map(source, target, True))


def fetch(polys: Sequence[Poly], source: PolyRing, target: PolyRing) -> list[Poly]:
    """Singular's ``fetch``: the i-th variable goes to the i-th variable of the target (0 if
    the target has fewer), parameters likewise by position."""
    images = [target.gen(i) if i < target.nvars else None for i in range(source.nvars)]
    return _apply(_check(polys, source), target, images, coefficient_map(source, target, False))


def _check(polys: Sequence[Poly], source: PolyRing) -> list[Poly]:
    for f in polys:
        if f.ring is not source and f.ring != source:
            raise DomainError("a polynomial that is not in the source ring")
    return list(polys)


def subst(f: Poly, var_index: int, g: Any) -> Poly:
    """Singular's ``subst(f, x_i, g)``: ``g`` (a polynomial or a scalar) for the variable."""
    ring = f.ring
    if not 0 <= var_index < ring.nvars:
        raise DomainError(f"no variable {var_index + 1} in a ring with {ring.nvars} variables")
    g = g if isinstance(g, Poly) else ring.const(g)
    images = list(ring.gens())
    images[var_index] = g
    return _apply([f], ring, images, coefficient_map(ring, ring))[0]
