"""Singular's options (``option(redSB);``): their names and defaults."""
from __future__ import annotations

from typing import Any

#: Singular's default options, in the order ``option()`` prints them.
OPTION_ORDER = ["prot", "redSB", "notBuckets", "notSugar", "interrupt", "sugarCrit", "teach", "cancelunit",
                "morePairs", "notSyzMinim", "returnSB", "fastHC", "redTailSyz", "staircaseBound", "multBound", "degBound", "redTail",
                "redThrough", "lazy", "intStrategy", "infRedTail", "notRegularity", "weightM", "mem", "yacc",
                "redefine", "reading", "loadLib", "debugLib", "loadProc", "defRes", "usage", "Imap", "prompt",
                "notWarnSB", "contentSB", "warn"]
#: The options a session starts with.
DEFAULT_OPTIONS = {"redTail", "redThrough", "intStrategy", "redefine", "usage", "prompt"}



#: The options Singular switches on or off with the basering (see :func:`ring_defaults`).
RING_DEPENDENT = frozenset(("redTail", "redThrough", "intStrategy"))

#: Singular's option bits by number (``test(k)``), the named ones; bits 23 and 24 (multBound, degBound)
#: take values and are not shown; other numbers show as themselves.
OPTION_BITS = {0: "prot", 1: "redSB", 2: "notBuckets", 3: "notSugar", 4: "interrupt", 5: "sugarCrit", 6: "teach",
               7: "redThrough", 8: "notSyzMinim", 9: "returnSB", 10: "fastHC", 20: "lazy", 21: "redTailSyz",
               22: "staircaseBound", 23: None, 24: None, 25: "redTail", 26: "intStrategy", 28: "infRedTail",
               30: "notRegularity", 31: "weightM"}


def ring_defaults(ring: Any) -> set[str]:
    """The options a basering brings, as Singular sets them: redThrough, and redTail without parameters,
    when the ordering's first weight row is positive on every variable (a degree ordering); intStrategy
    over QQ and over fields with parameters."""
    if ring is None:
        return set()
    poly = getattr(ring, "poly", ring)
    params = bool(getattr(poly.field, "params", ()))
    out = set()
    if all(w > 0 for w in poly.order.first_row()):
        out |= {"redThrough"} if params else {"redTail", "redThrough"}
    if params or not poly.field.characteristic:
        out.add("intStrategy")
    return out


def shown_options(options: set[str], explicit: set[str], ring: Any) -> list[str]:
    """The options ``option()`` prints: the ring-dependent ones when the basering brings them or they were
    set explicitly, in Singular's order (numbered bits after the named ones of the first word)."""
    defaults = ring_defaults(ring)
    on = {o for o in options if o not in RING_DEPENDENT or o in defaults or o in explicit}
    split = OPTION_ORDER.index("mem")
    numbers = sorted((o for o in on if o.isdigit()), key=int)
    others = sorted(o for o in on if o not in OPTION_ORDER and not o.isdigit())
    return [o for o in OPTION_ORDER[:split] if o in on] + numbers + [o for o in OPTION_ORDER[split:] if o in on] + others
