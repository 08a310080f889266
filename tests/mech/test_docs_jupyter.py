"""docs/jupyter.md runs as shown: its python blocks as programs and its ipython blocks in one IPython
shell (each compared with the plain block after it), its install commands."""
import re
import sys

from mech import cli

from tests.util import ROOT

DOC = ROOT / "docs" / "jupyter.md"


def blocks():
    """(info string, text, the plain block after it or None)."""
    found = re.findall(r"^```(\w*)\n(.*?)^```$", DOC.read_text(), re.S | re.M)
    return [(info, text, found[k + 1][1] if k + 1 < len(found) and found[k + 1][0] == "" else None)
            for k, (info, text) in enumerate(found) if info]


def test_python_blocks(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    ran = 0
    for info, code, expected in blocks():
        if info == "python":
            exec(compile(code, str(DOC), "exec"), {})  # noqa: S102 - the documentation's own example
            assert capsys.readouterr().out == expected
            ran += 1
    assert ran == 3


def test_ipython_blocks(capsys, tmp_path, monkeypatch):
    from IPython.core.interactiveshell import InteractiveShell
    monkeypatch.chdir(tmp_path)
    shell = InteractiveShell()
    try:
        for info, code, expected in blocks():
            if info == "ipython":
                result = shell.run_cell(code)
                assert result.success, code
                assert capsys.readouterr().out == (expected or "")
    finally:
        InteractiveShell.clear_instance()


def test_install_commands(tmp_path, monkeypatch, capsys):
    (sh,) = [text for info, text, _ in blocks() if info == "sh"]
    assert sh.splitlines() == ["pip install 'mech[jupyter]'", "mech --install-kernel"]
    monkeypatch.setattr(sys, "prefix", str(tmp_path))        # where this environment's kernels go
    assert cli.main(["--install-kernel"]) == 0
    kernels = tmp_path / "share" / "jupyter" / "kernels"
    assert sorted(p.name for p in kernels.iterdir()) == ["mech", "mech-m2"]
    assert capsys.readouterr().out == "".join(f"installed the Jupyter kernel spec {n} in {kernels / n}\n"
                                              for n in ("mech", "mech-m2"))
