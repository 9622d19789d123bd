"""Markdown with $…$ LaTeX math: one section per problem, one per question."""

from __future__ import annotations

from rbdsolve.form.printers import relation_latex
from rbdsolve.render.numbers import accuracy_lines, groups, route_text, tail_text, unit_text, value_latex
from rbdsolve.report.key import AnswerKey, Picture
from rbdsolve.report.steps import ProblemReport, Step, StepKind, accuracy_steps, answer_steps
from rbdsolve.errors import printable


# Parentheses stay as they are: without a '[…]' before them they make no link, and a
# backslashed one, \( … \), is where MathJax and KaTeX start inline math (the key's
# statement "(below O)" was typeset as math in a viewer that shows its $$…$$).
_MARKUP = {"<": "&lt;", ">": "&gt;", "&": "&amp;"} | {c: "\\" + c for c in "\\`*_[]#$|!~"}


def md(text: str, lines: bool = False) -> str:
    """Text from a file as Markdown text: control characters escaped (printable), HTML
    as entities (no <script>, no <img onerror>), and Markdown's own marks backslashed (no
    links, images, emphasis, headings or $math$ a file did not mean)."""
    return "".join(_MARKUP.get(c, c) for c in printable(text, lines))


def _step(step: Step) -> list[str]:
    out = []
    if step.text:
        out.append(f"*{step.text}*" if step.kind is StepKind.NOTE else step.text)
    for rel in step.math:
        math = relation_latex(rel)
        out.append(f"$$\\boxed{{{math}}}$$" if step.kind is StepKind.RESULT else f"$${math}$$")
    return out + [""]


def render(report: ProblemReport, pictures: tuple[Picture, ...] = (), level: int = 1) -> str:
    head = "#" * level
    lines = [f"{head} {md(report.title)}", ""]
    if report.source:
        lines += [f"*{md(report.source)}* — {md(report.file)}", ""]
    if report.statement:
        lines += [md(report.statement, lines=True), ""]
    lines += [f"![{md(p.caption)}]({p.path.as_posix()})\n\n*{md(p.caption)}*\n" for p in pictures]
    if report.values:
        given = (f"${value_latex(k, v)}$" + unit_text(report.units.get(k)) + report.degrees_text(k)
                 for k, v in report.values.items())
        lines += ["Parameter values: " + ", ".join(given), ""]
    if report.model.steps:
        lines += [f"{head}# Model", ""]
        for step in report.model.steps:
            lines += _step(step)
    for number, s in enumerate(report.solutions, start=1):
        lines += [f"{head}# Question {number}: {s.question}", "", f"*Route: {route_text(s)}.*", ""]
        for step in answer_steps(s.steps):
            lines += _step(step)
        lines += [f"> **Warning:** {md(w)}" for w in s.warnings]
        if s.error:
            lines += [f"> **Could not answer:** {md(s.error)}", ""]
        lines += _numbers(s)
        lines += _accuracy(accuracy_steps(s.steps), accuracy_lines(s))
    return "\n".join(lines) + "\n"


def _numbers(s) -> list[str]:
    """The numeric block, each value under the name the solution prints, by heading."""
    blocks = groups(s.numbers)
    if not blocks:
        return []
    lines = ["Numeric values:", ""]
    for heading, numbers in blocks:
        lines += [f"- {md(heading)}:"] if heading else []
        indent = "  " if heading else ""
        lines += [f"{indent}- ${relation_latex(n.relation)}${md(tail_text(n))}" for n in numbers]
    return lines + [""]


def _accuracy(steps: tuple[Step, ...], numbers: list[str]) -> list[str]:
    """How accurate the numeric route's answers are, under them, set apart."""
    if not steps and not numbers:
        return []
    lines = ["*Accuracy:*", ""]
    for step in steps:
        lines += _step(step)
    return lines + [f"- `{line}`" for line in numbers] + ([""] if numbers else [])


def render_key(key: AnswerKey) -> str:
    """The answer key as one Markdown document: a title, then each problem a section."""
    parts = [f"# {md(key.title)}\n"]
    for entry in key.entries:
        if entry.report is None:
            parts.append(f"## {md(entry.source)}\n\n> **Not solved:** {md(entry.failure or '')}\n")
        else:
            parts.append(render(entry.report, entry.pictures, level=2))
    return "\n".join(parts)
