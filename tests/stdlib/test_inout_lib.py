"""inout.lib's show (its indentation argument, maps) and size of a ring, against Singular."""
from __future__ import annotations

import pytest

from tests.util import run, run_singular


SHOW_AND_SIZE = """LIB "inout.lib";
ring r;
ideal i = x3+y5-6z3, xy;
show(i, 3);
ring S = (0,T),(a,b,c,d),dp;
map F = r, a2, b2, 3c3;
show(F);
size(S);
ring r1 = (2,a),x,dp; minpoly = a4+a+1;
size(r1);
ring r2 = 32003,(x,y),dp;
size(r2);
"""


@pytest.mark.parametrize("with_singular", [False, pytest.param(True, marks=pytest.mark.singular)])
def test_show_indents_and_shows_maps_and_size_of_a_ring_counts_the_field(with_singular: bool) -> None:
    expected = """   // ideal, 2 generator(s)
y5+x3-6z3,
xy
// i-th variable of preimage ring is mapped to @map[i]
// @map map  from r
@map[1]=a2
@map[2]=b2
@map[3]=3*c3
-1
16
32003"""
    got = run(SHOW_AND_SIZE)
    assert got.splitlines() == (run_singular(SHOW_AND_SIZE) if with_singular else expected).splitlines()
