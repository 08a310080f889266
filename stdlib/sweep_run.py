"""Running a sweep: batches of designs on Dask, rows written as they come, resuming.

* Where: ``scheduler=None`` starts a Dask ``LocalCluster`` on this machine (``workers`` processes,
  default one per core, one thread each: the analyses hold the GIL) and stops it at the end;
  ``scheduler="tcp://host:8786"`` (or a ``distributed.Client``) runs the same tasks on that cluster
  (its workers need mech installed); ``scheduler="inline"`` runs in this process (no Dask).
* Batches: designs are grouped so that every worker gets about ``BATCHES_PER_WORKER`` tasks
  (at most ``MAX_BATCH`` designs each): per-task overhead stays small and the load balanced.
* Results: each finished batch's rows are appended to the CSV file at once (flushed); when the
  file exists, the designs it already holds (by ``id``) are not computed again, so an interrupted
  sweep resumes where it stopped. With pyarrow installed a Parquet copy of the whole table is
  written at the end too.
* Progress: a bar on standard error when it is a terminal; ``on_row(row, done, total)`` is called
  for every finished design.
"""
from __future__ import annotations

import csv
import math
import os
import sys
import time
from typing import Any, Callable, Iterator

from mech.dsl.errors import MechRuntimeError
from mech.stdlib.sweep import STOPPED, Shared, SweepSpec, check_parameters, run_batch, shared_work
from mech.stdlib.sweep_designs import DesignSet

BATCHES_PER_WORKER = 8
MAX_BATCH = 64
SHARED_CURVES = 20.0            # seconds for the discriminant curves, at least
CURVE_SECONDS_PER_DESIGN = 0.25  # and this per design to do
CURVES_LIMIT = 300.0            # at most

OnRow = Callable[[dict[str, Any], int, int], None]


def batches(items: list[Any], workers: int, size: int | None = None) -> list[list[Any]]:
    """``items`` cut into consecutive batches (``size`` each, or sized for ``workers``)."""
    if size is None:
        size = max(1, min(MAX_BATCH, math.ceil(len(items) / (max(1, workers) * BATCHES_PER_WORKER))))
    return [items[i:i + size] for i in range(0, len(items), size)]


def read_rows(path: str) -> tuple[list[str], list[dict[str, str]]]:
    """The header and the rows of a sweep's CSV file (an unfinished last line dropped)."""
    with open(path, newline="", encoding="utf-8") as fh:
        text = fh.read()
    if text and not text.endswith("\n"):  # interrupted in the middle of a line
        text = text[:text.rfind("\n") + 1]
    lines = list(csv.reader(text.splitlines()))
    if not lines:
        return [], []
    header = lines[0]
    return header, [dict(zip(header, r)) for r in lines[1:] if len(r) == len(header)]


class _Table:
    """The CSV file, opened for appending (header written when new)."""

    def __init__(self, path: str | None, columns: list[str]) -> None:
        self.path, self.columns, self.done = path, columns, {}
        self.fh = None
        if path is None:
            return
        if os.path.exists(path) and os.path.getsize(path):
            header, rows = read_rows(path)
            if header != columns:
                raise MechRuntimeError(f"sweep: {path} holds another sweep's table (columns "
                                       f"{','.join(header)}); remove it or write elsewhere")
            self.done = {int(r["id"]): r for r in rows}
            with open(path, "r+", encoding="utf-8") as fh:  # drop an unfinished last line
                text = fh.read()
                keep = text[:text.rfind("\n") + 1]
                if keep != text:
                    fh.seek(0), fh.truncate(), fh.write(keep)
            self.fh = open(path, "a", newline="", encoding="utf-8")
        else:
            self.fh = open(path, "w", newline="", encoding="utf-8")
            csv.writer(self.fh).writerow(columns)
            self.fh.flush()
        self.writer = csv.writer(self.fh)

    def write(self, rows: list[dict[str, Any]]) -> None:
        if self.fh is not None:
            self.writer.writerows([[r.get(c, "") for c in self.columns] for r in rows])
            self.fh.flush()

    def close(self) -> None:
        if self.fh is not None:
            self.fh.close()


class _Bar:
    """A one-line progress bar on standard error (only on a terminal)."""

    def __init__(self, total: int, show: bool | None) -> None:
        self.total, self.start, self.last = total, time.monotonic(), 0.0
        self.show = show if show is not None else _is_terminal(sys.stderr)

    def update(self, done: int) -> None:
        now = time.monotonic()
        if not self.show or (now - self.last < 0.2 and done < self.total):
            return
        self.last = now
        rate = done / max(now - self.start, 1e-9)
        left = (self.total - done) / rate if rate else 0
        filled = int(30 * done / max(self.total, 1))
        sys.stderr.write(f"\rsweep [{'#' * filled}{'.' * (30 - filled)}] {done}/{self.total} "
                         f"{rate:.1f} designs/s, {left:.0f} s left ")
        if done >= self.total:
            sys.stderr.write("\n")
        sys.stderr.flush()


