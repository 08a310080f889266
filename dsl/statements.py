"""The statement executor: expression statements (printing their values), control flow, procedure
definitions, kill, export, keepring, setring and quit; declarations, assignments, LIB and help
have their own modules."""
from __future__ import annotations

from typing import Any, Callable, Optional

from . import ast as A
from . import ops
from .boundary import convert_exception
from .compiled import stmt_fn
from .errors import MechError, MechNameError, MechRuntimeError, MechTypeError
from .limits import LimitExceeded, limit_error
from .printing import join_outputs, render
from .rings import indexed_names
from .signals import SIGNALS, BreakSignal, ContinueSignal, QuitSignal, ReturnSignal
from .values import NONE, NOTHING, ExprList, List, Proc, Ring, typeof


class Statements:
    """Running statements (part of the interpreter)."""

    def exec_block(self, body: list[A.Stmt]) -> None:
        for stmt in body:
            self.exec_stmt(stmt)

    def exec_stmt(self, stmt: A.Stmt) -> None:
        self.stmt = stmt
        try:
            fn = getattr(stmt, "_fn", None) if self.compiled else None
            if fn is not None:
                fn(self)
            elif type(stmt) is A.Relit:  # most lines of a long script
                self._exec_relit(stmt)
            else:
                self._run_cold(stmt)
        except SIGNALS:
            raise
        except MechError as e:
            e.locate(stmt.pos, self.source)
            raise
        except LimitExceeded as e:
            raise limit_error(e).locate(stmt.pos, self.source) from None
        except Exception as e:
            raise convert_exception(e).locate(stmt.pos, self.source) from None

    def _run_cold(self, stmt: A.Stmt) -> None:
        """A statement without its closure: loops and statements running a second time are
        compiled (:mod:`~mech.dsl.compiled`), a statement's first run goes by its type (most lines
        of a long script run once)."""
        kind = type(stmt)
        if self.compiled and kind is not A.Moved and kind is not A.Relit:
            if kind is A.For or kind is A.While or stmt.__dict__.get("_seen"):
                stmt_fn(stmt)(self)
                return
            stmt._seen = True
        self._exec[kind](stmt)

    def _exec_moved(self, s: A.Moved) -> None:
        """A statement tree shared with the same text on an earlier line (:mod:`~mech.dsl.fastparse`):
        warnings name this line (``line_shift``), errors are moved to it."""
        saved, self.line_shift = self.line_shift, s.dline
        inner = self.stmt = s.stmt
        try:
            fn = getattr(inner, "_fn", None) if self.compiled else None
            if fn is not None:
                fn(self)
            else:
                self._run_cold(inner)
        except MechError as e:
            _move_error(e, inner.pos.line, s.dline, self.source)
            raise
        except (BreakSignal, ContinueSignal):  # reported at the top level where self.stmt is
            if self.stmt is not None:
                self.stmt = A.Empty(pos=_moved(self.stmt.pos, s.dline))
            raise
        finally:
            self.line_shift = saved

    def _exec_relit(self, s: A.Relit) -> None:
        """A statement run by the template of its shape (:mod:`~mech.dsl.templates`) with its own
        numbers; warnings name this line, errors are moved to it."""
        template, lits = s.template, s.lits
        tree = template.tree
        saved = self.lits, self.line_shift
        self.lits, self.line_shift = lits, s.dline
        try:
            if not self.compiled:
                self.exec_stmt(template.actual(tree, lits))
            else:
                if "_fn" not in tree.__dict__:
                    template.compile()
                self.exec_stmt(tree)
        except MechError as e:
            _move_error(e, tree.pos.line, s.dline, self.source, lambda p: template.move(p, s.dline, lits))
            raise
        except (BreakSignal, ContinueSignal):  # reported at the top level where self.stmt is
            if self.stmt is not None:
                self.stmt = A.Empty(pos=template.move(self.stmt.pos, s.dline, lits))
            raise
        finally:
            self.lits, self.line_shift = saved

    def _exec_expr(self, s: A.ExprStmt) -> None:
        parts, values = [], []
        for node in s.exprs:
            v = self.eval(node)
            if v is NONE:
                if isinstance(node, A.Call) and isinstance(node.func, A.Name) and \
                        isinstance(getattr(self.lookup(node.func.id), "value", None), Proc):
                    self.last = NOTHING  # a procedure's empty result: Singular's `_` holds nothing
                continue
            self.last = v
            values.append(v)
            named = self._indexed_declared(node, v)
            if named:
                parts.extend((render(x, n), isinstance(x, List)) for n, x in named)
                continue
            parts.append((render(v, node.id if isinstance(node, A.Name) else None), isinstance(v, List)))
        if not parts:
            return
        text = join_outputs(parts) + "\n"
        if "display" in self.settings:  # a notebook: LaTeX beside the text, when the values have it
            from .latex import bundle
            rich = bundle(values, text)
            if len(rich) > 1:
                self.display(rich)
                return
        self.write(text)

    def _indexed_declared(self, node: A.Expr, v: Any) -> list[tuple[str, Any]]:
        """(name, value) of variables declared with indices that ``j(2..3)`` shows, as Singular names them."""
        base = node
        while isinstance(base, A.Call):
            base = base.func
        if (base is node or not isinstance(base, A.Name) or self.lookup(base.id) is not None
                or self.registry.find(base.id, self.loaded_libs) is not None):
            return []
        names = indexed_names(node, self.eval)
        if not names or any(self.lookup(n) is None for n in names):
            return []
        items = v.items if isinstance(v, ExprList) and len(names) > 1 else [v]
        return list(zip(names, items)) if len(items) == len(names) else []

    def _exec_if(self, s: A.If) -> None:
        if ops.truth(self.eval(s.cond)):
            self.exec_block(s.then)
        elif s.orelse is not None:
            self.exec_block(s.orelse)

    def _exec_for(self, s: A.For) -> None:
        if s.init is not None:
            self.exec_stmt(s.init)
        while s.cond is None or ops.truth(self.eval(s.cond)):
            try:
                self.exec_block(s.body)
            except BreakSignal:
                break
            except ContinueSignal:  # as in Singular, continue skips the step: it goes on with the condition
                continue
            if s.step is not None:
                self.exec_stmt(s.step)

    def _exec_while(self, s: A.While) -> None:
        while ops.truth(self.eval(s.cond)):
            try:
                self.exec_block(s.body)
            except BreakSignal:
                break
            except ContinueSignal:
                pass

    def _exec_break(self, s: A.Break) -> None:
        raise BreakSignal()

    def _exec_continue(self, s: A.Continue) -> None:
        raise ContinueSignal()

    def _exec_return(self, s: A.Return) -> None:
        if len(self.frames) == 1:
            raise MechRuntimeError("return outside a procedure")
        vals = self._values(s.values) if s.values else []
        raise ReturnSignal(NONE if not vals else vals[0] if len(vals) == 1 else ExprList(vals))

    def _exec_procdef(self, s: A.ProcDef) -> None:
        lib = self._loading_lib
        self.declare(s.name, "proc", Proc(s.name, s.params, s.body, s.doc, self.source, lib, s.body_line))

    def _names_of(self, targets: list[A.Expr], what: str) -> list[A.Name]:
        out = []
        for t in targets:
            items = t.items if isinstance(t, A.Tuple) else [t]
            for it in items:
                if isinstance(it, A.Call):  # `kill p(2)`: a variable declared with an index
                    names = indexed_names(it, self.eval)
                    if names:
                        out.extend(A.Name(n, pos=it.pos) for n in names)
                        continue
                if not isinstance(it, A.Name):
                    raise MechRuntimeError(f"{what} needs variable names", it.pos, self.source)
                out.append(it)
        return out

    def _exec_kill(self, s: A.Kill) -> None:
        for n in self._names_of(s.targets, "kill"):
            var = self.lookup(n.id)
            if var is None:
                raise MechNameError(f"'{n.id}' is not defined", n.pos, self.source)
            self._remove(var)
            if isinstance(var.value, Ring) and var.value is self.ring:
                self.ring = None

    def _exec_export(self, s: A.Export) -> None:
        for n in self._names_of(s.targets, "export"):
            self.export(n.id)

    def _exec_keepring(self, s: A.Keepring) -> None:
        ring = self.eval(s.ring)
        if not isinstance(ring, Ring):
            raise MechTypeError(f"keepring needs a ring, not {typeof(ring)}")
        if isinstance(s.ring, A.Name):
            ring.name = s.ring.id
            var = self.lookup(s.ring.id)
            if var is not None and var.level > 0:  # the caller sees the kept ring (made global here)
                self.export(s.ring.id)
        self.ring = ring
        self.frames[-1].keep_ring = True

    def _exec_setring(self, s: A.Setring) -> None:
        ring = self.eval(s.ring)
        if not isinstance(ring, Ring):
            raise MechTypeError(f"setring needs a ring, not {typeof(ring)}")
        if isinstance(s.ring, A.Name):  # as Singular, the basering is known by the name it was set by
            ring.name = s.ring.id
        self.ring = ring

    def _exec_quit(self, s: A.Quit) -> None:
        raise QuitSignal()


def _moved(pos: A.Pos, dline: int) -> A.Pos:
    return A.Pos(pos.line + dline, pos.col, pos.end_line + dline, pos.end_col)


def _move_error(e: MechError, line: int, dline: int, source: object,
                move: Optional[Callable[[A.Pos], A.Pos]] = None) -> None:
    """Move the position of ``e`` raised in a shared tree (on ``line``) ``dline`` lines (or by
    ``move``): its own position, or when it comes from inside a procedure, that of the outermost call."""
    move = move or (lambda pos: _moved(pos, dline))
    if e.notes:
        note = e.notes[-1]
        if note.pos is not None and note.pos.line == line and note.source is source:
            note.pos = move(note.pos)
    elif e.pos is not None and e.pos.line == line and e.source in (None, source):
        e.pos = move(e.pos)
