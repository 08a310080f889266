"""What an identifier means: a declared variable, else a ring variable or parameter, else a
system variable (``basering``, ``timer``...), else a short monomial (``x2y``), else it is unknown;
also number and monomial literals (``7/2``, ``3x2y``) and indexed ring variables (``x(2)``)."""
from __future__ import annotations

import time
from typing import Any, Optional

from . import ast as A
from .errors import MechError, MechNameError, MechRuntimeError
from .minpoly import get_minpoly
from .noether import noether_poly
from .printing import is_short
from .rings import indexed_names
from .values import ExprList, LibCommand, Number, Ring


class Names:
    """Identifiers and literals (part of the interpreter)."""

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
        cmd = self.registry.find(name, self.loaded_libs)
        if cmd is not None and cmd.lib:  # a library procedure as a value
            return LibCommand(cmd)
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
        if name == "short" and self.ring is not None:
            return int(is_short(self.ring.poly))
        if name == "minpoly" and self.ring is not None:
            return get_minpoly(self.ring)
        if name == "newline":
            return "\n"
        if name in ("degBound", "multBound"):
            return 0
        if name == "noether" and self.ring is not None:
            return noether_poly(self.ring.poly) or self.ring.poly.zero()
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

    def _indexed_vars(self, node: A.Call) -> Any:
        """Variables declared with an index (``poly p(2)``), ring variables or parameters written ``x(2)``,
        ``x(1..3)`` (several), ``y(1)(2)``; None if not such."""
        names = indexed_names(node, self.eval)
        if names is None:
            return None
        gens = []
        for n in names:
            var = self.lookup(n)
            i = self.ring.var_index(n) if self.ring is not None else None
            if var is not None:  # declared as `poly rp(3) = ...;`
                gens.append(var.value)
            elif i is not None:
                gens.append(self.ring.poly.gen(i))
            elif self.ring is not None and n in self.ring.params:
                gens.append(self._param(self.ring, n))
            else:
                return None
        return gens[0] if len(gens) == 1 else ExprList(gens)
