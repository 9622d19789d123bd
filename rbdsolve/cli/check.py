"""``rbdsolve check``: validate problem files without solving them (no sympy)."""

from __future__ import annotations

import click

from rbdsolve.cli.app import debug_option, run_guarded, sources
from rbdsolve.errors import ExitCode, InputError, printable


@click.command()
@click.argument("paths", nargs=-1, required=True, type=click.Path())
@click.option("-q", "--quiet", is_flag=True,
              help="Say nothing of a good file: only the errors, on standard error (the exit code says the rest).")
@debug_option
def check(paths, quiet, debug):
    """Validate problem files without solving them (fast: no algebra).

    \b
    Example:
      rbdsolve check problems/sg2150-2015-10-29/
      rbdsolve check 'problems/**/*.yaml'
      rbdsolve check -q problems/ && echo all good
    """
    run_guarded(debug, lambda: _check(paths, quiet))


def _check(paths, quiet: bool = False) -> ExitCode:
    worst = ExitCode.OK
    for source in sources(paths):
        try:
            problem = source.load()
        except InputError as exc:
            click.echo(str(exc), err=True)
            worst = max(worst, exc.exit_code)
            continue
        if not quiet:
            questions = ", ".join(q.kind.value for q in problem.questions)
            click.echo(printable(f"{source.name}: ok ({questions})"))
    return worst
