"""``rbdsolve grade``: a student checks their own answers against a problem's exact
solution; a teacher grades a class's numeric answers against ``rbdsolve variants``."""

from __future__ import annotations

import sys
from dataclasses import replace
from pathlib import Path

import click

from rbdsolve.cli.app import OutputPath, Source, append_help, debug_option, refuse_overwriting_inputs, \
    run_guarded, write_text
from rbdsolve.cli.solve import DEFAULT_BUDGET, budget_option
from rbdsolve.errors import ExitCode, InputError, Location

GRADE_EXAMPLES = """
\b
A student, checking answers worked by hand (the answer itself is never printed
unless --show is given):
  rbdsolve grade problems/sg2150-2015-10-29/p1-two-rods.yaml \\
      --answer 'modes.frequencies[1] = sqrt(24*g/(25*r))' --answer 'omega2 = sqrt(2*g/r)'
  rbdsolve grade p1.yaml my-answers.txt      # one 'ANSWER = EXPRESSION' a line

\b
A teacher, grading a class that had the variants of a problem:
  rbdsolve variants p1.yaml --count 120 --seed 7 -o variants.json
  rbdsolve grade variants.json answers.csv -o grades.csv
  rbdsolve grade variants.json answers.csv --sig-figs 3 --slip-credit 0.5

\b
answers.csv has a header 'student,variant,' then the answers it gives, e.g.
  student,variant,omega1,omega2,equilibrium2.stability
  anna,17,4.38,6.26,unstable

\b
Answers are named by their JSON path with indices from 1 (docs/json.md), e.g.
modes.frequencies[1], equilibria.equilibria[2].at.phi, impact.velocities.x,
inertia.principal_moments[3], or an alias: omega1, lambda2, equilibrium2.theta,
equilibrium2.stability, dot(x) (after an impact), J1 (a principal moment); in a
student's check also an equilibrium by its place: equilibrium(theta=0, phi=pi).stability.

\b
Exit codes: 0 every answer checked is right, 1 one is not (or could not be
graded), 2 bad input: a bad file or a malformed answer (reported one each; the
rest is still graded), 3 internal error.
"""

FORMATS = ("text", "json")


@click.command()
@click.argument("file", type=click.Path())
@click.argument("answers", required=False, type=click.Path())
@click.option("-a", "--answer", "entries", multiple=True, metavar="'ANSWER = EXPRESSION'",
              help="An answer to check, in the problem's symbols (repeatable).")
@click.option("--show", is_flag=True, help="Also print rbdsolve's answer (a student check).")
@click.option("--rtol", type=click.FloatRange(min=0, max=1), default=0.01, show_default=True,
              help="A number is right within this relative tolerance of the key (a class's numbers; a "
                   "student's number for a file whose parameters all have values).")
@click.option("--atol", type=click.FloatRange(min=0), default=1e-9, show_default=True,
              help="...or within this absolute tolerance (for keys at or near 0).")
@click.option("--sig-figs", type=click.IntRange(min=1, max=15), default=None,
              help="Instead: right within one unit of the key's N-th significant figure.")
@click.option("--slip-credit", type=click.FloatRange(min=0, max=1), default=0.0, show_default=True,
              help="The part of a mark a recognised slip earns (sign, 2π, degrees, root, factor 2).")
@click.option("-o", "--output", type=OutputPath(dir_okay=False, writable=True),
              help="Write the run to this file as JSON (.json); a class's grades also as CSV (.csv, "
                   "one row per student).")
@click.option("-f", "--format", "fmt", type=click.Choice(FORMATS), default="text", show_default=True,
              help="Standard output: a summary (text) or the JSON of the run (docs/json.md).")
@budget_option
@debug_option
def grade(file, answers, entries, show, rtol, atol, sig_figs, slip_credit, output, fmt, budget, debug):
    """Check answers: a student's expressions against a problem's exact solution
    (FILE a problem, answers by --answer or an ANSWERS file), or a class's numbers
    against a variants table (FILE the JSON of 'rbdsolve variants', ANSWERS a CSV).

    Expressions are read like a problem file's (+ - * / **, sqrt, sin, pi, ...; the
    problem's symbols only) and compared exactly, then at random admissible
    parameter values; a wrong answer is said to be off by a sign, a factor 2, 2π
    (ω ↔ f), in degrees, or missing a square root where it is.
    """
    if file.lower().endswith(".json"):
        run_guarded(debug, lambda: _grade_class(file, answers, entries, sig_figs, rtol, atol, slip_credit,
                                                output, fmt, budget))
    else:
        run_guarded(debug, lambda: _check(file, answers, entries, show, output, fmt, _rule(rtol, atol, sig_figs,
                                                                                           slip_credit), budget))


append_help(grade, GRADE_EXAMPLES)


def _rule(rtol: float, atol: float, sig_figs: int | None, slip_credit: float):
    from rbdsolve.teaching.grading import Rule

    return Rule(rtol, atol, sig_figs, slip_credit)


# --- a student's check ---------------------------------------------------------------


