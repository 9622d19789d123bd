"""Steps and solutions.

A solution reads as a list of typed steps, the way a good exam solution does: what is
given, what is defined, the equations, what is substituted, the results, and notes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from enum import Enum
from typing import TYPE_CHECKING, Mapping

import sympy as sp

from rbdsolve.form.display import Along, Relation, Terms
from rbdsolve.form.factor import factored
from rbdsolve.form.printers import float_text, unicode_name

if TYPE_CHECKING:
    from rbdsolve.report.numbers import Number


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
    """A result, each value in its factored form where that reads no longer (ν = Ω √((a² −
    b²)(a² − c²))/…): the one place every family's answers pass on their way to print."""
    return Step(StepKind.RESULT, text, tuple(_factored(rel) for rel in math))


def _factored(rel: Relation) -> Relation:
    """The factors of a product factored (the sums under a root, over a fraction); a sum
    at the top is left as its solver ordered it (F's time part apart from the rest); a
    vector written along its basis, component by component (an impulse's M l m v₀ (e + 1)
    (3 d − 2 l)/(2 (M l² + 3 d² m)) eₓ)."""
    rhs = factored(rel.rhs) if _product(rel.rhs) else _along_factored(rel.rhs)
    if isinstance(rhs, sp.MatrixBase) and 1 in rhs.shape:  # a vector, entry by entry
        rhs = rhs.applyfunc(lambda x: factored(x) if _product(x) else x)
    more = tuple(factored(x) if _product(x) else x for x in rel.more)
    return rel if (rhs is rel.rhs and more == rel.more) else replace(rel, rhs=rhs, more=more)


def _along_factored(value):
    """Each component along a basis vector (``Along``, alone or in a sum of them) factored
    as a product is; anything else as it is."""
    if isinstance(value, Along) and _product(value.component):
        return replace(value, component=factored(value.component))
    if isinstance(value, Terms):
        parts = tuple(_along_factored(x) for x in value.items)
        return value if parts == value.items else replace(value, items=parts)
    return value


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
    remedy: str = ""  # the end of ``error`` that only this route needs (UnsolvedError.remedy)
    error_estimate: float | None = None  # numeric route: bound on the answers' relative error
    numbers: tuple[Number, ...] = ()  # the numeric block: values by their printed names (report/numbers.py)

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
    """A solved problem: the file and its title, source and statement, the model section,
    a Solution per question, and the parameter values, symbols and units used."""

    file: str
    title: str
    source: str
    statement: str
    model: ModelSummary
    solutions: tuple[Solution, ...]
    values: Mapping[str, object] = field(default_factory=dict)  # parameter values used
    symbols: tuple[str, ...] = ()  # parameter names, to read answers back (docs/json.md)
    units: Mapping[str, str] = field(default_factory=dict)  # SI unit of each value whose dimension is known
    angles: frozenset[str] = frozenset()  # parameters given in an angle unit (30 deg): shown with their degrees

    def value_text(self, name: str) -> str:
        """'m = 0.2 kg', 'v₀ = 300 m/s', 'α = 0.523599 (30°)': a parameter's value as the
        answers print it, with its unit where known, and an angle's degrees."""
        unit = self.units.get(name)
        return f"{unicode_name(name)} = {float_text(self.values[name])}" + (f" {unit}" if unit else "") + \
            self.degrees_text(name)

    def degrees_text(self, name: str) -> str:
        """' (30°)' after a parameter given in an angle unit (its value in radians, as
        every answer uses it), '' after any other."""
        if name not in self.angles:
            return ""
        return f" ({float_text(math.degrees(float(self.values[name])))}°)"

    @property
    def solved(self) -> bool:
        return all(s.solved for s in self.solutions)


def _product(value) -> bool:
    return isinstance(value, sp.Expr) and not value.is_Add
