"""The layers import one way, kernel <- dsl <- stdlib <- mech, and no modules import each other in
a cycle: read from the sources' import statements (those inside functions too), not by importing."""
from __future__ import annotations

import ast
from pathlib import Path


from tests.util import ROOT

#: folder of the checkout -> package name, lowest layer first
LAYERS = {"kernel": "mech.kernel", "dsl": "mech.dsl", "stdlib": "mech.stdlib", "mech": "mech"}


def _modules() -> dict[str, Path]:
    mods = {}
    for folder, package in LAYERS.items():
        for path in (ROOT / folder).glob("*.py"):
            mods[package if path.stem == "__init__" else f"{package}.{path.stem}"] = path
    return mods


def _imports(name: str, path: Path, known: set[str]) -> set[str]:
    """The modules of ``known`` that module ``name`` (file ``path``) imports anywhere in its code."""
    package = name if path.stem == "__init__" else name.rpartition(".")[0]
    out: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                parts = package.split(".")
                base = ".".join(parts[:len(parts) - node.level + 1] + ([node.module] if node.module else []))
            else:
                base = node.module or ""
            for a in node.names:  # `from pkg import module` imports the module, else the package
                out.add(f"{base}.{a.name}" if f"{base}.{a.name}" in known else base)
    return {m for m in out if m in known and m != name}


def import_graph() -> dict[str, set[str]]:
    mods = _modules()
    return {name: _imports(name, path, set(mods)) for name, path in mods.items()}


def _layer(module: str) -> int:
    """0 for the kernel's modules, ... 3 for the facade's (the longest package name that contains it)."""
    packages = list(LAYERS.values())
    return max((len(p), i) for i, p in enumerate(packages) if module == p or module.startswith(p + "."))[1]


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan, iteratively)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found = []
    for root in sorted(graph):
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            v, children = work[-1]
            w = next(children, None)
            if w is not None:
                if w not in index:
                    index[w] = low[w] = len(index)
                    stack.append(w)
                    on_stack.add(w)
                    work.append((w, iter(sorted(graph[w]))))
                elif w in on_stack:
                    low[v] = min(low[v], index[w])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on_stack.discard(w)
                    comp.append(w)
                    if w == v:
                        break
                if len(comp) > 1:
                    found.append(sorted(comp))
    return found


def test_graph_sees_the_imports():
    graph = import_graph()
    assert "mech.dsl.values" in graph["mech.dsl.registry"]              # from .values import ...
    assert "mech.kernel.errors" in graph["mech.dsl.boundary"]          # from ..kernel.errors import ...
    assert "mech.dsl.registry" in graph["mech.stdlib"]                 # inside load()
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert [_layer(m) for m in ("mech.kernel.f4", "mech.dsl", "mech.stdlib.m2", "mech.session")] == [0, 1, 2, 3]


def test_layers_import_downwards_only():
    upward = [f"{m} imports {t}" for m, targets in sorted(import_graph().items())
              for t in sorted(targets) if _layer(t) > _layer(m)]
    assert upward == []


def test_no_import_cycles_anywhere():
    assert cycles(import_graph()) == []
