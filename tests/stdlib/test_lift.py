"""lift (stdlib/lift.py): one implementation for ideals, modules and vectors — the same matrices as
Singular's, the zero matrix with a warning for a standard basis that does not contain the second
argument, an error otherwise, and over a qring a matrix that is right modulo its ideal."""
from __future__ import annotations

import pytest

from tests.util import SINGULAR, error, output_lines, run, run_singular

MODULES = """
ring A = 0,(x,y),dp;
ideal I = x10+x9y2,y8-x2y7;
print(lift(module(I), module(ideal(xy13+y12))));
print(lift(module(I), module(std(I))));
print(lift(module(ideal(xy+y2, x2, y3)), module(ideal(x2y)))); print(lift(module(ideal(x2, xy, y3)), module(ideal(x2y))));
print(lift(module(ideal(xy+y2, x2+y2)), module(ideal(x2y)))); print(lift(module(ideal(x2+y, xy)), module(ideal(x3y))));
module K = std(module(ideal(x2, xy+y2))); print(lift(K, module(ideal(x2y))));
print(lift(std(module(ideal(x2,y2))), module(ideal(x3+x2y+y, x2))));
module M = [x2, xy], [y, x+y], [x3, 0]; print(lift(M, module([x3y+x2y, x2y2+x2y+xy2], [x4y, 0])));
module N = std(M); print(N); print(lift(N, module([x3y+x2y, x2y2+x2y+xy2], [x4y, 0])));
print(lift(M, [x3y+x2y, x2y2+x2y+xy2]));
ring r1 = 32003,(x,y,z),(c,dp);
module i2 = std(module(jacob(y7+x3+xyz+z2)));
print(lift(i2, module(ideal(3x2+yz,7y6+2x2y+5xz))));
module M = [x2, xy], [y, x+y], [x3, 0]; print(lift(M, module([x3y+x2y, x2y2+x2y+xy2], [x4y, 0])));
matrix U; print(lift(M, module([x3y+x2y, x2y2+x2y+xy2], [x4y, 0]), U, "std")); print(U);
"""


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
def test_modules_as_singular() -> None:
    """Modules (of rank 1 and 2, standard bases or not, (dp,C) and (c,dp)) give Singular's matrices, as
    the ideals they come from do (a standard basis not containing the second module: the zero matrix)."""
    assert output_lines(run(MODULES)) == output_lines(run_singular(MODULES))


def test_not_contained() -> None:
    e = error("ring r = 0,(x,y),dp; module M = [x, y], [y2, x]; lift(M, [x, 0]);")
    assert "lift: the second module does not lie in the first" in e.message
    e = error("ring r = 0,(x,y),dp; lift(ideal(x2, y2), x);")
    assert "lift: the second ideal does not lie in the first" in e.message


def test_module_over_a_qring() -> None:
    """Over R/(x2-y3): T with M*T = N modulo the ideal (Singular chooses another T: lifts are not unique)."""
    out = run("ring r = 0,(x,y),dp; qring q = std(ideal(x2-y3));\n"
              "module M = [x, y], [y2, x]; module N = [x2+y3, 2xy], [2xy2, y3+x2]; matrix T = lift(M, N);\n"
              "setring r; module D = matrix(imap(q, M)) * imap(q, T) - matrix(imap(q, N));\n"
              "module Q = std(ideal(x2-y3) * freemodule(2)); size(reduce(D, Q)); size(D);")
    assert out.split() == ["0", "1"]  # D is not 0, but 0 modulo the ideal
