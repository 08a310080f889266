"""Matrix operations of the Singular dialect compared with the installed Singular line by line: block
assignment M[rows, cols] = values, matrix +/- a scalar (a multiple of the unit matrix added on the
diagonal), matrix - ideal (the ideal as a 1 x n matrix), products of vectors and modules as matrices,
a vector's components by an intvec, ideal + vector,
and the errors Singular gives for sizes that do not match and for module * module."""
from __future__ import annotations

import pytest

from tests.util import error, output_lines, run, run_singular

pytestmark = pytest.mark.singular

SNIPPETS = {
    "block_assignment": """
ring r = 0,(x,y),dp;
matrix A[3][3];
A[2,1..3] = 1,2,3;
matrix B[2][2] = x,y,x2,y2;
A[2..3,2..3] = B;
print(A);
A[1..2,1] = x+y, 5;
print(A);
""",
    "scalars": """
ring r = 0,(x,y),dp;
matrix E[2][3] = x,y,1,2,3,4;
print(E+1); print(E-x); print(1+E); print(E+2/3);
matrix F[2][2] = x,y,0,1;
print(F+2); print(F-y);
matrix G[1][2] = x,y;
print(G-ideal(x2,1));
""",
    "vector_products": """
ring r = 0,(x,y),dp;
vector v = [x]; module m = [y]; v*v; v*m; m*v;
module m2 = [x,y],[y,1]; vector w = [x,1]; print(matrix(m2)*w);
ring s = 0,(x,y,z),(c,dp);
module M = [1,2]; vector u = [x,y,z];
M+u[1..2]; M+u[2..3]; u[1..2]; ideal I = x; I+u[1..2]; u[3]+I;
""",
}


@pytest.mark.parametrize("name", sorted(SNIPPETS))
def test_as_singular(name: str) -> None:
    src = SNIPPETS[name]
    assert output_lines(run(src)) == output_lines(run_singular(src))


def test_sizes_that_do_not_match_are_errors() -> None:
    """Singular refuses them ("matrix size not compatible"); so does mech."""
    assert "do not match" in str(error("ring r = 0,x,dp; matrix F[2][2] = x,1,0,1; F - ideal(x, x);"))
    assert "do not match" in str(error("ring r = 0,x,dp; matrix F[2][2] = x,1,0,1; x - F;"))
    assert "values" in str(error("ring r = 0,x,dp; matrix F[2][2]; F[1..2,1..2] = 1,2,3;"))
    assert "no product of two submodules" in str(error("ring r = 0,x,dp; module m = [x]; m*m;"))
    assert "not compatible" in str(error("ring r = 0,(x,y),dp; vector v = [x,y]; v*v;"))
