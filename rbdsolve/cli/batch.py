"""Solving many problem files: in file order, or in parallel processes (``--jobs``),
with a progress bar on a terminal. Each file gives an :class:`Outcome`; one file's
failure (bad input, an unanswered question, a bug) never loses the others, and the
exit code is the worst of the files."""

from __future__ import annotations

import pickle
import time
import traceback
from concurrent.futures import ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass
from typing import TYPE_CHECKING, Iterable

from rbdsolve.cli.app import Source, check_sets, describe, internal_message
from rbdsolve.errors import ExitCode, InputError, Location, UnsolvedError, printable

if TYPE_CHECKING:  # the report module imports sympy: not at start-up
    from rbdsolve.problem.quantity import Value
    from rbdsolve.report.steps import ProblemReport

PROGRESS_FROM = 4  # files: fewer than a handful finish before a bar is worth drawing


@dataclass(frozen=True)
class Settings:
    """How every file is solved: the command's options, as plain values."""

    values: tuple[tuple[str, Value], ...] = ()  # --set, read but not yet checked against a file
    budget: float = 60.0
    route: str = "auto"
    debug: bool = False


@dataclass(frozen=True)
class Failure:
    """Why a file gave no report, as the JSON and the terminal say it (an exception
    does not cross a process boundary with its location)."""

    message: str
    location: Location | None
    exit_code: ExitCode
    line: str  # the one line for standard error


@dataclass(frozen=True)
class Outcome:
    source: str
    report: ProblemReport | None  # None with a failure
    failure: Failure | None
    seconds: float

    @property
    def code(self) -> ExitCode:
        if self.failure is not None:
            return self.failure.exit_code
        return ExitCode.OK if self.report.solved else ExitCode.UNSOLVED


def solve_source(source: Source, settings: Settings) -> Outcome:
    """Load, build and solve one problem; every failure becomes an Outcome."""
    from rbdsolve.solvers import Options, RouteChoice, solve_file

    start = time.perf_counter()
    try:
        problem = source.load()
        values = check_sets(dict(settings.values), problem)
        options = Options(values=values, budget=settings.budget, route=RouteChoice(settings.route))
        report = solve_file(problem, options)
    except (InputError, UnsolvedError) as exc:
        failure = Failure(exc.message, exc.location, exc.exit_code, str(exc))
        return Outcome(source.name, None, failure, time.perf_counter() - start)
    except Exception as exc:  # noqa: BLE001 - a bug in one file must not lose the others
        if settings.debug:
            traceback.print_exc()
        return crashed(source.name, exc, time.perf_counter() - start)
    return Outcome(source.name, report, None, time.perf_counter() - start)


def crashed(name: str, exc: BaseException, seconds: float) -> Outcome:
    """The Outcome of a file whose solving hit a bug: exit code 3 for it alone."""
    failure = Failure(describe(exc), None, ExitCode.INTERNAL, f"{printable(name)}: {internal_message(exc)}")
    return Outcome(name, None, failure, seconds)


def solve_all(items: list[Source], settings: Settings, jobs: int = 1,
              progress: bool = False) -> list[Outcome]:
    """Every source's Outcome, in the sources' order, ``jobs`` at a time."""
    with _bar(len(items), progress) as bar:
        if jobs <= 1 or len(items) <= 1:
            return [_one(s, settings, bar) for s in items]
        return _in_parallel(items, settings, min(jobs, len(items)), bar)


def _in_parallel(items: list[Source], settings: Settings, jobs: int, bar: _Shown) -> list[Outcome]:
    outcomes: list[Outcome | None] = [None] * len(items)
    lost: list[int] = []  # files whose worker died (with the pool, every file it still had)
    pool = ProcessPoolExecutor(max_workers=jobs, initializer=_quiet_worker)
    try:
        futures = {pool.submit(_solve_pickled, s, settings): i for i, s in enumerate(items)}
        bar.solving(_under_way(items, outcomes, lost, jobs))
        for future in as_completed(futures):
            i = futures[future]
            try:
                outcomes[i] = bar.done(pickle.loads(future.result()))
            except BrokenProcessPool:
                lost.append(i)
            bar.solving(_under_way(items, outcomes, lost, jobs))
    except BaseException:  # Ctrl-C, SIGTERM: stop the workers now, not after their files
        _stop(pool)
        raise
    pool.shutdown()
    for i in sorted(lost):  # each alone, so that the one that kills its process is found
        bar.solving([items[i].name])
        outcomes[i] = bar.done(_alone(items[i], settings))
    return outcomes


