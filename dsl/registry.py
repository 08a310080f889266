"""The command registry: how Python functions become commands of the language.

A command is a function decorated with :func:`command`; its parameter annotations declare the
argument types, which the registry checks and coerces (Singular's automatic conversions
int -> number -> poly -> ideal -> matrix, int -> intvec) before the call::

    from mech.dsl.registry import command
    from mech.dsl.values import Ideal

    @command("std")
    def std(ctx, I: Ideal) -> Ideal:
        '''std(I): a standard basis of the ideal I.'''
        ...

Registering the same name again adds an overload (tried in order: first without, then with
coercion).  ``lib="primdec.lib"`` makes the command visible only after ``LIB "primdec.lib";``.
``raw=True`` passes the unevaluated argument trees instead of values (for ``defined(x)``,
``imap(r, I)``...).  The docstring is what ``help name;`` prints.  A first parameter named
``ctx`` receives the interpreter's :class:`Context`.

The language runtime knows no library: a library package registers a loader with
:func:`add_loader` (mech's facade registers ``mech.stdlib.load``), which the interpreter runs once,
before its first program (:func:`load_plugins`); the loader imports the library's modules, whose
decorators register their commands (and :func:`mech.dsl.types.register_type` their types) and
:func:`add_library_dir` the folder of their ``*.lib`` sources.  mech's loader registers the commands
from a record of an earlier start without importing their modules (:mod:`mech.dsl.plugins`): a
command's module is imported on its first call or help, so command modules import nothing at
start-up and heavy packages (sympy) on use.
"""
from __future__ import annotations

import importlib
import inspect
import sys
import threading
import types
import typing
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Optional, Protocol

from .errors import MechNameError, MechTypeError
from .values import (NONE, BigInt, ExprList, Ideal, IntVec, List, Map, Matrix, Number, Proc, Ring,
                          to_ideal, to_intvec, to_matrix, to_number, to_poly, typeof)
from ..kernel import Poly, PolyRing
from .convert_modules import to_module, to_vector
from .values_modules import Module, Vector

#: Library names ``LIB "...";`` accepts; a command's ``lib=`` adds its library.
LIBRARIES: set[str] = {"primdec.lib", "sing.lib", "elim.lib", "poly.lib", "polylib.lib", "general.lib",
                       "matrix.lib", "ring.lib", "standard.lib"}


class Context(Protocol):
    """What a command sees of the interpreter (the first parameter ``ctx``)."""

    ring: Optional[Ring]          #: the basering (None before any ring is declared)
    argnames: list[str]           #: names of the argument expressions, "_" for unnamed ones
    options: set[str]             #: active option(...) names, e.g. "redSB"
    settings: dict[str, Any]      #: session settings the facade gives (e.g. "report_format": "json")

    def basering(self) -> Ring:
        """The basering; raises a clear error when no ring is active."""

    def write(self, text: str) -> None:
        """Print ``text`` (include the newline)."""

    def warn(self, message: str) -> None:
        """Print Singular's warning line ``// ** message``."""

    def display(self, bundle: dict[str, str]) -> None:
        """Show a rich result (MIME type -> data): in a notebook all of it, elsewhere its ``text/plain``."""

    def assume_std(self, ideal: Ideal, argno: int) -> None:
        """Warn ``// ** I is no standard basis`` when argument ``argno`` (0-based) is not marked as one."""

    def eval(self, node: Any) -> Any:
        """Evaluate an argument tree (raw commands)."""


@dataclass
class Overload:
    func: Callable
    wants_ctx: bool
    names: list[str]
    specs: list[Optional[tuple]] = field(default_factory=list)
    required: int = 0
    varargs: Optional[tuple] = None
    has_varargs: bool = False
    resolved: bool = False
    doc: str = ""


def overload_key(ov: Overload) -> str:
    """What names an overload across processes (its function's module and qualified name)."""
    return f"{ov.func.__module__}:{ov.func.__qualname__}"


