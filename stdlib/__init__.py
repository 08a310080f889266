"""Command libraries the language loads (algebra commands, mechanisms, plots).

Importing this package registers nothing; :func:`load` (which mech's facade hands to
:func:`mech.dsl.registry.add_loader`) registers the commands and types of every public module
here, whose decorators define them (:func:`mech.dsl.plugins.load_package`: from the record of an
earlier start, each module imported when one of its commands is first used); the ``*.lib``
sources here become loadable by ``LIB "name.lib";``."""
from __future__ import annotations

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
    from ..dsl.plugins import load_package
    from ..dsl.registry import add_library_dir
    add_library_dir(LIB_DIR)
    load_package(__name__, LIB_DIR)
