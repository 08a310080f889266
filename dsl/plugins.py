"""Loading a library package's commands lazily (start-up time, issue 20).

A library package (``mech.stdlib``: about 120 modules registering about 600 commands) costs about
0.2 s to import, at every start.  :func:`load_package` imports it all only when its *record* is
missing or stale: which module registered which commands (and the order of their overloads), the
other dialects' commands and operators, the types, the help topics and the library names.  The
record is kept in a JSON file in the package's ``__pycache__`` (or under ``sys.pycache_prefix``),
keyed, as Python's byte code is, by the sizes and modification times of the package's and the
language runtime's sources.  With a valid record, stand-ins are registered instead
(:func:`mech.dsl.registry.defer`, :func:`~mech.dsl.registry.defer_operator`,
:func:`mech.dsl.types.defer_type`): a command's modules are imported when it is first called or its
help read, a type's when it is first declared, an operator's when it is first applied.  Names,
libraries and help topics (listing, completion, ``help;``) need no import.
"""
from __future__ import annotations

import importlib
import json
import os
import sys
import zlib
from pathlib import Path
from typing import Any, Optional

from . import registry, types

FORMAT = 1  # of the record; a change makes older records stale
#: whether the last package was registered from its record (its modules not imported)
LAZY = False
_RUNTIME = Path(__file__).resolve().parent


def load_package(package: str, folder: Path) -> None:
    """Register the commands of the package ``package`` (its modules are the ``*.py`` files in
    ``folder`` not starting with ``_``), from its record when it is valid, else by importing every
    module (and writing the record)."""
    modules = sorted(p[:-3] for p in os.listdir(folder) if p.endswith(".py") and not p.startswith("_"))
    global LAZY
    key = _key(folder, modules)
    path = _record_path(folder)
    record = _read(path, key)
    LAZY = record is not None
    if record is not None:
        _replay(package, record)
        return
    fresh = not any(f"{package}.{m}" in sys.modules for m in modules)
    record = _import_all(package, modules)
    if fresh:  # (a module imported earlier registered unseen: no record then)
        _write(path, {"key": key, **record})


def _key(folder: Path, modules: list[str]) -> int:
    """The sources' names, sizes and modification times (the package's and the runtime's)."""
    parts = [str(FORMAT), sys.version]
    for d, names in ((folder, [f"{m}.py" for m in modules] + ["__init__.py"]),
                     (_RUNTIME, sorted(p for p in os.listdir(_RUNTIME) if p.endswith(".py")))):
        for name in names:
            st = os.stat(d / name)
            parts.append(f"{d}/{name}:{st.st_size}:{st.st_mtime_ns}")
    return zlib.crc32("\n".join(parts).encode())


def _record_path(folder: Path) -> Path:
    prefix = sys.pycache_prefix
    base = Path(prefix + str(folder.resolve())) if prefix else folder / "__pycache__"
    return base / "mech-registry.json"


def _read(path: Path, key: int) -> Optional[dict]:
    try:
        with open(path, encoding="utf-8") as f:
            record = json.load(f)
    except (OSError, ValueError):
        return None
    return record if isinstance(record, dict) and record.get("key") == key else None


def _write(path: Path, record: dict) -> None:
    """Write the record atomically; a folder that cannot be written leaves it unwritten."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_name(f"{path.name}.{os.getpid()}.tmp")
        tmp.write_text(json.dumps(record, separators=(",", ":")), encoding="utf-8")
        os.replace(tmp, path)
    except OSError:
        pass


# ---------------------------------------------------------------- recording and replaying
def _state() -> tuple[dict, dict, set]:
    tables = {None: registry.COMMANDS, **registry.DIALECTS}
    commands = {(d, name): len(cmd._overloads) for d, table in tables.items() for name, cmd in table.items()}
    operators = {(d, sym): f for d, ops in registry.OPERATORS.items() for sym, f in ops.items()}
    return commands, operators, set(types.type_names())


def _import_all(package: str, modules: list[str]) -> dict[str, Any]:
    """Import every module, noting what each registers (a module importing another is credited
    with what the other registers, which importing it brings)."""
    topics = dict(registry.TOPICS)
    found: dict[tuple, list[str]] = {}
    ops: dict[tuple, str] = {}
    typ: dict[str, str] = {}
    for m in modules:
        commands, operators, names = _state()
        importlib.import_module(f"{package}.{m}")
        after, after_ops, after_names = _state()
        for k, n in after.items():
            if n != commands.get(k, 0):
                found.setdefault(k, []).append(m)
        for k, f in after_ops.items():
            if operators.get(k) is not f:
                ops[k] = m
        for name in after_names - names:
            typ[name] = m
    out: dict[str, Any] = {"commands": [], "operators": [], "types": [], "topics": {},
                           "libraries": sorted(registry.LIBRARIES)}
    for (d, name), mods in found.items():
        cmd = registry.table_of(d)[name]
        out["commands"].append([d, name, cmd.lib, cmd.raw, mods,
                                [registry.overload_key(ov) for ov in cmd._overloads]])
    out["operators"] = [[d, sym, m] for (d, sym), m in ops.items()]
    for name in types.type_names():  # in their order of registration
        if name in typ:
            t = types.find_type(name)
            out["types"].append([name, typ[name], t is not None and t.statements is not None])
    out["topics"] = {k: v for k, v in registry.TOPICS.items() if topics.get(k) != v}
    return out


def _replay(package: str, record: dict[str, Any]) -> None:
    for d, name, lib, raw, mods, order in record["commands"]:
        registry.defer(d, name, lib, raw, tuple(f"{package}.{m}" for m in mods), order)
    for d, sym, m in record["operators"]:
        registry.defer_operator(d, sym, f"{package}.{m}")
    for name, m, statements in record["types"]:
        types.defer_type(name, _importer(f"{package}.{m}"), statements)
    registry.TOPICS.update(record["topics"])
    registry.LIBRARIES.update(record["libraries"])


def _importer(module: str) -> Any:
    return lambda: importlib.import_module(module)
