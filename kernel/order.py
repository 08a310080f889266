"""Monomial orderings as weight matrices.

Every ordering mech knows (Singular's ``lp dp Dp wp Wp ls ds Ds ws Ws``, weight prefixes
``a(w)``, matrix orderings ``M(...)`` and blocks of these) is one integer matrix ``M``:
``x^a > x^b`` iff the first nonzero entry of ``M (a - b)`` is positive.  The ordering
compiles ``M`` into a sort key (a tuple) with fast paths for the common blocks.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Sequence

from .errors import OrderingError

Exp = tuple[int, ...]
Row = tuple[tuple[int, int], ...]
"""A sparse row of the weight matrix: ``(column, nonzero weight)`` pairs, columns increasing."""


@dataclass(frozen=True)
class Block:
    """One block of an ordering.

    ``kind`` is a Singular ordering name (``lp``, ``dp``, ``Dp``, ``wp``, ``Wp``, ``ls``,
    ``ds``, ``Ds``, ``ws``, ``Ws``), ``"a"`` for a weight prefix (it covers no variables of
    its own) or ``"M"`` for a matrix block (``weights`` holds the matrix row by row).
    """

    kind: str
    size: int
    weights: tuple[int, ...] = field(default=())

    def rows(self) -> list[list[int]]:
        """The block's weight matrix on its own variables (a prefix: on the next len(w))."""
        n, k, w = self.size, self.kind, list(self.weights)
        if k == "a":
            return [w]
        if k == "M":
            return [w[i * n:(i + 1) * n] for i in range(n)]
        unit = [[1 if j == i else 0 for j in range(n)] for i in range(n)]
        rev = [[-1 if j == n - 1 - i else 0 for j in range(n)] for i in range(n - 1)]
        if k == "lp":
            return unit
        if k == "ls":
            return [[-v for v in r] for r in unit]
        top = {"dp": [1] * n, "Dp": [1] * n, "ds": [-1] * n, "Ds": [-1] * n,
               "wp": w, "Wp": w, "ws": [-v for v in w], "Ws": [-v for v in w]}[k]
        tail = rev if k in ("dp", "ds", "wp", "ws") else unit
        return [top] + tail

    def sparse_rows(self, start: int) -> list[Row]:
        """The block's rows as ``((column, weight), ...)`` for variables from ``start`` on, without
        zeros: linear in the size for every kind but ``M`` (whose rows are its matrix)."""
        n, k = self.size, self.kind
        if k in ("a", "M"):
            return [tuple((start + j, v) for j, v in enumerate(r) if v) for r in self.rows()]
        if k in ("lp", "ls"):
            s = 1 if k == "lp" else -1
            return [((start + j, s),) for j in range(n)]
        w = [1] * n if k in ("dp", "Dp", "ds", "Ds") else list(self.weights)
        s = 1 if k in ("dp", "Dp", "wp", "Wp") else -1
        top = tuple((start + j, s * v) for j, v in enumerate(w) if v)
        if k in ("dp", "ds", "wp", "ws"):
            return [top] + [((start + n - 1 - i, -1),) for i in range(n - 1)]
        return [top] + [((start + j, 1),) for j in range(n)]


_GLOBAL = frozenset(("lp", "dp", "Dp", "wp", "Wp"))
_LOCAL = frozenset(("ls", "ds", "Ds", "ws", "Ws"))
_KEYS: dict[tuple, Callable[[Exp], tuple]] = {}
"""The sort keys of the orderings built so far, by blocks."""


