"""Design-space sweeps from Python and from the command line (``mech sweep FILE ...``); the
machinery is :mod:`mech.stdlib.sweep` and its neighbours, the guide docs/sweeps.md.

    from mech.sweep import sweep
    table = sweep("ground O A 2; bar O B l1; bar B C l2; bar C A 4", "grid l1=1:5:50 l2=1:5:50",
                  ["grashof"], "fourbar.csv")

returns a pandas DataFrame when pandas is installed, else a list of dicts (one per design).
"""
from __future__ import annotations

import argparse
import sys
from typing import Any, Callable, Optional

from .dsl.errors import MechError


def _mechanism(m: Any) -> Any:
    from .stdlib.mechanism import to_mechanism
    return to_mechanism(m)


def sweep(mechanism: Any, designs: str, answers: Any = ("mobility", "real"), out: Optional[str] = None, *,
          scheduler: Any = None, workers: Optional[int] = None, timeout: Optional[float] = None,
          batch: Optional[int] = None, progress: Optional[bool] = None,
          callback: Optional[Callable[[dict[str, Any], int, int], None]] = None,
          frame: Optional[bool] = None, notes: Optional[list[str]] = None) -> Any:
    """Analyse ``mechanism`` (a ``Mechanism`` value or its description) at every design.

    ``designs``: ``"grid l1=a:b:n ..."``, ``"random N l1=a:b ... seed=S"``, ``"lhs N ..."`` or
    ``"csv FILE"``; ``answers``: names among mobility, modes, real, grashof, singular; ``out``: the
    CSV file written as designs finish (an existing one is resumed); ``scheduler``: None (a Dask
    LocalCluster with ``workers`` processes, default one per core), a scheduler address
    ``"tcp://host:8786"``, a ``distributed.Client``, or ``"inline"`` (this process);
    ``timeout``: seconds per design; ``callback(row, done, total)`` after each design; ``notes``
    receives a line on the discriminant curves. A DataFrame (pandas installed and ``frame`` not
    False) or a list of dicts."""
    from .stdlib.sweep_commands import sweep_rows
    rows = sweep_rows(_mechanism(mechanism), designs, answers, out, scheduler=scheduler, workers=workers,
                      timeout=timeout, batch=batch, progress=progress, on_row=callback, notes=notes)
    if frame is not False:
        try:
            import pandas
        except ImportError:
            if frame:
                raise
            return rows
        return pandas.DataFrame(rows)
    return rows


def sweep_map(mechanism: Any, rows: Any, x: str, y: str, answer: str, path: str) -> None:
    """Draw ``answer`` over the parameters ``x`` and ``y`` of a sweep's rows (a list of dicts or a
    DataFrame) to ``path`` (.png or .svg), with the mechanism's length conditions as curves."""
    from .stdlib.sweep_commands import map_curves
    from .stdlib.sweep_map import draw_map
    if hasattr(rows, "to_dict"):
        rows = rows.to_dict("records")
    m = _mechanism(mechanism)
    draw_map(list(rows), x, y, answer, path, map_curves(m, list(rows), x, y))


# ---------------------------------------------------------------- mech sweep FILE ...
def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="mech sweep", description="Analyse a mechanism of FILE at many designs "
                                "(docs/sweeps.md).")
    p.add_argument("file", help="a script (.mech) that defines the mechanism")
    p.add_argument("--mechanism", metavar="NAME", help="the mechanism variable (default: the script's only one)")
    p.add_argument("--designs", required=True, metavar="SPEC", help="'grid l1=a:b:n ...', 'random N l1=a:b ... "
                   "[seed=S]', 'lhs N ...' or 'csv FILE'")
    p.add_argument("--answers", default="mobility,real", help="mobility, modes, real, grashof, singular "
                   "(comma-separated; default mobility,real)")
    p.add_argument("--out", metavar="CSV", help="the table (resumed when it exists); default FILE's name .csv")
    p.add_argument("--map", metavar="X,Y,ANSWER,PICTURE", action="append", default=[],
                   help="also draw ANSWER over parameters X and Y to PICTURE (.png or .svg)")
    p.add_argument("--scheduler", metavar="ADDRESS", help="a Dask scheduler (tcp://host:8786), or 'inline'; "
                   "default: a local Dask cluster on all cores")
    p.add_argument("--workers", type=int, metavar="N", help="local worker processes (default: one per core)")
    p.add_argument("--timeout", type=float, metavar="SECONDS", help="time limit per design (a design over it is "
                   "recorded with the error and the sweep goes on)")
    p.add_argument("--total-timeout", type=float, metavar="SECONDS", help="time limit of the whole sweep: it stops "
                   "before, with the rows done kept in the table, and running it again resumes (as "
                   "'mech --timeout SECONDS sweep ...')")
    p.add_argument("--batch", type=int, metavar="N", help="designs per task (default: sized to the workers)")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    return p


