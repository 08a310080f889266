"""Singular commands added for issue 21: type, and primdec.lib's algorithm options (they choose an
algorithm, not the result)."""
from __future__ import annotations

import pytest

from tests.util import error, run, run_singular

TYPE_SRC = ('int i=3; type i; ring r; poly f=x2+1; type f; ideal I=x,y; type I; list L=1,2; type L; '
            'string s="ab"; type s; number n=3; type n; matrix m[2][2]=1,x,y,2; type m; intvec v=1,2; type v; '
            'type(f); def d=3; type d; type r; map phi=r,x,y,z; type phi; intmat im[2][2]=1,2,3,4; type im;')


@pytest.mark.singular
def test_type_as_singular() -> None:
    assert run(TYPE_SRC).split() == run_singular(TYPE_SRC).split()


def test_type_header() -> None:
    assert run("int i = 3; type i;").strip() == "// i int 3"


def test_primdec_options_same_result() -> None:
    base = 'LIB "primdec.lib"; ring r=0,(x,y,z),dp; ideal i = xy, xz, (x-1)^2*y; '
    assert run(base + "primdecSY(i, 1);") == run(base + "primdecSY(i);")
    assert run(base + 'minAssGTZ(i, "noFacstd");') == run(base + "minAssGTZ(i);")
    assert run(base + "minAssChar(i, 2);") == run(base + "minAssChar(i);")
    assert "unknown option" in str(error(base + 'minAssGTZ(i, "foo");'))
