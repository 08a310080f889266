"""Helpers shared by the tests: running mech code, parsing Singular's long-form output, running Singular."""
from __future__ import annotations

import re
import shutil
import subprocess
from fractions import Fraction
from pathlib import Path

import pytest

from mech import MechError, Session
from mech.kernel import QQ, MonomialOrder, Poly, PolyRing

SINGULAR = shutil.which("Singular")
#: The checkout's root (examples/, docs/, tests/corpus/ are found from it).
ROOT = Path(__file__).resolve().parent.parent


def run(src: str) -> str:
    """What ``src`` prints in a fresh session."""
    return Session().execute(src)


def error(src: str, kind: type = MechError) -> MechError:
    """The error ``src`` raises in a fresh session; it must be located and shown with the source line
    and a caret under it."""
    with pytest.raises(kind) as info:
        run(src)
    e = info.value
    assert e.line > 0 and "^" in e.format().splitlines()[2], e.format()
    return e


def parse_poly(ring: PolyRing, text: str) -> Poly:
    """A polynomial from Singular's long form (``3*x^2*y-1/2*z``)."""
    names = {n: g for n, g in zip(ring.names, ring.gens())}
    expr = re.sub(r"(\d+)/(\d+)", r"Fraction(\1,\2)", text.replace("^", "**"))
    value = eval(expr, {"__builtins__": {}}, _Scope(ring, names))  # noqa: S307 - test data only
    return value if isinstance(value, Poly) else ring.const(value)


class _Scope(dict):
    def __init__(self, ring: PolyRing, names: dict[str, Poly]) -> None:
        super().__init__(names, Fraction=Fraction)
        self.ring = ring

    def __missing__(self, key: str):
        raise NameError(key)


def ideal_blocks(output: str) -> list[list[str]]:
    """The ideals printed as consecutive ``name[i]=...`` lines, in order."""
    blocks: list[list[str]] = []
    for line in output.splitlines():
        m = re.match(r"^\s*[\w_]*\[(\d+)\]=(.*)$", line)
        if not m:
            continue
        if m.group(1) == "1":
            blocks.append([])
        blocks[-1].append(m.group(2))
    return blocks


def run_singular(script: str, timeout: float = 120) -> str:
    """Singular's output for a script (``quit;`` appended)."""
    assert SINGULAR, "Singular is not installed"
    res = subprocess.run([SINGULAR, "-q", "--no-warn"], input=script + "\nquit;\n", text=True,
                         capture_output=True, timeout=timeout)
    return res.stdout



def run_m2(script: str, tmp_path: Path, timeout: float = 120) -> str:
    """Macaulay2's output for a script (``M2 --script``: only what it prints)."""
    f = tmp_path / "case.m2"
    f.write_text(script)
    return subprocess.run([shutil.which("M2") or "M2", "--script", str(f)], capture_output=True, text=True,
                          timeout=timeout).stdout


def m2_case_tests(cases: list[tuple[str, str, str]], prelude: str = "") -> tuple:
    """The two tests of a list of (name, script, what Macaulay2 1.21 prints for it): mech's Macaulay2
    dialect prints it, and (marked ``macaulay2``) Macaulay2 does, the script after ``prelude``."""
    ids = [c[0] for c in cases]

    @pytest.mark.parametrize("name, code, expected", cases, ids=ids)
    def test_cases(name: str, code: str, expected: str) -> None:
        assert Session(dialect="m2").execute(code) == expected

    @pytest.mark.macaulay2
    @pytest.mark.parametrize("name, code, expected", cases, ids=ids)
    def test_cases_are_macaulay2s(tmp_path, name: str, code: str, expected: str) -> None:
        assert run_m2(prelude + code, tmp_path) == expected
    return test_cases, test_cases_are_macaulay2s


def output_lines(text: str) -> list[str]:
    """The lines of an output that carry values: blank lines and Singular's `// **` notes dropped."""
    return [ln.rstrip() for ln in text.splitlines() if ln.strip() and not ln.startswith("// **")]

# ---------------------------------------------------------------- benchmark systems
def ring(names, blocks, field=QQ):
    """A polynomial ring with a block ordering."""
    return PolyRing(field, names, MonomialOrder(blocks))


def katsura(R, n):
    """katsura-n in the first n+1 variables of R."""
    X = R.gens()

    def V(i):
        i = abs(i)
        return X[i] if i <= n else R.zero()
    ideal = [sum((V(j) for j in range(-n, n + 1)), R.zero()) - 1]
    for m in range(n):
        ideal.append(sum((V(j) * V(m - j) for j in range(-n, n + 1)), R.zero()) - V(m))
    return ideal


def cyclic(R):
    """cyclic-n in the n variables of R."""
    X, n = R.gens(), R.nvars
    ideal = []
    for d in range(1, n):
        p = R.zero()
        for i in range(n):
            t = R.one()
            for k in range(d):
                t = t * X[(i + k) % n]
            p = p + t
        ideal.append(p)
    t = R.one()
    for x in X:
        t = t * x
    return ideal + [t - 1]


class LongCCall:
    """A stand-in for one long python-flint call, which the limits' watchdog cannot interrupt: it
    blocks in C (a lock) until the watchdog has checked the statement past its time limit while a
    budget's exception was pending (``overlap`` is then set), so both fall inside it whatever the
    machine's speed.  Installed on ``mech.dsl.limits``'s watchdog through ``monkeypatch``."""

    def __init__(self, monkeypatch: pytest.MonkeyPatch, wait: float = 60.0) -> None:
        import threading

        from mech.dsl import limits
        self.wait = wait
        self.overlap = threading.Event()
        self.gate = threading.Lock()
        self.gate.acquire()
        check = limits._WATCHDOG._check_thread

        def spy(watches: list, now: float, rss: int | None) -> None:
            check(watches, now, rss)
            statement = next((w for w in watches if not w.budget), None)
            if statement is not None and statement.deadline is not None and now >= statement.deadline \
                    and any(w.fired for w in watches if w.budget) and not self.overlap.is_set():
                self.overlap.set()
                self.gate.release()
        monkeypatch.setattr(limits._WATCHDOG, "_check_thread", spy)

    def __call__(self, *args: object) -> None:
        self.gate.acquire(timeout=self.wait)  # one C call: asynchronous exceptions wait for its end
