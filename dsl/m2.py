"""The Macaulay2 dialect's interpreter: mech's interpreter with Macaulay2's name rules (global
variables of any type; making or assigning a ring makes its variables visible, as Macaulay2's
``use``; names without a value are symbols), its rings (:mod:`mech.dsl.m2_rings`: ``QQ[x,y]``,
``ZZ/p[x]``, towers, ``R/I``), its commands (registered with ``dialect="m2"``, e.g. by
``stdlib/m2.py``), its operators (:mod:`mech.dsl.m2_ops`, and ``I : J``, ``f % I``, ``==`` on ideals
registered by the library with :func:`mech.dsl.registry.operator`) and its output (statements not
ending in ``;`` print ``oN = ...`` in the REPL and in ``echo`` mode; a script prints only what it
``print``s, as ``M2 --script``).  The tree and the parser are :mod:`mech.dsl.m2_ast` and
:mod:`mech.dsl.m2_parser`; control flow is :mod:`mech.dsl.m2_control`.
"""
from __future__ import annotations

from typing import Any, Optional

from . import ast as A
from . import ops
from .errors import MechError, MechNameError, MechRuntimeError, MechTypeError, Source
from .interpreter import Interpreter
from .limits import LimitExceeded, limit_error
from .m2_ast import (BreakExpr, Coeffs, Dot, ForLoop, Function, Generators, HashHas, IfExpr, Length, ListLit,
                     Option, ReturnExpr, RingCons, Seq, SetVar, Statement, Subscript, SymbolLit, TimeExpr, TryExpr,
                     WhileLoop)
from .m2_control import M2Control
from .m2_local import LocalFraction, local_ring, localized_at
from .m2_maps import apply_map
from .m2_modules import FreeModule, columns, with_default_degrees
from .m2_subquotients import ANY_MODULE, zero_element
from .m2_ops import SYMBOLS, lift_to, m2_binary
from .m2_parser import is_complete, parse
from .m2_printing import to_string
from .m2_ringcons import build_ring, variable_names
from .m2_rings import FractionField, M2Ring, is_integral, normal, owner
from .maps import map_value
from .m2_vectors import Vector, basis_vector
from .m2_values import (FUNCTIONS, QQ_RING, ZZ_RING, Array, CoeffRing, CommandRef, Composed, Factored, Iterator,
                        M2Function, M2Set, Monoid, Opt, Partial, RingMap, Symbol)
from .scopes import Var
from ..kernel import Poly
from .values import NONE, ExprList, Ideal, List, Matrix, Number, Ring, to_int, typeof

__all__ = ["M2Interpreter", "M2Function", "CommandRef", "parse", "run_m2_repl"]


