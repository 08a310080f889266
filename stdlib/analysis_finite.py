"""The analysis of a rigid mechanism (numeric lengths, ``dim J = 0``): finitely many configurations.

Everything comes from the quotient algebra ``A = Q[x]/J`` and a rational univariate
representation of its points (:func:`mech.kernel.real_solve.real_solutions`, computed once and
shared with the real answers' assembly modes, :mod:`mech.stdlib.mechanism_real`):

* ``vdim = dim_Q A`` counts the configurations with multiplicity, the degree of the squarefree
  separating polynomial ``f`` (the characteristic polynomial of a linear form ``u`` that takes
  distinct values at the points) the distinct ones: ``J`` is radical iff they are equal;
* the assembly modes (the minimal primes of ``J``, each a Galois orbit of configurations) are the
  irreducible factors ``f_k`` of ``f`` over Q: ``P_k = J + <f_k(u)> + <x_i - s_i(u)>`` with
  ``x_i = s_i(t)`` the representation (``P_k`` is the kernel of ``Q[x] -> Q[t]/(f_k)``, so prime);
  the new generators are normal forms in ``A`` (vectors of ``A``, no power of ``u`` is expanded);
* a point is a smooth variety: the configuration space has no singular configuration.  Where
  ``J`` is not reduced the constraints are dependent (a multiple point, the Jacobian's rank drops):
  the Jacobian's rank is computed exactly at every point, over each field ``Q[t]/(f_k)``, and
  reported; for a radical ``J`` it is full (the Jacobian criterion), which the check confirms;
* real configurations: the real roots of each ``f_k``, isolated exactly.

The Fitting ideal (``n x n`` minors of the Jacobian), the decomposition strategies and the local
analysis are not run: they have nothing to add for finitely many points.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable

from flint import fmpq, fmpq_mat, fmpq_poly, fmpz_poly, nmod_poly

from mech.kernel import Poly
from mech.kernel.ideals import std
from mech.kernel.progress import stage
from mech.kernel.real_roots import isolate_real_roots
from mech.kernel.real_solve import RUR, QuotientAlgebra, RealSolution, Solutions, rur_of, solution_boxes
from mech.stdlib.mechanism import MechanismError


#: Decimals of the real solutions' boxes (those of the report's poses, mech.stdlib.mechanism_real.DIGITS).
DIGITS = 4


@dataclass
class Orbit:
    """One assembly mode: the irreducible factor ``factor`` of the separating polynomial, its
    ``degree`` (complex configurations), ``real`` (real ones), ``rank`` of the Jacobian at its points
    and ``multiplicity`` of its points as solutions of ``J``."""

    factor: fmpz_poly
    degree: int
    real: int
    rank: int
    multiplicity: int


@dataclass
class Finite:
    """The zero-dimensional analysis: the solutions (shared with the real answers), the separating
    form ``u`` (a polynomial) and the orbits, in the order of the modes."""

    solutions: Solutions
    form: Poly
    orbits: list[Orbit]
    nvars: int
    digits: int  # the real solutions' boxes have width 10^-digits

    @property
    def total(self) -> int:
        return self.solutions.total

    @property
    def distinct(self) -> int:
        return self.solutions.complex_count


def _apply(A: QuotientAlgebra, M: fmpq_mat, p: fmpq_poly, v: fmpq_mat) -> fmpq_mat:
    """The coordinates of ``p(u) v`` in ``A`` (``M`` multiplies by ``u``), by Horner's rule."""
    cs = p.coeffs()
    out = v * fmpq(cs[-1]) if cs else fmpq_mat(A.dim, 1)
    for c in reversed(cs[:-1]):
        out = M * out + v * fmpq(c)
    return out


def _ideal(A: QuotientAlgebra, M: fmpq_mat, rep: RUR, f: fmpz_poly, power: int, shapes: bool) -> list[Poly]:
    """The reduced ``dp`` Gröbner basis (of ``A.ring``) of ``J + <f(u)^power>`` (+ ``<x_i - s_i(u)>``
    with ``shapes``): ``P / J`` is the subspace of ``A`` spanned by the generators' multiples ``g b``
    (``b`` the standard monomials); linear algebra as in FGLM (Faugère, Gianni, Lazard, Mora 1993)
    gives the basis, no Buchberger step.

    With ``shapes`` and ``power`` 1 it is the prime of the points at the roots of ``f`` (the kernel
    of ``Q[x] -> Q[t]/(f)``, ``x_i -> s_i(t)``; for a radical ``J`` the ``x_i - s_i(u)`` are in ``J``
    already); with ``power`` the multiplicity of ``f`` in ``u``'s characteristic polynomial, the
    primary component of ``J`` at those points (``f(u)`` is nilpotent in the local algebras there,
    a unit in the others)."""
    one = fmpq_mat(A.dim, 1, A.coords(A.source.one()))
    fq = fmpq_poly(f)
    gens = [_apply(A, M, fq ** power, one)]
    if shapes:
        for i, s in enumerate(rep.shape):
            gens.append(fmpq_mat(A.dim, 1, A.coords(A.source.gens()[i])) - _apply(A, M, s % fq, one))
    cols = [A.monomial_matrix(b) * g for g in gens for b in A.monomials]
    return _basis_from_subspace(A, [[c[k, 0] for k in range(A.dim)] for c in cols])


