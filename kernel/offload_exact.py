"""Single python-flint calls of exact linear algebra and univariate polynomials that can run long:
a linear solve or a characteristic polynomial over Q (FGLM's tails, the real solver's rational
univariate representation and Hermite's form), the squarefree decomposition or the factorization
of an integer polynomial (real-root isolation).  Each goes through :mod:`.offload`, so an interrupt
or a limit stops it; a rough estimate of its time from the sizes keeps the cheap ones (nearly
all) in the process.  The constants were measured with python-flint 0.9 on the project's machine
on random dense entries, the worst case; sparse input is overestimated (then a child costs a fork,
about 0.1 s, for a call of a fraction of a second), never underestimated."""
from __future__ import annotations

from typing import Any

from . import offload

_SOLVE = 1.5e-7     # seconds per D^3 (D + L) of fmpq_mat.solve (D = 40, 24-bit entries: 0.75 s)
_CHARPOLY = 4e-8    # seconds per D^4 of fmpq_mat.charpoly (D = 80, 24-bit entries: 2.3 s)
_SQUAREFREE = 2e-10  # seconds per n^2 bits of fmpz_poly.factor_squarefree (n = 3200, 2048 bits: 3.6 s)
_FACTOR = 2e-9      # the same for fmpz_poly.factor (recombination makes it dearer)


def _bits(x: Any) -> int:
    """Bits of an fmpz or fmpq (numerator and denominator)."""
    if hasattr(x, "q"):
        return int(x.p).bit_length() + int(x.q).bit_length()
    return int(x).bit_length()


def _mat_size(*mats: Any) -> float:
    """A size factor of matrices' entries (1 for 32-bit ones; the largest entry counts)."""
    return max(1.0, max((_bits(x) for M in mats for x in M.entries()), default=0) / 32)


def _poly_bits(p: Any) -> int:
    """The largest coefficient's bits (a sparse polynomial with huge coefficients has dense
    intermediate results as large)."""
    return max((_bits(c) for c in p.coeffs()), default=0)


def solve_seconds(V: Any, N: Any) -> float:
    D, L = V.nrows(), N.ncols()
    return _SOLVE * D ** 3 * (D + L) * _mat_size(V, N)


def charpoly_seconds(M: Any) -> float:
    return _CHARPOLY * M.nrows() ** 4 * _mat_size(M)


def solve(V: Any, N: Any) -> Any:
    """``V.solve(N)`` (ZeroDivisionError when ``V`` is singular)."""
    return offload.call(lambda: solve_seconds(V, N), V.solve, N)


def charpoly(M: Any) -> Any:
    """``M.charpoly()``."""
    return offload.call(lambda: charpoly_seconds(M), M.charpoly)


def factor_squarefree(p: Any) -> Any:
    """``p.factor_squarefree()`` of an integer polynomial."""
    return offload.call(lambda: _SQUAREFREE * p.degree() ** 2 * _poly_bits(p), p.factor_squarefree)


def factor(p: Any) -> Any:
    """``p.factor()`` of an integer (or rational) univariate polynomial."""
    return offload.call(lambda: _FACTOR * p.degree() ** 2 * _poly_bits(p), p.factor)
