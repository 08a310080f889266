"""The kernel package: no package attribute shadows a submodule (``import mech.kernel.groebner as gb``
gives the module).  Layering and import cycles: tests/test_layers.py."""
from __future__ import annotations

import importlib
import types

from tests.util import ROOT

import mech.kernel

KERNEL = ROOT / "kernel"


def test_no_submodule_is_shadowed():
    import mech.kernel.groebner as gb
    assert isinstance(gb, types.ModuleType) and callable(gb.groebner)
    for path in sorted(KERNEL.glob("*.py")):
        if path.stem == "__init__":
            continue
        module = importlib.import_module(f"mech.kernel.{path.stem}")
        assert getattr(mech.kernel, path.stem) is module, path.stem
