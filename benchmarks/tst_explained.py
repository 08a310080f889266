"""Why a case of the conformance run differs from Singular where the difference was checked by hand
and is not a wrong value of mech's (the report prints the reason after the difference).  A case
listed here still counts as ``differ``."""
from __future__ import annotations

EXPLAINED: dict[str, str] = {
}
