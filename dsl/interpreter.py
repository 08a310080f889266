"""The interpreter: Singular's semantics for the statements and expressions of :mod:`mech.dsl.ast`.

:class:`Interpreter` runs programs a statement at a time under the limits (:mod:`mech.dsl.limits`),
writes their output and is the commands' context (:class:`mech.dsl.registry.Context`).  Its parts,
one module each: variables in scopes (:mod:`~mech.dsl.scopes`), statements
(:mod:`~mech.dsl.statements`), declarations, assignments, procedure calls, libraries and help, ring
maps, identifiers and literals (:mod:`~mech.dsl.names`), expressions.  Python exceptions become
user errors in :mod:`~mech.dsl.boundary`.
"""
from __future__ import annotations

import sys
import time
import weakref
from contextlib import nullcontext
from typing import Any, Callable, ContextManager, Optional, TextIO

from ..kernel.collector import relaxed
from ..kernel.engines import AUTO, default_engine, using_engine
from . import ast as A
from . import registry
from .assignment import Assignment
from .declarations import Declarations
from .errors import MechError, MechRuntimeError, Source
from .expressions import Expressions
from .libraries import Libraries
from .echo import echo_lines
from .limits import Limits
from .maps import Maps
from .names import Names
from .options import DEFAULT_OPTIONS
from .parser import parse_pieces
from .procedures import Procedures
from .scopes import Frame, Scopes, Var
from .signals import BreakSignal, ContinueSignal, QuitSignal, ReturnSignal
from .statements import Statements
from .values import NONE, Ideal, Ring

__all__ = ["Interpreter", "QuitSignal"]


#: a script at least this long runs with fewer collections of the young objects (see _young_gc)
LONG_SCRIPT = 1 << 16
YOUNG_THRESHOLD = 10000  # allocations between two collections of the young generation (Python's default: 700)


def _young_gc(size: int) -> ContextManager[None]:
    """Python's cyclic garbage collector less often while a long script runs: each statement makes
    and drops a few dozen objects (its tree, its values), so the default threshold (700
    allocations) collects every few statements and, with the modules' objects, costs 15-25 % of a
    flat script's time (benchmarks/INTERPRETER.md).  Garbage is still collected, in larger batches."""
    return relaxed(YOUNG_THRESHOLD) if size >= LONG_SCRIPT else nullcontext()


