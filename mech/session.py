"""The Python API: a :class:`Session` runs mech code and exchanges values with Python."""
from __future__ import annotations

import io
import sys
from fractions import Fraction
from typing import Any, Callable

from .dsl import ast as A
from .dsl.errors import MechError, MechNameError, MechSyntaxError, MechTypeError, Source
from .dsl.interpreter import Interpreter, QuitSignal
from .dsl.parser import parse
from .dsl.values import NONE, ExprList, IntVec, Ring
from .kernel import offload
from .kernel.engines import check_engine
from .kernel.errors import EngineError
from .kernel.progress import Event, listening


class Session:
    """An interpreter with its variables and rings, kept between calls.

    ``execute(code)`` runs statements and returns what they printed; ``eval(expr)`` returns the
    value of one expression; ``session[name]`` reads a variable and ``session[name] = value``
    sets one (ints, strings, Fractions, floats (their exact binary value), sympy numbers,
    expressions and matrices, lists of them, or mech values); :func:`mech.to_sympy` turns values
    into sympy objects.  Errors raise :class:`MechError` subclasses carrying ``line`` and
    ``column`` (``err.output`` holds what was printed before the error).  ``timeout`` (seconds)
    and ``max_memory`` (MB it may add to the process) limit each statement (``mech.dsl.limits``):
    exceeding one raises ``MechLimitError`` and leaves the session usable; ``KeyboardInterrupt`` (Ctrl-C)
    stops a statement and leaves it usable too.  Both act inside long python-flint calls, which run
    in a child process (``mech.kernel.offload``).  ``engine`` names the
    Gröbner engine of every standard basis (``mech.kernel.engines``; default ``"auto"``; the
    language's ``engine("NAME")`` changes it).  ``report_format``
    is analyze's default (``mech --format``); ``display``, a callable taking MIME bundles
    (``{"text/plain": ..., "text/latex": ...}``), receives the values of expression statements,
    reports and pictures instead of their text (notebooks give one); ``echo``: also print the
    output to ``sys.stdout`` as it is produced; ``scheduler``: where the language's ``sweep`` runs (a Dask
    scheduler address ``"tcp://host:8786"``, or ``"inline"``; default a local Dask cluster);
    ``progress``: a callable receiving a :class:`mech.kernel.progress.Event` for each stage of a
    long computation (``analyze``'s elimination, decomposition, singular points, ...) as it
    starts, advances and ends, in the thread running the statement.  A session is a context manager:
    ``with Session() as s: ...``."""

    def __init__(self, warnings: bool = True, timeout: float | None = None,
                 max_memory: float | None = None, dialect: str = "singular", *,
                 report_format: str = "text", engine: str = "auto",
                 display: Callable[[dict[str, str]], None] | None = None, echo: bool = False,
                 scheduler: str | None = None,
                 progress: Callable[[Event], None] | None = None) -> None:
        self._out = io.StringIO()
        self.progress = progress
        offload.INTERRUPTIBLE = True  # long python-flint calls in a child: Ctrl-C stops them
        if dialect not in ("singular", "m2"):
            raise ValueError(f"unknown dialect '{dialect}' (known: singular, m2)")
        self.dialect = dialect
        try:
            check_engine(engine)
        except EngineError as e:
            raise ValueError(str(e)) from None
        settings: dict[str, Any] = {"report_format": report_format, "engine": engine}
        if display is not None:
            settings["display"] = display
        if scheduler is not None:
            settings["sweep_scheduler"] = scheduler
        cls = Interpreter
        if dialect == "m2":  # Macaulay2's syntax on the same interpreter (mech.dsl.m2)
            from .dsl.m2 import M2Interpreter as cls
        self._interp = cls(out=_Echo(self._out) if echo else self._out, flush=echo, warnings=warnings,
                           timeout=timeout, max_memory=max_memory, settings=settings)

    def __enter__(self) -> "Session":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    def close(self) -> None:
        """Forget the session's variables, rings and libraries (a closed session stays usable,
        as a fresh one)."""
        self._interp.globals.clear()
        self._interp.ring = None
        self._interp.loaded_libs.clear()

    @property
    def settings(self) -> dict[str, Any]:
        """The interpreter's settings ("report_format", "display", ...); changes apply at once."""
        return self._interp.settings

    @property
    def interpreter(self) -> Interpreter:
        return self._interp

    @property
    def ring(self) -> Ring | None:
        """The basering (None before a ring is declared)."""
        return self._interp.ring

    def execute(self, source: str, name: str = "<string>") -> str:
        """Run ``source`` and return the text it printed."""
        self._out.seek(0)
        self._out.truncate()
        try:
            with listening(self.progress):
                self._interp.execute(source, name)
        except QuitSignal:
            pass
        except MechError as e:
            e.output = self._out.getvalue()
            raise _short(e) from None
        except KeyboardInterrupt:
            self._interp.unwind()
            raise
        return self._out.getvalue()

    def eval(self, expr: str) -> Any:
        """The value of the expression ``expr`` (a tuple for a comma expression)."""
        text = expr.strip().rstrip(";")
        src = Source("<eval>", text)
        try:
            program = self._parse_eval(text, src)
        except MechError as e:
            raise _short(e) from None
        if self.dialect == "m2":
            exprs = [s.expr for s in program.body]
        else:
            exprs = program.body[0].exprs if program.body and isinstance(program.body[0], A.ExprStmt) else []
        if len(program.body) != 1 or not exprs:
            raise MechSyntaxError("eval takes one expression (use execute for statements)", None, src)
        stmt = program.body[0]
        it = self._interp
        saved = it.source
        it.source, it.stmt = src, stmt
        self._out.seek(0)
        self._out.truncate()
        try:
            with listening(self.progress):
                values = it.guarded(lambda: [it.eval(e) for e in exprs])
        except MechError as e:
            raise _short(e) from None
        finally:
            it.source = saved
        values = [v for v in values if v is not NONE]
        flat = []
        for v in values:
            flat.extend(v.items if isinstance(v, ExprList) else [v])
        if not flat:
            return None
        return flat[0] if len(flat) == 1 else tuple(flat)

    def _parse_eval(self, text: str, src: Source) -> A.Program:
        if self.dialect == "m2":
            from .dsl.m2_parser import parse as parse_m2
            return parse_m2(text, src)
        return parse(text + ";", src)

    def __getitem__(self, name: str) -> Any:
        var = self._interp.lookup(name)
        if var is None:
            raise MechNameError(f"unknown identifier '{name}'")
        return var.value

    def __contains__(self, name: str) -> bool:
        return self._interp.lookup(name) is not None

    def __setitem__(self, name: str, value: Any) -> None:
        it = self._interp
        var = it.lookup(name)
        try:
            if isinstance(value, str) and var is not None and var.type not in ("string", "def"):
                text = f"{name} = {value};"
                it.execute(text, "<setitem>")
                return
            v, typ = self._from_python(value)
            if var is not None:
                it.stmt = None
                it.assign(A.Name(name), v)
            else:
                from .dsl.values import convert
                ring = it.ring.poly if it.ring else None
                it.declare(name, typ, convert(v, typ, ring) if typ != "def" else v)
        except MechError as e:
            raise _short(e) from None

    def _from_python(self, value: Any) -> tuple[Any, str]:
        from .dsl.convert import is_sympy, python_number, sympy_to_poly
        from .dsl.values import Ideal, List, Matrix, Map, Number, Proc, typeof
        from .kernel import Poly
        if isinstance(value, bool):
            return int(value), "int"
        if isinstance(value, int):
            return value, "int"
        if isinstance(value, str):
            return value, "string"
        if isinstance(value, (Poly, Number, Ideal, Matrix, Map, IntVec, List, Ring, Proc)):
            return value, typeof(value) if not isinstance(value, (Ring, Proc)) else "def"
        if isinstance(value, (Fraction, float)) or (is_sympy(value) and getattr(value, "is_Number", False)):
            ring = self._interp.basering().poly
            return Number(ring, ring.field(python_number(value))), "number"
        if is_sympy(value):
            ring = self._interp.basering().poly
            if getattr(value, "is_Matrix", False):
                rows, cols = value.shape
                return Matrix(ring, rows, cols, [sympy_to_poly(x, ring) for x in value]), "matrix"
            return sympy_to_poly(value, ring), "poly"
        if isinstance(value, (list, tuple)):
            if all(isinstance(x, int) and not isinstance(x, bool) for x in value):
                return IntVec(value), "intvec"
            if all(isinstance(x, (int, Poly, Fraction, float)) or is_sympy(x) for x in value):
                ring = self._interp.basering().poly
                gens = [x if isinstance(x, Poly) else ring.const(python_number(x))
                        if isinstance(x, (Fraction, float)) else sympy_to_poly(x, ring) for x in value]
                return Ideal(ring, gens), "ideal"
            return List([self._from_python(x)[0] for x in value]), "list"
        raise MechTypeError(f"cannot convert a Python {type(value).__name__} to a mech value")


def _short(e: MechError) -> MechError:
    """The error without the interpreter's frames: notebooks show a short traceback (and IPython
    the error as mech prints it, through ``MechError._render_traceback_``)."""
    e.__traceback__ = None
    e.__context__ = None
    return e


class _Echo:
    """The session's output: kept for :meth:`Session.execute` and printed to ``sys.stdout`` (the
    one of the moment: notebooks replace it) as it is produced."""

    def __init__(self, buffer: io.StringIO) -> None:
        self.buffer = buffer

    def write(self, text: str) -> int:
        self.buffer.write(text)
        sys.stdout.write(text)
        return len(text)

    def flush(self) -> None:
        sys.stdout.flush()
