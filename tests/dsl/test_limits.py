"""Time and memory limits per statement (``mech.dsl.limits``): ``mech --timeout/--max-memory``,
``Session(timeout=..., max_memory=...)`` and ``limits(...)`` in the language.  A limit stops a
runaway computation with a clear error and leaves the session usable."""
import re
import resource
import shlex
import shutil
import subprocess
import sys
import threading
import time

import pytest

from mech import MechError, Session
from mech.dsl.interpreter import Interpreter
from mech.dsl.limits import MechLimitError, default_limits

from tests.util import ROOT

CYCLIC7 = ("ring r = 0, (x(1..7)), dp;\n"
           "ideal I = " + ", ".join(
               "+".join("*".join(f"x({(i + j) % 7 + 1})" for j in range(k)) for i in range(7)) for k in range(1, 7))
           + ", x(1)*x(2)*x(3)*x(4)*x(5)*x(6)*x(7)-1;\nint k = 3;\n")


def limit_error(session, code):
    with pytest.raises(MechLimitError) as info:
        session.execute(code)
    return info.value


# ---------------------------------------------------------------- time
def test_timeout_stops_std_with_a_clear_error_and_keeps_the_session():
    s = Session(timeout=1)
    s.execute(CYCLIC7)
    e = limit_error(s, "ideal J = std(I);")
    assert e.message == "time limit of 1 s exceeded in std"
    assert e.format() == ("<string>:1:11: error: time limit of 1 s exceeded in std\n"
                          "ideal J = std(I);\n"
                          "          ^~~~~~\n")
    assert s.execute("k; nvars(basering); I[1];") == "3\n7\nx(1)+x(2)+x(3)+x(4)+x(5)+x(6)+x(7)\n"
    assert "J" not in s
    assert s.execute("std(ideal(x(1)^2, x(1)*x(2)));") == "_[1]=x(1)*x(2)\n_[2]=x(1)^2\n"


def test_timeout_in_a_procedure_restores_frames_and_basering():
    s = Session(timeout=0.5)
    s.execute("ring r = 0, (x,y), dp; poly f = x+y;\n"
              "proc spin() { ring t = 0, (u), dp; int i; while (1) { i++; } }")
    e = limit_error(s, "spin();")
    assert e.message == "time limit of 0.5 s exceeded"
    assert "in procedure 'spin' called here" in e.format()
    assert len(s.interpreter.frames) == 1
    assert s.execute("f; nvars(basering);") == "x+y\n2\n"


def test_timeout_of_a_top_level_loop_and_of_eval():
    s = Session(timeout=0.5)
    e = limit_error(s, "int i;\nwhile (1) { i++; }")
    assert (e.line, e.message) == (2, "time limit of 0.5 s exceeded")
    s.execute(CYCLIC7)
    with pytest.raises(MechLimitError, match="exceeded in std"):
        s.eval("std(I)")
    assert s.eval("k") == 3


def test_the_limit_is_per_statement():
    s = Session(timeout=1)
    out = s.execute("int n; int i;\n" + "for (i = 0; i < 2000; i++) { n = n + i; }\n" * 3 + "n;")
    assert out == str(3 * sum(range(2000))) + "\n"


def test_limits_in_a_thread_that_is_not_the_main_one():
    errors = []

    def work():
        try:
            Session(timeout=0.5).execute("while (1) { }")
        except MechError as e:
            errors.append(e.message)
    t = threading.Thread(target=work)
    t.start()
    t.join(30)
    assert errors == ["time limit of 0.5 s exceeded"]


# ---------------------------------------------------------------- memory
def test_memory_limit_stops_a_growing_computation():
    before = resource.getrlimit(resource.RLIMIT_AS)
    s = Session(max_memory=150)
    s.execute("ring r = 0, (x,y), dp; poly f = x2+y; int k = 5;")
    e = limit_error(s, 'string st = "0123456789"; while (1) { st = st + st; }')
    assert e.message == "memory limit of 150 MB exceeded"
    assert resource.getrlimit(resource.RLIMIT_AS) == before
    # st keeps what it had reached: the limit is on what each statement adds, so the session goes on
    assert s.execute("f; k; size(st) > 1000000;") == "x2+y\n5\n1\n"


