"""The progress display of the shell and the ``mech`` command: the stages of long computations
(``mech.kernel.progress`` events) as a tqdm bar on standard error, shown only once a
computation has run :data:`DELAY` seconds and only when standard error is a terminal; the bar
is removed when the computation ends, so scripts' output is unchanged.

For the Python API pass a callback instead: ``mech.Session(progress=callback)`` gets every
:class:`mech.kernel.progress.Event` (a Jupyter front end can turn them into a widget)."""
from __future__ import annotations

import contextlib
import importlib.util
import sys
import threading
import time
from typing import Any, Iterator, Optional, TextIO

from mech.kernel.progress import Event, listening

DELAY = 1.0     # seconds before a computation shows its progress
REFRESH = 0.25  # seconds between redraws


class Display:
    """A listener keeping the open stages and a thread redrawing one tqdm line from them."""

    def __init__(self, stream: TextIO) -> None:
        self.stream = stream
        self.open: list[list[Any]] = []  # [name, done, total, detail, start] of the open stages
        self.lock = threading.Lock()
        self.bar: Any = None
        self.stop = threading.Event()
        self.thread: Optional[threading.Thread] = None

    def __call__(self, e: Event) -> None:
        with self.lock:
            depth = len(e.path)
            if e.kind == "start":
                del self.open[depth:]
                self.open.append([e.stage, e.done, e.total, e.detail, time.monotonic()])
            elif e.kind == "step" and depth < len(self.open) and self.open[depth][0] == e.stage:
                row = self.open[depth]
                row[1], row[2], row[3] = e.done, e.total if e.total is not None else row[2], e.detail
            elif e.kind == "end":
                del self.open[depth:]
        if e.kind == "start" and not e.path:
            self._begin()
        elif e.kind == "end" and not e.path:
            self._finish()

    def _begin(self) -> None:
        self._finish()
        self.stop.clear()
        self.thread = threading.Thread(target=self._loop, name="mech-progress", daemon=True)
        self.thread.start()

    def _finish(self) -> None:
        if self.thread is not None:
            self.stop.set()
            self.thread.join()
            self.thread = None
        if self.bar is not None:
            self.bar.close()
            self.bar = None

    def _loop(self) -> None:
        start = time.monotonic()
        while not self.stop.wait(REFRESH):
            if time.monotonic() - start >= DELAY:
                self._draw()

    def _draw(self) -> None:
        with self.lock:
            if not self.open:
                return
            names = [row[0] for row in self.open]
            path = " > ".join(x for i, x in enumerate(names) if i == 0 or x != names[i - 1])  # a step in a stage of its name
            counted = [row for row in self.open if row[2]]
            detail = next((row[3] for row in reversed(self.open) if row[3]), "")
            done, total = (counted[-1][1] or 0, counted[-1][2]) if counted else (0, None)
        if self.bar is None:
            from tqdm import tqdm
            self.bar = tqdm(total=total, file=self.stream, leave=False, dynamic_ncols=True,
                            bar_format="{desc} {percentage:3.0f}%|{bar:12}| {n_fmt}/{total_fmt} [{elapsed}]"
                            if total else "{desc} [{elapsed}]")
        self.bar.total = total
        self.bar.n = done
        self.bar.set_description_str(path + (f": {detail}" if detail else ""), refresh=False)
        self.bar.refresh()


@contextlib.contextmanager
def terminal_progress(stream: TextIO | None = None) -> Iterator[None]:
    """Show progress on ``stream`` (default standard error) when it is a terminal and tqdm is
    installed; otherwise nothing."""
    stream = stream or sys.stderr
    try:  # tqdm is imported when a bar is drawn, not on every start
        shown = stream.isatty() and importlib.util.find_spec("tqdm") is not None
    except (AttributeError, ValueError):
        shown = False
    if not shown:
        yield
        return
    display = Display(stream)
    try:
        with listening(display):
            yield
    finally:
        display._finish()
