"""Design-space sweeps: design sets, rows against direct single analyses and Grashof's inequality,
time limits, resuming, a real Dask LocalCluster, the language's commands, the CLI and the Python
API, and docs/sweeps.md's examples."""
from __future__ import annotations

import csv
import re
import shlex
import time
from fractions import Fraction

import pytest

from mech import MechError, Session
from mech.stdlib.analysis import global_analysis, local_analysis
from mech.stdlib.mechanism import parse_mechanism
from mech.stdlib.sweep_commands import sweep_rows
from mech.stdlib.sweep_designs import design_set
from mech.kernel.engines import clear_cache
from tests.util import ROOT

FOURBAR = "ground O A g; bar O B l1; bar B C l2; bar C A l3"
WATT = "ground O A 1; fix G g 0; bar O B 1; bar B C 1; body A C 1 0 E 0 1; bar E F 1; bar F G l"
RPR = "fix A1 0 0; fix A2 5 0; fix A3 6 6; bar A1 B1 r1; body B1 B2 4 0 B3 2 3; bar A2 B2 r2; bar A3 B3 r3"


def same(a, b):
    """Tables equal but for the time taken."""
    strip = [{k: v for k, v in r.items() if k != "seconds"} for r in a]
    return strip == [{k: v for k, v in r.items() if k != "seconds"} for r in b]


# ---------------------------------------------------------------- design sets
def test_grid_is_exact_and_ordered():
    ds = design_set("grid a=0:1:3 b=2 c=1/2:3/2:2")
    assert ds.names == ["a", "b", "c"]
    assert [tuple(d.values()) for d in ds.designs] == [
        (0, 2, Fraction(1, 2)), (0, 2, Fraction(3, 2)), (Fraction(1, 2), 2, Fraction(1, 2)),
        (Fraction(1, 2), 2, Fraction(3, 2)), (1, 2, Fraction(1, 2)), (1, 2, Fraction(3, 2))]


def test_latin_hypercube_has_one_point_per_slice_and_a_seed():
    ds = design_set("lhs 10 a=0:1 b=2:4 seed=3 digits=6")
    for name, (lo, hi) in (("a", (0, 1)), ("b", (2, 4))):
        slots = sorted(int((d[name] - lo) / (hi - lo) * 10) for d in ds.designs)
        assert slots == list(range(10))
    assert ds.designs == design_set("lhs 10 a=0:1 b=2:4 seed=3 digits=6").designs
    assert ds.designs != design_set("lhs 10 a=0:1 b=2:4 seed=4 digits=6").designs
    r = design_set("random 5 a=1:2 seed=1").designs
    assert len(r) == 5 and all(1 <= d["a"] <= 2 and (d["a"] * 1000).denominator == 1 for d in r)


def test_csv_designs(tmp_path):
    f = tmp_path / "d.csv"
    f.write_text("l1,l2\n1,2.5\n3/2,4\n")
    assert design_set(f"csv {f}").designs == [{"l1": 1, "l2": Fraction(5, 2)}, {"l1": Fraction(3, 2), "l2": 4}]


@pytest.mark.parametrize("text, message", [
    ("cube a=1:2:3", "unknown kind"), ("grid a=1:2", "expected NAME=a:b:n"), ("grid a=1:x:3", "not a number"),
    ("lhs a=1:2", "positive count"), ("grid", "no parameter")])
def test_bad_design_sets(text, message):
    with pytest.raises(MechError, match=message):
        design_set(text)


# ---------------------------------------------------------------- rows against truth
def grashof_truth(g, a, b, c):
    """Grashof's inequality and the position of the shortest link, by hand."""
    links = [g, a, b, c]
    s, l = min(links), max(links)
    rest = sorted(links)[1:3]
    if s + l > sum(rest):
        return "non-Grashof"
    if s + l == sum(rest):
        return "change point"
    shortest = links.index(s)
    return {0: "double-crank", 1: "crank-rocker", 2: "double-rocker", 3: "crank-rocker"}[shortest]


def test_grashof_types_agree_with_the_inequality_on_every_design():
    rows = sweep_rows(parse_mechanism(FOURBAR), "grid g=2 l1=1/2:5:10 l2=1/2:5:10 l3=4", "grashof",
                      scheduler="inline")
    assert len(rows) == 100 and not any(r["error"] for r in rows)
    for r in rows:
        lengths = [Fraction(r[k]) for k in ("g", "l1", "l2", "l3")]
        assert r["grashof"] == grashof_truth(*lengths), r
    assert {r["grashof"] for r in rows} >= {"crank-rocker", "double-crank", "double-rocker", "non-Grashof"}


