"""mech's Jupyter kernel over the real protocol (jupyter_client): execution with rich output,
errors in mech's format, completion, help, input completeness, kernel commands, a dialect per
notebook or per cell, limits per cell, an interrupt that keeps the session; installing the specs."""
import json
import subprocess
import sys
import time

import pytest
from jupyter_client.manager import start_new_kernel

from mech import cli


class Client:
    """A started kernel and what its cells produce."""

    def __init__(self, name: str) -> None:
        self.manager, self.client = start_new_kernel(kernel_name=name, startup_timeout=120)

    def reply(self, msg_id: str, timeout: float = 120) -> dict:
        while True:
            msg = self.client.get_shell_msg(timeout=timeout)
            if msg["parent_header"].get("msg_id") == msg_id:
                return msg["content"]

    def run(self, code: str, timeout: float = 120) -> tuple[dict, list]:
        # each reply is checked here: an error must not make the kernel abort the next cells
        msg_id = self.client.execute(code, stop_on_error=False)
        outputs = []
        while True:
            msg = self.client.get_iopub_msg(timeout=timeout)
            if msg["parent_header"].get("msg_id") != msg_id:
                continue
            if msg["msg_type"] == "status" and msg["content"]["execution_state"] == "idle":
                break
            if msg["msg_type"] in ("stream", "display_data", "error"):
                outputs.append((msg["msg_type"], msg["content"]))
        return self.reply(msg_id, timeout), outputs

    def text(self, code: str) -> str:
        reply, outputs = self.run(code)
        assert reply["status"] == "ok", outputs
        return "".join(c["text"] if t == "stream" else c["data"]["text/plain"] for t, c in outputs)

    def close(self) -> None:
        self.client.stop_channels()
        self.manager.shutdown_kernel(now=True)


@pytest.fixture(scope="module")
def kernel(kernel_specs):
    k = Client("mech")
    yield k
    k.close()


def test_cells_keep_their_session_and_show_latex(kernel):
    assert kernel.text("ring r = 0,(x,y,z),dp;\nideal I = x2-y, xy-z;") == ""
    reply, outputs = kernel.run("std(I);\nsize(I);")
    assert reply["status"] == "ok"
    (kind, first), (kind2, second) = outputs
    assert kind == "display_data" and first["data"] == {
        "text/plain": "_[1]=y2-xz\n_[2]=xy-z\n_[3]=x2-y\n",
        "text/latex": r"$\left\langle y^{2} - x z,\; x y - z,\; x^{2} - y \right\rangle$"}
    assert (kind2, second["text"]) == ("stream", "2\n")


def test_errors_are_mech_errors_without_traceback(kernel):
    reply, outputs = kernel.run("int k = 5;\nideal J = x +* y;")
    assert reply["status"] == "error" and reply["ename"] == "MechSyntaxError"
    (kind, err), = outputs
    assert kind == "error" and err["traceback"] == [
        f"cell[{reply['execution_count']}]:2:14: error: unexpected '*', expected an expression",
        "ideal J = x +* y;", "             ^"]
    assert kernel.text("k;") == "5\n"             # statements before the error ran


def test_completion_help_and_completeness(kernel):
    c = kernel.client
    got = kernel.reply(c.complete("ideal G = st", 12))
    assert got["status"] == "ok" and "std" in got["matches"] and got["cursor_start"] == 10
    assert "primdec.lib" in kernel.reply(c.complete('LIB "prim', 9))["matches"]
    assert "I" in kernel.reply(c.complete("size(", 5))["matches"]          # the session's variables
    found = kernel.reply(c.inspect("reduce(x3, std(I));", 13))
    assert found["found"] and found["data"]["text/plain"].startswith("std(ideal)")
    assert not kernel.reply(c.inspect("1 + 1;", 2))["found"]
    assert kernel.reply(c.is_complete("ideal I = x2,"))["status"] == "incomplete"
    assert kernel.reply(c.is_complete("ideal I = x2;"))["status"] == "complete"
    assert kernel.reply(c.is_complete("proc f() {\n  return(1);"))["status"] == "incomplete"
    assert kernel.text("?dim").startswith("dim(ideal)")


def test_other_dialect_per_cell(kernel):
    assert kernel.text("%%m2\nR = QQ[a,b];\nI = ideal(a^2, a*b);\ndim I") == "o3 = 1\n"
    assert kernel.text("%%singular\nsize(I);") == "2\n"        # each dialect keeps its own variables


def test_limits_per_cell_and_kernel_commands(kernel):
    reply, outputs = kernel.run("%timeout 1\nint n = 0;\nwhile (1) { n++; }")
    assert reply["status"] == "error" and outputs[0] == ("stream", {"name": "stdout", "text": "// timeout 1 per cell\n"})
    assert outputs[1][1]["traceback"][0].endswith("error: time limit of 1 s exceeded")
    assert kernel.text("n > 0;") == "1\n"                          # the session goes on
    assert kernel.text("%timeout 0") == "// timeout 0 per cell (none)\n"
    for bad in ("%max-memory 1", "%timeout -3", "%nothing"):
        reply, outputs = kernel.run(bad)
        assert reply["status"] == "error" and outputs[0][1]["traceback"][0].startswith("error: ")
    assert "at least 16 MB" in kernel.run("%max-memory 1")[1][0][1]["evalue"]
    assert kernel.text("%max-memory 500\n1+1;") == "// max-memory 500 per cell\n2\n"