def _is_terminal(stream: Any) -> bool:
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError, OSError):
        return False


def prepare(spec: SweepSpec, designs: DesignSet) -> tuple[SweepSpec, list[str]]:
    """The spec with the parameters that are equal in every design set in the mechanism, and the
    parameters that vary (the shared work is over those alone)."""
    check_parameters(spec.mechanism, designs.names)
    const = {n: designs.designs[0][n] for n in designs.names
             if designs.designs and all(d[n] == designs.designs[0][n] for d in designs.designs)}
    values = {k: (int(v) if v.denominator == 1 else v) for k, v in const.items()}
    varying = [n for n in designs.names if n not in const]
    return SweepSpec(spec.mechanism.with_values(values), spec.answers, spec.timeout, spec.deadline), varying


def run_sweep(spec: SweepSpec, designs: DesignSet, out: str | None = None, *, scheduler: Any = None,
              workers: int | None = None, batch: int | None = None, progress: bool | None = None,
              on_row: OnRow | None = None, shared: bool | None = None,
              notes: list[str] | None = None) -> list[dict[str, Any]]:
    """All rows of the sweep (those already in ``out`` included), ordered by design id. ``shared``:
    compute the generic length conditions first (default: when singular configurations are asked
    for, the answer they save work on) and, for real counts over two parameters, the discriminant
    curves (default: yes, unless ``shared`` is False; designs in one cell of them are analysed
    once). ``notes`` receives a line on the curves (found, used, or why not). Under a statement's
    time limit (``mech --timeout``) the sweep stops before it with the rows done kept, and raises
    the limit's error saying so; per-design limits end by then too."""
    from mech.dsl.limits import LimitExceeded, MechLimitError, TimeLimitExceeded, limit_error, remaining
    from mech.kernel.progress import stage
    work_spec, varying = prepare(spec, designs)
    left = remaining()
    work_spec.deadline = None if left is None else time.time() + left
    columns = spec.columns(designs.names)
    table = _Table(out, columns)
    total, done, stopped = len(designs.designs), len(table.done), 0
    rows: dict[int, dict[str, Any]] = {i: typed(r) for i, r in table.done.items()}
    try:
        with stage("sweep", total=total) as progress_stage:
            todo = [(i, d) for i, d in enumerate(designs.designs) if i not in table.done]
            bar = _Bar(total, progress)
            bar.update(done)
            progress_stage.step(done, f"{done}/{total} designs")
            common = shared_work(work_spec, varying) if todo and (shared or (shared is None and "singular" in spec.answers)) \
                else Shared(varying)
            later: dict[int, tuple[int, dict]] = {}
            if todo and shared is not False and "real" in spec.answers and len(varying) == 2:
                later = _classify(work_spec, designs, varying, common, todo, rows, notes)
                todo = [t for t in todo if t[0] not in later]

            def finish(got: list[dict[str, Any]]) -> None:
                nonlocal done, stopped
                kept = [r for r in got if r.get("error") != STOPPED]
                stopped += len(got) - len(kept)
                table.write(kept)
                for r in kept:
                    r = typed({c: "" if r.get(c) is None else str(r.get(c, "")) for c in columns})
                    rows[r["id"]] = r
                    done += 1
                    if on_row is not None:
                        on_row(r, done, total)
                bar.update(done)
                progress_stage.step(done, f"{done}/{total} designs")

            def inherit() -> None:
                ready = [i for i, (src, _) in later.items() if src in rows and _usable(rows[src])]
                if ready:
                    finish([_inherit(rows[later[i][0]], i, later.pop(i)[1]) for i in ready])
            inherit()
            for got in _execute(work_spec, common, todo, scheduler, workers, batch):
                finish(got)
                inherit()
            if later and not stopped:  # designs whose cell's representative failed: analysed themselves
                for got in _execute(work_spec, common, [(i, d) for i, (_, d) in sorted(later.items())], scheduler,
                                    workers, batch):
                    finish(got)
    except LimitExceeded as e:  # the statement's limit fired before the designs noticed it
        stopped = stopped or 1
        error = limit_error(e)
    else:
        error = limit_error(TimeLimitExceeded()) if stopped else None
    finally:
        table.close()
    if stopped:
        kept = f"; they are in {out}: the same sweep resumes there" if out else ""
        raise MechLimitError(f"{error.message if error else 'time limit exceeded'}: the sweep stopped after "
                             f"{done} of {total} designs{kept}")
    result = [rows[i] for i in sorted(rows)]
    if out is not None:
        _parquet(out, columns, result)
    return result


