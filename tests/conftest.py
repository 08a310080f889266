"""Shared test set-up.  The tests are packages (``tests.kernel``, ``tests.dsl``, ``tests.stdlib``,
``tests.mech``, ``tests.differential``) mirroring the source tree and importing their helpers as
``tests.util``, so pytest runs them from the checkout's root or from any directory
(``python -m pytest /path/to/checkout``).

Tests marked ``singular`` or ``macaulay2`` are skipped when that program is not installed."""
from __future__ import annotations

import shutil
import signal

import pytest

_PROGRAMS = {"singular": "Singular", "macaulay2": "M2"}

# The shell's tests simulate Ctrl-C (``_thread.interrupt_main``), which needs Python's KeyboardInterrupt
# handler; Python leaves SIGINT ignored when its parent ignores it (a background job of a script).
if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
    signal.signal(signal.SIGINT, signal.default_int_handler)


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    missing = {mark: prog for mark, prog in _PROGRAMS.items() if shutil.which(prog) is None}
    for item in items:
        for mark, prog in missing.items():
            if item.get_closest_marker(mark):
                item.add_marker(pytest.mark.skip(reason=f"{prog} is not installed"))
