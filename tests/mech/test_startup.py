"""Start-up (issue 20): ``Session()`` and ``mech -c`` import none of the heavy modules a script
may not need (a test of imports, not of time); commands registered lazily from the record of an
earlier start (mech.dsl.plugins) behave as when every command module is imported at start-up."""
import os
import subprocess
import sys

HEAVY = ("flint", "lark", "sympy", "numpy", "matplotlib", "dask", "pygments", "prompt_toolkit", "mech.dsl.m2",
         "mech.dsl.builder", "mech.stdlib.analysis", "mech.stdlib.reports", "mech.stdlib.plots")

PROBE = f"""
import sys
{{run}}
from mech.kernel.lazy_modules import loaded
print(sorted(m for m in {HEAVY!r} if loaded(m)))
print(sum(m.startswith("mech.stdlib.") for m in sys.modules))
"""

# commands whose overloads come from several modules (size, hilb, nrows, print, std, lcm), help texts
# (usage lists the overloads in order), topics, the listing, a library, a library's type, errors
SCRIPT = """int a = 3; intmat M[2][2] = 1,2,3,4; size(M); nrows(M); print(M); string s = "abc"; size(s);
ring r = 0, (x,y,z), dp; ideal I = x2-y, xy-z, z3; size(I); ideal G = std(I); hilb(G);
LIB "general.lib"; lcm(x2y, xy3);
matrix N[2][3] = x,y,z,1,2,3; nrows(N); module m = [x, y], [z, 1]; size(m); std(m); print(N, "%s");
help size; help hilb; help if; help std; LIB "primdec.lib"; minAssGTZ(I); primdecGTZ(ideal(x2, xy));
LIB "mechanism.lib"; mechanism k = "ground O A 4; bar O B 1; bar B C 3; bar C A 2"; k;
help;
size(1, 2, 3, 4);
"""

M2 = "R = QQ[x,y]\nI = ideal(x^2, x*y)\nJ = ideal(x)\nI : J\nI == J\nI * J\nx^2 % I\ngb I\n"


def _python(code: str, prefix: str) -> str:
    env = dict(os.environ, PYTHONPYCACHEPREFIX=prefix)
    r = subprocess.run([sys.executable, "-c", code], text=True, capture_output=True, env=env, timeout=300)
    assert r.returncode == 0, r.stderr
    return r.stdout


def test_start_up_imports_no_heavy_module(tmp_path):
    for run in ("import mech; mech.Session().execute('int a = 1; a; a = a + 1;')",
                "from mech.cli import main; main(['-c', 'int a = 1; a; a = a + 1;'])"):
        first = _python(PROBE.format(run=run), str(tmp_path))  # writes the record when it is missing
        out = _python(PROBE.format(run=run), str(tmp_path)).splitlines()
        assert out[-2] == "[]" and int(out[-1]) < 3, (first, out)
    # a program the fast parser leaves to Lark, and a ring, load them
    out = _python(PROBE.format(run="import mech; mech.Session().execute('proc f() { return(1); } "
                                   "ring r = 0, x, dp; poly p = x + 1/3; p; f();')"), str(tmp_path)).splitlines()
    assert out[-2] == "['flint', 'lark', 'mech.dsl.builder']"


def test_lazy_commands_behave_as_imported_ones(tmp_path):
    code = ("import mech\nfrom mech.dsl.errors import MechError\n"
            "for dialect, text in (('singular', {s!r}), ('m2', {m!r})):\n"
            "    s = mech.Session(dialect=dialect)\n"
            "    try:\n        print(s.execute(text))\n"
            "    except MechError as e:\n        print(e.output, str(e))\n"
            "from mech.dsl import plugins, registry\n"
            "print(plugins.LAZY, sum(bool(c.pending) for c in registry.COMMANDS.values()))\n"
            ).format(s=SCRIPT, m=M2)
    eager = _python(code, str(tmp_path))     # no record yet: every module imported, the record written
    lazy = _python(code, str(tmp_path))
    *eager_out, eager_state = eager.splitlines()
    *lazy_out, lazy_state = lazy.splitlines()
    assert eager_state.split()[0] == "False" and lazy_state.split()[0] == "True" and int(lazy_state.split()[1]) > 0
    assert lazy_out == eager_out
    assert "wrong arguments for size" in eager and "mechanism" in eager and "primdec.lib" in eager
