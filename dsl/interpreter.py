"""The interpreter: Singular's semantics for the statements and expressions of :mod:`mech.dsl.ast`.

Names live in scopes as Singular keeps them: ring-independent variables (int, string, intvec, lists
of those, procs, rings) at their level (top level or a procedure call), ring-dependent ones (number,
poly, ideal, matrix, map, lists holding them) additionally with the ring they were created in, so
after ``setring s`` the objects of ``r`` are invisible until mapped.  A procedure sees its own
variables and the top level.  An identifier resolves to a declared variable, else a variable of
the basering, else a short monomial (``x2y``), else it is unknown.
"""
from __future__ import annotations

import sys
import time
import weakref
from pathlib import Path
from typing import Any, Callable, Optional, TextIO

from ..kernel import KernelError, Poly
from . import ast as A
from . import ops
from .errors import MechError, MechInternalError, MechNameError, MechRuntimeError, MechTypeError, Note, Source
from .limits import LimitExceeded, Limits, limit_error
from .parser import parse_pieces
from .printing import join_outputs, render
from .rings import build_ring, default_ring, indexed_names
from .values import (NONE, ExprList, Ideal, IntVec, List, Map, Matrix, Number, Proc, Ring, convert, is_ring_dependent,
                     to_int, to_matrix, to_poly, typeof)

RING_TYPES = {"number", "poly", "ideal", "matrix", "map"}
UNSUPPORTED_TYPES = {"qring", "vector", "module", "resolution", "link", "intmat"}
MAX_DEPTH = 1000
STDLIB_DIR = Path(__file__).resolve().parent.parent / "stdlib"

#: Singular's default options, in the order ``option()`` prints them.
OPTION_ORDER = ["prot", "redSB", "notBuckets", "notSugar", "interrupt", "sugarCrit", "teach", "cancelunit",
                "morePairs", "returnSB", "fastHC", "staircaseBound", "multBound", "degBound", "redTail",
                "redThrough", "lazy", "intStrategy", "infRedTail", "notRegularity", "weightM", "mem", "yacc",
                "redefine", "reading", "loadLib", "debugLib", "loadProc", "defRes", "usage", "Imap", "prompt",
                "notWarnSB", "contentSB"]
DEFAULT_OPTIONS = {"redTail", "redThrough", "intStrategy", "redefine", "usage", "prompt"}


class _Break(Exception):
    pass


class _Continue(Exception):
    pass


class _Return(Exception):
    def __init__(self, value: Any) -> None:
        self.value = value


class QuitSignal(Exception):
    """``quit;`` or ``exit;``: stop the program (not an error)."""


_SIGNALS = (_Break, _Continue, _Return, QuitSignal)


class Var:
    """A variable: declared type, value, the ring it belongs to (None if ring-independent), level."""

    __slots__ = ("name", "type", "value", "ring", "level")

    def __init__(self, name: str, type_: str, value: Any, ring: Optional[Ring], level: int) -> None:
        self.name, self.type, self.value, self.ring, self.level = name, type_, value, ring, level


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


def convert_exception(e: BaseException) -> MechError:
    """A Python exception raised during evaluation as the error the user sees (a broken pipe,
    the reader of the output gone as in ``mech f | head``, is raised again for the caller)."""
    if isinstance(e, BrokenPipeError):
        raise e
    if isinstance(e, MechError):
        return e
    if isinstance(e, KernelError):
        return MechRuntimeError(str(e))
    if isinstance(e, ZeroDivisionError):
        return MechRuntimeError("division by 0")
    if isinstance(e, RecursionError):
        return MechRuntimeError("recursion too deep")
    if isinstance(e, (ValueError, ArithmeticError)):
        return MechRuntimeError(str(e))
    if isinstance(e, MemoryError):
        return limit_error(e)
    return MechInternalError(f"internal error: {type(e).__name__}: {e}")


