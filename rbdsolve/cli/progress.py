"""Progress on standard error while files are solved: after the first second, rich's
progress display with the file and the stage under way ('p1.yaml: question 3 of 3:
modes'), and, for several files, a bar and a count. Nothing for a run that ends
within the second, in a pipe, or with ``--format json`` (the commands decide
``shown``). The display is transient: it leaves no trace on the terminal."""

from __future__ import annotations

import threading
import time

from rbdsolve.errors import printable

DELAY = 1.0  # seconds before anything is drawn: most single files are solved by then


class Progress:
    """A context manager: ``started(name)`` as a file starts, ``stage(text)`` as its
    solver moves on (Options.on_stage), ``advance(outcome)`` as a file ends. The display
    starts ``delay`` seconds after entering (a timer thread), or never."""

    def __init__(self, total: int, shown: bool, delay: float | None = None, console=None) -> None:
        self.total, self.shown, self.console = total, shown, console
        self.delay = DELAY if delay is None else delay
        self.lock = threading.Lock()
        self.timer: threading.Timer | None = None
        self.display = self.task = None
        self.file, self.detail, self.done = "", "", 0

    def __enter__(self) -> Progress:
        self.began = time.monotonic()  # the clock rich's elapsed column reads
        if self.shown:
            if self.delay <= 0:
                self._start()
            else:
                self.timer = threading.Timer(self.delay, self._start)
                self.timer.daemon = True
                self.timer.start()
        return self

    def __exit__(self, *exc) -> None:
        if self.timer is not None:
            self.timer.cancel()
        with self.lock:
            if self.display is not None:
                self.display.stop()
            self.display = None
            self.shown = False  # a timer already firing starts nothing now

    def started(self, name: str) -> None:
        self.file, self.detail = name, ""
        self._update()

    def stage(self, text: str) -> None:
        self.detail = text
        self._update()

    def advance(self, outcome) -> None:
        """A file ended: ``outcome`` is its cli.batch.Outcome (not imported: batch imports this)."""
        self.done += 1
        self.file, self.detail = outcome.source, ""
        self._update()

    def _start(self) -> None:
        from rich.console import Console
        from rich.progress import BarColumn, MofNCompleteColumn, Progress as Display, SpinnerColumn, \
            TextColumn, TimeElapsedColumn

        columns = [SpinnerColumn(), TextColumn("solving")]
        if self.total > 1:
            columns += [BarColumn(), MofNCompleteColumn()]
        columns += [TimeElapsedColumn(), TextColumn("{task.description}")]
        with self.lock:
            if not self.shown:
                return
            self.display = Display(*columns, console=self.console or Console(stderr=True), transient=True)
            self.task = self.display.add_task(self._description(), total=self.total, completed=self.done)
            next(t for t in self.display.tasks if t.id == self.task).start_time = self.began  # the run's time, not the display's
            self.display.start()

    def _update(self) -> None:
        with self.lock:
            if self.display is not None:
                self.display.update(self.task, completed=self.done, description=self._description())

    def _description(self) -> str:
        from rich.markup import escape

        shown = printable(self.file) + (f": {self.detail}" if self.detail else "")
        return escape(shown)  # file names are text from outside: neither markup nor controls