def _basis_from_subspace(A: QuotientAlgebra, vectors: list[list[fmpq]]) -> list[Poly]:
    """The reduced ``dp`` basis of ``J + V`` for the ideal ``V`` of ``A`` spanned by ``vectors``:
    the echelon form of ``V`` (columns by decreasing monomial) gives the new leading monomials and
    the normal forms of the old ones."""
    D, R, key = A.dim, A.ring, A.ring.order.key
    order = sorted(range(D), key=lambda k: key(A.monomials[k]), reverse=True)
    E, r = fmpq_mat(len(vectors), D, [v[order[j]] for v in vectors for j in range(D)]).rref()
    pivots: dict[int, dict[int, fmpq]] = {}
    for i in range(r):
        row = {order[c]: E[i, c] for c in range(D) if E[i, c] != 0}
        pivots[max(row, key=lambda k: key(A.monomials[k]))] = row

    def reduce(vec: dict[int, fmpq]) -> dict[int, fmpq]:
        for k, row in pivots.items():
            c = vec.get(k)
            if c:
                for l, d in row.items():
                    vec[l] = vec.get(l, fmpq(0)) - c * d
        return {k: c for k, c in vec.items() if c != 0}

    def divides(a: tuple, b: tuple) -> bool:
        return a != b and all(x <= y for x, y in zip(a, b))
    lead = {g.lm(): g.monic() for g in A.basis}
    candidates = list(lead) + [A.monomials[k] for k in pivots]
    out = []
    for m in candidates:
        if any(divides(o, m) for o in candidates):
            continue
        if m in lead:
            tail = reduce({A.index[e]: -c for e, c in lead[m].terms.items() if e != m})
            out.append(Poly(R, {m: fmpq(1), **{A.monomials[k]: -c for k, c in tail.items()}}))
        else:
            out.append(Poly(R, {A.monomials[k]: c for k, c in pivots[A.index[m]].items()}))
    return sorted(out, key=lambda g: key(g.lm()))


def _multiplicity(f: fmpq_poly, chi: fmpq_poly) -> int:
    """The largest ``e`` with ``f^e`` dividing ``chi``: the multiplicity of the points of ``f``'s orbit."""
    e = 0
    while (chi % f).is_zero():
        chi, e = chi // f, e + 1
    return e


def _rank(rows: list[list[Any]], f: Any, units_only: bool = False) -> int | None:
    """The rank of a matrix over ``Q[t]/(f)`` (``f`` irreducible: a field), by Gaussian elimination;
    with ``units_only`` (over ``F_p[t]/(f)``, not always a field) pivots are units only and None
    says that a column had none (the rank is then not decided)."""
    rows = [[e % f for e in r] for r in rows]
    rank, ncols = 0, len(rows[0]) if rows else 0
    for col in range(ncols):
        piv = None
        for i in range(rank, len(rows)):
            e = rows[i][col]
            if not e.is_zero() and (not units_only or e.gcd(f).degree() == 0):
                piv = i
                break
        if piv is None:
            if units_only and any(not rows[i][col].is_zero() for i in range(rank, len(rows))):
                return None
            continue
        rows[rank], rows[piv] = rows[piv], rows[rank]
        g, s, _ = rows[rank][col].xgcd(f)
        inv = (s * _constant(f, 1 / g.coeffs()[0])) % f
        pivot = [(e * inv) % f for e in rows[rank]]
        rows[rank] = pivot
        for i in range(len(rows)):
            if i != rank and not rows[i][col].is_zero():
                c = rows[i][col]
                rows[i] = [(e - c * q) % f for e, q in zip(rows[i], pivot)]
        rank += 1
    return rank


def _constant(f: Any, c: Any) -> Any:
    """The constant ``c`` as a polynomial of ``f``'s kind (``fmpq_poly`` or ``nmod_poly``)."""
    return nmod_poly([int(c)], f.modulus()) if isinstance(f, nmod_poly) else fmpq_poly([c])