class M2Interpreter(M2Control, Interpreter):
    """mech's interpreter reading the Macaulay2 dialect: same values, kernel and evaluation of the
    shared nodes; Macaulay2's variables (global, untyped), commands, operators and output."""

    compiled = False  # the shared nodes mean Macaulay2's operations here, not Singular's (dsl/compiled.py)

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.commands = self.registry.DIALECTS.get("m2", {})
        self.operators = self.registry.OPERATORS.get("m2", {})
        self.count = 0  # the number N of the statement, as Macaulay2's oN
        self.symbols: dict[str, Any] = {}  # the variables of the rings in use, by name
        self.m2_options: dict[str, Any] = {}  # the options Name => v of the command running
        self._exec[Statement] = self._exec_statement
        self._eval.update({
            Coeffs: lambda n: CoeffRing(n.characteristic, f"ZZ/{n.characteristic}"), ListLit: self._eval_list,
            RingCons: self._eval_ring, Option: self._eval_option, Subscript: self._eval_subscript,
            Length: self._eval_length, SetVar: self._eval_set, Function: self._eval_function, Seq: self._eval_seq,
            ForLoop: self._eval_for, WhileLoop: self._eval_while, IfExpr: self._eval_if, TryExpr: self._eval_try,
            TimeExpr: self._eval_time, ReturnExpr: self._eval_return, BreakExpr: self._eval_break,
            Generators: self._eval_generators, HashHas: self._eval_hash_has, Dot: self._eval_dot,
            SymbolLit: lambda n: Symbol(n.name),
        })

    #: the REPL numbers inputs (``i3 :`` and its ``o3 = ...``), scripts their statements
    numbers_inputs = False
    #: print ``oN = value`` for statements not ending in ``;`` (off: as ``M2 --script``)
    echo = True

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
            if not self.echo:
                return
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

    def use(self, ring: M2Ring) -> None:
        """Make ``ring`` current and its own variables the values of their names (a tower's
        coefficient variables keep their ring, whose elements promote)."""
        self.ring = ring
        for i, name in enumerate(ring.names[:len(ring.own) or None]):
            self.globals.pop(name, None)  # as Macaulay2: the name's value is now the variable
            self.symbols[name] = normal(ring.poly.gen(i))

    # ------------------------------------------------------------ names
    def lookup(self, name: str) -> Optional[Var]:
        frame = self.frames[-1]
        if frame.level and name in frame.vars:
            return frame.vars[name]
        return self.globals.get(name)

    def set_var(self, name: str, value: Any, local: bool = False) -> None:
        """``name = value``: a local of the running function if it has one (or ``local``: ``:=``), else a global."""
        if isinstance(value, Ring):
            if not value.name:
                value.name = name
            self.use(value)
        elif isinstance(value, (M2Function, Iterator)) and value.name == "-*Function*-":
            value.name = name
        elif isinstance(value, (Monoid, FractionField)) and not value.name:
            value.name = name
        elif isinstance(value, CoeffRing) and value.characteristic and not value.name.isidentifier():
            value.name = name
        frame = self.frames[-1]
        table = frame.vars if frame.level and (local or name in frame.vars) else self.globals
        var = table.get(name)
        if var is None:
            table[name] = Var(name, "def", value, None, frame.level if table is frame.vars else 0)
        else:
            var.value = value
        self.symbols.pop(name, None) if table is self.globals else None

    def declare(self, name: str, typ: str, value: Any) -> Var:
        """A variable set from Python (``session[name] = value``): Macaulay2's variables are untyped."""
        self.set_var(name, value)
        return self.lookup(name)

    def _eval_name(self, node: A.Name) -> Any:
        name = node.id
        var = self.lookup(name)
        if var is not None:
            return var.value
        if name in self.symbols:
            return self.symbols[name]
        if name in ("true", "false"):
            return name == "true"
        if name == "null":
            return NONE
        if name == "oo" and self.last is not NONE:  # the last value printed
            return self.last
        if name == "QQ":
            return QQ_RING
        if name == "ZZ":
            return ZZ_RING
        if name in self.commands and name not in SYMBOLS:
            return CommandRef(self.commands[name])
        return Symbol(name)

    def _eval_set(self, node: SetVar) -> Any:
        value = self.eval(node.value)
        target = node.target
        if isinstance(target, A.Tuple):
            items = value.items if isinstance(value, (ExprList, List)) else None
            if items is None or len(items) != len(target.items):
                raise MechRuntimeError(f"(a, b, ...) = v takes a sequence of {len(target.items)} values")
            for t, v in zip(target.items, items):
                if not isinstance(t, A.Name):
                    raise MechRuntimeError("(a, b, ...) = v assigns to names")
                self.set_var(t.id, v, node.local)
            return value
        if isinstance(target, Subscript):
            raise MechRuntimeError("cannot assign to an entry: Macaulay2's lists are immutable")
        self.set_var(target.id, value, node.local)
        return value

    def _eval_subscript(self, node: Subscript) -> Any:
        base = node.base
        if isinstance(base, A.Name) and self.lookup(base.id) is None and base.id not in self.symbols:
            i = self.eval(node.index)
            name = f"{base.id}_{to_string(i)}"
            if name in self.symbols:
                return self.symbols[name]
            if base.id in self.commands:
                cmd = self.commands[base.id]
                if any(getattr(ov.func, "subscript_value", False) for ov in cmd.overloads):  # id_M
                    return self.invoke(cmd, [i])
                return Partial(CommandRef(cmd), i)
            return Symbol(name)
        return self._entry(self.eval(base), self.eval(node.index))

    def _eval_index(self, node: A.Index) -> Any:
        return self._entry(self.eval(node.base), self.eval(node.indices[0]))

    def _entry(self, base: Any, k: Any) -> Any:
        """``base_k`` (``base#k``): entries counted from 0, negative ones from the end."""
        if type(base) is int and isinstance(k, Ring):  # 0_R: the number in the ring R
            return normal(k.poly.const(k.poly.field(base)))
        if type(base) is int and isinstance(k, CoeffRing):
            return base
        if isinstance(base, FUNCTIONS):
            return Partial(base, k)
        if isinstance(base, Poly) and isinstance(k, M2Ring) and _variable_name(base) in k.poly.names:  # x_R
            return normal(k.poly.gen(k.poly.names.index(_variable_name(base))))
        if base == 0 and type(base) is int and isinstance(k, ANY_MODULE):  # 0_M
            return zero_element(k)
        if isinstance(base, FreeModule):  # F_i: the i-th basis vector
            return basis_vector(base, to_int(k))
        if hasattr(base, "m2_entry"):  # C_i, C.dd_i of a resolution
            return base.m2_entry(to_int(k))
        if isinstance(k, List) and isinstance(base, Matrix):  # M_{j, ...}: columns
            return columns(base, [to_int(j) for j in k.items])
        if isinstance(k, (List, Array)) and not isinstance(base, Matrix):
            return List([self._entry(base, i) for i in k.items])
        if isinstance(base, M2Ring) and isinstance(k, Ideal):  # R_P: the local ring
            return local_ring(base, k)
        if isinstance(base, M2Ring):
            seq, what = [normal(base.poly.gen(i)) for i in range(len(base.own) or len(base.names))], "ring's variables"
        elif isinstance(base, Ideal):
            seq, what = base.gens, "ideal's generators"
        elif isinstance(base, (List, ExprList)):
            seq, what = base.items, "list"
        elif isinstance(base, Matrix) and isinstance(k, ExprList) and len(k.items) == 2:
            i, j = (to_int(x) for x in k.items)
            if not (-base.nrows <= i < base.nrows and -base.ncols <= j < base.ncols):
                raise MechRuntimeError(f"index ({i},{j}) out of range for a {base.nrows} x {base.ncols} matrix")
            return base.get(i % base.nrows + 1, j % base.ncols + 1)
        elif isinstance(base, str):
            seq, what = base, "string"
        else:
            raise MechTypeError(f"a {typeof(base)} cannot be indexed")
        i = to_int(k)
        if not -len(seq) <= i < len(seq):
            raise MechRuntimeError(f"index {i} out of range (the {what} has {len(seq)} entries, counted from 0)")
        return seq[i]

    def _eval_hash_has(self, node: HashHas) -> bool:
        try:
            self._entry(self.eval(node.base), self.eval(node.key))
        except MechError:
            return False
        return True

    def _eval_generators(self, node: Generators) -> List:
        v = self.eval(node.base)
        if isinstance(v, Ideal):
            return List(list(v.gens))
        if isinstance(v, Matrix):
            return List(list(v.entries))
        raise MechTypeError(f"I_* takes an ideal, not a {typeof(v)}")

    def _eval_dot(self, node: Dot) -> Any:
        fields = getattr(self.eval(node.base), "m2_fields", None)  # C.dd of a resolution
        if fields is not None and node.field in fields:
            v = fields[node.field]  # a matrix gets Macaulay2's default degrees (F.matrix)
            return with_default_degrees(v) if type(v) is Matrix else v
        raise MechRuntimeError(f"the operator . (fields such as .{node.field}) is not supported")

    def _eval_length(self, node: Length) -> int:
        v = self.eval(node.operand)
        if isinstance(v, (List, ExprList, M2Set)):
            return len(v.items)
        if isinstance(v, str):
            return len(v)
        if isinstance(v, Ideal):
            return len(v.gens)
        if isinstance(v, Factored):  # the factors, and the unit when it is printed
            return len(v.factors) + (v.unit != 1)
        raise MechTypeError(f"# needs a list, sequence or string, not a {typeof(v)}")

    # ------------------------------------------------------------ values
    def _values(self, nodes: list[A.Expr]) -> list[Any]:
        """Arguments evaluated one by one (a sequence stays one value, as in Macaulay2)."""
        return [self.eval(n) for n in nodes]

    def _eval_list(self, node: ListLit) -> List:
        return (Array if node.array else List)(self._values(node.items))

    def _eval_option(self, node: Option) -> Opt:
        return Opt(self.eval(node.key), self.eval(node.value))

    def _eval_range(self, node: A.Range) -> ExprList:
        lo, hi = self.eval(node.lo), self.eval(node.hi)
        if isinstance(lo, Symbol) and isinstance(hi, Symbol):
            from .m2_ringcons import _range
            return ExprList([Symbol(n) for n in _range(lo.name, hi.name, node)])
        if isinstance(lo, str) or isinstance(hi, str) or not (type(lo) is int and type(hi) is int):
            from .m2_ringcons import _range
            names = [to_string(lo), to_string(hi)]
            return ExprList([self.symbols.get(n, Symbol(n)) for n in _range(names[0], names[1], node)])
        return ExprList(list(range(lo, hi + 1)))

    def _eval_tuple(self, node: A.Tuple) -> Any:
        return ExprList(self._values(node.items)) if node.items else NONE

    def _eval_ring(self, node: RingCons) -> Any:
        base = self.eval(node.base)
        if isinstance(base, Poly):  # f[a, b]: the variables of f's ring replaced by a, b
            ring = owner(base)
            values = self._values(node.items)
            if ring is None or len(values) != ring.poly.nvars:
                raise MechRuntimeError("f[a, b, ...] takes one value per variable of f's ring")
            images = [lift_to(v, ring) if isinstance(v, (Poly, Number)) else normal(ring.poly.const(ring.poly.field(v)))
                      for v in values]
            return normal(map_value(base, images, ring.poly))
        if getattr(base, "name", None) == "monoid" and isinstance(base, (Symbol, CommandRef)):  # monoid[x, y]
            return Monoid(n for item in node.items for n in variable_names(item, self.eval, to_string))
        ring = build_ring(node, base, self.eval, to_string)
        self.use(ring)
        return ring

    # ------------------------------------------------------------ calls and operators
    def _eval_call(self, node: A.Call) -> Any:
        f = node.func
        if isinstance(f, A.Name) and self.lookup(f.id) is None and f.id in self.commands:
            return self.call_command(self.commands[f.id], node.args)
        v = self.eval(f)
        return self.apply_value(v, node.args, node)

    def apply_value(self, v: Any, arg_nodes: list[A.Expr], node: Optional[A.Expr] = None) -> Any:
        """``v args`` for a value ``v``: a command, a function, a ring (``R x``: x in R), ``Eliminate n``,
        ``ProductOrder {n1, n2}``."""
        if isinstance(v, CommandRef):
            return self.call_command(v.command, arg_nodes)
        if isinstance(v, M2Function):
            return self.call_function(v, self._values(arg_nodes), node)
        if isinstance(v, (Composed, Partial)):
            return self.apply(v, self._values(arg_nodes))
        if isinstance(v, RingMap):
            return apply_map(v, self._one_value(arg_nodes))
        if v in (Symbol("Eliminate"), Symbol("ProductOrder")) and len(arg_nodes) == 1:
            return Opt(v, self.eval(arg_nodes[0]))
        if isinstance(v, Symbol) and v.name not in SYMBOLS:
            raise MechNameError(f"unknown identifier '{v.name}'")
        raise MechTypeError(f"a {typeof(v)} cannot be applied to arguments")

    def _one_value(self, arg_nodes: list[A.Expr]) -> Any:
        vals = self._values(arg_nodes)
        return vals[0] if len(vals) == 1 else ExprList(vals)

    def eval_text(self, text: str) -> Any:
        """The value of one expression of the dialect given as text (``ideal "x^2,y"``, ``value s``)."""
        program = parse(text, Source("<string>", text))
        if len(program.body) != 1:
            raise MechRuntimeError(f"expected one expression, got {text!r}")
        return self.eval(program.body[0].expr)

    def apply(self, f: Any, args: list[Any]) -> Any:
        """A function value applied to evaluated arguments."""
        if isinstance(f, M2Function):
            return self.call_function(f, args)
        if isinstance(f, Composed):
            return self.apply(f.outer, [self.apply(f.inner, args)])
        if isinstance(f, Partial):
            return self.apply(f.func, [f.first, *args])
        if isinstance(f, CommandRef):
            return self.invoke(f.command, list(args))
        if isinstance(f, RingMap):
            return apply_map(f, args[0] if len(args) == 1 else ExprList(args))
        raise MechTypeError(f"a {typeof(f)} cannot be applied to arguments")

    def call_command(self, cmd: Any, arg_nodes: list[A.Expr]) -> Any:
        """A command applied to a sequence it takes as one argument (``toString (1,2)``) gets it whole."""
        plain = [n for n in arg_nodes if not isinstance(n, Option)]
        if len(plain) > 1 and all(len(ov.names) == 1 and not ov.has_varargs for ov in cmd.overloads):
            arg_nodes = [A.Tuple(plain, pos=plain[0].pos)] + [n for n in arg_nodes if isinstance(n, Option)]
        saved = self.argnames
        try:
            self.argnames = [n.id if isinstance(n, A.Name) else "_" for n in arg_nodes]
            return self.invoke(cmd, self._values(arg_nodes))
        finally:
            self.argnames = saved

    def invoke(self, cmd: Any, args: list[Any]) -> Any:
        """Run a command on evaluated arguments; commands not marked :func:`~mech.dsl.m2_rings.in_quotients`
        refuse elements of quotient rings (their answers would ignore the relations)."""
        args, self.m2_options = _options(cmd, args)
        if not getattr(cmd.overloads[0].func, "quotient_ok", False) and any(_in_quotient(a) for a in args):
            raise MechRuntimeError(f"{cmd.name} on elements of a quotient ring R/I is not supported by mech")
        if not any(getattr(ov.func, "zz_ok", False) for ov in cmd.overloads) and any(_over_zz(a) for a in args):
            raise MechRuntimeError(f"{cmd.name} on elements of a polynomial ring over ZZ is not supported by mech")
        if not any(getattr(ov.func, "group_ok", False) for ov in cmd.overloads) and any(_in_group(a) for a in args):
            raise MechRuntimeError(f"{cmd.name} on elements of a ring with invertible variables (GroupLex) is not supported by mech")
        if not any(getattr(ov.func, "local_ok", False) for ov in cmd.overloads) and any(_in_local(a) for a in args):
            raise MechRuntimeError(f"{cmd.name} on elements of a local ring R_P is not supported by mech")
        try:
            v = self.registry.invoke(cmd, self, list(args))
        except (LimitExceeded, MemoryError) as e:
            raise limit_error(e, cmd.name) from None
        func = cmd.overloads[0].func
        if hasattr(func, "m2_result"):  # the command's own value from the registry's (a bool or an index)
            return func.m2_result(args, v)
        if func.__annotations__.get("return") in ("bool", bool):
            return bool(v)  # the registry gives Singular's 0 and 1
        return v

    def _binary(self, op: str, a: Any, b: Any) -> Any:
        hook = self.operators.get("==" if op == "!=" else op)  # the library's operators (I : J, f % I, I == J)
        if hook is not None:
            v = hook(a, b)
            if v is not NotImplemented:
                return not v if op == "!=" else v
        return m2_binary(op, a, b, self.ring, self.apply, self._arith)

    def _arith(self, op: str, a: Any, b: Any, ring: Any) -> Any:
        if op in ("+", "*") and isinstance(a, Ideal) and isinstance(b, Ideal):  # generators as Macaulay2 lists them
            if a.ring is not b.ring:
                raise MechTypeError(f"the ideals of {op} are in different rings")
            gens = a.gens + b.gens if op == "+" else tuple(normal(f * g) for f in a.gens for g in b.gens)
            return Ideal(a.ring, [g for g in gens if not g.is_zero()] if op == "*" else gens)
        if op in ("<", "<=", ">", ">="):
            return bool(ops.compare(op, a, b, ring))
        if op in ("==", "!=") and isinstance(a, (List, ExprList)) and isinstance(b, (List, ExprList)):
            same = len(a.items) == len(b.items) and all(self._binary("==", x, y) for x, y in zip(a.items, b.items))
            return same if op == "==" else not same
        if op in ("==", "!="):
            return bool(ops.compare(op, a, b, ring))
        if isinstance(a, bool) or isinstance(b, bool):
            raise MechTypeError(f"no operator {op} for true/false")
        return ops.binary(op, a, b, ring, self.warn_in_line)

    def _eval_binop(self, node: A.BinOp) -> Any:
        if node.op == "&&":
            return self._truth(self.eval(node.left)) and self._truth(self.eval(node.right))
        if node.op == "or":
            return self._truth(self.eval(node.left)) or self._truth(self.eval(node.right))
        if node.op == "||":  # Macaulay2's || joins matrices (and lists) one above the other
            return self._binary("||", self.eval(node.left), self.eval(node.right))
        return super()._eval_binop(node)

    def _eval_unop(self, node: A.UnOp) -> Any:
        if node.op == "!":
            return not self._truth(self.eval(node.operand))
        v = self.eval(node.operand)
        if node.op == "-" and isinstance(v, Symbol) and v.name not in SYMBOLS:
            raise MechNameError(f"unknown identifier '{v.name}'")
        return v if node.op == "+" else -v if isinstance(v, Vector) else ops.negate(v)


