"""The mech command: scripts, -c code, standard input, exit status, error format, start-up imports."""
import os
import subprocess
import sys

import pytest

from mech.cli import main

from tests.util import ROOT

EXAMPLE = ROOT / "examples" / "twisted_cubic.mech"


def mech(*args, stdin=None):
    return subprocess.run([sys.executable, "-m", "mech", *args], input=stdin, text=True, capture_output=True,
                          timeout=120)


def test_done_when_twisted_cubic_code():
    r = mech("-c", "ring r=0,(x,y,z),dp; ideal I=x2-y,xy-z; std(I); dim(std(I));")
    assert r.returncode == 0 and r.stderr == ""
    assert r.stdout == "_[1]=y2-xz\n_[2]=xy-z\n_[3]=x2-y\n1\n"


def test_syntax_error_format_and_status():
    r = mech("-c", "ring r = 0, (x,y), dp; ideal I = x2 +* y;")
    assert r.returncode == 1 and r.stdout == ""
    assert r.stderr == ("<string>:1:38: error: unexpected '*', expected an expression\n"
                        "ring r = 0, (x,y), dp; ideal I = x2 +* y;\n"
                        "                                     ^\n")
    assert "Traceback" not in r.stderr


def test_unknown_identifier_keeps_earlier_output(tmp_path):
    script = tmp_path / "s.sing"
    script.write_text("ring r = 0,(x,y),dp;\nx+y;\npoly f = x + q;\ny;\n")
    r = mech(str(script))
    assert r.returncode == 1 and r.stdout == "x+y\n"
    assert r.stderr == f"{script}:3:14: error: unknown identifier 'q'\npoly f = x + q;\n             ^\n"


def test_unknown_command_underlines_the_call():
    r = mech("-c", "ring r = 0,(x,y),dp;\nlist L = minAssGTZ(ideal(x));")
    assert r.returncode == 1
    assert r.stderr.splitlines()[1:] == ["list L = minAssGTZ(ideal(x));", "         ^~~~~~~~~~~~~~~~~~~"]


def test_stdin_and_dash():
    r = mech("-", stdin="int i = 2; i * 3;")
    assert (r.returncode, r.stdout) == (0, "6\n")
    r = mech(stdin="1 + 1;")  # no arguments, stdin not a terminal: read it as a script
    assert (r.returncode, r.stdout) == (0, "2\n")


def test_quit_exits_zero():
    r = mech("-c", "1; quit; 2;")
    assert (r.returncode, r.stdout) == (0, "1\n")


def test_missing_file():
    r = mech("/nonexistent/file.mech")
    assert r.returncode == 2 and "cannot read" in r.stderr


def test_example_runs():
    r = mech(str(EXAMPLE))
    assert r.returncode == 0 and r.stderr == ""
    assert r.stdout == "G[1]=y2-xz\nG[2]=xy-z\nG[3]=x2-y\n1\nz\n0\n_[1]=0\n_[2]=0\n"


def test_no_sympy_or_jupyter_at_startup():
    code = ("import sys\nfrom mech.cli import main\nmain(['-c', '1;'])\n"
            "print([m for m in ('sympy', 'IPython', 'ipykernel', 'jupyter_client', 'zmq') if m in sys.modules])")
    r = subprocess.run([sys.executable, "-c", code], text=True, capture_output=True, timeout=60)
    assert r.stdout == "1\n[]\n"


def test_main_in_process(capsys):
    assert main(["-c", "ring r = 32003,(x,y),dp; x - 16004*y;"]) == 0
    assert capsys.readouterr().out == "x+15999y\n"
    assert main(["-c", "1;", "--no-warn"]) == 0
    assert main(["-c", "nothing;"]) == 1
    err = capsys.readouterr().err
    assert err.startswith("<string>:1:1: error: unknown identifier 'nothing'")


def test_repl_reads_until_complete(monkeypatch, capsys):
    from mech.dsl.repl import run_repl
    lines = iter(["ring r = 0,(x,y),dp;", "poly f = x", "+ y;", "f;", "if (1) {", "  2;", "}", "nothing;",
                  "f^2;", "quit;", "3;"])

    def read(prompt):
        try:
            return next(lines)
        except StopIteration:
            raise EOFError from None
    assert run_repl(read=read) == 0
    out = capsys.readouterr()
    assert out.out.splitlines()[1:] == ["x+y", "2", "x2+2xy+y2"]
    assert "unknown identifier 'nothing'" in out.err


