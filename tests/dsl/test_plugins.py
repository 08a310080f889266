"""The language runtime knows no library: libraries plug in their commands, types and operators.

A toy type registered here works end to end (declarations, its block form, procedures' parameters,
typeof, errors, highlighting, completion) without any edit of mech.dsl; no module of mech.dsl
imports mech.stdlib or names the mechanism domain; session settings reach commands; Python
exceptions become user errors (the kernel's) or internal errors (bugs)."""
from __future__ import annotations

import ast
import io

import pytest

from mech import Session
from mech.dsl import registry
from mech.dsl.boundary import convert_exception
from mech.dsl.errors import MechInternalError, MechRuntimeError, MechSyntaxError, MechTypeError
from mech.dsl.interpreter import Interpreter
from mech.dsl.types import block_types, register_type, unregister_type
from mech.dsl.values import typeof
from mech.kernel.errors import KernelError
from tests.util import ROOT, error, run

DSL = ROOT / "dsl"


class Toy:
    """A toy graph: nodes and edges."""

    type_name = "toy"

    def __init__(self, nodes: list[str], edges: list[tuple[str, ...]]) -> None:
        self.nodes, self.edges = nodes, edges

    def __str__(self) -> str:
        return f"nodes {' '.join(self.nodes)}; edges {' '.join('-'.join(e) for e in self.edges)}"


def to_toy(v: object) -> Toy:
    if isinstance(v, Toy):
        return v
    if not isinstance(v, str):
        raise MechTypeError(f"cannot convert {typeof(v)} to toy")
    toy = Toy([], [])
    for statement in filter(str.strip, v.split(";")):
        word, *rest = statement.split()
        if word == "node":
            toy.nodes += rest
        elif word == "edge" and len(rest) == 2:
            toy.edges.append(tuple(rest))
        else:
            raise MechRuntimeError(f"toy: cannot read '{statement.strip()}'")
    return toy


@pytest.fixture
def toy():
    Session()  # mech's own library first (as a session does), then the toy type
    register_type("toy", to_toy, default=lambda: Toy([], []), statements=lambda: ("node", "edge"))
    yield
    unregister_type("toy")


def test_a_registered_type_works_end_to_end(toy):
    out = run('toy t { node a b; edge a b; }\nt;\ntypeof(t);\ntoy u = "node c";\nu;\ntoy e;\ne;\n'
              'proc f(toy x) { return(x); }\nf("node z; edge z z");\nlist L = t, u;\nL[2];\n')
    assert out == ("nodes a b; edges a-b\ntoy\nnodes c; edges \nnodes ; edges \nnodes z; edges z-z\n"
                   "nodes c; edges \n")


def test_a_registered_types_errors(toy):
    e = error("toy t { node a; wire a b; }", MechSyntaxError)
    assert e.message == "unknown toy statement 'wire' (expected node, edge)" and (e.line, e.column) == (1, 17)
    e = error("poly p { node a; }", MechSyntaxError)
    assert e.message == f"a {{ ... }} description declares a {' or a '.join(block_types())}, not a poly"
    assert "toy" in block_types()
    assert error('toy t = "edge a";').message == "toy: cannot read 'edge a'"
    assert error("toy t = 3;").message == "cannot convert int to toy"
    register_type("toy", to_toy, default="a toy is declared with its nodes: toy t = \"node a\";")
    assert error("toy t;").message == 'a toy is declared with its nodes: toy t = "node a";'
    assert error("toy t { node a; }", MechSyntaxError).message.endswith("not a toy")


def test_a_registered_type_is_highlighted_and_completed(toy):
    from pygments.token import Keyword

    from mech.dsl.completion import candidates
    from mech.dsl.highlight import MechLexer
    assert (Keyword.Type, "toy") in list(MechLexer().get_tokens("toy t;"))
    assert ("toy", "type") in candidates(Interpreter(out=io.StringIO()), "to")[1]


def test_an_unregistered_type_is_no_keyword():
    assert error("toy t;", MechSyntaxError).message == "unexpected 't' ('toy' is not a type)"


def _dsl_modules() -> list:
    return sorted(DSL.glob("*.py"))


def _imported(path) -> list[str]:
    """The absolute names a module of mech.dsl imports (``mech.dsl.x.name`` for ``from .x import name``),
    in functions too, and the constant names it gives importlib."""
    out: list[str] = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out += [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                base = ".".join(["mech", "dsl"][:3 - node.level] + ([base] if base else []))
            out += [f"{base}.{a.name}" for a in node.names]
        elif isinstance(node, ast.Call) and getattr(node.func, "attr", getattr(node.func, "id", "")) in (
                "import_module", "__import__"):
            out += [a.value for a in node.args if isinstance(a, ast.Constant) and isinstance(a.value, str)]
    return out


def test_the_runtime_imports_no_library():
    """No module of mech.dsl imports mech.stdlib or the facade (mech, mech.session...), in a function
    either, nor by a module name given to importlib."""
    found = [f"{path.name}: {name}" for path in _dsl_modules() for name in _imported(path)
             if (name == "mech" or name.startswith("mech.") or "stdlib" in name)
             and not name.startswith(("mech.dsl.", "mech.kernel."))]
    assert found == []
    assert "mech.kernel.errors.KernelError" in _imported(DSL / "boundary.py")


def test_the_runtime_does_not_name_the_mechanism_domain():
    named = [p.name for p in [*_dsl_modules(), *DSL.glob("*.lark")] if "mechanism" in p.read_text(encoding="utf-8")]
    assert named == []


def test_settings_reach_commands():
    @registry.command("settingTest")
    def setting_test(ctx, key: str) -> str:
        return str(ctx.settings.get(key, "unset"))
    try:
        out = io.StringIO()
        Interpreter(out=out, settings={"report_format": "json"}).execute('settingTest("report_format");')
        Interpreter(out=out).execute('settingTest("report_format");')
        assert out.getvalue() == "json\nunset\n"
        assert "settings" in registry.Context.__annotations__
    finally:
        del registry.COMMANDS["settingTest"]


def test_exceptions_at_the_boundary():
    assert type(convert_exception(KernelError("no such ordering"))) is MechRuntimeError
    assert convert_exception(KernelError("no such ordering")).message == "no such ordering"
    assert convert_exception(ZeroDivisionError("x")).message == "division by 0"
    assert convert_exception(RecursionError()).message == "recursion too deep"
    bug = convert_exception(IndexError("tuple index out of range"))
    assert type(bug) is MechInternalError and bug.message == "internal error: IndexError: tuple index out of range"
    assert type(convert_exception(TypeError("x"))) is MechInternalError


def test_kernel_errors_and_bugs_in_commands():
    @registry.command("kernelErrorTest")
    def kernel_error_test(bug: int) -> int:
        raise KeyError("k") if bug else KernelError("the ordering is not global")
    try:
        e = error("int i = kernelErrorTest(0);")
        assert type(e) is MechRuntimeError and e.format().startswith(
            "<string>:1:9: error: the ordering is not global\nint i = kernelErrorTest(0);\n        ^~~~")
        e = error("kernelErrorTest(1);", MechInternalError)
        assert e.format().startswith("<string>:1:1: error: internal error: KeyError: 'k'")
    finally:
        del registry.COMMANDS["kernelErrorTest"]
