"""The expression evaluator: operators, ranges, indexing, calls of procedures, maps and commands."""
from __future__ import annotations

from typing import Any

from ..kernel import Poly
from . import ast as A
from . import ops
from .boundary import convert_exception
from .compiled import INT_OPS, arg_names, expr_fn
from .errors import MechError, MechRuntimeError, MechTypeError
from .machine_int import MAX64, MIN64, int_binary
from .limits import LimitExceeded, limit_error
from .signals import SIGNALS
from .intmat import IntMat
from .values import NONE, ExprList, Ideal, IntVec, LibCommand, List, Map, Matrix, Proc, to_int, typeof
from .values_modules import Module, Vector


class Expressions:
    """Evaluating expressions (part of the interpreter)."""

    #: whether nodes run as closures made once (:mod:`~mech.dsl.compiled`, Singular's semantics
    #: inline, also Singular's int operators in the evaluator); a dialect with other semantics for
    #: the shared nodes sets it False
    compiled = True

    def eval(self, node: A.Expr) -> Any:
        """The value of ``node``; errors without a position get the node's."""
        if self.compiled:
            fn = getattr(node, "_fn", None)
            if fn is not None:
                return fn(self)
            if node.__dict__.get("_seen"):  # compiled when it runs again (loops, procedures)
                return expr_fn(node)(self)
            node._seen = True
        return self._eval_node(node)

    def _eval_node(self, node: A.Expr) -> Any:
        """``eval`` by the node's type, without a closure."""
        try:
            return self._eval[type(node)](node)
        except SIGNALS:
            raise
        except MechError as e:
            if e.pos is None:
                e.locate(node.pos, self.source, isinstance(node, (A.Call, A.TypeCall, A.BinOp, A.Index)))
            raise
        except Exception as e:
            raise convert_exception(e).locate(node.pos, self.source,
                                              isinstance(node, (A.Call, A.TypeCall, A.BinOp))) from None

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

    def _eval_backquote(self, node: A.Backquote) -> Any:
        """`` `s` ``: the variable (or ring variable) named by the string ``s``, as Singular."""
        name = self.eval(node.expr)
        if type(name) is not str:
            raise MechTypeError(f"`...` needs a string expression, not {typeof(name)}")
        var = self.lookup(name)
        if var is not None:
            return var.value
        if self.ring is not None and self.ring.var_index(name) is not None:
            return self.ring.poly.gen(self.ring.var_index(name))
        raise MechRuntimeError(f"`{name}` is undefined")

    def _eval_tuple(self, node: A.Tuple) -> Any:
        return ExprList(self._values(node.items))

    def _eval_binop(self, node: A.BinOp) -> Any:
        op = node.op
        if op == "&&":
            return int(ops.truth(self.eval(node.left)) and ops.truth(self.eval(node.right)))
        if op == "||":
            return int(ops.truth(self.eval(node.left)) or ops.truth(self.eval(node.right)))
        if type(node.left) is not A.BinOp:  # the common case: one operator
            a, b = self.eval(node.left), self.eval(node.right)
            if type(a) is int and type(b) is int and op in INT_OPS and self.compiled:
                return self._int_op(op, a, b)
            return self._binary(op, a, b)
        spine = [node]  # a long sum x+y+...+z nests to the left: evaluate its left spine by a loop
        while type(spine[-1].left) is A.BinOp and spine[-1].left.op not in ("&&", "||"):
            spine.append(spine[-1].left)
        a = self.eval(spine[-1].left)
        for n in reversed(spine[1:]):
            b = self.eval(n.right)
            if type(a) is int and type(b) is int and n.op in INT_OPS and self.compiled:
                a = self._int_op(n.op, a, b)
                continue
            try:
                a = self._binary(n.op, a, b)
            except MechError as e:
                if e.pos is None:
                    e.locate(n.pos, self.source, True)
                raise
            except Exception as e:
                raise convert_exception(e).locate(n.pos, self.source, True) from None
        b = self.eval(node.right)
        if type(a) is int and type(b) is int and op in INT_OPS and self.compiled:
            return self._int_op(op, a, b)
        return self._binary(op, a, b)

    def _int_op(self, op: str, a: int, b: int) -> int:
        r = INT_OPS[op](a, b)
        return r if MIN64 <= r <= MAX64 else self._binary(op, a, b)  # beyond 64 bits: Singular's wrap-around

    def _binary(self, op: str, a: Any, b: Any) -> Any:
        ring = self.ring.poly if self.ring else None
        if op in ("==", "!=", "<", "<=", ">", ">="):
            return ops.compare(op, a, b, ring)
        if type(a) is int and type(b) is int:
            r = int_binary(op, a, b, self.warn)
            if r is not None:
                return r
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
        return self._index_value(base, [self.eval(i) for i in node.indices])

    def _index_value(self, base: Any, idx: list[Any]) -> Any:
        """``base[idx...]`` for evaluated indices."""
        if isinstance(base, Matrix) and len(idx) == 2 and (isinstance(idx[0], IntVec) or isinstance(idx[1], IntVec)):
            rows = idx[0].values if isinstance(idx[0], IntVec) else [to_int(idx[0])]
            cols = idx[1].values if isinstance(idx[1], IntVec) else [to_int(idx[1])]
            for i in rows:
                for j in cols:
                    if not (1 <= i <= base.nrows and 1 <= j <= base.ncols):
                        raise MechRuntimeError(f"index [{i},{j}] out of range for a {base.nrows} x {base.ncols} matrix")
            return ExprList([base.get(i, j) for i in rows for j in cols])
        if isinstance(base, Matrix) and len(idx) == 2:
            i, j = to_int(idx[0]), to_int(idx[1])
            if not (1 <= i <= base.nrows and 1 <= j <= base.ncols):
                raise MechRuntimeError(f"index [{i},{j}] out of range for a {base.nrows} x {base.ncols} matrix")
            return base.get(i, j)
        if isinstance(base, IntMat) and len(idx) == 2:
            rows = idx[0].values if isinstance(idx[0], IntVec) else [to_int(idx[0])]
            cols = idx[1].values if isinstance(idx[1], IntVec) else [to_int(idx[1])]
            got = [base.get(i, j) for i in rows for j in cols]
            return got[0] if len(got) == 1 else ExprList(got)
        if isinstance(base, str) and len(idx) == 2:
            return _substring(base, to_int(idx[0]), to_int(idx[1]))
        if len(idx) != 1:
            raise MechRuntimeError(f"a {typeof(base)} takes one index")
        k = idx[0]
        if isinstance(k, IntVec) and isinstance(base, Poly):  # Singular: the sum of those terms
            return sum((self._item(base, i) for i in k.values), base.ring.zero())
        if isinstance(k, IntVec) and isinstance(base, Vector):  # Singular: the vector of those components
            keep = set(k.values)
            return Vector(base.ring, [p if i in keep else base.ring.zero() for i, p in enumerate(base.entries, 1)])
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
        elif isinstance(base, str):  # as Singular: a character out of range is the empty string
            return base[i - 1] if 1 <= i <= len(base) else ""
        elif isinstance(base, Map):
            seq, what = base.images, "map"
        elif isinstance(base, Poly):
            seq, what = [base.ring.monomial(e, c) for e, c in base.sorted_terms()], "poly"
            if 1 <= i <= len(seq):
                return seq[i - 1]
            if i > len(seq) or i < 1:
                return base.ring.zero()
        elif isinstance(base, Vector):
            return base.get(i)
        elif isinstance(base, Module):
            seq, what = base.gens, "module"
        elif isinstance(base, Matrix):  # as Singular: M[i] is the i-th column, a vector
            if not 1 <= i <= base.ncols:
                raise MechRuntimeError(f"index {i} out of range (the matrix has {base.ncols} columns)")
            return Vector(base.ring, [base.get(r, i) for r in range(1, base.nrows + 1)])
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
                if isinstance(v, LibCommand):
                    return self.call_command(v.command, node.args)
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

    def _eval_typecall(self, node: A.TypeCall) -> Any:
        cmd = self.registry.find(node.type, self.loaded_libs)
        if cmd is None:
            raise MechTypeError(f"type '{node.type}' is not supported yet")
        return self.call_command(cmd, node.args)

    def call_command(self, cmd: Any, arg_nodes: list[A.Expr]) -> Any:
        if not cmd.raw:
            return self.invoke_command(cmd, self._values(arg_nodes), arg_names(arg_nodes))
        saved = self.argnames
        try:
            return self.registry.invoke_raw(cmd, self, arg_nodes)
        except (LimitExceeded, MemoryError) as e:  # "time limit of 5 s exceeded in std"
            raise limit_error(e, cmd.name) from None
        finally:
            self.argnames = saved

    def invoke_command(self, cmd: Any, args: list[Any], argnames: list[str]) -> Any:
        """A command (not raw) on evaluated arguments; ``argnames``: their names (:func:`arg_names`)."""
        saved = self.argnames
        self.argnames = argnames
        try:
            return self.registry.invoke(cmd, self, args)
        except (LimitExceeded, MemoryError) as e:
            raise limit_error(e, cmd.name) from None
        finally:
            self.argnames = saved


def _substring(s: str, start: int, length: int) -> str:
    """Singular's ``s[start, length]``: ``length`` characters from position ``start`` (1-based), padded
    with blanks past the end of s."""
    if start < 1 or start > len(s) or length < 0:
        raise MechRuntimeError(f"index [{start},{length}] out of range for a string of length {len(s)}")
    return s[start - 1:start - 1 + length].ljust(length)
