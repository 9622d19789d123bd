"""The solver families, one folder each: the table of contents of rbdsolve's answers.

Each family has the same rooms: ``answers.py`` (what it answers, both routes: frozen
dataclasses, the JSON contract), ``exact.py`` (sympy, rational arithmetic) and
``numeric.py`` (floating point, with an error estimate), each route a pure function

    solve(question, model, options) -> Solution

and ``steps.py``, where both routes write their worked solutions. Beside the families,
the machinery several use, each folder named for what it holds: ``conditions/``
(conditions on the parameters, signs decided exactly), ``configuration/`` (the
placement of a scene, singular points), ``numeric/`` (the numeric model of a scene and
its root search), ``routes/`` (options and routes, the time budget, the checks),
``lagrange/`` (accelerations, the energy integral, moving frames). Numeric values
and units live in rbdsolve/model/values/, the model section of a report in
rbdsolve/model/summary/.

    family          question          what it answers
    eom/            eom               Lagrange's equations, in moving frames too
    equilibria/     equilibria        ∂V/∂q = 0, each equilibrium's stability
    modes/          modes             M, K, det(K − λM) = 0, eigenvalues, frequencies, shapes
    impact/         impact            generalized impulses, velocities after, energy lost
    inertia/        inertia           a body's tensor about a point, principal moments and axes
    steady_spin/    steady_spin       Euler's equations, spins about principal axes, stability
    steady_motion/  steady_motion     rolling conditions, angular momentum balance, solve_for
    kinematics/     kinematics        points' position, velocity, acceleration at a state; distances
    reactions/      reactions         forces at pivots, contacts, strings; energy; contact limits
    energy/         energy            T + V (or Jacobi's integral) constant: q̇²(q), speeds at a configuration
"""

from __future__ import annotations

from rbdsolve.model.build import Model, build_model
from rbdsolve.problem.schema import Problem, Question, QuestionKind
from rbdsolve.report.steps import ProblemReport, Solution
from rbdsolve.solvers.routes import routes
from rbdsolve.solvers.routes.options import Options, RouteChoice
from rbdsolve.solvers.routes.routes import Family, later, later_check, later_residuals

FAMILIES = {
    QuestionKind.EOM: Family(later("eom.exact"), later("eom.numeric"), named=later("eom.named", "named")),
    QuestionKind.EQUILIBRIA: Family(later("equilibria.exact"), later("equilibria.numeric"),
                                    later_residuals("equilibria.check"), later_check("equilibria.exact"),
                                    named=later("equilibria.named", "named")),
    QuestionKind.MODES: Family(later("modes.exact"), later("modes.numeric"), later_residuals("modes.check"),
                               later_check("modes.exact"), named=later("modes.named", "named")),
    QuestionKind.INERTIA: Family(later("inertia.exact"), later("inertia.numeric"),
                                 named=later("inertia.named", "named")),
    QuestionKind.IMPACT: Family(later("impact.exact"), later("impact.numeric"), later_residuals("impact.check"),
                                named=later("impact.named", "named")),
    QuestionKind.STEADY_SPIN: Family(later("steady_spin.exact"), later("steady_spin.numeric"),
                                     named=later("steady_spin.named", "named")),
    QuestionKind.STEADY_MOTION: Family(later("steady_motion.exact"), later("steady_motion.numeric"),
                                       later_residuals("steady_motion.check"),
                                       named=later("steady_motion.named", "named")),
    QuestionKind.KINEMATICS: Family(later("kinematics.exact"), later("kinematics.numeric"),
                                    partial=later_check("kinematics.exact"), named=later("kinematics.named", "named")),
    QuestionKind.REACTIONS: Family(later("reactions.exact"), later("reactions.numeric"),
                                   later_residuals("reactions.check"), named=later("reactions.named", "named")),
    QuestionKind.ENERGY: Family(later("energy.exact"), later("energy.numeric"), named=later("energy.named", "named")),
}


def solve_question(question: Question, model: Model, options: Options = Options()) -> Solution:
    """One question, on the route ``options`` asks for, within its budget: an unanswerable
    question becomes a Solution with an error (exit code 1), not an exception."""
    return routes.answer(FAMILIES[question.kind], question, model, options)


def partial_by_structure(question: Question, model: Model, options: Options = Options()) -> str | None:
    """Why the exact route would answer ``question`` only in part, read from the structure
    of its equations (the check ``auto`` runs before choosing the numeric route); None
    where the exact route answers in full, or the structure cannot say."""
    family = FAMILIES[question.kind]
    return None if family.partial is None else routes.partial_reason(family.partial, question, model, options)


def solve_problem(model: Model, options: Options = Options()) -> ProblemReport:
    """Every question of a model already built, each within the budget."""
    return routes.report(model.problem, lambda: model, solve_question, options)


def solve_file(problem: Problem, options: Options = Options()) -> ProblemReport:
    """Build the model of ``problem``, then answer every question, each within the budget."""
    return routes.report(problem, lambda: build_model(problem), solve_question, options)


__all__ = ["FAMILIES", "Family", "Options", "RouteChoice", "partial_by_structure", "solve_file", "solve_problem",
           "solve_question"]
