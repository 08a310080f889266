"""A checkout is a package: from its root, ``from mech import Session`` and ``python -m mech`` use the
checkout's own ``dsl/``, ``kernel/``, ``stdlib/`` (installed or not, editable or not)."""
from __future__ import annotations

import shutil
import subprocess
import sys

from tests.util import ROOT

PROBE = ("import mech, mech.dsl, mech.kernel, mech.stdlib; from mech import Session; "
         "print(mech.dsl.__file__); print(Session().execute('ring r=0,(x,y),dp; std(ideal(x2,xy));'), end='')")


def _copy_checkout(dest):
    for part in ("mech", "dsl", "kernel", "stdlib"):
        shutil.copytree(ROOT / part, dest / part, ignore=shutil.ignore_patterns("__pycache__"))
    return dest


def test_a_copied_checkout_imports_its_own_packages(tmp_path):
    root = _copy_checkout(tmp_path / "checkout")
    r = subprocess.run([sys.executable, "-c", PROBE], cwd=root, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    where, *out = r.stdout.splitlines()
    assert where.startswith(str(root / "dsl")) and out == ["_[1]=xy", "_[2]=x2"]


def test_python_dash_m_mech_from_a_checkout(tmp_path):
    root = _copy_checkout(tmp_path / "checkout")
    r = subprocess.run([sys.executable, "-m", "mech", "-c", "ring r=0,x,dp; (x+1)^2;"], cwd=root,
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0 and r.stdout == "x2+2x+1\n", r.stderr


def test_pytest_runs_from_another_directory(tmp_path):
    r = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
                        str(ROOT / "tests" / "kernel" / "test_package.py")],
                       cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert r.returncode == 0 and " passed" in r.stdout, r.stdout + r.stderr
