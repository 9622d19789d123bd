"""A point's kinematics, the floating-point route: the exact route's expressions (they
are derivatives of the positions, cheap to form) evaluated at the parameter values.
An entry that still depends on what the state leaves out is None."""

from __future__ import annotations

import math

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.kinematics.answers import (NumericBodyMotion, NumericDistance, NumericKinematicsAnswers,
                                                 NumericLineTurning, NumericPointMotion)
from rbdsolve.solvers.kinematics.exact import kinematics
from rbdsolve.solvers.kinematics.steps import numeric_steps
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.routes.needed import require_values

ROUNDING = 1e-15  # one rounding of each evaluated expression, relative


def solve(question: Question, model: Model, options: Options) -> Solution:
    require_values(model, "the numeric route")
    exact, _ = kinematics(question.options, model, dict(model.values))

    def f(x: sp.Expr) -> float | None:
        value = x.xreplace(model.values)
        if value.free_symbols:
            return None
        number = complex(sp.N(value, 17))
        return number.real if math.isfinite(number.real) and abs(number.imag) <= 1e-14 else None

    def fs(v):
        return tuple(f(x) for x in v)

    points = tuple(NumericPointMotion(p.point, fs(p.position), fs(p.velocity), fs(p.acceleration), f(p.speed))
                   for p in exact.points)
    distances = tuple(NumericDistance(d.between, f(d.distance), f(d.rate)) for d in exact.distances)
    bodies = tuple(NumericBodyMotion(b.body, fs(b.angular_velocity), fs(b.angular_acceleration)) for b in exact.bodies)
    lines = tuple(NumericLineTurning(x.through, f(x.rate), f(x.acceleration)) for x in exact.lines)
    answers = NumericKinematicsAnswers({k: f(v) for k, v in exact.at.items()}, points, distances, bodies, lines)
    return Solution("kinematics", Route.NUMERIC, answers, numeric_steps(answers), error_estimate=ROUNDING)
