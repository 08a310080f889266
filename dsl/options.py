"""Singular's options (``option(redSB);``): their names and defaults."""
from __future__ import annotations

#: Singular's default options, in the order ``option()`` prints them.
OPTION_ORDER = ["prot", "redSB", "notBuckets", "notSugar", "interrupt", "sugarCrit", "teach", "cancelunit",
                "morePairs", "returnSB", "fastHC", "staircaseBound", "multBound", "degBound", "redTail",
                "redThrough", "lazy", "intStrategy", "infRedTail", "notRegularity", "weightM", "mem", "yacc",
                "redefine", "reading", "loadLib", "debugLib", "loadProc", "defRes", "usage", "Imap", "prompt",
                "notWarnSB", "contentSB", "warn"]
#: The options a session starts with.
DEFAULT_OPTIONS = {"redTail", "redThrough", "intStrategy", "redefine", "usage", "prompt"}