class Command:
    """A command: its name, library, whether it takes argument trees (``raw``), its help text and
    its overloads (tried in order).  A deferred command (:func:`defer`) knows the modules that
    register its overloads and imports them when its overloads or its help are first read."""

    def __init__(self, name: str, lib: Optional[str], raw: bool, doc: str, overloads: list[Overload]) -> None:
        self.name, self.lib, self.raw = name, lib, raw
        self._doc = doc
        self._overloads = overloads
        #: modules still to import for the overloads (a deferred command)
        self.pending: tuple[str, ...] = ()
        #: the overloads' places by :func:`overload_key` (a deferred command's order of registration)
        self.rank: dict[str, int] = {}

    @property
    def overloads(self) -> list[Overload]:
        if self.pending:
            self._load()
        return self._overloads

    @property
    def doc(self) -> str:
        """The help text: the first one given, in the overloads' order."""
        if self.pending:
            self._load()
        return self._doc or next((ov.doc for ov in self._overloads if ov.doc), "")

    def _load(self) -> None:
        with _LOADING:  # another thread waits for the overloads; this one, re-entering, takes them as they are
            if self.pending and self not in _LOADING_NOW:
                _LOADING_NOW.add(self)
                try:
                    for module in self.pending:
                        importlib.import_module(module)
                    self.pending = ()
                finally:
                    _LOADING_NOW.discard(self)

    def add(self, ov: Overload) -> None:
        """One more overload, after the others or, for a deferred command, at its recorded place."""
        rank = self.rank
        if rank:
            last = len(rank)
            mine = rank.get(overload_key(ov), last)
            i = len(self._overloads)
            while i and rank.get(overload_key(self._overloads[i - 1]), last) > mine:
                i -= 1
            self._overloads.insert(i, ov)
        else:
            self._overloads.append(ov)

    def usage(self) -> str:
        outs = []
        for ov in self.overloads:
            _resolve(ov)
            parts = [_spec_name(s) for s in ov.specs]
            for i in range(ov.required, len(parts)):
                parts[i] = f"[{parts[i]}]"
            if ov.has_varargs:
                parts.append(f"{_spec_name(ov.varargs)}...")
            outs.append(f"{self.name}({', '.join(parts)})")
        return " or ".join(outs)

    def __repr__(self) -> str:
        return f"Command({self.name!r}, lib={self.lib!r})"


_LOADING = threading.RLock()
_LOADING_NOW: set[Command] = set()  # deferred commands whose modules are being imported

COMMANDS: dict[str, Command] = {}
#: Commands of the other surface dialects (``dialect="m2"``), by dialect: invisible to Singular code.
DIALECTS: dict[str, dict[str, Command]] = {}


def table_of(dialect: Optional[str]) -> dict[str, Command]:
    """The commands of ``dialect`` (None: the Singular dialect's)."""
    return COMMANDS if dialect is None else DIALECTS.setdefault(dialect, {})


def defer(dialect: Optional[str], name: str, lib: Optional[str], raw: bool, modules: tuple[str, ...],
          order: list[str]) -> None:
    """Register the command ``name`` without importing the ``modules`` that define it (imported
    when it is first used); ``order``: its overloads' keys (:func:`overload_key`) as registered."""
    table = table_of(dialect)
    cmd = table.get(name)
    if cmd is None:
        cmd = table[name] = Command(name, lib, raw, "", [])
    cmd.pending = tuple(m for m in modules if m not in sys.modules) + cmd.pending
    cmd.rank = {key: i for i, key in enumerate(order)}
    last = len(order)
    cmd._overloads.sort(key=lambda ov: cmd.rank.get(overload_key(ov), last))
    if lib:
        LIBRARIES.add(lib)


def command(name: str, lib: Optional[str] = None, raw: bool = False,
            dialect: Optional[str] = None) -> Callable[[Callable], Callable]:
    """Register the decorated function as the command ``name`` (or as one more overload of it);
    ``dialect="m2"``: a command of the Macaulay2 dialect only."""
    def deco(func: Callable) -> Callable:
        sig = inspect.signature(func)
        params = list(sig.parameters.values())
        wants_ctx = bool(params) and params[0].name == "ctx"
        if wants_ctx:
            params = params[1:]
        ov = Overload(func, wants_ctx, [p.name for p in params if p.kind != p.VAR_POSITIONAL],
                      doc=inspect.getdoc(func) or "")
        ov.required = sum(1 for p in params if p.default is p.empty and p.kind == p.POSITIONAL_OR_KEYWORD)
        ov.has_varargs = any(p.kind == p.VAR_POSITIONAL for p in params)
        table = table_of(dialect)
        cmd = table.get(name)
        if cmd is None:
            table[name] = Command(name, lib, raw, "", [ov])
        else:
            cmd.add(ov)
        if lib:
            LIBRARIES.add(lib)
        return func
    return deco


#: Binary operators of the other dialects defined by their libraries, by dialect and symbol.
OPERATORS: dict[str, dict[str, Callable[[Any, Any], Any]]] = {}


def operator(symbol: str, dialect: str) -> Callable[[Callable], Callable]:
    """Register the decorated ``f(a, b)`` as the operator ``symbol`` of ``dialect`` (``"=="`` also
    gives ``"!="``); it returns ``NotImplemented`` for operands it leaves to the dialect's own rules."""
    def deco(func: Callable) -> Callable:
        OPERATORS.setdefault(dialect, {})[symbol] = func
        return func
    return deco


