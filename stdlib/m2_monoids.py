"""Monoids in the Macaulay2 dialect: ``monoid[x, y]`` (built by the interpreter), ``monoid R``, and
``vars``, ``gens``/``generators`` and ``numgens`` of a monoid (its variables as symbols); ``toField``."""
from __future__ import annotations

from ..dsl.m2_rings import in_quotients
from ..dsl.m2_values import Monoid, Symbol
from ..dsl.registry import command
from ..dsl.values import List, Ring


@command("monoid", dialect="m2")
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
