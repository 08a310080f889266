"""Safety: scripts cannot run host code, import Python modules, or read or write files other than
the libraries next to them; and no output is lost: it is flushed as produced, and an error in
statement k leaves the output of statements 1..k-1 and a non-zero exit status."""
import os
import subprocess
import sys
import time

import pytest

from mech import MechError, Session

SECRET = "top-secret-line: do not print me"


def mech(*args, cwd=None, timeout=120):
    return subprocess.run([sys.executable, "-m", "mech", *args], capture_output=True, text=True, timeout=timeout,
                          cwd=cwd)


def error(code: str, name: str = "<string>") -> MechError:
    with pytest.raises(MechError) as info:
        Session().execute(code, name)
    return info.value


# ---------------------------------------------------------------- LIB reads only libraries
@pytest.mark.parametrize("name", ["/etc/passwd", "../x.lib", "sub/x.lib", "./x.lib", "..", ".", "",
                                  "primdec.lib/../../x", "~/x.lib", "/dev/zero"])
def test_lib_takes_no_paths(name):
    e = error(f'LIB "{name}";')
    assert e.message.startswith(f'LIB takes a library name, not a path: "{name}"') or "unknown library" in e.message
    assert (e.line, e.column) == (1, 1)


def test_lib_does_not_run_files_of_mech_itself():
    for name in ("registry.py", "__init__.py", "standard.py", "../dsl/singular.lark"):
        e = error(f'LIB "{name}";')
        assert "unknown library" in e.message or "not a path" in e.message


def test_lib_finds_files_next_to_the_script_only(tmp_path):
    (tmp_path / "mine.lib").write_text('proc hello() { return("hello from mine.lib"); }\n')
    (tmp_path / "secret.txt").write_text(SECRET + "\n")
    sub = tmp_path / "sub"
    sub.mkdir()
    (sub / "run.sing").write_text('LIB "mine.lib";\n')
    (tmp_path / "run.sing").write_text('LIB "mine.lib"; hello();\nLIB "sub/../secret.txt";\n')
    r = mech(str(tmp_path / "run.sing"), cwd="/")
    assert r.stdout == "hello from mine.lib\n"
    assert r.returncode == 1 and "not a path" in r.stderr and SECRET not in r.stderr
    r = mech(str(sub / "run.sing"), cwd=str(tmp_path))  # the script's directory, not the current one
    assert r.returncode == 1 and "unknown library 'mine.lib'" in r.stderr


def test_absolute_library_path_does_not_leak_the_file(tmp_path):
    secret = tmp_path / "secret.lib"
    secret.write_text(SECRET + "\n")
    r = mech("-c", f'LIB "{secret}";', cwd="/")
    assert r.returncode == 1 and SECRET not in r.stderr + r.stdout


# ---------------------------------------------------------------- no host code, no files
@pytest.mark.parametrize("code", ['system("sh", "ls");', 'system("pid");', 'system("getenv", "HOME");',
                                  'system("setenv", "X", "1");', 'system("--cpus");', 'system("random");',
                                  'system("sh");', 'system("execute", "ls");'])
def test_system_runs_nothing(code):
    e = error(code)
    assert "is not supported" in e.message


def test_system_ticks_per_sec_is_harmless():
    assert Session().execute('system("--ticks-per-sec", 1000); system("--ticks-per-sec");') == "1000\n"