class Interpreter:
    """Runs mech programs; output goes to ``out`` (flushed after each write when ``flush``)."""

    def __init__(self, out: Optional[TextIO] = None, flush: bool = False, warnings: bool = True,
                 timeout: Optional[float] = None, max_memory: Optional[float] = None) -> None:
        from . import registry
        self.limits = Limits(timeout, max_memory)  # per statement; see limits.py
        registry.load_commands()
        self.registry = registry
        self.out = out if out is not None else sys.stdout
        self.flush = flush
        self.warnings = warnings
        self.globals: dict[str, Var] = {}
        self.frames: list[Frame] = [Frame(0, self.globals)]
        self.ring: Optional[Ring] = None
        self.rings: weakref.WeakSet[Ring] = weakref.WeakSet()  # for 'it belongs to ring r' hints
        self.options: set[str] = set(DEFAULT_OPTIONS)
        self.loaded_libs: set[str] = set()
        self.source = Source("<string>", "")
        self.stmt: Optional[A.Stmt] = None
        self.last: Any = NONE
        self.argnames: list[str] = []
        self.ticks_per_sec = 1
        self.sysvars: dict[str, int] = {"printlevel": 0}
        self._t0 = time.process_time()
        self._r0 = time.time()
        self._exec: dict[type, Callable] = {
            A.ExprStmt: self._exec_expr, A.Decl: self._exec_decl, A.Assign: self._exec_assign,
            A.IncDec: self._exec_incdec, A.Block: lambda s: self.exec_block(s.body), A.If: self._exec_if,
            A.For: self._exec_for, A.While: self._exec_while, A.Break: self._exec_break,
            A.Continue: self._exec_continue, A.Return: self._exec_return, A.ProcDef: self._exec_procdef,
            A.Kill: self._exec_kill, A.Export: self._exec_export, A.Keepring: self._exec_keepring,
            A.Setring: self._exec_setring, A.Lib: self._exec_lib, A.Quit: self._exec_quit,
            A.Help: self._exec_help, A.Empty: lambda s: None,
        }
        self._eval: dict[type, Callable] = {
            A.Name: self._eval_name, A.IntLit: lambda n: n.value, A.RatLit: self._eval_rat,
            A.MonomLit: self._eval_monom, A.StrLit: lambda n: n.value, A.Tuple: self._eval_tuple,
            A.BinOp: self._eval_binop, A.UnOp: self._eval_unop, A.Range: self._eval_range,
            A.Index: self._eval_index, A.Call: self._eval_call, A.TypeCall: self._eval_typecall,
        }
        if sys.getrecursionlimit() < 20000:
            sys.setrecursionlimit(20000)

    # ------------------------------------------------------------ running programs
    def execute(self, text: str, name: str = "<string>") -> None:
        """Parse and run ``text`` a piece at a time (as Singular reads statement by statement):
        after a syntax error, the statements before it have run; then the error is raised."""
        source = Source(name, text)
        for program in parse_pieces(text, source):
            self.run(program, source)

    def run(self, program: A.Program, source: Source) -> None:
        """Run a parsed program at top level."""
        saved = self.source
        self.source = source
        try:
            for stmt in program.body:
                self.limits.run(self, self.exec_stmt, stmt)
        except (_Break, _Continue) as sig:
            word = "break" if isinstance(sig, _Break) else "continue"
            raise MechRuntimeError(f"{word} outside a loop", self.stmt.pos if self.stmt else None, source)
        except _Return:
            raise MechRuntimeError("return outside a procedure", self.stmt.pos if self.stmt else None, source)
        finally:
            self.source = saved

    # ------------------------------------------------------------ output
    def write(self, text: str) -> None:
        self.out.write(text)
        if self.flush:
            self.out.flush()

    def warn(self, message: str) -> None:
        if self.warnings:
            self.write(f"// ** {message}\n")

    def _line_text(self) -> str:
        if self.stmt is None or not self.stmt.pos.line:
            return ""
        return self.source.line(self.stmt.pos.line).rstrip("\r\n")  # as Singular: with its blanks

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

    # ------------------------------------------------------------ statements
    def exec_block(self, body: list[A.Stmt]) -> None:
        for stmt in body:
            self.exec_stmt(stmt)

    def exec_stmt(self, stmt: A.Stmt) -> None:
        self.stmt = stmt
        try:
            self._exec[type(stmt)](stmt)
        except _SIGNALS:
            raise
        except MechError as e:
            e.locate(stmt.pos, self.source)
            raise
        except LimitExceeded as e:
            raise limit_error(e).locate(stmt.pos, self.source) from None
        except Exception as e:
            raise convert_exception(e).locate(stmt.pos, self.source) from None

    def _exec_expr(self, s: A.ExprStmt) -> None:
        parts = []
        for node in s.exprs:
            v = self.eval(node)
            if v is NONE:
                continue
            self.last = v
            parts.append((render(v, node.id if isinstance(node, A.Name) else None), isinstance(v, List)))
        if parts:
            self.write(join_outputs(parts) + "\n")

    def _values(self, nodes: list[A.Expr]) -> list[Any]:
        """Evaluate an expression list, splicing in the items of expression-list values."""
        out: list[Any] = []
        for n in nodes:
            v = self.eval(n)
            if isinstance(v, ExprList):
                out.extend(v.items)
            elif v is not NONE or len(nodes) == 1:
                out.append(v)
        return out

    def _rhs(self, nodes: list[A.Expr]) -> Any:
        vals = self._values(nodes)
        if len(vals) == 1:
            return vals[0]
        return ExprList(vals)

    def _exec_decl(self, s: A.Decl) -> None:
        typ = s.type
        if typ in UNSUPPORTED_TYPES:
            raise MechTypeError(f"type '{typ}' is not supported yet")
        if typ == "ring":
            self._declare_ring(s)
            return
        if typ == "map":
            self._declare_map(s)
            return
        for d in s.items:
            if d.dims and typ != "matrix":
                raise MechTypeError(f"only a matrix is declared with dimensions, not a {typ}")
        values: list[Any]
        if s.value is None:
            values = [None] * len(s.items)
        elif len(s.items) == 1:
            values = [self._rhs(s.value)]
        else:
            values = self._values(s.value)
            if len(values) != len(s.items):
                raise MechRuntimeError(f"{len(s.items)} variables declared but {len(values)} values given")
        for d, v in zip(s.items, values):
            self._declare_item(typ, d, v)

    def _declare_item(self, typ: str, d: A.Declarator, v: Any) -> None:
        kring = self.ring.poly if self.ring else None
        if typ == "matrix":
            dims = [to_int(self.eval(x)) for x in d.dims]
            if dims and (len(dims) != 2 or dims[0] <= 0 or dims[1] <= 0):
                raise MechRuntimeError("a matrix is declared as matrix M[rows][cols]")
            ring = self.basering().poly
            if v is None:
                v = Matrix(ring, *(dims or (1, 1)))
            else:
                # as Singular: a matrix value keeps its size, other values fill [rows][cols] (default 1 x 1)
                v = to_matrix(v, ring) if isinstance(v, Matrix) else to_matrix(v, ring, *(dims or (1, 1)))
        elif v is None:
            v = self._default(typ)
        else:
            v = self._converted(v, typ, kring)
        self.declare(d.name, typ, v)

    def _default(self, typ: str) -> Any:
        if typ in ("int", "bigint"):
            return 0
        if typ == "string":
            return ""
        if typ == "list":
            return List()
        if typ == "intvec":
            return IntVec([0])
        if typ == "def":
            return NONE
        if typ == "proc":
            raise MechRuntimeError("a proc is declared with proc name(...) { ... }")
        if typ == "mechanism":
            raise MechRuntimeError('a mechanism is declared with its description: mechanism m = "fix O; bar O A l1";')
        ring = self.basering().poly
        if typ == "number":
            return Number(ring, ring.field.zero)
        if typ == "poly":
            return ring.zero()
        if typ == "ideal":
            return Ideal(ring, [], is_std=True)
        raise MechTypeError(f"type '{typ}' is not supported yet")

    def _converted(self, v: Any, typ: str, kring: Any) -> Any:
        if typ in RING_TYPES and kring is None:
            self.basering()
        v = convert(v, typ, kring)
        if isinstance(v, Ideal):
            std = v.is_std or len(v.gens) <= 1  # Singular marks one-generator ideals as standard bases
            if std != v.is_std:
                v = Ideal(v.ring, v.gens, std)
        return v

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
        if "redefine" not in self.options or self.stmt is None:
            return
        pos = self.stmt.pos
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

    def unwind(self) -> None:
        """Back to the top level after an interrupt: drop procedure frames an interrupted cleanup left."""
        if len(self.frames) > 1:
            self.ring = self.frames[1].ring_at_entry
            del self.frames[1:]
        self.stmt = None
        self._loading_lib = ""

    def lookup_in_ring(self, ring: Ring, name: str) -> Optional[Var]:
        """A ring-dependent variable of ``ring`` (not necessarily the basering)."""
        frame = self.frames[-1]
        if frame.level:
            t = frame.ring_vars.get(ring)
            if t is not None and name in t:
                return t[name]
        return ring.objects.get(name)

    def _declare_ring(self, s: A.Decl) -> None:
        if len(s.items) != 1 or s.items[0].dims:
            raise MechRuntimeError("declare one ring at a time: ring r = 0, (x,y,z), dp;")
        if s.value is None:
            ring = default_ring()
        elif len(s.value) == 1:
            v = self.eval(s.value[0])
            if not isinstance(v, Ring):
                raise MechTypeError(f"cannot convert {typeof(v)} to ring")
            ring = Ring(v.poly, v.params, v.blocks)
        else:
            ring = build_ring(s.value, self.eval)
        ring.name = s.items[0].name
        self.rings.add(ring)
        self.declare(ring.name, "ring", ring)
        self.ring = ring

    def _declare_map(self, s: A.Decl) -> None:
        if len(s.items) != 1:
            raise MechRuntimeError("declare one map at a time: map phi = r, f1, ..., fn;")
        if s.value is None:
            raise MechRuntimeError("a map is declared as map phi = r, f1, ..., fn;")
        v = self._values(s.value)
        if len(v) == 1 and isinstance(v[0], Map):
            m = v[0]
        else:
            if not v or not isinstance(v[0], Ring):
                raise MechTypeError("a map is declared as map phi = r, f1, ..., fn; with r the source ring")
            src = v[0]
            target = self.basering().poly
            images = list(self._converted(ExprList(v[1:]), "ideal", target).gens) if len(v) > 1 else []
            m = Map(src, target, tuple(images))  # as Singular, images beyond the variables are kept, unused
        self.declare(s.items[0].name, "map", m)

    def _exec_assign(self, s: A.Assign) -> None:
        if len(s.targets) == 1:
            self.assign(s.targets[0], self._rhs(s.values))
            return
        if len(s.values) == len(s.targets):  # Singular assigns pairwise, in turn: a, b = b, a; sets both to b
            for t, n in zip(s.targets, s.values):
                self.assign(t, self.eval(n))
            return
        vals = self._values(s.values)
        if len(vals) != len(s.targets):
            raise MechRuntimeError(f"{len(s.targets)} targets but {len(vals)} values")
        for t, v in zip(s.targets, vals):
            self.assign(t, v)

    def assign(self, target: A.Expr, value: Any) -> None:
        """Store ``value`` into a name or an indexed entry (``I[2]``, ``D[i,j]``, ``L[2][1]``)."""
        if type(value) is int and type(target) is A.Name:  # fast path: int variables in loops
            var = self.lookup(target.id)
            if var is not None and var.type == "int":
                var.value = value
                return
        chain: list[A.Index] = []
        base = target
        while isinstance(base, A.Index):
            chain.append(base)
            base = base.base
        assert isinstance(base, A.Name)
        name = base.id
        var = self.lookup(name)
        if var is None:
            if name in self.sysvars or name in ("timer", "rtimer"):
                self.sysvars[name] = to_int(value)
                return
            if self.ring is not None and self.ring.var_index(name) is not None:
                raise MechRuntimeError(f"cannot assign to the ring variable '{name}'")
            raise MechNameError(f"'{name}' is not declared (declare it first, e.g. int {name} = ...;)",
                                base.pos, self.source)
        kring = self.ring.poly if self.ring else None
        if not chain:
            if var.type == "ring":
                value = convert(value, "ring", None)
            elif var.type == "map":
                value = convert(value, "map", None)
            elif var.type == "matrix" and isinstance(var.value, Matrix):
                value = to_matrix(value, self.basering().poly, var.value.nrows, var.value.ncols) \
                    if not isinstance(value, Matrix) else to_matrix(value, self.basering().poly)
            else:
                value = self._converted(value, var.type, kring)
            self._rebind(var, value)
            return
        chain.reverse()
        new = self._set_in(var.value, chain, 0, value)
        self._rebind(var, new)

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

    def _set_in(self, container: Any, chain: list[A.Index], k: int, value: Any) -> Any:
        node = chain[k]
        idx = [self.eval(i) for i in node.indices]
        last = k == len(chain) - 1
        ring = self.ring.poly if self.ring else None
        if isinstance(container, Matrix):
            if len(idx) != 2 or not last:
                raise MechRuntimeError("a matrix entry is set as M[i,j] = ...")
            i, j = to_int(idx[0]), to_int(idx[1])
            if not (1 <= i <= container.nrows and 1 <= j <= container.ncols):
                raise MechRuntimeError(f"index [{i},{j}] out of range for a {container.nrows} x {container.ncols} matrix")
            ents = list(container.entries)
            ents[(i - 1) * container.ncols + j - 1] = to_poly(value, container.ring)
            return Matrix(container.ring, container.nrows, container.ncols, ents)
        if len(idx) != 1:
            raise MechRuntimeError(f"a {typeof(container)} takes one index")
        i = to_int(idx[0])
        if i < 1:
            raise MechRuntimeError(f"index {i} out of range (indices start at 1)")
        if isinstance(container, Ideal):
            if not last:
                raise MechRuntimeError("cannot index into an ideal's generator")
            gens = list(container.gens)
            gens += [container.ring.zero()] * (i - len(gens))
            gens[i - 1] = to_poly(value, container.ring if ring is None else ring)
            return Ideal(container.ring, gens)
        if isinstance(container, List):
            items = list(container.items)
            items += [NONE] * (i - len(items))
            if last:
                items[i - 1] = List(value.items) if isinstance(value, ExprList) else value
            else:
                items[i - 1] = self._set_in(items[i - 1], chain, k + 1, value)
            return List(items)
        if isinstance(container, IntVec):
            if not last:
                raise MechRuntimeError("cannot index into an int")
            vals = list(container.values)
            vals += [0] * (i - len(vals))
            vals[i - 1] = to_int(value)
            return IntVec(vals)
        if isinstance(container, str) and last and isinstance(value, str):
            # as Singular: the i-th character becomes the first one of the value ("" ends the string there)
            if not 1 <= i <= len(container):
                raise MechRuntimeError(f"string index {i} out of range 1..{len(container)}")
            return container[:i - 1] + value[:1] + (container[i:] if value else "")
        raise MechTypeError(f"cannot assign into an entry of a {typeof(container)}")

    def _exec_incdec(self, s: A.IncDec) -> None:
        if type(s.target) is A.Name:
            var = self.lookup(s.target.id)
            if var is not None and type(var.value) is int:
                var.value += s.delta
                return
        cur = self.eval(s.target)
        if type(cur) is not int:
            raise MechTypeError(f"++ and -- need an int, not {typeof(cur)}")
        self.assign(s.target, cur + s.delta)

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
            except _Break:
                break
            except _Continue:  # as in Singular, continue skips the step: it goes on with the condition
                continue
            if s.step is not None:
                self.exec_stmt(s.step)

    def _exec_while(self, s: A.While) -> None:
        while ops.truth(self.eval(s.cond)):
            try:
                self.exec_block(s.body)
            except _Break:
                break
            except _Continue:
                pass

    def _exec_break(self, s: A.Break) -> None:
        raise _Break()

    def _exec_continue(self, s: A.Continue) -> None:
        raise _Continue()

    def _exec_return(self, s: A.Return) -> None:
        if len(self.frames) == 1:
            raise MechRuntimeError("return outside a procedure")
        vals = self._values(s.values) if s.values else []
        raise _Return(NONE if not vals else vals[0] if len(vals) == 1 else ExprList(vals))

    def _exec_procdef(self, s: A.ProcDef) -> None:
        lib = getattr(self, "_loading_lib", "")
        self.declare(s.name, "proc", Proc(s.name, s.params, s.body, s.doc, self.source, lib, s.body_line))

    def _names_of(self, targets: list[A.Expr], what: str) -> list[A.Name]:
        out = []
        for t in targets:
            items = t.items if isinstance(t, A.Tuple) else [t]
            for it in items:
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

    def _remove(self, var: Var) -> None:
        frame = self.frames[var.level] if var.level < len(self.frames) else self.frames[-1]
        table = self._ring_table(frame, var.ring, False) if var.ring is not None else frame.vars
        if table is not None and table.get(var.name) is var:
            del table[var.name]

    def _exec_export(self, s: A.Export) -> None:
        for n in self._names_of(s.targets, "export"):
            self.export(n.id)

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

    def _exec_keepring(self, s: A.Keepring) -> None:
        ring = self.eval(s.ring)
        if not isinstance(ring, Ring):
            raise MechTypeError(f"keepring needs a ring, not {typeof(ring)}")
        if isinstance(s.ring, A.Name):
            ring.name = s.ring.id
        self.ring = ring
        self.frames[-1].keep_ring = True

    def _exec_setring(self, s: A.Setring) -> None:
        ring = self.eval(s.ring)
        if not isinstance(ring, Ring):
            raise MechTypeError(f"setring needs a ring, not {typeof(ring)}")
        if isinstance(s.ring, A.Name):  # as Singular, the basering is known by the name it was set by
            ring.name = s.ring.id
        self.ring = ring

    def _exec_lib(self, s: A.Lib) -> None:
        self.load_library(s.name)

    def load_library(self, name: str) -> None:
        """``LIB "name";``: enable a library's commands and run its mech source if it has one: one of
        mech's libraries, else the file of that name next to the running script (in the current
        directory for code without a file).  Never a path, so scripts read no other files."""
        if name in ("", ".", "..") or Path(name).name != name:
            raise MechNameError(f'LIB takes a library name, not a path: "{name}" (libraries are mech\'s own '
                                f'or files next to the script)')
        path = STDLIB_DIR / name if name.endswith(".lib") else Path()  # mech's library sources: stdlib/*.lib
        if name not in self.registry.LIBRARIES and not path.is_file():
            script = Path(self.source.name)
            user = (script.parent if script.is_file() else Path.cwd()) / name
            if user.is_file():
                path = user
            else:
                self.registry.check_library(name)
        if name in self.loaded_libs:
            return
        self.loaded_libs.add(name)
        if path.is_file():
            saved = getattr(self, "_loading_lib", "")
            self._loading_lib = name
            frames, self.frames = self.frames, self.frames[:1]
            try:
                self.execute(path.read_text(), str(path))
            finally:
                self._loading_lib = saved
                self.frames = frames

    def _exec_quit(self, s: A.Quit) -> None:
        raise QuitSignal()

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

    # ------------------------------------------------------------ expressions
    def eval(self, node: A.Expr) -> Any:
        try:
            return self._eval[type(node)](node)
        except _SIGNALS:
            raise
        except MechError as e:
            if e.pos is None:
                e.locate(node.pos, self.source, isinstance(node, (A.Call, A.TypeCall, A.BinOp, A.Index)))
            raise
        except Exception as e:
            raise convert_exception(e).locate(node.pos, self.source,
                                              isinstance(node, (A.Call, A.TypeCall, A.BinOp))) from None

    def _eval_name(self, node: A.Name) -> Any:
        name = node.id
        var = self.lookup(name)
        if var is not None:
            return var.value
        ring = self.ring
        if ring is not None:
            i = ring.var_index(name)
            if i is not None:
                return ring.poly.gen(i)
            if name in ring.params:
                return self._param(ring, name)
        special = self._special(name)
        if special is not None:
            return special
        if ring is not None:
            m = self._monomial(name)
            if m is not None:
                return m
        raise self._unknown(name)

    def _special(self, name: str) -> Any:
        if name == "basering":
            return self.basering()
        if name == "timer":
            return int((time.process_time() - self._t0) * self.ticks_per_sec)
        if name == "rtimer":
            return int((time.time() - self._r0) * self.ticks_per_sec)
        if name == "_":
            return self.last
        if name == "voice":
            return len(self.frames)
        return self.sysvars.get(name)

    def _unknown(self, name: str) -> MechError:
        if self.registry.COMMANDS.get(name) is not None:
            return MechNameError(f"'{name}' is a command: call it as {name}(...)")
        for r in self.rings:
            if r is not self.ring and name in r.objects:
                where = f"ring {r.name}" if r.name else "another ring"
                return MechNameError(f"unknown identifier '{name}' (it belongs to {where}: use setring {r.name} "
                                     f"or bring it over with imap/fetch)")
        if self.ring is None:
            return MechNameError(f"unknown identifier '{name}' (no ring is active)")
        return MechNameError(f"unknown identifier '{name}'")

    def _param(self, ring: Ring, name: str) -> Number:
        return Number(ring.poly, ring.poly.field.gen(ring.params.index(name)))

    def _monomial(self, text: str, coeff: Any = None) -> Optional[Any]:
        """``x2y`` as x^2*y when it reads as one-letter ring variables (or parameters) with exponents."""
        ring = self.ring
        if ring is None:
            return None
        exp = [0] * len(ring.names)
        params: list[tuple[str, int]] = []
        i, n = 0, len(text)
        while i < n:
            ch = text[i]
            j = i + 1
            while j < n and text[j].isdigit():
                j += 1
            k = int(text[i + 1:j]) if j > i + 1 else 1
            idx = ring.var_index(ch) if ch.isalpha() else None
            if idx is not None:
                exp[idx] += k
            elif ch.isalpha() and ch in ring.params:
                params.append((ch, k))
            else:
                return None
            i = j
        p = ring.poly.monomial(tuple(exp))
        for name, k in params:
            p = p * (self._param(ring, name).c ** k)
        return p

    def _eval_rat(self, node: A.RatLit) -> Any:
        if self.ring is None:
            raise MechRuntimeError(f"no ring active: {node.num}/{node.den} is a rational number "
                                   f"(for integer division use {node.num} div {node.den})")
        if node.den == 0:
            raise MechRuntimeError("division by 0")
        f = self.ring.poly.field
        return Number(self.ring.poly, f(node.num) / f(node.den))

    def _eval_monom(self, node: A.MonomLit) -> Any:
        if self.ring is None:
            raise MechNameError(f"unknown identifier '{node.num}{node.monomial}' (no ring is active)")
        m = self._monomial(node.monomial)
        if m is None:
            i = self.ring.var_index(node.monomial)
            if i is None:
                text = f"{node.num}" + (f"/{node.den}" if node.den != 1 else "") + node.monomial
                raise MechNameError(f"unknown identifier '{text}'")
            m = self.ring.poly.gen(i)
        if node.den == 0:
            raise MechRuntimeError("division by 0")
        f = self.ring.poly.field
        return m * (f(node.num) / f(node.den))

    def _eval_tuple(self, node: A.Tuple) -> Any:
        return ExprList(self._values(node.items))

    def _eval_binop(self, node: A.BinOp) -> Any:
        op = node.op
        if op == "&&":
            return int(ops.truth(self.eval(node.left)) and ops.truth(self.eval(node.right)))
        if op == "||":
            return int(ops.truth(self.eval(node.left)) or ops.truth(self.eval(node.right)))
        spine = [node]  # a long sum x+y+...+z nests to the left: evaluate its left spine by a loop
        while type(spine[-1].left) is A.BinOp and spine[-1].left.op not in ("&&", "||"):
            spine.append(spine[-1].left)
        a = self.eval(spine[-1].left)
        for n in reversed(spine[1:]):
            b = self.eval(n.right)
            try:
                a = self._binary(n.op, a, b)
            except MechError as e:
                if e.pos is None:
                    e.locate(n.pos, self.source, True)
                raise
            except Exception as e:
                raise convert_exception(e).locate(n.pos, self.source, True) from None
        return self._binary(op, a, self.eval(node.right))

    def _binary(self, op: str, a: Any, b: Any) -> Any:
        ring = self.ring.poly if self.ring else None
        if op in ("==", "!=", "<", "<=", ">", ">="):
            return ops.compare(op, a, b, ring)
        return ops.binary(op, a, b, ring, self.warn_in_line)

    def _eval_unop(self, node: A.UnOp) -> Any:
        v = self.eval(node.operand)
        if node.op == "-":
            return ops.negate(v)
        if node.op == "+":
            return v
        return int(not ops.truth(v))

    def _eval_range(self, node: A.Range) -> IntVec:
        lo, hi = to_int(self.eval(node.lo)), to_int(self.eval(node.hi))
        step = 1 if hi >= lo else -1
        return IntVec(range(lo, hi + step, step))

    def _eval_index(self, node: A.Index) -> Any:
        base = self.eval(node.base)
        idx = [self.eval(i) for i in node.indices]
        if isinstance(base, Matrix) and len(idx) == 2:
            i, j = to_int(idx[0]), to_int(idx[1])
            if not (1 <= i <= base.nrows and 1 <= j <= base.ncols):
                raise MechRuntimeError(f"index [{i},{j}] out of range for a {base.nrows} x {base.ncols} matrix")
            return base.get(i, j)
        if len(idx) != 1:
            raise MechRuntimeError(f"a {typeof(base)} takes one index")
        k = idx[0]
        if isinstance(k, IntVec):
            return ExprList([self._item(base, i) for i in k.values])
        return self._item(base, to_int(k))

    def _item(self, base: Any, i: int) -> Any:
        if isinstance(base, Ideal):
            seq, what = base.gens, "ideal"
        elif isinstance(base, List):
            seq, what = base.items, "list"
        elif isinstance(base, IntVec):
            seq, what = base.values, "intvec"
        elif isinstance(base, str):
            seq, what = base, "string"
        elif isinstance(base, Map):
            seq, what = base.images, "map"
        elif isinstance(base, Poly):
            seq, what = [base.ring.monomial(e, c) for e, c in base.sorted_terms()], "poly"
            if 1 <= i <= len(seq):
                return seq[i - 1]
            if i > len(seq):
                return base.ring.zero()
        elif isinstance(base, Matrix):
            raise MechRuntimeError("a matrix entry is M[i,j]")
        else:
            raise MechTypeError(f"a {typeof(base)} cannot be indexed")
        if not 1 <= i <= len(seq):
            raise MechRuntimeError(f"index {i} out of range (the {what} has {len(seq)} entries)")
        return seq[i - 1]

    def _eval_call(self, node: A.Call) -> Any:
        f = node.func
        if isinstance(f, A.Name):
            name = f.id
            var = self.lookup(name)
            if var is not None:
                v = var.value
                if isinstance(v, Proc):
                    return self.call_proc(v, self._values(node.args), node)
                if isinstance(v, Map):
                    nvars = len(v.source.names)
                    if len(v.images) < nvars:  # Singular's quirk: applying a map stores its missing images (0)
                        var.value = Map(v.source, v.ring, v.images + (v.ring.zero(),) * (nvars - len(v.images)))
                    return self.apply_map(v, node.args)
            cmd = self.registry.find(name, self.loaded_libs)
            if cmd is not None:
                return self.call_command(cmd, node.args)
            gens = self._indexed_vars(node)
            if gens is not None:
                return gens
            if var is not None:
                raise MechTypeError(f"'{name}' is a {typeof(var.value)}, not a procedure")
            raise self.registry.unknown_command(name)
        if isinstance(f, A.Call):
            gens = self._indexed_vars(node)
            if gens is not None:
                return gens
        v = self.eval(f)
        if isinstance(v, Proc):
            return self.call_proc(v, self._values(node.args), node)
        if isinstance(v, Map):
            return self.apply_map(v, node.args)
        raise MechTypeError(f"a {typeof(v)} cannot be called")

    def _indexed_vars(self, node: A.Call) -> Any:
        """Ring variables written ``x(2)``, ``x(1..3)`` (several), ``y(1)(2)``; None if not such."""
        if self.ring is None:
            return None
        names = indexed_names(node, self.eval)
        if names is None:
            return None
        idx = [self.ring.var_index(n) for n in names]
        if any(i is None for i in idx):
            return None
        gens = [self.ring.poly.gen(i) for i in idx]
        return gens[0] if len(gens) == 1 else ExprList(gens)

    def _eval_typecall(self, node: A.TypeCall) -> Any:
        cmd = self.registry.find(node.type, self.loaded_libs)
        if cmd is None:
            raise MechTypeError(f"type '{node.type}' is not supported yet")
        return self.call_command(cmd, node.args)

    def call_command(self, cmd: Any, arg_nodes: list[A.Expr]) -> Any:
        args = None if cmd.raw else self._values(arg_nodes)
        saved = self.argnames
        try:
            if cmd.raw:
                return self.registry.invoke_raw(cmd, self, arg_nodes)
            self.argnames = [n.id if isinstance(n, A.Name) else "_" for n in arg_nodes]
            return self.registry.invoke(cmd, self, args)
        except (LimitExceeded, MemoryError) as e:  # "time limit of 5 s exceeded in std"
            raise limit_error(e, cmd.name) from None
        finally:
            self.argnames = saved

    def call_proc(self, proc: Proc, args: list[Any], node: Optional[A.Expr] = None) -> Any:
        """Call a procedure with evaluated arguments in a new scope; the basering is restored
        afterwards (unless the procedure used keepring)."""
        if len(self.frames) > MAX_DEPTH:
            raise MechRuntimeError(f"procedure calls nested deeper than {MAX_DEPTH}")
        caller_source = self.source
        frame = Frame(len(self.frames), {}, proc, node.pos if node else None, caller_source, self.ring)
        self.frames.append(frame)
        saved_stmt = self.stmt
        try:
            self._bind_params(proc, args)
        except MechError as e:
            self.frames.pop()
            self.ring = frame.ring_at_entry
            if node is not None:
                e.locate(node.pos, caller_source, True)
            raise
        self.source = proc.source
        try:
            try:
                self.exec_block(proc.body)
            except _Return as r:
                return r.value
            except _Break:
                raise MechRuntimeError("break outside a loop", self.stmt.pos if self.stmt else None, self.source)
            except _Continue:
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
            self.stmt = saved_stmt
            if not frame.keep_ring:
                self.ring = frame.ring_at_entry

    def _bind_params(self, proc: Proc, args: list[Any]) -> None:
        params = proc.params or []
        if proc.params is None and args:
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
            if typ == "ring":
                v = convert(args[i], "ring", None)
            elif typ == "matrix":  # as a declaration without dimensions: a non-matrix fills a 1 x 1 matrix
                v = to_matrix(args[i], self.basering().poly, *((0, 0) if isinstance(args[i], Matrix) else (1, 1)))
            else:
                try:
                    v = self._converted(args[i], typ, self.ring.poly if self.ring else None)
                except MechError as e:
                    e.message = f"argument {i + 1} of {proc.name}: {e.message}"
                    raise
            self.declare(p.name, typ, v)
            i += 1
        if i < len(args):
            raise MechTypeError(f"too many arguments for procedure {proc.name}: expected {len(params)}, got {len(args)}")

    # ------------------------------------------------------------ maps
    def apply_map(self, m: Map, arg_nodes: list[A.Expr]) -> Any:
        if len(arg_nodes) != 1:
            raise MechTypeError("a map is applied to one argument: phi(I)")
        node = arg_nodes[0]
        value = None
        if isinstance(node, A.Name):
            var = self.lookup_in_ring(m.source, node.id)
            if var is not None:
                value = var.value
        if value is None:
            saved = self.ring
            self.ring = m.source
            try:
                value = self.eval(node)
            finally:
                self.ring = saved
        nvars = len(m.source.names)
        images = list(m.images[:nvars]) + [m.ring.zero()] * (nvars - len(m.images))
        from ..kernel.maps import map_polys
        return map_value(value, images, m.ring, lambda polys, source: map_polys(polys, images, m.ring, source))


