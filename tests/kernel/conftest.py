"""Fixtures of the kernel's tests."""
from __future__ import annotations

import pytest

from mech.kernel import f4_pairs, f4_rows


@pytest.fixture(params=["compiled", "python"])
def row_kernel(request, monkeypatch):
    """A test run with the compiled F4 row kernel and pair set (when built) and with the pure-Python
    path: a module takes it for all its tests with ``pytestmark = pytest.mark.usefixtures("row_kernel")``."""
    if request.param == "python":
        monkeypatch.setattr(f4_rows, "KERNEL", None)
        monkeypatch.setattr(f4_pairs, "_Compiled", None)
    elif f4_rows.KERNEL is None:
        pytest.skip("the compiled row kernel is not built")
