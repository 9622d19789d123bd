"""The rbdsolve command line: each command is load -> build -> solve -> render.

Heavy modules (sympy, rich) are imported inside the commands that need them, so
``rbdsolve --help`` and ``rbdsolve check`` start fast.
"""

from __future__ import annotations

import sys
import traceback
from fractions import Fraction
from pathlib import Path

import click

from rbdsolve import __version__
from rbdsolve.errors import ExitCode, InputError, InternalError, RbdError, UnsolvedError

FORMATS = ("terminal", "markdown", "latex", "json")
ROUTES = ("auto", "exact", "numeric")  # spelled out here: importing the solvers would load sympy
EXPECTED_SUFFIX = ".expected.yaml"  # golden answers beside a problem file, not problems
DEFAULT_BUDGET = 60.0  # seconds per question: an exam question that takes longer is stuck

SOLVE_EXAMPLES = """
\b
Examples:
  rbdsolve solve problems/sg2150-2015-10-29/p1-two-rods.yaml
  rbdsolve solve problems/sg2150-2015-10-29/          # a whole exam, in file order
  rbdsolve solve p1.yaml --format json | jq .results  # JSON Lines for scripts
  rbdsolve solve p1.yaml --set m=2 --set r=0.5 --set g=9.81
  rbdsolve solve p1.yaml --route numeric --set m=1 --set r=1 --set g=9.81
  rbdsolve solve p1.yaml --format latex -o p1.tex

\b
Exit codes: 0 solved, 1 a question could not be answered,
            2 bad input or usage, 3 internal error.
"""


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="rbdsolve")
def main() -> None:
    """rbdsolve: rigid body dynamics exam problems, solved step by step.

    A problem is a short YAML scene (parameters, coordinates, points, bodies,
    forces, questions); see docs/format.md and the examples in problems/.

    \b
    Questions: eom, equilibria, modes (Lagrange's equations, equilibria and their
    stability, small oscillations; in moving frames too), impact (Lagrange's
    equations for impact), inertia (tensors, principal axes), steady_spin (Euler's
    equations of a free body), steady_motion (rolling, tops, in a turning triad).
    """


def expand_paths(paths: tuple[str, ...]) -> list[Path]:
    """Files as given; a folder gives the *.yaml files below it, in path order."""
    out: list[Path] = []
    for raw in paths:
        path = Path(raw)
        if path.is_dir():
            found = sorted(p for p in path.rglob("*") if p.is_file() and _is_problem(p))
            if not found:
                raise InputError(f"{raw}: no problem files (*.yaml) in this folder")
            out += found
        else:
            out.append(path)
    return out


def _is_problem(path: Path) -> bool:
    return path.suffix in (".yaml", ".yml") and not path.name.endswith(EXPECTED_SUFFIX)


def parse_sets(items: tuple[str, ...]) -> dict[str, Fraction]:
    from rbdsolve.problem.expr import parse_number
    from rbdsolve.errors import Location

    values = {}
    for item in items:
        name, sep, text = item.partition("=")
        if not sep or not name.strip().isidentifier():
            raise InputError(f"--set expects NAME=VALUE, found '{item}'")
        try:
            values[name.strip()] = parse_number(text, Location("--set", 1, len(name) + 2))
        except InputError as exc:  # said as the option, not as a place in a file
            raise InputError(f"--set {name.strip()}: {exc.message}") from None
    return values


@main.command()
@click.argument("paths", nargs=-1, required=True, type=click.Path())
@click.option("-f", "--format", "fmt", type=click.Choice(FORMATS), default="terminal",
              show_default=True, help="Output format.")
@click.option("-o", "--output", type=click.Path(dir_okay=False, writable=True),
              help="Write to this file instead of standard output.")
@click.option("--set", "sets", multiple=True, metavar="NAME=VALUE",
              help="Give a parameter a numeric value (repeatable); overrides the file's values.")
@click.option("--route", type=click.Choice(ROUTES), default="auto", show_default=True,
              help="exact (sympy), numeric (floating point; every parameter needs a value) or auto "
                   "(exact, then numeric where exact cannot answer or runs out of its budget).")
@click.option("--budget", type=click.FloatRange(min=0, min_open=True), default=DEFAULT_BUDGET,
              show_default=True, metavar="SECONDS",
              help="Time budget for building each file's model and for each route of each question; "
                   "a question past it is left unanswered (exit code 1), or, with --route auto and "
                   "every value given, answered by the numeric route, which gets the same budget "
                   "again (so a question may take twice the budget; a model whose T and V run out "
                   "shows the coordinates only).")
@click.option("--debug", is_flag=True, help="Show the traceback of an internal error.")
def solve(paths, fmt, output, sets, route, budget, debug):
    """Solve problem files and print their step-by-step solutions."""
    code = _guard(debug, lambda: _solve(paths, fmt, output, sets, debug, budget, route))
    sys.exit(int(code))
