"""Statements and expressions compiled once to Python closures, kept on their tree nodes and reused
each time the node runs again (loop bodies, procedure bodies, repeated lines of long scripts).

A closure takes the interpreter and does what the interpreter's dispatch on the node's type does,
with the same results, output, warnings and error positions, minus the dispatch: the common cases
(int and same-ring polynomial arithmetic, comparisons of ints, names, assignments of ints, polys and
strings to variables of their type, ``x++``, ``if``, ``for``, ``while``) run inline, everything else
calls the interpreter's own methods.  Closures hold no interpreter (trees are shared between
sessions, see :mod:`~mech.dsl.fastparse`).
"""
from __future__ import annotations

from contextlib import contextmanager
from typing import Any, Callable, Iterator

from ..kernel import Poly
from . import ast as A
from . import ops
from .boundary import convert_exception
from .errors import MechError, MechRuntimeError
from .machine_int import MAX64, MIN64, int32
from .signals import SIGNALS, BreakSignal, ContinueSignal, ReturnSignal
from .values import NONE, ExprList, Ideal, IntVec, List, Matrix, Proc

Fn = Callable[[Any], Any]

MAX_DEPTH = 40  # deeper subtrees are left to the interpreter's evaluator (it loops over long sums)

#: while a template compiles (:mod:`~mech.dsl.templates`): the closures of its literal nodes (by id),
#: the ids of the nodes holding literals, and the copy of a node with a statement's own numbers
_SLOTS: dict[int, Fn] = {}
_HOLDERS: set[int] = set()
_ACTUAL: list[Callable[[Any, list], Any]] = []


@contextmanager
def templating(slots: dict[int, Fn], holders: set[int], actual: Callable[[Any, list], Any]) -> Iterator[None]:
    """Compile a template's tree: its literals read the running statement's numbers (``it.lits``)."""
    global _SLOTS, _HOLDERS
    _SLOTS, _HOLDERS = slots, holders
    _ACTUAL.append(actual)
    try:
        yield
    finally:
        _SLOTS, _HOLDERS = {}, set()
        _ACTUAL.pop()


def _actual(node: Any) -> Callable[[Any], Any]:
    """The node a closure hands to the interpreter: ``node`` itself, or in a template the copy with
    the running statement's numbers."""
    if id(node) not in _HOLDERS:
        return lambda it: node
    copy = _ACTUAL[-1]
    return lambda it: copy(node, it.lits)


def expr_fn(node: A.Expr) -> Fn:
    """The closure evaluating ``node`` (as ``Interpreter.eval``), made once."""
    return _child(node, 0)


def stmt_fn(stmt: A.Stmt) -> Fn:
    """The closure running ``stmt`` (as the interpreter's ``_exec`` table), made once."""
    fn = getattr(stmt, "_fn", None)
    if fn is None:
        fn = _stmt(stmt)
        _keep(stmt, fn)
    return fn


def _keep(node: Any, fn: Fn) -> None:
    try:
        node._fn = fn
    except AttributeError:  # a node without a __dict__: compiled again next time
        pass


# ---------------------------------------------------------------- expressions
def _child(node: A.Expr, depth: int) -> Fn:
    fn = getattr(node, "_fn", None)
    if fn is None:
        fn = _expr(node, depth)
        _keep(node, fn)
    return fn


def _locate(e: Exception, node: A.Expr, it: Any) -> Exception:
    """The evaluator's handling of an error raised by ``node``: one without a position gets the
    node's (calls, operators and indexing underlined)."""
    if isinstance(e, MechError):
        if e.pos is None:
            e.locate(node.pos, it.source, isinstance(node, (A.Call, A.TypeCall, A.BinOp, A.Index)))
        return e
    return convert_exception(e).locate(node.pos, it.source, isinstance(node, (A.Call, A.TypeCall, A.BinOp)))


def _generic(node: A.Expr) -> Fn:
    if id(node) in _HOLDERS:
        real = _actual(node)
        return lambda it: it._eval_node(real(it))
    return lambda it: it._eval_node(node)