@pytest.mark.parametrize("code, message", [
    ('read("/etc/passwd");', "unknown command 'read'"),
    ('string s = read("/etc/passwd");', "unknown command 'read'"),
    ('write(":w /tmp/mech-safety", 1);', "unknown command 'write'"),
    ('fopen("/etc/passwd", "r");', "unknown command 'fopen'"),
    ('dump(":w /tmp/mech-safety");', "unknown command 'dump'"),
    ('getdump("/etc/passwd");', "unknown command 'getdump'"),
    ('status("/etc/passwd", "exists");', "unknown command 'status'"),
    ('open("/etc/passwd");', "unknown command 'open'"),
    ('__import__("os");', "unknown command '__import__'"),
    ('eval("1");', "unknown command 'eval'"),
    ('exec("1");', "unknown command 'exec'"),
    ('link l = ":r /etc/passwd";', "type 'link' is not supported"),
    ('< "/etc/passwd";', "unexpected '<'"),
    ('import os;', "unexpected 'os'"),
    ('`"1"`;', "`1` is undefined"),  # a backquote names a variable, it runs no code
    ('execute("system(\\"sh\\", \\"ls\\");");', 'system("sh") is not supported'),  # \" escapes a quote
])
def test_file_and_host_access_fails_clearly(code, message):
    e = error(code)
    assert message in e.message
    assert e.line >= 1 and e.format().count("\n") >= 3  # located, with the source line and a caret


def test_execute_runs_only_the_language():
    s = Session()
    assert s.execute('execute("int i = 6; i * 7;");') == "42\n"
    with pytest.raises(MechError, match="is not supported"):
        s.execute('string cmd = "sh"; execute("system(cmd);");')


def test_scripts_write_no_files(tmp_path):
    attempts = ['write(":w out.txt", 1);', 'dump(":w out.txt");', 'link l = ":w out.txt";', 'LIB "out.txt";',
                'execute("write(\\":w out.txt\\", 1);");', 'system("sh", "touch out.txt");']
    for code in attempts:
        r = mech("-c", code, cwd=str(tmp_path))
        assert r.returncode == 1 and "Traceback" not in r.stderr
    assert os.listdir(tmp_path) == []


# ---------------------------------------------------------------- no output lost
def test_error_in_statement_k_keeps_the_output_before_it(tmp_path):
    script = tmp_path / "s.sing"
    script.write_text("ring r = 0, (x,y), dp;\n1;\nx + y;\nint i;\nfor (i = 1; i <= 3; i++) { i; }\n"
                      "poly f = x / 0;\n5;\n")
    r = mech(str(script))
    assert r.returncode == 1
    assert r.stdout == "1\nx+y\n1\n2\n3\n"
    assert r.stderr.startswith(f"{script}:6:10: error: division by 0\n")


def test_syntax_error_late_in_a_script_keeps_the_output_before_it(tmp_path):
    script = tmp_path / "s.sing"
    script.write_text("".join(f"{i};\n" for i in range(1, 2001)) + "int j = ;\n9999;\n")
    r = mech(str(script))
    assert r.returncode == 1
    assert r.stdout == "".join(f"{i}\n" for i in range(1, 2001))
    assert r.stderr.startswith(f"{script}:2001:9: error: unexpected ';'")


def test_error_inside_a_procedure_keeps_the_output_before_it():
    r = mech("-c", 'proc f(int n) { "in f"; n; return(1 div (n - 2)); } f(1); f(2); "never";')
    assert r.returncode == 1
    assert r.stdout == "in f\n1\n-1\nin f\n2\n"
    assert "division by 0" in r.stderr and "in procedure 'f' called here" in r.stderr


def test_a_lot_of_output_then_an_error_through_pipes():
    r = mech("-c", "int i; for (i = 1; i <= 20000; i++) { i; } nothing;")
    assert r.returncode == 1
    assert r.stdout.count("\n") == 20000 and r.stdout.endswith("19999\n20000\n")
    assert "unknown identifier 'nothing'" in r.stderr


def test_output_is_flushed_as_produced():
    """The first results reach the pipe while the script is still computing."""
    p = subprocess.Popen([sys.executable, "-m", "mech", "--timeout", "60", "-c", "1; 2; while (1) { }"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        start = time.monotonic()
        assert p.stdout.readline() == "1\n"
        assert p.stdout.readline() == "2\n"
        assert p.poll() is None and time.monotonic() - start < 50
    finally:
        p.kill()
        p.communicate()
