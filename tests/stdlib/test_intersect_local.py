"""intersect and quotient in local orderings (issue 21), checked by hand."""
from __future__ import annotations

from tests.util import run


def test_intersect_local() -> None:
    # (x2(1+x), y) ∩ (x, y2(1+y)) = (x2, y) ∩ (x, y2) = (x2, xy, y2) in the localization at 0
    out = run("ring r=0,(x,y),ds; intersect(ideal(x2+x3, y), ideal(x, y2+y3));")
    assert sorted(out.split()) == ["_[1]=x2", "_[2]=xy", "_[3]=y2"]
    assert run("ring r=0,(x,y),ds; intersect(ideal(x-x2), ideal(y+x*y));").split() == ["_[1]=xy"]


def test_quotient_local() -> None:
    # (x2(1+x), xy) : x = (x(1+x), y) = (x, y) in the localization at 0
    assert sorted(run("ring r=0,(x,y),ds; quotient(ideal(x2+x3, xy), ideal(x));").split()) == ["_[1]=x", "_[2]=y"]
    out = run("ring r=0,(x,y),ds; quotient(ideal(x2*(1+y), y3), ideal(x,y));")
    assert out.split() == ["_[1]=x2", "_[2]=xy2", "_[3]=y3"]
