"""Solving many problem files: in file order, or in parallel processes (``--jobs``),
with a progress bar on a terminal. Each file gives an :class:`Outcome`; one file's
failure (bad input, an unanswered question, a bug) never loses the others, and the
exit code is the worst of the files."""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable, Iterable

from rbdsolve.cli.app import Source, check_sets, describe, internal_message
from rbdsolve.errors import ExitCode, InputError, Location, UnsolvedError, printable

if TYPE_CHECKING:  # not at start-up: the report module imports sympy, the pool multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    from rbdsolve.problem.quantities.quantity import Value
    from rbdsolve.report.steps import ProblemReport


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
    """One file's result: its report, or the failure that stopped it (with its exit
    code), the seconds it took, and the processor seconds of its budget it spent."""

    source: str
    report: ProblemReport | None  # None with a failure
    failure: Failure | None
    seconds: float
    spent: float = 0.0  # processor seconds (what --budget counts), for what the run does next (a key's pictures)

    @property
    def code(self) -> ExitCode:
        if self.failure is not None:
            return self.failure.exit_code
        return ExitCode.OK if self.report.solved else ExitCode.UNSOLVED


def solve_source(source: Source, settings: Settings, on_stage: Callable[[str], None] | None = None) -> Outcome:
    """Load, build and solve one problem; every failure becomes an Outcome. ``on_stage``
    is told each stage as it starts (cli/progress.py)."""
    from rbdsolve.solvers import Options, RouteChoice, solve_file

    start, processor = time.perf_counter(), time.process_time()
    try:
        problem = source.load()
        values = check_sets(dict(settings.values), problem)
        options = Options(budget=settings.budget, route=RouteChoice(settings.route), on_stage=on_stage)
        report = solve_file(problem.with_values(values), options)
    except (InputError, UnsolvedError) as exc:
        failure = Failure(exc.message, exc.location, exc.exit_code, str(exc))
        return Outcome(source.name, None, failure, time.perf_counter() - start)
    except Exception as exc:  # noqa: BLE001 - a bug in one file must not lose the others
        if settings.debug:
            import traceback  # only for a bug's traceback (--debug)

            traceback.print_exc()
        return crashed(source.name, exc, time.perf_counter() - start)
    return Outcome(source.name, report, None, time.perf_counter() - start, time.process_time() - processor)


def crashed(name: str, exc: BaseException, seconds: float) -> Outcome:
    """The Outcome of a file whose solving hit a bug: exit code 3 for it alone."""
    failure = Failure(describe(exc), None, ExitCode.INTERNAL, f"{printable(name)}: {internal_message(exc)}")
    return Outcome(name, None, failure, seconds)


def solve_all(items: list[Source], settings: Settings, jobs: int = 1,
              progress: bool = False) -> list[Outcome]:
    """Every source's Outcome, in the sources' order, ``jobs`` at a time; with
    ``progress``, a display on standard error once the run takes more than a second."""
    from rbdsolve.cli.progress import Progress

    with Progress(len(items), progress) as shown:
        if jobs <= 1 or len(items) <= 1:
            return [_advanced(_one(s, settings, shown), shown.advance) for s in items]
        return _in_parallel(items, settings, min(jobs, len(items)), shown.advance)


def _one(source: Source, settings: Settings, shown) -> Outcome:
    shown.started(source.name)
    return solve_source(source, settings, shown.stage)


def _in_parallel(items: list[Source], settings: Settings, jobs: int,
                 advance: Callable[[Outcome], None]) -> list[Outcome]:
    # the process pool (multiprocessing, sockets, logging) only where --jobs asks for it
    import pickle
    from concurrent.futures import ProcessPoolExecutor, as_completed
    from concurrent.futures.process import BrokenProcessPool

    outcomes: list[Outcome | None] = [None] * len(items)
    lost: list[int] = []  # files whose worker died (with the pool, every file it still had)
    pool = ProcessPoolExecutor(max_workers=jobs, initializer=_quiet_worker)
    try:
        futures = {pool.submit(_solve_pickled, s, settings): i for i, s in enumerate(items)}
        for future in as_completed(futures):
            i = futures[future]
            try:
                outcomes[i] = _advanced(pickle.loads(future.result()), advance)
            except BrokenProcessPool:
                lost.append(i)
    except BaseException:  # Ctrl-C, SIGTERM: stop the workers now, not after their files
        _stop(pool)
        raise
    pool.shutdown()
    for i in sorted(lost):  # each alone, so that the one that kills its process is found
        outcomes[i] = _advanced(_alone(items[i], settings), advance)
    return outcomes


def _alone(source: Source, settings: Settings) -> Outcome:
    import pickle
    from concurrent.futures import ProcessPoolExecutor

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
    within a second of Ctrl-C, not after the files under way are solved. The pool's
    manager thread is waited for once its workers are gone: it closes the pipe that
    Python's exit handler for process pools writes to, and racing it there printed
    'Exception ignored … OSError: Bad file descriptor' under 'rbdsolve: terminated'."""
    processes = list((getattr(pool, "_processes", None) or {}).values())
    manager = getattr(pool, "_executor_manager_thread", None)
    pool.shutdown(wait=False, cancel_futures=True)
    for process in processes:
        process.terminate()
    for process in processes:
        process.join(timeout=1)
    if manager is not None:
        manager.join(timeout=5)


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
    import pickle

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


def _advanced(outcome: Outcome, advance: Callable[[Outcome], None]) -> Outcome:
    advance(outcome)
    return outcome


def worst(outcomes: Iterable[Outcome]) -> ExitCode:
    return max((o.code for o in outcomes), default=ExitCode.OK)