def _check(file: str, answers: str | None, entries: tuple[str, ...], show: bool, output: str | None,
           fmt: str, rule, budget: float = DEFAULT_BUDGET) -> ExitCode:
    from rbdsolve.problem import load_file
    from rbdsolve.teaching.check import check, read_entries, read_entry
    from rbdsolve.teaching.grade_report import check_object, dumps

    if output and Path(output).suffix.lower() != ".json":
        raise InputError(f"-o {output}: a check is written as JSON; give a .json file")
    refuse_overwriting_inputs(output, [Source(file)], "the problem file")
    refuse_overwriting_inputs(output, [Source(answers)] if answers else [], "the file of answers")
    if not entries and not answers:
        raise InputError("give the answers to check: --answer 'modes.frequencies[1] = sqrt(2*g/r)', "
                         "or a file of them after the problem")
    parsed, errors = read_entries(answers) if answers else ([], [])
    for n, text in enumerate(entries, start=1):
        try:
            parsed.append(read_entry(text, Location("--answer", n, 1)))
        except InputError as exc:
            errors.append(exc)
    run = check(load_file(file), parsed, budget, rule)
    errors = sorted([*errors, *run.errors], key=lambda e: (e.location.line, e.location.column) if e.location else (0, 0))
    run = replace(run, errors=tuple(errors))
    if output:
        write_text(dumps(check_object(run, show)), output)
    if fmt == "json":
        write_text(dumps(check_object(run, show)), None)
    else:
        write_text("".join(_check_line(c, show) for c in run.checked), None)
    for error in errors:
        click.echo(str(error), err=True)
    if errors:
        return ExitCode.BAD_INPUT
    return ExitCode.OK if all(c.right for c in run.checked) else ExitCode.UNSOLVED


def _check_line(checked, show: bool) -> str:
    from rbdsolve.errors import printable
    from rbdsolve.teaching.verdicts import describe

    line = f"{checked.address} = {printable(checked.given)}: {describe(checked.verdict, show)}\n"
    return line + (f"  the answer: {checked.address} = {checked.answer}\n" if show and checked.answer else "")


# --- a teacher's grading -------------------------------------------------------------


def _grade_class(file: str, answers: str | None, entries: tuple[str, ...], sig_figs: int | None, rtol: float,
                 atol: float, slip_credit: float, output: str | None, fmt: str,
                 budget: float = DEFAULT_BUDGET) -> ExitCode:
    from rbdsolve.teaching.grade_report import class_csv, class_object, dumps
    from rbdsolve.teaching.grading import grade as grade_class, read_key

    if entries:
        raise InputError("--answer checks an expression against a problem file; with a variants table, "
                         "give the class's answers as a CSV")
    if not answers:
        raise InputError(f"give the class's answers after {file}: rbdsolve grade {file} answers.csv")
    if output and Path(output).suffix.lower() not in (".csv", ".json"):
        raise InputError(f"-o {output}: write the grades to a .csv or a .json file")
    refuse_overwriting_inputs(output, [Source(file)], "the variants table")
    refuse_overwriting_inputs(output, [Source(answers)], "the class's answers")
    grades = grade_class(read_key(file), answers, _rule(rtol, atol, sig_figs, slip_credit), budget)
    if output:
        write_text(class_csv(grades) if output.lower().endswith(".csv") else dumps(class_object(grades)), output)
    if fmt == "json":
        write_text(dumps(class_object(grades)), None)
    else:
        _print_summary(grades)
    for error in grades.errors:
        click.echo(str(error), err=True)
    if grades.errors:
        return ExitCode.BAD_INPUT
    return ExitCode.OK if grades.all_right else ExitCode.UNSOLVED


def _print_summary(grades) -> None:
    """The class per answer (right, slips, wrong, blank, ungraded) and its scores."""
    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    from rbdsolve.render.text import no_trailing_spaces
    from rbdsolve.errors import printable
    from rbdsolve.teaching.grading import Outcome, score_counts, tallies

    title = f"{len(grades.students)} students, {printable(grades.key.problem or grades.key.file)}"
    table = Table(title=escape(title), title_justify="left")
    table.add_column("answer", overflow="fold")
    for name in ("right", "slips", "wrong", "blank", "ungraded"):
        table.add_column(name, justify="left" if name == "slips" else "right")
    for t in tallies(grades):
        slips = ", ".join(f"{word} {n}" for word, n in t.slips.items()) or "-"
        share = f" ({100 * t.counts[Outcome.RIGHT] / max(sum(t.counts.values()), 1):.0f} %)"
        table.add_row(escape(printable(t.answer)), f"[green]{t.counts[Outcome.RIGHT]}{share}[/green]", slips,
                      str(t.counts[Outcome.WRONG]), str(t.counts[Outcome.BLANK]), str(t.counts[Outcome.UNGRADED]))
    console = Console(highlight=False, width=100, no_color=True) if not sys.stdout.isatty() \
        else Console(highlight=False)
    with console.capture() as captured:
        console.print(table)
    scores = " · ".join(f"{score:g}/{len(grades.answers)}: {n}" for score, n in score_counts(grades))
    write_text(no_trailing_spaces(captured.get()) + f"scores (students): {scores}\n", None)