def test_rows_agree_with_single_analyses():
    m = parse_mechanism(FOURBAR)
    rows = sweep_rows(m, "grid g=2 l1=1:3:3 l2=2:3:2 l3=3", "mobility,modes,real,singular", scheduler="inline")
    s = Session()
    s.execute('LIB "mechanism.lib";')
    for r in rows:
        one = m.with_values({k: int(r[k]) for k in ("g", "l1", "l2", "l3")})
        a = global_analysis(one)
        points = local_analysis(a)
        assert (r["mobility"], r["modes"], r["singular"]) == (a.mobility, len(a.modes), len(points)), r
        assert r["singular_types"] == "; ".join(p.kind for p in points)
        s.execute(f'mechanism m = "{one}"; def q = configurationRing(m); setring q; ideal J = constraints(m);')
        assert r["real"] == s.eval("realCircuits(J)")
    # the shared length conditions skipped the designs on none of them, and named the others
    assert [r["conditions"] for r in rows if r["singular"]] == [c for c in (r["conditions"] for r in rows) if c]
    assert any(r["singular"] == 0 and not r["conditions"] for r in rows)


def independent_3rpr_count(r1, r2, r3):
    """Real assembly modes in position coordinates (B1 = (x, y), platform turned by (c, s))."""
    s = Session()
    s.execute(f"""ring q = 0,(x,y,c,s),dp;
        poly b2x = x + 4c - 5; poly b2y = y + 4s;
        poly b3x = x + 2c - 3s - 6; poly b3y = y + 2s + 3c - 6;
        ideal I = x2 + y2 - ({r1})^2, b2x^2 + b2y^2 - ({r2})^2, b3x^2 + b3y^2 - ({r3})^2, c2 + s2 - 1;""")
    return s.eval("countRealSolutions(I)").values[1]


def test_3rpr_real_assembly_modes_agree_with_independent_counts():
    rows = sweep_rows(parse_mechanism(RPR), "grid r1=5:8:4 r2=4:7:4 r3=4", "mobility,real", scheduler="inline")
    counts = {r["real"] for r in rows}
    assert len(counts) >= 3, counts  # the grid crosses regions with different counts
    for r in rows[::3]:
        assert r["mobility"] == 0
        assert r["real"] == independent_3rpr_count(r["r1"], r["r2"], r["r3"]), r


# ---------------------------------------------------------------- failures, limits, resuming
def test_a_failure_or_a_timeout_is_recorded_and_the_sweep_goes_on():
    rows = sweep_rows(parse_mechanism(FOURBAR), "grid g=0:2:2 l1=1 l2=3 l3=3", "grashof,mobility",
                      scheduler="inline")
    # g = 0 is no mechanism (the description's checks refuse a zero length): recorded, and the next design runs
    assert "the ground length is 0" in rows[0]["error"] and rows[1]["error"] == "" and rows[1]["mobility"] == 1
    clear_cache()                       # bases cached by earlier tests would finish within the 1 ms limit
    # a Watt six-bar's modes and real answers take over a second a design: far past the watchdog's poll (the
    # four-bar's modes now finish within one poll, so its 1 ms limit was not always seen)
    slow = sweep_rows(parse_mechanism(WATT), "grid g=2 l=1:2:2", "modes,real", scheduler="inline", timeout=0.001)
    assert len(slow) == 2 and all("time limit of 0.001 s exceeded" in r["error"] for r in slow)


