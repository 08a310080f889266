"""The reports of an analysis, one renderer per format (:data:`FORMATS`): ``text`` (readable),
``json`` (the analysis as plain data), ``latex`` (the ideals).  ``analyze(m, FORMAT)`` and
``mech --format FORMAT`` take the names of this table."""
from __future__ import annotations

from typing import Any, Callable, Sequence

from mech.kernel import Poly
from mech.kernel.ideals import dp_ring, ideals_equal, move, std
from mech.stdlib.analysis import Analysis, SingularPoint
from mech.stdlib.analysis_finite import finite_data, modes_line, singular_lines
from mech.stdlib.mechanism_real import real_sections
from mech.stdlib.mode_names import mode_names
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
        "mobility": a.mobility, **_count_data(a), "radical": a.radical if a.radical_decided else None,
        "fitting_minor_size": a.fitting_size}
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
        names = mode_names(a) if a.decomposed else []
        d["motion_modes"] = [{"prime": ps(dp_basis(m.prime)), "dimension": m.dim, "real_points": m.real,
                              "primary_equals_prime": None if m.primary is None
                              else ideals_equal(m.primary, m.prime, a.ring),
                              **({"name": n.name, "shape": n.data()} if n else {"name": None} if names else {})}
                             for m, n in zip(a.modes, names or [None] * len(a.modes))]
        if a.mobility == 0 and a.radical:
            d["complex_configurations"] = configuration_count(a)
        d["motion_modes_by"] = a.modes_by if a.modes_found and a.decomposed else None
        if a.mode_degrees and not a.modes_found:
            d["motion_mode_degrees"] = a.mode_degrees  # the count and degrees proved, the ideals not computed
        d["equidimensional"] = a.equidimensional
        d["embedded_components"] = None if a.embedded is None else [
            {"prime": ps(dp_basis(e.prime)), "primary": ps(dp_basis(e.primary)), "dimension": e.dim,
             "point": [_frac(c) for c in e.point] if e.point else None, "modes": e.modes,
             "in_singular_configuration": e.singular} for e in a.embedded]
        d["singular"] = [{
            "prime": ps(dp_basis(s.prime)), "dimension": s.dim, "real_points": s.real,
            "point": [_frac(c) for c in s.point] if s.point else ps(s.algebraic.coords) if s.algebraic
            else None, "modes": s.modes,
            **({"primitive_element": poly_str(s.algebraic.form),
                "minimal_polynomial": poly_str(normalize(s.algebraic.minpoly))} if s.algebraic else {}),
            "kind": s.kind, "tangent_cone": ps(_local(s, s.tangent_cone)),
            "local_components": [ps(_local(s, c)) for c in s.local_components],
            "transition": s.transition, **({"tangent_cone_note": s.cone_note} if s.cone_note else {})}
            for s in a.singular]
    for section in DATA_SECTIONS:
        d.update(section(a))
    d["notes"], d["unfinished"] = list(a.notes), list(a.unfinished)
    return d


#: More entries of the ``json`` report: each maps an analysis to a dict merged into the data
#: (before ``notes`` and ``unfinished``); the text report's :data:`TEXT_SECTIONS` is the twin.
DATA_SECTIONS: list[Callable[[Analysis], dict]] = [finite_data, lambda a: real_sections(a).data]


def configuration_count(a: Analysis) -> int:
    """The number of complex configurations of a rigid mechanism (mobility 0, J radical): the
    vector-space dimension of Q[x]/J."""
    from mech.kernel.hilbert import vdim
    if a.finite is not None:
        return a.finite.total
    return vdim([g.lm() for g in std(a.ideal, a.ring)], a.ring.nvars)


def report_text(a: Analysis) -> str:
    """The readable report."""
    from mech.dsl.printing import poly_str
    out = [f"mechanism: {a.mechanism}",
           f"variables: {_names(a)}" + (f"; symbolic lengths (last block): {','.join(a.params)}"
                                         if a.params else ""),
           "constraint ideal J:"] + [f"  {poly_str(g)}" for g in a.ideal]
    mob = f"mobility {a.mobility}" + (f" (dim J = {a.dim} minus {len(a.params)} lengths)" if a.params else "")
    radical = "radical" if a.radical else "not radical" if a.radical_decided else \
        "not known to be radical (the analysis stopped before deciding)"
    out.append(f"{mob}{_count_note(a)}; J is {radical}"
               + ("" if a.equidimensional else ", not equidimensional"))
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
    for section in TEXT_SECTIONS:
        lines = section(a)
        out += lines
        if lines is _STOP:
            break
    return "\n".join(out + _unfinished_lines(a)) + "\n"


