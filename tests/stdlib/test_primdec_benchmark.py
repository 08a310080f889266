"""The decomposition benchmark's cases (benchmarks/primdec.py): the timed statement of a library
example, the Macaulay2 tests it keeps and how it writes them for Macaulay2; the installed files'
tests skip when Singular's or Macaulay2's files are absent."""
from __future__ import annotations

import re
import sys

import pytest

from tests.util import ROOT

sys.path.insert(0, str(ROOT / "benchmarks"))

import primdec  # noqa: E402

LIBRARY = '''
proc minAssGTZ(ideal i) { return(i); }
example
{ "EXAMPLE:";  echo = 2;
   ring  r = 0,(x,y),dp;
   ideal i = x2,
             y;
   list pr = minAssGTZ(i);
   pr;
}
static proc hidden(ideal i) { return(i); }
example
{ ring r = 0,x,dp; hidden(x); }
proc equidim(ideal i) { return(i); }
example
{ "EXAMPLE:"; echo = 2;
   ring  r = 32003,(x,y,z),dp;
   ideal i = x*y;
   equidim(i);
}
'''


def test_library_example_setup_command_and_result():
    gtz, equidim = primdec.library_cases(LIBRARY)
    assert gtz.setup == "ring  r = 0,(x,y),dp;\nideal i = x2,\n             y;\n"
    assert (gtz.command, gtz.result) == ("list pr = minAssGTZ(i);", "pr")
    assert (equidim.command, equidim.result) == ("def value = equidim(i);", "value")
    assert gtz.m2 is None


@pytest.mark.skipif(not primdec.PRIMDEC_LIB.exists(), reason="Singular's primdec.lib not installed")
def test_installed_library_gives_one_case_per_procedure():
    cases = primdec.library_cases(primdec.PRIMDEC_LIB.read_text(errors="replace"))
    assert {c.name.split()[1] for c in cases} == set(primdec.LIB_PROCS)
    for case in cases:
        assert case.command.rstrip(";").split("(")[0].split()[-1] in primdec.LIB_PROCS
        assert "ring" in case.setup and case.result in case.command


@pytest.mark.skipif(not primdec.m2_examples(), reason="Macaulay2's MinimalPrimes tests not installed")
def test_minimal_primes_cases_polynomial_ideals_in_m2_syntax():
    cases = primdec.minimal_primes_cases()
    assert cases and all(c.command == "list L = minAssGTZ(I);" and c.m2 for c in cases)
    for case in cases:
        ideal = case.setup.split("ideal I = ")[1]
        assert "/(" not in ideal.replace(" ", "") or not any(ch.isalpha() for ch in ideal.split("/(")[1].split(")")[0])
        m2_ideal = case.m2.split("I = ")[1]
        assert m2_ideal.startswith("ideal(") or not re.search(r"[*^]", m2_ideal)  # M2's strings read a2b only
        assert not re.search(r"[\w)]\s*\(", ideal)  # M2's juxtaposed products written with *
        assert set(re.findall(r"[A-Za-z]", ideal)) <= set(case.setup.split("(")[1].split(")")[0].split(","))


def test_components_and_seconds():
    assert primdec.components("[1]:\n   _[1]=x\n[2]:\n   [1]:\n      _[1]=y\n") == "2"
    assert primdec.components("_[1]=x\n") == "ideal"
    assert primdec._seconds(primdec.Timing(None, note="> 60 s")) == "> 60 s"
    assert primdec._seconds(primdec.Timing(0.0123)) == "12 ms"
    assert primdec._seconds(primdec.Timing(0.00123)) == "1.2 ms"
    assert primdec._seconds(primdec.Timing(12.34)) == "12.3 s"
