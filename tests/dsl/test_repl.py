"""The REPL (mech.dsl.repl) driven through prompt_toolkit's pipe input: multi-line input, completion,
errors, interrupts, history, help, timing, reset; the lexer; the `mech` command on a terminal; the
examples of docs/repl.md."""
import _thread
import io
import os
import re
import select
import shutil
import signal
import subprocess
import sys
import threading
import time

import pytest
from prompt_toolkit.input import create_pipe_input
from prompt_toolkit.output import DummyOutput

from mech import __version__
from mech.dsl.completion import candidates
from mech.dsl.repl import BANNER, Shell, StatusLine, is_complete, prompt_loop, prompt_session, run_repl

from tests.util import ROOT

DOC = ROOT / "docs" / "repl.md"


@pytest.fixture(autouse=True)
def history(tmp_path, monkeypatch):
    path = tmp_path / "data" / "history"
    monkeypatch.setenv("MECH_HISTORY", str(path))
    return path


def drive(keys, shell=None):
    """Type ``keys`` into a prompt_toolkit REPL (then end of input); the shell and its exit status."""
    shell = shell or Shell()
    with create_pipe_input() as pipe:
        pipe.send_text(keys)
        pipe.close()
        status = prompt_loop(shell, prompt_session(shell, input=pipe, output=DummyOutput()))
    return shell, status


def katsura(n):
    """katsura-n in n+1 variables u0..un as mech source (a ring and the ideal I)."""
    u = [f"u{i}" for i in range(n + 1)]
    eqs = ["+".join(f"2*{v}" if i else v for i, v in enumerate(u)) + "-1"]
    for m in range(n):
        terms = [f"{u[abs(k)]}*{u[abs(m - k)]}" for k in range(-n, n + 1) if abs(m - k) <= n]
        eqs.append("+".join(terms) + f"-{u[m]}")
    return f"ring r = 0,({','.join(u)}),lp;\rideal I = {', '.join(eqs)};\r"


def test_multiline_input_continues_until_complete(capsys):
    keys = ("ring r = 0,(x,y),dp;\r"
            "poly f = x\r+ y;\r"                       # continues until the ';'
            "proc g(int n)\r{\rreturn(n+1);\r}\r"      # until the braces balance
            "g(2);\r"
            "ideal I = x, // a comment; is not the end\ry;\r"
            'string s = "a;\rb";\r'                     # nor is a ';' in a string
            "I; s; f;\r")
    _, status = drive(keys)
    out = capsys.readouterr()
    assert status == 0 and out.err == ""
    assert out.out == "3\nI[1]=x\nI[2]=y\na;\nb\nx+y\n"


def test_is_complete():
    assert is_complete("") and is_complete("  \n")
    assert is_complete("1;") and is_complete("proc f() { return(1); }") and is_complete("if (1) { 2; }")
    assert not is_complete("poly f = x") and not is_complete("proc f() {") and not is_complete("1; 2")
    assert not is_complete("1 /* ; */") and not is_complete('"a;') and is_complete('string s = "{(";')
    assert is_complete(":reset") and is_complete("?std") and is_complete("%time on")


def test_prompt_names_the_basering():
    shell = Shell()
    assert shell.prompt() == "mech> "
    shell.run("ring r1 = 0,(x,y),dp;")
    assert shell.prompt() == "r1> " and shell.continuation(4) == " .. "
    shell.run("ring s = 32003,(a,b),lp;")
    assert shell.prompt() == "s> "
    assert "ring s: ZZ/32003[a,b], lp(2),C" in shell.toolbar()


