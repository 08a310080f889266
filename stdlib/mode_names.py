"""Names of motion modes a person understands, read off each mode's prime ideal ``P`` (numeric
lengths): every property is an ideal membership decided by a normal form against ``P``'s reduced
Gröbner basis (dp), never a table of known mechanisms.

* **frozen link** ``i``: its angle is constant on the mode — ``c_i - a`` and ``s_i - b`` lie in
  ``P`` for rational ``a, b`` (the normal forms of ``c_i``, ``s_i`` are constants; the angle is
  ``atan2(b, a)``), or ``c_i`` is algebraic over Q modulo ``P`` (``P + <c_i - r>`` is the unit
  ideal for two rational ``r``: a non-constant function on an irreducible variety misses at most
  finitely many values);
* **folded**: two joint points coincide on the mode, ``B - A`` (each coordinate) lies in ``P``;
* **parallelogram**: a loop of four points ``a b c d`` joined by four different links (or the
  ground) with ``b - a = c - d`` on the mode (opposite sides equal and parallel; the two links'
  directions equal or opposite);
* **anti-parallelogram**: such a loop, not a parallelogram, whose opposite sides have equal
  lengths and whose diagonals ``ac`` and ``bd`` are parallel on the mode (the crossed form);
* **parallel links**: ``c_i - c_j, s_i - s_j`` (same direction) or ``c_i + c_j, s_i + s_j``
  (opposite) in ``P``;
* **rigid**: the mode is a point, or a Galois orbit of points (dimension 0); otherwise **general** when none of the above holds.
"""
from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Optional, Sequence

from mech.kernel import Poly, PolyRing
from mech.kernel.groebner import normal_form
from mech.kernel.ideals import dp_ring, is_unit, move, std
from mech.stdlib.mechanism import Mechanism


@dataclass
class ModeName:
    """What a mode is, in words (``name``) and as data: frozen links with their angle in degrees
    (None: an algebraic angle), coincident points, parallelograms and anti-parallelograms (loops
    of points), parallel links ``(i, j, "same" | "opposite")``, rigid."""

    name: str
    frozen: list[tuple[int | str, Optional[float]]] = field(default_factory=list)
    coincident: list[tuple[str, str]] = field(default_factory=list)
    parallelograms: list[tuple[str, ...]] = field(default_factory=list)
    anti_parallelograms: list[tuple[str, ...]] = field(default_factory=list)
    parallel_links: list[tuple[int | str, int | str, str]] = field(default_factory=list)
    rigid: bool = False

    def data(self) -> dict[str, Any]:
        return {"frozen_links": [{"link": k, "angle": a} for k, a in self.frozen],
                "coincident_points": [list(p) for p in self.coincident],
                "parallelograms": [list(q) for q in self.parallelograms],
                "anti_parallelograms": [list(q) for q in self.anti_parallelograms],
                "parallel_links": [list(p) for p in self.parallel_links], "rigid": self.rigid}


class _Mode:
    """A prime with its reduced dp basis: membership and normal forms."""

    def __init__(self, prime: Sequence[Poly]) -> None:
        self.ring = dp_ring(prime[0].ring)
        self.basis = std(move(list(prime), self.ring), self.ring)

    def nf(self, f: Poly) -> Poly:
        return normal_form(Poly(self.ring, f.terms), self.basis)

    def zero(self, *fs: Poly) -> bool:
        return all(self.nf(f).is_zero() for f in fs)

    def constant(self, f: Poly) -> Optional[Fraction]:
        g = self.nf(f)
        if not g.is_constant():
            return None
        c = g.terms.get((0,) * self.ring.nvars)
        return Fraction(0) if c is None else Fraction(int(c.p), int(c.q))

    def algebraic(self, f: Poly) -> bool:
        """``f`` takes finitely many values on V(P): two rational values are missed."""
        R = self.ring
        g = Poly(R, f.terms)
        return all(is_unit(std(self.basis + [g - R.const(Fraction(r))], R)) for r in (Fraction(3, 7), Fraction(-5, 11)))


