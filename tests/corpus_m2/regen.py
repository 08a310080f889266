"""Regenerate the expected outputs: ``python3 tests/corpus_m2/regen.py`` runs every ``*.m2`` here
through Macaulay2 (``M2 --script``; the stored outputs come from Debian's macaulay2 1.21)."""
from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent


def main() -> int:
    m2 = shutil.which("M2")
    if m2 is None:
        sys.stderr.write("regen.py: Macaulay2 (M2) is not installed\n")
        return 1
    for script in sorted(HERE.glob("*.m2")):
        run = subprocess.run([m2, "--script", script.name], cwd=HERE, capture_output=True, text=True, timeout=600)
        script.with_suffix(".out").write_text(run.stdout + run.stderr)
        print(f"{script.name}: {len((run.stdout + run.stderr).splitlines())} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
