"""What a person reads of a configuration: the relative joint angles in degrees (and the slides of
prismatic joints), named after the joints; the ideal keeps its own variables.

* planar: at a fixed pivot the angle of the first link there from the x-axis; at a point joining
  links, the angle from the first link there to the second (links in the order written), in
  ``(-180, 180]``; a prismatic bar's length ``d_i``;
* a loop of joints: each joint's angle ``theta_J`` (and ``theta2_J`` of a universal joint) and
  slide ``d_J``, the cut joints' angles computed from the others;
* spatial points and bodies: the lengths ``d_i`` of prismatic legs (a spherical joint has no angle
  of its own).
"""
from __future__ import annotations

import math

from mech.stdlib.joints import Described


def _deg(c: float, s: float) -> float:
    a = math.degrees(math.atan2(s, c))
    return 180.0 if a <= -180.0 + 1e-12 else a


Reading = tuple[str, float, bool]  # name, value, is an angle (degrees; else a length)


def joint_readings(m: Described, values: dict[str, float]) -> list[Reading]:
    """The joints' angles (degrees) and slides at the configuration whose variables (and
    parameters) have ``values``."""
    from mech.stdlib import loops
    out: list[Reading] = []
    if m.joints:
        for j, v in zip(m.joints, loops.joint_values(m, values)):
            if "theta" in v and "theta" in j.joint_variables:
                out.append((j.name, _deg(*v["theta"]), True))
            if "theta2" in v:
                out.append((f"{j.name}.2", _deg(*v["theta2"]), True))
            if "d" in v:
                out.append((f"d_{j.name}", v["d"], False))
        return out
    if m.dim == 3:  # spherical joints have no angle of their own; a prismatic leg its length
        return [(f"d{i}", values[f"d{i}"], False) for i, link in enumerate(m.links, 1) if link.prismatic]
    angle = {i: (values[f"c{i}"], values[f"s{i}"]) for i in range(1, len(m.links) + 1)}
    at: dict[str, list[int]] = {}
    for i, link in enumerate(m.links, 1):
        for p in link.points:
            at.setdefault(p, []).append(i)
    for p, ids in at.items():
        if p in m.fixed:
            out.append((p, _deg(*angle[ids[0]]), True))
        elif len(ids) >= 2:
            (c1, s1), (c2, s2) = angle[ids[0]], angle[ids[1]]
            out.append((p, _deg(c1 * c2 + s1 * s2, c1 * s2 - s1 * c2), True))
    for i, link in enumerate(m.links, 1):
        if link.prismatic:
            out.append((f"d{i}", values[f"d{i}"], False))
    return out


def readings_text(readings: list[Reading]) -> str:
    """``O 90°, A -45°, d2 1.5``: angles rounded to 0.01 degree."""
    return ", ".join(f"{k} {round(v, 2):g}°" if angle else f"{k} {v:.4g}" for k, v, angle in readings)