def _expr(node: A.Expr, depth: int) -> Fn:
    if _SLOTS:
        fn = _SLOTS.get(id(node))
        if fn is not None:
            return fn
    kind = type(node)
    if kind is A.IntLit or kind is A.StrLit:
        value = node.value
        return lambda it: value
    if depth > MAX_DEPTH:
        return _generic(node)
    if kind is A.Name:
        return _name(node)
    if kind is A.BinOp:
        return _binop(node, depth)
    if kind is A.UnOp:
        return _unop(node, depth)
    if kind is A.Index and len(node.indices) == 1:
        return _index(node, depth)
    if kind is A.Call and type(node.func) is A.Name:
        return _call(node, depth)
    return _generic(node)


def _name(node: A.Name) -> Fn:
    name = node.id
    last: list = [None, None]  # a ring's polynomial ring and its variable of this name

    def fn(it: Any) -> Any:
        var = it.lookup(name)
        if var is not None:
            return var.value
        ring = it.ring
        if ring is not None:
            if last[0] is ring.poly:
                return last[1]
            i = ring.var_index(name)
            if i is not None:
                last[0], last[1] = ring.poly, ring.poly.gen(i)
                return last[1]
        return it._eval_node(node)  # parameters, system variables, monomials, errors
    return fn


def _binop(node: A.BinOp, depth: int) -> Fn:
    op = node.op
    lf, rf = _child(node.left, depth + 1), _child(node.right, depth + 1)
    truth = ops.truth
    if op == "&&" or op == "||":
        both = op == "&&"

        def logic(it: Any) -> Any:
            try:
                return int(truth(lf(it)) and truth(rf(it))) if both else int(truth(lf(it)) or truth(rf(it)))
            except SIGNALS:
                raise
            except Exception as e:
                raise _locate(e, node, it) from None
        return logic
    fast, slow, poly = INT_OPS.get(op), _INT_DIV.get(op), _POLY_OPS.get(op)

    def fn(it: Any) -> Any:
        a = lf(it)
        b = rf(it)
        ta, tb = type(a), type(b)
        if ta is int and tb is int and fast is not None:
            r = fast(a, b)
            if MIN64 <= r <= MAX64:
                return r  # else Singular's 64-bit wrap-around below
        try:
            if slow is not None and ta is int and tb is int:
                return slow(a, b)
            if ta is str and tb is str and op == "+":
                return a + b
            if poly is not None:
                if ta is Poly:
                    if tb is Poly and a.ring is b.ring:
                        return poly(a, b)
                    if tb is int:
                        return poly(a, a.ring.const(b))
                elif ta is int and tb is Poly:
                    return poly(b.ring.const(a), b)
            return it._binary(op, a, b)
        except SIGNALS:
            raise
        except Exception as e:
            raise _locate(e, node, it) from None
    return fn


#: int operators with their results in Singular (comparisons give ints)
INT_OPS = {"+": int.__add__, "-": int.__sub__, "*": int.__mul__,
            "<": lambda a, b: int(a < b), "<=": lambda a, b: int(a <= b), ">": lambda a, b: int(a > b),
            ">=": lambda a, b: int(a >= b), "==": lambda a, b: int(a == b), "!=": lambda a, b: int(a != b)}
#: div and mod read their operands as 32-bit ints, as Singular's; they raise "division by 0"
_INT_DIV = {"div": lambda a, b: ops.trunc_div(int32(a), int32(b)), "mod": lambda a, b: ops.trunc_mod(int32(a), int32(b))}
_POLY_OPS = {"+": Poly.__add__, "-": Poly.__sub__, "*": Poly.__mul__}


def _unop(node: A.UnOp, depth: int) -> Fn:
    f = _child(node.operand, depth + 1)
    if node.op == "+":
        return f
    minus = node.op == "-"

    def fn(it: Any) -> Any:
        v = f(it)
        if minus and type(v) is int:
            return -v
        try:
            return ops.negate(v) if minus else int(not ops.truth(v))
        except SIGNALS:
            raise
        except Exception as e:
            raise _locate(e, node, it) from None
    return fn


