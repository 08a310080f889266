"""Checks that catch likely mistakes in a mechanism's description.

Errors (the description is refused): a point fixed twice at different places, a loop joint name
used twice, loop joints together with points, lengths set to zero or negative numbers.  Warnings
(the description stands, the message says what is odd): a fixed point that nothing uses, a point
fixed twice at the same place, two fixed points at one place, a point that only one bar mentions
(a misspelt name leaves the chain open: a dangling link), a bar repeated, between two fixed
points or between two points of one body, a slider repeated or on a fixed point (redundant
constraints).  Every message names the statement (its number in the description and its text).
The Grübler–Kutzbach count beside the true mobility is in the analysis' report.
"""
from __future__ import annotations

from fractions import Fraction
from typing import Callable

from mech.stdlib.joints import (Bar, Described, Fix, Helical, LineSlider, Link, LoopJoint, MechanismError, PrismaticBar, Slider,
                                where)



def check(m: Described, warn: Callable[[str], None]) -> None:
    """Raise the errors, ``warn`` the warnings of a parsed description."""
    _fixed_twice(m, warn)
    if m.joints:
        _loop(m)
        for j in m.joints:
            if isinstance(j, Helical):
                warn(f"mechanism: {where(j.source)}: the slide d_{j.name} = {j.pitch}*theta_{j.name} is not polynomial: "
                     f"the ideal lets {j.name} slide freely (as a cylindrical joint); on a motion mode where {j.name} "
                     "moves the helical loop has one freedom less than the mobility reported")
        return
    _undefined(m)
    _unused_and_dangling(m, warn)
    _fixed_bars(m)
    _redundant(m, warn)


def _undefined(m: Described) -> None:
    """A slider's or gear's points must be points of links (or fixed): a name nothing else uses is a
    misspelling."""
    known = set(m.fixed) | {p for link in m.links for p in link.points}
    for e in [*m.sliders, *m.gears]:
        for p in e.mentions():
            if p not in known:
                raise MechanismError(f"{where(e.source)}: {p} is not a point of any link or fixed point "
                                     "(an undefined point: a misspelt name?)")


def _fixed_twice(m: Described, warn: Callable[[str], None]) -> None:
    seen: dict[str, Fix] = {}
    places: dict[tuple, Fix] = {}
    for e in m.elements:
        if not isinstance(e, Fix):
            continue
        first = seen.get(e.point)
        if first is not None:
            if first.coords != e.coords:
                raise MechanismError(f"{where(e.source)}: {e.point} is already fixed at {_at(first.coords)} by "
                                     f"{where(first.source)} (a point is fixed once)")
            if first.source != e.source:
                warn(f"mechanism: {where(e.source)}: {e.point} is fixed twice (as in {where(first.source)})")
            continue
        seen[e.point] = e
        other = places.get(e.coords)
        if other is not None and all(not isinstance(v, str) for v in e.coords):
            warn(f"mechanism: {where(e.source)}: {e.point} is fixed at {_at(e.coords)}, where {other.point} is "
                 f"fixed ({where(other.source)}): two names for one point?")
        places.setdefault(e.coords, e)


def _at(coords: tuple) -> str:
    return "(" + ", ".join(str(v) for v in coords) + ")"


def _loop(m: Described) -> None:
    names: dict[str, LoopJoint] = {}
    for j in m.joints:
        if j.name in names:
            raise MechanismError(f"{where(j.source)}: the joint name {j.name} is used by {where(names[j.name].source)} "
                                 "already (name each joint once)")
        names[j.name] = j
    other = next((e for e in m.elements if not isinstance(e, LoopJoint)), None)
    if other is not None:
        raise MechanismError(f"{where(other.source)}: a loop of joints (revolute, prismatic, cylindrical, universal, "
                             "helical) is described by its joints alone: points, bars and bodies cannot be added to it")
    if len(m.joints) < 3:
        raise MechanismError(f"{where(m.joints[-1].source)}: a loop needs at least three joints, not "
                             f"{len(m.joints)}")


