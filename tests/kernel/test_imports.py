"""The kernel's imports: no cycles among its modules (imports inside functions count), nothing
from the layers above it, and no package attribute shadowing a submodule."""
from __future__ import annotations

import ast
import importlib
import types

from tests.util import ROOT

import mech.kernel

KERNEL = ROOT / "kernel"


def kernel_imports() -> dict[str, set[str]]:
    """Module name (``groebner``) -> the kernel modules it imports anywhere in its source."""
    graph: dict[str, set[str]] = {}
    for path in sorted(KERNEL.glob("*.py")):
        name = path.stem
        deps: set[str] = set()
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom):
                if node.level == 1:
                    if node.module:
                        deps.add(node.module.split(".")[0])
                    else:  # from . import x
                        deps.update(a.name for a in node.names)
                elif node.level == 0 and node.module and node.module.startswith("mech.kernel."):
                    deps.add(node.module.split(".")[2])
            elif isinstance(node, ast.Import):
                deps.update(a.name.split(".")[2] for a in node.names if a.name.startswith("mech.kernel."))
        graph[name] = deps - {name}
    return graph


def find_cycle(graph: dict[str, set[str]]) -> list[str] | None:
    """A cycle of the directed graph as a list of nodes, or None."""
    state: dict[str, int] = {}  # 1: on the current path, 2: done
    path: list[str] = []

    def visit(n: str) -> list[str] | None:
        state[n] = 1
        path.append(n)
        for m in sorted(graph.get(n, ())):
            if state.get(m) == 1:
                return path[path.index(m):] + [m]
            if m not in state and (found := visit(m)):
                return found
        path.pop()
        state[n] = 2
        return None

    for n in sorted(graph):
        if n not in state and (found := visit(n)):
            return found
    return None


def test_no_import_cycle_in_the_kernel():
    graph = kernel_imports()
    assert {"groebner", "engines", "f4", "modular", "mora", "primdec", "ideals"} <= set(graph)
    assert find_cycle(graph) is None, " -> ".join(find_cycle(graph))


def test_the_cycle_finder_finds_cycles():
    assert find_cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == ["a", "b", "c", "a"]
    assert find_cycle({"a": {"b"}, "b": set(), "c": {"a", "b"}}) is None


def test_the_kernel_imports_no_layer_above_it():
    for path in sorted(KERNEL.glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom):
                assert node.level <= 1, f"{path.name} imports from above the kernel"
                assert node.level == 1 or not (node.module or "").startswith("mech"), \
                    f"{path.name} imports {node.module}"
            elif isinstance(node, ast.Import):
                assert not any(a.name.startswith("mech") for a in node.names), path.name


def test_no_submodule_is_shadowed():
    import mech.kernel.groebner as gb
    assert isinstance(gb, types.ModuleType) and callable(gb.groebner)
    for path in sorted(KERNEL.glob("*.py")):
        if path.stem == "__init__":
            continue
        module = importlib.import_module(f"mech.kernel.{path.stem}")
        assert getattr(mech.kernel, path.stem) is module, path.stem
