"""``assemblyModes(m)``: the assembly modes of a rigid mechanism (mobility 0) counted exactly,
without the rest of ``analyze`` (motion modes, Fitting ideal, singular configurations).

For a Stewart–Gough platform with six legs locked the whole analysis needs the Jacobian's 9 x 9
determinant modulo J; the assembly modes alone need only the quotient algebra ``Q[x]/J``: its
dimension (``vdim``, the modes counted with multiplicity), the degree of the squarefree part of
the characteristic polynomial of a separating linear form (the distinct complex modes, exact
over Q: :mod:`mech.kernel.real_solve`) and the real roots of that polynomial, isolated exactly
(the real modes, with their poses as certified decimals).
"""
from __future__ import annotations

from typing import Any

from mech.dsl.errors import MechRuntimeError
from mech.dsl.registry import command
from mech.kernel.real_roots import RealSolvingError
from mech.stdlib.analysis import Analysis
from mech.stdlib.mechanism import Mechanism, MechanismError
from mech.stdlib.mechanism_real import assembly_modes


def assembly(m: Mechanism) -> dict[str, Any]:
    """The assembly modes of ``m`` (numeric lengths, a finite configuration space): ``complex``
    (distinct), ``with_multiplicity`` (``vdim``), ``real`` and the real ``poses``."""
    if m.symbols():
        raise MechRuntimeError(f"assemblyModes needs numeric lengths (setLengths(m, ...) for "
                               f"{','.join(m.symbols())})")
    try:
        R, J = m.constraints()
    except MechanismError as e:
        raise MechRuntimeError(str(e)) from None
    try:
        return assembly_modes(Analysis(m, R, J, len(m.variables()), [], dim=0, mobility=0))
    except RealSolvingError as e:
        if "zero-dimensional" in str(e):
            raise MechRuntimeError("assemblyModes: the mechanism moves (its configuration space is not "
                                   "finite; mobility(m) says how much)") from None
        raise MechRuntimeError(f"assemblyModes: {e}") from None


@command("assemblyModes", lib="mechanism.lib")
def assembly_modes_cmd(m: Mechanism) -> str:
    """assemblyModes(m): the assembly modes of a rigid mechanism (mobility 0): the number of
    distinct complex configurations (and, if different, the number counted with multiplicity),
    the number of real ones and each real pose, computed exactly (quicker than analyze, which also
    computes the Fitting ideal and the singular configurations).

    Example:
      LIB "mechanism.lib";
      mechanism m = "fix O 0 0; fix Q 4 0; bar O A 5; bar Q A 3";
      assemblyModes(m);
      → assembly modes: 2 complex, 2 real
      →   [1] A = (4.0000, -3.0000)
      →   [2] A = (4.0000, 3.0000)
    """
    am = assembly(m)
    mult = f" ({am['with_multiplicity']} with multiplicity)" if am["with_multiplicity"] != am["complex"] else ""
    lines = [f"assembly modes: {am['complex']} complex{mult}, {am['real']} real"]
    for i, pose in enumerate(am["poses"], 1):
        pts = ", ".join(f"{p} = ({', '.join(xs)})" for p, xs in pose["points"].items()) \
            or "configuration (" + ", ".join(pose["configuration"]) + ")"
        lines.append(f"  [{i}] {pts}")
    return "\n".join(lines)
