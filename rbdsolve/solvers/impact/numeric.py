"""Impact, the floating-point route: the same impulse equations as the exact route
(Lagrange's equations for impact and Newton's restitution laws, linear in the velocities
after and the unknown impulses), with the parameter values put in and solved in floats
by LU with partial pivoting (numpy.linalg.solve).

Error estimate: the forward error of a backward-stable solve, n ε cond(A) (Higham,
Accuracy and Stability of Numerical Algorithms, §7.1). A condition number past
1/(n ε) means the equations are singular in floating point: refused.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model
from rbdsolve.problem.options import ImpactOptions
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.impact.equations import ImpactEquations, blows, instant
from rbdsolve.solvers.impact.steps import numeric_steps
from rbdsolve.solvers.numeric.numeric_model import to_floats
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.configuration.singular import float_reason
from rbdsolve.model.values.values import with_floats
from rbdsolve.solvers.routes.needed import require_values

EPS = float(np.finfo(float).eps)


class NumericImpactEquations(ImpactEquations):
    """The exact route's equations, solved in floats; ``condition`` is cond(A)."""

    condition: float = float("nan")

    def _solve(self) -> dict[sp.Symbol, sp.Expr]:
        unknowns = [*self.final, *self.sizes]
        equations = self.equations()
        A, b = sp.linear_eq_to_matrix([sp.expand(x) for x in equations], unknowns)
        Af, bf = to_floats(A, self.model.values), to_floats(b, self.model.values)
        self.condition = float(np.linalg.cond(Af))
        if not np.isfinite(self.condition) or self.condition * len(unknowns) * EPS >= 1:
            inertia = float_reason(to_floats(self.inertia(), self.model.values), self.model.coordinate_names(),
                                   "at the instant")
            raise UnsolvedError(f"{self.singular_reason(inertia)} (in floating point: condition number "
                                f"{self.condition:.3g})")
        x = np.linalg.solve(Af, bf).ravel()
        return {u: sp.Float(float(v), 17) for u, v in zip(unknowns, x)}


    def centre_of_percussion(self, support):
        if self.opts.centre_of_percussion is None:
            return None, None
        return None, ("the centre of percussion solves for a parameter: the exact route finds it "
                      "(--route exact)")


def solve(question: Question, model: Model, options: Options) -> Solution:
    require_values(model, "the numeric route")
    opts: ImpactOptions = question.options
    now = instant(model, opts)
    work = NumericImpactEquations(model, opts, now, blows(model, opts, now))
    answers, warnings = work.results()
    estimate = len(work.solution) * EPS * work.condition
    return Solution("impact", Route.NUMERIC, with_floats(answers, model.values), numeric_steps(work, work.condition),
                    warnings=warnings, error_estimate=estimate)
