"""A time budget for one piece of solving, kept by the real-time alarm (SIGALRM).

Solvers are pure functions and know nothing of time: the caller wraps a question, or
the building of the model, in ``within(seconds, what)``. When the time is up the alarm
raises :class:`OutOfTime` in whatever sympy is doing. It derives from BaseException
because sympy catches ``Exception`` in many places and would swallow it; should a bare
``except:`` swallow it anyway, the alarm rings again every REPEAT seconds until it
gets through. On leaving, the alarm is disarmed and the previous handler restored.

Where there is no SIGALRM (Windows) or when not on the main thread (signal handlers
belong to it), ``within`` does nothing: the work runs to its end. Windows do not nest.
"""

from __future__ import annotations

import signal
import sys
import threading
from contextlib import contextmanager
from typing import Iterator

REPEAT = 0.05  # seconds between rings once the budget is spent


class OutOfTime(BaseException):
    """The budget of ``what`` ran out. Private to the solving layer: callers turn it
    into an unanswered question or a one-line message."""

    def __init__(self, seconds: float, what: str):
        self.seconds = seconds
        self.what = what
        super().__init__(f"{what} ran out of its {seconds:g} s budget (--budget to change it)")


def available() -> bool:
    return hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()


@contextmanager
def within(seconds: float | None, what: str) -> Iterator[None]:
    """Run the body with at most ``seconds`` of wall-clock time (None: no limit)."""
    if seconds is None or not available():
        yield
        return

    def ring(signum, frame):
        raise OutOfTime(seconds, what)

    def unraisable(info) -> None:
        # A ring inside a __del__ or a gc callback cannot propagate; Python would print it
        # as "Exception ignored in ...". Drop it quietly: the next ring gets through.
        if not isinstance(info.exc_value, OutOfTime):
            hook(info)

    previous, hook = signal.signal(signal.SIGALRM, ring), sys.unraisablehook
    try:  # armed inside: a budget so short that it rings at once still disarms
        sys.unraisablehook = unraisable
        signal.setitimer(signal.ITIMER_REAL, seconds, REPEAT)
        yield
    finally:
        _disarm(previous)
        sys.unraisablehook = hook


def _disarm(previous) -> None:
    # The alarm may ring between the body's end and the disarming: retry until the
    # timer is off, then put the previous handler back. Never the default action: a
    # ring that was already on its way would kill the process ("Alarm clock").
    while True:
        try:
            signal.setitimer(signal.ITIMER_REAL, 0)
            break
        except OutOfTime:
            continue
    signal.signal(signal.SIGALRM, _stray if previous in (signal.SIG_DFL, None) else previous)


def _stray(signum, frame) -> None:
    """A ring that arrives after its budget was disarmed: nothing is left to stop."""
