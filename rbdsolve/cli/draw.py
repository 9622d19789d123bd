"""``rbdsolve draw``: a planar scene to scale at a configuration, and its mode shapes."""

from __future__ import annotations

from pathlib import Path

import click

from rbdsolve.cli.app import OutputPath, Source, append_help, check_sets, debug_option, parse_sets, run_guarded, \
    tell
from rbdsolve.cli.solve import DEFAULT_BUDGET, Budget, sets_option
from rbdsolve.errors import ExitCode, InputError, Location, UnsolvedError, did_you_mean, printable

DRAW_EXAMPLES = """
\b
Examples:
  rbdsolve draw problems/sg2150-2015-10-29/p1-two-rods.yaml -o p1.png
  rbdsolve draw p1.yaml -o p1.svg --at theta=0.3 --at phi=-pi/6
  rbdsolve draw p1.yaml -o p1.png --set r=2 --no-modes

\b
With a modes question, the mode shapes go next to the scene (p1-modes.png);
the paths written are printed, one per line. Exit codes: 0 drawn, 1 the mode
shapes could not be computed, 2 bad input (also: a scene that is not planar).
"""


@click.command()
@click.argument("path", type=click.Path(dir_okay=False))
@click.option("-o", "--output", required=True, type=OutputPath(dir_okay=False),
              help="The picture to write: a .png or .svg file.")
@click.option("--at", "at", multiple=True, metavar="COORDINATE=VALUE",
              help="Draw at this value of a coordinate (repeatable; a number or an expression "
                   "in the parameters, such as pi/6). Default: the modes question's equilibrium "
                   "or the impact's configuration, else 0.")
@sets_option
@click.option("--modes/--no-modes", default=True, show_default=True,
              help="With a modes question, also draw its mode shapes (OUTPUT's name + '-modes').")
@click.option("--budget", type=Budget(), default=DEFAULT_BUDGET, show_default=True,
              metavar="SECONDS", help="Budget of processor seconds for the whole drawing: the model, then each "
                                      "picture of mode shapes a share of what is left; a picture past its share is "
                                      "not drawn (exit code 1).")
@debug_option
def draw(path, output, at, sets, modes, budget, debug):
    """Draw a planar scene to scale: bodies by shape, points labelled, gravity.

    Lengths come from the file's values and --set; a parameter without a value is
    drawn as 1 (the picture says so). Scenes turned in 3D are refused (exit code 2).
    """
    run_guarded(debug, lambda: _draw(path, Path(output), at, sets, modes, budget))


append_help(draw, DRAW_EXAMPLES)


def _draw(path: str, output: Path, at: tuple[str, ...], sets: tuple[str, ...], modes: bool,
          budget: float = DEFAULT_BUDGET) -> ExitCode:
    from rbdsolve.errors import RbdError
    from rbdsolve.model.build import build_model
    from rbdsolve.render.files import publish, require_folder, staging
    from rbdsolve.solvers.routes.budget import Allowance, OutOfTime, within
    from rbdsolve.render.drawing.figures import (
        check_suffix,
        modes_questions,
        save_modes,
        save_scene,
    )

    check_suffix(output)
    require_folder(output, "the picture")
    problem = Source(path).load()
    values = check_sets(parse_sets(sets), problem)
    run = Allowance(budget)  # one budget: the model, then each picture of mode shapes a share of what is left
    try:
        with within(run.left(), "the model (T and V)", budget):
            model = build_model(problem)
    except OutOfTime as exc:
        raise UnsolvedError(f"{path}: {exc}") from None
    model = model.with_values(values) if values else model
    with staging(output) as stage:  # the scene and its mode shapes appear together, or neither
        drawn = [save_scene(model, stage / output.name, configuration(model, at)).path]
        code = ExitCode.OK
        asked = modes_questions(model) if modes else []
        for n, question in enumerate(asked, 1):
            name = f"{output.stem}-modes{'' if n == 1 else f'-{n}'}{output.suffix}"
            try:
                with within(run.share(len(asked) - n + 1), "the mode shapes", budget):
                    drawn.append(save_modes(model, question, stage / name).path)
            except (RbdError, OutOfTime) as exc:  # the scene is drawn; say why the modes are not
                tell(f"{question.loc}: no mode shapes: {exc}")
                code = max(code, getattr(exc, "exit_code", ExitCode.UNSOLVED))
        publish([(picture, output.with_name(picture.name)) for picture in drawn])
    for picture in drawn:
        click.echo(printable(str(output.with_name(picture.name))))
    return code


def configuration(model, items: tuple[str, ...]) -> dict[str, float]:
    """``--at NAME=VALUE``: a coordinate of the model, a number or an expression in the
    parameters (read by the problem files' own expression parser, never eval)."""
    from rbdsolve.render.drawing.sketch import NotDrawable, number
    from rbdsolve.problem import expr as ex

    names = model.coordinate_names()
    out: dict[str, float] = {}
    for item in items:
        name, sep, text = (part.strip() for part in item.partition("="))
        if not sep or not name.isidentifier():
            raise InputError(f"--at expects COORDINATE=VALUE, found '{item}'")
        if name not in names:
            raise InputError(f"--at {name}: {model.problem.file} has no coordinate '{name}'"
                             f"{did_you_mean(name, names)} (coordinates: {', '.join(names)})")
        scope = ex.Scope(frozenset(model.symbols.parameters))
        tree = ex.parse(text, Location(f"--at {name}", 1, 1), scope, plain=False)
        try:
            out[name] = number(model, model.symbols.scalar(tree))
        except NotDrawable:
            raise InputError(f"--at {name}: '{text}' is not a real number") from None
    return out