def _index(node: A.Index, depth: int) -> Fn:
    """``base[i]`` with one index: an entry of a list or ideal inline, the rest as the evaluator does."""
    bf, kf = _child(node.base, depth + 1), _child(node.indices[0], depth + 1)

    def fn(it: Any) -> Any:
        base = bf(it)
        k = kf(it)
        if type(k) is int and 1 <= k:
            tb = type(base)
            seq = base.items if tb is List else base.gens if tb is Ideal else None
            if seq is not None and k <= len(seq):
                return seq[k - 1]
        try:
            return it._index_value(base, [k])
        except SIGNALS:
            raise
        except Exception as e:
            raise _locate(e, node, it) from None
    return fn


def _values(nodes: list[A.Expr], depth: int) -> Callable[[Any], list]:
    """The evaluator's list of values of ``nodes`` (expression lists spliced in)."""
    fns = [_child(n, depth + 1) for n in nodes]
    single = len(fns) == 1

    def values(it: Any) -> list:
        out = []
        for f in fns:
            v = f(it)
            if isinstance(v, ExprList):
                out.extend(v.items)
            elif v is not NONE or single:
                out.append(v)
        return out
    return values


def arg_names(nodes: list[A.Expr]) -> list[str]:
    """The names of a call's argument expressions as commands see them (``ctx.argnames``: "_" for
    an argument that is not a name)."""
    return [n.id if isinstance(n, A.Name) else "_" for n in nodes]


def _call(node: A.Call, depth: int) -> Fn:
    """``name(args)`` calling a procedure or a command (not raw) inline, with the arguments'
    closures; other calls (raw commands, maps, indexed names) as the evaluator does."""
    name = node.func.id
    values = _values(node.args, depth)
    names = arg_names(node.args)
    real = _actual(node)

    def fn(it: Any) -> Any:
        var = it.lookup(name)
        if var is None:  # as the evaluator: a variable first, then a command
            cmd = it.registry.find(name, it.loaded_libs)
            if cmd is None or cmd.raw:
                return it._eval_node(real(it))
            try:
                return it.invoke_command(cmd, values(it), names)
            except SIGNALS:
                raise
            except Exception as e:
                raise _locate(e, node, it) from None
        if type(var.value) is not Proc:
            return it._eval_node(real(it))
        try:
            return it.call_proc(var.value, values(it), node)
        except SIGNALS:
            raise
        except Exception as e:
            raise _locate(e, node, it) from None
    return fn


# ---------------------------------------------------------------- statements
def _stmt(s: A.Stmt) -> Fn:
    kind = type(s)
    if kind is A.Assign and len(s.targets) == 1 and len(s.values) == 1 and type(s.targets[0]) is A.Name:
        return _assign(s)
    if (kind is A.Assign and len(s.targets) == 1 and len(s.values) == 1 and type(s.targets[0]) is A.Index
            and type(s.targets[0].base) is A.Name and 1 <= len(s.targets[0].indices) <= 2):
        return _assign_entry(s)
    if kind is A.IncDec and type(s.target) is A.Name and not s.ignored:
        return _incdec(s)
    if kind is A.If:
        return _if(s)
    if kind is A.For:
        return _for(s)
    if kind is A.While:
        return _while(s)
    if kind is A.Return and s.values:
        return _return(s)
    if kind is A.Block:
        body = s.body
        return lambda it: _run(it, body)
    if id(s) in _HOLDERS:
        real = _actual(s)
        return lambda it: it._exec[kind](real(it))
    return lambda it: it._exec[kind](s)


def _run(it: Any, body: list[A.Stmt]) -> None:
    run = it.exec_stmt
    for stmt in body:
        run(stmt)


def _assign(s: A.Assign) -> Fn:
    """``name = value;``: ints, polys and strings into variables of their type inline."""
    target = s.targets[0]
    name = target.id
    vf = expr_fn(s.values[0])

    def inner(it: Any) -> None:
        v = vf(it)
        tv = type(v)
        if tv is int:
            var = it.lookup(name)
            if var is not None and var.type == "int":
                var.value = v
                return
        elif tv is Poly:
            var = it.lookup(name)
            ring = it.ring
            if var is not None and var.type == "poly" and ring is not None and v.ring is ring.poly:
                var.value = v
                return
        elif tv is str:
            var = it.lookup(name)
            if var is not None and var.type == "string":
                var.value = v
                return
        elif isinstance(v, ExprList):  # as the evaluator's list of values: one item is that item
            items = list(v.items)
            v = items[0] if len(items) == 1 else ExprList(items)
        it.assign(target, v)
    return inner


