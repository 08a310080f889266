"""The sweep commands of ``LIB "mechanism.lib";`` (``sweep``, ``sweepMap``) and the one entry point
they share with the CLI and Python (:func:`sweep_rows`, :func:`map_curves`); docs/sweeps.md."""
from __future__ import annotations

from typing import Any, Callable

from mech.dsl.errors import MechRuntimeError
from mech.dsl.files import output_file
from mech.dsl.registry import command
from mech.stdlib.mechanism import Mechanism
from mech.stdlib.sweep import Shared, SweepSpec, parse_answers, shared_work
from mech.stdlib.sweep_designs import design_set
from mech.stdlib.sweep_map import draw_map
from mech.stdlib.sweep_run import read_rows, run_sweep, typed

MAP_LIMIT = 5.0  # seconds for the length conditions drawn on a map
MAP_CURVES_LIMIT = 300.0  # seconds for the discriminant curves of a mechanism of mobility 0
OPTIONS = ("workers", "timeout", "batch", "scheduler", "shared")


def sweep_rows(m: Mechanism, designs: str, answers: Any = "mobility,real", out: str | None = None, *,
               scheduler: Any = None, workers: int | None = None, timeout: float | None = None,
               batch: int | None = None, progress: bool | None = None, shared: bool | None = None,
               on_row: Callable[[dict[str, Any], int, int], None] | None = None,
               notes: list[str] | None = None) -> list[dict[str, Any]]:
    """The rows of the sweep of ``m`` over ``designs`` (a design-set description); ``notes``
    receives a line on the discriminant curves, when the sweep looked for them."""
    spec = SweepSpec(m, parse_answers(answers), timeout)
    return run_sweep(spec, design_set(designs), out, scheduler=scheduler, workers=workers, batch=batch,
                     progress=progress, on_row=on_row, shared=shared, notes=notes)


def map_curves(m: Mechanism, rows: list[dict[str, Any]], x: str, y: str) -> list[tuple[str, Any]]:
    """The curves drawn in the plane of ``x`` and ``y`` (the other parameters as in the rows, when
    they are the same in all of them; none otherwise): for a mechanism of mobility 0 its
    discriminant curves (:mod:`mech.stdlib.sweep_discriminant`, ``MAP_CURVES_LIMIT`` seconds),
    else the generic length conditions (``MAP_LIMIT`` seconds)."""
    values: dict[str, Any] = {}
    for p in m.symbols():
        if p in (x, y):
            continue
        seen = {r.get(p) for r in rows}
        if len(seen) != 1 or None in seen:
            return []
        from mech.dsl.convert import parse_decimal
        v = parse_decimal(str(seen.pop()))
        values[p] = int(v) if v.denominator == 1 else v
    fixed = m.with_values(values)
    from mech.stdlib.sweep_discriminant import curve_label, mechanism_curves
    curves = mechanism_curves(fixed, [x, y], MAP_CURVES_LIMIT)
    if curves.factors:
        return [(curve_label(n, k), f) for k, (n, f) in enumerate(zip(curves.names, curves.factors))]
    common: Shared = shared_work(SweepSpec(fixed, ()), [x, y], MAP_LIMIT)
    return list(zip(common.names, common.conditions))


def _options(text: str) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for w in text.replace(",", " ").split():
        k, eq, v = w.partition("=")
        if not eq or k not in OPTIONS:
            raise MechRuntimeError(f"sweep: unknown option '{w}' (known: {'=, '.join(OPTIONS)}=)")
        try:
            out[k] = v if k == "scheduler" else (v not in ("no", "0", "false")) if k == "shared" else \
                float(v) if k == "timeout" else int(v)
        except ValueError:
            raise MechRuntimeError(f"sweep: option '{w}': expected a number") from None
    return out


@command("sweep", lib="mechanism.lib")
def sweep_cmd(ctx: Any, m: Mechanism, designs: str, answers: str = "mobility,real", file: str = "",
              options: str = "") -> None:
    """sweep(m, designs[, answers[, file[, options]]]): analyses m at every design and prints how
    many designs gave each answer; with a file (.csv) writes one row per design there (a sweep
    that was interrupted resumes: designs already in the file are not computed again).
    designs: "grid l1=a:b:n ...", "random N l1=a:b ... [seed=S]" or "lhs N ...";
    answers: mobility, modes, real, grashof, singular; options: "workers=N timeout=S batch=N
    scheduler=ADDRESS|inline shared=yes|no" (default: a Dask cluster on all cores; the generic
    length conditions first only for singular; the discriminant curves for real counts over two
    parameters, a line saying what they gave; docs/sweeps.md). A progress bar on a terminal; under a
    statement time limit the sweep stops with the rows done kept in the file.

    Example:
      LIB "mechanism.lib";
      mechanism fb { ground O A 2; bar O B l1; bar B C 3; bar C A 4; }
      sweep(fb, "grid l1=1:4:4", "grashof", "", "scheduler=inline");
      → 4 designs, 0 with errors
      → grashof: change point 2, double-crank 1, non-Grashof 1
    """
    if designs.split()[:1] and designs.split()[0].lower() == "csv":
        raise MechRuntimeError("sweep: scripts read no files: give csv designs to mech sweep or Python")
    opts = _options(options)
    opts.setdefault("scheduler", ctx.settings.get("sweep_scheduler"))
    out = str(output_file(file, (".csv",))) if file else None
    spec_answers = parse_answers(answers)
    notes: list[str] = []
    rows = sweep_rows(m, designs, spec_answers, out, progress=False, notes=notes, **opts)
    ctx.write(summary(rows, spec_answers) + "".join(n + "\n" for n in notes))


def summary(rows: list[dict[str, Any]], answers: tuple[str, ...]) -> str:
    """How many designs gave each answer, one line per answer."""
    errors = sum(1 for r in rows if r.get("error"))
    lines = [f"{len(rows)} designs, {errors} with errors"]
    for a in answers:
        counts: dict[Any, int] = {}
        for r in rows:
            v = r.get(a, "")
            if v != "":
                counts[v] = counts.get(v, 0) + 1
        order = sorted(counts, key=lambda v: (-counts[v], str(v)))
        lines.append(f"{a}: " + ", ".join(f"{v} {counts[v]}" for v in order))
    return "\n".join(lines) + "\n"


@command("sweepMap", lib="mechanism.lib")
def sweep_map_cmd(m: Mechanism, table: str, x: str, y: str, answer: str, picture: str) -> None:
    """sweepMap(m, table, x, y, answer, picture): draws the answer of a sweep's table (a .csv file
    written by sweep) over the designs' parameters x and y, with the length conditions of m (where
    singular configurations appear) as curves; picture ends in .png or .svg.

    Example:
      LIB "mechanism.lib";
      mechanism fb { ground O A 2; bar O B l1; bar B C l2; bar C A 4; }
      sweepMap(fb, "nosuch.csv", "l1", "l2", "grashof", "map.png");
      → <stdin>:3:1: error: sweepMap: no table nosuch.csv (write it with sweep(m, designs, answers, "nosuch.csv"))
      → sweepMap(fb, "nosuch.csv", "l1", "l2", "grashof", "map.png");
      → ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
    """
    path = output_file(picture, (".png", ".svg"))
    source = output_file(table, (".csv",))
    if not source.is_file():
        raise MechRuntimeError(f"sweepMap: no table {table} (write it with sweep(m, designs, answers, \"{table}\"))")
    _, rows = read_rows(str(source))
    rows = [typed(r) for r in rows]
    draw_map(rows, x, y, answer, str(path), map_curves(m, rows, x, y))