def _angles(ring: PolyRing) -> list[tuple[int | str, Poly, Poly]]:
    """The orientation pairs ``(c_k, s_k)`` of the ring, labelled by ``k`` (a link number for
    planar mechanisms)."""
    names = list(ring.names)
    gens = dict(zip(names, ring.gens()))
    out: list[tuple[int | str, Poly, Poly]] = []
    for n in names:
        if n.startswith("c") and "s" + n[1:] in gens:
            k = n[1:].lstrip("_")
            out.append((int(k) if k.isdigit() else k, gens[n], gens["s" + n[1:]]))
    return out


def _edges(m: Mechanism) -> dict[frozenset, int]:
    """Pairs of points on one rigid part: link number (0: the ground)."""
    edges: dict[frozenset, int] = {}
    for a, b in itertools.combinations(list(m.fixed), 2):
        edges[frozenset((a, b))] = 0
    for i, link in enumerate(m.links, 1):
        for a, b in itertools.combinations(link.points, 2):
            edges.setdefault(frozenset((a, b)), i)
    return edges


def _loops(m: Mechanism) -> list[tuple[str, str, str, str]]:
    """Loops ``a b c d`` of four points joined by four different rigid parts (each loop once)."""
    edges = _edges(m)
    pts = m.points()
    out = []
    for a, b, c, d in itertools.permutations(pts, 4):
        if pts.index(a) > min(pts.index(p) for p in (b, c, d)):
            continue  # one rotation per loop: from its first point
        parts = [edges.get(frozenset(e)) for e in ((a, b), (b, c), (c, d), (d, a))]
        if None in parts or len(set(parts)) < 4:
            continue
        first, last = (p or math.inf for p in (parts[0], parts[3]))  # a link, not the ground, first
        if (first, pts.index(b)) < (last, pts.index(d)):
            out.append((a, b, c, d))
    return out


def _degrees(c: Fraction, s: Fraction) -> float:
    a = round(math.degrees(math.atan2(float(s), float(c))), 2)
    return 180.0 if a == -180.0 else a + 0.0


def name_mode(m: Mechanism, prime: Sequence[Poly], dim: int) -> ModeName:
    """The name of the motion mode ``V(prime)`` (of dimension ``dim``) of ``m``."""
    P = _Mode(prime)
    if dim == 0:
        from mech.kernel.hilbert import vdim
        k = vdim([g.lm() for g in P.basis], P.ring.nvars)
        what = "an isolated configuration" if k == 1 else f"{k} conjugate isolated configurations over C"
        return ModeName(f"rigid mode ({what}: no link moves)", rigid=True)
    out = ModeName("")
    frozen_k: set = set()
    for k, c, s in _angles(prime[0].ring):
        a, b = P.constant(c), P.constant(s)
        if a is not None and b is not None:
            out.frozen.append((k, _degrees(a, b)))
        elif P.algebraic(c) or P.algebraic(s):
            out.frozen.append((k, None))
        else:
            continue
        frozen_k.add(k)
    moving = [(k, c, s) for k, c, s in _angles(prime[0].ring) if k not in frozen_k]
    for (i, ci, si), (j, cj, sj) in itertools.combinations(moving, 2):
        if P.zero(ci - cj, si - sj):
            out.parallel_links.append((i, j, "same"))
        elif P.zero(ci + cj, si + sj):
            out.parallel_links.append((i, j, "opposite"))
    pos: dict[str, tuple[Poly, ...]] = {}
    if hasattr(m.model, "positions"):
        pos, _ = m.positions(prime[0].ring)
    for p, q in itertools.combinations([p for p in m.points() if p in pos], 2):
        if p in m.fixed and q in m.fixed:
            continue
        if P.zero(*(u - v for u, v in zip(pos[q], pos[p]))):
            out.coincident.append((q, p) if p in m.fixed else (p, q))
    if pos and m.dim == 2:
        for a, b, c, d in _loops(m):
            (ax, ay), (bx, by), (cx, cy), (dx, dy) = (pos[p] for p in (a, b, c, d))
            if P.zero(bx - ax - cx + dx, by - ay - cy + dy):
                out.parallelograms.append((a, b, c, d))
                continue
            sq = lambda u, v: (u[0] - v[0]) ** 2 + (u[1] - v[1]) ** 2  # noqa: E731
            A, B, C, D = (pos[p] for p in (a, b, c, d))
            if any(p in pair and q in pair for pair in out.coincident for p, q in ((a, c), (b, d), (a, b),
                                                                                   (b, c), (c, d), (d, a))):
                continue  # folded: a degenerate loop
            if P.zero(sq(B, A) - sq(D, C), sq(C, B) - sq(A, D),
                      (cx - ax) * (dy - by) - (cy - ay) * (dx - bx)):
                out.anti_parallelograms.append((a, b, c, d))
    out.name = _words(out, len(_angles(prime[0].ring)))
    return out