def test_repl_survives_interrupt_and_eof(capsys):
    from mech.dsl.repl import run_repl
    events = iter(["1;", KeyboardInterrupt, "2;"])

    def read(prompt):
        try:
            e = next(events)
        except StopIteration:
            raise EOFError from None
        if e is KeyboardInterrupt:
            raise KeyboardInterrupt
        return e
    assert run_repl(read=read) == 0
    assert capsys.readouterr().out.splitlines()[1:3] == ["1", ""]


@pytest.mark.skipif(os.name != "posix", reason="console script check on POSIX")
def test_console_script_installed():
    import shutil
    exe = shutil.which("mech")
    if exe is None:
        pytest.skip("console script not on PATH")
    r = subprocess.run([exe, "-c", "2+3;"], text=True, capture_output=True, timeout=60)
    assert r.stdout == "5\n"


@pytest.mark.skipif(os.name != "posix", reason="shell pipes")
def test_a_closed_pipe_ends_quietly():
    script = "int i; for (i = 0; i < 200000; i++) { i; }"
    cmd = f"{sys.executable} -m mech -c '{script}' | head -1; echo status ${{PIPESTATUS[0]}} >&2"
    r = subprocess.run(["bash", "-c", cmd], text=True, capture_output=True, timeout=120)
    assert r.stdout == "0\n" and r.stderr == "status 141\n"


ANALYZE = 'LIB "mechanism.lib"; mechanism m = "fix O; bar O A 1; slider A"; analyze(m);'


@pytest.mark.parametrize("args, form", [(["--format", "latex"], "latex"), (["--format", "json"], "json"),
                                        (["--json"], "json"), (["--format", "text"], "text"), ([], "text")])
def test_format_option_is_analyze_default(args, form, capsys):
    from mech import Session
    assert main(args + ["-c", ANALYZE]) == 0
    assert capsys.readouterr().out == Session().execute(ANALYZE.replace("(m)", f'(m, "{form}")'))


def test_json_alias_and_last_option_wins():
    from mech.cli import _parser
    assert _parser().parse_args(["--json"]).format == "json"
    assert _parser().parse_args(["--json", "--format", "latex"]).format == "latex"
    assert _parser().parse_args([]).format == "text"


def test_unknown_format_option():
    r = mech("--format", "xml", "-c", "1;")
    assert r.returncode == 2 and r.stdout == ""
    assert "argument --format: invalid choice: 'xml' (choose from 'text', 'json', 'latex')" in r.stderr


def test_format_reaches_the_repl(capsys):
    from mech.dsl.repl import run_repl
    lines = iter([ANALYZE, ":reset", ANALYZE])

    def read(prompt):
        try:
            return next(lines)
        except StopIteration:
            raise EOFError from None
    assert run_repl(read=read, quiet=True, settings={"report_format": "latex"}) == 0
    out = capsys.readouterr().out
    assert out.count("\\begin{align*}") == 2 and "mechanism:" not in out


def test_json_reports_are_json_lines(tmp_path):
    import json
    r = subprocess.run([sys.executable, "-m", "mech", "--json", str(ROOT / "examples" / "slider2.mech")], cwd=tmp_path,
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0 and r.stderr == ""
    reports = [json.loads(line) for line in r.stdout.splitlines()]
    assert [d["mobility"] for d in reports] == [1, 1] and len(reports[1]["motion_modes"]) == 2


def test_startup_frozen_once(monkeypatch):
    """The start-up's objects are moved out of the collector's reach once per process, not at
    every program run in it (a second freeze would keep the first program's garbage cycles)."""
    import gc

    from mech import cli
    calls = []
    monkeypatch.setattr(cli, "_FROZEN", [])
    monkeypatch.setattr(gc, "freeze", lambda: calls.append(1))
    assert cli.run_text("int a = 1;", "<string>") == 0
    assert cli.run_text("int b = 2;", "<string>") == 0
    assert calls == [1]
