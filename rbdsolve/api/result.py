"""A solved problem and its questions, as Python objects: the answers are the solvers'
own typed answers (frozen dataclasses of sympy objects), the numbers floats, and
every result renders itself in each of the CLI's formats and in a notebook.

The renderers are render/'s, the ones the CLI uses; nothing here formats mathematics.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Iterator, Mapping

from rbdsolve.errors import ExitCode, InputError
from rbdsolve.problem.schema import Problem

if TYPE_CHECKING:  # sympy comes with the report: imported when a problem is solved
    import sympy as sp

    from rbdsolve.report.steps import ProblemReport, Solution, Step

FORMATS = ("text", "markdown", "latex", "html", "json")


@dataclass(frozen=True, eq=False)
class Answer:
    """One question's solution. ``answers`` is the question kind's answers dataclass
    (``ModesAnswers``: M, K, eigenvalues…, each a sympy object), None when the question
    could not be answered (``error`` says why); ``values`` are its numbers where the
    parameters have values. ``number`` counts from 1, as the report's headings do."""

    solution: Solution
    number: int

    question = property(lambda self: self.solution.question, doc="the question's kind: 'modes', 'impact'…")
    route = property(lambda self: self.solution.route.value, doc="'exact' or 'numeric': the route that answered")
    answers = property(lambda self: self.solution.answers, doc="the answers dataclass, or None")
    values = property(lambda self: self.solution.values, doc="numeric values: a tree of floats, by answer name")
    units = property(lambda self: self.solution.units, doc="each value's SI unit, in the same tree")
    steps = property(lambda self: self.solution.steps, doc="the worked solution: typed steps")
    warnings = property(lambda self: self.solution.warnings, doc="what the answer depends on or leaves out")
    error = property(lambda self: self.solution.error, doc="why there is no answer, or None")
    seconds = property(lambda self: self.solution.seconds, doc="time the route took")
    error_estimate = property(lambda self: self.solution.error_estimate,
                              doc="numeric route: a bound on the answers' relative error")

    @property
    def solved(self) -> bool:
        return self.solution.solved

    @property
    def results(self) -> tuple[Step, ...]:
        """The steps that state the final answers (boxed in a key)."""
        from rbdsolve.report.steps import StepKind

        return tuple(s for s in self.steps if s.kind is StepKind.RESULT)

    def __getitem__(self, name: str) -> object:
        """One answer by name: ``answer['eigenvalues']`` is ``answer.answers.eigenvalues``."""
        if self.answers is None:
            raise KeyError(f"question {self.number} ({self.question}) has no answers: {self.error}")
        try:
            return getattr(self.answers, name)
        except AttributeError:
            raise KeyError(f"question {self.number} ({self.question}) has no answer '{name}'") from None

    def _repr_html_(self) -> str:
        from rbdsolve.render.html import render_solution

        return render_solution(self.number, self.solution)

    def _repr_latex_(self) -> str:
        from rbdsolve.render.notebook import results_latex

        return results_latex([self.solution])

    def __repr__(self) -> str:
        state = "solved" if self.solved else f"not answered: {self.error}"
        return f"<Answer {self.number}: {self.question} ({self.route}), {state}>"