def main(argv: list[str], total_timeout: Optional[float] = None, max_memory: Optional[float] = None) -> int:
    """``mech sweep ...``: the exit status. ``total_timeout`` (``mech --timeout T sweep``) and
    ``max_memory`` limit the whole sweep as one statement."""
    try:
        args = _parser().parse_args(argv)
    except SystemExit as e:
        return e.code if isinstance(e.code, int) else 2
    if args.total_timeout is not None and total_timeout:
        sys.stderr.write("mech sweep: error: give the sweep's time limit once (--total-timeout, or mech --timeout "
                         "before sweep)\n")
        return 2
    total = args.total_timeout if args.total_timeout is not None else total_timeout
    if total is not None and not 0 <= total < float("inf") or args.timeout is not None and not 0 < args.timeout < float("inf"):
        sys.stderr.write("mech sweep: error: time limits must be positive numbers of seconds\n")
        return 2
    from .session import Session
    from .stdlib.mechanism import Mechanism
    try:
        with open(args.file, encoding="utf-8-sig") as fh:
            text = fh.read()
    except OSError as e:
        sys.stderr.write(f"mech: error: cannot read {args.file}: {e.strerror}\n")
        return 2
    try:
        s = Session()
        s.execute(text)
        found = {n: v.value for n, v in s.interpreter.globals.items() if isinstance(getattr(v, "value", None), Mechanism)}
        if args.mechanism:
            if args.mechanism not in found:
                raise _Usage(f"{args.file} defines no mechanism '{args.mechanism}' (it has {', '.join(found) or 'none'})")
            m = found[args.mechanism]
        elif len(found) == 1:
            m = next(iter(found.values()))
        else:
            raise _Usage(f"{args.file} defines {len(found)} mechanisms ({', '.join(found)}): choose one with --mechanism")
        from .stdlib.sweep_commands import map_curves, summary
        from .stdlib.sweep import parse_answers
        from .stdlib.sweep_map import draw_map
        out = args.out or (args.file.rsplit(".", 1)[0] + ".csv")
        answers = parse_answers(args.answers)
        notes: list[str] = []

        def run() -> list[dict[str, Any]]:
            return sweep_rows(m, args.designs, answers, out, scheduler=args.scheduler, workers=args.workers,
                              timeout=args.timeout, batch=args.batch, notes=notes,
                              progress=False if args.no_progress else None)
        from .dsl.limits import Limits
        from .stdlib.sweep_commands import sweep_rows
        rows = Limits(total or 0, max_memory or 0).run(s.interpreter, run)
        for spec in args.map:
            parts = spec.split(",")
            if len(parts) != 4:
                raise _Usage(f"--map {spec}: expected X,Y,ANSWER,PICTURE")
            x, y, answer, picture = parts
            draw_map(rows, x, y, answer, picture, map_curves(m, rows, x, y))
    except _Usage as e:
        sys.stderr.write(f"mech sweep: error: {e}\n")
        return 2
    except MechError as e:
        sys.stderr.write(e.format() if getattr(e, "pos", None) is not None else f"mech sweep: error: {e.message}\n")
        return 1
    sys.stdout.write(summary(rows, answers) + "".join(n + "\n" for n in notes) + f"table: {out}\n")
    return 0


class _Usage(Exception):
    """A mistake in the command line (exit status 2)."""