def _classes(pairs: list[tuple[str, str]]) -> list[list[str]]:
    """The classes of points that coincide, each in the order first seen (a fixed point last,
    as the pairs put it)."""
    classes: list[list[str]] = []
    for p, q in pairs:
        hit = [c for c in classes if p in c or q in c]
        merged = [x for c in hit for x in c]
        for x in (p, q):
            if x not in merged:
                merged.append(x)
        fixed_last = sorted(merged, key=lambda x: any(x == b for _, b in pairs) and not any(x == a for a, _ in pairs))
        classes = [c for c in classes if c not in hit] + [fixed_last]
    return classes


def _label(k: int | str) -> str:
    return f"link {k}" if isinstance(k, int) else f"joint {k}"


def _words(n: ModeName, nangles: int) -> str:
    parts = []
    if n.coincident:
        parts.append("folded mode: " + ", ".join(" = ".join(c) for c in _classes(n.coincident)))
    if n.parallelograms:
        parts.append("parallelogram mode: " + ", ".join(" ".join(q) for q in n.parallelograms))
    if n.anti_parallelograms:
        parts.append("anti-parallelogram mode (crossed): " + ", ".join(" ".join(q) for q in n.anti_parallelograms))
    if n.parallel_links and not parts:
        parts.append("parallel links: " + ", ".join(
            f"{_label(i)} and {j} {'same direction' if how == 'same' else 'opposite directions'}"
            for i, j, how in n.parallel_links))
    if n.frozen:
        if nangles and len(n.frozen) == nangles:
            parts.append("every link frozen (only the prismatic lengths or slider points move)")
        else:
            parts.append(", ".join(f"{_label(k)} frozen" + (f" at {a:g}°" if a is not None else " (at an algebraic angle)")
                                   for k, a in n.frozen))
    return "; ".join(parts) if parts else "general mode"


_CACHE: dict[int, tuple[Any, list]] = {}
#: Seconds of CPU time the names of one analysis may take together (a busy machine does not change them).
BUDGET = 10.0


def mode_names(a: Any) -> list[Optional[ModeName]]:
    """The names of the motion modes of the analysis ``a`` (numeric lengths; None for a mode
    whose name did not finish within the shared :data:`BUDGET`; [] with symbolic lengths)."""
    hit = _CACHE.get(id(a))
    if hit is not None and hit[0] is a:
        return hit[1]
    import time
    from mech.dsl.limits import REPORT_KEEP, cut, remaining, within
    names: list[Optional[ModeName]] = []
    if not a.params:
        deadline = time.thread_time() + BUDGET
        for md in a.modes:
            seconds = cut(deadline - time.thread_time(), REPORT_KEEP)  # never beyond the statement's limit
            ok, n = within(seconds, name_mode, a.mechanism, md.prime, md.dim, cpu=True, reserve=REPORT_KEEP) \
                if seconds > 0 else (False, None)
            names.append(n if ok else None)
    if remaining() is None or all(names):  # names cut short by the statement's time limit: again next time
        _CACHE[id(a)] = (a, names)
    return names
