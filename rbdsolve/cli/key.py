"""``rbdsolve key``: a whole exam's answer key as one document (PDF, LaTeX, Markdown or
HTML): each problem's statement, its pictures, its step-by-step solution, the final
answers boxed."""

from __future__ import annotations

from pathlib import Path

import click

from rbdsolve.cli.app import OutputPath, parse_sets, refuse_overwriting_inputs, run_guarded, sources, \
    stderr_is_terminal, tell
from rbdsolve.cli.batch import Settings, solve_all, worst
from rbdsolve.cli.solve import batch_options, print_summary, say_failures
from rbdsolve.errors import ExitCode


@click.command()
@click.argument("paths", nargs=-1, required=True, type=click.Path())
@click.option("-o", "--output", required=True, type=OutputPath(dir_okay=False, writable=True),
              help="The key: key.pdf, key.tex, key.md or key.html (the suffix picks the format).")
@click.option("--title", help="The key's title (default: the problems' common source, or the folder's name).")
@click.option("--figures/--no-figures", default=True, show_default=True,
              help="Draw each planar scene and its mode shapes into the key.")
@batch_options
def key(paths, output, title, figures, sets, route, budget, jobs, quiet, debug):
    """Write an answer key for an exam: a folder (or files) of problems in, one document out.

    .tex and .md keys keep their pictures in a folder beside them (key-figures/); .pdf
    and .html keys are single files. A PDF needs a TeX engine: the first of pdflatex,
    lualatex, xelatex and tectonic on PATH, or the one $RBDSOLVE_LATEX names.

    \b
    Examples:
      rbdsolve key problems/sg2150-2015-10-29/ -o key.pdf
      rbdsolve key problems/sg2150-2015-10-29/ -o key.html --title "SG2150, 29 October 2015"
      rbdsolve key p1.yaml p2.yaml -o key.md --no-figures
    """
    run_guarded(debug, lambda: _key(paths, Path(output), title, figures, quiet, jobs,
                                    Settings(tuple(parse_sets(sets).items()), budget, route, debug)))


def _key(paths, output: Path, title: str | None, figures: bool, quiet: bool, jobs: int,
         settings: Settings) -> ExitCode:
    from rbdsolve.render.files import require_folder

    require_folder(output, "the key")  # a typo in -o is said first, before a missing engine
    if output.suffix == ".pdf":  # before sympy is even imported: a missing engine costs no solve
        from rbdsolve.render.pdf import require_engine

        require_engine()
    from rbdsolve.teaching.key import Solved, check_output, key_title, write_key

    check_output(output, figures)
    items = sources(paths)
    refuse_overwriting_inputs(str(output), items)
    outcomes = solve_all(items, settings, jobs, progress=not quiet and stderr_is_terminal())
    say_failures(outcomes)
    problems = [Solved(s.name, s.load, o.report, o.failure.line if o.failure else None, o.spent)
                for s, o in zip(items, outcomes)]
    notes = write_key(output, title or key_title(paths, problems), problems, figures, dict(settings.values),
                      settings.budget)
    for note in notes:
        tell(note)
    if not quiet:
        if len(outcomes) > 1:
            print_summary(outcomes)
        tell(f"wrote {output}")
    return worst(outcomes)
