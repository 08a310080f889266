"""Regenerate the expected outputs (*.out) of the corpus scripts (*.sing) with real Singular.

    python tests/corpus/regen.py            # every script
    python tests/corpus/regen.py rings      # only rings.sing

Singular runs in this directory with the bare file name (its warnings quote it), reading `quit;` from
standard input after the script.
"""
from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent


def singular_output(script: Path) -> str:
    exe = shutil.which("Singular")
    if exe is None:
        raise SystemExit("Singular is not installed")
    res = subprocess.run([exe, "-q", script.name], input="quit;\n", text=True, capture_output=True,
                         cwd=script.parent, timeout=600)
    return res.stdout


def main(names: list[str]) -> None:
    scripts = [HERE / f"{n.removesuffix('.sing')}.sing" for n in names] if names else sorted(HERE.glob("*.sing"))
    for script in scripts:
        out = singular_output(script)
        script.with_suffix(".out").write_text(out)
        print(f"{script.name}: {len(out.splitlines())} lines")


if __name__ == "__main__":
    main(sys.argv[1:])
