"""``rbdsolve new KIND``: a commented template problem for one question kind, to start
a new problem from. The templates are package data (``rbdsolve/templates/KIND.yaml``),
copied as they are: no YAML parsing and no sympy, so the command is instant."""

from __future__ import annotations

from importlib import resources
from pathlib import Path

import click

from rbdsolve.cli.app import OutputPath, append_help, debug_option, run_guarded, tell, write_text
from rbdsolve.errors import ExitCode, InputError

# Spelled out (as solve's ROUTES are) so that the command line starts without loading the
# problem package; tests/test_templates.py checks these are exactly QuestionKind's values.
KINDS = {
    "eom": "Lagrange's equations (a rolling wheel carrying a pendulum)",
    "equilibria": "equilibria and stability (a sliding ladder held by a spring)",
    "modes": "small oscillations (a rod pendulum with a bob on a string)",
    "inertia": "inertia tensor, principal axes (a plate about its corner)",
    "impact": "Lagrange's equations for impact (a cart and rod, struck)",
    "steady_spin": "steady spins of a free body (a phone thrown spinning)",
    "steady_motion": "steady motion, dL/dt = M (a conical pendulum of a rod)",
    "kinematics": "a point's position, velocity and acceleration at a state (a slider-crank)",
    "reactions": "forces at supports, energy (a bar swinging on a pivot)",
    "energy": "speed by conservation of energy, T + V constant (a bar falling from upright)",
}

# Scenes rather than question kinds: templates that show a part of the format.
SCENES = {
    "rolling": "a contact: a cylinder rolling inside a cylinder (equilibria, modes)",
    "rocking": "a contact on a curved edge: a half-disk rocking on the floor (modes)",
}

NEW_EXAMPLES = """
\b
Examples:
  rbdsolve new --list
  rbdsolve new modes                      # print the template
  rbdsolve new modes -o my-problem.yaml && rbdsolve solve my-problem.yaml
  rbdsolve new impact -o hit.yaml --force # replace an existing file
"""


@click.command()
@click.argument("kind", required=False, type=click.Choice([*KINDS, *SCENES]), metavar="KIND")
@click.option("-o", "--output", type=OutputPath(dir_okay=False),
              help="Write to this file instead of standard output.")
@click.option("--force", is_flag=True, help="Overwrite the output file if it exists.")
@click.option("--list", "list_kinds", is_flag=True, help="List the kinds, one line each, and exit.")
@debug_option
def new(kind, output, force, list_kinds, debug):
    """Write a commented template problem for one question KIND.

    Each template is a small working problem (it solves as it is) whose comments
    explain every section and the options of its question; edit it into yours.
    """
    if list_kinds:
        click.echo(kinds_listing())
        return
    if kind is None:
        raise click.UsageError("Missing argument 'KIND' (or give --list).")
    run_guarded(debug, lambda: _new(kind, output, force))


def kinds_listing() -> str:
    """One aligned line per kind: its name and what its template shows."""
    width = max(map(len, [*KINDS, *SCENES]))
    return "\n".join(f"{kind:<{width}}  {text}" for kind, text in {**KINDS, **SCENES}.items())


def template_text(kind: str) -> str:
    """The template for ``kind``, read from the installed package (works from a wheel
    or a zip too, which a path relative to this file would not)."""
    return (resources.files("rbdsolve") / "templates" / f"{kind}.yaml").read_text(encoding="utf-8")


def _new(kind: str, output: str | None, force: bool) -> ExitCode:
    if output and Path(output).exists() and not force:
        raise InputError(f"{output} already exists; use --force to overwrite it")
    write_text(template_text(kind), output)
    if output:  # on standard error, so that standard output stays the template alone
        tell(f"wrote {output} (the '{kind}' template); solve it with: rbdsolve solve {output}")
    return ExitCode.OK


# The kinds and the examples in --help, from the same table as --list.
append_help(new, "\b\nKinds:\n" + "\n".join(f"  {line}" for line in kinds_listing().splitlines())
            + "\n" + NEW_EXAMPLES)
