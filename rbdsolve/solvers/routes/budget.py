"""A time budget for one piece of solving, in seconds of the processor's time this
process spends (user and system), kept by the profiling timer (ITIMER_PROF, SIGPROF).

Processor time, not the wall clock: a machine whose cores are busy with other work
runs rbdsolve more slowly but gives it the same processor seconds for the same work, so
a file gets the same answer, the same route and the same exit code on a quiet machine
and on a loaded one. (Waiting — on a pipe, a FIFO, a lock — spends no processor time:
what waits is bounded where it waits, not here.)

Solvers are pure functions and know nothing of time: the caller wraps a question, or
the building of the model, in ``within(seconds, what)``. When the time is up the timer
raises :class:`OutOfTime` in whatever sympy is doing. It derives from BaseException
because sympy catches ``Exception`` in many places and would swallow it; should a bare
``except:`` swallow it anyway, the alarm rings again every REPEAT seconds until it
gets through. On leaving, the alarm is disarmed and the previous handler restored.

One budget for a whole run (``Allowance``): ``--budget`` caps a file's run, and each
stage — the model, each question, each route of a question — gets a share of what is
left when it starts, what is left divided by the stages still to come (itself
included). A stage that needs little leaves the rest to the ones after it; the run
never takes more than its budget.

Where there is no SIGPROF (Windows) or when not on the main thread (signal handlers
belong to it), ``within`` does nothing: the work runs to its end. Windows do not nest.
"""

from __future__ import annotations

import signal
import sys
import threading
import time
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Iterator

REPEAT = 0.05  # seconds between rings once the budget is spent
# processor seconds the stages before the model may spend (reading the file, a first import)
# and the model's share still be said as the whole budget: 1 % of 0.2 s was 2 ms, which a
# loaded or cold process passed, and the message (and a test of it) changed with the machine
BLINK = 0.05
MIN_SHARE = 0.001  # a timer's resolution: a share of nothing still rings at once (0 would disarm the timer)
TIMER, SIGNAL = getattr(signal, "ITIMER_PROF", None), getattr(signal, "SIGPROF", None)


_stopping: list[type[BaseException]] = []  # set once the process is told to stop (stop())


def stop(kind: type[BaseException]) -> None:
    """The process is being stopped (Ctrl-C, SIGTERM: ``kind`` is what the caller's signal
    handler raises). From now on a ring raises ``kind`` too, not OutOfTime: a ring that
    comes while the interrupt is on its way out would otherwise replace it, be caught as
    a budget run out, and the run would go on as if never interrupted."""
    _stopping[:] = [kind]


class OutOfTime(BaseException):
    """The budget of ``what`` ran out (its share ``seconds`` of a run's ``total``).
    Private to the solving layer: callers turn it into an unanswered question or a
    one-line message."""

    def __init__(self, seconds: float, what: str, total: float | None = None):
        self.seconds = seconds
        self.what = what
        if total is None:
            said = f"its {seconds:g} s budget"
        elif seconds >= total - max(0.01 * total, BLINK):  # all of it, less what the stages before spent in a blink
            said = f"its {total:g} s budget"
        else:
            said = f"its share ({seconds:.2g} s) of the {total:g} s budget"
        super().__init__(f"{what} ran out of {said} (--budget to change it)")


@dataclass(frozen=True)
class Allowance:
    """A run's budget: ``seconds`` of processor time (None: no limit) from ``start``,
    the process's processor time (time.process_time, the clock ITIMER_PROF counts) when
    the run began."""

    seconds: float | None
    start: float = field(default_factory=time.process_time)

    def left(self) -> float | None:
        """The processor seconds not spent yet (at least MIN_SHARE), None without a limit."""
        if self.seconds is None:
            return None
        return max(self.seconds - (time.process_time() - self.start), MIN_SHARE)

    def share(self, stages: int) -> float | None:
        """What is left divided among ``stages`` stages still to run, this one included."""
        left = self.left()
        return None if left is None else max(left / max(stages, 1), MIN_SHARE)


def available() -> bool:
    return (hasattr(signal, "setitimer") and SIGNAL is not None
            and threading.current_thread() is threading.main_thread())


@contextmanager
def within(seconds: float | None, what: str, total: float | None = None) -> Iterator[None]:
    """Run the body with at most ``seconds`` of processor time (None: no limit): a
    stage's share of a run's ``total`` budget, said so when it runs out."""
    if seconds is None or not available():
        yield
        return

    def ring(signum, frame):
        if _stopping:
            raise _stopping[0]()
        raise OutOfTime(seconds, what, total)

    def unraisable(info) -> None:
        # A ring inside a __del__ or a gc callback cannot propagate; Python would print it
        # as "Exception ignored in ...". Drop it quietly: the next ring gets through.
        if not isinstance(info.exc_value, OutOfTime):
            hook(info)

    previous, hook = signal.signal(SIGNAL, ring), sys.unraisablehook
    try:  # armed inside: a budget so short that it rings at once still disarms
        sys.unraisablehook = unraisable
        signal.setitimer(TIMER, seconds, REPEAT)
        yield
    finally:
        _disarm(previous)
        sys.unraisablehook = hook


def _disarm(previous) -> None:
    # The alarm may ring between the body's end and the disarming: retry until the
    # timer is off, then put the previous handler back. Never the default action: a
    # ring that was already on its way would kill the process ("Profiling timer expired").
    while True:
        try:
            signal.setitimer(TIMER, 0)
            break
        except OutOfTime:
            continue
    signal.signal(SIGNAL, _stray if previous in (signal.SIG_DFL, None) else previous)


def _stray(signum, frame) -> None:
    """A ring that arrives after its budget was disarmed: nothing is left to stop."""