@dataclass(frozen=True, eq=False)
class Result:
    """A solved problem: the Problem as loaded and the report the CLI renders.

    ``result[0]`` is the first question's Answer, ``result['modes']`` the one modes
    question; ``result.symbols['g']`` the sympy symbol g in the answers."""

    problem: Problem
    report: ProblemReport

    @property
    def title(self) -> str:
        return self.report.title

    @property
    def answers(self) -> tuple[Answer, ...]:
        return tuple(Answer(s, n) for n, s in enumerate(self.report.solutions, start=1))

    @property
    def solved(self) -> bool:
        return self.report.solved

    @property
    def exit_code(self) -> ExitCode:
        """What ``rbdsolve solve`` would exit with: 0 every question answered, 1 not."""
        return ExitCode.OK if self.solved else ExitCode.UNSOLVED

    @property
    def warnings(self) -> tuple[str, ...]:
        return tuple(f"question {a.number} ({a.question}): {w}" for a in self.answers for w in a.warnings)

    @property
    def errors(self) -> tuple[str, ...]:
        return tuple(f"question {a.number} ({a.question}): {a.error}" for a in self.answers if a.error)

    @property
    def symbols(self) -> Mapping[str, sp.Basic]:
        """The names of the problem as the answers hold them: each parameter's symbol
        (positive unless declared otherwise), each coordinate as a function of time
        (theta(t)), and t: the keys to substitute values for."""
        from rbdsolve.model.state import t, user_function
        from rbdsolve.model.symbols import Symbols

        coordinates = {c.name: user_function(c.name)(t) for c in self.problem.coordinates}
        return {**Symbols.of(self.problem).parameters, **coordinates, "t": t}

    def subs(self, expr, **values):
        """``expr`` with parameters replaced by values given by name:
        ``result.subs(ω, g=9.81, r=0.5)``; a name the problem lacks is an InputError."""
        symbols = self.symbols
        unknown = sorted(set(values) - set(symbols))
        if unknown:
            raise InputError(f"{self.report.file} has no name {', '.join(map(repr, unknown))}")
        return expr.subs({symbols[name]: value for name, value in values.items()})

    def __getitem__(self, key: int | str) -> Answer:
        answers = self.answers
        if isinstance(key, int):
            return answers[key]
        found = [a for a in answers if a.question == key]
        if len(found) != 1:
            kinds = ", ".join(f"[{i}] {a.question}" for i, a in enumerate(answers))
            why = (f"{self.report.file} has no question '{key}'" if not found else
                   f"{self.report.file} asks '{key}' {len(found)} times: take one by its place, result[i]")
            raise KeyError(f"{why}; its questions: {kinds}")
        return found[0]

    def __iter__(self) -> Iterator[Answer]:
        return iter(self.answers)

    def __len__(self) -> int:
        return len(self.report.solutions)

    def render(self, fmt: str = "text") -> str:
        """The report as ``rbdsolve solve --format`` writes it: text (the terminal's,
        without colour), markdown, latex (the body; ``to_latex(document=True)`` for a
        whole document), html (a fragment with MathML) or json (one JSON line)."""
        if fmt not in FORMATS:
            raise InputError(f"format: expected one of {', '.join(FORMATS)}, found {fmt!r}")
        return getattr(self, f"to_{fmt}")()

    def to_text(self, width: int = 100) -> str:
        from rbdsolve.render.text import terminal_text

        return terminal_text(self.report, width)

    def to_markdown(self) -> str:
        from rbdsolve.render.markdown import render

        return render(self.report)

    def to_latex(self, document: bool = False) -> str:
        from rbdsolve.render.latex import body, render_document

        return render_document([self.report]) if document else "\n".join(body(self.report))

    def to_html(self) -> str:
        from rbdsolve.render.html import render_report

        return render_report(self.report)

    def to_json(self) -> str:
        from rbdsolve.render.json import render_report

        return render_report(self.report)

    def to_dict(self) -> dict:
        """The JSON object (docs/json.md) as Python data: exact answers as strings."""
        from rbdsolve.render.json import report_object

        return report_object(self.report)

    _repr_html_ = to_html
    _repr_markdown_ = to_markdown

    def _repr_latex_(self) -> str:
        from rbdsolve.render.notebook import results_latex

        return results_latex(self.report.solutions)

    def __repr__(self) -> str:
        state = "solved" if self.solved else f"{len(self.errors)} not answered"
        count = f"{len(self)} question{'' if len(self) == 1 else 's'}"
        return f"<Result {self.title!r}: {count} ({', '.join(a.question for a in self)}), {state}>"
