"""Libraries and help: ``LIB "name";`` enables a library's commands and runs its mech source;
``help;`` lists the commands by library, ``help name;`` shows a command's or procedure's text."""
from __future__ import annotations

from pathlib import Path

from . import ast as A
from .errors import MechNameError
from .files import library_file
from .values import Proc


class Libraries:
    """LIB and help statements (part of the interpreter)."""

    def _exec_lib(self, s: A.Lib) -> None:
        self.load_library(s.name)

    def load_library(self, name: str) -> None:
        """``LIB "name";``: enable a library's commands and run its mech source if it has one: one of
        mech's libraries, else the file of that name next to the running script (in the current
        directory for code without a file).  Never a path, so scripts read no other files."""
        if name in ("", ".", "..") or Path(name).name != name:
            raise MechNameError(f'LIB takes a library name, not a path: "{name}" (libraries are mech\'s own '
                                f'or files next to the script)')
        path = self.registry.library_source(name)  # a library's mech source (mech's own: stdlib/*.lib)
        if name not in self.registry.LIBRARIES and path is None:
            script = Path(self.source.name)
            path = library_file(script.parent if script.is_file() else Path.cwd(), name)
            if path is None:
                self.registry.check_library(name)
        if name in self.loaded_libs:
            return
        self.loaded_libs.add(name)
        if path is not None:
            saved = self._loading_lib
            self._loading_lib = name
            frames, self.frames = self.frames, self.frames[:1]
            try:
                self.execute(path.read_text(), str(path))
            finally:
                self._loading_lib = saved
                self.frames = frames

    def _exec_help(self, s: A.Help) -> None:
        if s.topic is None:
            self.write("help NAME; shows what a command or procedure does.  Commands by library:\n")
            libs: dict[str, list[str]] = {}
            for n, c in self.registry.COMMANDS.items():
                libs.setdefault(c.lib or "", []).append(n)
            for lib in sorted(libs):
                head = "built in" if not lib else lib if lib in self.loaded_libs else f'{lib} (LIB "{lib}";)'
                self.write(f"{head}:\n{_wrap(sorted(libs[lib], key=str.lower), indent='  ')}\n")
            procs = sorted(v.name for v in self.visible_names().values() if isinstance(v.value, Proc))
            if procs:
                self.write(f"procedures:\n{_wrap(procs, indent='  ')}\n")
            return
        var = self.lookup(s.topic)
        if var is not None and isinstance(var.value, Proc):
            p = var.value
            self.write((p.doc or f"procedure {p.name} has no help text").strip("\n") + "\n")
            return
        text = self.registry.help_text(s.topic)
        if text is None:
            raise MechNameError(f"no help for '{s.topic}'")
        self.write(text.rstrip("\n") + "\n")


def _wrap(names: list[str], width: int = 78, indent: str = "") -> str:
    lines, cur = [], ""
    for n in names:
        if cur and len(indent) + len(cur) + 1 + len(n) > width:
            lines.append(indent + cur)
            cur = n
        else:
            cur = f"{cur} {n}" if cur else n
    if cur:
        lines.append(indent + cur)
    return "\n".join(lines)
