"""Where variables live, as Singular keeps them.

Ring-independent variables (int, string, intvec, lists of those, procs, rings) belong to their
level (the top level, or one procedure call: a :class:`Frame`); ring-dependent ones (number, poly,
ideal, matrix, map, lists holding them) additionally to the ring they were created in, so after
``setring s`` the objects of ``r`` are invisible until mapped.  A procedure sees its own variables
and the top level's.  :class:`Scopes` is the interpreter's part that declares, finds, moves and
removes variables.
"""
from __future__ import annotations

from typing import Any, Optional

from . import ast as A
from .errors import MechNameError, Source
from .values import Proc, Ring, is_ring_dependent, typeof

#: The types whose variables belong to a ring.
RING_TYPES = {"number", "poly", "ideal", "matrix", "map", "vector", "module"}


class Var:
    """A variable: declared type, value, the ring it belongs to (None if ring-independent), level."""

    __slots__ = ("name", "type", "value", "ring", "level", "alias", "attributes")

    def __init__(self, name: str, type_: str, value: Any, ring: Optional[Ring], level: int) -> None:
        self.name, self.type, self.value, self.ring, self.level = name, type_, value, ring, level
        self.alias: Optional[str] = None  # an alias parameter: the caller's variable it stands for
        self.attributes: Optional[dict] = None  # attrib(x, name, value): Singular's attributes but isSB


class Frame:
    """A scope: the top level (level 0) or one procedure call."""

    __slots__ = ("level", "vars", "ring_vars", "proc", "call_pos", "call_source", "ring_at_entry", "keep_ring")

    def __init__(self, level: int, vars_: dict, proc: Optional[Proc] = None, call_pos: Optional[A.Pos] = None,
                 call_source: Optional[Source] = None, ring_at_entry: Optional[Ring] = None) -> None:
        self.level = level
        self.vars = vars_
        self.ring_vars: dict[Ring, dict[str, Var]] = {}
        self.proc = proc
        self.call_pos = call_pos
        self.call_source = call_source
        self.ring_at_entry = ring_at_entry
        self.keep_ring = False


class Scopes:
    """Variables in frames and rings (part of the interpreter: uses ``frames``, ``globals``, ``ring``)."""

    def declare(self, name: str, typ: str, value: Any) -> Var:
        """Create a variable in the current scope (a ring-dependent one with the basering)."""
        if self.registry.is_builtin(name):
            raise MechNameError(f"'{name}' is a command and cannot be declared as a variable")
        frame = self.frames[-1]
        dependent = typ in RING_TYPES or (typ in ("def", "list") and is_ring_dependent(value))
        ring = self.basering() if dependent else None
        table = self._ring_table(frame, ring, True) if dependent else frame.vars
        other = frame.vars if dependent else (self._ring_table(frame, self.ring, False) if self.ring else None)
        if name in table or (other is not None and name in other):
            old = table.get(name) or other.get(name)
            kind = {"bigint": "int", "qring": "ring"}
            if typ != "def" and kind.get(typ, typ) != kind.get(typeof(old.value), typeof(old.value)):
                raise MechNameError(f"identifier '{name}' in use (a {typeof(old.value)}): as in Singular, "
                                    f"kill it before declaring a {typ} of that name")
            self._redefining(name)
            table.pop(name, None)
            if other is not None:
                other.pop(name, None)
        var = Var(name, typ, value, ring, frame.level)
        table[name] = var
        return var

    def _redefining(self, name: str) -> None:
        """Singular's warning ``// ** redefining NAME (LINE) WHERE``."""
        if "redefine" not in self.options or self.stmt is None or not self.warnings:
            return
        pos = self.stmt.pos
        if self.line_shift:
            pos = A.Pos(pos.line + self.line_shift, pos.col, pos.end_line + self.line_shift, pos.end_col)
        line = self.source.line(pos.line)
        proc = self.frames[-1].proc
        if proc is not None:
            start = line.rfind("{", 0, pos.col - 1) + 1
            end = line.find("}", pos.end_col - 1 if pos.end_line == pos.line else len(line))
            text = line[start:end if end >= 0 else len(line)]
            where = f" ::{proc.name}:{pos.line - proc.body_line + 1}"
        else:
            text = line.strip()
            where = "" if self.source.name in ("<string>", "<stdin>", "<input>") else f" {self.source.name}:{pos.line}"
        self.warn(f"redefining {name} ({text}){where}")

    def _ring_table(self, frame: Frame, ring: Optional[Ring], create: bool) -> Optional[dict]:
        if ring is None:
            return None
        if frame.level == 0:
            return ring.objects
        t = frame.ring_vars.get(ring)
        if t is None and create:
            t = frame.ring_vars[ring] = {}
        return t

    def lookup(self, name: str) -> Optional[Var]:
        """The variable ``name`` visible here: the current procedure's, then the top level's;
        ring-dependent ones only with the basering."""
        frame = self.frames[-1]
        ring = self.ring
        if frame.level:
            if ring is not None:
                t = frame.ring_vars.get(ring)
                if t is not None:
                    v = t.get(name)
                    if v is not None:
                        return v
            v = frame.vars.get(name)
            if v is not None:
                return v
        if ring is not None:
            v = ring.objects.get(name)
            if v is not None:
                return v
        return self.globals.get(name)

    def lookup_in_ring(self, ring: Ring, name: str) -> Optional[Var]:
        """A ring-dependent variable of ``ring`` (not necessarily the basering)."""
        frame = self.frames[-1]
        if frame.level:
            t = frame.ring_vars.get(ring)
            if t is not None and name in t:
                return t[name]
        return ring.objects.get(name)

    def visible_names(self) -> dict[str, Var]:
        """The variables visible here, by name (for the REPL's completion and help)."""
        names = dict(self.globals)
        if self.ring is not None:
            names.update(self.ring.objects)
        frame = self.frames[-1]
        if frame.level:
            names.update(frame.vars)
            if self.ring is not None:
                names.update(frame.ring_vars.get(self.ring, {}))
        return names

    def _rebind(self, var: Var, value: Any) -> None:
        """Set a variable's value; a def or list moves to or from its ring as the value requires."""
        if var.type in ("def", "list") and is_ring_dependent(value) != (var.ring is not None):
            dependent = var.ring is None
            frame = self.frames[var.level] if var.level < len(self.frames) else self.frames[-1]
            old = self._ring_table(frame, var.ring, False) if var.ring is not None else frame.vars
            if old is not None:
                old.pop(var.name, None)
            var.ring = self.basering() if dependent else None
            table = self._ring_table(frame, var.ring, True) if dependent else frame.vars
            table[var.name] = var
        var.value = value

    def _remove(self, var: Var) -> None:
        frame = self.frames[var.level] if var.level < len(self.frames) else self.frames[-1]
        table = self._ring_table(frame, var.ring, False) if var.ring is not None else frame.vars
        if table is not None and table.get(var.name) is var:
            del table[var.name]

    def export(self, name: str) -> None:
        """Move a procedure's variable to the top level (with its ring if ring-dependent)."""
        var = self.lookup(name)
        if var is None:
            raise MechNameError(f"'{name}' is not defined")
        if var.level == 0:
            return
        self._remove(var)
        var.level = 0
        table = var.ring.objects if var.ring is not None else self.globals
        if name in table:
            self._redefining(name)
        table[name] = var

    def unwind(self) -> None:
        """Back to the top level after an interrupt: drop procedure frames an interrupted cleanup left."""
        if len(self.frames) > 1:
            self.ring = self.frames[1].ring_at_entry
            del self.frames[1:]
        self.stmt = None
        self._loading_lib = ""
