"""Solver families: one module per family, each a pure function

    solve(question, model, options) -> Solution

``solve_problem`` runs every question of a problem and times each one.
"""

from __future__ import annotations

import time
from dataclasses import replace

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question, QuestionKind
from rbdsolve.report.steps import ProblemReport, Route, Solution
from rbdsolve.solvers import eom, equilibria, impact, inertia, modes, steady_motion, steady_spin
from rbdsolve.solvers.common import Options, numeric
from rbdsolve.solvers.energies import summarize_model
from rbdsolve.solvers.frames import frame_of, solve_in_frame

SOLVERS = {
    QuestionKind.EOM: eom.solve,
    QuestionKind.EQUILIBRIA: equilibria.solve,
    QuestionKind.MODES: modes.solve,
    QuestionKind.INERTIA: inertia.solve,
    QuestionKind.IMPACT: impact.solve,
    QuestionKind.STEADY_SPIN: steady_spin.solve,
    QuestionKind.STEADY_MOTION: steady_motion.solve,
}


def solve_question(question: Question, model: Model, options: Options) -> Solution:
    """Run one question's solver; an unanswerable question becomes a Solution with an
    error (exit code 1), not an exception, so the other questions still run."""
    start = time.perf_counter()
    try:
        if frame_of(question) is None:
            solution = SOLVERS[question.kind](question, model, options)
        else:
            solution = solve_in_frame(SOLVERS[question.kind], question, model, options)
    except UnsolvedError as exc:
        solution = Solution(question.kind.value, Route.EXACT, None, (), error=str(exc))
    values = numeric(solution.answers, model.values) if model.values and solution.answers else {}
    return replace(solution, values=values or {}, seconds=time.perf_counter() - start)


def solve_problem(model: Model, options: Options = Options()) -> ProblemReport:
    model = model.with_values(options.values) if options.values else model
    problem = model.problem
    summary = summarize_model(model)
    solutions = tuple(solve_question(q, model, options) for q in problem.questions)
    values = {str(k): float(v) for k, v in model.values.items()}
    symbols = tuple(p.name for p in problem.parameters) + problem.unknowns
    return ProblemReport(problem.file, problem.title, problem.source, problem.statement,
                         summary, solutions, values, symbols)


__all__ = ["Options", "SOLVERS", "solve_problem", "solve_question"]
