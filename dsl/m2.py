"""The Macaulay2 dialect's interpreter: mech's interpreter with Macaulay2's name rules (global
variables of any type; assigning a ring makes its variables visible, as Macaulay2's ``use``), its
rings and monomial orders (``QQ[x,y, MonomialOrder => Lex]``), its commands (registered with
``dialect="m2"``, e.g. by ``stdlib/m2.py``), its operators (``I : J``, ``f % I`` and ``==`` on
ideals, registered by the same library with :func:`mech.dsl.registry.operator`) and its output
(``m2_printing.py``: ``o1 = ...`` for statements not ending in ``;``).  The tree and the parser
are :mod:`mech.dsl.m2_ast` and :mod:`mech.dsl.m2_parser`.
"""
from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from typing import Any, Optional

from . import ast as A
from . import ops
from .errors import MechError, MechNameError, MechRuntimeError, MechSyntaxError, MechTypeError, Source
from .interpreter import Interpreter
from .m2_ast import (BreakExpr, Coeffs, ForLoop, Function, IfExpr, Length, ListLit, Option, ReturnExpr, RingCons,
                     Seq, SetVar, Statement, Subscript, WhileLoop)
from .m2_orders import order_blocks
from .m2_parser import is_complete, parse
from .m2_printing import Opt, Symbol, to_string
from .rings import make_ring
from .scopes import Frame, Var
from .signals import BreakSignal, ReturnSignal
from .values import NONE, ExprList, Ideal, List, Matrix, Number, OrderBlock, Ring, to_int, typeof

__all__ = ["M2Interpreter", "M2Function", "CommandRef", "parse", "run_m2_repl"]



#: Macaulay2 symbols mech knows (option names and monomial orders)
SYMBOLS = {"MonomialOrder", "Lex", "GRevLex", "GLex", "RevLex", "Weights", "Eliminate", "Global", "Degrees",
           "Variables"}


@dataclass(eq=False)
class M2Function:
    """A function ``(a, b) -> body``, named after the variable it was first assigned to."""
    params: list[str]
    body: A.Expr
    source: Source
    captured: dict  # the enclosing function's variables when this one was made
    name: str = "-*Function*-"


@dataclass(eq=False)
class CommandRef:
    """A command used as a value (``apply(L, dim)``)."""
    command: Any

    @property
    def name(self) -> str:
        return self.command.name


