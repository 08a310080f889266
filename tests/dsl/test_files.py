"""The one file policy (mech.dsl.files, docs/reliability.md "Files"): plot commands write relative
paths inside the working directory only; LIB reads regular files next to the script only."""
import os

import pytest

from mech import MechError, Session

DRAW = 'LIB "mechanism.lib"; mechanism m = "fix O; bar O A 1; bar A B 1; slider B"; drawMechanism(m, list(0, -1, 0, 1), "{}");'


def draw(path: str) -> str:
    return Session().execute(DRAW.format(path))


@pytest.mark.parametrize("path, message", [
    ("/tmp/x.svg", "give a path relative to the working directory"),
    ("~/x.svg", "give a path relative to the working directory"),
    ("../x.svg", "'..' is not allowed"),
    ("sub/../../x.svg", "'..' is not allowed"),
    ("missing/x.svg", "the folder missing does not exist"),
    ("link/x.svg", "link is a symbolic link"),
    ("file.svg", "exists and is not a regular file"),
    ("x.pdf", "give a file name ending in .png or .svg"),
])
def test_refused_paths(path, message, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "outside").mkdir()
    (tmp_path / "link").symlink_to(tmp_path / "outside")
    (tmp_path / "target.svg").write_text("keep")
    (tmp_path / "file.svg").symlink_to(tmp_path / "target.svg")
    before = sorted(os.listdir(tmp_path))
    with pytest.raises(MechError) as e:
        draw(path)
    assert message in e.value.message
    assert sorted(os.listdir(tmp_path)) == before and (tmp_path / "target.svg").read_text() == "keep"
    assert not list((tmp_path / "outside").iterdir())


def test_written_paths(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "pics").mkdir()
    draw("m.svg")
    draw("pics/m.svg")
    draw("./pics/m2.svg")
    (tmp_path / "m.svg").write_text("old")
    draw("m.svg")                                     # a regular file is replaced
    assert sorted(p.name for p in tmp_path.rglob("*.svg")) == ["m.svg", "m.svg", "m2.svg"]
    assert (tmp_path / "m.svg").read_text().startswith("<svg")


def test_lib_reads_no_symbolic_link(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    secret = tmp_path / "secret.txt"
    secret.write_text("root:x:0:0:secret line\n")
    (tmp_path / "pw.lib").symlink_to(secret)
    (tmp_path / "ok.lib").write_text("int fromlib = 3;\n")
    script = tmp_path / "s.mech"
    script.write_text('LIB "ok.lib"; fromlib;\nLIB "pw.lib";\n')
    s = Session()
    with pytest.raises(MechError) as e:
        s.execute(script.read_text(), str(script))
    assert e.value.output == "3\n"
    assert "pw.lib is a symbolic link" in e.value.message and "secret" not in e.value.format()