def test_completion_candidates():
    shell = Shell()
    shell.run('ring r = (0,t),(c1,s1,c2,s2),dp; ideal J = s1+s2; ideal Jacobi = c1; int jj = 1;'
              'proc jolly() { return(1); }')
    it = shell.interp
    assert candidates(it, "J") == ("J", [("J", "ideal"), ("Jacobi", "ideal")])
    assert candidates(it, "std(J")[1][:2] == [("J", "ideal"), ("Jacobi", "ideal")]
    assert candidates(it, "poly f = c")[1][:2] == [("c1", "ring variable of r"), ("c2", "ring variable of r")]
    assert ("t", "parameter") in candidates(it, "t")[1]
    names = dict(candidates(it, "j")[1])
    assert names["jj"] == "int" and names["jolly"] == "proc" and names["jacob"] == "command"
    assert dict(candidates(it, "ra")[1])["radical"] == 'LIB "primdec.lib";'
    st = candidates(it, "st")[1]
    assert st[0] == ("std", "command") and st[-1] == ("static", "keyword")     # commands, then library procs, then keywords
    assert {("stdfglm", "command"), ("string", "command"), ("sturm", 'LIB "rootsur.lib";')} <= set(st)
    assert ("while", "keyword") in candidates(it, "wh")[1]
    assert candidates(it, 'LIB "pri') == ("pri", [("primdec.lib", "library")])
    assert candidates(it, "help jol") == ("jol", [("jolly", "proc")])
    assert ("std", "command") in candidates(it, "?st")[1]
    assert [t for t, _ in candidates(it, ":re")[1]] == [":reset"]
    assert [t for t, _ in candidates(it, "%ti")[1]] == ["%time"]
    assert candidates(it, '"abc s')[1] == [] and candidates(it, "1; // st")[1] == []
    shell.run('LIB "primdec.lib";')
    assert dict(candidates(it, "ra")[1])["radical"] == "command"


def typing(shell, steps):
    """Run the REPL in a thread and type each ``(keys, ready)`` of ``steps`` once ``ready(session)`` holds."""
    with create_pipe_input() as pipe:
        session = prompt_session(shell, input=pipe, output=DummyOutput())
        loop = threading.Thread(target=prompt_loop, args=(shell, session))
        loop.start()
        for keys, ready in steps:
            deadline = time.time() + 10
            while not ready(session) and time.time() < deadline:
                time.sleep(0.02)
            pipe.send_text(keys)
        pipe.close()
        loop.join(30)


def test_tab_completes_in_the_prompt(capsys):
    shell = Shell()
    shell.run("ring r = 0,(x,y),dp; ideal Jacobi = x2;")
    typing(shell, [("Jaco\t", lambda s: True), (";\r", lambda s: s.default_buffer.text == "Jacobi")])
    assert capsys.readouterr().out == "Jacobi[1]=x2\n"


def test_syntax_error_then_a_correct_statement(capsys):
    drive("ring r = 0,(x,y),dp;\rideal I = x +* y;\rideal I = x + y;\rI;\rnothing;\rI[1]^2;\r")
    out = capsys.readouterr()
    assert out.out == "I[1]=x+y\nx2+2xy+y2\n"
    assert out.err == ("<stdin>:1:14: error: unexpected '*', expected an expression\n"
                       "ideal I = x +* y;\n             ^\n"
                       "<stdin>:1:1: error: unknown identifier 'nothing'\nnothing;\n^\n")


def test_interrupt_during_a_long_std_keeps_the_session(capsys):
    # Python's Buchberger: the auto engine may be inside one python-flint call (FGLM's exact solve, which
    # holds the interpreter lock: Ctrl-C waits for it) when the interrupt comes.
    shell = Shell()
    shell.interp.settings["engine"] = "buchberger"
    run = shell.interp.execute

    def execute(text, name):                  # Ctrl-C 0.3 s into katsura-8's lex std (Python loops, minutes)
        if "std(I)" in text:
            threading.Timer(0.3, _thread.interrupt_main).start()
        return run(text, name)
    shell.interp.execute = execute
    started = time.perf_counter()
    drive(katsura(8) + "ideal G = std(I);\rsize(I); defined(G);\rideal K = std(ideal(u0^2-u1, u1));\rK;\r", shell)
    out = capsys.readouterr()
    assert time.perf_counter() - started < 30
    assert out.err == "interrupted (rings and variables are kept)\n"
    assert out.out == "9\n0\nK[1]=u1\nK[2]=u0^2\n"
    assert shell.prompt() == "r> " and len(shell.interp.frames) == 1