def _classify(spec: SweepSpec, designs: DesignSet, varying: list[str], common: Shared, todo: list,
              rows: dict[int, dict[str, Any]], notes: list[str] | None) -> dict[int, tuple[int, dict]]:
    """With the discriminant curves (put in ``common``): the designs to take from another design of
    their cell (a grid's or any design set's, :mod:`mech.stdlib.sweep_cells`), as id -> (that
    design's id, design); the others stay to do. Only real counts and mobility are taken (every
    other answer needs its own analysis)."""
    from mech.stdlib.sweep_cells import design_cells
    from mech.stdlib.sweep_discriminant import curve_label, mechanism_curves
    budget = min(CURVES_LIMIT, max(SHARED_CURVES, CURVE_SECONDS_PER_DESIGN * len(todo)))
    if spec.deadline is not None:  # under a statement's limit: half of what remains at most
        budget = min(budget, max(0.0, (spec.deadline - time.time()) / 2))
    curves = mechanism_curves(spec.mechanism, varying, budget)
    common.curves = curves.factors
    common.curve_labels = [curve_label(n, k) for k, n in enumerate(curves.names)]
    say = notes.append if notes is not None else (lambda _: None)
    if not curves.factors:
        say(f"{curves.note}: every design analysed")
        return {}
    found = f"discriminant curves in ({', '.join(varying)}): {', '.join(common.curve_labels)}"
    if not set(spec.answers) <= {"mobility", "real"}:
        say(f"{found} (named in conditions; every design analysed for the other answers)")
        return {}
    cells = design_cells({i: (d[varying[0]], d[varying[1]]) for i, d in enumerate(designs.designs)}, curves.factors)
    source: dict[int, int] = {}  # a cell's analysed design: one already done, else its smallest id
    for i, g in sorted(cells.items()):
        if i in rows and _usable(rows[i]):
            source.setdefault(g, i)
    todo_ids = {i for i, _ in todo}
    later = {}
    for i, d in todo:
        g = cells[i]
        src = source.setdefault(g, i)
        if src != i and (src in todo_ids or src in rows):
            later[i] = (src, d)
    say(f"{found}; {len(later)} of {len(todo)} designs take the count of an analysed design of their cell")
    return later


def _usable(row: dict[str, Any]) -> bool:
    return not row.get("error") and row.get("real", "") != ""


def _inherit(src: dict[str, Any], ident: int, design: dict) -> dict[str, Any]:
    """The row of a design in the same cell as the analysed row ``src``."""
    from mech.stdlib.sweep import _show
    row = {"id": ident, **{k: _show(v) for k, v in design.items()}}
    for c in ("mobility", "real"):
        if c in src:
            row[c] = src[c]
    row.update(conditions=f"same cell as {src['id']}", seconds=0.0, error="")
    return row


def _execute(spec: SweepSpec, shared: Shared, todo: list, scheduler: Any, workers: int | None,
             batch: int | None) -> Iterator[list[dict[str, Any]]]:
    """The rows of the designs to do, batch by batch as they finish."""
    if not todo:
        return
    if scheduler == "inline":  # one design at a time: each row is kept as soon as it is done
        for item in todo:
            yield run_batch(spec, shared, [item])
        return
    from distributed import Client, LocalCluster, as_completed
    cluster = None
    if scheduler is None:
        n = workers or os.cpu_count() or 1
        cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=":0")
        client = Client(cluster)
    elif isinstance(scheduler, Client):
        client = scheduler
    else:
        client = Client(scheduler)
    try:
        n = max(1, len(client.scheduler_info().get("workers", {})) or (workers or 1))
        parts = batches(todo, n, batch)
        spec_f, shared_f = client.scatter([spec, shared], broadcast=True)
        futures = {client.submit(run_batch, spec_f, shared_f, b, pure=False): b for b in parts}
        for fut in as_completed(futures):
            try:
                yield fut.result()
            except Exception as e:  # noqa: BLE001 - a lost worker: the batch's rows record it
                yield [_failed(i, d, e) for i, d in futures[fut]]
    finally:
        if client is not scheduler:
            client.close()
        if cluster is not None:
            cluster.close()


_INTS = ("id", "mobility", "modes", "real", "singular")


def typed(row: dict[str, str]) -> dict[str, Any]:
    """A row as read from the CSV file with its numbers as numbers (parameters stay exact strings)."""
    out: dict[str, Any] = dict(row)
    for c in _INTS:
        if out.get(c, "").lstrip("-").isdigit():
            out[c] = int(out[c])
    if out.get("seconds"):
        out["seconds"] = float(out["seconds"])
    return out


def _failed(ident: int, design: dict, e: BaseException) -> dict[str, Any]:
    from mech.stdlib.sweep import _show
    return {"id": ident, **{k: _show(v) for k, v in design.items()}, "error": f"task failed: {type(e).__name__}: {e}"}


def _parquet(out: str, columns: list[str], rows: list[dict[str, Any]]) -> None:
    """A Parquet copy of the table beside the CSV file, when pyarrow is installed."""
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError:
        return
    base = out[:-4] if out.endswith(".csv") else out
    data = {c: [str(r.get(c, "")) for r in rows] for c in columns}
    pq.write_table(pa.table(data), base + ".parquet")
