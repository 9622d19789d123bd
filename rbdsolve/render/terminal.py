"""Terminal output with rich: a heading per problem and per question, prose in plain
text, math on indented lines in readable unicode, results in bold; the lines
themselves, and their styles, are render/lines.py's."""

from __future__ import annotations

from rich.console import Group
from rich.padding import Padding
from rich.rule import Rule
from rich.text import Text

from rbdsolve.render import lines as ln
from rbdsolve.render.wrap import wrap_math
from rbdsolve.report.steps import ProblemReport, Step


class MathLine:
    """A relation on its own indented line, broken where it is too long for the
    console at a + or − between terms, with a hanging indent (render/wrap.py)."""

    def __init__(self, text: str, style: str) -> None:
        self.text, self.style = text, style

    def __rich_console__(self, console, options):
        for line in wrap_math(self.text, options.max_width):
            yield Text(line, style=self.style, overflow="fold")


def shown(line: ln.Line):
    """One line as rich draws it."""
    if line.kind == ln.MATH:
        return MathLine(line.text, line.pieces[0][1])
    (first, style), *rest = line.pieces
    text = Text(first, style=style)
    for piece, style in rest:
        text.append(piece, style=style)
    if line.kind == ln.RULE:
        return Rule(text, align="left")
    return Padding(text, (1, 0, 0, 0)) if line.gap else text


def step_lines(step: Step) -> list:
    return [shown(line) for line in ln.step_lines(step)]


def render(report: ProblemReport) -> Group:
    return Group(*[shown(line) for line in ln.report_lines(report)])
