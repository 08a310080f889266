"""The files a script may touch (the one policy; docs/reliability.md, "Files", documents it).

Scripts read no files but libraries (``LIB "name";``: mech's own, or a regular file of that name
next to the script, never through a symbolic link), and write none but the pictures of the plot
commands and the configuration files of ``exportConfigurations``: :func:`output_file` admits a
relative path inside the working directory, ending in one of the caller's endings, without ``..``, not through a symbolic link, to a folder that exists; a
file there is replaced only when it is a regular file.
"""
from __future__ import annotations

import os
from pathlib import Path, PurePath

from .errors import MechRuntimeError


def output_file(path: str, endings: tuple[str, ...]) -> Path:
    """The file ``path`` names, checked against the policy; raises :class:`MechRuntimeError`
    saying what is refused."""
    if not path.lower().endswith(endings):
        raise MechRuntimeError(f"'{path}': give a file name ending in {' or '.join(endings)}")
    pure = PurePath(path)
    if pure.is_absolute() or path.startswith("~"):
        raise MechRuntimeError(f"'{path}': give a path relative to the working directory (scripts write "
                               f"only inside it)")
    if ".." in pure.parts:
        raise MechRuntimeError(f"'{path}': '..' is not allowed (scripts write only inside the working directory)")
    cwd = Path.cwd()
    folder = cwd
    for part in pure.parts[:-1]:
        folder = folder / part
        if folder.is_symlink():
            raise MechRuntimeError(f"'{path}': {folder.relative_to(cwd)} is a symbolic link (scripts write "
                                   f"only inside the working directory)")
        if not folder.is_dir():
            raise MechRuntimeError(f"'{path}': the folder {folder.relative_to(cwd)} does not exist")
    target = cwd / pure
    if target.is_symlink() or (os.path.lexists(target) and not target.is_file()):
        raise MechRuntimeError(f"'{path}': exists and is not a regular file (scripts replace only regular files)")
    return target


def library_file(folder: Path, name: str) -> Path | None:
    """The user library ``name`` in ``folder``: a regular file, not a symbolic link (None when
    there is none); raises when a symbolic link or another kind of file has that name."""
    path = folder / name
    if path.is_symlink():
        raise MechRuntimeError(f'LIB "{name}": {path} is a symbolic link (libraries are regular files next to '
                               f'the script)')
    if not os.path.lexists(path):
        return None
    if not path.is_file():
        raise MechRuntimeError(f'LIB "{name}": {path} is not a regular file')
    return path
