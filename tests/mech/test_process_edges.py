"""The edges of the process: every one ends with a clean message and an exit status, never a
Python traceback or a hang (closed standard streams, a C locale, a byte-order mark, Python's
inspect mode, limits out of range, huge numbers where a computation would not end)."""
import os
import resource
import subprocess
import sys

import pytest

from mech import MechError, Session


def mech(*args, stdin=None, env=None, **kw):
    return subprocess.run([sys.executable, "-m", "mech", *args], input=stdin, text=True, capture_output=True,
                          timeout=120, env={**os.environ, **(env or {})}, **kw)


def closed(*args, stream: str):
    """``mech ARGS`` with standard input or output closed (as ``mech <&-`` / ``mech >&-``)."""
    cmd = " ".join([f"'{sys.executable}'", "-m", "mech", *args, "<&-" if stream == "stdin" else ">&-"])
    return subprocess.run(["bash", "-c", cmd], capture_output=True, text=True, timeout=60)


@pytest.mark.parametrize("args", [["-"], []])
def test_closed_standard_input(args):
    r = closed(*args, stream="stdin")
    assert r.returncode == 2 and "Traceback" not in r.stderr
    assert r.stderr == "mech: error: standard input is closed (give a FILE, -c CODE, or run in a terminal)\n"


def test_closed_standard_output():
    r = closed("-c", "'1;'", stream="stdout")
    assert (r.returncode, r.stderr) == (2, "mech: error: standard output is closed\n")


def test_c_locale_output_is_escaped_not_an_error():
    env = {"LC_ALL": "C", "LANG": "C", "PYTHONUTF8": "0", "PYTHONCOERCECLOCALE": "0", "PYTHONIOENCODING": ""}
    r = mech("-c", 'print("Gröbner ∩");', env=env)
    assert (r.returncode, r.stdout, r.stderr) == (0, "Gr\\xf6bner \\u2229\n", "")
    r = mech("-c", 'print("Gröbner");', env={"PYTHONIOENCODING": "ascii"})
    assert (r.returncode, r.stdout) == (0, "Gr\\xf6bner\n")


def test_a_byte_order_mark_is_dropped(tmp_path):
    script = tmp_path / "bom.mech"
    script.write_bytes("\ufeffring r = 0,(x),dp; x2;\n".encode())
    assert (mech(str(script)).stdout, mech("-", stdin="\ufeff1+1;").stdout) == ("x2\n", "2\n")
    r = subprocess.run([sys.executable, "-m", "mech", "-"], input=b"\xff1;", capture_output=True, timeout=60)
    assert r.returncode == 2 and r.stderr == b"mech: error: standard input is not UTF-8 text\n"


def test_python_inspect_mode_and_startup_file(tmp_path):
    startup = tmp_path / "startup.py"
    startup.write_text("print('startup')\n")
    for env in ({"PYTHONINSPECT": "1"}, {"PYTHONSTARTUP": str(startup)}, {"PYTHONINSPECT": "1", "PYTHONSTARTUP": str(startup)}):
        r = mech("-c", "1;", env=env, stdin="")
        assert (r.returncode, r.stdout, r.stderr) == (0, "1\n", ""), env
        r = mech("-c", "nothing;", env=env, stdin="")
        assert r.returncode == 1 and "Traceback" not in r.stderr and "SystemExit" not in r.stderr


@pytest.mark.parametrize("value", ["1", "15.9", "-1", "nan", "inf"])
def test_memory_limits_out_of_range_are_refused(value):
    r = mech("--max-memory", value, "-c", "1;")
    assert r.returncode == 2 and r.stdout == "" and "argument --max-memory: expected" in r.stderr
    if value == "1":
        assert "expected 0 (no limit) or at least 16 MB, got '1'" in r.stderr


def test_memory_limits_in_the_session_and_the_language():
    with pytest.raises(ValueError, match="at least 16 MB"):
        Session(max_memory=1)
    s = Session()
    with pytest.raises(MechError, match="at least 16 MB"):
        s.execute('limits("max-memory", 1);')
    assert Session(max_memory=0).interpreter.limits.max_memory is None


def test_the_memory_limit_bounds_the_process():
    """A statement doubling a string: the process stays near the limit (the address-space backstop
    is the limit plus a quarter), not at twice it."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    r = mech("--max-memory", "300", "-c", 'string s = "ab"; while (1) { s = s + s; }')
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    assert r.returncode == 1 and "error: memory limit of 300 MB exceeded" in r.stderr
    assert before / 1024 > 375 or peak < 300 + 75 + 100   # limit, backstop slack, the interpreter itself


@pytest.mark.parametrize("code, message", [
    ('LIB "mechanism.lib"; mechanism m = "fix O; bar O A l1; bar A B l2; slider B"; setLengths(m, "1e999999999", 1);',
     "setLengths: '1e999999999': exponent too large (at most 10000)"),
    ('LIB "mechanism.lib"; mechanism m = "fix O; bar O A 1; bar A B 1; slider B";'
     'drawMechanism(m, list("1e999999999", 0, 1, 0), "m.svg");',
     "drawMechanism: '1e999999999' is not a number"),
    ("ring r = 0,(x,y),(a(bigint(10)^100000),dp);", "an ordering's size or weights must be at most 2147483647"),
    ("ring r = 0,(x,y),(a(1" + "0" * 100000 + "),dp);", "integer literal too long (100001 digits; at most 100000)"),
    ("bigint k = 1" + "0" * 5000 + ";", None),
])
def test_huge_numbers_end_quickly_with_a_message(code, message, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    s = Session(timeout=20)
    if message is None:
        s.execute(code)
        assert s.execute("size(string(k));") == "5001\n"
        return
    with pytest.raises(MechError) as e:
        s.execute(code)
    assert message in e.value.message and "internal" not in e.value.message
    assert not list(tmp_path.iterdir())


def test_machine_int_powers_wrap_as_in_singular():
    """int arithmetic wraps at 64 bits with Singular's warning (10^100000 ends at once): a weight 0."""
    s = Session(timeout=20)
    out = s.execute("ring r = 0,(x,y),(a(10^100000),dp); r;")
    assert "// ** int overflow(^), result may be wrong" in out and "weights  0" in out
    with pytest.raises(MechError) as e:
        s.execute("int k = 1" + "0" * 5000 + ";")
    assert "int = bigint is not supported" in e.value.message


def test_decimal_lengths_still_work():
    s = Session()
    out = s.execute('LIB "mechanism.lib"; mechanism m = "fix O; bar O A l1; bar A B l2; slider B";'
                    'setLengths(m, "1.5e2", "0.25");')
    assert out == "fix O 0 0; bar O A 150; bar A B 1/4; slider B\n"


def test_shell_commands_in_a_script_say_what_they_are():
    r = mech(stdin="ring r = 0,(x),dp;\n:time on\n")
    assert r.returncode == 1 and r.stderr.startswith(
        "<stdin>:2:1: error: unexpected ':': ':time on' is a command of the interactive shell (mech in a terminal), "
        "not of scripts\n")
