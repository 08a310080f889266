"""The linear solve ``V X = N`` over QQ of FGLM's tails (:mod:`.fglm`), multimodular and in
the process.

``X`` is found modulo word-size primes (flint's ``nmod_mat.solve``, each call a few
milliseconds), lifted by Chinese remaindering and rational reconstruction
(matrix-wise, and :class:`~.modular.Reconstructor`), and accepted only when
``V X == N`` holds exactly.  Every step is a short C call, so an interrupt or a limit stops it
between primes; no child process is needed (systems small enough to take well under a second
in the worst case go to flint's solve directly) (``offload_exact.solve`` forks one when its
worst-case estimate for ``fmpq_mat.solve`` is large: on FGLM's sparse systems that estimate
was a thousand times the real time, and the fork cost far more than the solve).  After
:data:`MAX_PRIMES` primes without an answer the solve goes to ``offload_exact.solve``.
"""
from __future__ import annotations

from typing import Any, Iterator

import flint

from . import offload_exact
from .modular import Reconstructor

MAX_PRIMES = 400  # of about 62 bits: answers up to ~12000 bits per entry

DIRECT = 0.25
"""Systems whose dense worst case (:func:`direct_seconds`) is below this many seconds go to
flint's ``fmpq_mat.solve`` directly (faster than the multimodular loop on large answers:
katsura-5 in ``lp``, D = 32 with 2700-bit entries, 11 ms against 35 ms).  That is one C call:
entries far above 24 bits make it longer before an interrupt is seen (a script's time limit
still ends it through ``mech/watcher.py``)."""


def direct_seconds(D: int, L: int) -> float:
    """A bound for ``fmpq_mat.solve`` on ``D x D`` and ``D x L`` matrices of random dense 24-bit
    entries (python-flint 0.9 on the project's machine: D = 40, L = 40 in 0.03 s; D = 156,
    L = 39 in 0.87 s; FGLM's own systems of these sizes take 2 and 26 ms)."""
    return 6e-9 * D ** 3 * (D + L)


def _primes() -> Iterator[int]:
    """Primes below ``2^62``, decreasing."""
    n = (1 << 62) - 1
    while True:
        n -= 2
        if flint.fmpz(n).is_prime():
            yield n


def solve_qq(V: Any, N: Any) -> Any:
    """``X`` with ``V X = N`` (``fmpq_mat``; ``V`` square); ZeroDivisionError when ``V`` is
    singular.  Small systems by flint's solve, the others multimodular."""
    D, L = N.nrows(), N.ncols()
    if direct_seconds(D, L) < DIRECT:
        return V.solve(N)
    Vn, dv = V.numer_denom()
    Nn, dn = N.numer_denom()
    scale = flint.fmpq(dv, dn)  # V X = N  <=>  Vn X = (dv / dn) Nn
    rec = Reconstructor([D] * L)
    Y, m = None, 1  # Vn^-1 Nn modulo m, lifted (an fmpz_mat with entries in [0, m))
    unlucky, attempt_at = 0, 0
    for used, p in enumerate(_primes()):
        if used == MAX_PRIMES:
            break
        try:
            Yp = flint.nmod_mat(Vn, p).solve(flint.nmod_mat(Nn, p))
        except ZeroDivisionError:  # singular mod p: V is singular, or p divides its determinant
            unlucky += 1
            if Y is None and unlucky >= 3:
                raise
            continue
        if Y is None:
            Y, m = flint.fmpz_mat(D, L, [int(v) for v in Yp.entries()]), p
        else:  # Chinese remaindering, matrix-wise: Y + m ((Yp - Y) / m mod p)
            t = (Yp - flint.nmod_mat(Y, p)) * pow(m, -1, p)
            Y += flint.fmpz_mat(D, L, [int(v) for v in t.entries()]) * m
            m *= p
        if m.bit_length() < attempt_at:
            continue
        attempt_at = m.bit_length() * 5 // 4  # reconstruction attempts at geometric sizes
        ys = [int(v) for v in Y.transpose().entries()]
        got = rec.attempt([ys[c * D:(c + 1) * D] for c in range(L)], m)
        if got is None:
            continue
        X = flint.fmpq_mat(D, L, [got[c][r] * scale for r in range(D) for c in range(L)])
        if V * X == N:
            return X
        rec.reset()
    return offload_exact.solve(V, N)
