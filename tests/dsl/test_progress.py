"""Progress of long computations: the Python API's callback (Session(progress=...)), the
terminal display of the shell and the CLI (mech.dsl.progress), quiet when not a terminal."""
from __future__ import annotations

import io
import subprocess
import sys

from mech import Session
from mech.dsl.progress import Display, terminal_progress
from mech.kernel.progress import Event

KITE = 'LIB "mechanism.lib";\nmechanism m = "ground O A 1; bar O B 1; bar B C 2; bar C A 2";\nanalyze(m);\n'


def test_session_progress_callback_gets_the_stages():
    from mech.stdlib import analysis
    analysis._CACHE.clear()  # analyze keeps the analyses of a process: run every stage
    events: list[Event] = []
    out = Session(progress=events.append).execute(KITE)
    assert "singular configurations" in out
    top = [(e.kind, e.stage) for e in events if not e.path]
    assert top[0] == ("start", "analysis") and top[-1] == ("end", "analysis")
    inner = {e.stage for e in events if e.path == ("analysis",)}
    assert {"constraints", "decomposition", "singular configurations", "points", "local components",
            "tangent cones"} <= inner
    starts = sum(e.kind == "start" for e in events)
    assert starts == sum(e.kind == "end" for e in events)  # every stage that opens closes
    assert all(e.status == "done" for e in events if e.kind == "end" and e.stage == "analysis")


def test_no_callback_no_events_and_the_same_output():
    events: list[Event] = []
    assert Session(progress=events.append).execute(KITE) == Session().execute(KITE)


class _Tty(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_display_draws_the_stage_path_and_clears_it():
    stream = _Tty()
    d = Display(stream)
    d(Event("start", "analysis"))
    d(Event("start", "decomposition", ("analysis",), 0, 4))
    d(Event("step", "decomposition", ("analysis",), 2, 4, "strategy slice"))
    d._draw()
    shown = stream.getvalue()
    assert "analysis > decomposition: strategy slice" in shown and "2/4" in shown
    d(Event("end", "decomposition", ("analysis",), status="done"))
    d(Event("end", "analysis", status="done"))
    assert d.bar is None and d.thread is None


def test_quiet_when_not_a_terminal():
    with terminal_progress(io.StringIO()):  # not a terminal: no listener installed
        from mech.kernel.progress import active
        assert not active()
    r = subprocess.run([sys.executable, "-m", "mech", "-c", KITE.replace("\n", " ")],
                       text=True, capture_output=True, timeout=300)
    assert r.returncode == 0 and r.stderr == "" and "singular configurations" in r.stdout
