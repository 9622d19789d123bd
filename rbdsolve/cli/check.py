"""``rbdsolve check``: validate problem files without solving them (no sympy)."""

from __future__ import annotations

import click

from rbdsolve.cli.app import debug_option, main, run_guarded, sources
from rbdsolve.errors import ExitCode, InputError


@main.command()
@click.argument("paths", nargs=-1, required=True, type=click.Path())
@debug_option
def check(paths, debug):
    """Validate problem files without solving them (fast: no algebra).

    \b
    Example:
      rbdsolve check problems/sg2150-2015-10-29/
      rbdsolve check 'problems/**/*.yaml'
    """
    run_guarded(debug, lambda: _check(paths))


def _check(paths) -> ExitCode:
    worst = ExitCode.OK
    for source in sources(paths):
        try:
            problem = source.load()
        except InputError as exc:
            click.echo(str(exc), err=True)
            worst = max(worst, exc.exit_code)
            continue
        questions = ", ".join(q.kind.value for q in problem.questions)
        click.echo(f"{source.name}: ok ({questions})")
    return worst
