"""``noether = m;`` (dsl/noether.py): per ring, read back, std and reduce truncated below it,
against Singular."""
import pytest
from tests.util import error, run, run_singular

NOETHER_SRC = """ring R = 32003,(x,y,z),ds;
ideal i = x2+y12, y13;
std(i);
noether = x11;
std(i);
noether;
ring S = 32003,(a,b),ds;
noether;
setring R;
std(ideal(z+x11+y11, y12, x12));
noether = x5;
reduce(z+x5+x4y+x3y2, std(ideal(z3)));
noether = 0;
std(i);
"""


@pytest.mark.singular
def test_noether_matches_singular():
    assert run(NOETHER_SRC).split() == run_singular(NOETHER_SRC).split()


def test_noether_is_refused_where_the_corner_is_not_a_degree_cut():
    assert "local degree orderings" in str(error("ring r = 0,(x,y),ls; noether = x3;"))
