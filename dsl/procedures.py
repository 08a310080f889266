"""Procedure calls: a new frame, the arguments bound to the parameters (converted to their
types), the body run; the basering is restored afterwards unless the procedure used keepring."""
from __future__ import annotations

from typing import Any, Optional

from . import ast as A
from .errors import MechError, MechRuntimeError, MechTypeError, Note
from .scopes import Frame
from .signals import BreakSignal, ContinueSignal, ReturnSignal
from .values import NONE, List, Matrix, Proc, convert, to_matrix

#: How deep procedure calls may nest.
MAX_DEPTH = 1000


class Procedures:
    """Calling procedures (part of the interpreter)."""

    def call_proc(self, proc: Proc, args: list[Any], node: Optional[A.Expr] = None) -> Any:
        """Call a procedure with evaluated arguments in a new scope; the basering is restored
        afterwards (unless the procedure used keepring)."""
        if len(self.frames) > MAX_DEPTH:
            raise MechRuntimeError(f"procedure calls nested deeper than {MAX_DEPTH}")
        caller_source = self.source
        frame = Frame(len(self.frames), {}, proc, node.pos if node else None, caller_source, self.ring)
        self.frames.append(frame)
        saved_stmt, saved_shift = self.stmt, self.line_shift
        self.line_shift = 0
        try:
            self._bind_params(proc, args, node.args if isinstance(node, A.Call) else None)
        except MechError as e:
            self.frames.pop()
            self.ring, self.line_shift = frame.ring_at_entry, saved_shift
            if node is not None:
                e.locate(node.pos, caller_source, True)
            raise
        self.source = proc.source
        try:
            try:
                self.exec_block(proc.body)
            except ReturnSignal as r:
                return r.value
            except BreakSignal:
                raise MechRuntimeError("break outside a loop", self.stmt.pos if self.stmt else None, self.source)
            except ContinueSignal:
                raise MechRuntimeError("continue outside a loop", self.stmt.pos if self.stmt else None,
                                       self.source)
            return NONE
        except MechError as e:
            if e.pos is None:
                e.locate(self.stmt.pos if self.stmt else proc_pos(proc), self.source)
            if node is not None:
                e.notes.append(Note(f"in procedure '{proc.name}' called here", caller_source, node.pos))
            raise
        finally:
            self.frames.pop()
            self.source = caller_source
            self.stmt, self.line_shift = saved_stmt, saved_shift
            if not frame.keep_ring and not (frame.ring_at_entry is None and self.ring is not None and any(
                    v.value is self.ring for v in self.globals.values())):
                self.ring = frame.ring_at_entry  # as Singular: a global ring made without a basering stays

    def _bind_params(self, proc: Proc, args: list[Any], nodes: Optional[list[A.Expr]] = None) -> None:
        params = proc.params or []
        if proc.params is None:  # a procedure without parameters takes any arguments in #
            params = [A.Param("list", "#")]
        i = 0
        for p in params:
            if p.name == "#":
                self.declare("#", "list", List(args[i:]))
                i = len(args)
                continue
            if i >= len(args):
                raise MechTypeError(f"too few arguments for procedure {proc.name}: expected {len(params)}, "
                                    f"got {len(args)}")
            typ = p.type or "def"
            a = args[i]
            if (typ == "int" and type(a) is int) or (typ == "string" and type(a) is str):
                v = a  # as convert gives them
            elif typ == "ring":
                v = convert(args[i], "ring", None)
            elif typ == "matrix":  # as a declaration without dimensions: a non-matrix fills a 1 x 1 matrix
                v = to_matrix(args[i], self.basering().poly, *((0, 0) if isinstance(args[i], Matrix) else (1, 1)))
            else:
                try:
                    v = self._converted(args[i], typ, self.ring.poly if self.ring else None)
                except MechError as e:
                    e.message = f"argument {i + 1} of {proc.name}: {e.message}"
                    raise
            var = self.declare(p.name, typ, v)
            if p.alias and nodes is not None and len(nodes) == len(args) and isinstance(nodes[i], A.Name):
                var.alias = nodes[i].id
            i += 1
        if i < len(args):
            raise MechTypeError(f"too many arguments for procedure {proc.name}: expected {len(params)}, got {len(args)}")


def proc_pos(proc: Proc) -> Optional[A.Pos]:
    return proc.body[0].pos if proc.body else None
