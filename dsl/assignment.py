"""Assignments: ``x = v;``, into entries (``I[2] = f;``, ``M[i,j] = f;``, ``L[2][1] = v;``),
several at once (``a, b = b, a;``), ``x++;``.  Values are immutable: an entry assignment builds a
new value and rebinds the variable."""
from __future__ import annotations

from typing import Any, Optional

from ..kernel import Poly
from . import ast as A
from .echo import mark_echo
from .errors import MechNameError, MechRuntimeError, MechTypeError
from .intmat import IntMat, to_intmat
from .minpoly import set_minpoly
from .noether import set_noether
from .printing import set_short
from .rings import indexed_names
from .values_modules import Module, Vector
from .values import (NONE, ExprList, Ideal, IntVec, List, Map, Matrix, convert, ring_of, to_ideal, to_int, to_matrix,
                     to_poly, typeof)


#: Singular's bounds on standard basis computations: mech computes without them (only 0 is accepted).
UNSUPPORTED_BOUNDS = {"degBound": "a degree bound for std", "multBound": "a multiplicity bound for std"}


class Assignment:
    """Assignment statements (part of the interpreter)."""

    def _exec_assign(self, s: A.Assign) -> None:
        if len(s.targets) == 1:
            if len(s.values) == 1:  # the common case: _rhs of one value
                v = self.eval(s.values[0])
                if isinstance(v, ExprList):
                    v = v.items[0] if len(v.items) == 1 else ExprList(list(v.items))
                self.assign(s.targets[0], v)
                return
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
        if isinstance(base, A.Call):  # `len(3) = ...`: the variable declared as `int len(3)`
            names = indexed_names(base, self.eval)
            if not names or len(names) != 1:
                raise MechRuntimeError("cannot assign to this expression", base.pos, self.source)
            base = A.Name(names[0], pos=base.pos)
        assert isinstance(base, A.Name)
        name = base.id
        var = self.lookup(name)
        if var is None:
            if name == "short" and not chain and self.ring is not None:
                set_short(self.ring.poly, bool(to_int(value)))
                return
            if name == "minpoly" and not chain:
                set_minpoly(self, value)
                return
            if name == "noether" and not chain:
                set_noether(self.ring, value)
                return
            if name in UNSUPPORTED_BOUNDS and not chain:
                if (not value.is_zero()) if isinstance(value, Poly) else to_int(value) != 0:
                    raise MechRuntimeError(f"{name} other than 0 ({UNSUPPORTED_BOUNDS[name]}) is not supported")
                return
            if name in self.sysvars or name in ("timer", "rtimer"):
                self.sysvars[name] = to_int(value)
                if name == "echo":
                    mark_echo(self)
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
                value = self._map_value(list(value.items)) if isinstance(value, ExprList) else convert(value, "map", None)
            elif var.type == "intmat" and isinstance(var.value, IntMat) and not isinstance(value, IntMat):
                value = to_intmat(value, var.value.nrows, var.value.ncols)
            elif var.type == "matrix" and isinstance(var.value, Matrix):
                value = to_matrix(value, self.basering().poly, var.value.nrows, var.value.ncols) \
                    if not isinstance(value, Matrix) else to_matrix(value, self.basering().poly)
            else:
                value = self._converted(value, var.type, kring)
            self._rebind(var, value)
            var.attributes = None  # as Singular: a new value has none of the old one's attributes
            return
        chain.reverse()
        new = self._set_in(var.value, chain, 0, value)
        self._rebind(var, new)
        var.attributes = None

    def _set_in(self, container: Any, chain: list[A.Index], k: int, value: Any, idx: Optional[list] = None) -> Any:
        """``container`` with the entry ``chain[k:]`` set to ``value`` (``idx``: the values of
        ``chain[k]``'s indices when they are evaluated already)."""
        node = chain[k]
        if idx is None:
            idx = [self.eval(i) for i in node.indices]
        last = k == len(chain) - 1
        ring = self.ring.poly if self.ring else None
        if isinstance(container, IntMat):
            if len(idx) != 2 or not last:
                raise MechRuntimeError("an intmat entry is set as m[i,j] = ...")
            return container.with_entry(to_int(idx[0]), to_int(idx[1]), to_int(value))
        if isinstance(container, Matrix):
            if len(idx) != 2 or not last:
                raise MechRuntimeError("a matrix entry is set as M[i,j] = ...")
            if isinstance(idx[0], IntVec) or isinstance(idx[1], IntVec):
                return _set_matrix_block(container, idx[0], idx[1], value)
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
        if isinstance(container, Map) and last:  # as an ideal's entry: the image of the i-th variable
            images = list(container.images) + [container.ring.zero()] * (i - len(container.images))
            images[i - 1] = to_poly(value, container.ring)
            return Map(container.source, container.ring, tuple(images))
        if isinstance(container, Ideal):
            if not last:
                raise MechRuntimeError("cannot index into an ideal's generator")
            gens = list(container.gens)
            gens += [container.ring.zero()] * (i - len(gens))
            gens[i - 1] = to_poly(value, container.ring if ring is None else ring)
            return Ideal(container.ring, gens)
        if isinstance(container, (Vector, Module)):
            return _set_module_entry(container, i, value, last, lambda v: self._set_in(v, chain, k + 1, value))
        if isinstance(container, List):
            items = list(container.items)
            items += [NONE] * (i - len(items))
            if last and isinstance(value, ExprList):  # Singular: only into an ideal entry (it joins them)
                if i > len(container.items) or not isinstance(container.items[i - 1], Ideal):
                    raise MechRuntimeError("cannot assign several values to one list entry")
                items[i - 1] = to_ideal(value, container.items[i - 1].ring)
            elif last:
                items[i - 1] = value
            else:
                items[i - 1] = self._set_in(items[i - 1], chain, k + 1, value)
            if ring_of(container) is None:  # the new entry is the only one that may depend on a ring
                return List(items, ring_of(items[i - 1]))
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
        if s.ignored:
            self.warn_in_line("right side is not a datum, assignment ignored")
        if type(s.target) is A.Name:
            var = self.lookup(s.target.id)
            if var is not None and type(var.value) is int:
                var.value += s.delta
                return
        cur = self.eval(s.target)
        if type(cur) is not int:
            raise MechTypeError(f"++ and -- need an int, not {typeof(cur)}")
        self.assign(s.target, cur + s.delta)


