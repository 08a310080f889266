"""README.md's examples run: each ```mech block in a fresh session (its output must equal the
plain ``` block right after it, when there is one), each ```python block as a program, and the
set-up commands are the ones CI runs."""

import pytest

from mech import Session

from tests.util import ROOT

README = (ROOT / "README.md").read_text()


def blocks(kind: str) -> list[tuple[str, str | None]]:
    import re
    found = re.findall(r"^```(\w*)\n(.*?)^```$", README, re.S | re.M)
    out = []
    for k, (lang, code) in enumerate(found):
        if lang == kind:
            nxt = found[k + 1] if k + 1 < len(found) else None
            out.append((code, nxt[1] if nxt and nxt[0] == "" else None))
    return out


@pytest.mark.parametrize("code, expected", blocks("mech"), ids=lambda v: (v or "")[:30])
def test_mech_blocks(code, expected, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    out = Session().execute(code)
    if expected is not None:
        assert out == expected


@pytest.mark.parametrize("code, expected", blocks("python"), ids=lambda v: (v or "")[:30])
def test_python_blocks(code, expected, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "README.md", "exec"), {})  # noqa: S102 - the README's own example
    if expected is not None:
        assert capsys.readouterr().out == expected


def test_there_are_examples_and_the_ci_command_is_the_readme_one():
    assert len(blocks("mech")) >= 3 and blocks("python")
    ci = (ROOT / ".ci" / "run").read_text().strip().splitlines()[-1]
    assert f"```sh\n{ci}\n```" in README