class M2Interpreter(Interpreter):
    """mech's interpreter reading the Macaulay2 dialect: same values, kernel and evaluation of the
    shared nodes; Macaulay2's variables (global, untyped), commands, operators and output."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.commands = self.registry.DIALECTS.get("m2", {})
        self.operators = self.registry.OPERATORS.get("m2", {})
        self.count = 0  # the number N of the statement, as Macaulay2's oN
        self._exec[Statement] = self._exec_statement
        self._eval.update({
            Coeffs: lambda n: n, ListLit: self._eval_list, RingCons: self._eval_ring, Option: self._eval_option,
            Subscript: self._eval_subscript, Length: self._eval_length, SetVar: self._eval_set,
            Function: self._eval_function, Seq: self._eval_seq,
            ForLoop: self._eval_for, WhileLoop: self._eval_while, IfExpr: self._eval_if,
            ReturnExpr: self._eval_return, BreakExpr: self._eval_break,
        })

    #: the REPL numbers inputs (``i3 :`` and its ``o3 = ...``), scripts their statements
    numbers_inputs = False

    def execute(self, text: str, name: str = "<string>") -> None:
        source = Source(name, text)
        if self.numbers_inputs:
            self.count += 1
        self.run(parse(text, source), source)

    def _exec_statement(self, s: Statement) -> None:
        if not self.numbers_inputs:
            self.count += 1
        v = self.eval(s.expr)
        if not s.silent and v is not NONE:
            self.last = v
            blank = "\n" if self.numbers_inputs else ""  # the shell sets outputs off as Macaulay2 does
            text = f"{blank}o{self.count} = {to_string(v)}\n"
            rich = {}
            if "display" in self.settings:  # a notebook: LaTeX beside the text, when the value has it
                from .latex import bundle
                rich = bundle([v], text)
            if len(rich) > 1:
                self.display(rich)
            else:
                self.write(text)

    def basering(self) -> Ring:
        if self.ring is None:
            raise MechRuntimeError("no ring active: define one first, e.g. R = QQ[x,y,z]")
        return self.ring

    # ------------------------------------------------------------ names
    def lookup(self, name: str) -> Optional[Var]:
        frame = self.frames[-1]
        if frame.level and name in frame.vars:
            return frame.vars[name]
        return self.globals.get(name)

    def set_var(self, name: str, value: Any) -> None:
        """``name = value``: a local of the running function if it has one, else a global."""
        if isinstance(value, Ring):
            if not value.name:
                value.name = name
            self.ring = value
        elif isinstance(value, M2Function) and value.name == "-*Function*-":
            value.name = name
        frame = self.frames[-1]
        table = frame.vars if frame.level and name in frame.vars else self.globals
        var = table.get(name)
        if var is None:
            table[name] = Var(name, "def", value, None, frame.level if table is frame.vars else 0)
        else:
            var.value = value

    def declare(self, name: str, typ: str, value: Any) -> Var:
        """A variable set from Python (``session[name] = value``): Macaulay2's variables are untyped."""
        self.set_var(name, value)
        return self.lookup(name)

    def _eval_name(self, node: A.Name) -> Any:
        name = node.id
        var = self.lookup(name)
        if var is not None:
            return var.value
        ring = self.ring
        if ring is not None and ring.var_index(name) is not None:
            return ring.poly.gen(ring.var_index(name))
        if name in ("true", "false"):
            return name == "true"
        if name == "null":
            return NONE
        if name in SYMBOLS:
            return Symbol(name)
        if name in self.commands:
            return CommandRef(self.commands[name])
        raise MechNameError(f"unknown identifier '{name}'" + ("" if ring else " (no ring is active)"))

    def _eval_set(self, node: SetVar) -> Any:
        value = self.eval(node.value)
        if isinstance(node.target, Subscript):
            raise MechRuntimeError("cannot assign to an entry: Macaulay2's lists are immutable")
        self.set_var(node.target.id, value)
        return value

    def _eval_subscript(self, node: Subscript) -> Any:
        base = node.base
        if isinstance(base, A.Name) and self.lookup(base.id) is None:
            i = self.eval(node.index)
            name = f"{base.id}_{to_string(i)}"
            if self.ring is not None and self.ring.var_index(name) is not None:
                return self.ring.poly.gen(self.ring.var_index(name))
            raise MechNameError(f"unknown identifier '{name}'")
        return self._entry(self.eval(base), self.eval(node.index))

    def _eval_index(self, node: A.Index) -> Any:
        return self._entry(self.eval(node.base), self.eval(node.indices[0]))

    def _entry(self, base: Any, k: Any) -> Any:
        """``base_k`` (``base#k``): entries counted from 0, negative ones from the end."""
        if type(base) is int and isinstance(k, Ring):  # 0_R: the number in the ring R
            return k.poly.const(k.poly.field(base))
        if isinstance(base, Ring):
            seq, what = [base.poly.gen(i) for i in range(len(base.names))], "ring's variables"
        elif isinstance(base, Ideal):
            seq, what = base.gens, "ideal's generators"
        elif isinstance(base, (List, ExprList)):
            seq, what = base.items, "list"
        elif isinstance(base, Matrix) and isinstance(k, ExprList) and len(k.items) == 2:
            i, j = (to_int(x) for x in k.items)
            if not (0 <= i < base.nrows and 0 <= j < base.ncols):
                raise MechRuntimeError(f"index ({i},{j}) out of range for a {base.nrows} x {base.ncols} matrix")
            return base.get(i + 1, j + 1)
        elif isinstance(base, str):
            seq, what = base, "string"
        else:
            raise MechTypeError(f"a {typeof(base)} cannot be indexed")
        i = to_int(k)
        if not -len(seq) <= i < len(seq):
            raise MechRuntimeError(f"index {i} out of range (the {what} has {len(seq)} entries, counted from 0)")
        return seq[i]

    def _eval_length(self, node: Length) -> int:
        v = self.eval(node.operand)
        if isinstance(v, (List, ExprList)):
            return len(v.items)
        if isinstance(v, str):
            return len(v)
        raise MechTypeError(f"# needs a list, sequence or string, not a {typeof(v)}")

    # ------------------------------------------------------------ values
    def _values(self, nodes: list[A.Expr]) -> list[Any]:
        """Arguments evaluated one by one (a sequence stays one value, as in Macaulay2)."""
        return [self.eval(n) for n in nodes]

    def _eval_list(self, node: ListLit) -> List:
        return List(self._values(node.items))

    def _eval_option(self, node: Option) -> Opt:
        return Opt(self.eval(node.key), self.eval(node.value))

    def _eval_range(self, node: A.Range) -> ExprList:
        lo, hi = to_int(self.eval(node.lo)), to_int(self.eval(node.hi))
        return ExprList(list(range(lo, hi + 1)))

    def _eval_tuple(self, node: A.Tuple) -> Any:
        return ExprList(self._values(node.items)) if node.items else NONE

    def _eval_function(self, node: Function) -> M2Function:
        frame = self.frames[-1]
        return M2Function(node.params, node.body, self.source, dict(frame.vars) if frame.level else {})

    def _eval_seq(self, node: Seq) -> Any:
        v: Any = NONE
        for e in node.exprs:
            v = self.eval(e)
        return NONE if node.silent else v

    def _eval_ring(self, node: RingCons) -> Ring:
        base = self.eval(node.base)
        if not isinstance(base, Coeffs):
            raise MechTypeError(f"a polynomial ring is built over QQ or ZZ/p, not over a {typeof(base)}")
        names: list[str] = []
        options: dict[str, Any] = {}
        for item in node.items:
            if isinstance(item, Option):
                key = item.key.id if isinstance(item.key, A.Name) else ""
                if key not in ("MonomialOrder", "Global"):
                    raise MechRuntimeError(f"unknown ring option '{key}' (known: MonomialOrder, Global)")
                options[key] = self.eval(item.value)
            else:
                names.extend(self._variable_names(item))
        if not names or len(set(names)) != len(names):
            raise MechRuntimeError("a ring needs distinct variables: QQ[x,y,z]")
        blocks = order_blocks(options.get("MonomialOrder", Symbol("GRevLex")), len(names))
        ring = make_ring(base.characteristic, (), names, blocks + [OrderBlock("C")])
        if options.get("Global", True) is not ring.poly.order.is_global:
            want = "global" if options.get("Global", True) else "local"
            raise MechRuntimeError(f"the monomial order is not {want} (Global => "
                                   f"{to_string(options.get('Global', True))})")
        return ring

    def _variable_names(self, node: A.Expr) -> list[str]:
        if isinstance(node, A.Name):
            return [node.id]
        if isinstance(node, Subscript) and isinstance(node.base, A.Name):
            return [f"{node.base.id}_{to_int(self.eval(node.index))}"]
        if isinstance(node, A.Range):
            lo, hi = self._variable_names(node.lo), self._variable_names(node.hi)
            a, _, i = lo[0].rpartition("_")
            b, _, j = hi[0].rpartition("_")
            if a and a == b and i.isdigit() and j.isdigit():
                return [f"{a}_{k}" for k in range(int(i), int(j) + 1)]
            x, y = lo[0], hi[0]
            if len(x) == 1 and len(y) == 1 and x <= y:
                return [chr(c) for c in range(ord(x), ord(y) + 1)]
        raise MechSyntaxError("a ring variable is a name, x_i or a range x_1..x_n", node.pos)

    # ------------------------------------------------------------ control
    def _eval_for(self, node: ForLoop) -> Any:
        if node.items is not None:
            seq = self.eval(node.items)
            if not isinstance(seq, (List, ExprList)):
                raise MechTypeError(f"for ... in needs a list, not a {typeof(seq)}")
            values: Any = list(seq.items)
        else:
            start = to_int(self.eval(node.start)) if node.start is not None else 0
            if node.stop is None:
                raise MechRuntimeError("for i from a to b: the upper bound is missing")
            values = range(start, to_int(self.eval(node.stop)) + 1)
        out = []
        for x in values:
            self.set_var(node.var, x)
            try:
                v = self.eval(node.body)
            except BreakSignal:
                break
            if node.collect:
                out.append(v)
        return List(out) if node.collect else NONE

    def _eval_while(self, node: WhileLoop) -> Any:
        while self._truth(self.eval(node.cond)):
            try:
                self.eval(node.body)
            except BreakSignal:
                break
        return NONE

    def _eval_if(self, node: IfExpr) -> Any:
        if self._truth(self.eval(node.cond)):
            return self.eval(node.then)
        return self.eval(node.orelse) if node.orelse is not None else NONE

    def _truth(self, v: Any) -> bool:
        if not isinstance(v, bool):
            raise MechTypeError(f"a condition is true or false, not a {typeof(v)}")
        return v

    def _eval_return(self, node: ReturnExpr) -> Any:
        raise ReturnSignal(self.eval(node.value) if node.value is not None else NONE)

    def _eval_break(self, node: BreakExpr) -> Any:
        raise BreakSignal()

    # ------------------------------------------------------------ calls and operators
    def _eval_call(self, node: A.Call) -> Any:
        f = node.func
        if isinstance(f, A.Name) and self.lookup(f.id) is None and f.id in self.commands:
            return self.call_command(self.commands[f.id], node.args)
        v = self.eval(f)
        if isinstance(v, CommandRef):
            return self.call_command(v.command, node.args)
        if isinstance(v, M2Function):
            return self.call_function(v, self._values(node.args), node)
        if v == Symbol("Eliminate") and len(node.args) == 1:
            return Opt(v, self.eval(node.args[0]))
        raise MechTypeError(f"a {typeof(v)} cannot be applied to arguments")

    def call_command(self, cmd: Any, arg_nodes: list[A.Expr]) -> Any:
        """A command applied to a sequence it takes as one argument (``toString (1,2)``) gets it whole."""
        if len(arg_nodes) > 1 and all(len(ov.names) == 1 and not ov.has_varargs for ov in cmd.overloads):
            arg_nodes = [A.Tuple(arg_nodes, pos=arg_nodes[0].pos)]
        v = super().call_command(cmd, arg_nodes)
        if cmd.overloads[0].func.__annotations__.get("return") in ("bool", bool):
            return bool(v)  # the registry gives Singular's 0 and 1
        return v

    def call_function(self, fn: M2Function, args: list[Any], node: Optional[A.Expr] = None) -> Any:
        """Call a Macaulay2 function with evaluated arguments in a new scope."""
        if len(args) != len(fn.params):
            if len(fn.params) == 1:
                args = [ExprList(args)]
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

    def _binary(self, op: str, a: Any, b: Any) -> Any:
        hook = self.operators.get("==" if op == "!=" else op)  # the library's operators (I : J, f % I, I == J)
        if hook is not None:
            v = hook(a, b)
            if v is not NotImplemented:
                return not v if op == "!=" else v
        ring = self.ring.poly if self.ring else None
        if op == "/" and type(a) is int and type(b) is int:
            if b == 0:
                raise MechRuntimeError("division by 0")
            if ring is None:
                return Fraction(a, b)
            return Number(ring, ring.field(a) / ring.field(b))
        if Fraction in (type(a), type(b)) and {type(a), type(b)} <= {int, Fraction} and op in "+-*/^":
            return _rational(op, a, b)
        if op in "+*" and isinstance(a, Ideal) and isinstance(b, Ideal):  # generators as Macaulay2 lists them
            if a.ring is not b.ring:
                raise MechTypeError(f"the ideals of {op} are in different rings")
            gens = a.gens + b.gens if op == "+" else tuple(f * g for f in a.gens for g in b.gens)
            return Ideal(a.ring, gens)
        if op in ("<", "<=", ">", ">="):
            return bool(ops.compare(op, a, b, ring))
        if isinstance(a, bool) or isinstance(b, bool):
            raise MechTypeError(f"no operator {op} for true/false")
        return ops.binary(op, a, b, ring, self.warn_in_line)

    def _eval_binop(self, node: A.BinOp) -> Any:
        if node.op == "&&":
            return self._truth(self.eval(node.left)) and self._truth(self.eval(node.right))
        if node.op == "||":
            return self._truth(self.eval(node.left)) or self._truth(self.eval(node.right))
        return super()._eval_binop(node)

    def _eval_unop(self, node: A.UnOp) -> Any:
        if node.op == "!":
            return not self._truth(self.eval(node.operand))
        return super()._eval_unop(node)


