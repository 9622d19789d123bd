"""What the terminal shows of a report, line by line, before any layout (no rich here):
the title's rule, prose (wrapped between words), relations (broken at their operators,
render/wrap.py), each with its styles. render/terminal.py lays these out with rich, in
colour; render/text.py lays them out itself where no colour is asked for (a pipe, a
file), without importing rich, and with the same characters rich writes."""

from __future__ import annotations

from dataclasses import dataclass, replace

from rbdsolve.errors import printable
from rbdsolve.form.printers import relation_text
from rbdsolve.render.numbers import accuracy_lines, groups, number_text, route_text
from rbdsolve.report.steps import ProblemReport, Solution, Step, StepKind, accuracy_steps, answer_steps

PROSE, MATH, RULE = "prose", "math", "rule"

_STYLE = {
    StepKind.GIVEN: "",
    StepKind.DEFINITION: "",
    StepKind.EQUATION: "",
    StepKind.SUBSTITUTION: "",
    StepKind.RESULT: "bold green",
    StepKind.NOTE: "italic",
}


@dataclass(frozen=True)
class Line:
    """One line of a report as written, before it is fitted to a width: ``pieces`` of
    text, each with its rich style ('' for none); ``gap``: a blank line above it."""

    pieces: tuple[tuple[str, str], ...]
    kind: str = PROSE  # PROSE, MATH (indented, broken at + and −) or RULE (the title, a rule after it)
    gap: bool = False

    @property
    def text(self) -> str:
        return "".join(text for text, _ in self.pieces)


def line(text: str, style: str = "", kind: str = PROSE, gap: bool = False) -> Line:
    return Line(((text, style),), kind, gap)


def step_lines(step: Step) -> list[Line]:
    lines = [line(step.text, "italic" if step.kind is StepKind.NOTE else "")] if step.text else []
    return lines + [line(relation_text(r), _STYLE[step.kind], MATH) for r in step.math]


def report_lines(report: ProblemReport) -> list[Line]:
    out = [line(printable(report.title), "bold", RULE)]
    out.append(line(" · ".join(printable(x) for x in (report.source, report.file) if x), "dim"))
    if report.statement:  # text from the file: no control character reaches the terminal
        out.append(line(printable(report.statement, lines=True), gap=True))
    if report.values:
        given = ", ".join(report.value_text(k) for k in report.values)
        out.append(line(f"Parameter values: {given}", "dim"))
    if report.model.steps:
        out.append(line("Model", "bold underline", gap=True))
        for step in report.model.steps:
            out += step_lines(step)
    for number, solution in enumerate(report.solutions, start=1):
        out += _solution(number, solution)
    return out + [line("")]


def _solution(number: int, s: Solution) -> list[Line]:
    head = Line(((f"Question {number}: {s.question}", "bold underline"), (f"   ({route_text(s)})", "dim")), gap=True)
    out = [head]
    for step in answer_steps(s.steps):
        out += step_lines(step)
    for warning in s.warnings:
        out.append(line(f"warning: {printable(warning)}", "yellow"))
    if s.error:
        out.append(line(f"could not answer: {printable(s.error)}", "bold red"))
    blocks = groups(s.numbers)
    if blocks:
        out.append(line("Numeric values:"))
        for heading, numbers in blocks:
            out += [line(f"  {heading}:")] if heading else []
            out += [line(number_text(n), "cyan", MATH) for n in numbers]
    return out + _accuracy(accuracy_steps(s.steps), accuracy_lines(s))


def _accuracy(steps: tuple[Step, ...], numbers: list[str]) -> list[Line]:
    """How accurate the numeric route's answers are, dim, under them."""
    if not steps and not numbers:
        return []
    out = [line("Accuracy:", "dim")]
    for step in steps:
        out += [replace(x, pieces=((x.text, "dim"),)) for x in step_lines(step)]
    return out + [line("    " + text, "dim") for text in numbers]
