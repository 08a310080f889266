"""Command libraries the language loads (algebra commands, mechanisms, plots).

Importing this package registers nothing; :func:`load` (which mech's facade hands to
:func:`mech.dsl.registry.add_loader`) imports every public module here once, and their
decorators register the commands and types; the ``*.lib`` sources here become loadable by
``LIB "name.lib";``."""
from __future__ import annotations

import importlib
import pkgutil
from pathlib import Path

#: The folder of the libraries' mech sources (``primdec.lib``...).
LIB_DIR = Path(__file__).resolve().parent

_loaded = False


def load() -> None:
    """Register the commands, types and library sources of ``mech.stdlib`` (once)."""
    global _loaded
    if _loaded:
        return
    _loaded = True
    from ..dsl.registry import add_library_dir
    add_library_dir(LIB_DIR)
    for info in pkgutil.iter_modules(__path__):
        if not info.name.startswith("_"):
            importlib.import_module(f"{__name__}.{info.name}")