def test_a_statement_time_limit_stops_the_sweep_with_its_rows_kept_and_resumable(tmp_path, monkeypatch):
    """Under ``mech --timeout T`` (here Session(timeout=T)) the sweep stops at T even with a larger
    per-design limit, says so, keeps the rows done; running it again computes only the others."""
    import time
    monkeypatch.chdir(tmp_path)
    s = Session(timeout=0.5, scheduler="inline")
    s.execute(f'LIB "mechanism.lib"; mechanism rpr {{ {RPR}; }}')
    start = time.monotonic()
    with pytest.raises(MechError) as e:
        s.execute('sweep(rpr, "grid r1=1:12:12 r2=1:24:24 r3=4", "real", "lim.csv", "timeout=60 shared=no");')
    assert time.monotonic() - start < 0.5 + 10  # wall clock: generous on a loaded machine; kept < 288 shows the stop
    kept = (tmp_path / "lim.csv").read_text().count("\n") - 1
    assert re.search(r"time limit of 0.5 s exceeded: the sweep stopped after (\d+) of 288 designs; they are in "
                     r".*lim.csv: the same sweep resumes there", str(e.value)), str(e.value)
    assert 0 <= kept < 288 and f"after {kept} of 288" in str(e.value)  # 0 only when the machine is very loaded
    computed = []
    rows = sweep_rows(parse_mechanism(RPR), "grid r1=1:12:12 r2=1:24:24 r3=4", "real", str(tmp_path / "lim.csv"),
                      scheduler="inline", on_row=lambda row, done, total: computed.append(row["id"]))
    assert len(computed) == 288 - kept and len(rows) == 288 and not any(r["error"] for r in rows)
    full = sweep_rows(parse_mechanism(RPR), "grid r1=1:12:12 r2=1:24:24 r3=4", "real", scheduler="inline")
    assert [r["real"] for r in rows] == [r["real"] for r in full]


def test_the_language_sweep_reports_progress():
    """``sweep(...)`` in a script reports a "sweep" stage (a bar on a terminal, as the CLI's)."""
    events = []
    Session(scheduler="inline", progress=events.append).execute(
        f'LIB "mechanism.lib"; mechanism fb {{ {FOURBAR}; }} sweep(fb, "grid g=2 l1=1:4:4 l2=3 l3=3", "grashof");')
    mine = [e for e in events if e.stage == "sweep" and not e.path]
    assert mine[0].kind == "start" and mine[0].total == 4 and mine[-1].kind == "end" and mine[-1].status == "done"
    assert [e.done for e in mine if e.kind == "step"][-1] == 4


def test_resuming_computes_no_design_twice(tmp_path):
    m, designs = parse_mechanism(FOURBAR), "grid g=2 l1=1:4:4 l2=2:5:4 l3=3"
    full = sweep_rows(m, designs, "grashof,mobility", scheduler="inline")
    out = tmp_path / "t.csv"
    sweep_rows(m, designs, "grashof,mobility", str(out), scheduler="inline")
    lines = out.read_text().splitlines(keepends=True)
    out.write_text("".join(lines[:6]) + lines[6][:5])  # interrupted: 5 rows and part of a line
    seen = []
    again = sweep_rows(m, designs, "grashof,mobility", str(out), scheduler="inline",
                       on_row=lambda row, done, total: seen.append((row["id"], done, total)))
    assert sorted(i for i, _, _ in seen) == list(range(5, 16)) and seen[-1][1:] == (16, 16)
    assert same(again, full)
    with open(out, newline="") as fh:
        assert sorted(int(r["id"]) for r in csv.DictReader(fh)) == list(range(16))
    with pytest.raises(MechError, match="another sweep"):
        sweep_rows(m, designs, "grashof", str(out), scheduler="inline")


def test_a_dask_local_cluster_gives_the_same_table(tmp_path):
    distributed = pytest.importorskip("distributed")
    m, designs = parse_mechanism(FOURBAR), "grid g=2 l1=1:3:3 l2=2:3:2 l3=3"
    local = sweep_rows(m, designs, "mobility,real,singular", scheduler="inline")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=":0") as cluster, distributed.Client(cluster) as client:
        remote = sweep_rows(m, designs, "mobility,real,singular", str(tmp_path / "d.csv"),
                            scheduler=cluster.scheduler_address, batch=2)
        assert len(client.scheduler_info()["workers"]) == 2
    assert same(remote, local)


