"""``rbdsolve variants``: exam variants of one problem, drawn from the ranges in its
``values:``; a CSV, JSON or LaTeX sheet of every variant's values and answers."""

from __future__ import annotations

from pathlib import Path

import click

from rbdsolve.cli.app import OutputPath, STDIN_NAME, Source, append_help, debug_option, read_stdin, \
    refuse_overwriting_inputs, run_guarded, stderr_is_terminal, tell, write_text
from rbdsolve.cli.solve import DEFAULT_BUDGET, budget_option, route_option
from rbdsolve.errors import ExitCode, InputError

PROGRESS_FROM = 1000  # variants: fewer are done before a bar would be drawn
MAX_COUNT = 100_000  # a class is hundreds; a million rows is a typo that would fill the memory
FORMATS = ("csv", "json", "tex")
SUFFIXES = {".csv": "csv", ".json": "json", ".tex": "tex"}

VARIANTS_EXAMPLES = """
\b
Examples:
  rbdsolve variants problems/sg2150-2015-10-29/p1-two-rods.yaml --count 30 --seed 1 -o variants.csv
  rbdsolve variants p1.yaml --count 30 --seed 1 -o sheets.tex    # a page per student, answers last
  rbdsolve variants p1.yaml --count 1000 --seed 7 --format json  # to standard output

\b
A parameter is drawn from its 'values:' entry in the file:
  values: {m: {range: [1, 5], step: 0.5}, g: {choices: [9.81, 10]}, r: 0.5}

\b
Exit codes: 0 the table is written, 1 a question has no exact answer or the
check by a full solve disagrees (no table is written), 2 bad input or usage,
3 internal error.
"""


@click.command()
@click.argument("path", type=click.Path(allow_dash=True))
@click.option("-n", "--count", type=click.IntRange(min=1, max=MAX_COUNT), default=30, show_default=True,
              help="How many variants (students).")
@click.option("-s", "--seed", type=click.IntRange(min=0), default=0, show_default=True,
              help="Seed of the random draw: the same seed gives the same variants.")
@click.option("-o", "--output", type=OutputPath(dir_okay=False, writable=True),
              help="Write to this file (format from its suffix: .csv, .json, .tex).")
@click.option("-f", "--format", "fmt", type=click.Choice(FORMATS),
              help="Output format (default: from --output's suffix, else csv).")
@click.option("--verify", type=click.IntRange(min=0), default=3, show_default=True, metavar="K",
              help="Solve K variants again in full, with their values given, and refuse to write "
                   "the table unless every number agrees (relative 1e-9).")
@route_option
@budget_option
@debug_option
def variants(path, count, seed, output, fmt, verify, route, budget, debug):
    """Exam variants: draw COUNT sets of parameter values from the ranges in the
    file's 'values:', solve the problem exactly once, and write each variant's values
    and numeric answers.

    PATH is one problem file, or - for standard input. Warnings (empty cells, answers
    left out) go to standard error.
    """
    run_guarded(debug, lambda: _variants(path, count, seed, output, fmt, verify, route, budget))


append_help(variants, VARIANTS_EXAMPLES)


def output_format(output: str | None, fmt: str | None) -> str:
    """--format, else the output file's suffix, else csv."""
    if fmt:
        return fmt
    if output is None:
        return "csv"
    suffix = Path(output).suffix.lower()
    if suffix not in SUFFIXES:
        raise InputError(f"-o {output}: cannot tell the format from '{suffix or 'no suffix'}'; "
                         "use .csv, .json or .tex, or give --format")
    return SUFFIXES[suffix]


def _variants(path: str, count: int, seed: int, output: str | None, fmt: str | None, verify: int,
              route: str, budget: float = DEFAULT_BUDGET) -> ExitCode:
    from rbdsolve.render.variants import RENDERERS
    from rbdsolve.solvers import Options, RouteChoice
    from rbdsolve.teaching.variants import variants as make

    kind = output_format(output, fmt)
    source = Source(STDIN_NAME, read_stdin()) if path == "-" else Source(path)
    refuse_overwriting_inputs(output, [source])
    problem = source.load()
    with _progress(count >= PROGRESS_FROM and stderr_is_terminal()) as stage:
        table = make(problem, count, seed, Options(route=RouteChoice(route), budget=budget), verify, stage)
        stage("writing the table", 0, 1)
        text = RENDERERS[kind](table)
    for line in (*table.notes, *(f"warning: {w}" for w in table.warnings)):
        tell(f"{table.file}: {line}")
    write_text(text, output)
    if output:
        tell(f"{table.file}: wrote {count} variant{'s' if count > 1 else ''} to {output} ({kind})")
    return ExitCode.OK


class _progress:
    """A bar on standard error, one stage at a time (the stage's name, its count), while
    a large table is made on a terminal; nothing otherwise."""

    def __init__(self, shown: bool):
        self.shown, self.bar, self.task, self.stage = shown, None, None, None

    def __enter__(self):
        if not self.shown:
            return lambda what, done, total: None
        from rich.console import Console
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

        self.bar = Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                            TimeElapsedColumn(), console=Console(stderr=True), transient=True)
        self.bar.start()
        self.task = self.bar.add_task("", total=1)
        return self.show

    def show(self, what: str, done: int, total: int) -> None:
        self.bar.update(self.task, description=what, completed=done, total=total)

    def __exit__(self, *exc) -> None:
        if self.bar is not None:
            self.bar.stop()