class MonomialOrder:
    """A monomial ordering on ``nvars`` variables, built from blocks."""

    def __init__(self, blocks: Sequence[Block], nvars: int | None = None) -> None:
        self.blocks = tuple(blocks)
        covered = sum(b.size for b in self.blocks if b.kind != "a")
        self.nvars = covered if nvars is None else nvars
        if covered != self.nvars:
            raise OrderingError(f"the ordering covers {covered} variables, the ring has {self.nvars}")
        self._rows: tuple[Row, ...] | None = None
        self._dense: list[list[int]] | None = None
        self._hash: int | None = None
        if self.blocks not in _KEYS:  # checking and compiling cost more than many small Gröbner bases
            if not self._standard():
                self._check_nondegenerate()  # the standard blocks are monomial orderings
            _KEYS[self.blocks] = self._compile()
        self.key: Callable[[Exp], tuple] = _KEYS[self.blocks]
        if self._standard():  # from the blocks, without building rows
            kinds = {b.kind for b in self.blocks}
            self.is_global = kinds <= _GLOBAL
            self.is_local = kinds <= _LOCAL
            b = self.blocks[0] if self.blocks else None
            self.is_graded = b is not None and b.size == self.nvars and (
                b.kind in ("dp", "Dp", "wp", "Wp") or (b.kind == "lp" and b.size == 1))
        else:
            signs = [0] * self.nvars  # the sign of each variable's first nonzero weight
            for row in self.rows:
                for j, v in row:
                    if not signs[j]:
                        signs[j] = 1 if v > 0 else -1
            self.is_global = all(s > 0 for s in signs)
            self.is_local = all(s < 0 for s in signs)
            first = self.rows[0] if self.rows else ()
            self.is_graded = len(first) == self.nvars and all(v > 0 for _, v in first)
        # is_graded: the first weight row is positive, the ordering refines a (weighted) degree

    def _standard(self) -> bool:
        """Only Singular's named blocks with positive weights (no ``a`` or ``M``)."""
        return all(b.kind in _GLOBAL | _LOCAL and all(w > 0 for w in b.weights) for b in self.blocks)

    @property
    def rows(self) -> tuple[Row, ...]:
        """The weight matrix as sparse rows (built on first use, linear in the variables)."""
        if self._rows is None:
            self._rows = self._sparse_rows()
        return self._rows

    @property
    def matrix(self) -> list[list[int]]:
        """The dense weight matrix (built on first use: quadratic in the number of variables)."""
        if self._dense is None:
            self._dense = []
            for row in self.rows:
                full = [0] * self.nvars
                for j, v in row:
                    full[j] = v
                self._dense.append(full)
        return self._dense

    def first_row(self) -> list[int]:
        """The first row of the weight matrix, dense."""
        full = [0] * self.nvars
        for j, v in (self.rows[0] if self.rows else ()):
            full[j] = v
        return full

    @classmethod
    def simple(cls, kind: str, nvars: int, weights: Sequence[int] = ()) -> "MonomialOrder":
        """One-block ordering, e.g. ``MonomialOrder.simple("dp", 3)``."""
        return cls([Block(kind, nvars, tuple(weights))])

    def _sparse_rows(self) -> tuple[Row, ...]:
        rows, start = [], 0
        for b in self.blocks:
            rows += [r for r in b.sparse_rows(start) if r]
            if b.kind != "a":
                start += b.size
        return tuple(rows)

    def _check_nondegenerate(self) -> None:
        from fractions import Fraction
        m = [[Fraction(v) for v in r] for r in self.matrix]
        rank, n = 0, self.nvars
        for c in range(n):
            piv = next((i for i in range(rank, len(m)) if m[i][c] != 0), None)
            if piv is None:
                continue
            m[rank], m[piv] = m[piv], m[rank]
            for i in range(len(m)):
                if i != rank and m[i][c] != 0:
                    f = m[i][c] / m[rank][c]
                    m[i] = [a - f * b for a, b in zip(m[i], m[rank])]
            rank += 1
        if rank < n:
            raise OrderingError("the ordering is not a monomial ordering (degenerate weights)")

    def _compile(self) -> Callable[[Exp], tuple]:
        """The sort key ``e -> M e``, compiled to one Python expression: slices and sums for
        the standard blocks (linear in the variables), dot products for weights and matrices."""
        parts, start = [], 0
        for b in self.blocks:
            s, t, k = start, start + b.size, b.kind
            part = "e" if (s, t) == (0, self.nvars) else f"e[{s}:{t}]"
            if k == "lp":
                parts.append(f"*{part}")
            elif k == "ls":
                parts.append(f"*[-v for v in {part}]")
            elif k in ("dp", "ds", "Dp", "Ds"):
                parts.append(f"{'-' if k[1] == 's' else ''}sum({part})")
                if k[0] == "D":
                    parts.append(f"*{part}")
                elif b.size > 1:  # the reverse lexicographic tie-break
                    parts.append(f"*[-v for v in e[{t - 1}:{s - 1 if s else ''}:-1]]")
            else:
                parts += [_dot(r) for r in b.sparse_rows(start) if r]
            if k != "a":
                start = t
        return eval("lambda e: (" + ", ".join(parts) + ",)")  # noqa: S307 - built from integers only

    def compare(self, a: Exp, b: Exp) -> int:
        """-1, 0 or 1 as ``x^a`` is smaller than, equal to or greater than ``x^b``."""
        ka, kb = self.key(a), self.key(b)
        return (ka > kb) - (ka < kb)

    def is_elimination_for(self, vars_: Sequence[int]) -> bool:
        """Whether every monomial involving one of ``vars_`` is larger than every monomial
        free of them: true when leading rows of the matrix are nonnegative, vanish outside
        ``vars_`` and together cover ``vars_``."""
        want, covered = set(vars_), set()
        for row in self.rows:
            support = {j for j, _ in row}
            if any(v < 0 for _, v in row) or not support <= want:
                return False
            covered |= support
            if covered == want:
                return True
        return not want

    def __eq__(self, other: object) -> bool:
        if self is other:
            return True
        return isinstance(other, MonomialOrder) and (self.blocks == other.blocks or self.rows == other.rows)

    def __hash__(self) -> int:
        if self._hash is None:
            self._hash = hash(self.rows)
        return self._hash

    def __repr__(self) -> str:
        return f"MonomialOrder({list(self.blocks)!r})"


def _dot(row: Row) -> str:
    """The source of ``row . e``."""
    terms = [("e[%d]" % j if v == 1 else "-e[%d]" % j if v == -1 else "%d*e[%d]" % (v, j)) for j, v in row]
    return "+".join(terms).replace("+-", "-") or "0"
