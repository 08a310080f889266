"""The report of an analysis as HTML tables, for notebooks (``analyze(m);`` in the Jupyter kernel
or a ``%%mech`` cell shows it beside the text report); built from :func:`report_data`."""
from __future__ import annotations

from html import escape
from typing import Any, Sequence

from mech.stdlib.analysis import Analysis
from mech.stdlib.reports import report_data


def _ideal(polys: Sequence[str]) -> str:
    return "&lang;" + ", ".join(f"<code>{escape(p)}</code>" for p in polys) + "&rang;"


def _table(caption: str, head: Sequence[str], rows: Sequence[Sequence[Any]]) -> str:
    cells = lambda tag, row: "".join(f"<{tag}>{c}</{tag}>" for c in row)  # noqa: E731
    body = "".join(f"<tr>{cells('td', r)}</tr>" for r in rows)
    return (f'<table class="mech-report"><caption style="text-align:left"><b>{escape(caption)}</b></caption>'
            f"<thead><tr>{cells('th', head)}</tr></thead><tbody>{body}</tbody></table>")


def _yes(v: Any) -> str:
    return "" if v is None else "yes" if v else "no"


def report_html(a: Analysis) -> str:
    """The analysis as HTML: the mechanism and its constraint ideal, then one table each for the
    motion modes, the singular configurations and (symbolic lengths) the conditions on the lengths."""
    d = report_data(a)
    facts = [("mechanism", f"<code>{escape(d['mechanism'])}</code>"),
             ("variables", escape(", ".join(d["variables"])))]
    if d["lengths"]:
        facts.append(("symbolic lengths", escape(", ".join(d["lengths"]))))
    facts += [("constraint ideal J", _ideal(d["constraints"])),
              ("mobility", str(d["mobility"])), ("J is radical", _yes(d["radical"]))]
    parts = [_table("mechanism", ["", ""], [(f"<b>{k}</b>", v) for k, v in facts])]
    if d["lengths"]:
        parts.append(_table("singular variety: minimal primes P of the Fitting ideal", ["", "P", "(J+P) ∩ Q[lengths]"],
                            [(i, _ideal(c["prime"]), _ideal(c["elimination"]) if c["on_configuration_space"]
                              else "not on the configuration space")
                             for i, c in enumerate(d["fitting_components"], 1)]))
        if d["length_conditions"]:
            parts.append("<p>singularities need one of: " +
                         ", ".join(f"<code>{escape(f)} = 0</code>" for f in d["length_conditions"]) + "</p>")
    if d["motion_modes"]:
        named = any("name" in m for m in d["motion_modes"])
        parts.append(_table(f"motion modes: {len(d['motion_modes'])}",
                            ["", "dim", "real points"] + (["name"] if named else []) + ["prime"],
                            [(i, m["dimension"], _yes(m["real_points"]))
                             + ((escape(m.get("name") or ""),) if named else ()) + (_ideal(m["prime"]),)
                             for i, m in enumerate(d["motion_modes"], 1)]))
    if "singular" in d:
        rows = []
        for i, s in enumerate(d["singular"], 1):
            point = f"({escape(', '.join(s['point']))})" if s["point"] else _ideal(s["prime"])
            rows.append((f"q{i}", point, escape(", ".join(map(str, s["modes"]))), escape(s["kind"] or ""),
                         _ideal(s["tangent_cone"]) if s["tangent_cone"] else "",
                         "<br>".join(_ideal(c) for c in s["local_components"])))
        parts.append(_table(f"singular configurations: {len(rows)}",
                            ["", f"({escape(','.join(d['variables']))})", "modes", "type", "tangent cone",
                             "local components"], rows))
    return "<div>" + "".join(parts) + "</div>"