def _assign_entry(s: A.Assign) -> Fn:
    """``name[i] = value;`` and ``name[i,j] = value;``: an int into an intvec, a poly of the
    basering into an ideal or a matrix inline; other entries by the interpreter's ``_set_in`` (the
    value first, then the indices, as the evaluator)."""
    target = s.targets[0]
    name = target.base.id
    vf = expr_fn(s.values[0])
    kfs = [expr_fn(i) for i in target.indices]
    real = _actual(target)

    def inner(it: Any) -> None:
        v = vf(it)
        if isinstance(v, ExprList):  # as the evaluator's list of values: one item is that item
            items = list(v.items)
            v = items[0] if len(items) == 1 else ExprList(items)
        var = it.lookup(name)
        if var is None:
            it.assign(real(it), v)
            return
        c = var.value
        idx = [f(it) for f in kfs]
        tc, tv = type(c), type(v)
        if len(idx) == 1:
            k = idx[0]
            if type(k) is int and k >= 1:
                if tc is IntVec and tv is int:
                    vals = list(c.values)
                    if k > len(vals):
                        vals += [0] * (k - len(vals))
                    vals[k - 1] = v
                    var.value = IntVec(vals)
                    return
                ring = it.ring
                if tc is Ideal and tv is Poly and ring is not None and v.ring is ring.poly:
                    gens = list(c.gens)
                    if k > len(gens):
                        gens += [c.ring.zero()] * (k - len(gens))
                    gens[k - 1] = v
                    var.value = Ideal(c.ring, gens)
                    return
        elif tc is Matrix and tv is Poly and v.ring is c.ring:
            i, j = idx
            if type(i) is int and type(j) is int and 1 <= i <= c.nrows and 1 <= j <= c.ncols:
                ents = list(c.entries)
                ents[(i - 1) * c.ncols + j - 1] = v
                var.value = Matrix(c.ring, c.nrows, c.ncols, ents)
                return
        it._rebind(var, it._set_in(c, [real(it)], 0, v, idx))
    return inner


def _return(s: A.Return) -> Fn:
    values = _values(s.values, 0)

    def inner(it: Any) -> None:
        if len(it.frames) == 1:
            raise MechRuntimeError("return outside a procedure")
        vals = values(it)
        raise ReturnSignal(NONE if not vals else vals[0] if len(vals) == 1 else ExprList(vals))
    return inner


def _incdec(s: A.IncDec) -> Fn:
    name, delta = s.target.id, s.delta

    def inner(it: Any) -> None:
        var = it.lookup(name)
        if var is not None and type(var.value) is int:
            var.value += delta
            return
        it._exec_incdec(s)
    return inner


def _cond(node: A.Expr) -> Callable[[Any], bool]:
    f = expr_fn(node)
    truth = ops.truth

    def cond(it: Any) -> bool:
        v = f(it)
        return v != 0 if type(v) is int else truth(v)
    return cond


def _if(s: A.If) -> Fn:
    cond, then, orelse = _cond(s.cond), s.then, s.orelse

    def inner(it: Any) -> None:
        if cond(it):
            _run(it, then)
        elif orelse is not None:
            _run(it, orelse)
    return inner


def _for(s: A.For) -> Fn:
    return _loop(s.init, _cond(s.cond) if s.cond is not None else (lambda it: True), s.step, s.body)


def _while(s: A.While) -> Fn:
    return _loop(None, _cond(s.cond), None, s.body)


def _loop(init: Any, cond: Callable[[Any], bool], step: Any, body: list) -> Fn:
    """``for``/``while``: as in Singular, ``continue`` skips the step and goes on with the condition."""
    def inner(it: Any) -> None:
        run = it.exec_stmt
        if init is not None:
            run(init)
        while cond(it):
            try:
                for stmt in body:
                    run(stmt)
            except BreakSignal:
                break
            except ContinueSignal:
                continue
            if step is not None:
                run(step)
    return inner

