"""The energy question, in floating point: the exact route's integral, rates and speeds
at the configuration asked, evaluated at the parameter values (one rounding each)."""

from __future__ import annotations

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.energy.answers import NumericEnergyAnswers
from rbdsolve.solvers.energy.exact import energy, lost_contacts, undirected
from rbdsolve.solvers.energy.steps import numeric_steps
from rbdsolve.solvers.routes.options import Options
from rbdsolve.model.values.values import numeric
from rbdsolve.solvers.routes.needed import require_values

ROUNDING = 1e-15  # one rounding of each evaluated expression, relative


def solve(question: Question, model: Model, options: Options) -> Solution:
    require_values(model, "the numeric route")
    if not question.options.to:
        raise UnsolvedError("the numeric route answers at a configuration: give 'to: {q: VALUE}'")
    exact, e, _ = energy(question.options, model)
    there = exact.there
    values = numeric((exact.start, there.rate_squared, there.rate, there.speed), model.values)
    answers = NumericEnergyAnswers(*values)
    return Solution("energy", Route.NUMERIC, answers, numeric_steps(answers, model), error_estimate=ROUNDING,
                    warnings=(*lost_contacts(question.options, model, exact, e),
                              *undirected(question.options, model, exact, e)))
