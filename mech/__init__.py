"""mech: a computer-algebra language for the configuration spaces of rigid mechanisms.

Python API::

    from mech import Session, MechError
    s = Session()
    s.execute("ring r = 0, (x,y,z), dp; ideal I = x2-y, xy-z;")
    G = s.eval("std(I)")          # an Ideal: G.gens are kernel polynomials, G.to_sympy() sympy ones
    to_sympy(s.eval("x2 + 1/2"))  # any value as sympy objects
    s["f"] = "x3"                 # strings are parsed as mech expressions for existing variables
    print(s.execute("reduce(x3, std(I));"))   # 'z\\n'
"""
from .dsl.convert import to_sympy
from .session import Session
from .dsl.errors import (MechError, MechInternalError, MechNameError, MechRuntimeError, MechSyntaxError,
                          MechTypeError)

__version__ = "0.1.0"

__all__ = ["Session", "to_sympy", "MechError", "MechSyntaxError", "MechRuntimeError", "MechNameError", "MechTypeError",
           "MechInternalError", "__version__"]