#: options of Macaulay2's functions that do not change the value (how it is computed, what is printed)
NEUTRAL_OPTIONS = {"Verbosity", "Verbose", "Strategy", "MinimalGenerators", "SeparateExponents", "Check", "Unmixed",
                   "CompleteIntersection"}



def _variable_name(p: Poly) -> str | None:
    """The name of the variable p is (None when p is not a variable)."""
    if len(p.terms) != 1:
        return None
    (e, c), = p.terms.items()
    if c != 1 or sum(e) != 1:
        return None
    return p.ring.names[e.index(1)]


def _options(cmd: Any, args: list[Any]) -> tuple[list[Any], dict[str, Any]]:
    """The arguments without their options ``Name => v``, and the options the command reads
    (``m2_options`` of its function); options changing the value that it does not read are refused."""
    if not any(isinstance(a, Opt) for a in args):
        return args, {}
    read = set()
    for ov in cmd.overloads:
        read |= set(getattr(ov.func, "m2_options", ()))
    given: dict[str, Any] = {}
    for a in args:
        if isinstance(a, Opt):
            key = a.key.name if isinstance(a.key, Symbol) else a.key if isinstance(a.key, str) else to_string(a.key)
            if key in read:
                given[key] = a.value
            elif key not in NEUTRAL_OPTIONS:
                raise MechRuntimeError(f"{cmd.name}: the option {key} is not supported by mech")
    return [a for a in args if not isinstance(a, Opt)], given


def _in_quotient(v: Any) -> bool:
    if isinstance(v, (List, ExprList)):
        return any(_in_quotient(x) for x in v.items)
    ring = getattr(v, "ring", None)
    owner = getattr(ring, "owner", None) if ring is not None else (v if isinstance(v, M2Ring) else None)
    return owner is not None and owner.quotient is not None


def _over_zz(v: Any) -> bool:
    if isinstance(v, (List, ExprList)):
        return any(_over_zz(x) for x in v.items)
    return is_integral(v if isinstance(v, M2Ring) else getattr(v, "ring", None))


def _in_group(v: Any) -> bool:
    if isinstance(v, (List, ExprList)):
        return any(_in_group(x) for x in v.items)
    ring = v if isinstance(v, M2Ring) else getattr(getattr(v, "ring", None), "owner", None)
    return isinstance(ring, M2Ring) and bool(ring.ambient().info.get("group"))


def _in_local(v: Any) -> bool:
    if isinstance(v, (List, ExprList)):
        return any(_in_local(x) for x in v.items)
    if isinstance(v, M2Ring):
        return localized_at(v) is not None
    return isinstance(v, LocalFraction) or localized_at(getattr(v, "ring", None)) is not None


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
