"""``rbdsolve solve``: problem files, folders, globs or ``-`` in, step-by-step solutions
out, in the chosen format; a summary table on standard error for more than one file."""

from __future__ import annotations

import sys

import click

from rbdsolve.cli.app import OutputPath, append_help, debug_option, parse_sets, refuse_overwriting_inputs, \
    run_guarded, sources, stderr_is_terminal, write_text
from rbdsolve.cli.batch import Outcome, Settings, solve_all, worst
from rbdsolve.errors import ExitCode

FORMATS = ("terminal", "markdown", "latex", "json")
ROUTES = ("auto", "exact", "numeric")  # spelled out here: importing the solvers would load sympy
DEFAULT_BUDGET = 60.0  # processor seconds per file: an exam problem that takes longer is stuck

SOLVE_EXAMPLES = """
\b
Examples:
  rbdsolve solve problems/sg2150-2015-10-29/p1-two-rods.yaml
  rbdsolve solve problems/sg2150-2015-10-29/          # a whole exam, in file order
  rbdsolve solve 'problems/**/*.yaml' --jobs 2        # a glob, two processes
  rbdsolve solve p1.yaml --format json | jq .results  # JSON Lines for scripts
  cat p1.yaml | rbdsolve solve -                      # a problem on standard input
  rbdsolve solve p1.yaml --set m=2 --set r=0.5 --set g=9.81
  rbdsolve solve p1.yaml --route numeric --set m=1 --set r=1 --set g=9.81
  rbdsolve solve p1.yaml --format latex -o p1.tex
  rbdsolve solve p1.yaml --route numeric --digits 10  # numbers to 10 digits

\b
Exit codes (the worst of the files): 0 solved, 1 a question could not be
answered, 2 bad input or usage, 3 internal error.
"""

route_option = click.option(
    "--route", type=click.Choice(ROUTES), default="auto", show_default=True,
    help="exact (sympy), numeric (floating point; every parameter needs a value) or auto "
         "(exact, then numeric where exact cannot answer or runs out of its budget).")
MIN_BUDGET, MAX_BUDGET = 0.001, 1e6  # seconds: a timer's resolution; eleven days, far inside its range


class Budget(click.ParamType):
    """Seconds, finite, from a millisecond to MAX_BUDGET: ``nan``, ``inf`` and ``1e308``
    are refused here, as usage errors, not deep in the timer."""

    name = "seconds"

    def convert(self, value, param, ctx) -> float:
        try:
            seconds = float(value)
        except (TypeError, ValueError):
            self.fail(f"expected a number of seconds, found '{value}'", param, ctx)
        if not MIN_BUDGET <= seconds <= MAX_BUDGET:  # NaN compares false: refused too
            self.fail(f"expected seconds from {MIN_BUDGET:g} to {MAX_BUDGET:g}, found '{value}'", param, ctx)
        return seconds


budget_option = click.option(
    "--budget", type=Budget(), default=DEFAULT_BUDGET,
    show_default=True, metavar="SECONDS",
    help="Budget of processor seconds (the same on a quiet or a busy machine) for each file's whole run. "
         "Each stage gets a share of what is left: the model all of it (half with --route auto and every "
         "value given), each question what is left divided by the questions still to come; a question past "
         "its share is left unanswered (exit code 1). With --route auto and every value given, the exact "
         "route gets half of its question's share and the numeric route the rest (a model whose T and V "
         "run out shows the coordinates only).")
sets_option = click.option(
    "--set", "sets", multiple=True, metavar="NAME=VALUE",
    help="Give a parameter a numeric value (repeatable); overrides the file's values.")
jobs_option = click.option(
    "-j", "--jobs", type=click.IntRange(min=1), default=1, show_default=True,
    help="Solve this many files at once, in separate processes.")
quiet_option = click.option(
    "-q", "--quiet", is_flag=True,
    help="No progress bar and no summary table; errors are still said on standard error.")


def batch_options(command):
    """The options of every command that solves many files (solve, key)."""
    for option in (debug_option, quiet_option, jobs_option, budget_option, route_option, sets_option):
        command = option(command)
    return command


@click.command()
@click.argument("paths", nargs=-1, required=True, type=click.Path(allow_dash=True))
@click.option("-f", "--format", "fmt", type=click.Choice(FORMATS), default="terminal",
              show_default=True, help="Output format.")
