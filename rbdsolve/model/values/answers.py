"""An answers tree at the parameter values, in one call: its numbers (``values.py``),
the warnings on those that have none (not finite, not real), their SI units
(``units.py``) and the numeric block's lines (``numbers.py``).

Used by solvers/routes/routes.py on every answered question: the routes hand the
answers down once and put what comes back on the Solution."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable, Iterable

from rbdsolve.model.angles import angle_parameters
from rbdsolve.model.build import Model
from rbdsolve.model.values.values import not_finite, not_real, numbers

if TYPE_CHECKING:
    from rbdsolve.report.numbers import Named, Number


@dataclass(frozen=True)
class Valued:
    """An answers tree's numbers (``{}`` where the model has no values, or nothing was
    answered), the warnings on answers shown as null, their units (``{}`` likewise) and
    the numeric block."""

    values: object
    warnings: tuple[str, ...]
    units: object
    lines: tuple[Number, ...]


NOTHING = Valued({}, (), {}, ())


def valued(answers: object, model: Model, kind: str, named: Callable[[], Iterable[Named]] | None) -> Valued:
    """The answers of a ``kind`` question at the model's values. ``named``: which
    answers the worked solution prints under which name (the family's, asked only
    where there are numbers), or None for a family without a numeric block."""
    found = numbers(answers, model.values) if model.values and answers else None
    if found is None or not found.tree:
        return NOTHING
    # the units and the numeric block's lines, loaded where there are numbers
    from rbdsolve.model.values.numbers import numbers as numeric_lines
    from rbdsolve.model.values.units import answer_units, parameter_units

    said = (not_finite(answers, model.values), not_real(found))
    units = answer_units(answers, model, kind)
    lines = ()
    if named is not None:
        left = _open(model, parameter_units(model))
        line_units = answer_units(answers, model, kind, frozenset(left)) if left else units
        lines = numeric_lines(named(), answers, found.tree, line_units, model.values, left)
    return Valued(found.tree, tuple(x for x in said if x), units, lines)


def _open(model: Model, units: dict[str, str]) -> dict:
    """The parameters left without a value (an unknown a question solves for is not one),
    each with its SI unit ('' for a pure number, None where its dimension is not known;
    rad for an angle: an incline's β in sin β, a release angle θ₀, ``model.angles``)."""
    given = set(model.values)
    unknowns = set(model.problem.unknowns)
    left = {s: units.get(name) for name, s in model.symbols.parameters.items()
            if s not in given and name not in unknowns}
    unknown = frozenset(s.name for s, unit in left.items() if unit is None)
    if unknown:
        from rbdsolve.model.values.units import rate_parameter_units

        angles, rates = angle_parameters(model, unknown), rate_parameter_units(model, unknown)
        left = {s: "rad" if s.name in angles else rates.get(s.name, unit) for s, unit in left.items()}
    return left
