"""Markdown with $…$ LaTeX math: one section per problem, one per question."""

from __future__ import annotations

from rbdsolve.form.printers import relation_latex
from rbdsolve.render.numbers import numeric_lines, route_text
from rbdsolve.report.key import AnswerKey, Picture
from rbdsolve.report.steps import ProblemReport, Step, StepKind


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
    lines = [f"{head} {report.title}", ""]
    if report.source:
        lines += [f"*{report.source}* — `{report.file}`", ""]
    if report.statement:
        lines += [report.statement, ""]
    lines += [f"![{p.caption}]({p.path.as_posix()})\n\n*{p.caption}*\n" for p in pictures]
    if report.values:
        lines += ["Parameter values: " + ", ".join(f"${k} = {v:g}$" for k, v in report.values.items()), ""]
    if report.model.steps:
        lines += [f"{head}# Model", ""]
        for step in report.model.steps:
            lines += _step(step)
    for number, s in enumerate(report.solutions, start=1):
        lines += [f"{head}# Question {number}: {s.question}", "", f"*Route: {route_text(s)}.*", ""]
        for step in s.steps:
            lines += _step(step)
        lines += [f"> **Warning:** {w}" for w in s.warnings]
        if s.error:
            lines += [f"> **Could not answer:** {s.error}", ""]
        numbers = numeric_lines(s.values)
        if numbers:
            lines += ["Numeric values:", ""] + [f"- `{line}`" for line in numbers] + [""]
    return "\n".join(lines) + "\n"


def render_key(key: AnswerKey) -> str:
    """The answer key as one Markdown document: a title, then each problem a section."""
    parts = [f"# {key.title}\n"]
    for entry in key.entries:
        if entry.report is None:
            parts.append(f"## {entry.source}\n\n> **Not solved:** {entry.failure}\n")
        else:
            parts.append(render(entry.report, entry.pictures, level=2))
    return "\n".join(parts)
