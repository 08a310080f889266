"""The modular lift's rational reconstruction (kernel/modular.py's Reconstructor): the compiled
loops (kernel/_f4lift.c) give the same coefficients, resume points, heights and checks as the
pure-Python ones."""
import random

import flint
import pytest

from mech.kernel import modular
from mech.kernel.modular import Reconstructor

compiled = pytest.mark.skipif(modular.RATREC_ROWS is None, reason="the compiled lift is not built")


def residues(rng: random.Random, m: int) -> list[list[int]]:
    """Rows of small fractions mod m, now and then a residue with no small fraction."""
    rows = []
    for _ in range(rng.randrange(1, 5)):
        row = []
        for _ in range(rng.randrange(1, 30)):
            n, d = rng.randrange(-300, 300), rng.randrange(1, 50)
            row.append(rng.randrange(m) if rng.random() < 0.05 else n * pow(d, -1, m) % m)
        rows.append(row)
    return rows


def lift(rows, m, use_compiled, monkeypatch):
    if not use_compiled:
        monkeypatch.setattr(modular, "RATREC_ROWS", None)
        monkeypatch.setattr(modular, "AGREE_ROWS", None)
        monkeypatch.setattr(modular, "FRACTIONS", None)
    rec = Reconstructor([len(r) for r in rows])
    got = rec.attempt(rows, m)
    monkeypatch.undo()
    return rec, got


@compiled
@pytest.mark.parametrize("m", [(1 << 27) + 29, 1000003 * 1000033, (1 << 61) - 1])
def test_compiled_and_python_lifts_agree(m, monkeypatch):
    rng = random.Random(m)
    for _ in range(40):
        rows = residues(rng, m)
        ours, got = lift(rows, m, True, monkeypatch)
        theirs, want = lift(rows, m, False, monkeypatch)
        assert got == want
        assert ours.out == theirs.out and (ours.i, ours.j, ours.den) == (theirs.i, theirs.j, theirs.den)
        if got is not None:
            assert ours.height == max(c.height_bits() for row in got for c in row)
            assert ours.confident() == theirs.confident()


@compiled
def test_compiled_and_python_checks_agree(monkeypatch):
    """Against another prime's residues, right ones and ones with a wrong coefficient."""
    rng = random.Random(5)
    m, p = 1000003 * 1000033, 998244353
    for _ in range(40):
        fracs = [[(rng.randrange(-300, 300), rng.randrange(1, 50)) for _ in range(rng.randrange(1, 20))]
                 for _ in range(3)]
        rows = [[n * pow(d, -1, m) % m for n, d in row] for row in fracs]
        mod_p = [[n * pow(d, -1, p) % p for n, d in row] for row in fracs]
        if rng.random() < 0.5:
            i = rng.randrange(3)
            mod_p[i][rng.randrange(len(mod_p[i]))] += 1
        ours, _ = lift(rows, m, True, monkeypatch)
        theirs, _ = lift(rows, m, False, monkeypatch)
        disagrees = ours.check(mod_p, p)  # compiled
        monkeypatch.setattr(modular, "AGREE_ROWS", None)
        assert disagrees == theirs.check(mod_p, p)
        monkeypatch.undo()
        assert (ours.i, ours.j, ours.den) == (theirs.i, theirs.j, theirs.den)


@compiled
def test_fractions_of_any_size():
    """The compiled lift's fractions (small integers shared through the cache)."""
    rows = [[(2**70, 1), (3, 1), (-5, 7), (2**80 + 1, 3**50), (-32767, 1), (32768, 1)], [(3, 1)]]
    cache = {}
    got = modular.FRACTIONS(rows, flint.fmpq, cache)
    assert got == [[flint.fmpq(n, d) for n, d in row] for row in rows]
    assert all(type(q) is flint.fmpq for row in got for q in row)
    assert sorted(cache) == [(-32767, 1), (-5, 7), (3, 1)] and got[1][0] is got[0][1]
