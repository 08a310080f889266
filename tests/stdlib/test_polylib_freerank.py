"""polylib.lib's freerank compared with Singular (free and non-free cokernels, pruned unit relations)."""
from __future__ import annotations

import pytest

from tests.util import output_lines, run, run_singular

SCRIPT = """
LIB "polylib.lib";
ring r;
module M = [x,0,1], [-x,0,-1];
freerank(M);
freerank(syz(M), "");
freerank(ideal(x));
freerank(syz(ideal(x)));
ring s = 0,(x,y,z),dp;
freerank(module([x,y],[y,x]));
freerank(module([1,x,y],[0,0,0]));
freerank(matrix(ideal(x,y)));
freerank(module([1,0,x],[0,1,y],[x,y,z]));
freerank(syz(ideal(x,y)), 1);
freerank(poly(0));
freerank(module([0,0,1]));
"""


@pytest.mark.singular
def test_as_singular() -> None:
    assert output_lines(run(SCRIPT)) == output_lines(run_singular(SCRIPT))


def test_values() -> None:
    """coker of [1,x],[0,y] is R/(y) (not free); of [1,x],[0,1] is 0 (free of rank 0); of 0 is R."""
    src = 'LIB "polylib.lib"; ring r = 0,(x,y),dp; freerank(module([1,x],[0,y])); freerank(module([1,x],[0,1]));'
    assert run(src + "freerank(ideal(0));") == "-1\n0\n1\n"
