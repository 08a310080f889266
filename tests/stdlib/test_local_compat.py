"""Singular commands in local orderings (eliminate) and simplify of a matrix, against Singular."""
import pytest
from tests.util import run, run_singular

ELIM_SRC = """ring r1 = 0,(t,x,y,z),ls;
ideal j1 = eliminate(ideal(x-t2, y-t3, z), t);
j1;
eliminate(ideal(y-t2, z-t3, x), t);
ring r2 = 0,(t,x,y),ds;
eliminate(ideal((1+x)*t-y, t-x), t);
ring r3 = 0,(x,y,z),dp;
matrix m[2][3] = x,0,y,z,0,1;
print(simplify(m, 2));
matrix n[2][2];
print(simplify(n, 2));
"""


@pytest.mark.singular
def test_eliminate_in_local_orderings_and_simplify_of_a_matrix_match_singular():
    assert run(ELIM_SRC).split() == run_singular(ELIM_SRC).split()
