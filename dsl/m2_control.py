"""Control flow of the Macaulay2 dialect as expressions (a mixin of :class:`mech.dsl.m2.M2Interpreter`):
``for``/``while`` loops (``do`` or ``list``, ``when``), ``if``, ``try ... then ... else``, ``time``,
``return``, ``break``, ``( a; b )`` sequences and functions ``(a, b) -> body``."""
from __future__ import annotations

import time
from typing import Any, Optional

from . import ast as A
from .errors import MechError, MechRuntimeError, MechTypeError
from .m2_ast import BreakExpr, ForLoop, Function, IfExpr, ReturnExpr, Seq, TimeExpr, TryExpr, WhileLoop
from .m2_values import M2Function, M2Set
from .scopes import Frame, Var
from .signals import BreakSignal, ReturnSignal
from .values import NONE, ExprList, List, to_int, typeof


class _Break(BreakSignal):
    """``break v``: leave the loop with the value ``v``."""

    def __init__(self, value: Any) -> None:
        super().__init__()
        self.value = value


class M2Control:
    """Loops, conditionals, ``try``, ``time``, sequences and functions."""

    def _eval_for(self, node: ForLoop) -> Any:
        if node.items is not None:
            seq = self.eval(node.items)
            if isinstance(seq, M2Set):
                values: Any = list(seq.items)
            elif isinstance(seq, (List, ExprList)):
                values = list(seq.items)
            else:
                raise MechTypeError(f"for ... in needs a list, not a {typeof(seq)}")
        else:
            start = to_int(self.eval(node.start)) if node.start is not None else 0
            if node.stop is None and node.when is None:
                raise MechRuntimeError("for i from a to b: the upper bound is missing")
            stop = to_int(self.eval(node.stop)) if node.stop is not None else None
            values = range(start, stop + 1) if stop is not None else _count(start)
        out = []
        for x in values:
            self.set_var(node.var, x, local=True)
            if node.when is not None and not self._truth(self.eval(node.when)):
                break
            try:
                v = self.eval(node.body)
            except _Break as b:
                if b.value is not NONE and node.collect:
                    out.append(b.value)
                break
            except BreakSignal:
                break
            if node.collect:
                out.append(v)
        return List(out) if node.collect else NONE

    def _eval_while(self, node: WhileLoop) -> Any:
        while self._truth(self.eval(node.cond)):
            try:
                self.eval(node.body)
            except BreakSignal as b:
                return getattr(b, "value", NONE)
        return NONE

    def _eval_if(self, node: IfExpr) -> Any:
        if self._truth(self.eval(node.cond)):
            return self.eval(node.then)
        return self.eval(node.orelse) if node.orelse is not None else NONE

    def _eval_try(self, node: TryExpr) -> Any:
        try:
            v = self.eval(node.body)
        except MechError:
            return self.eval(node.orelse) if node.orelse is not None else NONE
        return self.eval(node.then) if node.then is not None else v

    def _eval_time(self, node: TimeExpr) -> Any:
        t0, c0 = time.time(), time.process_time()
        v = self.eval(node.body)
        if node.elapsed:
            self.write(f"-- {time.time() - t0:.6f}s elapsed\n")
        else:
            self.write(f"-- used {time.process_time() - c0:.6f}s (cpu)\n")
        return v

    def _truth(self, v: Any) -> bool:
        if not isinstance(v, bool):
            raise MechTypeError(f"a condition is true or false, not a {typeof(v)}")
        return v

    def _eval_return(self, node: ReturnExpr) -> Any:
        raise ReturnSignal(self.eval(node.value) if node.value is not None else NONE)

    def _eval_break(self, node: BreakExpr) -> Any:
        raise _Break(self.eval(node.value) if node.value is not None else NONE)

    def _eval_seq(self, node: Seq) -> Any:
        v: Any = NONE
        for e in node.exprs:
            v = self.eval(e)
        return NONE if node.silent else v

    def _eval_function(self, node: Function) -> M2Function:
        frame = self.frames[-1]
        return M2Function(node.params, node.body, self.source, dict(frame.vars) if frame.level else {})

    def call_function(self, fn: M2Function, args: list[Any], node: Optional[A.Expr] = None) -> Any:
        """Call a Macaulay2 function with evaluated arguments in a new scope."""
        if len(args) != len(fn.params):
            if len(fn.params) == 1:
                args = [ExprList(args)]
            elif len(args) == 1 and isinstance(args[0], ExprList) and len(args[0].items) == len(fn.params):
                args = list(args[0].items)
            else:
                raise MechTypeError(f"{fn.name} expects {len(fn.params)} arguments, got {len(args)}")
        if len(self.frames) > 1000:
            raise MechRuntimeError("function calls nested deeper than 1000")
        level = len(self.frames)
        frame = Frame(level, {**fn.captured, **{p: Var(p, "def", a, None, level) for p, a in zip(fn.params, args)}})
        self.frames.append(frame)
        saved = self.source
        self.source = fn.source
        try:
            return self.eval(fn.body)
        except ReturnSignal as r:
            return r.value
        finally:
            self.frames.pop()
            self.source = saved


def _count(start: int):
    k = start
    while True:
        yield k
        k += 1