class Interpreter(Statements, Declarations, Assignment, Procedures, Libraries, Maps, Names, Expressions, Scopes):
    """Runs mech programs; output goes to ``out`` (flushed after each write when ``flush``)."""

    def __init__(self, out: Optional[TextIO] = None, flush: bool = False, warnings: bool = True,
                 timeout: Optional[float] = None, max_memory: Optional[float] = None,
                 settings: Optional[dict[str, Any]] = None) -> None:
        self.limits = Limits(timeout, max_memory)  # per statement; see limits.py
        registry.load_plugins()
        self.registry = registry
        #: session settings the facade gives, read by commands as ``ctx.settings`` ("report_format";
        #: "display": a callable taking MIME bundles, given by notebooks)
        self.settings: dict[str, Any] = dict(settings or {})
        self.out = out if out is not None else sys.stdout
        self.flush = flush
        self.warnings = warnings
        self.globals: dict[str, Var] = {}
        self.frames: list[Frame] = [Frame(0, self.globals)]
        self.ring: Optional[Ring] = None
        self.rings: weakref.WeakSet[Ring] = weakref.WeakSet()  # for 'it belongs to ring r' hints
        self.options: set[str] = set(DEFAULT_OPTIONS)
        self.explicit_options: set[str] = set()  # set by option(...) or test(...), whatever the ring brings
        self.loaded_libs: set[str] = set()
        self._loading_lib = ""  # the library whose source runs (its procedures belong to it)
        self.source = Source("<string>", "")
        self.stmt: Optional[A.Stmt] = None
        self.line_shift = 0  # lines from self.stmt's position to the running statement's (A.Moved)
        self.lits: list[str] = []  # the numbers of the statement a template runs for (A.Relit)
        self.last: Any = NONE
        self.argnames: list[str] = []
        self.ticks_per_sec = 1
        self.sysvars: dict[str, int] = {"printlevel": 0, "echo": 0, "pagewidth": 80}  # pagewidth: as Singular
        self._t0 = time.process_time()
        self._r0 = time.time()
        self._exec: dict[type, Callable] = {
            A.ExprStmt: self._exec_expr, A.Decl: self._exec_decl, A.Assign: self._exec_assign,
            A.IncDec: self._exec_incdec, A.Block: lambda s: self.exec_block(s.body), A.If: self._exec_if,
            A.For: self._exec_for, A.While: self._exec_while, A.Break: self._exec_break,
            A.Continue: self._exec_continue, A.Return: self._exec_return, A.ProcDef: self._exec_procdef,
            A.Kill: self._exec_kill, A.Export: self._exec_export, A.Keepring: self._exec_keepring,
            A.Setring: self._exec_setring, A.Lib: self._exec_lib, A.Quit: self._exec_quit,
            A.Help: self._exec_help, A.Empty: lambda s: None, A.Moved: self._exec_moved,
            A.Relit: self._exec_relit,
        }
        self._eval: dict[type, Callable] = {
            A.Name: self._eval_name, A.IntLit: lambda n: n.value, A.RatLit: self._eval_rat,
            A.MonomLit: self._eval_monom, A.StrLit: lambda n: n.value, A.Tuple: self._eval_tuple,
            A.BinOp: self._eval_binop, A.UnOp: self._eval_unop, A.Range: self._eval_range,
            A.Index: self._eval_index, A.Call: self._eval_call, A.TypeCall: self._eval_typecall,
            A.Backquote: self._eval_backquote,
        }
        if sys.getrecursionlimit() < 20000:
            sys.setrecursionlimit(20000)

    def execute(self, text: str, name: str = "<string>") -> None:
        """Parse and run ``text`` a piece at a time (as Singular reads statement by statement):
        after a syntax error, the statements before it have run; then the error is raised."""
        source = Source(name, text)
        with _young_gc(len(text)):
            for program in parse_pieces(text, source):
                self.run(program, source)

    def execute_here(self, text: str) -> None:
        """Run the statements of ``text`` in the current scope (Singular's ``execute``)."""
        saved, stmt, shift = self.source, self.stmt, self.line_shift
        source = Source("<execute>", text)
        self.line_shift = 0
        try:
            for program in parse_pieces(text, source):
                self.source = source
                for s in program.body:
                    self.exec_stmt(s)
        except MechError as e:  # reported at the execute call, the executed text named in the message
            if e.source is source:
                e.message = f"{e.message} (in the string executed: {text.strip()[:60]})"
                e.pos, e.source = None, None
            raise
        finally:
            self.source, self.stmt, self.line_shift = saved, stmt, shift

    def run(self, program: A.Program, source: Source) -> None:
        """Run a parsed program at top level."""
        saved = self.source
        self.source = source
        sysvars, settings, limits, exec_stmt = self.sysvars, self.settings, self.limits, self.exec_stmt
        try:
            for stmt in program.body:
                if sysvars["echo"] > 0:
                    echo_lines(self, stmt)
                if limits.timeout or limits.max_memory or settings.get("engine", AUTO) != default_engine():
                    self.guarded(exec_stmt, stmt)
                else:  # guarded's common case, inline (most statements of a script are short)
                    exec_stmt(stmt)
        except (BreakSignal, ContinueSignal) as sig:
            word = "break" if isinstance(sig, BreakSignal) else "continue"
            raise MechRuntimeError(f"{word} outside a loop", self.stmt.pos if self.stmt else None, source)
        except ReturnSignal:
            raise MechRuntimeError("return outside a procedure", self.stmt.pos if self.stmt else None, source)
        finally:
            self.source = saved

    def guarded(self, fn: Callable[..., Any], *args: Any) -> Any:
        """``fn(*args)`` as one top-level statement: under the limits, with the session's default
        Gröbner engine (``settings["engine"]``, see :mod:`mech.kernel.engines`)."""
        engine = self.settings.get("engine", AUTO)
        if engine == default_engine() and not (self.limits.timeout or self.limits.max_memory):
            return fn(*args)  # the common case, without the context managers' cost per statement
        with using_engine(engine):
            return self.limits.run(self, fn, *args)

    def write(self, text: str) -> None:
        self.out.write(text)
        if self.flush:
            self.out.flush()

    def display(self, bundle: dict[str, str]) -> None:
        """Show a rich result: the facade's display (``settings["display"]``: a notebook) gets the
        MIME bundle; elsewhere its ``text/plain`` is printed."""
        show = self.settings.get("display")
        if show is None:
            self.write(bundle["text/plain"])
        else:
            if self.flush:
                self.out.flush()
            show(bundle)

    def warn(self, message: str) -> None:
        if self.warnings:
            self.write(f"// ** {message}\n")

    def _line_text(self) -> str:
        if self.stmt is None or not self.stmt.pos.line:
            return ""
        return self.source.line(self.stmt.pos.line + self.line_shift).rstrip("\r\n")  # as Singular: with its blanks

    def warn_in_line(self, message: str) -> None:
        self.warn(f"{message} in line >>{self._line_text()}<<")

    def assume_std(self, ideal: Ideal, argno: int) -> None:
        if not getattr(ideal, "is_std", True):
            name = self.argnames[argno] if argno < len(self.argnames) else "_"
            self.warn(f"{name} is no standard basis")

    def basering(self) -> Ring:
        if self.ring is None:
            raise MechRuntimeError("no ring active: declare one first, e.g. ring r = 0, (x,y,z), dp;")
        return self.ring
