"""The loop of ``rbdsolve watch`` (cli/watch.py), without click or rich: the files'
state and the poll, its clock and file system injectable for tests.

The files are polled: each one's modification time and size, twice a second (no
dependency, no event loop of our own; an editor's save, in place or by renaming a
new file onto the old, changes both or either). A file that is momentarily invalid
keeps its last good solution on screen with the new error beneath it. Solving is the
same as ``rbdsolve solve``'s (cli/batch.py's ``solve_source``), one file at a time.
"""

from __future__ import annotations

import os
import time
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Callable

from rbdsolve.cli.batch import Outcome
from rbdsolve.errors import printable

if TYPE_CHECKING:
    from rbdsolve.report.steps import ProblemReport

INTERVAL = 0.5  # seconds between looks at the files: a save shows within half a second

Stamp = tuple[int, int] | None  # (mtime in ns, size), None while the file is absent


@dataclass(frozen=True)
class Watched:
    """One file as last solved: its last good report (kept while the file is invalid),
    the error of its latest solve, and when that was."""

    name: str
    report: ProblemReport | None = None
    error: str | None = None
    solved_at: float | None = None  # time.time() of the last good report
    seconds: float = 0.0


@dataclass(frozen=True)
class State:
    files: tuple[Watched, ...]
    latest: int = 0  # which file changed last: the one on screen
    rounds: int = 0  # solves so far, all files


def stamp(path: str) -> Stamp:
    """What a save changes: modification time and size (None: the file is not there,
    as for an instant while an editor renames its new copy onto it)."""
    try:
        info = os.stat(path)
    except OSError:
        return None
    return info.st_mtime_ns, info.st_size


def pause(seconds: float) -> None:
    time.sleep(seconds)


def updated(state: State, index: int, outcome: Outcome, now: float) -> State:
    """The state after file ``index`` was solved: a report replaces the last good one;
    a failure keeps it and says the error beneath."""
    old = state.files[index]
    if outcome.report is not None:
        new = Watched(old.name, outcome.report, None, now, outcome.seconds)
    else:
        new = replace(old, error=outcome.failure.line if outcome.failure else "no report")
    files = state.files[:index] + (new,) + state.files[index + 1:]
    return State(files, index, state.rounds + 1)


@dataclass
class Loop:
    """The watch loop, its clock and file system injectable: ``sleep`` and ``stamp``
    for tests, ``show`` to draw each new state. ``run`` returns only by an exception
    (KeyboardInterrupt: Ctrl-C) or after ``rounds`` polls when that is given."""

    names: tuple[str, ...]
    solve: Callable[[str], Outcome]
    show: Callable[[State], None]
    sleep: Callable[[float], None] = field(default_factory=lambda: pause)  # looked up when made: tests replace it
    stamp: Callable[[str], Stamp] = stamp
    now: Callable[[], float] = time.time
    interval: float = INTERVAL
    seen: dict[str, Stamp] = field(default_factory=dict)

    def run(self, polls: int | None = None) -> State:
        state = State(tuple(Watched(n) for n in self.names))
        for i, name in enumerate(self.names):
            self.seen[name] = self.stamp(name)
            state = updated(state, i, self.solve(name), self.now())
        self.show(state)
        count = 0
        while polls is None or count < polls:
            self.sleep(self.interval)
            count += 1
            state = self.poll(state)
        return state

    def poll(self, state: State) -> State:
        """Solve each file whose stamp changed (and is there); show the state if any was."""
        changed = False
        for i, name in enumerate(self.names):
            now = self.stamp(name)
            if now == self.seen.get(name) or now is None:
                continue
            self.seen[name] = now
            state = updated(state, i, self.solve(name), self.now())
            changed = True
        if changed:
            self.show(state)
        return state


def status_line(watched: Watched) -> str:
    """'p1.yaml: solved at 14:02:11 in 0.45 s' or '…: invalid (the solution of 14:01:50)'."""
    name = printable(watched.name)
    if watched.solved_at is None:
        return f"{name}: no solution yet"
    at = time.strftime("%H:%M:%S", time.localtime(watched.solved_at))
    if watched.error:
        return f"{name}: invalid since the last save; the solution shown is from {at}"
    return f"{name}: solved at {at} in {watched.seconds:.2f} s"
