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


_KEYS: dict[tuple, tuple[Callable[[Exp], tuple], Callable[[Exp], tuple]]] = {}
"""The sort keys of the orderings built so far, by blocks and matrix."""


class MonomialOrder:
    """A monomial ordering on ``nvars`` variables, built from blocks."""

    def __init__(self, blocks: Sequence[Block], nvars: int | None = None) -> None:
        self.blocks = tuple(blocks)
        covered = sum(b.size for b in self.blocks if b.kind != "a")
        self.nvars = covered if nvars is None else nvars
        if covered != self.nvars:
            raise OrderingError(f"the ordering covers {covered} variables, the ring has {self.nvars}")
        self.matrix = self._matrix()
        sig = (self.blocks, tuple(map(tuple, self.matrix)))
        if sig not in _KEYS:  # checking and compiling cost more than many small Gröbner bases
            self._check_nondegenerate()
            # neg_key sorts monomials from the largest down (heaps)
            _KEYS[sig] = (self._compile(), _linear_key([[-v for v in r] for r in self.matrix]))
        self.key: Callable[[Exp], tuple]
        self.neg_key: Callable[[Exp], tuple]
        self.key, self.neg_key = _KEYS[sig]
        signs = []
        for j in range(self.nvars):
            col = [r[j] for r in self.matrix if r[j] != 0]
            signs.append(1 if col[0] > 0 else -1)
        self.is_global = all(s > 0 for s in signs)
        self.is_local = all(s < 0 for s in signs)
        # the first weight row is positive: the ordering refines a (weighted) degree
        self.is_graded = all(w > 0 for w in self.matrix[0])

    @classmethod
    def simple(cls, kind: str, nvars: int, weights: Sequence[int] = ()) -> "MonomialOrder":
        """One-block ordering, e.g. ``MonomialOrder.simple("dp", 3)``."""
        return cls([Block(kind, nvars, tuple(weights))])

    def _matrix(self) -> list[list[int]]:
        n, rows, start = self.nvars, [], 0
        for b in self.blocks:
            for r in b.rows():
                full = [0] * n
                full[start:start + len(r)] = r
                rows.append(full)
            if b.kind != "a":
                start += b.size
        return rows

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
        real = [b for b in self.blocks if b.kind != "a"]
        if len(real) == len(self.blocks) == 1 and real[0].kind in ("dp", "lp", "Dp", "ds", "ls", "Ds"):
            k = real[0].kind
            if k == "lp":
                return lambda e: e
            if k == "dp":
                return lambda e: (sum(e), *[-v for v in reversed(e)])
            if k == "Dp":
                return lambda e: (sum(e), *e)
            if k == "ls":
                return lambda e: tuple(-v for v in e)
            if k == "ds":
                return lambda e: (-sum(e), *[-v for v in reversed(e)])
            return lambda e: (-sum(e), *e)
        return _linear_key(self.matrix)

    def compare(self, a: Exp, b: Exp) -> int:
        """-1, 0 or 1 as ``x^a`` is smaller than, equal to or greater than ``x^b``."""
        ka, kb = self.key(a), self.key(b)
        return (ka > kb) - (ka < kb)

    def is_elimination_for(self, vars_: Sequence[int]) -> bool:
        """Whether every monomial involving one of ``vars_`` is larger than every monomial
        free of them: true when leading rows of the matrix are nonnegative, vanish outside
        ``vars_`` and together cover ``vars_``."""
        want, covered = set(vars_), set()
        for row in self.matrix:
            support = {j for j, v in enumerate(row) if v}
            if any(v < 0 for v in row) or not support <= want:
                return False
            covered |= support
            if covered == want:
                return True
        return not want

    def __eq__(self, other: object) -> bool:
        return isinstance(other, MonomialOrder) and self.matrix == other.matrix

    def __hash__(self) -> int:
        return hash(tuple(map(tuple, self.matrix)))

    def __repr__(self) -> str:
        return f"MonomialOrder({list(self.blocks)!r})"


def _linear_key(matrix: list[list[int]]) -> Callable[[Exp], tuple]:
    """``e -> (row . e for each row)`` compiled to one Python expression (several times faster
    than a loop over the rows, and the key is evaluated for every monomial compared)."""
    def dot(row: list[int]) -> str:
        terms = [("e[%d]" % j if v == 1 else "-e[%d]" % j if v == -1 else "%d*e[%d]" % (v, j))
                 for j, v in enumerate(row) if v]
        return "+".join(terms).replace("+-", "-") or "0"
    source = "lambda e: (" + "".join(dot(r) + ", " for r in matrix) + ")"
    return eval(source)  # noqa: S307 - built from integers only