def _modes_lines(a: Analysis) -> list[str]:
    """The motion modes (numeric lengths)."""
    out = []
    names = mode_names(a) if a.decomposed else []
    if not a.modes_found:
        bound = f" (at most {a.mode_bound}: a slice meets V(J) in {a.mode_bound} Galois orbits)" \
            if a.mode_bound else ""
        why = "" if any("time limit" in u for u in a.unfinished) else ", no strategy finished within its budget"
        if a.mode_degrees:
            k, degs = len(a.mode_degrees), ", ".join(map(str, a.mode_degrees))
            out.append(f"motion modes: {k}, curves of degrees {degs} (proved by a projection to the plane whose "
                       f"eliminant factors into irreducible curves of these degrees, adding up to deg V = "
                       f"{sum(a.mode_degrees)}); their ideals not computed{why}")
        else:
            out.append(f"motion modes: not determined{why}{bound}")
        if a.radical and a.complete_intersection:
            out.append('  (analyze(m, "text", "quick") gives the singular configurations without the modes)')
    elif not a.decomposed:
        out.append("motion modes: not computed (quick analysis); the configuration space has real points")
    else:
        out.append(modes_line(a) if a.finite else f"motion modes ({a.modes_by}): {len(a.modes)}")
    for i, m in enumerate(a.modes, 1):
        real = "has real points" if m.real else "no real points (not physically feasible)" \
            if m.real is False else "real points not decided (out of budget)"
        low = "" if m.dim == a.dim else ", lower-dimensional (fewer degrees of freedom than the mobility" + \
            ("; a rigid configuration" if m.dim == 0 else "") + ")"
        out.append(f"  [{i}] dim {m.dim}, {real}{low}: {_show(dp_basis(m.prime))}")
        if names:
            out.append(f"      {names[i - 1].name if names[i - 1] else 'not named (over the names budget)'}")
    return out


def _singular_lines(a: Analysis) -> list[str]:
    """The singular configurations and their local analysis (numeric lengths)."""
    from mech.dsl.printing import poly_str
    if not a.singular_done:
        return _STOP
    if a.finite:
        return singular_lines(a)
    out = []
    how = f"Theorem 1: V(J + I_{a.fitting_size}(dJ))" if a.radical and a.equidimensional else \
        "the singular loci of the motion modes and their intersections"
    out.append(f"singular configurations ({how}): {len(a.singular)}")
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
        note = f"; {s.cone_note}" if s.cone_note else ""
        out.append(f"     tangent cone (coordinates centred at q{i}{over}{note}): "
                   f"{_show(_local(s, s.tangent_cone))}")
        if a.decomposed and s.local_components:
            out.append(f"     local components (Theorem 3): {len(s.local_components)}: " +
                       ", ".join(_show(_local(s, c)) for c in s.local_components))
            out.append(f"     {s.transition}")
    return out




def _embedded_lines(a: Analysis) -> list[str]:
    """The embedded components of a non-radical J and what they mean for the linkage."""
    if a.radical or not a.decomposed or not a.radical_decided:
        return []
    if a.embedded is None:
        return ["embedded components of J: not computed (out of budget)"]
    out = [f"embedded components of J: {len(a.embedded)} (not motion modes: where J is not reduced, "
           "the constraint equations are dependent beyond the mobility: constraint singularities, "
           "as in an overconstrained linkage)"]
    for i, e in enumerate(a.embedded, 1):
        modes = ("modes " if len(e.modes) > 1 else "mode ") + ", ".join(map(str, e.modes))
        where = f"({_names(a)}) = ({','.join(_frac(c) for c in e.point)})" if e.point else \
            f"{_show(dp_basis(e.prime))} (dim {e.dim})"
        what = "" if e.singular is None else ": also a singular configuration" if e.singular else \
            ": the configuration space is smooth here, only the constraints drop rank"
        out.append(f"  e{i} = {where} on {modes}{what}")
    return out


_STOP: list[str] = []  # a section returning this object ends the report (the steps after it did not run)

#: The sections of the text report of a mechanism with numeric lengths, in order, after the header
#: (mechanism, J, mobility): each maps an analysis to its lines; more sections (real answers:
#: assembly modes, circuits, ...) are appended here.  Notes and unfinished steps come last.
TEXT_SECTIONS: list[Callable[[Analysis], list[str]]] = [_modes_lines, _embedded_lines, _singular_lines,
                                                         lambda a: real_sections(a).lines]


def _unfinished_lines(a: Analysis) -> list[str]:
    return [f"note: {n}" for n in a.notes] + [f"not finished: {u}" for u in a.unfinished]


def _count_data(a: Analysis) -> dict[str, Any]:
    """The Grübler–Kutzbach count when it differs from the mobility (the reports of mechanisms
    whose count is right stay as they were)."""
    gk = a.mechanism.gruebler_kutzbach()
    return {} if gk == a.mobility else {"gruebler_kutzbach": gk, "overconstrained": gk < a.mobility}


def _count_note(a: Analysis) -> str:
    """Beside the mobility, the Grübler–Kutzbach count when it differs."""
    gk = a.mechanism.gruebler_kutzbach()
    if gk == a.mobility:
        return ""
    if gk < a.mobility:
        return f" (Grübler–Kutzbach count {gk}: overconstrained, a special geometry gives more freedom)"
    return f" (Grübler–Kutzbach count {gk}: the dimensions leave less freedom than the count)"


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