def test_interrupt_keeps_the_session(kernel):
    kernel.text("int j = 7;")
    msg_id = kernel.client.execute("int i; while (1) { i++; }", stop_on_error=False)
    time.sleep(1.5)
    kernel.manager.interrupt_kernel()
    reply = kernel.reply(msg_id, timeout=60)
    assert reply["status"] == "error" and reply["ename"] == "KeyboardInterrupt"
    assert kernel.text("j; i > 0;") == "7\n1\n"


def test_interrupt_and_limits_stop_one_long_flint_call(kernel):
    """(x+y+z+1)^1500 is one python-flint call of minutes: it runs in a child the kernel kills."""
    kernel.text("%max-memory 0\nring r = 0,(x,y,z),dp; int j = 7;")   # no memory limit left by another test
    long = "poly f = (x+y+z+1)^1500;"
    msg_id = kernel.client.execute(long, stop_on_error=False)
    time.sleep(2)
    started = time.monotonic()
    kernel.manager.interrupt_kernel()
    reply = kernel.reply(msg_id, timeout=60)
    assert time.monotonic() - started < 30           # at once; a few seconds on a busy machine
    assert reply["status"] == "error" and reply["ename"] == "KeyboardInterrupt"
    assert kernel.text("j; defined(f);") == "7\n0\n"
    # the time limit on a call that is long but small in memory (the power above reaches any memory limit
    # within seconds on an idle machine): flint needs over 35 s to factor g
    kernel.text("poly g = (x+y+z+1)^60*(x-2y+3z+5)^60+1;")
    started = time.monotonic()
    reply, outputs = kernel.run("%timeout 2\nlist L = factorize(g);")
    assert time.monotonic() - started < 30
    assert reply["status"] == "error" and reply["evalue"] == "time limit of 2 s exceeded in factorize"
    assert outputs[1][1]["traceback"][0] == (f"cell[{reply['execution_count']}]:2:10: error: "
                                             "time limit of 2 s exceeded in factorize")
    reply, outputs = kernel.run("%timeout 0\n%max-memory 200\n" + long)
    assert reply["status"] == "error" and reply["evalue"] == "memory limit of 200 MB exceeded"
    assert kernel.text("%max-memory 0\nj; defined(f);") == "// max-memory 0 per cell (none)\n7\n0\n"


def test_reset_gives_a_fresh_session(kernel):
    kernel.text("int kept = 1;")
    assert kernel.text("%reset") == "// a fresh session: no rings, no variables, no libraries\n"
    reply, outputs = kernel.run("kept;")
    assert reply["status"] == "error" and "unknown identifier 'kept'" in reply["evalue"]


def test_the_m2_kernel(kernel_specs):
    k = Client("mech-m2")
    try:
        info = k.reply(k.client.kernel_info())
        assert info["language_info"]["name"] == "mech-m2" and info["implementation"] == "mech"
        assert k.text("R = QQ[x,y];\nI = ideal(x^2, y);\ncodim I") == "o3 = 2\n"
        assert k.text("%%singular\nring r = 0,(x),dp; x2+1;") == "x2+1\n"
    finally:
        k.close()


def test_kernel_info_of_the_singular_kernel(kernel):
    info = kernel.reply(kernel.client.kernel_info())
    assert info["language_info"]["name"] == "mech" and info["language_info"]["pygments_lexer"] == "mech"


def test_install_the_kernel_specs(tmp_path, monkeypatch):
    r = subprocess.run([sys.executable, "-m", "mech.kernelspec", "install", "--prefix", str(tmp_path)],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    for name, dialect in (("mech", "singular"), ("mech-m2", "m2")):
        spec = json.loads((tmp_path / "share" / "jupyter" / "kernels" / name / "kernel.json").read_text())
        assert spec["argv"] == [sys.executable, "-m", "mech.jupyter", "-f", "{connection_file}", "--dialect", dialect]
        assert spec["interrupt_mode"] == "signal"
    calls = []
    import mech.kernelspec
    monkeypatch.setattr(mech.kernelspec, "install", lambda **kw: calls.append(kw) or ["/k/mech", "/k/mech-m2"])
    assert cli.main(["--install-kernel"]) == 0 and calls == [{}]


def test_the_kernel_refuses_an_unknown_dialect():
    r = subprocess.run([sys.executable, "-m", "mech.jupyter", "--dialect", "maple"], capture_output=True, text=True,
                       timeout=60)
    assert r.returncode == 1 and r.stderr == "mech kernel: error: unknown dialect 'maple' (singular or m2)\n"
