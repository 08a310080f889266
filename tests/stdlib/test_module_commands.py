"""Vectors and modules in the Singular dialect: printing in the ring's module ordering, arithmetic,
std/syz/lift/liftstd/modulo/intersect/quotient, polylib's id2mod (outputs checked in Singular 4.3.1)."""
from __future__ import annotations

import pytest

from tests.util import run, run_singular

BASICS = """ring r=0,(x,y,z),dp;
vector v=[x,y2,0,1];
v; print(v); string(v);
vector w = x*gen(2)+gen(1);
w; w[2]; w[5]; nrows(v); size(v);
module m = v, w, [x+y, z];
m; print(m);
std(m);
syz(m);
"""

BASICS_OUT = """y2*gen(2)+x*gen(1)+gen(4)
[x,y2,0,1]
y2*gen(2)+x*gen(1)+gen(4)
x*gen(2)+gen(1)
x
0
4
3
m[1]=y2*gen(2)+x*gen(1)+gen(4)
m[2]=x*gen(2)+gen(1)
m[3]=x*gen(1)+y*gen(1)+z*gen(2)
x, 1,x+y,
y2,x,z,
0, 0,0,
1, 0,0
_[1]=x*gen(1)+y*gen(1)+z*gen(2)
_[2]=x*gen(2)+gen(1)
_[3]=yz*gen(2)+x*gen(4)+z*gen(1)
_[4]=y2*gen(2)-y*gen(1)-z*gen(2)+gen(4)
_[5]=xy*gen(4)+2yz*gen(1)+z2*gen(2)-z*gen(4)
_[6]=x2*gen(4)-2yz*gen(1)-z2*gen(2)
_[1]=0
"""

ORDERINGS = """ring r2=(0,a),(x,y,z),(dp(1),C,dp(2));
vector v=[x,1,y2];
v; -3*v; a*v;
module m=v,[0,0,0,0],[1];
m; nrows(m); ncols(m); size(m);
ring r3 = 32003,(x,y),(c,dp);
vector v = [x,-y+x2,0,-1];
v; -v;
module m=v,gen(2);
m; string(m);
std(m);
ring r4 = 0,(x,y),(C,dp);
vector v=[x,y2,0,1];
v+x2*gen(3);
"""

ORDERINGS_OUT = """x*gen(1)+y2*gen(3)+gen(2)
-3*x*gen(1)-3*y2*gen(3)-3*gen(2)
(a)*x*gen(1)+(a)*y2*gen(3)+(a)*gen(2)
m[1]=x*gen(1)+y2*gen(3)+gen(2)
m[2]=0
m[3]=gen(1)
3
3
2
[x,x2-y,0,-1]
[-x,-x2+y,0,1]
m[1]=[x,x2-y,0,-1]
m[2]=[0,1]
[x,x2-y,0,-1],[0,1]
_[1]=[0,1]
_[2]=[x,0,0,-1]
gen(4)+x2*gen(3)+y2*gen(2)+x*gen(1)
"""

OPERATIONS = """ring r=0,(x,y),dp;
module M=[x,y],[y,x2]; module N=[x2,0],[0,y];
quotient(M,N); quotient(M,x); interred(M); dim(std(M)); deg([x2,y3]); deg(gen(3));
vector v=[x,y]; ideal(x,y)*v; M+[1,0]; M+M; homog(M); reduce([x2,y],ideal(x));
matrix T; module U;
ideal S=liftstd(ideal(x2-y,xy,x3),T,U); S; print(T); U;
print(matrix(S)-matrix(ideal(x2-y,xy,x3))*T);
modulo(ideal(x), ideal(x2, y));
"""

OPERATIONS_OUT = """_[1]=x3-y2
_[1]=x*gen(1)+y*gen(2)
_[2]=x2*gen(2)+y*gen(1)
_[1]=x*gen(1)+y*gen(2)
_[2]=x2*gen(2)+y*gen(1)
1
3
0
_[1]=x2*gen(1)+xy*gen(2)
_[2]=xy*gen(1)+y2*gen(2)
_[1]=x*gen(1)+y*gen(2)
_[2]=x2*gen(2)+y*gen(1)
_[3]=gen(1)
_[1]=x*gen(1)+y*gen(2)
_[2]=x2*gen(2)+y*gen(1)
0
y*gen(2)
S[1]=y2
S[2]=xy
S[3]=x2-y
-y,0,1,
x, 1,0,
0, 0,0 
U[1]=x*gen(1)-gen(3)+gen(2)
U[2]=x2*gen(2)-y*gen(3)
0,0,0
_[1]=y*gen(1)
_[2]=x*gen(1)
"""

