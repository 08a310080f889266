"""The support of a module in the Macaulay2 dialect (``dialect="m2"``):
``isSupportedInZeroLocus(B, M)``, also written ``isSupportedInZeroLocus_B M``."""
from __future__ import annotations

from typing import Any

from ..dsl.errors import MechRuntimeError
from ..dsl.m2_modules import CyclicModule
from ..dsl.m2_submodules import Module
from ..dsl.m2_subquotients import Subquotient
from ..dsl.registry import command
from ..dsl.values import Ideal
from .m2 import saturate
from .m2_resolutions import annihilator
from .m2_subquotients import annihilator_subquotient


@command("isSupportedInZeroLocus", dialect="m2")
def is_supported_in_zero_locus(B: Ideal, M: Any) -> bool:
    """isSupportedInZeroLocus(B, M): whether the support of M (of R^1/I for an ideal I) lies in the
    zero locus of B: B inside the radical of ann M, that is ann M : B^infinity is the unit ideal."""
    if isinstance(M, Ideal):
        ann = M
    elif isinstance(M, CyclicModule):
        ann = M.ideal
    elif isinstance(M, Module):
        ann = annihilator(M)
    elif isinstance(M, Subquotient):
        ann = annihilator_subquotient(M)
    else:
        raise MechRuntimeError("isSupportedInZeroLocus(B, M) takes an ideal B and a module or an ideal M")
    return any(g.is_constant() for g in saturate(ann, B).nonzero())