def map_value(v: Any, images: tuple | list, target: Any, how: Optional[Callable] = None) -> Any:
    """The image of a value under the substitution x_i -> images[i] into ``target``, coefficients
    converted by :func:`mech.kernel.maps.coefficient_map` (parameters by name, as imap does);
    ``how(polys, source)`` replaces the substitution (e.g. :func:`mech.kernel.maps.map_polys`)."""
    if how is None:
        def how(polys: list, source: Any) -> list:
            from ..kernel.maps import coefficient_map
            coeff = coefficient_map(source, target)
            out = []
            for p in polys:
                acc = target.zero()
                for e, c in p.terms.items():
                    t = coeff(c)
                    for i, k in enumerate(e):
                        if k:
                            t = t * images[i] ** k
                    acc = acc + t
                out.append(acc)
            return out

    def each(polys: Any) -> list:
        polys = list(polys)
        return how(polys, polys[0].ring) if polys else []
    if isinstance(v, Poly):
        return each([v])[0]
    if isinstance(v, Number):
        p = each([v.to_poly()])[0]
        if not p.is_constant():
            raise MechRuntimeError("the image of a number is not a number")
        return Number(target, p.lc() if p.terms else target.field.zero)
    if isinstance(v, Ideal):
        return Ideal(target, each(v.gens))
    if isinstance(v, Matrix):
        return Matrix(target, v.nrows, v.ncols, each(v.entries))
    if isinstance(v, Map):
        return Map(v.source, target, tuple(each(v.images)))
    if isinstance(v, List):
        return List([map_value(x, images, target, how) for x in v.items])
    if isinstance(v, ExprList):
        return ExprList([map_value(x, images, target, how) for x in v.items])
    return v


def proc_pos(proc: Proc) -> Optional[A.Pos]:
    return proc.body[0].pos if proc.body else None


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

