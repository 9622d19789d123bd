"""Terminal output with rich: a heading per problem and per question, prose in plain
text, math on indented lines in readable unicode, results in bold."""

from __future__ import annotations

from rich.console import Group
from rich.padding import Padding
from rich.rule import Rule
from rich.text import Text

from rbdsolve.errors import printable
from rbdsolve.form.printers import relation_text
from rbdsolve.render.numbers import accuracy_lines, groups, number_text, route_text
from rbdsolve.render.wrap import wrap_math
from rbdsolve.report.steps import ProblemReport, Solution, Step, StepKind, accuracy_steps, answer_steps

_STYLE = {
    StepKind.GIVEN: "",
    StepKind.DEFINITION: "",
    StepKind.EQUATION: "",
    StepKind.SUBSTITUTION: "",
    StepKind.RESULT: "bold green",
    StepKind.NOTE: "italic",
}


class MathLine:
    """A relation on its own indented line, broken where it is too long for the
    console at a + or − between terms, with a hanging indent (render/wrap.py)."""

    def __init__(self, text: str, style: str) -> None:
        self.text, self.style = text, style

    def __rich_console__(self, console, options):
        for line in wrap_math(self.text, options.max_width):
            yield Text(line, style=self.style, overflow="fold")


def step_lines(step: Step) -> list:
    lines: list = [Text(step.text, style="italic" if step.kind is StepKind.NOTE else "")] if step.text else []
    lines += [MathLine(relation_text(r), _STYLE[step.kind]) for r in step.math]
    return lines


def render(report: ProblemReport) -> Group:
    parts: list = [Rule(Text(printable(report.title), style="bold"), align="left")]
    parts.append(Text(" · ".join(printable(x) for x in (report.source, report.file) if x), style="dim"))
    if report.statement:  # text from the file: no control character reaches the terminal
        parts.append(Padding(Text(printable(report.statement, lines=True)), (1, 0, 0, 0)))
    if report.values:
        given = ", ".join(report.value_text(k) for k in report.values)
        parts.append(Text(f"Parameter values: {given}", style="dim"))
    if report.model.steps:
        parts.append(Padding(Text("Model", style="bold underline"), (1, 0, 0, 0)))
        for step in report.model.steps:
            parts += step_lines(step)
    for number, solution in enumerate(report.solutions, start=1):
        parts += _solution(number, solution)
    parts.append(Text(""))
    return Group(*parts)


def _solution(number: int, s: Solution) -> list:
    head = Text(f"Question {number}: {s.question}", style="bold underline")
    head.append(f"   ({route_text(s)})", style="dim")
    out: list = [Padding(head, (1, 0, 0, 0))]
    for step in answer_steps(s.steps):
        out += step_lines(step)
    for warning in s.warnings:
        out.append(Text(f"warning: {printable(warning)}", style="yellow"))
    if s.error:
        out.append(Text(f"could not answer: {printable(s.error)}", style="bold red"))
    blocks = groups(s.numbers)
    if blocks:
        out += [Text("Numeric values:")]
        for heading, numbers in blocks:
            out += [Text(f"  {heading}:")] if heading else []
            out += [MathLine(number_text(n), "cyan") for n in numbers]
    return out + _accuracy(accuracy_steps(s.steps), accuracy_lines(s))


def _accuracy(steps: tuple[Step, ...], numbers: list[str]) -> list:
    """How accurate the numeric route's answers are, dim, under them."""
    if not steps and not numbers:
        return []
    out: list = [Text("Accuracy:", style="dim")]
    for step in steps:
        out += [Text(line.plain, style="dim") if isinstance(line, Text) else MathLine(line.text, "dim")
                for line in step_lines(step)]
    return out + [Text("    " + line, style="dim") for line in numbers]
