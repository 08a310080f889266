"""mech: a computer-algebra language for the configuration spaces of rigid mechanisms.

Python API::

    from mech import Session, MechError, to_sympy
    s = Session()
    s.execute("ring r = 0, (x,y,z), dp; ideal I = x2-y, xy-z;")   # returns the printed text: ''
    G = s.eval("std(I)")               # an Ideal; G.gens are kernel polynomials
    G.to_sympy()                       # [-x*z + y**2, x*y - z, x**2 - y]
    s.execute("reduce(x3, std(I));")   # 'z\\n'
    s["I"] = "x2-y, xy-z, z"           # a string for an existing ideal is read as mech code
    s["f"] = to_sympy(s.eval("x+y"))**2   # sympy expressions become polys
    s.execute("f;")                    # 'x2+2xy+y2\\n'
"""
from pathlib import Path as _Path

# In a checkout, the language's packages (dsl/, kernel/, stdlib/) sit beside this folder and the
# installed package maps them to mech.dsl, mech.kernel, mech.stdlib.  When this folder is the
# one imported (a raw checkout, or the checkout's root shadowing an installed copy), look for
# them beside it too.
_CHECKOUT = _Path(__file__).resolve().parent.parent
if (_CHECKOUT / "dsl" / "singular.lark").is_file() and str(_CHECKOUT) not in __path__:
    __path__.append(str(_CHECKOUT))

from . import stdlib as _stdlib
from .dsl import registry as _registry
from .dsl.errors import (MechError, MechInternalError, MechNameError, MechRuntimeError, MechSyntaxError,
                         MechTypeError)
from .dsl import interop as _interop  # noqa: F401 - the Python hooks on values (sympy, LaTeX)
from .dsl.values import to_sympy
from .session import Session

# The language runtime (mech.dsl) knows no library: mech's own (mech.stdlib) is registered here and
# loaded when the first interpreter starts (registry.load_plugins).
_registry.add_loader(_stdlib.load)

__version__ = "0.1.0"


def load_ipython_extension(ipython: object) -> None:
    """``%load_ext mech`` in IPython or Jupyter: the ``%mech`` and ``%%mech`` magics (mech.ipython)."""
    from .ipython import load_ipython_extension as load
    load(ipython)

__all__ = ["Session", "to_sympy", "MechError", "MechSyntaxError", "MechRuntimeError", "MechNameError",
           "MechTypeError", "MechInternalError", "__version__"]