solve.help = (solve.help or "").rstrip() + "\n\n" + SOLVE_EXAMPLES.lstrip("\n")


@main.command()
@click.argument("paths", nargs=-1, required=True, type=click.Path())
@click.option("--debug", is_flag=True, help="Show the traceback of an internal error.")
def check(paths, debug):
    """Validate problem files without solving them (fast: no algebra).

    \b
    Example:
      rbdsolve check problems/sg2150-2015-10-29/
    """
    code = _guard(debug, lambda: _check(paths))
    sys.exit(int(code))


def _guard(debug: bool, run) -> ExitCode:
    try:
        return run()
    except RbdError as exc:
        click.echo(str(exc), err=True)
        return exc.exit_code
    except KeyboardInterrupt:
        click.echo("rbdsolve: interrupted", err=True)
        return ExitCode.INTERNAL
    except Exception as exc:  # noqa: BLE001 - the one place that reports a bug
        if debug:
            traceback.print_exc()
        click.echo(f"rbdsolve: internal error: {type(exc).__name__}: {exc} "
                   "(run with --debug for the traceback)", err=True)
        return ExitCode.INTERNAL


def _check(paths) -> ExitCode:
    from rbdsolve.problem import load_file

    worst = ExitCode.OK
    for path in expand_paths(paths):
        try:
            problem = load_file(path)
        except InputError as exc:
            click.echo(str(exc), err=True)
            worst = max(worst, exc.exit_code)
            continue
        questions = ", ".join(q.kind.value for q in problem.questions)
        click.echo(f"{path}: ok ({questions})")
    return worst


def _solve(paths, fmt: str, output: str | None, sets, debug: bool = False,
           budget: float | None = DEFAULT_BUDGET, route: str = "auto") -> ExitCode:
    from rbdsolve.problem import load_file
    from rbdsolve.solvers import Options, RouteChoice, solve_file

    values = parse_sets(sets)
    reports, chunks, worst = [], [], ExitCode.OK
    for path in expand_paths(paths):
        try:
            problem = load_file(path)
            _check_sets(values, problem, path)
            report = solve_file(problem, Options(values=values, budget=budget, route=RouteChoice(route)))
        except (InputError, UnsolvedError) as exc:
            worst = max(worst, _file_failed(str(path), exc, str(exc), fmt, chunks))
            continue
        except Exception as exc:  # noqa: BLE001 - a bug in one file must not lose the others
            if debug:
                traceback.print_exc()
            message = (f"{path}: rbdsolve: internal error: {type(exc).__name__}: {exc} "
                       "(run with --debug for the traceback)")
            worst = max(worst, _file_failed(str(path), InternalError(str(exc)), message, fmt, chunks))
            continue
        reports.append(report)
        if not report.solved:
            worst = max(worst, ExitCode.UNSOLVED)
        if fmt == "json":
            from rbdsolve.render.json import render_report

            chunks.append(render_report(report))
    _write(fmt, reports, chunks, output)
    return worst


def _file_failed(path: str, exc, message: str, fmt: str, chunks: list[str]) -> ExitCode:
    click.echo(message, err=True)
    if fmt == "json":
        from rbdsolve.render.json import render_error

        chunks.append(render_error(path, exc))
    return exc.exit_code


def _check_sets(values: dict[str, Fraction], problem, path: Path) -> None:
    names = [p.name for p in problem.parameters]
    for name, value in values.items():
        if name not in names:
            from rbdsolve.errors import did_you_mean

            raise InputError(f"--set {name}: {path} has no parameter '{name}'{did_you_mean(name, names)}")
        if value <= 0 and next(p for p in problem.parameters if p.name == name).positive:
            raise InputError(f"--set {name}: the parameter is positive, found {value}")


def _write(fmt: str, reports, chunks: list[str], output: str | None) -> None:
    if fmt == "json":
        text = "".join(chunks)
    elif fmt == "markdown":
        from rbdsolve.render.markdown import render

        text = "\n".join(render(r) for r in reports)
    elif fmt == "latex":
        if not reports:
            return
        from rbdsolve.render.latex import render_document

        text = render_document(reports)
    else:
        _write_terminal(reports, output)
        return
    if output:
        with _open_output(output) as handle:
            handle.write(text)
    else:
        click.echo(text, nl=False)


def _open_output(output: str):
    try:
        return open(output, "w", encoding="utf-8")
    except OSError as exc:
        raise InputError(f"cannot write {output}: {exc.strerror}") from None


def _write_terminal(reports, output: str | None) -> None:
    from rich.console import Console

    from rbdsolve.render.terminal import render

    if output:
        with _open_output(output) as handle:
            console = Console(file=handle, color_system=None, width=100, highlight=False)
            for report in reports:
                console.print(render(report))
        return
    console = Console(highlight=False)
    for report in reports:
        console.print(render(report))


if __name__ == "__main__":  # pragma: no cover
    main()