class _DeferredOperator:
    """An operator whose module is imported on its first use (:func:`defer_operator`)."""

    def __init__(self, dialect: str, symbol: str, module: str) -> None:
        self.dialect, self.symbol, self.module = dialect, symbol, module

    def __call__(self, a: Any, b: Any) -> Any:
        importlib.import_module(self.module)
        func = OPERATORS[self.dialect][self.symbol]
        if func is self:
            raise RuntimeError(f"{self.module} did not define the operator {self.symbol}")
        return func(a, b)


def defer_operator(dialect: str, symbol: str, module: str) -> None:
    """Register the operator ``symbol`` of ``dialect`` defined in ``module``, imported on first use."""
    OPERATORS.setdefault(dialect, {}).setdefault(symbol, _DeferredOperator(dialect, symbol, module))


# ---------------------------------------------------------------- argument types
_SPEC_NAMES = {int: "int", str: "string", Number: "number", Poly: "poly", Ideal: "ideal", Matrix: "matrix",
               IntVec: "intvec", List: "list", Ring: "ring", Map: "map", Proc: "proc", Vector: "vector",
               Module: "module"}


def _spec_name(spec: Optional[tuple]) -> str:
    if spec is None:
        return "any"
    return "|".join(_SPEC_NAMES.get(t, getattr(t, "type_name", None) or getattr(t, "__name__", str(t)))
                    for t in spec)


def _to_spec(hint: Any) -> Optional[tuple]:
    if hint is inspect.Parameter.empty or hint is Any or hint is object:
        return None
    origin = typing.get_origin(hint)
    if origin in (typing.Union, types.UnionType):
        out: list = []
        for h in typing.get_args(hint):
            if h is type(None):
                continue
            s = _to_spec(h)
            if s is None:
                return None
            out.extend(s)
        return tuple(out)
    return (hint,)


def _resolve(ov: Overload) -> None:
    if ov.resolved:
        return
    hints = typing.get_type_hints(ov.func)
    sig = inspect.signature(ov.func)
    params = list(sig.parameters.values())[1 if ov.wants_ctx else 0:]
    for p in params:
        spec = _to_spec(hints.get(p.name, inspect.Parameter.empty))
        if p.kind == p.VAR_POSITIONAL:
            ov.varargs = spec
        else:
            ov.specs.append(spec)
    ov.resolved = True


_NO = object()

# implicit conversions: target type -> (source types, converter(value, ring))
_COERCE: dict[type, tuple[tuple, Callable[[Any, Optional[PolyRing]], Any]]] = {
    int: ((BigInt,), lambda v, r: v),  # a bigint literal (beyond 2^31-1) where a command takes an int
    Number: ((int,), to_number),
    Poly: ((int, Number), to_poly),
    Ideal: ((int, Number, Poly), to_ideal),
    Matrix: ((Ideal,), to_matrix),
    IntVec: ((int,), lambda v, r: to_intvec(v)),
    Module: ((Ideal, Matrix, Vector), to_module),
    Vector: ((int, Number, Poly), to_vector),
}


def _accept(spec: Optional[tuple], v: Any, ring: Optional[PolyRing], coerce: bool) -> Any:
    if spec is None:
        return v
    for t in spec:
        if t is int:
            if type(v) is int:
                return v
        elif isinstance(v, t):
            return v
    if coerce:
        for t in spec:
            rule = _COERCE.get(t)
            if rule and isinstance(v, rule[0]) and not isinstance(v, bool):
                try:
                    return rule[1](v, ring)
                except Exception:
                    continue
    return _NO


def _bind(ov: Overload, args: list, ring: Optional[PolyRing], coerce: bool) -> Optional[list]:
    if not ov.resolved:
        _resolve(ov)
    n = len(args)
    specs = ov.specs
    if n < ov.required or (not ov.has_varargs and n > len(specs)):
        return None
    if not coerce:  # _accept without coercion, inline (commands called in loops)
        for i, a in enumerate(args):
            spec = specs[i] if i < len(specs) else ov.varargs
            if spec is not None:
                ta = type(a)
                for t in spec:
                    if (ta is int) if t is int else isinstance(a, t):
                        break
                else:
                    return None
        return args
    out = []
    for i, a in enumerate(args):
        spec = ov.specs[i] if i < len(ov.specs) else ov.varargs
        c = _accept(spec, a, ring, coerce)
        if c is _NO:
            return None
        out.append(c)
    return out


