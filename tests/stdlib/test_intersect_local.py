"""intersect in local orderings (issue 21), checked by hand."""
from __future__ import annotations

from tests.util import run


def test_intersect_local() -> None:
    # (x2(1+x), y) ∩ (x, y2(1+y)) = (x2, y) ∩ (x, y2) = (x2, xy, y2) in the localization at 0
    out = run("ring r=0,(x,y),ds; intersect(ideal(x2+x3, y), ideal(x, y2+y3));")
    assert sorted(out.split()) == ["_[1]=x2", "_[2]=xy", "_[3]=y2"]
    assert run("ring r=0,(x,y),ds; intersect(ideal(x-x2), ideal(y+x*y));").split() == ["_[1]=xy"]
