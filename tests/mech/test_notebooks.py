"""The example notebooks run through the real kernels (nbclient): examples/mechanisms.ipynb on mech's
kernel, examples/python.ipynb (the %%mech magic) on IPython's.  Their text outputs are what a
plain Session prints for the same cells; the rich outputs are checked for what they must show."""
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest
from nbclient import NotebookClient

from mech import MechError, Session

from tests.util import ROOT


def execute(name: str, cwd, kernel: str | None = None):
    nb = nbformat.read(ROOT / "examples" / name, as_version=4)
    NotebookClient(nb, timeout=300, kernel_name=kernel or nb.metadata.kernelspec.name,
                   resources={"metadata": {"path": str(cwd)}}).execute()
    return [c for c in nb.cells if c.cell_type == "code"]


def text(cell) -> str:
    """What the cell printed: its streams and the text of its displays (pictures excepted)."""
    out = []
    for o in cell.outputs:
        if o.output_type == "stream":
            out.append(o.text)
        elif o.output_type in ("display_data", "execute_result") and "image/svg+xml" not in o.data:
            out.append(o.data["text/plain"])
    return "".join(out)


def kinds(cell) -> set[str]:
    return {k for o in cell.outputs if o.output_type in ("display_data", "execute_result") for k in o.data}


def test_the_mechanisms_notebook_on_the_mech_kernel(kernel_specs, tmp_path):
    cells = execute("mechanisms.ipynb", tmp_path)
    plain = {"singular": Session(), "m2": Session(dialect="m2")}
    for cell in cells:
        source = cell.source
        dialect = "m2" if source.startswith("%%m2") else "singular"
        source = source.removeprefix("%%m2\n")
        if dialect == "m2":
            assert "text/latex" in kinds(cell)
        if "raises-exception" in cell.metadata.get("tags", []):
            (err,) = [o for o in cell.outputs if o.output_type == "error"]
            with pytest.raises(MechError) as e:
                plain[dialect].execute(source)
            assert err.traceback == re.sub(r"^<string>", f"cell[{cell.execution_count}]",
                                           e.value.format()).rstrip("\n").split("\n")
            assert not any("Traceback" in line for line in err.traceback)
            continue
        assert text(cell) == plain[dialect].execute(source, "<cell>"), source
        if source.startswith(("plotConfigurations", "drawMechanism")):
            (svg,) = [o.data["image/svg+xml"] for o in cell.outputs if "image/svg+xml" in o.data]
            assert svg.startswith("<svg ") and svg.rstrip().endswith("</svg>") and 'class="' in svg
            assert (tmp_path / re.search(r'"(\w+\.svg)"', source).group(1)).is_file()
        if "analyze(" in source:
            (html,) = [o.data["text/html"] for o in cell.outputs if "text/html" in o.data]
            assert html.count("<table") >= 3 and "motion modes" in html and "singular configurations" in html
        if source.startswith(("mechanism m ", "mechanism s3 ", "mechanism fb ", "ring r")):
            assert "text/latex" in kinds(cell)
    latex = [o.data["text/latex"] for c in cells for o in c.outputs if "text/latex" in o.get("data", {})]
    assert r"\left\langle s_{1} l_{1} + s_{2} l_{2},\; c_{1}^{2} + s_{1}^{2} - 1,\; c_{2}^{2} + s_{2}^{2} - 1 \right\rangle" \
        in latex[0]
    assert any(r"\begin{pmatrix} 2 x & - 1 & 0 \\ y & x & - 1 \end{pmatrix}" in t for t in latex)


def test_the_magic_notebook_on_the_python_kernel(tmp_path):
    cells = execute("python.ipynb", tmp_path, "python3")
    by_source = {c.source.split("\n")[0] if not c.source.startswith("%%mech") else c.source: c for c in cells}
    modes = next(c for c in cells if "minAssGTZ(J);" in c.source)
    assert text(modes).startswith("[1]:\n   _[1]=s1+s2\n   _[2]=c1+c2\n") and "text/latex" in kinds(modes)
    assert text(by_source["modes = %mech minAssGTZ(J)"]) == "2"
    assert text(by_source["import sympy"]) == "[s1 + s2, c1 + c2, c2**2 + s2**2 - 1]"
    assert text(by_source["J = mech_session['J']"]) == "True"
    assert text(by_source["from fractions import Fraction"]) == "1/2*s1+1/2*s2\n"
    picture = next(c for c in cells if "drawMechanism" in c.source)
    assert "image/svg+xml" in kinds(picture) and (tmp_path / "q2.svg").is_file()
    (err,) = [o for o in cells[-1].outputs if o.output_type == "error"]
    assert err.traceback == ["<cell>:1:15: error: unexpected '*', expected an expression",
                             "ideal K = c1 +* s1;", "              ^"]


def test_readme_notebook_route(kernel_specs, tmp_path):
    """README's notebook command: after the install (done here by the fixture), `jupyter execute` writes
    the executed notebook beside the example."""
    readme = (ROOT / "README.md").read_text()
    (line,) = [ln for ln in re.findall(r"^```sh\n(.*?)\n```$", readme, re.S | re.M) if "jupyter execute" in ln]
    steps = [shlex.split(step) for step in line.split(" && ")]
    assert steps[1] == [".venv/bin/pip", "install", "-q", ".[jupyter]"] and steps[2] == [".venv/bin/mech", "--install-kernel"]
    argv = steps[3]
    assert argv[:2] == [".venv/bin/jupyter", "execute"]
    shutil.copy(ROOT / argv[2], tmp_path / Path(argv[2]).name)
    jupyter = Path(sys.executable).with_name("jupyter")
    r = subprocess.run([str(jupyter), "execute", Path(argv[2]).name, *argv[3:]], cwd=tmp_path, capture_output=True,
                       text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    done = nbformat.read(tmp_path / "mechanisms_run.ipynb", as_version=4)
    assert sum("image/svg+xml" in o.get("data", {}) for c in done.cells if c.cell_type == "code" for o in c.outputs) == 5
