"""Mechanisms: the language's type ``mechanism``, described by statements (:mod:`mech.stdlib.joints`).

A mechanism is its parsed statements (elements: fixed points, links, sliders, loop joints), in
one of three models, each with its variables and equations: planar
(:mod:`mech.stdlib.planar`), spatial points and bodies (:mod:`mech.stdlib.spatial`), or a
spatial loop of joints with Denavit–Hartenberg parameters (:mod:`mech.stdlib.loops`).  The
checks that catch likely mistakes are in :mod:`mech.stdlib.mechanism_checks`.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any, Callable, ClassVar, Optional

from mech.dsl.errors import MechRuntimeError, MechTypeError
from mech.dsl.types import register_type
from mech.dsl.values import typeof
from mech.kernel import QQ, Block, MonomialOrder, Poly, PolyRing
from mech.stdlib.joints import (Element, Fix, Gear, Length, LineSlider, Link, LoopJoint, MechanismError, Slider, Source,
                                arity_message, classes, keywords)

__all__ = ["Mechanism", "MechanismError", "Length", "parse_mechanism", "to_mechanism"]


@dataclass
class Mechanism:
    """Joint points (some fixed), links between them, sliders, or a loop of joints (the
    language's type ``mechanism``)."""

    type_name: ClassVar[str] = "mechanism"
    name: str = "mechanism"
    elements: list[Element] = field(default_factory=list)
    dim: int = 2

    # the parts
    @property
    def fixed(self) -> dict[str, tuple[Length, ...]]:
        out: dict[str, tuple[Length, ...]] = {}
        for e in self.elements:
            if isinstance(e, Fix):
                out[e.point] = e.coords
        return out

    @property
    def links(self) -> list[Link]:
        return [e for e in self.elements if isinstance(e, Link)]

    @property
    def sliders(self) -> list[Slider | LineSlider]:
        return [e for e in self.elements if isinstance(e, (Slider, LineSlider))]

    @property
    def joints(self) -> list[LoopJoint]:
        return [e for e in self.elements if isinstance(e, LoopJoint)]

    @property
    def gears(self) -> list[Gear]:
        return [e for e in self.elements if isinstance(e, Gear)]

    @property
    def model(self) -> Any:
        """The module generating the variables and equations: planar, spatial or loops."""
        from mech.stdlib import loops, planar, spatial
        return loops if self.joints else spatial if self.dim == 3 else planar

    def __str__(self) -> str:
        lines = [f"fix {p} " + " ".join(str(v) for v in xy) for p, xy in self.fixed.items()]
        for group in (1, 2, 3):
            lines += [e.text() for e in self.elements if e.group == group]
        return "; ".join(lines)

    def with_values(self, values: dict[str, Length]) -> "Mechanism":
        """The same mechanism with some symbolic parameters replaced by numbers."""
        from mech.stdlib.mechanism_checks import check_values
        m = Mechanism(self.name, [e.with_values(values) for e in self.elements], self.dim)
        check_values(m)
        return m

    def points(self) -> list[str]:
        """Joint points in order of first appearance."""
        seen = list(self.fixed)
        for link in self.links:
            seen += [p for p in link.points if p not in seen]
        return seen

    # the model's variables and equations
    def symbols(self) -> list[str]:
        """Symbolic parameters (lengths, coordinates) in order of first appearance."""
        seen: list[str] = []
        values = [v for xy in self.fixed.values() for v in xy]
        for group in (1, 2, 3):
            values += [v for e in self.elements if e.group == group for v in e.parameters()]
        for v in values:
            if isinstance(v, str) and v not in seen:
                seen.append(v)
        return seen

    def variables(self) -> list[str]:
        """The configuration variables (see docs/mechanisms.md, the naming table)."""
        return self.model.variables(self)

    def ring(self, values: dict[str, Length] | None = None) -> PolyRing:
        """``QQ[configuration, (parameters)]``, the parameters without a value in ``values`` as a trailing
        dp block (omitted when every parameter has one)."""
        config = self.variables()
        params = [p for p in self.symbols() if p not in (values or {})]
        blocks = [Block("dp", len(config))] + ([Block("dp", len(params))] if params else [])
        return PolyRing(QQ, config + params, MonomialOrder(blocks))

    def positions(self, R: PolyRing, values: dict[str, Length] | None = None
                  ) -> tuple[dict[str, tuple[Poly, ...]], list[Poly]]:
        """Each joint point's coordinates as polynomials of ``R`` and the closure polynomials
        (planar and spatial points)."""
        return self.model.positions(self, R, values or {})

    def constraints(self, values: dict[str, Length] | None = None) -> tuple[PolyRing, list[Poly]]:
        """The constraint ideal's ring and generators."""
        if not self.links and not self.joints:
            raise MechanismError(f"{self.name}: a mechanism needs at least one link")
        if self.dim == 2 and not self.fixed and not any(isinstance(s, Slider) for s in self.sliders):
            raise MechanismError(f"{self.name}: nothing is fixed (fix a point, or put one on a fixed line "
                                 "with slider)")
        return self.model.constraints(self, values or {})

    def gruebler_kutzbach(self) -> int:
        """The Grübler–Kutzbach count of the mechanism's links and joints."""
        if self.joints:
            return self.model.gruebler_kutzbach(self)[0]
        return self.model.gruebler_kutzbach(self)


# ---------------------------------------------------------------- the description language
def statements() -> tuple[str, ...]:
    """The first words of the description's statements (what ``mechanism m { ... }`` accepts)."""
    return keywords()


_SPLIT = re.compile(r"[;\n]")


def _dimension(parts: list[tuple[Source, str, list[str]]]) -> int:
    """2 or 3: a statement that exists only in space (a point fixed with three coordinates, a loop
    joint) makes the mechanism spatial; one that exists only in the plane, planar; both: an error."""
    implied: dict[int, Source] = {}
    for src, word, args in parts:
        dims = [d for d in (2, 3) if any(c.accepts(args, d) for c in classes(word))]
        if len(dims) == 1:
            implied.setdefault(dims[0], src)
    if len(implied) == 2:
        raise MechanismError(f"{implied[3]} is spatial but {implied[2]} is planar: a mechanism is either "
                             "planar or spatial")
    return 3 if 3 in implied else 2


def parse_mechanism(text: str, name: str = "mechanism",
                    warn: Optional[Callable[[str], None]] = None) -> Mechanism:
    """A :class:`Mechanism` from its description (see :func:`mech.stdlib.joints.syntax`); likely
    mistakes are errors or go to ``warn`` (one message each, naming the statement)."""
    from mech.stdlib.mechanism_checks import check
    texts = [s.strip() for s in _SPLIT.split(text) if s.strip()]
    if not texts:
        raise MechanismError("empty mechanism description")
    parts = []
    for k, stmt in enumerate(texts, 1):
        word, *args = stmt.split()
        src = Source(k, stmt)
        if not classes(word):
            *first, last = keywords()
            raise MechanismError(f"{src}: unknown statement '{word}' (expected {', '.join(first)} or {last})")
        parts.append((src, word, args))
    dim = _dimension(parts)
    m = Mechanism(name, [], dim)
    for src, word, args in parts:
        cls = next((c for c in classes(word) if c.accepts(args, dim)), None)
        if cls is None:
            space = "in space" if dim == 3 else "in the plane"
            if any(c.accepts(args, 5 - dim) for c in classes(word)):
                raise MechanismError(f"{src}: this form of '{word}' is not {space}, and the mechanism is "
                                     f"{'spatial' if dim == 3 else 'planar'}")
            raise MechanismError(f"{src}: {arity_message(word, len(args))}")
        m.elements += cls.parse(args, src, dim)
    check(m, warn or (lambda message: None))
    return m


def to_mechanism(v: Any, warn: Optional[Callable[[str], None]] = None) -> Mechanism:
    """A value of type ``mechanism``: a mechanism, or a description string parsed (its warnings
    printed by the interpreter)."""
    if isinstance(v, Mechanism):
        return v
    if not isinstance(v, str):
        raise MechTypeError(f"cannot convert {typeof(v)} to mechanism (give its description as a string)")
    try:
        return parse_mechanism(v, warn=warn)
    except MechanismError as e:
        raise MechRuntimeError(f"mechanism: {e.message}") from None


register_type("mechanism", to_mechanism,
              default='a mechanism is declared with its description: mechanism m = "fix O; bar O A l1";',
              statements=statements)