@click.option("-o", "--output", type=OutputPath(dir_okay=False, writable=True),
              help="Write to this file instead of standard output.")
@click.option("--digits", type=click.IntRange(1, 15), default=6, show_default=True,
              help="Significant digits of the numbers in text (terminal, Markdown, LaTeX), 1 to 15 "
                   "(a float holds about 15); JSON keeps full precision.")
@batch_options
def solve(paths, fmt, output, digits, sets, route, budget, jobs, quiet, debug):
    """Solve problem files and print their step-by-step solutions.

    PATHS are problem files, folders (their *.yaml files, in path order), quoted
    globs, or - for standard input. Progress and the summary table go to standard
    error, so standard output holds only the solutions (JSON Lines with --format json).
    """
    run_guarded(debug, lambda: _solve(paths, fmt, output, Settings(tuple(parse_sets(sets).items()),
                                                                   budget, route, debug), jobs, quiet, digits))


append_help(solve, SOLVE_EXAMPLES)


def _solve(paths, fmt: str, output: str | None, settings: Settings, jobs: int = 1,
           quiet: bool = False, digits: int = 6) -> ExitCode:
    from rbdsolve.cli.writing import Look, joined, rendered

    items = sources(paths)
    refuse_overwriting_inputs(output, items)
    shown = not quiet and fmt != "json" and stderr_is_terminal()  # JSON is for scripts: no display
    solved = solve_all(items, settings, jobs, progress=shown)
    look = Look() if output or fmt != "terminal" else Look.of_stdout()
    pieces = rendered(solved, fmt, look, settings.debug, digits)
    outcomes = [p.outcome for p in pieces]
    say_failures(outcomes)
    write_text(joined(fmt, pieces), output)
    if len(outcomes) > 1 and not quiet:
        print_summary(outcomes)
    return worst(outcomes)


def say_failures(outcomes: list[Outcome]) -> None:
    """Each file that gave no report, in one line on standard error."""
    for outcome in outcomes:
        if outcome.failure is not None:
            click.echo(outcome.failure.line, err=True)


def print_summary(outcomes: list[Outcome]) -> None:
    """One row per file on standard error: questions answered, routes, seconds, result.
    Files are named from their common folder (in the title), whole, never cut short."""
    from rich.console import Console
    from rich.table import Table

    from rbdsolve.render.text import no_trailing_spaces

    folder, names = _short_names([o.source for o in outcomes])
    from rich.markup import escape

    from rbdsolve.errors import printable

    shown = escape(printable(folder))  # file names are text from outside: neither markup nor controls
    table = Table(title=f"Summary ({shown})" if folder else "Summary", title_justify="left")
    table.add_column("file", overflow="fold")
    for name in ("answered", "route", "seconds", "result"):
        table.add_column(name, justify="right" if name in ("answered", "seconds") else "left", no_wrap=True)
    for name, o in zip(names, outcomes):
        table.add_row(escape(printable(name)), *_row(o))
    shown_on = Console(stderr=True, highlight=False)
    with shown_on.capture() as captured:
        shown_on.print(table)
    sys.stderr.write(no_trailing_spaces(captured.get()))


def _short_names(sources: list[str]) -> tuple[str, list[str]]:
    """The files' common folder and each file's path below it."""
    import os

    files = [s for s in sources if not s.startswith("<")]
    try:
        folder = os.path.commonpath([os.path.dirname(s) for s in files]) if files else ""
    except ValueError:  # absolute and relative paths mixed
        folder = ""
    if not folder:
        return "", sources
    return folder + os.sep, [os.path.relpath(s, folder) if not s.startswith("<") else s for s in sources]


def _row(outcome: Outcome) -> tuple[str, str, str, str]:
    seconds = f"{outcome.seconds:.2f}"
    if outcome.report is None:
        return "-", "-", seconds, f"[red]{_RESULT[outcome.code]}[/red]"
    solutions = outcome.report.solutions
    answered = sum(s.solved for s in solutions)
    routes = ", ".join(sorted({s.route.value for s in solutions})) or "-"
    style = "green" if outcome.code is ExitCode.OK else "yellow"
    return f"{answered}/{len(solutions)}", routes, seconds, f"[{style}]{_RESULT[outcome.code]}[/{style}]"


_RESULT = {ExitCode.OK: "solved", ExitCode.UNSOLVED: "unanswered question",
           ExitCode.BAD_INPUT: "bad input", ExitCode.INTERNAL: "internal error"}