def test_interrupt_inside_a_procedure_returns_to_the_top_level(capsys):
    shell = Shell()
    shell.run("ring a = 0,(x),dp; ring b = 0,(y),dp; proc spin() { setring a; int i; while (1) { i++; } }")
    threading.Timer(0.3, _thread.interrupt_main).start()
    shell.run("spin();")
    assert shell.prompt() == "b> " and len(shell.interp.frames) == 1
    shell.run("int k = 3; k; defined(i); y;")
    out = capsys.readouterr()
    assert out.out == "3\n0\ny\n" and out.err == "interrupted (rings and variables are kept)\n"


def test_ctrl_c_at_the_prompt_clears_the_input(capsys):
    _, status = drive("1 +\r\x032;\r")
    assert status == 0 and capsys.readouterr().out == "2\n"


def test_history_persists_across_sessions(history, capsys):
    drive("int secret = 42;\rproc twice(int n)\r{\rreturn(2*n);\r}\r1;\r")
    assert history.is_file() and "+int secret = 42;" in history.read_text()
    capsys.readouterr()
    # a new session (once the history is loaded): Ctrl-R finds the declaration, Up thrice the procedure
    def loaded(n):  # the prompt's buffer holds the n entries of the history (loaded in the background)
        return lambda s: len(s.default_buffer._working_lines) == n + 1
    typing(Shell(), [("\x12secret\r\r", loaded(3)), ("\x1b[A" * 3 + "\r", loaded(4)), ("twice(secret);\r", loaded(5))])
    assert capsys.readouterr().out == "84\n"


def test_unwritable_history_is_kept_in_memory(tmp_path, monkeypatch, capsys):
    (tmp_path / "file").write_text("")
    monkeypatch.setenv("MECH_HISTORY", str(tmp_path / "file" / "history"))
    _, status = drive("1;\r")
    out = capsys.readouterr()
    assert status == 0 and out.out == "1\n" and out.err.startswith("// history is not saved: cannot write ")


def test_help(capsys):
    shell = Shell()
    shell.run("?std")
    shell.run("help;")
    shell.run("? radical;")
    out = capsys.readouterr().out
    assert out.startswith("std(ideal) or std(matrix) or std(ideal, poly|ideal) or std(module)\nstd(I): a standard basis")
    assert "\nbuilt in:\n  " in out and '\nprimdec.lib (LIB "primdec.lib";):\n  ' in out
    assert "radical(ideal) or radical(ideal, any...)    [primdec.lib]\n" in out


def test_timing_switch_and_reset(capsys):
    shell, _ = drive(":time on\rint a = 1;\r:time off\rtimer = 1;\ra;\rtimer = 0;\r:reset\ra;\r:bogus\r")
    out = capsys.readouterr()
    assert out.out == ("// timing on\n// timing off\n1\n// a fresh session: no rings, no variables, no libraries\n")
    times = re.findall(r"// time: \d+\.\d\d s \(cpu \d+\.\d\d s\)\n", out.err)
    assert len(times) == 3  # int a = 1;  timer = 1;  a;  (not the shell commands, not timer = 0;)
    assert "error: unknown identifier 'a'" in out.err
    assert "unknown shell command ':bogus' (:help lists them)" in out.err
    assert shell.prompt() == "mech> "


def test_quit_ends_the_session(capsys):
    _, status = drive("1;\rquit;\r2;\r")
    assert status == 0 and capsys.readouterr().out == "1\n"


def test_status_line_shows_elapsed_time_and_clears_before_output():
    term = io.StringIO()
    status = StatusLine(term, delay=0.0, interval=0.01)
    out = io.StringIO()
    shell = Shell(out=out, err=io.StringIO(), status=status)
    shell.interp.execute = lambda text, name: (time.sleep(0.2), shell.interp.write("done\n"))
    shell.run("anything;")
    shown = term.getvalue()
    assert re.search(r"\r\x1b\[2K\x1b\[2m\[0\.\d s - Ctrl-C interrupts\]\x1b\[0m", shown)
    assert shown.endswith("\r\x1b[2K") and out.getvalue() == "done\n"