# ---------------------------------------------------------------- the entry points
def test_the_language_command_and_the_map(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    s = Session(scheduler="inline")
    out = s.execute('LIB "mechanism.lib"; mechanism fb { ground O A 2; bar O B l1; bar B C l2; bar C A 4; }'
                    'sweep(fb, "grid l1=1:5:5 l2=1:5:5", "grashof", "t.csv");'
                    'sweepMap(fb, "t.csv", "l1", "l2", "grashof", "t.svg");')
    assert out.splitlines()[0] == "25 designs, 0 with errors"
    assert (tmp_path / "t.svg").read_text().count("<path") > 20
    with pytest.raises(MechError, match="scripts read no files"):
        s.execute('sweep(fb, "csv d.csv");')
    with pytest.raises(MechError, match="unknown answer 'speed'"):
        s.execute('sweep(fb, "grid l1=1:2:2 l2=1", "speed", "", "scheduler=inline");')
    with pytest.raises(MechError, match="designs give no value to l2"):
        s.execute('sweep(fb, "grid l1=1:2:2", "grashof", "", "scheduler=inline");')


def test_the_cli_subcommand(tmp_path, capsys):
    from mech.cli import main
    script = tmp_path / "fb.mech"
    script.write_text('LIB "mechanism.lib";\nmechanism fb { ground O A 2; bar O B l1; bar B C l2; bar C A 4; }\n')
    status = main(["sweep", str(script), "--designs", "grid l1=1:5:5 l2=1:5:5", "--answers", "grashof",
                   "--scheduler", "inline", "--map", f"l1,l2,grashof,{tmp_path / 'm.png'}"])
    assert status == 0
    assert capsys.readouterr().out.splitlines()[-1] == f"table: {tmp_path / 'fb.csv'}"
    assert (tmp_path / "m.png").stat().st_size > 1000
    assert main(["sweep", str(script), "--designs", "grid l1=1", "--scheduler", "inline"]) == 1
    assert "designs give no value to l2" in capsys.readouterr().err
    assert main(["sweep", str(script)]) == 2  # --designs is required


def test_the_cli_whole_sweep_time_limit_keeps_the_rows_and_resumes(tmp_path, capsys, monkeypatch):
    """``mech sweep --timeout`` is per design; ``--total-timeout T`` (or ``mech --timeout T sweep``)
    limits the whole sweep: it stops with the rows done in the table and says how to resume."""
    from mech.cli import main
    from mech.stdlib import sweep_run
    run_batch = sweep_run.run_batch

    def slow_batch(*args):  # each design at least 50 ms: the 144 outlast the 1 s limit on any machine
        time.sleep(0.05)
        return run_batch(*args)
    script = tmp_path / "rpr.mech"
    script.write_text(f'LIB "mechanism.lib";\nmechanism rpr {{ {RPR}; }}\n')
    grid = ["--designs", "grid r1=1:12:12 r2=1:12:12 r3=4", "--answers", "real", "--scheduler", "inline"]
    # each spelling writes its own table: a second run on the first's table would resume it and could finish
    for name, limit in (("total", ["sweep", str(script), "--total-timeout", "1"]),
                        ("rpr", ["--timeout", "1", "sweep", str(script)])):
        with monkeypatch.context() as patch:
            patch.setattr(sweep_run, "run_batch", slow_batch)
            assert main(limit + grid + ["--out", str(tmp_path / f"{name}.csv")]) == 1
        err = capsys.readouterr().err
        kept = (tmp_path / f"{name}.csv").read_text().count("\n") - 1
        assert re.fullmatch(rf"mech sweep: error: time limit of 1 s exceeded: the sweep stopped after {kept} of 144 "
                            rf"designs; they are in .*{name}.csv: the same sweep resumes there\n", err), err
    assert main(["--timeout", "1", "sweep", str(script), "--total-timeout", "1"] + grid) == 2
    assert "give the sweep's time limit once" in capsys.readouterr().err
    assert main(["--format", "json", "sweep", str(script)] + grid) == 2
    assert "--format does not apply to 'mech sweep'" in capsys.readouterr().err
    assert main(["sweep", str(script), "--total-timeout", "-1"] + grid) == 2
    assert main(["sweep", str(script)] + grid) == 0
    rows = list(csv.DictReader((tmp_path / "rpr.csv").read_text().splitlines()))
    assert sorted(int(r["id"]) for r in rows) == list(range(144))
    assert "discriminant curves in (r1, r2): r1, r2, D3; " in capsys.readouterr().out


def test_python_api_rows_or_a_data_frame():
    from mech.sweep import sweep
    rows = sweep(FOURBAR, "grid g=2 l1=1:2:2 l2=3 l3=3", ["grashof"], scheduler="inline", frame=False)
    assert [r["grashof"] for r in rows] == ["crank-rocker", "change point"]
    table = sweep(FOURBAR, "grid g=2 l1=1:2:2 l2=3 l3=3", ["grashof"], scheduler="inline")
    try:
        import pandas  # noqa: F401
        assert list(table["grashof"]) == ["crank-rocker", "change point"]
    except ImportError:
        assert same(table, rows)


def test_docs_examples_run(tmp_path, monkeypatch):
    """Each ```mech block of docs/sweeps.md prints the ```text block after it."""
    monkeypatch.chdir(tmp_path)
    text = (ROOT / "docs" / "sweeps.md").read_text()
    pairs = re.findall(r"```mech\n(.*?)```\n+```text\n(.*?)```", text, re.S)
    assert pairs
    for code, expected in pairs:
        assert Session(scheduler="inline").execute(code) == expected
    (tmp_path / "fb.mech").write_text(pairs[0][0].split("sweep(")[0])
    from mech.cli import main
    (command,) = re.findall(r"```sh\n(mech sweep .*?)\n```", text)
    assert main(shlex.split(command)[1:] + ["--scheduler", "inline", "--no-progress"]) == 0
    assert (tmp_path / "fb.csv").read_text().count("\n") == 401 and (tmp_path / "fb.png").is_file()
    (python,) = re.findall(r"```python\n(.*?)```", text, re.S)
    exec(python, {})  # the default: a Dask LocalCluster on all cores
    assert (tmp_path / "fb20.csv").read_text().count("\n") == 401 and (tmp_path / "fb20.png").is_file()


# ---------------------------------------------------------------- discriminant curves and cells
DYAD = "fix A 0 0; fix B 3 0; bar A P r1; bar B P r2"


def test_the_dyads_discriminant_curves_are_its_circle_conditions():
    from mech.stdlib.sweep_discriminant import mechanism_curves
    curves = mechanism_curves(parse_mechanism(DYAD), ["r1", "r2"], 60)
    # two circles of radii r1, r2 three apart meet in 2 real points inside |r1 - r2| < 3 < r1 + r2
    assert sorted(curves.names) == sorted(["r1", "r2", "r1+r2+3", "r1+r2-3", "r1-r2+3", "r1-r2-3"]) and curves.D == 2


def test_designs_in_one_cell_take_one_analysis_and_agree_with_all_analysed():
    from mech.stdlib.sweep_cells import check_cells
    from mech.stdlib.sweep_discriminant import mechanism_curves
    grid = "grid r1=1/2:6:12 r2=1/2:6:12"
    classified = sweep_rows(parse_mechanism(DYAD), grid, "mobility,real", scheduler="inline", shared=True)
    full = sweep_rows(parse_mechanism(DYAD), grid, "mobility,real", scheduler="inline", shared=False)
    assert same([{**r, "conditions": ""} for r in classified], [{**r, "conditions": ""} for r in full])
    inherited = [r for r in classified if r["conditions"].startswith("same cell as ")]
    assert 100 < len(inherited) < 144 and all(r["seconds"] == 0 for r in inherited)
    on_curve = [r for r in classified if {"r1-r2+3", "r1+r2-3", "r1-r2-3"} & set(r["conditions"].split(", "))]
    assert on_curve and all(abs(Fraction(r["r1"]) - Fraction(r["r2"])) == 3 or Fraction(r["r1"]) + Fraction(r["r2"]) == 3
                            for r in on_curve)
    curves = mechanism_curves(parse_mechanism(DYAD), ["r1", "r2"], 60)
    assert check_cells(full, "r1", "r2", "real", curves.factors) == []
    assert check_cells(full, "r1", "r2", "real", curves.factors[:2]) != []  # without the circle conditions: wrong


def test_any_design_set_is_grouped_into_cells_and_agrees_with_all_analysed():
    """Random designs (no grid): designs joined by segments free of the curves take one analysis;
    the table equals the one with every design analysed, and a note says what the curves gave."""
    designs = "random 120 r1=1/2:6 r2=1/2:6 seed=3"
    notes = []
    classified = sweep_rows(parse_mechanism(DYAD), designs, "real", scheduler="inline", notes=notes)
    full = sweep_rows(parse_mechanism(DYAD), designs, "real", scheduler="inline", shared=False)
    assert [r["real"] for r in classified] == [r["real"] for r in full]
    inherited = sum(r["conditions"].startswith("same cell as ") for r in classified)
    assert 60 < inherited < 120
    assert notes == [f"discriminant curves in (r1, r2): r1, r1+r2+3, r1+r2-3, r1-r2+3, r1-r2-3, r2; "
                     f"{inherited} of 120 designs take the count of an analysed design of their cell"]


def test_designs_joined_only_by_segments_free_of_the_curves():
    """One sign, two components: (a - 2)(b - 2) > 1/4 both north-east and south-west of the
    hyperbola; designs there are never joined (the segment crosses the curve twice), designs of
    one branch's side are, and a design on the curve is analysed itself."""
    from mech.stdlib.sweep_cells import scattered_cells
    hyperbola = {(1, 1): Fraction(1), (1, 0): Fraction(-2), (0, 1): Fraction(-2), (0, 0): Fraction(15, 4)}
    pts = {0: (Fraction(4), Fraction(4)), 1: (Fraction(1), Fraction(1)), 2: (Fraction(1), Fraction(1, 2)),
           3: (Fraction(5), Fraction(7, 2)), 4: (Fraction(5, 2), Fraction(5, 2))}
    assert scattered_cells(pts, [hyperbola]) == {0: 0, 1: 1, 2: 1, 3: 0, 4: 4}


def test_the_sweep_says_when_there_are_no_discriminant_curves():
    notes = []
    sweep_rows(parse_mechanism(FOURBAR), "grid g=2 l1=2:3:2 l2=3:4:2 l3=3", "real", scheduler="inline", notes=notes)
    assert notes == ["no discriminant curves (the configuration space is not finite and nonempty (mobility is "
                     "not 0)): every design analysed"]


@pytest.mark.slow
def test_the_3rpr_discriminant_curves_separate_its_real_counts():
    """The curves of the 3-RPR (no generic analysis finishes): on a grid every two neighbours with
    different counts are separated by a curve, and the classified sweep gives the analysed table."""
    from mech.stdlib.sweep_cells import check_cells
    from mech.stdlib.sweep_discriminant import mechanism_curves
    m = parse_mechanism(RPR)
    curves = mechanism_curves(m.with_values({"r3": 4}), ["r1", "r2"], 600)
    assert curves.D == 6 and curves.names[:2] == ["r1", "r2"] and len(curves.factors) == 3, curves.note
    assert max(i + j for i, j in curves.factors[2]) == 24
    grid = "grid r1=1:12:12 r2=1:12:12 r3=4"
    full = sweep_rows(m, grid, "real", scheduler="inline", shared=False)
    assert len({r["real"] for r in full}) >= 3
    assert check_cells(full, "r1", "r2", "real", curves.factors) == []
    classified = sweep_rows(m, grid, "real", scheduler="inline", shared=True)
    assert [r["real"] for r in classified] == [r["real"] for r in full]
    assert sum(r["conditions"].startswith("same cell") for r in classified) > 20
    for r in classified[::9]:
        assert r["real"] == independent_3rpr_count(r["r1"], r["r2"], r["r3"])
    lhs = "lhs 60 r1=1:12 r2=1:12 r3=4 seed=5"
    scattered = sweep_rows(m, lhs, "real", scheduler="inline")
    assert [r["real"] for r in scattered] == [r["real"] for r in sweep_rows(m, lhs, "real", scheduler="inline", shared=False)]
    assert sum(r["conditions"].startswith("same cell") for r in scattered) > 20


@pytest.mark.parametrize("name, grid, small", [
    ("sweep_fourbar", "grid l1=1/2:5:50 l2=1/2:5:50", "grid l1=1/2:5:12 l2=1/2:5:12"),
    ("sweep_3rpr", "grid r1=1:12:12 r2=1:12:12 r3=4", "grid r1=4:7:2 r2=4:7:2 r3=4")])
def test_the_examples_write_their_table_and_map(name, grid, small, tmp_path, monkeypatch):
    """The examples on a smaller grid: rows checked against Grashof's inequality and independent
    counts of real assembly modes."""
    monkeypatch.chdir(tmp_path)
    script = (ROOT / "examples" / f"{name}.mech").read_text()
    assert grid in script
    Session(scheduler="inline").execute(script.replace(grid, small))
    assert (tmp_path / f"{name}.png").stat().st_size > 1000
    with open(tmp_path / f"{name}.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == (144 if name == "sweep_fourbar" else 4) and not any(r["error"] for r in rows)
    for r in rows:
        if name == "sweep_fourbar":
            assert r["grashof"] == grashof_truth(2, Fraction(r["l1"]), Fraction(r["l2"]), 4)
        else:
            assert int(r["real"]) == independent_3rpr_count(r["r1"], r["r2"], r["r3"])


def test_dask_is_imported_only_when_a_sweep_runs():
    import subprocess
    import sys
    code = ("import sys, mech; mech.Session().execute('LIB \\\"mechanism.lib\\\";'); "
            "print([m for m in ('dask', 'distributed', 'pandas') if m in sys.modules])")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert out.stdout.strip() == "[]", out.stderr

