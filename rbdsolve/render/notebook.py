"""What a notebook shows as LaTeX for a solved problem or question: the boxed results,
one display of math (``$$\\begin{gathered} … \\end{gathered}$$``), which MathJax
typesets in a notebook and nbconvert puts in a PDF as it is. The whole worked
solution is the HTML and Markdown displays' (render/html.py, render/markdown.py)."""

from __future__ import annotations

from typing import Iterable

from rbdsolve.form.printers import relation_latex
from rbdsolve.render.latex import text
from rbdsolve.report.steps import Solution, StepKind


def results_latex(solutions: Iterable[Solution]) -> str:
    """Each question's results, boxed, or why it has none, one line each."""
    lines = []
    for s in solutions:
        lines += [f"\\boxed{{{relation_latex(rel)}}}" for step in s.steps if step.kind is StepKind.RESULT
                  for rel in step.math]
        if s.error:
            lines.append(f"\\text{{{text(s.question)}: could not answer: {text(s.error)}}}")
    if not lines:
        return ""
    return "$$\\begin{gathered}\n" + " \\\\\n".join(lines) + "\n\\end{gathered}$$"