INTERSECT = """ring r=0,(x,y),dp;
module I = intersect(module([x,y],[y,x2]), module([x2,0],[0,y]));
module J = [x2,xy],[x4,y3];
size(reduce(I, std(J))) + size(reduce(J, std(I)));
"""


@pytest.mark.parametrize("src, out", [(BASICS, BASICS_OUT), (ORDERINGS, ORDERINGS_OUT),
                                      (OPERATIONS, OPERATIONS_OUT)])
def test_vectors_and_modules(src: str, out: str) -> None:
    assert run(src).split() == out.split()


@pytest.mark.singular
@pytest.mark.parametrize("src", [BASICS, ORDERINGS, OPERATIONS, INTERSECT])
def test_vectors_and_modules_as_singular(src: str) -> None:
    assert run(src).split() == run_singular(src).split()


def test_intersection_is_the_module_singular_gives() -> None:
    assert run(INTERSECT).split() == ["0"]


def test_id2mod_and_mod2id_are_inverse() -> None:
    src = """LIB "polylib.lib"; ring r=0,(e(1),e(2),x,y,z),(dp(2),ds(3));
    ideal i=e(2)^2,e(1)*e(2),e(1)^2,e(1)*y+e(2)*x; intvec iv=2,1;
    module m = id2mod(i,iv); m; mod2id(m, iv);"""
    assert run(src).split() == ["m[1]=x*gen(1)+y*gen(2)", "_[1]=e(2)^2", "_[2]=e(1)*e(2)", "_[3]=e(1)^2",
                                "_[4]=e(1)*y+e(2)*x"]


LOCAL = """ring r=0,(x,y,z),ds; module M=[x+y2,y],[y+x3,z],[z2,x+z]; syz(M);
ring r2=0,(x,y),(c,ds); module M=[1+x,y],[y,x2+y3]; std(M);
"""


@pytest.mark.parametrize("with_singular", [False, pytest.param(True, marks=pytest.mark.singular)])
def test_local_orderings(with_singular: bool) -> None:
    expected = ("_[1]=x2*gen(2)-xy*gen(1)+y2*gen(3)-xz*gen(3)+xz*gen(2)-yz*gen(1)+xy2*gen(2)-y2z*gen(3)"
                "+y2z*gen(2)-yz2*gen(2)+z3*gen(1)-x4*gen(1)+x3y*gen(3)-x3z*gen(1)\n"
                "_[1]=[1+x,y]\n_[2]=[0,x2-y2+x3+y3+xy3]")
    assert run(LOCAL).split() == (run_singular(LOCAL) if with_singular else expected).split()


def test_a_local_standard_basis_has_the_lead_terms_singular_gives() -> None:
    src = """ring r=0,(x,y,z),ds; module M=[x+y2,y],[y+x3,z],[z2,x+z]; module S = std(M);
    S;"""
    out = run(src).split()
    assert [line.split("=")[1].split("+")[0] for line in out[:4]] == ["x*gen(2)", "x*gen(1)", "y*gen(1)", "y2*gen(2)"]


SIMPLIFY = """ring r=0,(x,y,z),(c,dp);
matrix A[2][3]=x,0,2x,y,0,2y;
simplify(A,2+8);
simplify(A,2);
module n=[x,y],[2x,2y],[0,y2],[x2],[0,3y2];
simplify(n,32);
simplify(n,16+2+1);
simplify(n,4);
"""


@pytest.mark.parametrize("with_singular", [False, pytest.param(True, marks=pytest.mark.singular)])
def test_simplify_of_a_module_and_of_a_matrix(with_singular: bool) -> None:
    """simplify(matrix, n) converts to a module as Singular does; the flags act on vectors' leading terms."""
    expected = """_[1]=[x,y]
_[1]=[x,y]
_[2]=[2x,2y]
_[1]=[x,y]
_[2]=0
_[3]=[0,y2]
_[4]=0
_[5]=0
_[1]=[x,y]
_[2]=[0,y2]
_[3]=[x2]
_[1]=[x,y]
_[2]=[2x,2y]
_[3]=[0,y2]
_[4]=[x2]
_[5]=[0,3y2]"""
    assert run(SIMPLIFY).split() == (run_singular(SIMPLIFY) if with_singular else expected).split()