def invoke(cmd: Command, ctx: Any, args: list) -> Any:
    """Call ``cmd`` with evaluated arguments: pick the overload, coerce, convert the result."""
    ring = ctx.ring.poly if ctx.ring is not None else None
    for coerce in (False, True):
        for ov in cmd.overloads:
            bound = _bind(ov, args, ring, coerce)
            if bound is not None:
                if coerce and hasattr(ctx, "argnames"):
                    ctx.argnames = [n if b is a else "_" for n, a, b in zip(ctx.argnames, args, bound)]
                result = ov.func(ctx, *bound) if ov.wants_ctx else ov.func(*bound)
                return result_value(result)
    if cmd.lib and any(isinstance(a, Matrix) for a in args):  # a library's `ideal i` takes a matrix's entries
        return invoke(cmd, ctx, [to_ideal(a, a.ring) if isinstance(a, Matrix) else a for a in args])
    got = ", ".join(typeof(a) for a in args)
    raise MechTypeError(f"wrong arguments for {cmd.name}: got ({got}), expected {cmd.usage()}")


def invoke_raw(cmd: Command, ctx: Any, nodes: list) -> Any:
    """Call a raw command with the argument trees, checking their number."""
    ov = cmd.overloads[0]
    if len(nodes) < ov.required or (not ov.has_varargs and len(nodes) > len(ov.names)):
        want = ov.required if ov.required == len(ov.names) or ov.has_varargs else f"{ov.required} to {len(ov.names)}"
        more = " or more" if ov.has_varargs and ov.required else ""
        raise MechTypeError(f"wrong number of arguments for {cmd.name}: got {len(nodes)}, expected {want}{more}")
    return result_value(ov.func(ctx, *nodes))


def result_value(v: Any) -> Any:
    """A command's Python result as a value of the language."""
    if v is None:
        return NONE
    if isinstance(v, bool):
        return int(v)
    if isinstance(v, list):
        return List(v)
    if isinstance(v, tuple):
        return ExprList(v)
    return v


# ---------------------------------------------------------------- plug-ins, lookup and libraries
_PENDING: list[Callable[[], None]] = []
#: Folders holding libraries' mech sources (``x.lib``, run by ``LIB "x.lib";``).
LIBRARY_DIRS: list[Path] = []


def add_loader(load: Callable[[], None]) -> None:
    """Register a library package's ``load`` (which registers its commands and types), run by the
    next :func:`load_plugins`."""
    _PENDING.append(load)


def load_plugins() -> None:
    """Run the loaders registered since the last call (each once); interpreters call it on creation."""
    while _PENDING:
        _PENDING.pop(0)()


def add_library_dir(folder: Path) -> None:
    """Make the ``*.lib`` mech sources in ``folder`` loadable by ``LIB "name";``."""
    if folder not in LIBRARY_DIRS:
        LIBRARY_DIRS.append(folder)


def library_source(name: str) -> Optional[Path]:
    """The mech source of the library ``name`` in a library folder (None if there is none)."""
    if not name.endswith(".lib"):
        return None
    for folder in LIBRARY_DIRS:
        path = folder / name
        if path.is_file():
            return path
    return None


def find(name: str, loaded_libs: set[str]) -> Optional[Command]:
    """The command ``name`` if it is built in or its library is loaded."""
    cmd = COMMANDS.get(name)
    if cmd is None or (cmd.lib and cmd.lib not in loaded_libs):
        return None
    return cmd


def unknown_command(name: str) -> MechNameError:
    cmd = COMMANDS.get(name)
    if cmd is not None and cmd.lib:
        return MechNameError(f"unknown command '{name}' (it is in {cmd.lib}: load it with LIB \"{cmd.lib}\";)")
    return MechNameError(f"unknown command '{name}'")


def check_library(name: str) -> None:
    if name not in LIBRARIES:
        known = " ".join(sorted(LIBRARIES))
        raise MechNameError(f"unknown library '{name}' (known: {known})")


def is_builtin(name: str) -> bool:
    cmd = COMMANDS.get(name)
    return cmd is not None and not cmd.lib


#: Help texts of language topics that are not commands (keywords, types): ``help if;``.
TOPICS: dict[str, str] = {}


def help_text(name: str) -> Optional[str]:
    cmd = COMMANDS.get(name)
    if cmd is None:
        return TOPICS.get(name)
    head = f"{cmd.usage()}" + (f"    [{cmd.lib}]" if cmd.lib else "")
    text = head + ("\n" + cmd.doc if cmd.doc else "")
    topic = TOPICS.get(name)  # a type that is also a conversion command (ring(L)): the type first
    return topic + "\n\n" + text if topic else text


__all__ = ["command", "Context", "COMMANDS", "LIBRARIES", "invoke", "find", "add_loader", "load_plugins",
           "add_library_dir"]
