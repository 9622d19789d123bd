"""``rbdsolve key``: a whole exam's answer key as one document (PDF, LaTeX, Markdown or
HTML): each problem's statement, its pictures, its step-by-step solution, the final
answers boxed."""

from __future__ import annotations

import re
import shutil
import tempfile
from pathlib import Path

import click

from rbdsolve.cli.app import Source, main, parse_sets, run_guarded, sources, stderr_is_terminal
from rbdsolve.cli.batch import Outcome, Settings, solve_all, worst
from rbdsolve.cli.solve import batch_options, print_summary, say_failures
from rbdsolve.errors import ExitCode, InputError

KINDS = (".pdf", ".tex", ".md", ".html")


@main.command()
@click.argument("paths", nargs=-1, required=True, type=click.Path())
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False, writable=True),
              help="The key: key.pdf, key.tex, key.md or key.html (the suffix picks the format).")
@click.option("--title", help="The key's title (default: the problems' common source, or the folder's name).")
@click.option("--figures/--no-figures", default=True, show_default=True,
              help="Draw each planar scene and its mode shapes into the key.")
@batch_options
def key(paths, output, title, figures, sets, route, budget, jobs, quiet, debug):
    """Write an answer key for an exam: a folder (or files) of problems in, one document out.

    .tex and .md keys keep their pictures in a folder beside them (key-figures/); .pdf
    and .html keys are single files (a PDF needs a LaTeX engine such as pdflatex).

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
    _check_output(output)
    items = sources(paths)
    outcomes = solve_all(items, settings, jobs, progress=not quiet and stderr_is_terminal())
    say_failures(outcomes)
    with tempfile.TemporaryDirectory(prefix="rbdsolve-key-") as scratch:
        _write(output, title or _title(paths, outcomes), items, outcomes, Path(scratch), figures, settings)
    if not quiet:
        if len(outcomes) > 1:
            print_summary(outcomes)
        click.echo(f"wrote {output}", err=True)
    return worst(outcomes)


def _check_output(output: Path) -> None:
    """Before any solving: a key's format and a folder to write it in."""
    if output.suffix not in KINDS:
        raise InputError(f"-o {output}: the key is written as {', '.join(KINDS)}; found '{output.suffix or output.name}'")
    if not output.parent.is_dir():
        raise InputError(f"-o {output}: there is no folder {output.parent}/ to write the key in")


def _safe(name: str) -> str:
    """A file name TeX, Markdown and HTML all read as it is: letters, digits, . _ -."""
    return re.sub(r"[^A-Za-z0-9._-]+", "-", name).strip("-") or "key"


def _title(paths, outcomes: list[Outcome]) -> str:
    from rbdsolve.report.key import default_title

    return default_title(list(paths), [o.report.source if o.report else "" for o in outcomes])


def _write(output: Path, title: str, items: list[Source], outcomes: list[Outcome], scratch: Path,
           figures: bool, settings: Settings) -> None:
    """Pictures into a folder beside a .tex/.md key, or into scratch for a single-file
    key; then the document, in the format the suffix names."""
    from rbdsolve.report.key import AnswerKey, KeyEntry

    single_file = output.suffix in (".pdf", ".html")
    home = scratch if single_file else output.parent
    folder = home / f"{_safe(output.stem)}-figures"
    suffix = ".svg" if output.suffix == ".html" else ".png"
    entries = tuple(KeyEntry(o.source, o.report, o.failure.line if o.failure else None,
                             _pictures(s, folder, home, f"{n:02d}-{_safe(Path(s.name).stem)}", suffix, settings)
                             if figures and o.report is not None else ())
                    for n, (s, o) in enumerate(zip(items, outcomes), start=1))
    _document(AnswerKey(title, entries), output, home, scratch)


def _document(answer_key, output: Path, home: Path, scratch: Path) -> None:
    from rbdsolve.cli.app import write_text

    if output.suffix == ".md":
        from rbdsolve.render.markdown import render_key

        write_text(render_key(answer_key), str(output))
    elif output.suffix == ".html":
        from rbdsolve.render.html import render_key

        write_text(render_key(answer_key, home), str(output))
    else:
        from rbdsolve.render.latex import render_key

        tex = render_key(answer_key)
        if output.suffix == ".tex":
            write_text(tex, str(output))
            return
        from rbdsolve.render.pdf import compile_pdf

        shutil.copyfile(compile_pdf(tex, scratch), output)


def _pictures(source: Source, folder: Path, home: Path, stem: str, suffix: str, settings: Settings):
    """The scene and its mode shapes, drawn at the values the solution used; none for a
    scene that is not planar. A picture that fails is said on standard error and left
    out: the key still has the solution."""
    from rbdsolve.model.build import build_model
    from rbdsolve.render.draw import save_figures
    from rbdsolve.report.key import Picture

    try:
        model = build_model(source.load())
        if settings.values:
            model = model.with_values(dict(settings.values))
        folder.mkdir(parents=True, exist_ok=True)
        figures = save_figures(model, folder, stem, suffix)
    except Exception as exc:  # noqa: BLE001 - a picture must not lose the key
        click.echo(f"{source.name}: no picture in the key: {type(exc).__name__}: {exc}", err=True)
        return ()
    return tuple(Picture(f.path.relative_to(home), f.caption) for f in figures)
