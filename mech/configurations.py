"""Sampled real configurations of a mechanism from Python:

    from mech.configurations import configurations
    table = configurations("ground O A 5; bar O B 2; bar B C 5; bar C A 4", 50)

one row per configuration (mode, circuit, variables, link and joint angles in degrees, moving
points' coordinates; docs/mechanisms.md, "Real answers"): a pandas DataFrame when pandas is
installed, else a list of dicts.  The language's commands are ``sampleConfigurations`` and
``exportConfigurations`` (CSV or JSON files).
"""
from __future__ import annotations

from typing import Any, Optional


def configurations(mechanism: Any, count: int = 100, *, frame: Optional[bool] = None) -> Any:
    """About ``count`` real configurations of each motion mode of ``mechanism`` (a ``Mechanism``
    or its description, numeric lengths): a DataFrame (pandas installed and ``frame`` not False;
    its columns in order) or a list of dicts."""
    from .stdlib import load
    from .stdlib.configurations import sample_configurations
    from .stdlib.mechanism import to_mechanism
    load()
    s = sample_configurations(to_mechanism(mechanism), count)
    if frame is not False:
        try:
            import pandas
        except ImportError:
            if frame:
                raise
            return s.rows
        return pandas.DataFrame(s.rows, columns=s.columns)
    return s.rows