def test_highlight_lexer():
    from pygments.token import Comment, Keyword, Name, Number, String
    from mech.dsl.highlight import MechLexer
    tokens = [(t, v) for t, v in MechLexer().get_tokens('ring r = 0,(x,y),dp; ideal I = std(x2+1/2); // c\n'
                                                        'proc f() { return(basering); } "s";\n:reset')
              if v.strip()]
    assert tokens[:2] == [(Keyword.Type, "ring"), (Name, "r")]
    assert (Name.Builtin, "std") in tokens and (Number, "1/2") in tokens and (Comment.Single, "// c") in tokens
    assert (Keyword, "proc") in tokens and (Keyword, "return") in tokens and (String, '"s"') in tokens
    assert (Name.Builtin.Pseudo, "basering") in tokens and tokens[-1] == (Keyword.Pseudo, ":reset")


class Terminal:
    """A command on a pseudo-terminal, its controlling terminal (Ctrl-C sends SIGINT): ``type`` keys,
    ``until`` it shows a text, ``close`` for the exit status."""

    def __init__(self, argv, env):
        import fcntl
        import pty
        import termios
        self.master, slave = pty.openpty()
        self.proc = subprocess.Popen(argv, stdin=slave, stdout=slave, stderr=slave, env=dict(env, TERM="xterm"),
                                     start_new_session=True,
                                     preexec_fn=lambda: fcntl.ioctl(0, termios.TIOCSCTTY, 0))
        os.close(slave)
        self.seen = b""

    def type(self, keys):
        os.write(self.master, keys)

    def until(self, token, timeout=60):
        """Read until ``token`` appears in what the terminal showed since the last call."""
        start = len(self.seen)
        deadline = time.time() + timeout
        while token not in self.seen[start:] and time.time() < deadline:
            if select.select([self.master], [], [], 0.1)[0]:
                try:
                    data = os.read(self.master, 4096)
                except OSError:  # the command has left
                    break
                if b"\x1b[6n" in data:  # answer prompt_toolkit's cursor position request
                    self.type(b"\x1b[1;1R")
                self.seen += data
        return token in self.seen[start:]

    def close(self):
        """Ctrl-D at the prompt; the exit status."""
        try:
            self.type(b"\x04")
            self.until(b"never shown", timeout=30)
            return self.proc.wait(timeout=30)
        finally:
            self.kill()

    def kill(self):
        """End the command and whatever it started (its own process group), if still running."""
        if self.proc.poll() is None:
            os.killpg(self.proc.pid, signal.SIGKILL)
            self.proc.wait(timeout=30)
        if self.master >= 0:
            os.close(self.master)
            self.master = -1


posix_only = pytest.mark.skipif(os.name != "posix", reason="pseudo-terminals are POSIX")


@posix_only
def test_mech_opens_the_repl_on_a_terminal(history):
    term = Terminal([sys.executable, "-m", "mech"], dict(os.environ, MECH_HISTORY=str(history)))
    assert term.until(b"mech>"), term.seen[-500:]
    term.type(b"ring r = 0,(x,y),dp;\r")
    assert term.until(b"r>")
    term.type(b"(x+y)^2;\r")
    assert term.until(b"x2+2xy+y2") and term.until(b"r>")
    assert term.close() == 0
    assert history.read_text().count("\n+") == 2


@posix_only
def test_ctrl_c_and_the_time_limit_stop_one_long_flint_call_on_a_terminal(history):
    """(x+y+z+1)^1500 is one python-flint call of minutes: it runs in a child that Ctrl-C (the
    terminal's SIGINT) and --timeout kill; the session goes on."""
    env = dict(os.environ, MECH_HISTORY=str(history))
    for argv, stop, shown in ((["-q"], b"\x03", b"interrupted (rings and variables are kept)"),
                              (["-q", "--timeout", "2"], b"", b"error: time limit of 2 s exceeded")):
        term = Terminal([sys.executable, "-m", "mech", *argv], env)
        try:
            assert term.until(b"mech>"), term.seen[-500:]
            term.type(b"ring r = 0,(x,y,z),dp; int k = 7;\r")
            assert term.until(b"r>")
            term.type(b"poly f = (x+y+z+1)^1500;\r")
            time.sleep(2)
            started = time.monotonic()
            term.type(stop)
            assert term.until(shown, timeout=60), term.seen[-500:]
            assert time.monotonic() - started < 30
            assert term.until(b"r>")      # typed only at the prompt (a Ctrl-D typed ahead would be lost)
            term.type(b"k; defined(f);\r")
            assert term.until(b"7\r\n0\r\n") and term.until(b"r>"), term.seen[-500:]
            assert term.close() == 0
        finally:
            term.kill()   # also the computation, should the test fail