def _set_matrix_block(m: Matrix, rows: Any, cols: Any, value: Any) -> Matrix:
    """``M[rows, cols] = values`` with intvec indices, as Singular: the entries of the block, row by row,
    take the values in turn (a matrix's entries row by row)."""
    rs = list(rows.values) if isinstance(rows, IntVec) else [to_int(rows)]
    cs = list(cols.values) if isinstance(cols, IntVec) else [to_int(cols)]
    items = list(value.items) if isinstance(value, ExprList) else [value]
    flat: list[Any] = []
    for v in items:
        flat.extend(v.entries if isinstance(v, Matrix) else [v])
    if len(flat) != len(rs) * len(cs):
        raise MechRuntimeError(f"{len(rs) * len(cs)} matrix entries but {len(flat)} values")
    ents = list(m.entries)
    for k, (i, j) in enumerate((i, j) for i in rs for j in cs):
        if not (1 <= i <= m.nrows and 1 <= j <= m.ncols):
            raise MechRuntimeError(f"index [{i},{j}] out of range for a {m.nrows} x {m.ncols} matrix")
        ents[(i - 1) * m.ncols + j - 1] = to_poly(flat[k], m.ring)
    return Matrix(m.ring, m.nrows, m.ncols, ents)


def _set_module_entry(container: Vector | Module, i: int, value: Any, last: bool, deeper: Any) -> Vector | Module:
    """``v[i] = p`` (the i-th entry of a vector) and ``M[i] = v`` (the i-th generator of a module;
    ``M[i][j] = p`` sets an entry of it)."""
    from .convert_modules import to_vector
    ring = container.ring
    if isinstance(container, Vector):
        if not last:
            raise MechRuntimeError("cannot index into a vector's entry")
        ents = container.padded(max(i, container.nrows))
        ents[i - 1] = to_poly(value, ring)
        return Vector(ring, ents)
    gens = list(container.gens) + [Vector(ring, ())] * (i - len(container.gens))
    gens[i - 1] = to_vector(value, ring) if last else deeper(gens[i - 1])
    return Module(ring, gens, container.rank)