def _one(source: Source, settings: Settings, bar: _Shown) -> Outcome:
    bar.solving([source.name])
    return bar.done(solve_source(source, settings))


def _under_way(items: list[Source], outcomes: list, lost: list[int], jobs: int) -> list[str]:
    """The files the workers hold now: the pool hands files out in the order they
    were submitted, so these are the first ``jobs`` not yet finished."""
    waiting = [s.name for i, (s, o) in enumerate(zip(items, outcomes)) if o is None and i not in lost]
    return waiting[:jobs]


def _alone(source: Source, settings: Settings) -> Outcome:
    start = time.perf_counter()
    pool = ProcessPoolExecutor(max_workers=1, initializer=_quiet_worker)
    try:
        return pickle.loads(pool.submit(_solve_pickled, source, settings).result())
    except Exception as exc:  # noqa: BLE001 - the process died (memory, a signal): this file only
        return crashed(source.name, exc, time.perf_counter() - start)
    except BaseException:
        _stop(pool)
        raise
    finally:
        pool.shutdown()


def _quiet_worker() -> None:
    """A worker leaves interrupts to its parent: Ctrl-C reaches every process of the
    terminal's group, and a worker's KeyboardInterrupt would print its traceback. The
    parent stops the workers itself (``_stop``); SIGTERM kills a worker outright."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def _stop(pool: ProcessPoolExecutor) -> None:
    """End the workers at once and drop the files not yet started: the parent exits
    within a second of Ctrl-C, not after the files under way are solved."""
    processes = list((getattr(pool, "_processes", None) or {}).values())
    pool.shutdown(wait=False, cancel_futures=True)
    for process in processes:
        process.terminate()
    for process in processes:
        process.join(timeout=1)


def _solve_pickled(source: Source, settings: Settings) -> bytes:
    """The Outcome pickled so that sums, products and powers come back as they were:
    sympy rebuilds an expression from its arguments and, by default, evaluates them
    again, which would fold a display form the solver kept on purpose (√(24g/(25r))
    into 2√6 √g/(5√r)). Those three are rebuilt unevaluated; their arguments are
    already in canonical order, so nothing else changes. A file's functions of time
    are rebuilt as such (sympy would rebuild a plain function, without the namespace
    that keeps a coordinate called Float from being printed as a number)."""
    import copyreg
    import io

    import sympy as sp
    from sympy.core.function import UndefinedFunction

    buffer = io.BytesIO()
    pickler = pickle.Pickler(buffer)
    pickler.dispatch_table = copyreg.dispatch_table.copy()
    for kind in (sp.Add, sp.Mul, sp.Pow):
        pickler.dispatch_table[kind] = _reduce_unevaluated
    pickler.dispatch_table[UndefinedFunction] = _reduce_function
    pickler.dump(solve_source(source, settings))
    return buffer.getvalue()


def _reduce_unevaluated(expr):
    return _unevaluated, (type(expr), expr.args)


def _unevaluated(kind, args):
    return kind(*args, evaluate=False)


def _reduce_function(function):
    from sympy.core.function import _reduce_undef

    if "precedence" not in vars(function):
        return _reduce_undef(function)
    return _user_function, (function.name,)


def _user_function(name: str):
    from rbdsolve.model.state import user_function

    return user_function(name)


class _Shown:
    """What the bar is told: the files being solved now, and each file done."""

    def __init__(self, progress=None, task=None):
        self.progress, self.task = progress, task

    def solving(self, names: list[str]) -> None:
        if self.progress is not None:
            from rich.markup import escape

            self.progress.update(self.task, description=escape(printable(", ".join(names))))

    def done(self, outcome: Outcome) -> Outcome:
        if self.progress is not None:
            self.progress.update(self.task, advance=1)
        return outcome


class _bar:
    """A rich progress bar on standard error while files are solved, naming the files
    under way, or nothing."""

    def __init__(self, total: int, shown: bool):
        self.total, self.shown, self.progress = total, shown and total >= PROGRESS_FROM, None

    def __enter__(self) -> _Shown:
        if not self.shown:
            return _Shown()
        from rich.console import Console
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

        self.progress = Progress(TextColumn("solving"), BarColumn(), MofNCompleteColumn(),
                                 TimeElapsedColumn(), TextColumn("{task.description}"),
                                 console=Console(stderr=True), transient=True)
        self.progress.start()
        return _Shown(self.progress, self.progress.add_task("", total=self.total))

    def __exit__(self, *exc) -> None:
        if self.progress is not None:
            self.progress.stop()


def worst(outcomes: Iterable[Outcome]) -> ExitCode:
    return max((o.code for o in outcomes), default=ExitCode.OK)
