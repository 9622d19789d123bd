"""Powell's hybrid method (scipy's ``root``, MINPACK's hybrd) from many starts at once,
each run exactly as alone: the runs go in threads, and each call of the generalized
force Q waits until every run still going has asked for its own; then Q is evaluated at
all their points together, in one evaluation on arrays (search._forces). A run's path
depends on nothing but the values of Q it is given, and those are the same as one by
one, so each result is what the loop over the starts gave; what is saved is numpy's
cost per call, paid once per round instead of once per run."""

from __future__ import annotations

import threading
from collections.abc import Callable

import numpy as np
import scipy
from scipy import optimize

_OPTIONS = {"xtol": 1e-12}
_AT_ONCE = 128  # runs per gathering: a thread each (a larger grid goes in several)


def _reentrant() -> bool:
    """Whether scipy's hybrd can run in several threads at once: from scipy 1.15 MINPACK
    is C code with its state per call; the Fortran wrapper before it kept the Python
    callback in a global, so threads would answer each other's calls (one by one there)."""
    major, minor = (int(x) for x in scipy.__version__.split(".")[:2])
    return (major, minor) >= (1, 15)


_THREADS = _reentrant()


class _Abandoned(Exception):
    """Another run's evaluation failed: the gathering is given up (and run one by one)."""


class _Gathering:
    """The calls of Q of ``runs`` runs, answered together once every run going has asked."""

    def __init__(self, forces: Callable[[list], list], runs: int):
        self.forces = forces
        self.running = runs
        self.asked: dict[int, np.ndarray] = {}
        self.answers: dict[int, np.ndarray] = {}
        self.failed: BaseException | None = None
        self.cond = threading.Condition()

    def force(self, i: int, q) -> np.ndarray:
        with self.cond:
            self.asked[i] = np.array(q, float)  # a copy: hybrd writes its next point in place
            self._answer_when_all_asked()
            while i not in self.answers and self.failed is None:
                self.cond.wait()
            if i not in self.answers:
                raise _Abandoned
            return self.answers.pop(i)

    def finished(self) -> None:
        with self.cond:
            self.running -= 1
            self._answer_when_all_asked()

    def _answer_when_all_asked(self) -> None:
        if not self.asked or len(self.asked) < self.running or self.failed is not None:
            return
        keys = list(self.asked)
        try:
            self.answers.update(zip(keys, self.forces([self.asked[k] for k in keys])))
        except Exception as exc:  # noqa: BLE001 - handed to the caller, which runs one by one
            self.failed = exc
        self.asked.clear()
        self.cond.notify_all()


def _together(forces: Callable[[list], list], starts: list) -> list | None:
    """Every run's result, or None where any run or evaluation failed."""
    gathering = _Gathering(forces, len(starts))
    results: list = [None] * len(starts)
    errors: list = []

    def run(i: int) -> None:
        try:
            results[i] = optimize.root(lambda q: gathering.force(i, q), starts[i], method="hybr", options=_OPTIONS)
        except BaseException as exc:  # noqa: BLE001 - any failure: the caller runs one by one
            errors.append(exc)
        finally:
            gathering.finished()

    threads = [threading.Thread(target=run, args=(i,), daemon=True) for i in range(len(starts))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return None if errors or gathering.failed is not None else results


def newton_runs(force: Callable, forces: Callable[[list], list], starts: list) -> list:
    """optimize.root(force, start, method="hybr") for every start, in order; ``forces``
    is ``force`` at many points at once. A failure anywhere (an exception of Q at some
    point) runs them one by one as the plain loop, which then meets it as it did."""
    out: list = []
    for k in range(0, len(starts), _AT_ONCE):
        chunk = starts[k:k + _AT_ONCE]
        got = _together(forces, chunk) if _THREADS else None
        if got is None:
            got = [optimize.root(force, s, method="hybr", options=_OPTIONS) for s in chunk]
        out += got
    return out
