"""Every command and every procedure of mech's libraries documents an example that runs.

The convention (docs/design.md "Commands and libraries"): the docstring ends with a paragraph
``Example:`` whose lines are input, indented two spaces, and the output each input prints, indented
two spaces and prefixed ``→ ``.  Each example runs in a fresh Session and must print exactly the
documented output (up to spaces at the ends of lines, which a docstring does not keep), an error
as the shell shows it; where Singular has the command, Singular must print the same."""
from __future__ import annotations

import pytest

from mech import Session
from mech.dsl.errors import MechError
from mech.stdlib import LIB_DIR as STDLIB_DIR
from mech.dsl.values import Proc
from mech.dsl.registry import COMMANDS, load_plugins
from tests.util import SINGULAR, run_singular

load_plugins()

#: Commands Singular does not have (their examples are checked by hand): these and mech's own libraries'.
MECH_ONLY = {"limits", "engine", "tangentConeAt", "localComponentsAt", "tangentSpaceDim", "pointType",
             "realRoots", "realSolutions", "countRealSolutions", "realCircuits", "realTopology", "realBranches"}
MECH_LIBS = {"mechanism.lib"}
#: Commands whose top-level list Singular prints in a random order (zerodec: random coordinates).
UNORDERED_IN_SINGULAR = {"zerodec"}

OUT = "  → "


def example(doc: str) -> list[tuple[str, str]]:
    """The Example paragraph of a docstring as (input, expected output) steps ([] if none)."""
    _, sep, tail = (doc or "").partition("\nExample:\n")
    steps: list[list[str]] = []
    for line in tail.splitlines() if sep else []:
        if line.startswith(OUT) or line == OUT.rstrip():
            assert steps, f"output before any input: {line!r}"
            steps[-1][1] += line[len(OUT):] + "\n"
        elif line.startswith("  ") and line.strip():
            if steps and not steps[-1][1]:
                steps[-1][0] += "\n" + line[2:]
            else:
                steps.append([line[2:], ""])
        else:
            raise AssertionError(f"not an input or output line of an example: {line!r}")
    return [(i, o) for i, o in steps]


def unpadded(text: str) -> str:
    """``text`` without spaces at the ends of its lines."""
    return "\n".join(line.rstrip(" ") for line in text.split("\n"))


def shown(s: Session, source: str) -> str:
    """What the shell shows for ``source``: its output, then the error if there is one."""
    try:
        return s.execute(source, "<stdin>")
    except MechError as e:
        return e.output + e.format().rstrip("\n") + "\n"


def library_procs() -> dict[str, str]:
    """The procedures defined by mech's library sources stdlib/*.lib, with their help text."""
    procs = {}
    for path in sorted(STDLIB_DIR.glob("*.lib")):
        s = Session()
        s.execute(f'LIB "{path.name}";')
        for var in s.interpreter.visible_names().values():
            if isinstance(var.value, Proc) and var.value.lib == path.name:
                procs[f"{path.name}:{var.value.name}"] = var.value.doc or ""
    return procs


DOCS = {name: cmd.doc for name, cmd in sorted(COMMANDS.items())} | library_procs()
EXAMPLES = {name: example(doc) for name, doc in DOCS.items()}
WITH_EXAMPLE = sorted(name for name, steps in EXAMPLES.items() if steps)


def test_every_command_and_procedure_has_an_example():
    missing = sorted(name for name, steps in EXAMPLES.items() if not steps)
    assert not missing, f"{len(missing)} commands or procedures have no Example paragraph: {', '.join(missing)}"


@pytest.mark.parametrize("name", WITH_EXAMPLE)
def test_example_prints_what_it_documents(name):
    s = Session()
    for source, expected in EXAMPLES[name]:
        assert unpadded(shown(s, source)) == expected, source


@pytest.mark.singular
@pytest.mark.skipif(not SINGULAR, reason="Singular is not installed")
@pytest.mark.parametrize("name", [n for n in WITH_EXAMPLE if n in COMMANDS and n not in MECH_ONLY
                                  and COMMANDS[n].lib not in MECH_LIBS
                                  and not any(": error: " in o for _, o in EXAMPLES[n])])
def test_example_agrees_with_singular(name):
    steps = EXAMPLES[name]
    theirs, ours = unpadded(run_singular("\n".join(i for i, _ in steps))), "".join(o for _, o in steps)
    if name in UNORDERED_IN_SINGULAR:
        theirs, ours = list_entries(theirs), list_entries(ours)
    assert theirs == ours


def list_entries(text: str) -> list[str]:
    """The entries of a printed top-level list (``[n]:`` blocks) without their numbers, sorted."""
    entries: list[list[str]] = []
    for line in text.splitlines():
        if line.startswith("[") and line.endswith("]:"):
            entries.append([])
        elif entries:
            entries[-1].append(line)
    return sorted("\n".join(e) for e in entries)


def test_help_prints_the_example():
    out = Session().execute("help std;")
    assert out.startswith("std(ideal) or std(matrix) or std(ideal, poly|ideal) or std(module)\nstd(I): a standard basis")
    assert "\n\nExample:\n  ring r = 0,(x,y,z),dp;\n" in out and f"\n{OUT}_[3]=x2-y\n" in out


def test_example_parsing():
    doc = "f(x): what.\n\nExample:\n  int a = 1;\n  a;\n  → 1\n  print(a);\n  print(a);\n  → 1\n  →\n  → 1"
    assert example(doc) == [("int a = 1;\na;", "1\n"), ("print(a);\nprint(a);", "1\n\n1\n")]
    assert example("f(x): no example.") == []
