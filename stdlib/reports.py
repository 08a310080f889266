"""The reports of an analysis, one renderer per format (:data:`FORMATS`): ``text`` (readable),
``json`` (the analysis as plain data), ``latex`` (the ideals).  ``analyze(m, FORMAT)`` and
``mech --format FORMAT`` take the names of this table."""
from __future__ import annotations

from typing import Any, Callable, Sequence

from mech.kernel import Poly
from mech.kernel.ideals import dp_ring, ideals_equal, move, std
from mech.stdlib.analysis import Analysis, SingularPoint
from mech.stdlib.realpoints import count_real_roots
from mech.stdlib.standard import normalize


def dp_basis(polys: Sequence[Poly]) -> list[Poly]:
    """A reduced dp basis (normalized as Singular's std) of an ideal of any ordering."""
    if not polys:
        return []
    glob = dp_ring(polys[0].ring)
    return [normalize(g) for g in std(move(list(polys), glob), glob)]


def _local(s: SingularPoint, polys: Sequence[Poly]) -> list[Poly]:
    """A cone or local component for the report: at a rational point its reduced dp basis; at
    algebraic points its basis over Q(t) (a Gröbner basis of algebraic.ring) without the
    minimal polynomial of t."""
    if s.algebraic is None:
        return dp_basis(polys)
    n = s.algebraic.ring.nvars - 1
    return [normalize(g) for g in polys if any(any(e[:n]) for e in g.terms)]


def _show(polys: Sequence[Poly]) -> str:
    from mech.dsl.printing import poly_str
    return "<" + ", ".join(poly_str(g) for g in polys) + ">"


def _tex(polys: Sequence[Poly]) -> str:
    import re
    from mech.dsl.printing import poly_str
    def one(g: Poly) -> str:
        s = re.sub(r"\^([0-9]+)", r"^{\1}", poly_str(g).replace("*", " "))
        return re.sub(r"\b([A-Za-z]+)([0-9]+)\b", r"\1_{\2}", s)
    return r"\langle " + ", ".join(one(g) for g in polys) + r" \rangle"


def _frac(c: Any) -> str:
    return str(c.p) if int(c.q) == 1 else f"{c.p}/{c.q}"


def _names(a: Analysis) -> str:
    return ",".join(a.ring.names[:a.nvars])


def report_data(a: Analysis) -> dict:
    """The analysis as plain data (strings for polynomials): the ``json`` report."""
    from mech.dsl.printing import poly_str
    ps = lambda polys: [poly_str(g) for g in polys]  # noqa: E731
    d: dict[str, Any] = {
        "mechanism": str(a.mechanism), "variables": list(a.ring.names[:a.nvars]),
        "lengths": a.params, "constraints": ps(a.ideal), "dimension": a.dim,
        "mobility": a.mobility, "radical": a.radical, "fitting_minor_size": a.fitting_size}
    if a.params:
        d["fitting_components"] = [
            {"prime": ps(c.prime),
             "on_configuration_space": c.elimination is not None,
             "elimination": ps(c.elimination or []), "condition": ps(c.conditions),
             "factors": ps(c.factors)} for c in a.length_components]
        d["length_conditions"] = ps(a.length_factors)
        d["motion_modes"] = [{"prime": ps(dp_basis(m.prime)), "dimension": m.dim, "real_points": None}
                             for m in a.modes]  # over Q(lengths); [] when not computed
    else:
        d["motion_modes"] = [{"prime": ps(dp_basis(m.prime)), "dimension": m.dim, "real_points": m.real,
                              "primary_equals_prime": ideals_equal(m.primary, m.prime, a.ring)}
                             for m in a.modes]
        d["singular"] = [{
            "prime": ps(dp_basis(s.prime)), "dimension": s.dim, "real_points": s.real,
            "point": [_frac(c) for c in s.point] if s.point else ps(s.algebraic.coords) if s.algebraic
            else None, "modes": s.modes,
            **({"primitive_element": poly_str(s.algebraic.form),
                "minimal_polynomial": poly_str(normalize(s.algebraic.minpoly))} if s.algebraic else {}),
            "kind": s.kind, "tangent_cone": ps(_local(s, s.tangent_cone)),
            "local_components": [ps(_local(s, c)) for c in s.local_components],
            "transition": s.transition} for s in a.singular]
    return d