def _evaluate(p: Poly, shapes: list[Any], f: Any, powers: dict) -> Any:
    """``p(shapes)`` modulo ``f`` (``powers``: a cache of the shapes' powers)."""
    out = _constant(f, 0)
    for e, c in p.terms.items():
        t = _constant(f, c if isinstance(f, fmpq_poly) else _mod(c, f.modulus()))
        for i, k in enumerate(e):
            if k:
                if (i, k) not in powers:
                    powers[i, k] = shapes[i].pow_mod(k, f) if isinstance(f, nmod_poly) else (shapes[i] ** k) % f
                t = (t * powers[i, k]) % f
        out += t
    return out % f


def _mod(c: fmpq, p: int) -> int:
    """The rational ``c`` modulo ``p`` (its denominator is prime to ``p``: checked by the caller)."""
    return int(c.p) * pow(int(c.q), -1, p) % p


#: Primes for the modular certificate of a full-rank Jacobian (the next when one divides a denominator).
_PRIMES = (2147483647, 2147483629, 2147483587)


def _full_rank_mod_p(rep: RUR, jac: list[list[Poly]], f: fmpz_poly) -> bool:
    """Whether the Jacobian ``jac`` has full column rank at every root of ``f``, certified modulo
    a prime ``p``: reduction ``Z_(p)[t]/(f) -> F_p[t]/(f)`` is a ring map, so a determinant that is
    a unit modulo ``p`` is non-zero in the field ``Q[t]/(f)``.  False: not certified."""
    dens = [int(c.q) for s in rep.shape for c in s.coeffs()] + \
        [int(c.q) for row in jac for e in row for c in e.terms.values()]
    for p in _PRIMES:
        if int(f.coeffs()[-1]) % p == 0 or any(d % p == 0 for d in dens):
            continue
        fp = nmod_poly([int(c) % p for c in f.coeffs()], p)
        shapes = [nmod_poly([_mod(c, p) for c in s.coeffs()], p) % fp for s in rep.shape]
        powers: dict = {}
        rows = [[_evaluate(e, shapes, fp, powers) for e in row] for row in jac]
        return _rank(rows, fp, units_only=True) == len(jac[0])
    return False


def _jacobian_rank(rep: RUR, gens: list[Poly], n: int, f: fmpz_poly, multiplicity: int) -> int:
    """The rank of the constraints' Jacobian at the points of the orbit of ``f``, exactly: for a
    simple orbit first by the modular certificate of full rank, else over the field ``Q[t]/(f)``."""
    jac = [[g.diff(j) for j in range(n)] for g in gens]
    if multiplicity == 1 and _full_rank_mod_p(rep, jac, f):
        return n
    fq = fmpq_poly(f)
    shapes = [s % fq for s in rep.shape]
    powers: dict = {}
    return _rank([[_evaluate(e, shapes, fq, powers) for e in row] for row in jac], fq)


def finite_analysis(a: Any, mode: Callable[..., Any]) -> bool:
    """Fill in the analysis ``a`` (numeric lengths, ``a.dim == 0``): radicality, the assembly
    modes as motion modes, no embedded components and no singular configurations (the Jacobian's
    rank at the points in ``a.finite``); ``mode(prime, primary, dim, real)`` makes a motion mode.  True:
    ``a`` is complete."""
    R, J, n = a.ring, a.ideal, a.nvars
    a.running, a.modes_found = "assembly modes", False  # not found until the orbits are (a partial report)
    with stage("assembly modes", detail="quotient algebra and separating polynomial"):
        A = QuotientAlgebra(J, R)
        rep = rur_of(A)
        roots = rep.real_roots()
        boxes = solution_boxes(rep, roots, fmpq(1, 10 ** DIGITS))
    sols = Solutions(A.dim, rep.count, [RealSolution(b, r.multiplicity, r) for r, b in boxes], rep)  # as real_solutions
    M = A.linear_matrix(rep.form)
    a.radical = radical = sols.total == sols.complex_count
    a.radical_decided = True
    factors = sorted((g for g, _ in rep.poly.factor()[1]), key=lambda g: (g.degree(), [int(c) for c in g.coeffs()]))
    orbits, modes = [], []
    with stage("assembly modes", total=len(factors)) as st:
        for k, f in enumerate(factors):
            st.step(k, f"orbit {k + 1} of {len(factors)} (degree {f.degree()})")
            mult = _multiplicity(fmpq_poly(f), rep.charpoly)
            real = len(isolate_real_roots(f))
            orbits.append(Orbit(f, f.degree(), real, _jacobian_rank(rep, J, n, f, mult), mult))
            P = _in(R, _ideal(A, M, rep, f, 1, not radical))
            Q = P if mult == 1 else _in(R, _ideal(A, M, rep, f, mult, False))
            modes.append((P, Q, real))
    order = _order(modes, R)
    a.modes = [mode(modes[i][0], modes[i][1], 0, modes[i][2] > 0) for i in order]
    form = Poly(R, {tuple(int(j == i) for j in range(R.nvars)): c for i, c in enumerate(rep.form) if c != 0})
    a.finite = Finite(sols, form, [orbits[i] for i in order], n, DIGITS)
    a.modes_by = "assembly modes: the Galois orbits of the configurations, the irreducible factors over Q " \
                 "of the separating polynomial"
    a.modes_found, a.decomposed, a.equidimensional, a.embedded, a.running = True, True, True, [], ""
    a.fitting_size, a.fitting, a.singular, a.singular_done = n, [], [], True
    if not any(o.real for o in orbits):
        raise MechanismError(f"{a.mechanism.name}: the mechanism does not close: the configuration space "
                             "has no real point (the lengths are inconsistent)")
    return True


