"""Singular's machine int in the Singular dialect: literals beyond 2^31-1 are bigints, + - * ^ wrap
around 64 bits with an overflow warning, div and mod read their operands as 32-bit ints; compared
with the installed Singular."""
from __future__ import annotations

import pytest

from tests.util import error, output_lines, run, run_singular

SCRIPT = """
int a = 100000*100000; a; a div 7; a mod 7; a + 1; a*3; -a;
int b = 2147483647; b+1; b*b; b*b*b; 2^40; 2^63; 2^64; 3^50;
int m = 2^62; m+m; -m-m-m;
11*13*17*100*200*2000*503*1111*222222;
typeof(2147483647); typeof(2147483648); typeof(-2147483648); typeof(10000000000 div 3);
2^31 div 2;
int k = 1; for (int j = 1; j <= 25; j++) { k = k*j; } k;
proc fak(int n) { if (n <= 1) { return(1); } return(n * fak(n-1)); }
fak(13) div fak(12);
ring r = 0,x,dp; poly f = 3000000000*x; f; typeof(3000000000*2);
"""


def test_wrap_around_and_warnings() -> None:
    out = run("int b = 2147483647; b*b*b; 3^99999999; 11*13*17*100*200*2000*503*1111*222222;")
    assert out == ("// ** int overflow(*), result may be wrong\n4611686024869838847\n"
                   "// ** int overflow(^), result may be wrong\n1826112817018578603\n"
                   "// ** int overflow(*), result may be wrong\n-6869239595516308480\n")


def test_big_literal_is_a_bigint() -> None:
    assert run("typeof(2147483647); typeof(2147483648); bigint c = 12345678901234567890; c*c;") == \
        "int\nbigint\n152415787532388367501905199875019052100\n"
    assert "int = bigint" in str(error("int i = 12345678901234567890;"))


@pytest.mark.singular
def test_as_singular() -> None:
    assert output_lines(run(SCRIPT)) == output_lines(run_singular(SCRIPT))