def report_text(a: Analysis) -> str:
    """The readable report."""
    from mech.dsl.printing import poly_str
    out = [f"mechanism: {a.mechanism}",
           f"variables: {_names(a)}" + (f"; symbolic lengths (last block): {','.join(a.params)}"
                                         if a.params else ""),
           "constraint ideal J:"] + [f"  {poly_str(g)}" for g in a.ideal]
    mob = f"mobility {a.mobility}" + (f" (dim J = {a.dim} minus {len(a.params)} lengths)" if a.params else "")
    out.append(f"{mob}; J is {'radical' if a.radical else 'not radical'}")
    if a.params:
        out.append(f"singular variety (Theorem 1): V(J + I_{a.fitting_size}(dJ)); "
                   f"minimal primes P of the Fitting ideal and (J + P) ∩ Q[{','.join(a.params)}]:")
        for i, c in enumerate(a.length_components, 1):
            if c.elimination is None:
                what = "J + P = <1>: not on the configuration space"
            elif not c.conditions:
                what = f"{_show(c.elimination)}: only with a vanishing length"
            else:
                what = _show(c.elimination)
            out.append(f"  [{i}] {_show(c.prime)}: {what}")
        if a.length_factors:
            out.append("singularities need one of: " +
                       ", ".join(f"{poly_str(f)} = 0" for f in a.length_factors))
        else:
            out.append("no singularities for non-zero lengths")
        if not a.decomposed:
            out.append("motion modes: not computed (quick analysis); singular configurations: give "
                       "numeric lengths (setLengths)")
            return "\n".join(out) + "\n"
        if not a.modes:
            out.append("motion modes and singular configurations: give numeric lengths (setLengths)")
            return "\n".join(out) + "\n"
        field = f"Q({','.join(a.params)})"
        out.append(f"motion modes over {field} (generic lengths, certified by a birational projection; "
                   f"real points not decided): {len(a.modes)}")
        for i, m in enumerate(a.modes, 1):
            what = f"J is prime over {field}" if len(a.modes) == 1 else _show(dp_basis(m.prime))
            out.append(f"  [{i}] dim {m.dim}: {what}")
        out.append("singular configurations: give numeric lengths (setLengths)")
        return "\n".join(out) + "\n"
    if not a.decomposed:
        out.append("motion modes: not computed (quick analysis); the configuration space has real points")
    else:
        out.append(f"motion modes ({a.modes_by}): {len(a.modes)}")
    for i, m in enumerate(a.modes, 1):
        real = "has real points" if m.real else "no real points (not physically feasible)"
        out.append(f"  [{i}] dim {m.dim}, {real}: {_show(dp_basis(m.prime))}")
    out.append(f"singular configurations (Theorem 1: V(J + I_{a.fitting_size}(dJ))): {len(a.singular)}")
    for i, s in enumerate(a.singular, 1):
        modes = "modes " + ", ".join(map(str, s.modes)) if len(s.modes) > 1 else f"mode {s.modes[0]}" \
            if s.modes else "no mode"
        if s.point is None and s.algebraic is None:
            where = f"{_show(dp_basis(s.prime))} (dim {s.dim}, {'real' if s.real else 'no real points'})"
            out.append(f"  q{i} {where}: not a point, no local analysis")
            continue
        on = f" on {modes}" if a.decomposed else ""
        pt = s.algebraic
        coords = [poly_str(c) for c in pt.coords] if pt else [_frac(c) for c in s.point]
        out.append(f"  q{i} = ({_names(a)}) = ({','.join(coords)}){on}: {s.kind}")
        if pt:
            out.append(f"     where t = {poly_str(pt.form)}, {poly_str(normalize(pt.minpoly))} = 0: "
                       f"{pt.degree} conjugate points, {count_real_roots(pt.minpoly)} real")
        over = ", coefficients in Q(t)" if pt else ""
        out.append(f"     tangent cone (coordinates centred at q{i}{over}): "
                   f"{_show(_local(s, s.tangent_cone))}")
        if a.decomposed:
            out.append(f"     local components (Theorem 3): {len(s.local_components)}: " +
                       ", ".join(_show(_local(s, c)) for c in s.local_components))
            out.append(f"     {s.transition}")
    return "\n".join(out) + "\n"


def report_latex(a: Analysis) -> str:
    """The ideals of the analysis in LaTeX (an ``align*`` environment)."""
    rows = [r"J &= " + _tex(a.ideal)]
    if a.params:
        rows += [rf"E_{{{i}}} &= " + _tex(c.elimination) for i, c in enumerate(a.length_components, 1)
                 if c.elimination is not None and c.conditions]
        if a.length_factors:
            rows.append(r"&\text{conditions: } " + r" \cdot ".join(
                "(" + _tex([f])[len(r"\langle "):-len(r" \rangle")] + ")" for f in a.length_factors) + " = 0")
    else:
        rows += [rf"J_{{{i}}} &= " + _tex(dp_basis(m.prime)) for i, m in enumerate(a.modes, 1)]
        rows += [rf"C_{{q_{{{i}}}}} &= V\left(" + _tex(_local(s, s.tangent_cone)) + r"\right)"
                 for i, s in enumerate(a.singular, 1) if s.point is not None or s.algebraic]
    return "\\begin{align*}\n" + " \\\\\n".join(rows) + "\n\\end{align*}\n"


def report_json(a: Analysis) -> str:
    """The ``json`` report: :func:`report_data` as JSON on one line, so that the reports of a
    script (``mech --json FILE``) are JSON Lines: one document per line."""
    import json
    return json.dumps(report_data(a)) + "\n"


#: The report formats: name -> renderer (an analysis -> the text printed).
FORMATS: dict[str, Callable[[Analysis], str]] = {"text": report_text, "json": report_json, "latex": report_latex}


def unknown_format(name: str) -> str:
    """The message for a format name not in :data:`FORMATS` (listing the known ones)."""
    *first, last = FORMATS
    return f"unknown format '{name}' ({', '.join(first)} or {last})"
