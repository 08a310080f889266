"""mech's kernel: exact commutative algebra (knows nothing of the language).

Submodules are never shadowed here: ``mech.kernel.groebner`` is the module (its function is
``mech.kernel.groebner.groebner``).  python-flint is imported on its first use (:mod:`.lazy_modules`)."""
from . import lazy_modules as _lazy_modules

_lazy_modules.defer("flint")  # before the submodules' `import flint`
from .coeffs import GF, QQ, Field, PrimeField, RationalField
from .engines import standard_basis, using_engine
from .errors import KernelError
from .groebner import contains, normal_form
from .order import Block, MonomialOrder
from .poly import Poly, PolyRing

__all__ = ["GF", "QQ", "Field", "PrimeField", "RationalField", "Block", "MonomialOrder",
           "Poly", "PolyRing", "standard_basis", "using_engine", "normal_form", "contains", "KernelError"]
