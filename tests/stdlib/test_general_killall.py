"""general.lib's killall compared with Singular: all, one type, all but some, procedures."""
from __future__ import annotations

import pytest

from tests.util import error, output_lines, run, run_singular

SCRIPTS = [
    'LIB "general.lib"; ring r = 0,(x,y),dp; int k = 1; string s = "a"; list L = 1, 2; killall("list"); listvar();'
    ' killall(); listvar(); int k = 2; killall("proc"); listvar();',
    'LIB "general.lib"; proc p() { return(1); } ring rtest; ideal i = x, y; string str = "hi"; int j = 3;'
    ' intvec v = 1, 2; poly f = x; ring s2; killall("ring"); listvar(); killall(); listvar(); killall("proc");'
    ' listvar();',
]


@pytest.mark.singular
@pytest.mark.parametrize("src", SCRIPTS)
def test_as_singular(src: str) -> None:
    assert output_lines(run(src)) == output_lines(run_singular(src))


def test_all_but() -> None:
    """killall("not", ...) as its help says (Singular's stops at general.lib's package: see the module)."""
    src = ('LIB "general.lib"; ring r; int k = 1; string s = "a"; list L = 1; intvec v = 1; ideal i = x;'
           'killall("not", "int", "L"); listvar();')
    assert run(src) == ("// v                              [0]  intvec (1)\n"
                        "// L                              [0]  list, size: 1\n"
                        "// k                              [0]  int 1\n")


def test_arguments_are_strings() -> None:
    assert "Need string as 1th argument" in str(error('LIB "general.lib"; killall(1);'))
