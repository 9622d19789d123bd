"""Steps and solutions.

A solution reads as a list of typed steps, the way a good exam solution does: what is
given, what is defined, the equations, what is substituted, the results, and notes.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum
from typing import Mapping

from rbdsolve.form.display import Relation
from rbdsolve.form.printers import float_text, unicode_name


class StepKind(Enum):
    GIVEN = "given"
    DEFINITION = "definition"
    EQUATION = "equation"
    SUBSTITUTION = "substitution"
    RESULT = "result"
    NOTE = "note"


class Route(Enum):
    EXACT = "exact"
    NUMERIC = "numeric"


@dataclass(frozen=True)
class Step:
    """``accuracy``: the step says how accurate a numeric route is (conditioning, error
    bounds, the search's tolerances), not what the answer is: renderers show it in a
    quieter block under the answers."""

    kind: StepKind
    text: str = ""
    math: tuple[Relation, ...] = ()
    accuracy: bool = False


def given(text: str, *math: Relation) -> Step:
    return Step(StepKind.GIVEN, text, math)


def definition(text: str, *math: Relation) -> Step:
    return Step(StepKind.DEFINITION, text, math)


def equation(text: str, *math: Relation) -> Step:
    return Step(StepKind.EQUATION, text, math)


def substitution(text: str, *math: Relation) -> Step:
    return Step(StepKind.SUBSTITUTION, text, math)


def result(text: str, *math: Relation) -> Step:
    return Step(StepKind.RESULT, text, math)


def note(text: str, *math: Relation) -> Step:
    return Step(StepKind.NOTE, text, math)


def accuracy(text: str, *math: Relation) -> Step:
    """How accurate a numeric route's answers are: said apart, under them."""
    return Step(StepKind.NOTE, text, math, accuracy=True)


def answer_steps(steps: tuple[Step, ...]) -> tuple[Step, ...]:
    return tuple(s for s in steps if not s.accuracy)


def accuracy_steps(steps: tuple[Step, ...]) -> tuple[Step, ...]:
    return tuple(s for s in steps if s.accuracy)


@dataclass(frozen=True)
class Solution:
    """One question's answer: exact answers (a frozen dataclass per question kind),
    their numeric values where parameter values are known, and the steps.

    ``error`` is set, and ``answers`` is None, when the question could not be answered.
    """

    question: str
    route: Route
    answers: object | None
    steps: tuple[Step, ...]
    values: Mapping[str, object] = field(default_factory=dict)
    units: Mapping[str, object] = field(default_factory=dict)  # beside values: each number's SI unit, or None
    warnings: tuple[str, ...] = ()
    seconds: float = 0.0
    error: str | None = None
    error_estimate: float | None = None  # numeric route: bound on the answers' relative error

    @property
    def solved(self) -> bool:
        return self.error is None


@dataclass(frozen=True)
class ModelSummary:
    """What the model section of a report shows: q, T and V, term by term."""

    coordinates: tuple[object, ...]
    T: object | None
    V: object | None
    steps: tuple[Step, ...]


@dataclass(frozen=True)
class ProblemReport:
    file: str
    title: str
    source: str
    statement: str
    model: ModelSummary
    solutions: tuple[Solution, ...]
    values: Mapping[str, object] = field(default_factory=dict)  # parameter values used
    symbols: tuple[str, ...] = ()  # parameter names, to read answers back (docs/json.md)
    units: Mapping[str, str] = field(default_factory=dict)  # SI unit of each value whose dimension is known

    def value_text(self, name: str) -> str:
        """'m = 0.2 kg', 'v₀ = 300 m/s': a parameter's value as the answers print it,
        with its unit where known."""
        unit = self.units.get(name)
        return f"{unicode_name(name)} = {float_text(self.values[name])}" + (f" {unit}" if unit else "")

    @property
    def solved(self) -> bool:
        return all(s.solved for s in self.solutions)
