"""``rbdsolve watch``: solve problem files again each time one is saved, and redraw the
solution in the terminal (the loop: cli/watching.py; the display: cli/watch_view.py).
Solving is ``rbdsolve solve``'s (cli/batch.py's ``solve_source``), one file at a time."""

from __future__ import annotations

import click

from rbdsolve.cli.app import Source, debug_option, parse_sets, run_guarded, sources
from rbdsolve.cli.batch import Settings, solve_source
from rbdsolve.cli.solve import budget_option, route_option, sets_option
from rbdsolve.cli.watching import INTERVAL, Loop
from rbdsolve.errors import ExitCode, InputError


@click.command()
@click.argument("paths", nargs=-1, required=True, type=click.Path())
@click.option("--interval", type=click.FloatRange(0.05, 60), default=INTERVAL, show_default=True,
              metavar="SECONDS", help="How often to look at the files for a save.")
@debug_option
@budget_option
@route_option
@sets_option
def watch(paths, interval, sets, route, budget, debug):
    """Solve problem files again each time one is saved, and show the solution.

    The solution of the file saved last stays on screen; when a save leaves the file
    invalid, its last good solution stays with the error beneath it. Ctrl-C stops
    (exit code 130). PATHS are files, folders or quoted globs, as for solve.

    \b
    Examples:
      rbdsolve watch problems/mine/p1.yaml
      rbdsolve watch p1.yaml --set m=2 --set g=9.81
    """
    run_guarded(debug, lambda: _watch(paths, interval, Settings(tuple(parse_sets(sets).items()), budget, route, debug)))


def _watch(paths, interval: float, settings: Settings) -> ExitCode:
    from rbdsolve.cli.watch_view import View

    if "-" in paths:
        raise InputError("watch reads files, not standard input ('-'): there is no save to wait for")
    names = tuple(s.name for s in sources(paths))
    with View(names) as view:
        Loop(names, lambda name: solve_source(Source(name), settings), view.show, interval=interval).run()
    return ExitCode.OK  # not reached: the loop ends by Ctrl-C