def test_memory_backstop_catches_one_huge_allocation():
    s = Session(max_memory=150)
    e = limit_error(s, "intvec v = 1..2000000000;")
    assert e.message == "memory limit of 150 MB exceeded"
    assert s.execute("intvec w = 1..3; w;") == "1,2,3\n"


# ---------------------------------------------------------------- the language's limits(...)
def test_limits_command():
    s = Session()
    assert s.execute("limits();") == "timeout none, max-memory none (per statement)\n"
    s.execute('limits("timeout", 1); limits("max-memory", 4000);')
    assert s.execute('limits("timeout"); limits("--max-memory"); limits();') == \
        "1\n4000\ntimeout 1 s, max-memory 4000 MB (per statement)\n"
    e = limit_error(s, "while (1) { }")
    assert e.message == "time limit of 1 s exceeded"
    s.execute('limits("timeout", 0); limits("max-memory", 0);')
    assert s.interpreter.limits.timeout is None and s.interpreter.limits.max_memory is None
    for bad, msg in [('limits("speed", 1);', 'unknown limit "speed"'),
                     ('limits("timeout", -2);', "nonnegative"),
                     ('limits("timeout", "soon");', "needs a number of seconds")]:
        with pytest.raises(MechError, match=msg):
            s.execute(bad)


def test_python_api_rejects_bad_limits():
    with pytest.raises(ValueError):
        Session(timeout=-1)
    with pytest.raises(ValueError):
        Session(max_memory="lots")


def test_default_limits_apply_to_new_interpreters_only_inside_the_block():
    with default_limits(3, 500):
        it = Interpreter()
        assert (it.limits.timeout, it.limits.max_memory) == (3, 500)
    assert Interpreter().limits.timeout is None


# ---------------------------------------------------------------- the command line
def mech(*args, **kw):
    return subprocess.run([sys.executable, "-m", "mech", *args], capture_output=True, text=True, timeout=120, **kw)


def test_cli_timeout(tmp_path):
    script = tmp_path / "run.sing"
    script.write_text(CYCLIC7 + "k;\nideal J = std(I);\nk + 1;\n")
    r = mech("--timeout", "1", str(script))
    assert r.returncode == 1
    assert r.stdout == "3\n"
    assert r.stderr == f"{script}:5:11: error: time limit of 1 s exceeded in std\nideal J = std(I);\n          ^~~~~~\n"


def test_cli_max_memory():
    r = mech("--max-memory", "300", "-c", 'int k = 7; k; string s = "ab"; while (1) { s = s + s; }')
    assert r.returncode == 1 and r.stdout == "7\n"
    assert "error: memory limit of 300 MB exceeded" in r.stderr and "Traceback" not in r.stderr


def test_cli_timeout_inside_one_flint_call_ends_the_script():
    """A long python-flint call under a limit runs in a child process (mech/kernel/offload.py):
    the limit stops it in time, with the limit error at the statement."""
    t = time.monotonic()
    r = mech("--timeout", "2", "-c", "ring r = 0,(x,y,z),dp; int k = 1; k; poly f = (x+y+z+1)^1500; k;")
    assert time.monotonic() - t < 20  # 2 s + start-up on a busy machine (the call alone: minutes)
    assert r.returncode == 1 and r.stdout == "1\n"
    assert r.stderr == ("<string>:1:38: error: time limit of 2 s exceeded\n"
                        "ring r = 0,(x,y,z),dp; int k = 1; k; poly f = (x+y+z+1)^1500; k;\n" + " " * 37 + "^\n")


def test_cli_memory_limit_inside_one_flint_call_ends_the_script():
    r = mech("--max-memory", "200", "-c", "ring r = 0,(x,y,z),dp; 7; poly f = (x+y+z+1)^1500;")
    assert r.returncode == 1 and r.stdout == "7\n"
    assert r.stderr.startswith("<string>:1:36: error: memory limit of 200 MB exceeded\n")


def unoffloaded(*args):
    """``mech ARGS`` with every python-flint call kept in the process: the watcher's case."""
    code = ("import sys; from mech.kernel import offload; offload.THRESHOLD = float('inf'); "
            "from mech.cli import main; sys.exit(main(sys.argv[1:]))")
    return subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True, timeout=120)


