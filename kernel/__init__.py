"""mech's kernel: exact commutative algebra (knows nothing of the language)."""
from .coeffs import GF, QQ, Field, PrimeField, RationalField
from .groebner import contains, groebner, normal_form
from .order import Block, MonomialOrder
from .poly import Poly, PolyRing

__all__ = ["GF", "QQ", "Field", "PrimeField", "RationalField", "Block", "MonomialOrder",
           "Poly", "PolyRing", "groebner", "normal_form", "contains"]