def _in(R: Any, basis: list[Poly]) -> list[Poly]:
    """A reduced ``dp`` basis as a reduced basis of ``R`` (the same when ``R`` is ordered by ``dp``)."""
    moved = [Poly(R, g.terms) for g in basis]
    return moved if R.order == basis[0].ring.order else std(moved, R)


def _order(modes: list[tuple[list[Poly], list[Poly], int]], R: Any) -> list[int]:
    """The modes in the order of :func:`mech.stdlib.analysis._sorted_primes` (leading monomials,
    then terms): the numbering does not depend on the path that found them."""
    key = R.order.key
    return sorted(range(len(modes)), key=lambda i: ([key(g.lm()) for g in modes[i][0]],
                                                    [[(key(e), c) for e, c in g.sorted_terms()] for g in modes[i][0]]))


# ---------------------------------------------------------------- the report's lines and data
def _and(xs: list[Any]) -> str:
    xs = [str(x) for x in xs]
    return xs[0] if len(xs) == 1 else ", ".join(xs[:-1]) + " and " + xs[-1]


def modes_line(a: Any) -> str:
    """The header of the modes of a rigid mechanism: the orbits, the complex and real counts."""
    from mech.dsl.printing import poly_str
    fin: Finite = a.finite
    sizes = _and([o.degree for o in fin.orbits])
    reals = _and([o.real for o in fin.orbits])
    mult = "" if fin.total == fin.distinct else f" ({fin.total} with multiplicity)"
    return (f"assembly modes (Galois orbits of configurations over Q: the irreducible factors of the separating "
            f"polynomial of t = {poly_str(fin.form)}): {len(fin.orbits)}, of {sizes} configurations ({reals} real); "
            f"{_count(fin.distinct, 'complex configuration')}{mult}, {sum(o.real for o in fin.orbits)} real")


def _count(k: int, word: str) -> str:
    return f"{k} {word}{'' if k == 1 else 's'}"


def singular_lines(a: Any) -> list[str]:
    """The singular configurations of a rigid mechanism: none (each configuration is a point),
    with the Jacobian's rank at the points, checked exactly."""
    fin: Finite = a.finite
    n = fin.nvars
    low = [(i, o) for i, o in enumerate(fin.orbits, 1) if o.rank < n]
    out = ["singular configurations: 0 (finitely many configurations, each an isolated point; the Fitting ideal "
           "and the local analysis do not apply)"]
    if not low:
        out.append(f"  the Jacobian of J has full rank {n} at all {fin.distinct} configurations (checked exactly on "
                   f"each orbit): J is reduced, no constraint singularity")
    for i, o in low:
        where = "its configuration, of" if o.degree == 1 else f"its {o.degree} configurations, each of"
        out.append(f"  mode {i}: the Jacobian of J has rank {o.rank} < {n} at {where} multiplicity {o.multiplicity}: "
                   f"J is not reduced there (the constraints are dependent: a constraint singularity)")
    return out


def finite_data(a: Any) -> dict[str, Any]:
    """The JSON report's entries of a rigid mechanism (``{}`` for the others)."""
    from mech.dsl.printing import poly_str
    fin: Finite | None = getattr(a, "finite", None)
    if fin is None:
        return {}
    return {"separating_form": poly_str(fin.form),
            "assembly_orbits": [{"configurations": o.degree, "real": o.real, "multiplicity": o.multiplicity,
                                 "jacobian_rank": o.rank, "polynomial": _univariate(o.factor)}
                                for o in fin.orbits]}


def _univariate(f: fmpz_poly) -> str:
    """``f`` in the variable ``t``, as the printer writes polynomials."""
    terms = []
    for k, c in reversed(list(enumerate(int(x) for x in f.coeffs()))):
        if c == 0:
            continue
        mono = "" if k == 0 else "t" if k == 1 else f"t^{k}"
        num = str(abs(c)) if abs(c) != 1 or not mono else ""
        body = num + ("*" if num and mono else "") + mono
        terms.append(("-" if c < 0 else "+") + body)
    s = "".join(terms)
    return s[1:] if s.startswith("+") else s