def _unused_and_dangling(m: Described, warn: Callable[[str], None]) -> None:
    count: dict[str, int] = {}
    for e in m.elements:
        if isinstance(e, Fix):
            continue
        for p in dict.fromkeys(e.mentions()):
            count[p] = count.get(p, 0) + 1
    for e in m.elements:
        if isinstance(e, Fix) and e.point not in count and e.point in m.fixed:
            warn(f"mechanism: {where(e.source)}: {e.point} is fixed but no link or slider uses it")
            count[e.point] = 1  # once
    for e in m.elements:
        if isinstance(e, (Bar, PrismaticBar)):
            for p in e.points:
                if count.get(p) == 1 and p not in m.fixed:
                    warn(f"mechanism: {where(e.source)}: {p} appears in no other statement: the link dangles "
                         f"(a misspelt point name?)")


def _redundant(m: Described, warn: Callable[[str], None]) -> None:
    bars: dict[frozenset, Link] = {}
    sliders: dict[tuple, Slider | LineSlider] = {}
    for e in m.elements:
        if isinstance(e, Link) and len(e.points) == 2:
            key = frozenset(e.points)
            if key in bars:
                warn(f"mechanism: {where(e.source)}: {' and '.join(e.points)} are joined by "
                     f"{where(bars[key].source)} already: a redundant constraint")
            bars.setdefault(key, e)
            body = next((b for b in m.links if b is not e and len(b.points) > 2 and key <= set(b.points)), None)
            if body is not None and not e.prismatic:
                warn(f"mechanism: {where(e.source)}: {' and '.join(e.points)} are points of one body "
                     f"({where(body.source)}): the bar is a redundant constraint")
            if all(p in m.fixed for p in e.points) and not e.prismatic:
                warn(f"mechanism: {where(e.source)}: both ends are fixed: the bar moves nothing (a redundant "
                     "constraint, or no configuration when the lengths differ)")
        elif isinstance(e, (Slider, LineSlider)):
            key = (e.text(),)
            if key in sliders:
                warn(f"mechanism: {where(e.source)}: repeats {where(sliders[key].source)}: a redundant constraint")
            sliders.setdefault(key, e)
            if isinstance(e, Slider) and e.point in m.fixed:
                warn(f"mechanism: {where(e.source)}: {e.point} is fixed: the slider moves nothing (a redundant "
                     "constraint)")


def _fixed_bars(m: Described) -> None:
    """A bar between two fixed points must fit their distance (numbers known): else no configuration."""
    fixed = m.fixed
    for e in m.elements:
        if not isinstance(e, Bar) or not all(p in fixed for p in e.points):
            continue
        a, b, length = fixed[e.points[0]], fixed[e.points[1]], e.local[0][0]
        if any(isinstance(v, str) for v in (*a, *b, length)):
            continue
        dist2 = sum((Fraction(q) - Fraction(p)) ** 2 for p, q in zip(a, b))
        if dist2 != Fraction(length) ** 2:
            raise MechanismError(f"{where(e.source)}: both ends are fixed, {_distance(dist2)} apart: a bar of length "
                                 f"{length} does not fit (no configuration)")


def _distance(d2: Fraction) -> str:
    q = Fraction(float(d2) ** 0.5).limit_denominator(10 ** 6)
    return str(q) if q * q == d2 else f"sqrt({d2})"


def check_values(m: Described) -> None:
    """Lengths given values must stay positive (bars, loop link lengths >= 0), two ground points
    apart."""
    for e in m.elements:
        if isinstance(e, Bar) and not isinstance(e.local[0][0], str) and e.local[0][0] <= 0:
            raise MechanismError(f"{where(e.source)}: the length of a bar is positive, not {e.local[0][0]}")
        if isinstance(e, LoopJoint) and not isinstance(e.a, str) and e.a < 0:
            raise MechanismError(f"{where(e.source)}: a is a distance (>= 0), not {e.a}")
    _fixed_bars(m)
    fixed = [e for e in m.elements if isinstance(e, Fix)]
    for i, a in enumerate(fixed):
        for b in fixed[i + 1:]:
            if a.point != b.point and a.source == b.source and a.coords == b.coords:
                raise MechanismError(f"{where(a.source)}: the ground length is 0: {a.point} and {b.point} would be "
                                     "one point")
