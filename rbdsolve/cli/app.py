"""The ``rbdsolve`` group and what every command shares: turning paths, globs and
``-`` into problem sources, ``--set`` values, output files, and the one place that turns
an exception into a message and an exit code."""

from __future__ import annotations

import glob
import importlib
import inspect
import os
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Callable

import click

from rbdsolve import __version__
from rbdsolve.errors import ExitCode, InputError, RbdError, printable

if TYPE_CHECKING:
    from rbdsolve.problem.quantities.quantity import Value

EXPECTED_SUFFIX = ".expected.yaml"  # golden answers beside a problem file, not problems
STDIN = "-"
_GLOB_CHARS = frozenset("*?[")


class Commands(click.Group):
    """The commands by name, each module imported when its command runs: importing
    every command's module (and what each imports) cost a solve ~8 ms of start-up.
    ``--help`` lists them from ``COMMANDS``' short help, importing none."""

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted(COMMANDS)

    def get_command(self, ctx: click.Context, name: str) -> click.Command | None:
        if name not in COMMANDS:
            return None
        return getattr(importlib.import_module(f"rbdsolve.cli.{name}"), name)

    def format_commands(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        """click's own listing (the short help cut to the width left beside the longest
        name), from the registry rather than from each command."""
        limit = formatter.width - 6 - max(map(len, COMMANDS))
        with formatter.section("Commands"):
            formatter.write_dl([(name, click.Command(name, help=COMMANDS[name]).get_short_help_str(limit))
                                for name in sorted(COMMANDS)])


# Each command: its module rbdsolve/cli/<name>.py defines it as <name>; the first
# sentence of its docstring (tests/cli/test_commands.py keeps the two the same).
COMMANDS = {
    "check": "Validate problem files without solving them (fast: no algebra).",
    "draw": "Draw a planar scene to scale: bodies by shape, points labelled, gravity.",
    "grade": "Check answers: a student's expressions against a problem's exact solution (FILE a problem, "
             "answers by --answer or an ANSWERS file), or a class's numbers against a variants table (FILE "
             "the JSON or the CSV of 'rbdsolve variants', ANSWERS a CSV).",
    "key": "Write an answer key for an exam: a folder (or files) of problems in, one document out.",
    "new": "Write a commented template problem for one question KIND.",
    "solve": "Solve problem files and print their step-by-step solutions.",
    "variants": "Exam variants: draw COUNT sets of parameter values from the ranges in the file's 'values:', "
                "solve the problem exactly once, and write each variant's values and numeric answers.",
    "watch": "Solve problem files again each time one is saved, and show the solution.",
}


@click.group(cls=Commands, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="rbdsolve")
def main() -> None:
    """rbdsolve: rigid body dynamics exam problems, solved step by step.

    A problem is a short YAML scene (parameters, coordinates, points, bodies,
    forces, questions); see docs/format.md and the examples in problems/.

    \b
    Questions: eom, equilibria, modes (Lagrange's equations, equilibria and their
    stability, small oscillations; in moving frames too), impact (Lagrange's
    equations for impact), inertia (tensors, principal axes), steady_spin (Euler's
    equations of a free body), steady_motion (rolling, tops, in a turning triad),
    kinematics (a point's position, velocity and acceleration), reactions (forces
    at the supports, contact lost), energy (speeds by T + V constant).
    Templates of each: rbdsolve new --list.

    \b
    Shell completion (bash; zsh and fish alike, see the README):
      eval "$(_RBDSOLVE_COMPLETE=bash_source rbdsolve)"
    """


@dataclass(frozen=True)
class Source:
    """One problem to read: a file, or text already read (standard input)."""

    name: str
    text: str | None = None

    def load(self):
        from rbdsolve.problem import load_file, load_text

        return load_file(self.name) if self.text is None else load_text(self.text, self.name)


def expand_paths(paths: tuple[str, ...]) -> list[Path]:
    """Files as given; a folder gives the *.yaml files below it, in path order; a glob
    (quoted, so the shell leaves it) the files it matches, in path order."""
    out: list[Path] = []
    for raw in paths:
        path = Path(raw)
        if path.is_dir():
            found = sorted(p for p in path.rglob("*") if p.is_file() and _is_problem(p))
            if not found:
                raise InputError(f"{raw}: no problem files (*.yaml) in this folder")
            out += found
        elif not path.exists() and _GLOB_CHARS & set(raw):
            found = sorted(Path(p) for p in glob.glob(raw, recursive=True) if _is_problem(Path(p)))
            if not found:
                raise InputError(f"{raw}: no problem files match this pattern")
            out += found
        else:
            out.append(path)
    return out


def sources(paths: tuple[str, ...]) -> list[Source]:
    """``expand_paths`` with ``-`` read once from standard input."""
    if paths.count(STDIN) > 1:
        raise InputError("'-' (standard input) is given more than once; it can be read only once")
    out: list[Source] = []
    for raw in paths:
        if raw == STDIN:
            out.append(Source(STDIN_NAME, read_stdin()))
        else:
            out += [Source(str(p)) for p in expand_paths((raw,))]
    return out


STDIN_NAME = "<stdin>"


def read_stdin() -> str:
    """Standard input as a problem's text, under the limits of a file: no more than
    one byte past the size limit is read, and a pipe that sends no end of file within
    the read deadline is refused rather than waited for."""
    from rbdsolve.problem.yamlnodes import read_stream, read_text

    return read_text(STDIN_NAME, read_stream(sys.stdin.buffer, STDIN_NAME))


def _is_problem(path: Path) -> bool:
    return path.suffix in (".yaml", ".yml") and not path.name.endswith(EXPECTED_SUFFIX)


def parse_sets(items: tuple[str, ...]) -> dict[str, Value]:
    """``--set NAME=VALUE``: a value as in ``values:`` (9.81, pi/6, 30 cm), read by
    rbdsolve's own parsers (problem/quantities/overrides.py, shared with the Python API)."""
    from rbdsolve.problem.quantities.overrides import read_value

    values = {}
    for item in items:
        name, sep, text = item.partition("=")
        if not sep or not name.strip().isidentifier():
            raise InputError(f"--set expects NAME=VALUE, found '{item}'")
        values[name.strip()] = read_value(name.strip(), text)
    return values


def check_sets(values: dict[str, Value], problem) -> dict[str, Value]:
    """Every ``--set`` names a parameter of ``problem`` (problem/quantities/overrides.py)."""
    from rbdsolve.problem.quantities.overrides import checked_values

    return checked_values(values, problem)


def write_text(text: str, output: str | None) -> None:
    """To ``output`` (whole or not at all: render.files), or to standard output when
    there is none; a write that fails is one line, exit code 2."""
    if output:
        from rbdsolve.render.files import write_file

        write_file(output, text)
        return
    try:
        click.echo(text, nl=False)
    except OSError as exc:
        _silence_stdout()
        raise InputError(f"cannot write to standard output: {exc.strerror or exc}") from None


def _silence_stdout() -> None:
    """Standard output to /dev/null once a write to it failed: what is still buffered
    would fail again when Python flushes it at exit, with a second message."""
    _silence(sys.stdout)


def _silence(stream) -> bool:
    """The stream's descriptor pointed at /dev/null (its buffer then flushes there);
    False where it has none (a test's stream)."""
    try:
        os.dup2(os.open(os.devnull, os.O_WRONLY), stream.fileno())
        return True
    except (OSError, ValueError, AttributeError):
        return False


class OutputPath(click.Path):
    """``-o PATH``: the file to write. An empty path names none: refused, where it
    would otherwise read as 'no -o' and the output go to standard output."""

    def convert(self, value, param, ctx):
        if isinstance(value, str) and not value.strip():
            self.fail("an empty path names no file", param, ctx)
        return super().convert(value, param, ctx)


def tell(line: str) -> None:
    """One line on standard error, escaped (errors.printable): the paths and names in it
    are text from outside (``-o $'x\\e]0;PWN\\a.csv'``), never a terminal's control."""
    click.echo(printable(line), err=True)


def refuse_overwriting_inputs(output: str | None, items: list[Source], what: str = "one of the problem files") -> None:
    """``-o`` naming one of the input files (``what`` they are): refused before anything
    is solved."""
    if not output:
        return
    for item in items:
        if item.text is None and _same_file(output, item.name):
            raise InputError(f"-o {output}: this is {what}; choose another output")


def _same_file(a: str, b: str) -> bool:
    try:
        return os.path.samefile(a, b)
    except (OSError, ValueError):  # not there, or a path no file can have (NUL in it)
        return False


def stderr_is_terminal() -> bool:
    return sys.stderr.isatty()


def run() -> None:
    """``rbdsolve`` as a process (the console script, ``python -m rbdsolve``): ``main``,
    then out with its exit code without tearing the interpreter down where nothing is
    left to finish (``_leave``). Tests call ``main``, which returns to them."""
    process_settings()
    try:
        main()  # standalone: click always ends it with SystemExit
    except SystemExit as exc:
        _forget_caught_interrupts()
        _leave(exc.code)
        raise


def _forget_caught_interrupts() -> None:
    """CPython marks a KeyboardInterrupt that ends an ``exec`` of a string as unhandled,
    even when it is caught afterwards (pythonrun.c, run_eval_code_obj), and under
    ``python -m`` its exit then kills the process with SIGINT (Py_RunMain checks that
    mark): a Ctrl-C that landed while a dataclass was being made (dataclasses exec their
    methods' source) was said "rbdsolve: interrupted" and ended by signal, not with exit
    code 130 (a rare failure of tests/cli/test_signals.py). Each exec of a string clears
    the mark first; once SystemExit is on its way out, every interrupt was caught. The
    string is this constant, never text from a file."""
    exec("", {})  # noqa: S102 - a constant, for its side effect on the interpreter's mark


def process_settings() -> None:
    """What the ``rbdsolve`` process sets for itself before it solves anything (the
    benchmarks' in-process measurements set the same, to time the command as it runs):
    the cycle collector less often and BLAS on one thread. sympy's integers are its own
    choice (SYMPY_GROUND_TYPES decides): python-flint's, installed for the certified roots
    (solvers/modes/certified.py). Importing them costs ~16 ms of every process, and they
    factor multivariate polynomials 2–2.5 times faster than Python's integers: a new
    user's disk on a spring on an incline (a stiffness K of five parameters put over one
    denominator and factored) took 5.4 s on Python's integers and 2.2 s on flint's; the
    files of problems/ and 10–24-link chains take the same or less (docs/performance.md),
    with the same answers, byte for byte. SYMPY_GROUND_TYPES=python rbdsolve solve …
    still asks for Python's."""
    _collect_less_often()
    _one_blas_thread()


BLAS_THREADS = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


def _one_blas_thread() -> None:
    """numpy's BLAS on one thread unless the environment says otherwise (read when
    numpy is first imported, which is later). rbdsolve's matrices are n ≤ a few hundred:
    at n = 50, eigh(K, M) takes 7 ms on OpenBLAS's threads and 0.2 ms on one, and on a
    busy machine the threads wait for each other (a 50-link chain on the numeric
    route: 0.09 s → 0.06 s). A larger system can still ask for threads:
    OPENBLAS_NUM_THREADS=4 rbdsolve solve …"""
    for name in BLAS_THREADS:
        os.environ.setdefault(name, "1")


GC_YOUNG = 200_000  # net allocations between collections of the youngest generation (Python's: 700)


def _collect_less_often() -> None:
    """Python's cycle collector looks at the young objects every 700 net allocations,
    and each tenth pass at the older ones: all of sympy's modules and caches. sympy's
    expressions hold no cycles (reference counting frees them), so on a seed problem
    those passes are ~6 % of the process (~0.035 s) and find next to nothing. A
    collection every 200,000 allocations still bounds memory over a batch or a large
    system (a seed problem then needs none; its peak memory is unchanged)."""
    import gc

    _, middle, old = gc.get_threshold()
    gc.set_threshold(GC_YOUNG, middle, old)


def _leave(code: object) -> None:
    """Exit now with ``code`` when the process has nothing left to do at exit: no thread
    but the main one (the progress timer is a daemon), no process pool, standard output
    and error flushed. Freeing every object one by one when an interpreter that holds
    sympy's caches shuts down takes about 0.07 s after one solve, and nothing comes of
    it. The exit handlers still run (the site's own, a library's); any doubt (a code
    that is not a number, a stream that cannot be flushed, a profiler or tracer that
    writes its results when the interpreter ends) leaves it to Python's exit."""
    import atexit
    import threading

    if code is None:
        code = 0
    others = [t for t in threading.enumerate() if t is not threading.main_thread() and not t.daemon]
    watched = sys.getprofile() is not None or sys.gettrace() is not None  # a profiler, coverage: they write at exit
    if not isinstance(code, int) or others or watched or "concurrent.futures.process" in sys.modules:
        return
    for stream in (sys.stdout, sys.stderr):
        if stream is not None and not _flushes(stream):
            return
    atexit._run_exitfuncs()  # what Python's exit would run, in the same order
    os._exit(code)


def run_guarded(debug: bool, run: Callable[[], ExitCode]) -> None:
    """Run a command's body and exit with its code: an RbdError is one line and its
    exit code, anything else a bug (exit code 3, the traceback with --debug). Standard
    error cannot fail it (closed, or on a full disk): messages are a courtesy there,
    the exit code is the contract."""
    stderr = sys.stderr
    sys.stderr = Unfailing(stderr)
    previous = _on_sigterm(_terminate)
    previous_int = _on_sigint(_interrupt)
    try:
        code = guard(debug, run)
        code = max(code, _flushed())
    finally:
        _on_sigterm(previous)
        _on_sigint(previous_int)
        sys.stderr = stderr
    sys.exit(int(code))


class Terminated(BaseException):
    """SIGTERM, raised where the main thread is, so that every ``finally`` and ``with``
    runs on the way out: scratch folders removed, half-written outputs deleted."""


def _terminate(signum, frame) -> None:
    _stopping(Terminated)
    raise Terminated()


def _interrupt(signum, frame) -> None:
    """Ctrl-C: KeyboardInterrupt, as Python's own handler raises."""
    _stopping(KeyboardInterrupt)
    raise KeyboardInterrupt()


def _stopping(kind: type[BaseException]) -> None:
    """Tell the budget that the process is stopping (budget.stop), so that no budget's
    ring can take the place of the interrupt on its way out. Not imported here: a
    process that has not imported the budget has no ring to fear (and a signal handler
    is no place for an import)."""
    budget = sys.modules.get("rbdsolve.solvers.routes.budget")
    if budget is not None:
        budget.stop(kind)


def _on_sigterm(handler):
    """Install ``handler`` for SIGTERM and return the previous one (None where signal
    handlers cannot be set: not the main thread)."""
    return _on_signal("SIGTERM", handler)


def _on_sigint(handler):
    """Install ``handler`` for SIGINT (Ctrl-C) and return the previous one, as _on_sigterm."""
    return _on_signal("SIGINT", handler)


def _on_signal(name: str, handler):
    import signal
    import threading

    if handler is None or threading.current_thread() is not threading.main_thread():
        return None
    return signal.signal(getattr(signal, name), handler)


def _flushes(stream) -> bool:
    """Flushed, or, where its device refuses (standard error on a full disk), emptied
    into /dev/null: what it held could not be said anyway, and Python's own flush at
    exit would fail again and end the process with 120 instead of its exit code."""
    try:
        stream.flush()
        return True
    except (OSError, ValueError):
        pass
    if not _silence(stream):
        return False
    try:
        stream.flush()
        return True
    except (OSError, ValueError):
        return False


def _flushed() -> ExitCode:
    """Standard output flushed now, while a failure can still be said and counted."""
    try:
        sys.stdout.flush()
    except OSError as exc:
        _silence_stdout()
        click.echo(f"rbdsolve: cannot write to standard output: {exc.strerror or exc}", err=True)
        return ExitCode.BAD_INPUT
    except (ValueError, AttributeError):  # closed or absent: nothing was written to it
        pass
    return ExitCode.OK


class Unfailing:
    """A text stream whose writes never raise: standard error closed (``2>&-``, then
    Python's sys.stderr is None) or full (``2>/dev/full``) must not cost the answers."""

    def __init__(self, stream):
        self.stream = stream
        self.encoding = getattr(stream, "encoding", None) or "utf-8"
        self.errors = getattr(stream, "errors", None) or "strict"

    def write(self, text: str) -> int:
        if not isinstance(text, str):  # so that click takes this for the text stream it is
            raise TypeError("a text stream")
        try:
            self.stream.write(text)
            self.stream.flush()
        except (OSError, ValueError, AttributeError):
            pass
        return len(text)

    def flush(self) -> None:
        try:
            self.stream.flush()
        except (OSError, ValueError, AttributeError):
            pass

    def isatty(self) -> bool:
        try:
            return self.stream.isatty()
        except (OSError, ValueError, AttributeError):
            return False

    def writable(self) -> bool:
        return True


def guard(debug: bool, run: Callable[[], ExitCode]) -> ExitCode:
    try:
        return run()
    except RbdError as exc:
        click.echo(str(exc), err=True)
        return exc.exit_code
    except KeyboardInterrupt:
        click.echo("rbdsolve: interrupted", err=True)
        return ExitCode.INTERRUPTED
    except Terminated:
        click.echo("rbdsolve: terminated", err=True)
        return ExitCode.TERMINATED
    except Exception as exc:  # noqa: BLE001 - the one place that reports a bug
        if debug:
            import traceback  # only for a bug's traceback (--debug)

            traceback.print_exc()
        click.echo(internal_message(exc), err=True)
        return ExitCode.INTERNAL


def internal_message(exc: BaseException) -> str:
    return f"rbdsolve: internal error: {describe(exc)} (run with --debug for the traceback)"


def describe(exc: BaseException) -> str:
    """The exception's class and text; the class alone when its text cannot be made
    (a sympy relational asked for its truth value fails even to say why)."""
    try:
        return printable(f"{type(exc).__name__}: {exc}")
    except Exception:  # noqa: BLE001 - the message of a bug must not be a second bug
        return type(exc).__name__


def append_help(command: click.Command, text: str) -> None:
    """Add a block (examples, a table) after a command's docstring. The docstring is
    dedented first: click does that only for a docstring it is left alone with, so an
    appended one would otherwise keep its indentation and be rewrapped around it."""
    command.help = inspect.cleandoc(command.help or "") + "\n\n" + text.strip("\n") + "\n"


debug_option = click.option("--debug", is_flag=True, help="Show the traceback of an internal error.")
