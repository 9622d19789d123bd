"""Impact, the exact route: the impulse equations (equations.py) solved exactly in a
fraction field, answers as cancelled fractions, the worked solution from steps.py."""

from __future__ import annotations

from rbdsolve.model.build import Model
from rbdsolve.problem.options import ImpactOptions
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.impact.equations import ImpactEquations, blows, instant, require_known
from rbdsolve.solvers.impact.steps import exact_steps
from rbdsolve.solvers.routes.options import Options


def solve(question: Question, model: Model, options: Options) -> Solution:
    opts: ImpactOptions = question.options
    now = instant(model, opts)
    hits = blows(model, opts, now)
    # in order, not a set's (the hash seed's): the first point not known names what it misses
    for point in dict.fromkeys([*(p for b in hits for p in (b.point, b.partner) if p), *opts.points]):
        require_known(now.velocity(point), model, opts)
    work = ImpactEquations(model, opts, now, hits)
    answers, warnings = work.results()
    return Solution("impact", Route.EXACT, answers, exact_steps(work, answers), warnings=warnings)