def test_mech_reads_a_script_when_stdin_is_not_a_terminal():
    r = subprocess.run([sys.executable, "-m", "mech"], input="ring r = 0,(x),dp;\n(x+1)^2;\n", text=True,
                       capture_output=True, timeout=60)
    assert r.returncode == 0 and r.stdout == "x2+2x+1\n"


def test_plain_loop_when_read_is_given(capsys):
    lines = iter(["ring r = 0,(x),dp;", "poly f = x", "+ 1;", "f^2;", ":time on"])

    def read(prompt):
        try:
            return next(lines)
        except StopIteration:
            raise EOFError from None
    assert run_repl(read=read, quiet=True) == 0
    assert capsys.readouterr().out == "x2+2x+1\n// timing on\n\n"


# ---------------------------------------------------------------- docs/repl.md
def doc_blocks():
    """The fenced blocks of docs/repl.md as (info string, text)."""
    return re.findall(r"^```(\S*)\n(.*?)^```$", DOC.read_text(), re.S | re.M)


def transcript(text):
    """A session as (what it shows before the first prompt, [[prompt, input, output], ...]);
    continuation lines start with '.. '."""
    before, items = "", []
    for line in text.splitlines():
        m = re.match(r"^(\w*> )(.*)$", line)
        c = re.match(r"^ *\.\. (.*)$", line)
        if m:
            items.append([m.group(1), m.group(2), ""])
        elif c and items and not items[-1][2]:
            items[-1][1] += "\n" + c.group(1)
        elif items:
            items[-1][2] += line + "\n"
        else:
            before += line + "\n"
    return before, items


def replay(text):
    """Run a session in a fresh shell; what the terminal shows (prompts, inputs, outputs)."""
    before, items = transcript(text)
    buf = io.StringIO()
    shell = Shell(out=buf, err=buf)
    shown = [BANNER.format(version=__version__) + "\n" if before else ""]
    for prompt, source, expected in items:
        lines = source.split("\n")
        assert all(not is_complete("\n".join(lines[:k])) for k in range(1, len(lines))), source
        assert is_complete(source), source
        cont = shell.continuation(len(shell.prompt()))
        shown.append(shell.prompt() + "".join(f"{x}\n" if not k else f"{cont}{x}\n" for k, x in enumerate(lines)))
        if "interrupted" in expected:  # Ctrl-C
            threading.Timer(0.3, _thread.interrupt_main).start()
        buf.seek(0)
        buf.truncate()
        shell.run(source)
        shown.append(buf.getvalue())
    return "".join(shown)


def normalized(text):
    return re.sub(r"\d+\.\d+ s\b", "T s", text)


def test_docs_repl_sessions():
    sessions = [text for info, text in doc_blocks() if info == "mech-repl"]
    assert len(sessions) >= 4
    for text in sessions:
        assert normalized(replay(text)) == normalized(text)


def test_docs_repl_python_and_shell_commands(history):
    blocks = doc_blocks()
    assert {info for info, _ in blocks} <= {"mech-repl", "python", "sh"}
    for info, text in blocks:
        if info == "python":
            exec(compile(text, str(DOC), "exec"), {})  # noqa: S102 - the documentation's own example
    commands = [line.split() for info, text in blocks if info == "sh" for line in text.splitlines()]
    if os.name != "posix" or shutil.which("mech") is None:
        pytest.skip("needs POSIX pseudo-terminals and the mech console script")
    env = dict(os.environ, MECH_HISTORY=str(history))
    for argv in commands:
        term = Terminal([sys.executable if argv[0] == "python" else shutil.which(argv[0]), *argv[1:]], env)
        assert term.until(b"mech>"), (argv, term.seen[-500:])
        assert (b"Singular-compatible" in term.seen) == ("-q" not in argv)
        assert term.close() == 0
