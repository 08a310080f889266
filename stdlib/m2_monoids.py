"""Monoids in the Macaulay2 dialect: ``monoid[x, y]`` (built by the interpreter), ``monoid R``, and
``vars``, ``gens``/``generators`` and ``numgens`` of a monoid (its variables as symbols); ``toField``."""
from __future__ import annotations

from typing import Any

from ..dsl.m2_rings import in_quotients, exact_over_zz
from ..dsl.m2_values import Monoid, Symbol
from ..dsl.registry import command
from ..dsl.values import NONE, List, Ring


@command("monoid", dialect="m2")
@exact_over_zz
def monoid(R: Ring) -> Monoid:
    """monoid R: the monoid of R's monomials (R's own variables)."""
    owner = getattr(R.poly, "owner", None) or R
    own = getattr(owner, "own", ()) or R.poly.names
    return Monoid(own)


def _variables(M: Monoid) -> List:
    return List([Symbol(n) for n in M.names])


@command("vars", dialect="m2")
def vars_monoid(M: Monoid) -> List:
    """vars M: the monoid's variables."""
    return _variables(M)


@command("gens", dialect="m2")
def gens_monoid(M: Monoid) -> List:
    """gens M: the monoid's variables."""
    return _variables(M)


@command("generators", dialect="m2")
def generators_monoid(M: Monoid) -> List:
    """generators M: the monoid's variables."""
    return _variables(M)


@command("numgens", dialect="m2")
def numgens_monoid(M: Monoid) -> int:
    """numgens M: the number of the monoid's variables."""
    return len(M.names)


@command("toField", dialect="m2")
@in_quotients
def to_field(R: Ring) -> Ring:
    """toField R: R (a quotient ring the user knows is a field) to be used as a field: mech's
    towers over R/I compute in the flattened ring, which needs no mark."""
    return R


@command("heft", dialect="m2")
def heft(R: Ring) -> Any:
    """heft R: the heft vector of R's degrees (a list w with w . d > 0 for each variable's degree d;
    {1} for a singly graded ring with positive degrees; null when there is none)."""
    from ..dsl.m2_rings import degree_vectors
    from ..dsl.m2_ringcons import heft as find_heft
    owner = getattr(R.poly, "owner", None) or R
    vecs = degree_vectors(owner)
    w = find_heft(vecs) if vecs else (1,)
    return List(list(w)) if w is not None else NONE