def _rational(op: str, a: Fraction | int, b: Fraction | int) -> Fraction | int:
    """Arithmetic of rational numbers outside a ring (``1/2 + 1``); integral results are ints."""
    if op == "^" and type(b) is not int:
        raise MechTypeError("a rational number's exponent is an integer")
    if op == "/" and b == 0:
        raise MechRuntimeError("division by 0")
    v = {"+": lambda: a + b, "-": lambda: a - b, "*": lambda: a * b, "/": lambda: Fraction(a) / b,
         "^": lambda: Fraction(a) ** b}[op]()
    return int(v) if v.denominator == 1 else v


# ---------------------------------------------------------------- the interactive shell
def run_m2_repl(warnings: bool = True, read: Optional[Any] = None, out: Optional[Any] = None) -> int:
    """Macaulay2's prompt ``iN :`` with outputs ``oN = ...`` until end of input or ``exit``."""
    import sys
    out = out or sys.stdout
    read = read or input
    it = M2Interpreter(out=out, flush=True, warnings=warnings)
    it.numbers_inputs = True
    while True:
        prompt = f"\ni{it.count + 1} : "
        try:
            text = read(prompt)
            while not is_complete(text):
                text += "\n" + read(" " * len(prompt.strip("\n")))
        except EOFError:
            out.write("\n")
            return 0
        if text.strip() in ("exit", "quit", "end"):
            return 0
        if not text.strip():
            continue
        try:
            it.execute(text, "<stdin>")
        except MechError as e:
            it.unwind()
            out.write(e.format())
        except KeyboardInterrupt:
            it.unwind()
            out.write("interrupted\n")