def test_watcher_ends_a_script_inside_one_flint_call():
    """One python-flint call in the process holds the interpreter: the watcher process
    (mech/watcher.py) ends the script a grace after the limit, with the limit error at the statement."""
    t = time.monotonic()
    r = unoffloaded("--timeout", "2", "-c", "ring r = 0,(x,y,z),dp; int k = 1; k; poly f = (x+y+z+1)^1500; k;")
    assert time.monotonic() - t < 30  # 2 s + the grace (3 s) + start-up on a busy machine
    assert r.returncode == 1 and r.stdout == "1\n"
    assert r.stderr.startswith("<string>:1:38: error: time limit of 2 s exceeded (stopped from outside")
    assert r.stderr.endswith("\n" + " " * 37 + "^" + "~" * 22 + "\n")


def test_watcher_reports_the_memory_limit_inside_one_flint_call():
    r = unoffloaded("--max-memory", "200", "-c", "ring r = 0,(x,y,z),dp; 7; poly f = (x+y+z+1)^1500;")
    # the allocation that meets the address-space limit first aborts the child: GMP prints its own
    # "Cannot reallocate memory" line (the child's stderr), FLINT its "Unable to allocate memory" (stdout)
    assert r.returncode == 1 and r.stdout.split("FLINT exception")[0] == "7\n"
    assert "\n<string>:1:27: error: memory limit of 200 MB exceeded" in "\n" + r.stderr


def test_watcher_passes_on_the_exit_status_and_output():
    r = mech("--timeout", "5", "-c", 'int k = 2; k; quit;')
    assert (r.returncode, r.stdout, r.stderr) == (0, "2\n", "")
    r = mech("--timeout", "5", "-c", "1; 1 div 0;")
    assert r.returncode == 1 and r.stdout == "1\n" and "division by 0" in r.stderr


def test_cli_limits_reach_the_repl_and_bad_values_are_refused(monkeypatch):
    r = mech("--timeout", "-1", "-c", "1;")
    assert r.returncode == 2 and "expected a nonnegative number" in r.stderr
    from mech import cli
    from mech.dsl import repl
    seen = []
    monkeypatch.setattr(repl, "run_repl", lambda **kw: seen.append(Interpreter().limits.timeout) or 0)
    monkeypatch.setattr(sys.stdin, "isatty", lambda: True)
    assert cli.main(["--timeout", "2.5"]) == 0
    assert seen == [2.5] and Interpreter().limits.timeout is None


# ---------------------------------------------------------------- docs/reliability.md runs as shown
DOC = ROOT / "docs" / "reliability.md"


def doc_blocks():
    """The fenced blocks of docs/reliability.md as (info string, text)."""
    return re.findall(r"^```(\w*)\n(.*?)^```$", DOC.read_text(), re.M | re.S)


def test_doc_console_examples():
    blocks = [text for info, text in doc_blocks() if info == "console"]
    assert blocks
    for text in blocks:
        for command, expected in re.findall(r"^\$ (.*)\n((?:(?!\$ ).*\n)*)", text, re.M):
            argv = shlex.split(command)
            assert argv[0] == "mech"
            r = subprocess.run([sys.executable, "-m", "mech", *argv[1:]], stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True, timeout=120)
            assert r.stdout == expected, command


def test_doc_python_example(capsys):
    blocks = doc_blocks()
    for (info, code), (next_info, expected) in zip(blocks, blocks[1:]):
        if info == "python":
            exec(compile(code, str(DOC), "exec"), {})
            assert next_info == "text" and capsys.readouterr().out == expected


def test_doc_big_run_commands_work(tmp_path):
    """The campaign commands, with their counts cut down."""
    root = DOC.parent.parent
    for info, text in doc_blocks():
        if info != "sh":
            continue
        for line in text.splitlines():
            command = shlex.split(line.split("#")[0])
            if "differential" in line and shutil.which("Singular") is None:
                continue
            command = [re.sub(r"^\d{3,}$", "2", a) for a in command]
            assert command[0] == "python"
            r = subprocess.run([sys.executable, *command[1:]], capture_output=True, text=True, timeout=600, cwd=root)
            assert r.returncode == 0, r.stdout + r.stderr
            assert "0 failures" in r.stdout or "0 mismatches" in r.stdout
