"""The IPython extension in-process: %load_ext mech, %%mech cells sharing one Session, the %mech line
magic (a value without ';'), options, errors shown as mech prints them."""
import pytest
from IPython.core.error import UsageError
from IPython.testing.globalipapp import start_ipython


@pytest.fixture(scope="module")
def ip():
    shell = start_ipython()
    shell.run_line_magic("load_ext", "mech")
    return shell


def test_cells_share_one_session(ip, capsys):
    ip.run_cell_magic("mech", "", "ring r = 0,(x,y),dp;\nideal I = x2-y, xy;\nsize(I);")
    assert capsys.readouterr().out == "2\n"
    ip.run_cell_magic("mech", "", "I[2];")
    assert capsys.readouterr().out.startswith("xy\n")    # a LaTeX display; a terminal prints its text
    G = ip.run_line_magic("mech", "std(I)")
    assert G == ip.user_ns["mech_session"]["I"] and len(G) == 3
    assert ip.run_line_magic("mech", "int k = 4; k;") is None and capsys.readouterr().out == "4\n"
    assert ip.user_ns["mech_session"]["k"] == 4


def test_m2_cells_and_limits(ip, capsys):
    ip.run_cell_magic("mech", "--m2", "R = QQ[a,b];\ndim ideal(a)")
    assert capsys.readouterr().out == "o2 = 1\n"
    with pytest.raises(Exception) as e:
        ip.run_cell_magic("mech", "--timeout 0.5", "int n; while (1) { n++; }")
    assert "time limit of 0.5 s exceeded" in str(e.value)
    assert ip.user_ns["mech_session"].interpreter.limits.timeout is None      # for that cell only
    for bad in ("--timeout -1", "--colour", "--max-memory lots"):
        with pytest.raises(UsageError):
            ip.run_cell_magic("mech", bad, "1;")


def test_errors_show_as_mech_prints_them(ip, capsys):
    result = ip.run_cell("%%mech\nint j = 1;\nj +* 2;")
    assert result.error_in_exec is not None
    out = capsys.readouterr()
    assert "<cell>:2:4: error: unexpected '*', expected an expression\nj +* 2;\n   ^" in out.out + out.err
    assert "Traceback" not in out.out + out.err


def test_the_module_is_the_extension():
    import mech
    assert callable(mech.load_ipython_extension)
