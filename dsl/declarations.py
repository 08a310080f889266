"""Declarations: ``T x = value;`` converts the value to the type (Singular's conversions) and
creates the variable; rings and maps have their own forms; ``T x;`` gives the type's default."""
from __future__ import annotations

from typing import Any

from . import ast as A
from .errors import MechRuntimeError, MechTypeError
from .rings import build_ring, default_ring, indexed_names
from .scopes import RING_TYPES
from .types import find_type
from .values_modules import Module, Vector
from .values import NONE, ExprList, Ideal, IntVec, List, Map, Matrix, Number, Ring, convert, to_int, to_matrix, typeof

#: Singular's types mech does not provide.
UNSUPPORTED_TYPES = {"resolution", "link"}


#: The types whose redeclaration ``T x = ...x...;`` reads the new, default x, as Singular does.
_FRESH = frozenset(("int", "bigint", "string", "number", "poly", "ideal", "intvec"))


class Declarations:
    """Declaration statements (part of the interpreter)."""

    def _exec_decl(self, s: A.Decl) -> None:
        """``T x = value;`` (a redeclared x of the same scope starts anew before value is read)."""
        typ = s.type
        if typ in UNSUPPORTED_TYPES:
            raise MechTypeError(f"type '{typ}' is not supported yet")
        if any(d.indices for d in s.items):
            s = A.Decl(typ, [n for d in s.items for n in self._expanded(d)], s.value, pos=s.pos)
        if typ == "ring":
            self._declare_ring(s)
            return
        if typ == "map":
            self._declare_map(s)
            return
        if typ == "qring":
            self._declare_qring(s)
            return
        for d in s.items:
            if d.dims and typ not in ("matrix", "intmat"):
                raise MechTypeError(f"only a matrix is declared with dimensions, not a {typ}")
        values: list[Any]
        if s.value is None:
            values = [None] * len(s.items)
        elif len(s.items) == 1:
            if typ in _FRESH and not s.items[0].dims:  # as Singular: `int i = i+1;` reads the new i
                old = self.lookup(s.items[0].name)
                if old is not None and old.level == self.frames[-1].level and old.type == typ:
                    var = self.declare(s.items[0].name, typ, self._default(typ))
                    var.value = self._converted(self._rhs(s.value), typ, self.ring.poly if self.ring else None)
                    return
            values = [self._rhs(s.value)]
        else:
            values = self._values(s.value)
            if len(values) != len(s.items):
                raise MechRuntimeError(f"{len(s.items)} variables declared but {len(values)} values given")
        for d, v in zip(s.items, values):
            self._declare_item(typ, d, v)

    def _expanded(self, d: A.Declarator) -> list[A.Declarator]:
        """``poly p(i)`` declares the variable named ``p(3)`` (i = 3); ``p(1..2)`` two of them."""
        if not d.indices:
            return [d]
        node: A.Expr = A.Name(d.name, pos=d.pos)
        for args in d.indices:
            node = A.Call(node, args, pos=d.pos)
        names = indexed_names(node, self.eval)
        if names is None:
            raise MechTypeError(f"the indices of the name {d.name}(...) must be int or intvec")
        return [A.Declarator(n, d.dims, pos=d.pos) for n in names]

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
                # as Singular: a matrix value keeps its size, other values fill [rows][cols] (default 1 x 1),
                # a vector's components too when the size is given
                if isinstance(v, Vector) and dims:
                    v = ExprList([v.get(i) for i in range(1, v.nrows + 1)])
                keeps = isinstance(v, (Matrix, Module, Vector)) or (typeof(v) == "intmat" and not dims)
                v = to_matrix(v, ring) if keeps else to_matrix(v, ring, *(dims or (1, 1)))
        elif typ == "intmat":
            from .intmat import to_intmat
            dims = [to_int(self.eval(x)) for x in d.dims]
            if dims and (len(dims) != 2 or dims[0] <= 0 or dims[1] <= 0):
                raise MechRuntimeError("an intmat is declared as intmat m[rows][cols]")
            v = to_intmat(v, *dims)
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
        plugin = find_type(typ)
        if plugin is not None:  # a library's type (mech.dsl.types)
            if isinstance(plugin.default, str):
                raise MechRuntimeError(plugin.default)
            return plugin.default()
        ring = self.basering().poly
        if typ == "number":
            return Number(ring, ring.field.zero)
        if typ == "poly":
            return ring.zero()
        if typ == "ideal":
            return Ideal(ring, [], is_std=True)
        if typ == "vector":
            return Vector(ring, ())
        if typ == "module":
            return Module(ring, (), is_std=True)
        raise MechTypeError(f"type '{typ}' is not supported yet")

    def _converted(self, v: Any, typ: str, kring: Any) -> Any:
        if typ in RING_TYPES and kring is None:
            self.basering()
        if typ == "def" and isinstance(v, ExprList) and len(v.items) > 1:  # Singular: "assign not impl."
            raise MechRuntimeError("a def takes one value (declare a list for several)")
        v = convert(v, typ, kring, self.warn)
        if isinstance(v, Ideal):
            std = v.is_std or len(v.gens) <= 1  # Singular marks one-generator ideals as standard bases
            if std != v.is_std:
                v = Ideal(v.ring, v.gens, std)
        elif isinstance(v, Module) and not v.is_std and len(v.gens) <= 1:  # as an ideal's
            v = Module(v.ring, v.gens, v.rank, True)
        return v

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
            ring = build_ring(s.value, self.eval, self.warn)
        ring.name = s.items[0].name
        self.rings.add(ring)
        self.declare(ring.name, "ring", ring)
        self.ring = ring

    def _declare_qring(self, s: A.Decl) -> None:
        from .qrings import make_qring
        if len(s.items) != 1 or s.items[0].dims or s.value is None:
            raise MechRuntimeError("a qring is declared as qring Q = I; with I a standard basis of the basering")
        ring = make_qring(self.basering(), self._rhs(s.value))
        ring.name = s.items[0].name
        self.rings.add(ring)
        self.declare(ring.name, "ring", ring)
        self.ring = ring

    def _declare_map(self, s: A.Decl) -> None:
        if len(s.items) != 1:
            raise MechRuntimeError("declare one map at a time: map phi = r, f1, ..., fn;")
        if s.value is None:
            raise MechRuntimeError("a map is declared as map phi = r, f1, ..., fn;")
        self.declare(s.items[0].name, "map", self._map_value(self._values(s.value)))

    def _map_value(self, v: list) -> Map:
        """The map of ``r, f1, ..., fn`` (or a map itself), into the basering."""
        if len(v) == 1 and isinstance(v[0], Map):
            return v[0]
        if not v or not isinstance(v[0], Ring):
            raise MechTypeError("a map is given as r, f1, ..., fn; with r the source ring")
        target = self.basering().poly
        images = list(self._converted(ExprList(v[1:]), "ideal", target).gens) if len(v) > 1 else []
        return Map(v[0], target, tuple(images))  # as Singular, images beyond the variables are kept, unused
