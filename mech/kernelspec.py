"""Installing the Jupyter kernels of mech: ``mech --install-kernel`` or
``python -m mech.kernelspec install [--user | --sys-prefix | --prefix DIR]``.

Two kernel specs: ``mech`` (Singular's dialect) and ``mech-m2`` (Macaulay2's); both run
``python -m mech.jupyter`` with this Python.  Without an option they go where Jupyter looks for
this environment's kernels (``sys.prefix``), as ``--sys-prefix``.
"""
from __future__ import annotations

import argparse
import json
import sys
import tempfile
from pathlib import Path
from typing import Optional

SPECS = {"mech": ("mech (Singular)", "singular"), "mech-m2": ("mech (Macaulay2)", "m2")}


def spec(dialect: str, display_name: str, python: str = "") -> dict:
    """The kernel.json of one kernel."""
    return {"argv": [python or sys.executable, "-m", "mech.jupyter", "-f", "{connection_file}", "--dialect", dialect],
            "display_name": display_name, "language": "mech" if dialect == "singular" else "mech-m2",
            "interrupt_mode": "signal", "metadata": {"debugger": False}}


def install(user: bool = False, prefix: Optional[str] = None) -> list[str]:
    """Install both kernel specs; the folders they were installed in."""
    try:
        from jupyter_client.kernelspec import KernelSpecManager
    except ImportError:
        raise SystemExit("mech: error: Jupyter is not installed (pip install 'mech[jupyter]')") from None
    if not user and prefix is None:
        prefix = sys.prefix
    out = []
    manager = KernelSpecManager()
    for name, (display, dialect) in SPECS.items():
        with tempfile.TemporaryDirectory() as tmp:
            (Path(tmp) / "kernel.json").write_text(json.dumps(spec(dialect, display), indent=1) + "\n")
            out.append(manager.install_kernel_spec(tmp, name, user=user, prefix=None if user else prefix))
    return out


def main(argv: Optional[list[str]] = None) -> int:
    p = argparse.ArgumentParser(prog="python -m mech.kernelspec", description="Install mech's Jupyter kernels.")
    p.add_argument("action", choices=["install"])
    where = p.add_mutually_exclusive_group()
    where.add_argument("--user", action="store_true", help="for this user (~/.local/share/jupyter)")
    where.add_argument("--sys-prefix", action="store_true", help="in this Python environment (the default)")
    where.add_argument("--prefix", metavar="DIR", help="under DIR/share/jupyter/kernels")
    args = p.parse_args(argv)
    for folder in install(user=args.user, prefix=args.prefix):
        print(f"installed the kernel spec {Path(folder).name} in {folder}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
