"""polylib.lib's subrInterred compared with Singular (global and local rings, char 0 and p)."""
from __future__ import annotations

import pytest

from tests.util import error, output_lines, run, run_singular

SCRIPT = """
LIB "polylib.lib";
ring r = 0,(x,y,z),dp;
ideal mon = x2, z, xy;
subrInterred(mon, ideal(x2+xy2, xy+x2y, z), intvec(1,3));
ring s = 7,(x,y,t),(c,ds);
ideal mon = x2, xy;
subrInterred(mon, ideal(x2+3xyt2, x2t+xy, 2xy), intvec(1,2));
ring s2 = 0,(x,y,t,u),dp;
ideal mon = x2, xy, y2;
subrInterred(mon, ideal(x2*(t+u)+3xyt2, x2t+xy*u, 2xy+y2*t, y2*u2), intvec(1,2));
"""


@pytest.mark.singular
def test_as_singular() -> None:
    assert output_lines(run(SCRIPT)) == output_lines(run_singular(SCRIPT))


def test_checks() -> None:
    head = 'LIB "polylib.lib"; ring r = 0,(x,y,z),dp; '
    assert "monomials" in str(error(head + "subrInterred(ideal(x+y), ideal(x), intvec(1));"))
    assert "not a submodule" in str(error(head + "subrInterred(ideal(x2), ideal(x2+xy), intvec(1,2));"))
